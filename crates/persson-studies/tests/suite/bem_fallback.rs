//! A stalled preconditioner (issue 22): the numerics flag each solve the
//! plain loop finished ([`persson::bem::rough::RoughPoint::fallback`]) and
//! the studies turn the flags into one `preconditioner_fallback` warning;
//! the answer is the plain solver's to the tolerance.
#![cfg(feature = "bem")]

use persson::bem::rough::{rough_contact, RoughOptions, RoughReport, SurfaceOrigin};
use persson::bem::surface::synthesize;
use persson::bem::{Method, Options};
use persson::spectrum::{Amplitude, SelfAffine};
use persson_studies::validation::{compare, ComparisonConfig, SweepSettings};
use persson_studies::warning::{of_rough, Warning};

/// ε of the solves.
const TOL: f64 = 1e-10;

/// The pressures of the load path, unit of E*: two where ε does not halve
/// at every iteration (at 0.02 E* the edge-corrected preconditioner of
/// issue 22 halves it every time, so a window of one no longer stalls there).
const PRESSURES: [f64; 2] = [0.004, 0.008];

fn report(method: Method) -> RoughReport {
    let (n, ql) = (64, std::f64::consts::TAU);
    let s = SelfAffine::new(
        ql,
        4.0 * ql,
        ql * n as f64 / 4.0,
        0.8,
        Amplitude::RmsSlope(0.1),
    )
    .unwrap();
    let surface = synthesize(&s, n, 1.0, 1).unwrap();
    let source = SurfaceOrigin::synthesised(&s, 1).unwrap();
    let options = RoughOptions {
        solver: Options {
            tolerance: TOL,
            warm_start: true,
            ..Options::default()
        },
        method,
        ..RoughOptions::default()
    };
    rough_contact(&surface, source, 1.0, &PRESSURES, &options, &mut ()).unwrap()
}

#[test]
fn a_forced_stall_falls_back_and_warns() {
    // A stall window of one iteration: ε must halve at every iteration,
    // which a projected CG misses at once.
    let forced = report(Method::Preconditioned {
        stall_iterations: 1,
    });
    let plain = report(Method::Plain);
    let warnings = of_rough(&forced);
    let w = warnings
        .iter()
        .find(|w| w.kind() == "preconditioner_fallback")
        .expect("a fallback warning");
    let Warning::PreconditionerFallback {
        nominal_pressure,
        iterations,
    } = w
    else {
        panic!("{w:?}")
    };
    assert_eq!(nominal_pressure, &PRESSURES.to_vec());
    assert_eq!(iterations.len(), PRESSURES.len());
    let json = serde_json::to_value(w).unwrap();
    assert_eq!(json["kind"], "preconditioner_fallback");
    assert!(w.to_string().contains("σ0 = 0.004, 0.008"), "{w}");
    // Same answer as the plain solver: the contact sets are equal.
    for (a, b) in forced.points.iter().zip(&plain.points) {
        assert!(a.fallback.is_some() && b.fallback.is_none());
        assert_eq!(a.contact_fraction, b.contact_fraction);
        assert!(a.residual <= TOL);
    }
    // The default method does not stall here: no warning.
    let default = report(Method::default());
    assert!(default.points.iter().all(|p| p.fallback.is_none()));
    assert!(of_rough(&default)
        .iter()
        .all(|w| w.kind() != "preconditioner_fallback"));
    assert!(of_rough(&plain)
        .iter()
        .all(|w| w.kind() != "preconditioner_fallback"));
}

/// `compare` at `PRESSURES` on two grids (32², 64²) of the rough case with `method`.
fn comparison(method: Method) -> persson_studies::validation::Comparison {
    let ql = std::f64::consts::TAU;
    let s = SelfAffine::new(ql, 4.0 * ql, 16.0 * ql, 0.8, Amplitude::RmsSlope(0.1)).unwrap();
    let mut config = ComparisonConfig::new(1.0);
    config.nominal_pressure = PRESSURES.to_vec();
    config.sweep = SweepSettings {
        grid: 64,
        levels: 2,
        alpha: Some(0.7),
        ..SweepSettings::default()
    };
    config.sweep.options.tolerance = TOL;
    config.method = method;
    compare(&s, &config, &mut |_| {}).unwrap()
}

#[test]
fn compare_carries_the_fallback_warning() {
    let forced = comparison(Method::Preconditioned {
        stall_iterations: 1,
    });
    let w = forced
        .warnings
        .iter()
        .find(|w| w.kind() == "preconditioner_fallback")
        .expect("a fallback warning in compare");
    let Warning::PreconditionerFallback {
        nominal_pressure, ..
    } = w
    else {
        panic!("{w:?}")
    };
    // The cold first solve stalls on both grids (the warm-started second may
    // not: its ε can halve at every iteration); only compared pressures.
    let first = nominal_pressure
        .iter()
        .filter(|&&p| p == PRESSURES[0])
        .count();
    assert_eq!(first, 2, "{nominal_pressure:?}");
    assert!(nominal_pressure.iter().all(|p| PRESSURES.contains(p)));
    // Same answer as the default method, which does not fall back here.
    let default = comparison(Method::default());
    assert!(default
        .warnings
        .iter()
        .all(|w| w.kind() != "preconditioner_fallback"));
    for (a, b) in forced.bem.iter().zip(&default.bem) {
        assert_eq!(a.contact_fraction, b.contact_fraction);
    }
}

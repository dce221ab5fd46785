//! A stalled preconditioner (issue 22): the numerics flag each solve the
//! plain loop finished ([`persson::bem::rough::RoughPoint::fallback`]) and
//! the studies turn the flags into one `preconditioner_fallback` warning;
//! the answer is the plain solver's to the tolerance.
#![cfg(feature = "bem")]

use persson::bem::rough::{rough_contact, RoughOptions, RoughReport, SurfaceOrigin};
use persson::bem::surface::synthesize;
use persson::bem::{Method, Options};
use persson::spectrum::{Amplitude, SelfAffine};
use persson_studies::warning::{of_rough, Warning};

/// ε of the solves.
const TOL: f64 = 1e-10;

/// The pressures of the load path, unit of E*.
const PRESSURES: [f64; 2] = [0.004, 0.02];

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
    assert!(w.to_string().contains("σ0 = 0.004, 0.02"), "{w}");
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

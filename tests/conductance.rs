//! Contact conductance: Barber's identity on closed forms, the gap term of
//! P(u), the BEM's exact stiffness, and bad input.

use persson::conductance::{
    electrical_conductance, gap_conductance, gap_conductance_of_field, thermal_conductance,
    Conductance, ConductanceOptions, Conductivity, GapLaw, Resistivity,
};
use persson::gap::{DensityOptions, SeparationDensity};
use persson::reference::Ball;
use persson::separation::Separation;
use persson::spectrum::{Amplitude, SelfAffine};
use persson::{Error, Estimate};

/// Closed forms evaluated in a few flops: a few ulps.
const ULPS: f64 = 1e-14;

fn exact(value: f64) -> Estimate {
    Estimate { value, error: 0.0 }
}

fn spectrum() -> SelfAffine {
    SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

#[test]
fn barber_on_holms_spot() {
    // Flat punch of radius a: K = 2E*a (Johnson Eq. 3.33). Holm: C = 4a/(ρ1 + ρ2),
    // thermal 4aκ1κ2/(κ1 + κ2).
    for (a, e_star, r1, r2, k1, k2) in [
        (1e-4, 1e11, 1.7e-8, 2.8e-8, 400.0, 237.0),
        (3e-7, 2e9, 1e-2, 1e-2, 0.2, 0.2),
        (5e-3, 7e10, 1e3, 1e-8, 1e-3, 1e3),
    ] {
        let k = exact(2.0 * e_star * a);
        let c = electrical_conductance(k, e_star, &Resistivity::new(r1, r2).unwrap()).unwrap();
        let holm = 4.0 * a / (r1 + r2);
        assert!(
            (c.value - holm).abs() <= ULPS * holm,
            "{} vs {holm}",
            c.value
        );
        let t = thermal_conductance(k, e_star, &Conductivity::new(k1, k2).unwrap()).unwrap();
        let holm_t = 4.0 * a * k1 * k2 / (k1 + k2);
        assert!(
            (t.value - holm_t).abs() <= ULPS * holm_t,
            "{} vs {holm_t}",
            t.value
        );
    }
}

#[test]
fn barber_on_a_hertz_ball() {
    // Hertz: F ∝ δ^{3/2}, so K = dF/dδ = 3F/(2δ), from reference.rs's F, δ and a;
    // the isopotential circle of radius a conducts 4a/(ρ1 + ρ2) (Holm).
    for (radius, load, e_star) in [(0.01, 10.0, 1e9), (1e-3, 1e-3, 2e11), (0.5, 1e4, 3e6)] {
        let ball = Ball::from_load(radius, load, e_star).unwrap();
        let k = exact(1.5 * ball.load / ball.penetration());
        let rho = Resistivity::new(2.0e-8, 5.0e-8).unwrap();
        let c = electrical_conductance(k, e_star, &rho).unwrap();
        let holm = 4.0 * ball.contact_radius / rho.sum();
        // K from F/δ of the closed form: ~4 roundings of the Hertz relations.
        assert!(
            (c.value - holm).abs() <= 4.0 * ULPS * holm,
            "{} vs {holm}",
            c.value
        );
    }
}

#[test]
fn theory_conductance_is_barber_on_the_separation_stiffness() {
    let s = spectrum();
    let e_star = 1e11;
    let opts = ConductanceOptions {
        conductivity: Some(Conductivity::new(50.0, 16.0).unwrap()),
        resistivity: Some(Resistivity::both(1e-7).unwrap()),
        ..Default::default()
    };
    let model = Conductance::new(&s, e_star, opts).unwrap();
    let sep = Separation::new(&s, e_star)
        .unwrap()
        .with_tolerance(1e-9)
        .unwrap();
    for p in [1e5, 1e7, 1e9] {
        let pt = model.point(p).unwrap();
        let k = sep.stiffness(p).unwrap();
        assert!((pt.stiffness - k.value).abs() <= 1e-12 * k.value);
        let ks = 50.0 * 16.0 / 66.0;
        let h = pt.thermal_conductance.unwrap();
        assert!((h - 2.0 * ks * k.value / e_star).abs() <= ULPS * h);
        let he = pt.electrical_conductance.unwrap();
        assert!((he - 2.0 * k.value / (2e-7 * e_star)).abs() <= ULPS * he);
        assert!(pt.thermal_conductance_error_bound.unwrap() >= 0.0);
    }
}

#[test]
fn low_load_conductance_is_linear_in_load() {
    // ū ≈ u0 ln(σ_ref/σ0) at small load, so K/A0 → σ0/u0 and h_c → 2κ_s σ0/(E* u0)
    // (Persson, PRL 99, 125502 (2007)). At σ0 = 1e-6 E* the next term of E1
    // is O((wσ0/E*)²): measured 3e-6 at 1e4, so ≲ 3e-7 below 3e3.
    let s = spectrum();
    let e_star = 1e11;
    let sep = Separation::new(&s, e_star).unwrap();
    let u0 = sep.low_load_law().unwrap().length.value;
    for p in [1e2, 1e3, 3e3] {
        let k = sep.stiffness(p).unwrap().value;
        let h = thermal_conductance(exact(k), e_star, &Conductivity::both(2.0).unwrap()).unwrap();
        let linear = 2.0 * 1.0 * p / (e_star * u0);
        assert!(
            (h.value / linear - 1.0).abs() < 1e-6,
            "{p}: {} vs {linear}",
            h.value
        );
    }
}

#[test]
fn gap_conductance_of_a_constant_law_is_the_open_area() {
    let s = spectrum();
    for p in [1e6, 1e8] {
        let d = SeparationDensity::new(&s, 1e9, p, &DensityOptions::default()).unwrap();
        let law = GapLaw::Table {
            points: vec![(0.0, 3.5), (1.0, 3.5)],
        };
        let h = gap_conductance(&d, &law).unwrap();
        let open = 3.5 * (1.0 - d.contact_fraction());
        assert!(
            (h.value - open).abs() <= h.error.max(1e-9 * open),
            "{} vs {open}",
            h.value
        );
        assert!(h.error < 1e-8 * open);
    }
}

#[test]
fn gap_conductance_of_a_gas_against_its_expansion() {
    // ℓ ≫ u: κ/(u + 2ℓ) = (κ/2ℓ)(1 − u/2ℓ + (u/2ℓ)² …), so
    // h_gap = (κ/2ℓ)[(1 − A1) − ∫uP/(2ℓ)] + O((u_max/2ℓ)²).
    let s = spectrum();
    let d = SeparationDensity::new(&s, 1e9, 1e7, &DensityOptions::default()).unwrap();
    let (kappa, ell) = (0.026, 1e-2);
    let law = GapLaw::Gas {
        gas_conductivity: kappa,
        mean_free_path: ell,
    };
    let h = gap_conductance(&d, &law).unwrap();
    let c = kappa / (2.0 * ell);
    let series = c * (d.non_contact_fraction().value - d.first_moment().value / (2.0 * ell));
    let rest = c * (d.largest_separation() / (2.0 * ell)).powi(2);
    assert!(
        (h.value - series).abs() <= rest,
        "{} vs {series} (±{rest})",
        h.value
    );
}

#[test]
fn gap_conductance_of_a_field() {
    let law = GapLaw::Gas {
        gas_conductivity: 0.026,
        mean_free_path: 6.8e-8,
    };
    let gap = [0.0, 1e-6, 2e-6, 0.0];
    let pressure = [1.0, 0.0, 0.0, 2.0];
    let h = gap_conductance_of_field(&gap, &pressure, &law).unwrap();
    let want = (law.alpha(1e-6) + law.alpha(2e-6)) / 4.0;
    assert!((h - want).abs() <= ULPS * want);
}

fn invalid_name(e: Error) -> String {
    match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("expected InvalidParameter, got {other:?}"),
    }
}

#[test]
fn bad_input_names_the_field() {
    for (r1, r2, name) in [
        (0.0, 1.0, "resistivity"),
        (-1.0, 1.0, "resistivity"),
        (f64::NAN, 1.0, "resistivity"),
        (1.0, 0.0, "resistivity2"),
    ] {
        assert_eq!(invalid_name(Resistivity::new(r1, r2).unwrap_err()), name);
        let n2 = name.replace("resistivity", "conductivity");
        assert_eq!(invalid_name(Conductivity::new(r1, r2).unwrap_err()), n2);
    }
    let k = exact(1.0);
    let rho = Resistivity::both(1.0).unwrap();
    assert_eq!(
        invalid_name(electrical_conductance(k, 0.0, &rho).unwrap_err()),
        "contact_modulus"
    );
    assert_eq!(
        invalid_name(electrical_conductance(exact(f64::NAN), 1.0, &rho).unwrap_err()),
        "stiffness"
    );
    for (law, name) in [
        (
            GapLaw::Gas {
                gas_conductivity: -1.0,
                mean_free_path: 1e-7,
            },
            "gas_conductivity",
        ),
        (
            GapLaw::Gas {
                gas_conductivity: 1.0,
                mean_free_path: -1e-7,
            },
            "mean_free_path",
        ),
        (
            GapLaw::Table {
                points: vec![(0.0, 1.0)],
            },
            "gap_table",
        ),
        (
            GapLaw::Table {
                points: vec![(1.0, 1.0), (0.5, 1.0)],
            },
            "gap_table[1]",
        ),
        (
            GapLaw::Table {
                points: vec![(0.0, 1.0), (1.0, f64::NAN)],
            },
            "gap_table[1]",
        ),
    ] {
        assert_eq!(invalid_name(law.validate().unwrap_err()), name);
    }
}

#[cfg(feature = "bem")]
mod bem {
    use persson::bem::stiffness::{contact_stiffness, StiffnessOptions};
    use persson::bem::surface::synthesize;
    use persson::bem::{Boundary, Control, Operator, Options, Solver};
    use persson::spectrum::{Amplitude, SelfAffine};

    #[test]
    fn linear_solve_stiffness_equals_the_load_approach_derivative() {
        // K from the fixed contact set against a central difference of the
        // load–approach curve (three solves at σ0(1 ± ε)); the contact set
        // changes between them, an O(ε) effect: 1e-3 relative at ε = 1e-4.
        let q_l = std::f64::consts::TAU;
        let s = SelfAffine::new(q_l, 2.0 * q_l, 16.0 * q_l, 0.8, Amplitude::RmsSlope(0.1)).unwrap();
        let n = 64;
        let surf = synthesize(&s, n, 1.0, 3).unwrap();
        let opts = Options {
            tolerance: 1e-12,
            ..Options::default()
        };
        let mut solver = Solver::new(Operator::new(Boundary::Periodic, n, 1.0, 1.0).unwrap());
        let p0 = 0.01;
        let eps = 1e-4;
        let mid = solver
            .solve(&surf.heights, Control::MeanPressure(p0), &opts)
            .unwrap();
        let hi = solver
            .solve(
                &surf.heights,
                Control::MeanPressure(p0 * (1.0 + eps)),
                &opts,
            )
            .unwrap();
        let lo = solver
            .solve(
                &surf.heights,
                Control::MeanPressure(p0 * (1.0 - eps)),
                &opts,
            )
            .unwrap();
        let fd = 2.0 * eps * p0 / (hi.approach - lo.approach);
        let k = contact_stiffness(
            solver.operator(),
            &mid.pressure,
            &StiffnessOptions::default(),
        )
        .unwrap();
        assert!(k.stiffness_error_bound < 1e-8 * k.stiffness, "{k:?}");
        assert!(
            (k.stiffness / fd - 1.0).abs() < 1e-3,
            "{} vs {fd}",
            k.stiffness
        );
        // and the mean gap moves by −dδ (periodic operator): K = −dσ0/dū
        let mean = |g: &[f64]| g.iter().sum::<f64>() / g.len() as f64;
        let fd_u = -2.0 * eps * p0 / (mean(&hi.gap) - mean(&lo.gap));
        assert!((fd_u / fd - 1.0).abs() < 1e-6, "{fd_u} vs {fd}");
    }
}

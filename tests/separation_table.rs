//! The load-independent table of P(u) (src/gap/table.rs) and the fixed point
//! rule (src/gap/points.rs) against the adaptive route and P(u)'s identities.

use persson::conductance::{Conductance, ConductanceOptions, GapLaw};
use persson::gap::{DensityOptions, SeparationDensity, SeparationTable, TableOptions};
use persson::leakage::{Drive, EffectiveMedium, LeakStatus, Seal};
use persson::separation::Separation;
use persson::spectrum::{Amplitude, SelfAffine};
use persson::Error;

/// The table's default fixed rules against the adaptive route (1e-9): the
/// worst difference measured on this spectrum is about 1e-6 (normalisation
/// 1e-10, ū 3e-7, σ_eff 1.2e-6); 10× margin.
const TABLE_TOL: f64 = 1e-5;

/// The load curves (table with 0.35 ζ-panels per unit, fixed u-rule)
/// against the adaptive point route: the worst difference measured over 97
/// loads up to A/A0 = 0.4 is 2.7e-5 (`examples/flow_accuracy.rs -- knobs`;
/// 2.4e-5 with the table's 0.5, so the fixed u-rule sets it); 2× margin.
const CURVE_TOL: f64 = 5e-5;

/// P_nc(u) pointwise, relative to its peak, at σ0 ≤ 1e7: the largest
/// difference measured is 1.8e-5 (σ0 = 1e7, at the peak); 5× margin. At
/// σ0 = 1e8 (A/A0 ≈ 0.27) the pointwise difference is 7e-4 with 0.5 s-panels
/// per unit and 1.1e-3 with 2, not yet understood: pointwise P(u) is given by
/// the adaptive route; the table serves the expectations (checked below).
const TABLE_DENSITY_TOL: f64 = 1e-4;

fn spectrum() -> SelfAffine {
    SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

fn breaks() -> Vec<f64> {
    vec![4e4]
}

fn table() -> SeparationTable {
    let opts = TableOptions {
        breaks: breaks(),
        ..Default::default()
    };
    SeparationTable::new(&spectrum(), 1e9, 1e5, &opts).unwrap()
}

#[test]
fn table_density_is_normalised_and_its_mean_is_the_separation() {
    let s = spectrum();
    let t = table();
    let sep = Separation::new(&s, 1e9).unwrap().with_breaks(&breaks());
    for p in [1e5, 1e6, 1e7, 1e8, 2e8] {
        let d = t.density(p).unwrap();
        // A(ζ1) + ∫P_nc = 1 (an identity: the s-rule integrates −dA exactly
        // up to its own error, which the bound carries)
        let nc = d.non_contact_fraction();
        let norm = d.contact_fraction() + nc.value;
        assert!(
            (norm - 1.0).abs() <= nc.error.max(1e-12),
            "{p}: {norm} ± {}",
            nc.error
        );
        // ∫(−A′)u1 dζ telescopes to ū of separation.rs (adaptive)
        let u = sep.mean_separation(p).unwrap().value;
        let m = d.unfolded_first_moment().value;
        assert!((m - u).abs() <= TABLE_TOL * u, "{p}: {m} vs {u}");
        assert!((d.mean_separation().value - u).abs() <= TABLE_TOL * u);
        assert!(d.fold_shift().value >= 0.0);
    }
}

#[test]
fn table_density_agrees_with_the_adaptive_density() {
    let s = spectrum();
    let t = table();
    let opts = DensityOptions {
        breaks: breaks(),
        ..Default::default()
    };
    for p in [1e5, 1e7] {
        let a = SeparationDensity::new(&s, 1e9, p, &opts).unwrap();
        let b = t.density(p).unwrap();
        // on 0.01 ū … 3 ū, relative to the largest P_nc there (the far tail,
        // ≪ 1e-5 of the peak, comes from nodes of negligible weight)
        let u = a.mean_separation().value;
        let xs: Vec<f64> = (0..=40)
            .map(|i| u * 10f64.powf(-2.0 + 2.5 * i as f64 / 40.0))
            .collect();
        let peak = xs.iter().map(|&x| a.density(x).value).fold(0.0, f64::max);
        for &x in &xs {
            let (da, db) = (a.density(x).value, b.density(x).value);
            assert!(
                (da - db).abs() <= TABLE_DENSITY_TOL * peak,
                "{p}, u = {x}: {da} vs {db}"
            );
        }
    }
}

fn seal() -> Seal {
    Seal {
        seal_width: 1e-3,
        seal_length: 2e-2,
        viscosity: 1e-3,
        drive: Drive::Liquid { pressure_drop: 1e5 },
    }
}

#[test]
fn effective_medium_curve_agrees_with_its_points() {
    let s = spectrum();
    let opts = DensityOptions {
        breaks: breaks(),
        ..Default::default()
    };
    let em = EffectiveMedium::new(&s, 1e9, seal(), opts).unwrap();
    // 3e8: A/A0 near ½, where σ_eff → 0 and relative errors grow: only
    // the bounds are checked there
    let pressures = [1e5, 1e7, 1e8, 3e8];
    let curve = em.load_curve(&pressures).unwrap();
    for (c, &p) in curve.iter().zip(&pressures) {
        let one = em.point(p).unwrap();
        assert_eq!(c.status, one.status, "{p}");
        assert_eq!(c.status, LeakStatus::Leaking, "{p}");
        let (a, b) = (
            one.effective_flow_conductivity,
            c.effective_flow_conductivity,
        );
        if p <= 1e8 {
            assert!((a - b).abs() <= CURVE_TOL * a, "{p}: {a} vs {b}");
        }
        // the curve's bound covers the difference
        let bounds =
            c.effective_flow_conductivity_error_bound + one.effective_flow_conductivity_error_bound;
        assert!((a - b).abs() <= bounds, "{p}: {a} vs {b} ± {bounds}");
    }
}

/// The gap-law curve against its points: the gap term (table, fixed
/// u-rule) and the thermal conductance, whose stiffness the curve takes
/// from the table's full band.
#[test]
fn gap_conductance_curve_agrees_with_its_points() {
    let s = spectrum();
    let opts = ConductanceOptions {
        conductivity: Some(persson::conductance::Conductivity::both(50.0).unwrap()),
        gap_law: Some(GapLaw::Gas {
            gas_conductivity: 0.026,
            mean_free_path: 7e-8,
        }),
        density: DensityOptions {
            breaks: breaks(),
            ..Default::default()
        },
        ..Default::default()
    };
    let model = Conductance::new(&s, 1e9, opts).unwrap();
    let pressures = [1e6, 1e8];
    let curve = model.load_curve(&pressures).unwrap();
    for (c, &p) in curve.iter().zip(&pressures) {
        let a = model.point(p).unwrap().gap_conductance.unwrap();
        let b = c.gap_conductance.unwrap();
        assert!((a - b).abs() <= CURVE_TOL * a, "{p}: {a} vs {b}");
        let a = model.point(p).unwrap().thermal_conductance.unwrap();
        let b = c.thermal_conductance.unwrap();
        assert!((a - b).abs() <= 1e-9 * a, "{p}: {a} vs {b}");
    }
}

/// The table's stiffness (its full band's fixed rule) against the
/// adaptive route at 1e-12: measured 1.9e-13 over 100 loads from 1e-4 E*
/// to 0.3 E* (its bound ≤ 1.1e-9).
#[test]
fn table_stiffness_agrees_with_the_adaptive_stiffness() {
    let s = spectrum();
    let t = table();
    let sep = Separation::new(&s, 1e9)
        .unwrap()
        .with_breaks(&breaks())
        .with_tolerance(1e-12)
        .unwrap();
    for i in 0..=20 {
        let p = 1e9 * 10f64.powf(-4.0 + 3.5 * f64::from(i) / 20.0);
        let (a, b) = (sep.stiffness(p).unwrap(), t.stiffness(p).unwrap());
        assert!(
            (a.value - b.value).abs() <= 2e-12 * a.value,
            "{p}: {a:?} vs {b:?}"
        );
        assert!((a.value - b.value).abs() <= a.error + b.error, "{p}");
    }
}

#[test]
fn bad_table_knobs_and_loads_name_the_field() {
    let s = spectrum();
    let name = |r: persson::Result<SeparationTable>| match r {
        Err(Error::InvalidParameter { name, .. }) => name,
        other => panic!("{other:?}"),
    };
    for v in [0.0, -1.0, f64::NAN, 1e3] {
        let o = TableOptions {
            zeta_panels_per_unit: v,
            ..Default::default()
        };
        assert_eq!(
            name(SeparationTable::new(&s, 1e9, 1e5, &o)),
            "zeta_panels_per_unit"
        );
    }
    let o = TableOptions {
        q_panels: 0,
        ..Default::default()
    };
    assert_eq!(name(SeparationTable::new(&s, 1e9, 1e5, &o)), "q_panels");
    let d = TableOptions::default();
    assert_eq!(
        name(SeparationTable::new(&s, 1e9, 0.0, &d)),
        "nominal_pressure"
    );
    assert_eq!(
        name(SeparationTable::new(&s, f64::NAN, 1e5, &d)),
        "contact_modulus"
    );
    // a load below the table's lowest: an error, not an extrapolation
    match table().density(1e4) {
        Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, "nominal_pressure"),
        other => panic!("{:?}", other.map(|d| d.contact_fraction())),
    }
}

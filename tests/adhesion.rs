//! Adhesion theory (issue 24, theory half): the Persson–Tosatti energy terms
//! against mpmath, the adhesive A/A0 against a brute-force finite-difference
//! solution of the moving-boundary diffusion, the non-adhesive limit, the
//! identities of the diffusion, the pull-off stress, the Pastewka–Robbins
//! criterion and bad input.
//!
//! Reference values: tests/reference/adhesion_energy_mpmath.py (30 digits) and
//! tests/reference/adhesion_diffusion_fd.py (Crank–Nicolson, Richardson).
#![allow(clippy::excessive_precision)] // reference values keep the digits mpmath and the script printed

use persson::adhesion::{true_area_ratio, AdhesionModel, AdhesiveContact, AreaEnhancement, Flag};
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::theory::Persson;

/// Closed-form moments and erfcx against 30-digit quadrature: a few ulps.
const ENERGY_TOL: f64 = 1e-13;
/// Δγ = 0 must give erf(1/(2√G)) (the kernel of the Volterra equation vanishes).
const NON_ADHESIVE_TOL: f64 = 1e-13;
/// The finite-difference reference's own error on A/A0 (its Richardson
/// estimate is ≤ 1e-5; the two methods agree to ~4e-8).
const FD_AREA_TOL: f64 = 1e-6;
/// The reference's tensile fraction interpolates the cumulative integral at
/// σ = 0 between grid nodes: its extrapolation moves by up to 4e-6.
const FD_TENSILE_TOL: f64 = 1e-5;
/// The reference's carried pressure moves by up to 1.4e-6 under extrapolation.
const FD_CARRIED_TOL: f64 = 3e-6;

/// The test spectrum: q_l = 1, q_r = 2, q_s = 100, H = 0.8, h'_rms = 0.5, E* = 1.
fn test_spectrum() -> SelfAffine {
    SelfAffine::new(1.0, 2.0, 100.0, 0.8, Amplitude::RmsSlope(0.5)).unwrap()
}

/// Rubber on a rough surface: q_l = 1e4, q_r = 1e5, q_s = 1e8 (1/m), H = 0.8, h'_rms = 1.
fn rubber_spectrum() -> SelfAffine {
    SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn true_area_ratio_matches_mpmath() {
    // (ξ², ∫₀^∞ e^{−x}(1 + ξ²x)^{1/2} dx), mpmath quad, 30 digits
    let table = [
        (1e-6, 1.000_000_499_999_750_000_4),
        (0.25, 1.113_169_262_495_293_644_8),
        (1.0, 1.378_936_078_070_656_053),
        (100.0, 8.944_643_131_587_037_803_9),
    ];
    for (x, exact) in table {
        let a = true_area_ratio(x).unwrap();
        assert!(
            rel(a.value, exact) < ENERGY_TOL,
            "{x}: {} vs {exact}",
            a.value
        );
        assert!((a.value - exact).abs() <= a.error, "{x}: bound {}", a.error);
    }
}

#[test]
fn energy_terms_match_mpmath() {
    // (ζ, U_el/A0, A_true/A0): adhesion_energy_mpmath.py
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let table = [
        (
            1.5,
            3.191_782_163_008_749_858_6e-4,
            1.000_818_275_079_176_509_9,
        ),
        (
            2.0,
            9.407_357_954_131_052_214_6e-4,
            1.003_014_732_014_655_214_6,
        ),
        (
            10.0,
            4.269_699_880_940_366_358_7e-3,
            1.031_221_801_774_719_343_6,
        ),
        (
            100.0,
            5.802_268_895_153_539_636_6e-3,
            1.113_169_262_495_293_644_8,
        ),
    ];
    for (z, u, a) in table {
        let p = m.energy_point(z).unwrap();
        assert!(
            rel(p.full_contact_energy, u) < ENERGY_TOL,
            "{z}: {}",
            p.full_contact_energy
        );
        assert!(
            rel(p.true_area_ratio, a) < ENERGY_TOL,
            "{z}: {}",
            p.true_area_ratio
        );
        let dg_eff = 0.01 * a - u;
        assert!(
            (p.effective_interfacial_energy - dg_eff).abs() < ENERGY_TOL * 0.01 * a,
            "{z}"
        );
    }
    // physical units: rubber, E* = 1 MPa
    let s = rubber_spectrum();
    let m = AdhesionModel::new(&s, 1e6, 0.05).unwrap();
    let table = [
        (
            10.0,
            2.227_585_384_948_502_252_6e-2,
            1.003_333_313_781_050_392_7,
        ),
        (
            1e3,
            1.267_320_224_700_807_507_7e-1,
            1.158_279_512_214_218_232_2,
        ),
        (
            1e4,
            1.319_996_043_913_366_116_7e-1,
            1.378_936_078_070_656_053,
        ),
    ];
    for (z, u, a) in table {
        let p = m.energy_point(z).unwrap();
        assert!(
            rel(p.full_contact_energy, u) < ENERGY_TOL,
            "{z}: {}",
            p.full_contact_energy
        );
        assert!(
            rel(p.true_area_ratio, a) < ENERGY_TOL,
            "{z}: {}",
            p.true_area_ratio
        );
    }
}

#[test]
fn stickiness_verdict_and_transition() {
    let s = rubber_spectrum();
    // Δγ_eff(ζ_max) = 0.05·1.3789 − 0.1320 < 0: not sticky; Δγ_eff(1) = Δγ > 0
    let m = AdhesionModel::new(&s, 1e6, 0.05).unwrap();
    let st = m.stickiness(&[1.0, 1e4]).unwrap();
    assert!(!st.sticky);
    assert!(st.points[0].sticky);
    assert_eq!(st.stickiness_transitions.len(), 1);
    let zc = st.stickiness_transitions[0];
    let at = m.energy_point(zc).unwrap();
    // the root of Δγ_eff to the rounding of its terms
    assert!(
        at.effective_interfacial_energy.abs() <= 4.0 * at.effective_interfacial_energy_error_bound,
        "{zc}: {}",
        at.effective_interfacial_energy
    );
    // the threshold Δγ puts Δγ_eff(ζ_max) at zero
    let thr = st.threshold_work_of_adhesion;
    let e = 0.131_999_604_391_336_611_67 / 1.378_936_078_070_656_053;
    assert!(rel(thr, e) < ENERGY_TOL, "{thr} vs {e}");
    let just_above = AdhesionModel::new(&s, 1e6, thr * (1.0 + 1e-9)).unwrap();
    assert!(just_above.stickiness(&[]).unwrap().sticky);
    // without the area enhancement the threshold is U_el itself
    let flat = m.with_area_enhancement(AreaEnhancement::None);
    let thr_flat = flat.stickiness(&[]).unwrap().threshold_work_of_adhesion;
    assert!(rel(thr_flat, 0.131_999_604_391_336_611_67) < ENERGY_TOL);
}

#[test]
fn zero_work_of_adhesion_reproduces_the_non_adhesive_area() {
    for s in [test_spectrum(), rubber_spectrum()] {
        let e = if s.q_min() == 1.0 { 1.0 } else { 1e6 };
        let theory = Persson::new(&s, e).unwrap();
        let c = AdhesiveContact::new(AdhesionModel::new(&s, e, 0.0).unwrap());
        let top = s.q_max() / s.q_min();
        let zetas = [1.0, 1.7, 10.0, top];
        for sigma0 in [1e-3 * e, 0.05 * e, 0.3 * e] {
            let pts = c.magnification_curve(sigma0, &zetas).unwrap();
            for p in pts {
                let a = theory.point(p.zeta, sigma0).unwrap().contact_fraction;
                assert!(
                    (p.contact_fraction - a).abs() < NON_ADHESIVE_TOL,
                    "σ0 = {sigma0}, ζ = {}: {} vs {a}",
                    p.zeta,
                    p.contact_fraction
                );
                assert_eq!(p.tensile_fraction, 0.0);
                assert_eq!(p.released_tension, 0.0);
            }
        }
    }
}

#[test]
fn adhesive_area_matches_the_finite_difference_reference() {
    // (Δγ, σ0, ζ, A/A0, tensile, carried): adhesion_diffusion_fd.py
    let table = [
        (
            0.01,
            0.05,
            100.0,
            0.976_892_325_966_274_1,
            0.401_858_816_816_994_9,
            0.055_151_056_231_873_32,
        ),
        (
            0.01,
            0.0,
            100.0,
            0.911_543_889_918_909_9,
            0.432_425_532_871_708_9,
            0.015_758_443_638_036_985,
        ),
        (
            0.01,
            -0.03,
            100.0,
            0.802_225_742_611_548_8,
            0.404_114_609_673_612_7,
            -0.000_410_796_156_946_811_34,
        ),
        (
            0.01,
            0.05,
            10.0,
            0.980_220_249_254_723_6,
            0.327_729_562_560_086_23,
            0.053_834_245_982_359_89,
        ),
    ];
    let s = test_spectrum();
    for (dg, sigma0, zeta, a, at, l) in table {
        let m = AdhesionModel::new(&s, 1.0, dg).unwrap();
        let c = AdhesiveContact::new(m).with_tolerance(1e-6).unwrap();
        let p = c.point(sigma0, zeta).unwrap();
        assert!(p.flags.is_empty(), "{:?}", p.flags);
        assert!(p.contact_fraction_error_bound <= 1e-6);
        assert!(
            (p.contact_fraction - a).abs() < FD_AREA_TOL,
            "σ0 = {sigma0}, ζ = {zeta}: {} vs {a}",
            p.contact_fraction
        );
        assert!(
            (p.tensile_fraction - at).abs() < FD_TENSILE_TOL,
            "{}",
            p.tensile_fraction
        );
        assert!(
            (p.carried_pressure - l).abs() < FD_CARRIED_TOL,
            "{}",
            p.carried_pressure
        );
    }
}

#[test]
fn the_error_estimate_tightens_with_the_tolerance() {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let fd = 0.911_543_889_918_909_9; // σ0 = 0, ζ = 100 (the reference's error ~1e-8 here)
    let mut last = f64::INFINITY;
    for tol in [1e-3, 1e-5, 1e-7] {
        let p = AdhesiveContact::new(m)
            .with_tolerance(tol)
            .unwrap()
            .point(0.0, 100.0)
            .unwrap();
        assert!(p.contact_fraction_error_bound <= tol);
        assert!(p.contact_fraction_error_bound <= last);
        assert!(
            (p.contact_fraction - fd).abs() <= p.contact_fraction_error_bound + 1e-8,
            "{tol}: {} vs {fd} ± {}",
            p.contact_fraction,
            p.contact_fraction_error_bound
        );
        last = p.contact_fraction_error_bound;
    }
}

#[test]
fn normalisation_and_load_balance_hold() {
    let s = test_spectrum();
    for dg in [0.004, 0.01] {
        let m = AdhesionModel::new(&s, 1.0, dg).unwrap();
        // 1e-4: the onset of σ_a at Δγ = 0.004 converges slowly (h^1.2)
        let c = AdhesiveContact::new(m).with_tolerance(1e-4).unwrap();
        for sigma0 in [-0.02, 0.0, 0.05, 0.2] {
            let pts = c.magnification_curve(sigma0, &[3.0, 30.0, 100.0]).unwrap();
            for p in pts {
                if p.flags.contains(&Flag::Detached) {
                    continue;
                }
                // ∫P dσ + detached = 1: two independent sums of one solution
                let norm = p.contact_fraction + p.non_contact_fraction - 1.0;
                let bound = p.contact_fraction_error_bound + p.non_contact_fraction_error_bound;
                assert!(
                    norm.abs() <= bound,
                    "{dg} {sigma0} {}: {norm:e} > {bound:e}",
                    p.zeta
                );
                // σ0 = ∫σP dσ − ∫σ_a dA_detached (the tensile part released)
                let load = p.carried_pressure - p.released_tension - sigma0;
                let bound = p.carried_pressure_error_bound + p.released_tension_error_bound;
                assert!(
                    load.abs() <= bound,
                    "{dg} {sigma0} {}: {load:e} > {bound:e}",
                    p.zeta
                );
                assert!(p.tensile_fraction >= -p.tensile_fraction_error_bound);
                assert!(p.tensile_fraction <= p.contact_fraction + p.contact_fraction_error_bound);
            }
        }
    }
}

#[test]
fn pull_off_stress_and_tensile_branch() {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let sp = m.pull_off_stress().unwrap();
    // σ_p = √(γ_eff(1) E* q_l), mpmath: γ_eff(1) = 0.0053294237297993968118
    assert!(
        rel(sp.value, 0.073_002_902_201_209_759_93) < ENERGY_TOL,
        "{}",
        sp.value
    );
    let c = AdhesiveContact::new(m);
    // A/A0 at full magnification falls monotonically to 0 as σ0 → −σ_p
    let mut last = f64::INFINITY;
    for f in [0.5, 0.0, -0.5, -0.9, -0.99, -0.999] {
        let p = c.point(f * sp.value, 100.0).unwrap();
        assert!(p.contact_fraction < last, "{f}: {}", p.contact_fraction);
        last = p.contact_fraction;
    }
    // near pull-off the surviving contact vanishes linearly in the distance d = σ0 + σ_p
    let a1 = c.point(-0.999 * sp.value, 100.0).unwrap().contact_fraction;
    let a2 = c.point(-0.9995 * sp.value, 100.0).unwrap().contact_fraction;
    assert!((a1 / a2 - 2.0).abs() < 0.05, "{a1} {a2}");
    // beyond it nothing is in contact
    let p = c.point(-1.0001 * sp.value, 100.0).unwrap();
    assert_eq!(p.contact_fraction, 0.0);
    assert_eq!(p.flags, vec![Flag::Detached]);
    // not sticky by the whole band's balance: σ_p = 0, σ0 = 0 is detached
    let weak = AdhesionModel::new(&s, 1.0, 0.004).unwrap();
    assert_eq!(weak.pull_off_stress().unwrap().value, 0.0);
    let p = AdhesiveContact::new(weak).point(0.0, 100.0).unwrap();
    assert_eq!(p.flags, vec![Flag::Detached]);
    // … yet adhesion at the finer scales raises A/A0 above the non-adhesive value
    let theory = Persson::new(&s, 1.0).unwrap();
    let p = AdhesiveContact::new(weak).point(0.05, 100.0).unwrap();
    let a0 = theory.point(100.0, 0.05).unwrap().contact_fraction;
    assert!(
        p.contact_fraction > 3.0 * a0,
        "{} vs {a0}",
        p.contact_fraction
    );
}

#[test]
fn pastewka_robbins_beside_persson_tosatti() {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let range = 1e-3;
    let pr = m.pastewka_robbins(range).unwrap();
    // h'' = 22.673198827806926842 (mpmath), h' = 0.5, d_rep = 4h'/h''
    let h2 = 22.673_198_827_806_926_842;
    assert!(rel(pr.rms_curvature, h2) < ENERGY_TOL);
    let d_rep = 4.0 * 0.5 / h2;
    let threshold = 0.5 * 1.0 * range / 2.0 * (0.5 * d_rep / (4.0 * range)).powf(2.0 / 3.0);
    assert!(rel(pr.threshold_work_of_adhesion, threshold) < 1e-12);
    assert!(rel(pr.stickiness_parameter, threshold / 0.01) < 1e-12);
    assert_eq!(pr.sticky, threshold < 0.01);
    assert!(pr.short_range); // Δr/g0 = 1e-3/(16/3·0.25/22.67) ≈ 0.017
    let cmp = m.compare_stickiness(range).unwrap();
    assert!(cmp.persson_tosatti); // Δγ = 0.01 > 0.0052
    assert_eq!(cmp.pastewka_robbins, pr.sticky);
    assert_eq!(cmp.agree, cmp.persson_tosatti == cmp.pastewka_robbins);
    assert!(
        rel(
            cmp.persson_tosatti_threshold,
            5.802_268_895_153_539_636_6e-3 / 1.113_169_262_495_293_644_8
        ) < ENERGY_TOL
    );
}

#[test]
fn bad_input_names_the_field() {
    let s = test_spectrum();
    let expect = |r: Result<(), persson::Error>, name: &str| {
        let e = r.err().unwrap_or_else(|| panic!("{name}: no error"));
        assert!(e.to_string().contains(name), "{name}: {e}");
    };
    expect(
        AdhesionModel::new(&s, 1.0, -0.01).map(|_| ()),
        "work_of_adhesion",
    );
    expect(
        AdhesionModel::new(&s, 1.0, f64::NAN).map(|_| ()),
        "work_of_adhesion",
    );
    expect(
        AdhesionModel::new(&s, f64::NAN, 0.01).map(|_| ()),
        "contact_modulus",
    );
    expect(
        AdhesionModel::new(&s, 0.0, 0.01).map(|_| ()),
        "contact_modulus",
    );
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    expect(
        m.with_detachment_prefactor(-1.0).map(|_| ()),
        "detachment_prefactor",
    );
    expect(m.pastewka_robbins(0.0).map(|_| ()), "adhesion_range");
    expect(m.pastewka_robbins(f64::NAN).map(|_| ()), "adhesion_range");
    expect(
        AdhesionModel::new(&s, 1.0, 0.0)
            .unwrap()
            .pastewka_robbins(1e-3)
            .map(|_| ()),
        "work_of_adhesion",
    );
    expect(m.energy_point(0.5).map(|_| ()), "zeta");
    expect(m.energy_point(f64::NAN).map(|_| ()), "zeta");
    expect(m.energy_point(1e3).map(|_| ()), "zeta");
    expect(true_area_ratio(-1.0).map(|_| ()), "slope_variance");
    let c = AdhesiveContact::new(m);
    expect(c.point(f64::NAN, 10.0).map(|_| ()), "nominal_pressure");
    expect(c.point(f64::INFINITY, 10.0).map(|_| ()), "nominal_pressure");
    expect(c.point(0.01, 0.0).map(|_| ()), "zeta");
    expect(c.with_tolerance(0.0).map(|_| ()), "tolerance");
    expect(c.with_nodes(1, 100).map(|_| ()), "nodes_per_e_fold");
    expect(c.with_nodes(8, 4).map(|_| ()), "max_nodes");
}

#[test]
fn at_the_stickiness_threshold_the_solver_stays_finite() {
    // Δγ at the threshold: γ_eff(1) = 0 to rounding, σ_a(ζ) starts from 0 at ζ = 1
    let s = test_spectrum();
    let thr = AdhesionModel::new(&s, 1.0, 1.0)
        .unwrap()
        .stickiness(&[])
        .unwrap()
        .threshold_work_of_adhesion;
    for k in [1.0 - 1e-12, 1.0, 1.0 + 1e-12] {
        let m = AdhesionModel::new(&s, 1.0, k * thr).unwrap();
        let p = AdhesiveContact::new(m).point(0.05, 100.0).unwrap();
        assert!(p.contact_fraction.is_finite() && p.contact_fraction_error_bound.is_finite());
        let a0 = Persson::new(&s, 1.0)
            .unwrap()
            .point(100.0, 0.05)
            .unwrap()
            .contact_fraction;
        assert!(
            p.contact_fraction > a0 && p.contact_fraction < 1.0,
            "{k}: {}",
            p.contact_fraction
        );
    }
}

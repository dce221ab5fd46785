//! Rubber friction (src/friction): limits that hold exactly, the double
//! integrals against an independent quadrature, the flash temperature's
//! closed-form limits and an independent ODE solution, bad input.

use std::f64::consts::{PI, TAU};
use std::path::Path;

use persson::friction::{
    heat_kernel, log_velocities, CutOff, FrequencyUnit, Friction, FrictionOptions, FrictionPoint,
    MasterCurve, Prony, PronyTerm, Rubber, ShiftTable, TemperatureShift, Thermal, VerticalShift,
    Viscoelastic,
};
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::Error;

/// Reference temperature of the test rubbers, K.
const T_REF: f64 = 293.15;

/// Relative tolerance asked of the solver in the accuracy tests.
const TIGHT: f64 = 1e-12;

/// μ, G, A/A0 against an independent quadrature (issue 26 asks 1e-10): the
/// solver runs at 1e-12 and the scipy reference is good to ~1e-13 (measured
/// agreement ≤ 1.4e-13).
const REFERENCE_TOL: f64 = 1e-12;

/// The closed-form flash limits (solver at 1e-11; measured ≤ 3e-15: the
/// integrands there are C's power laws times constants).
const FLASH_LIMIT_TOL: f64 = 1e-12;

/// The flash temperature against composite Simpson with 2×10⁵ intervals
/// (its h⁴ error ~1e-15; measured agreement 3e-14).
const SIMPSON_TOL: f64 = 1e-12;

/// The coupled flash problem against RK4 (its own error, from halving the
/// step, is ~2e-13; measured agreement ≤ 1.6e-13).
const RK4_TOL: f64 = 1e-11;

/// A master curve sampled at 40 points per decade against the analytic SLS:
/// log-log interpolation of a Debye peak errs by ~(Δ ln ω)²/8 ≈ 4e-4 times its
/// log-log curvature (≤ 1/4 here); measured ≤ 3.3e-5 in μ.
const SAMPLED_TABLE_TOL: f64 = 1e-4;

/// With a conductivity 10⁶ times rubber's the flash temperature is below
/// this (K) and μ changes by less than this relative amount.
const FAST_CONDUCTION_TOL: f64 = 1e-6;

/// rms slope of the cut-off (bisection on the exact moment, 200 halvings).
const CUTOFF_TOL: f64 = 1e-12;

/// Identities that hold term by term (same nodes, same arithmetic up to the
/// order of a few products): a few hundred ulps over ~10³ panel sums.
const IDENTITY_TOL: f64 = 1e-13;

/// The self-affine spectrum of every test: q_l = 1e2, q_r = 1e3, q_s = 1e7
/// (1/m), H = 0.8, C_r = 1e-15 m⁴ (rms slope 0.78).
fn spectrum() -> SelfAffine {
    SelfAffine::new(1e2, 1e3, 1e7, 0.8, Amplitude::CR(1e-15)).unwrap()
}

fn options(tolerance: f64) -> FrictionOptions {
    FrictionOptions {
        tolerance,
        breaks: vec![1e3],
        ..Default::default()
    }
}

/// A frequency-independent modulus E1 + i E2 (a constant three-point table).
fn constant_modulus(e1: f64, e2: f64) -> MasterCurve {
    MasterCurve::new(&[(1.0, e1, e2), (10.0, e1, e2), (100.0, e1, e2)]).unwrap()
}

/// The standard linear solid of tests/reference/friction_sls.py.
fn sls() -> Prony {
    Prony::standard_linear_solid(3e8, 3e6, 1e-4).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        ((a - b) / b).abs()
    }
}

fn mu(p: &FrictionPoint) -> f64 {
    p.isothermal.friction_coefficient
}

// (nominal_pressure, velocity, friction_coefficient, g, contact_fraction):
// scipy DOP853 + QUADPACK, tests/reference/friction_sls.py (rtol 1e-12 and
// 1e-13 agree to 1e-11; the angular integrals agree with mpmath to 1e-13).
#[allow(clippy::excessive_precision)] // the references keep 17 digits
const SLS_REFERENCE: [(f64, f64, f64, f64, f64); 16] = [
    (
        1e5,
        1e-9,
        5.312_546_358_966_599_5e-6,
        1.222_415_915_352_849_5e2,
        5.099_405_917_792_128_3e-2,
    ),
    (
        1e5,
        1e-8,
        5.312_546_274_528_188_9e-5,
        1.222_416_018_524_503_4e2,
        5.099_405_702_890_973_1e-2,
    ),
    (
        1e5,
        1e-7,
        5.312_537_830_721_031_2e-4,
        1.222_426_335_689_778_8e2,
        5.099_384_212_912_856_7e-2,
    ),
    (
        1e5,
        1e-6,
        5.311_693_783_255_815_4e-3,
        1.223_458_051_795_305_7e2,
        5.097_236_587_047_612_7e-2,
    ),
    (
        1e5,
        1e-5,
        5.230_459_355_389_482_9e-2,
        1.326_625_442_355_804_4e2,
        4.895_287_067_895_613e-2,
    ),
    (
        1e5,
        1e-4,
        3.068_339_778_008_225e-1,
        1.160_140_474_347_527_3e3,
        1.656_298_390_238_369_9e-2,
    ),
    (
        1e5,
        1e-3,
        5.542_615_741_081_892_1e-1,
        7.659_252_137_915_033_4e4,
        2.038_597_127_367_536_7e-3,
    ),
    (
        1e5,
        1e-2,
        4.730_939_788_178_167_3e-1,
        5.624_325_954_840_605_9e5,
        7.522_977_419_693_238_4e-4,
    ),
    (
        1e5,
        1e-1,
        3.221_331_759_587_064_4e-1,
        9.518_728_088_179_768_5e5,
        5.782_765_284_337_714_2e-4,
    ),
    (
        1e5,
        1e0,
        1.748_669_217_917_724_9e-1,
        1.129_226_462_171_720_1e6,
        5.309_266_289_600_491_1e-4,
    ),
    (
        1e5,
        1e1,
        6.094_974_827_301_263_1e-2,
        1.200_857_769_772_233_9e6,
        5.148_482_576_310_661_5e-4,
    ),
    (
        1e5,
        1e2,
        9.639_423_066_403_165_4e-3,
        1.219_919_372_023_222_5e6,
        5.108_100_932_833_220_4e-4,
    ),
    (
        1e5,
        1e3,
        1.027_504_232_822_876_9e-3,
        1.222_165_495_691_547_9e6,
        5.103_404_882_559_850_9e-4,
    ),
    (
        3e6,
        1e-6,
        5.536_126_166_953_248_7e-3,
        1.359_397_835_328_117_5e-1,
        9.448_683_298_023_549_1e-1,
    ),
    (
        3e6,
        1e-2,
        4.510_844_085_714_972_3e-1,
        6.249_251_060_934_002_5e2,
        2.256_592_641_213_201_3e-2,
    ),
    (
        3e6,
        1e2,
        9.196_782_088_788_555_2e-3,
        1.355_465_968_914_69e3,
        1.532_336_176_731_474_9e-2,
    ),
];

/// The scipy reference's own accuracy (its two runs agree to 1e-11).
const SCIPY_TOL: f64 = 1e-11;

#[test]
fn sls_double_integrals_match_an_independent_quadrature() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::none(T_REF).unwrap());
    let f = Friction::new(&s, &rubber, &options(TIGHT)).unwrap();
    for (sigma0, v, mu_ref, g_ref, a_ref) in SLS_REFERENCE {
        let p = f.point(v, T_REF, sigma0).unwrap();
        let r = &p.isothermal;
        assert!(r.converged, "v = {v}");
        let (e_mu, e_g, e_a) = (
            rel(r.friction_coefficient, mu_ref),
            rel(r.g, g_ref),
            rel(r.contact_fraction, a_ref),
        );
        assert!(
            e_mu <= REFERENCE_TOL && e_g <= REFERENCE_TOL && e_a <= REFERENCE_TOL,
            "σ0 {sigma0} v {v}: μ {e_mu:e}, G {e_g:e}, A {e_a:e}"
        );
        // The bounds are honest: they cover the difference (up to the reference's accuracy).
        let slack = SCIPY_TOL * mu_ref;
        assert!(
            (r.friction_coefficient - mu_ref).abs() <= r.friction_coefficient_error_bound + slack,
            "μ bound at v {v}"
        );
        assert!(
            (r.g - g_ref).abs() <= r.g_error_bound + SCIPY_TOL * g_ref,
            "G bound at v {v}"
        );
        // The decades add up to μ, the profile ends at the result.
        let sum: f64 = r.decades.iter().map(|d| d.friction_coefficient).sum();
        assert!(rel(sum, r.friction_coefficient) <= IDENTITY_TOL);
        let last = r.profile.last().unwrap();
        assert_eq!(
            (last.g, last.friction_coefficient),
            (r.g, r.friction_coefficient)
        );
        assert_eq!(r.decades.len(), 5);
    }
}

#[test]
fn loss_free_rubber_has_no_friction_and_the_elastic_g() {
    let s = spectrum();
    let (e, sigma0) = (5e6, 2e5);
    let rubber = Rubber::new(
        Prony::new(e, &[]).unwrap(),
        TemperatureShift::none(T_REF).unwrap(),
    )
    .with_thermal(Thermal::new(0.2, 1100.0, 1800.0).unwrap());
    let f = Friction::new(&s, &rubber, &options(TIGHT)).unwrap();
    // Elastic G = (π/4)(E*/σ0)² m3 (the crate's exact moment).
    let m3 = s.moment(3, 1e2, 1e7).unwrap().value;
    let g = PI / 4.0 * (e / (0.75 * sigma0)).powi(2) * m3;
    for v in [1e-9, 1e-3, 1e3] {
        let p = f.point(v, T_REF, sigma0).unwrap();
        let flash = p.flash.as_ref().unwrap();
        assert_eq!(mu(&p), 0.0);
        assert_eq!(flash.friction_coefficient, 0.0);
        assert_eq!(flash.flash_temperature, 0.0);
        assert!(
            rel(p.isothermal.g, g) <= IDENTITY_TOL,
            "{} vs {g}",
            p.isothermal.g
        );
        let a = libm::erf(0.5 / g.sqrt());
        assert!(rel(p.isothermal.contact_fraction, a) <= IDENTITY_TOL);
    }
}

// (nominal_pressure, gamma, friction_coefficient, g): tests/reference/friction_limits.py.
#[allow(clippy::excessive_precision)] // the references keep 20 digits
const CONSTANT_LOSS: [(f64, f64, f64, f64); 6] = [
    (
        1e5,
        0.5,
        9.881_684_919_024_912_7e-2,
        5.772_519_595_356_141_5e1,
    ),
    (
        1e5,
        1.0,
        1.816_718_519_828_358_5e-1,
        5.772_519_595_356_141_5e1,
    ),
    (
        1e3,
        0.5,
        9.634_307_926_151_699_5e-2,
        5.772_519_595_356_141_5e5,
    ),
    (
        1e3,
        1.0,
        1.925_160_396_210_288_8e-1,
        5.772_519_595_356_141_5e5,
    ),
    (
        1e9,
        0.5,
        1.297_023_568_511_657_5e-4,
        5.772_519_595_356_141_5e-7,
    ),
    (
        1e9,
        1.0,
        1.297_023_568_511_657_5e-4,
        5.772_519_595_356_141_5e-7,
    ),
];

/// A frequency-independent loss modulus: μ independent of v and equal to the
/// closed form (γ = 1) or its one-dimensional integral (γ = ½); σ0 = 1e3 is
/// the rigid side (G ≈ 6e5, A/A0 ≈ 7e-4), σ0 = 1e9 the full-contact side
/// (G ≈ 6e-7, P → 1: μ = 2 E2 m3/((1 − ν²) σ0)).
#[test]
fn constant_loss_modulus_gives_a_velocity_independent_closed_form() {
    let s = spectrum();
    let rubber = Rubber::new(
        constant_modulus(2e6, 5e5),
        TemperatureShift::none(T_REF).unwrap(),
    );
    for (sigma0, gamma, mu_ref, g_ref) in CONSTANT_LOSS {
        let opts = FrictionOptions {
            gamma,
            ..options(TIGHT)
        };
        let f = Friction::new(&s, &rubber, &opts).unwrap();
        for v in [1e-9, 1e-5, 1e-1, 1e3] {
            let p = f.point(v, T_REF, sigma0).unwrap();
            let r = &p.isothermal;
            assert!(
                rel(r.friction_coefficient, mu_ref) <= REFERENCE_TOL,
                "σ0 {sigma0} γ {gamma} v {v}: {} vs {mu_ref}",
                r.friction_coefficient
            );
            assert!(rel(r.g, g_ref) <= REFERENCE_TOL);
            // At v = 1e-9 every frequency q v cos φ ≤ 1e-2 rad/s is below the
            // table (1 to 100 rad/s): all of μ comes from outside it.
            let x = r.table_excursion.unwrap();
            if v == 1e-9 {
                assert!((x.friction_fraction - 1.0).abs() <= IDENTITY_TOL, "{x:?}");
                assert!((x.decades_below - 7.0).abs() <= IDENTITY_TOL, "{x:?}");
            }
        }
    }
}

#[test]
fn time_temperature_superposition_is_a_velocity_shift() {
    let s = spectrum();
    let table: Vec<(f64, f64, f64)> = (0..25)
        .map(|i| {
            let w = 10f64.powf(1.0 + 0.25 * i as f64);
            let e = sls().modulus(w);
            (w, e.storage_modulus, e.loss_modulus)
        })
        .collect();
    for v in [
        Viscoelastic::from(sls()),
        Viscoelastic::from(MasterCurve::new(&table).unwrap()),
    ] {
        let rubber = Rubber::new(v, TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap());
        let f = Friction::new(&s, &rubber, &options(1e-10)).unwrap();
        for t in [T_REF - 40.0, T_REF + 25.0, T_REF + 120.0] {
            let a_t = rubber.shift_factors(t).unwrap().shift_factor;
            for v in [1e-6, 1e-2, 10.0] {
                let hot = mu(&f.point(v, t, 1e5).unwrap());
                let cold = mu(&f.point(a_t * v, T_REF, 1e5).unwrap());
                assert!(
                    rel(hot, cold) <= IDENTITY_TOL,
                    "T {t} v {v}: {hot} vs {cold}"
                );
            }
        }
        // With b_T = T/T_ref: μ(v, T, σ0) = μ(a_T v, T_ref, σ0/b_T).
        let shift = TemperatureShift::wlf(T_REF, 8.86, 101.6)
            .unwrap()
            .with_vertical(VerticalShift::Entropic)
            .unwrap();
        let rubber = Rubber::new(rubber.viscoelastic().clone(), shift);
        let f = Friction::new(&s, &rubber, &options(1e-10)).unwrap();
        let t = T_REF + 30.0;
        let fac = rubber.shift_factors(t).unwrap();
        let hot = mu(&f.point(1e-3, t, 1e5).unwrap());
        let cold = mu(&f
            .point(fac.shift_factor * 1e-3, T_REF, 1e5 / fac.vertical_shift)
            .unwrap());
        assert!(rel(hot, cold) <= IDENTITY_TOL, "{hot} vs {cold}");
    }
}

/// μ depends on E and σ0 only through E/σ0: scaling both by λ up to 1e12
/// (E up to 3e20 Pa, far into the rigid limit in absolute terms) changes
/// nothing beyond rounding.
#[test]
fn rigid_limit_at_fixed_modulus_over_pressure() {
    let s = spectrum();
    let at = |lambda: f64| {
        let p = Prony::standard_linear_solid(3e8 * lambda, 3e6 * lambda, 1e-4).unwrap();
        let rubber = Rubber::new(p, TemperatureShift::none(T_REF).unwrap());
        let f = Friction::new(&s, &rubber, &options(1e-10)).unwrap();
        let p = f.point(1e-2, T_REF, 1e5 * lambda).unwrap();
        (
            p.isothermal.friction_coefficient,
            p.isothermal.contact_fraction,
        )
    };
    let base = at(1.0);
    for lambda in [1e-3, 1e6, 1e12] {
        let (m, a) = at(lambda);
        assert!(
            rel(m, base.0) <= IDENTITY_TOL && rel(a, base.1) <= IDENTITY_TOL,
            "λ {lambda}: {m} vs {}",
            base.0
        );
    }
}

#[test]
fn cutoff_by_rms_slope_and_its_bounds() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::none(T_REF).unwrap());
    let opts = FrictionOptions {
        cutoff: CutOff::RmsSlope(0.5),
        ..options(1e-8)
    };
    let f = Friction::new(&s, &rubber, &opts).unwrap();
    let slope = s.rms_slope(1e2, f.q1()).unwrap().value;
    assert!((slope - 0.5).abs() <= CUTOFF_TOL, "{slope}");
    let p = f.point(1.0, T_REF, 1e5).unwrap();
    assert_eq!(p.q1, f.q1());
    assert!(p.isothermal.profile.last().unwrap().q == f.q1());
    // Too steep a target, q1 outside the band: errors naming the field.
    for (c, name) in [
        (CutOff::RmsSlope(10.0), "q1_rms_slope"),
        (CutOff::RmsSlope(f64::NAN), "q1_rms_slope"),
        (CutOff::Wavevector(1e8), "q1"),
        (CutOff::Wavevector(1e2), "q1"),
        (CutOff::Wavevector(f64::INFINITY), "q1"),
    ] {
        let opts = FrictionOptions {
            cutoff: c,
            ..options(1e-8)
        };
        let e = Friction::new(&s, &rubber, &opts).err().expect("an error");
        assert!(
            matches!(&e, Error::InvalidParameter { name: n, .. } if n == name),
            "{c:?}: {e}"
        );
    }
}

/// The flash temperature of a temperature-independent rubber with γ = 1 (S = 1),
/// E = E1 + i E2 constant: ΔT = 4 v E2/((1 − ν²) ρc) ∫ q⁴ C h(q) dq.
/// Adiabatic (D → 0, h = π/(qv)): ΔT = 2 E2 h′²_rms/((1 − ν²) ρc).
/// Steady (x² = πDq/v ≫ 1, h = 1/(3Dq²)): ΔT = 4 v E2 m2/(3 (1 − ν²) κ).
#[test]
fn flash_temperature_limits_in_closed_form() {
    let s = spectrum();
    let (e2, rho, c) = (5e5, 1200.0, 1500.0);
    let opts = FrictionOptions {
        gamma: 1.0,
        ..options(1e-11)
    };
    let run = |kappa: f64, v: f64| {
        let rubber = Rubber::new(
            constant_modulus(2e6, e2),
            TemperatureShift::none(T_REF).unwrap(),
        )
        .with_thermal(Thermal::new(kappa, rho, c).unwrap());
        let f = Friction::new(&s, &rubber, &opts).unwrap();
        f.point(v, T_REF, 1e5).unwrap()
    };
    let slope2 = TAU * s.moment(3, 1e2, 1e7).unwrap().value;
    let p = run(1e-30, 1.0);
    let flash = p.flash.as_ref().unwrap();
    let adiabatic = 2.0 * e2 * slope2 / (0.75 * rho * c);
    assert!(
        rel(flash.flash_temperature, adiabatic) <= FLASH_LIMIT_TOL,
        "{} vs {adiabatic}",
        flash.flash_temperature
    );
    assert_eq!(flash.friction_coefficient, mu(&p)); // E does not depend on T
    let kappa = 1.8e3; // D = 1e-3 m²/s
    let (v, m2) = (1e-9, s.moment(2, 1e2, 1e7).unwrap().value);
    let steady = 4.0 * v * e2 * m2 / (3.0 * 0.75 * kappa);
    let got = run(kappa, v).flash.unwrap().flash_temperature;
    assert!(rel(got, steady) <= FLASH_LIMIT_TOL, "{got} vs {steady}");
}

/// Between the limits: the kernel integral by composite Simpson in ln q.
#[test]
fn flash_temperature_of_a_temperature_independent_rubber() {
    let s = spectrum();
    let (e2, kappa, rho, c, v) = (5e5, 0.25, 1200.0, 1500.0, 1e-2);
    let thermal = Thermal::new(kappa, rho, c).unwrap();
    let rubber = Rubber::new(
        constant_modulus(2e6, e2),
        TemperatureShift::none(T_REF).unwrap(),
    )
    .with_thermal(thermal);
    let opts = FrictionOptions {
        gamma: 1.0,
        ..options(1e-11)
    };
    let got = Friction::new(&s, &rubber, &opts)
        .unwrap()
        .point(v, T_REF, 1e5)
        .unwrap();
    let profile = &got.flash.as_ref().unwrap().profile;
    let d = thermal.thermal_diffusivity();
    let integrand = |x: f64| {
        let q = x.exp().clamp(1e2, 1e7); // e^{ln q} may round past the band
        q * q.powi(4) * s.c(q) * heat_kernel(q, v, d)
    };
    let k = 4.0 * v * e2 / (0.75 * rho * c);
    // Simpson on each side of the roll-off kink; 2×10⁵ intervals: error ~1e-15.
    let simpson = |a: f64, b: f64| {
        let n = 200_000;
        let h = (b - a) / n as f64;
        (0..=n)
            .map(|i| {
                integrand(a + i as f64 * h)
                    * if i == 0 || i == n {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    }
            })
            .sum::<f64>()
            * h
            / 3.0
    };
    let (l, r, e) = (1e2f64.ln(), 1e3f64.ln(), 1e7f64.ln());
    let want = k * (simpson(l, r) + simpson(r, e));
    let last = profile.last().unwrap();
    assert!(
        rel(last.flash_temperature, want) <= SIMPSON_TOL,
        "{} vs {want}",
        last.flash_temperature
    );
    // The profile rises monotonically from 0 at ζ = 1.
    assert_eq!(profile[0].flash_temperature, 0.0);
    assert!(profile
        .windows(2)
        .all(|w| w[1].flash_temperature >= w[0].flash_temperature));
}

/// The coupled flash problem (WLF rubber: T_q feeds back into E in μ, G and
/// the heating) against a classical RK4 integration of the same ODE system in
/// ln q, written here from the public pieces (Prony::angular, heat_kernel,
/// the shift factors). RK4 at 2×10⁴ steps per segment, checked against 10⁴.
#[test]
fn flash_feedback_against_runge_kutta() {
    let s = spectrum();
    let sls = sls();
    let shift = TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap();
    let thermal = Thermal::new(0.25, 1200.0, 1500.0).unwrap();
    let rubber = Rubber::new(sls.clone(), shift.clone()).with_thermal(thermal);
    let (v, sigma0, gamma) = (0.3, 1e5, 0.5);
    let f = Friction::new(&s, &rubber, &options(1e-10)).unwrap();
    let p = f.point(v, T_REF, sigma0).unwrap();
    let flash = p.flash.as_ref().unwrap();
    let (k, d, rc) = (
        1.0 / (0.75 * sigma0),
        thermal.thermal_diffusivity(),
        thermal.volumetric_heat_capacity(),
    );
    // y = (T, G, μ); x = ln q.
    let rhs = |x: f64, y: [f64; 3]| -> [f64; 3] {
        let q = x.exp().clamp(1e2, 1e7);
        let a_t = shift.factors(y[0]).unwrap().shift_factor;
        let ang = sls.angular(a_t * q * v);
        let q4c = q.powi(4) * s.c(q);
        let pp = if y[1] > 0.0 {
            libm::erf(0.5 / y[1].sqrt())
        } else {
            1.0
        };
        let ss = gamma + (1.0 - gamma) * pp * pp;
        [
            4.0 * v * q * q4c * ss * ang.loss * heat_kernel(q, v, d) / (0.75 * rc),
            0.5 * q4c * ang.modulus_squared * k * k,
            2.0 * q4c * ss * pp * ang.loss * k,
        ]
    };
    let rk4 = |n: usize| {
        let mut y = [T_REF, 0.0, 0.0];
        for (a, b) in [(1e2f64.ln(), 1e3f64.ln()), (1e3f64.ln(), 1e7f64.ln())] {
            let h = (b - a) / n as f64;
            for i in 0..n {
                let x = a + i as f64 * h;
                let add = |y: [f64; 3], k: [f64; 3], c: f64| {
                    [y[0] + c * k[0], y[1] + c * k[1], y[2] + c * k[2]]
                };
                let k1 = rhs(x, y);
                let k2 = rhs(x + h / 2.0, add(y, k1, h / 2.0));
                let k3 = rhs(x + h / 2.0, add(y, k2, h / 2.0));
                let k4 = rhs(x + h, add(y, k3, h));
                for j in 0..3 {
                    y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
                }
            }
        }
        y
    };
    let (fine, coarse) = (rk4(20_000), rk4(10_000));
    // RK4's own error (fourth order: fine − coarse ≈ 15 × the fine error).
    let rk_err = |j: usize| (fine[j] - coarse[j]).abs();
    assert!(
        rk_err(2) <= RK4_TOL * fine[2],
        "RK4 not converged: {}",
        rk_err(2)
    );
    let dt = flash.flash_temperature;
    assert!(dt > 5.0, "a flash temperature worth testing: {dt}");
    assert!(
        (T_REF + dt - fine[0]).abs() <= RK4_TOL * dt + rk_err(0),
        "T: {} vs {}",
        T_REF + dt,
        fine[0]
    );
    assert!(
        rel(flash.friction_coefficient, fine[2]) <= RK4_TOL,
        "μ: {} vs {}",
        flash.friction_coefficient,
        fine[2]
    );
    assert!(
        rel(flash.g, fine[1]) <= RK4_TOL,
        "G: {} vs {}",
        flash.g,
        fine[1]
    );
    assert!(flash.converged);
}

/// With a conductivity a million times rubber's, the flash temperature
/// vanishes and μ returns to its isothermal value.
#[test]
fn flash_temperature_vanishes_with_fast_conduction() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap())
        .with_thermal(Thermal::new(2.5e5, 1200.0, 1500.0).unwrap());
    let p = Friction::new(&s, &rubber, &options(1e-10))
        .unwrap()
        .point(1e-3, T_REF, 1e5)
        .unwrap();
    let flash = p.flash.unwrap();
    assert!(
        flash.flash_temperature < FAST_CONDUCTION_TOL,
        "{}",
        flash.flash_temperature
    );
    assert!(
        rel(
            flash.friction_coefficient,
            p.isothermal.friction_coefficient
        ) <= FAST_CONDUCTION_TOL
    );
}

/// A master curve (in Hz, from a file's text) sampled from the SLS at 40
/// points per decade gives the SLS's μ within the interpolation error.
#[test]
fn master_curve_file_reproduces_the_analytic_rubber() {
    let mut text = String::from("# f (Hz), E' (Pa), E'' (Pa): an SLS sampled\nf,E',E''\n");
    for i in 0..=16 * 40 {
        let f = 10f64.powf(-6.0 + i as f64 / 40.0);
        let e = sls().modulus(TAU * f);
        text += &format!("{f:e}, {:e}, {:e}\n", e.storage_modulus, e.loss_modulus);
    }
    let table =
        MasterCurve::from_bytes(Path::new("sls.csv"), text.as_bytes(), FrequencyUnit::Hertz)
            .unwrap();
    assert!((table.frequency_range().0 - TAU * 1e-6).abs() < 1e-20);
    let s = spectrum();
    let (a, b) = (
        Rubber::new(table, TemperatureShift::none(T_REF).unwrap()),
        Rubber::new(sls(), TemperatureShift::none(T_REF).unwrap()),
    );
    let (fa, fb) = (
        Friction::new(&s, &a, &options(1e-9)).unwrap(),
        Friction::new(&s, &b, &options(1e-9)).unwrap(),
    );
    for v in [1e-6, 1e-3, 1.0] {
        let (ma, mb) = (
            mu(&fa.point(v, T_REF, 1e5).unwrap()),
            mu(&fb.point(v, T_REF, 1e5).unwrap()),
        );
        assert!(rel(ma, mb) <= SAMPLED_TABLE_TOL, "v {v}: {ma} vs {mb}");
    }
}

/// A table used far outside its range says where and how much.
#[test]
fn table_excursion_is_reported() {
    let s = spectrum();
    let table = MasterCurve::new(&[(1e2, 3e6, 1e6), (1e3, 5e6, 2e6), (1e4, 9e6, 3e6)]).unwrap();
    let rubber = Rubber::new(table, TemperatureShift::none(T_REF).unwrap());
    let f = Friction::new(&s, &rubber, &options(1e-8)).unwrap();
    let p = f.point(1e-2, T_REF, 1e5).unwrap();
    let x = p.isothermal.table_excursion.unwrap();
    // Principal reduced frequencies q v from 1 to 1e5 rad/s against the table's 1e2..1e4.
    assert!(
        (x.decades_below - 2.0).abs() < IDENTITY_TOL
            && (x.decades_above - 1.0).abs() < IDENTITY_TOL,
        "{x:?}"
    );
    assert!(x.friction_fraction > 0.0 && x.friction_fraction < 1.0);
    assert!(x.g_fraction > 0.0 && x.g_fraction < 1.0);
    // Inside the table for q v in [1e2, 1e4]: v = 1, q in [1e2, 1e4] would need q1 = 1e4.
    let opts = FrictionOptions {
        cutoff: CutOff::Wavevector(1e4),
        ..options(1e-8)
    };
    let x = Friction::new(&s, &rubber, &opts)
        .unwrap()
        .point(1.0, T_REF, 1e5)
        .unwrap()
        .isothermal
        .table_excursion
        .unwrap();
    assert_eq!((x.decades_below, x.decades_above), (0.0, 0.0));
}

#[test]
fn master_curve_files_with_bad_rows_name_the_line() {
    let cases: [(&str, &str); 7] = [
        ("1 1e6 1e5\n10 1e6 1e5\n5 1e6 1e5\n", "x.txt:3"), // non-monotone
        ("1 1e6 1e5\n10 1e6 1e5\n10 2e6 1e5\n", "x.txt:3"), // repeated frequency
        ("# c\n1 1e6 1e5\n10 -1e6 1e5\n100 1e6 1e5\n", "x.txt:3"), // negative E′
        ("1 1e6 1e5\n10 1e6 NaN\n100 1e6 1e5\n", "x.txt:2"), // NaN E″
        ("1 1e6 1e5\n10 1e6 0\n100 1e6 1e5\n", "x.txt:2"), // E″ = 0
        ("1 1e6 1e5\n10 1e6 1e5\n", "fewer than 3"),       // too few
        ("1 1e6 1e5\n10 1e6\n100 1e6 1e5\n", "x.txt:2"),   // missing column
    ];
    for (text, want) in cases {
        let e = MasterCurve::from_bytes(
            Path::new("x.txt"),
            text.as_bytes(),
            FrequencyUnit::RadPerSecond,
        )
        .unwrap_err()
        .to_string();
        let want = if want == "fewer than 3" {
            "needs at least 3"
        } else {
            want
        };
        assert!(e.contains(want), "{text:?}: {e}");
        assert!(matches!(
            MasterCurve::from_bytes(Path::new("x.txt"), text.as_bytes(), FrequencyUnit::Hertz),
            Err(Error::Parse { .. })
        ));
    }
    let e =
        MasterCurve::from_file(Path::new("/no/such/file.txt"), FrequencyUnit::Hertz).unwrap_err();
    assert!(matches!(e, Error::Io { .. }));
}

#[test]
fn bad_input_names_the_field_and_never_gives_nan() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap());
    let f = Friction::new(&s, &rubber, &options(1e-8)).unwrap();
    let name_of = |e: Error| match e {
        Error::InvalidParameter { name, .. } => name,
        e => panic!("{e}"),
    };
    for (v, t, p, name) in [
        (0.0, T_REF, 1e5, "velocity"),
        (-1.0, T_REF, 1e5, "velocity"),
        (f64::NAN, T_REF, 1e5, "velocity"),
        (1.0, T_REF - 101.6, 1e5, "temperature"),
        (1.0, T_REF - 200.0, 1e5, "temperature"),
        (1.0, f64::NAN, 1e5, "temperature"),
        (1.0, T_REF, 0.0, "nominal_pressure"),
        (1.0, T_REF, f64::INFINITY, "nominal_pressure"),
    ] {
        assert_eq!(
            name_of(f.point(v, t, p).unwrap_err()),
            name,
            "({v}, {t}, {p})"
        );
    }
    let bad = |o: FrictionOptions| name_of(Friction::new(&s, &rubber, &o).err().expect("error"));
    assert_eq!(
        bad(FrictionOptions {
            gamma: 1.5,
            ..options(1e-8)
        }),
        "gamma"
    );
    assert_eq!(
        bad(FrictionOptions {
            tolerance: 0.0,
            ..options(1e-8)
        }),
        "tolerance"
    );
    assert_eq!(
        bad(FrictionOptions {
            points_per_decade: 0,
            ..options(1e-8)
        }),
        "points_per_decade"
    );
    assert_eq!(
        bad(FrictionOptions {
            breaks: vec![-1.0],
            ..options(1e-8)
        }),
        "break"
    );
    assert!(rubber.clone().with_poisson(0.7).is_err());
    assert_eq!(
        name_of(
            Prony::new(
                1e6,
                &[PronyTerm {
                    modulus: -1.0,
                    relaxation_time: 1.0
                }]
            )
            .unwrap_err()
        ),
        "prony_modulus[0]"
    );
    assert_eq!(
        name_of(TemperatureShift::wlf(T_REF, 8.86, -1.0).unwrap_err()),
        "wlf_c2"
    );
    assert_eq!(
        name_of(Thermal::new(0.2, 1e3, f64::NAN).unwrap_err()),
        "heat_capacity"
    );
    assert!(log_velocities(1.0, 0.1, 10).is_err() && log_velocities(0.0, 1.0, 10).is_err());
    // A shift table: temperatures outside it are errors.
    let table =
        ShiftTable::new(&[(280.0, 10.0, None), (300.0, 1.0, None), (320.0, 0.1, None)]).unwrap();
    let r2 = Rubber::new(sls(), TemperatureShift::table(300.0, table).unwrap());
    let f2 = Friction::new(&s, &r2, &options(1e-8)).unwrap();
    assert_eq!(
        name_of(f2.point(1.0, 330.0, 1e5).unwrap_err()),
        "temperature"
    );
    // Extreme but valid inputs: finite results.
    for (v, p) in [(1e-30, 1e5), (1e30, 1e5), (1.0, 1e-30), (1.0, 1e30)] {
        let r = f.point(v, T_REF, p).unwrap().isothermal;
        assert!(
            r.friction_coefficient.is_finite() && r.contact_fraction.is_finite() && r.g.is_finite(),
            "({v}, {p}): {r:?}"
        );
    }
}

#[test]
fn velocity_sweep_and_json_keys() {
    let s = spectrum();
    let rubber = Rubber::new(sls(), TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap())
        .with_thermal(Thermal::new(0.25, 1200.0, 1500.0).unwrap());
    let f = Friction::new(&s, &rubber, &options(1e-8)).unwrap();
    let vs = log_velocities(1e-4, 1.0, 5).unwrap();
    assert_eq!(vs.len(), 5);
    assert!((vs[2] - 1e-2).abs() < 1e-17);
    let pts = f.sweep(&vs, &[T_REF, T_REF + 20.0], &[1e5, 2e5]).unwrap();
    assert_eq!(pts.len(), 20);
    assert_eq!(
        (pts[5].temperature, pts[5].nominal_pressure, pts[5].velocity),
        (T_REF, 2e5, 1e-4)
    );
    let json = serde_json::to_value(&pts[0]).unwrap();
    for key in [
        "velocity",
        "temperature",
        "nominal_pressure",
        "friction_coefficient",
        "friction_coefficient_error_bound",
        "contact_fraction",
        "contact_fraction_error_bound",
        "decades",
        "profile",
        "flash",
    ] {
        assert!(json.get(key).is_some(), "missing {key}");
    }
    assert!(json["flash"]["flash_temperature"].as_f64().unwrap() >= 0.0);
}

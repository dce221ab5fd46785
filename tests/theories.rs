//! Corrected contact-area theories and the mean interfacial separation, each
//! against an independent reference (E1 is unit-tested in src/special.rs).

// Reference values keep the digits mpmath printed; f64 rounds them.
#![allow(clippy::excessive_precision)]

use persson::corrected::{self, Theory};
use persson::kappa::Kappa;
use persson::separation::Separation;
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::theory::Persson;
use persson::Error;

#[path = "common/oracle.rs"]
mod oracle;

// ---------------------------------------------------- corrected theories

/// Independent reference for the ODE theories: classical RK4 for
/// y = G_e/G in τ = ln G, dy/dτ = f(A(yG)) − y, with f written directly from
/// the papers' formulas (not via the 1 − A² rewriting of the library).
fn rk4_reference(rate: impl Fn(f64) -> f64, tau0: f64, h: f64, steps: usize) -> Vec<f64> {
    let area = |g_e: f64| libm::erf(0.5 / g_e.sqrt());
    let rhs = |tau: f64, y: f64| rate(area(y * tau.exp())) - y;
    let mut y = 1.0; // G_e = G exactly to 1e-100 at G = e^{τ0} ≤ 1e-4
    let mut out = vec![area(tau0.exp())];
    for i in 0..steps {
        let t = tau0 + i as f64 * h;
        let k1 = rhs(t, y);
        let k2 = rhs(t + 0.5 * h, y + 0.5 * h * k1);
        let k3 = rhs(t + 0.5 * h, y + 0.5 * h * k2);
        let k4 = rhs(t + h, y + h * k3);
        y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        let tn = tau0 + (i + 1) as f64 * h;
        out.push(area(y * tn.exp()));
    }
    out
}

/// The accuracy requirement for every corrected theory.
const THEORY_ABS: f64 = 1e-10;
/// RK4 self-consistency: the h and h/2 solutions must agree to this, which
/// bounds the reference's own error by ~this/15 (Richardson, order 4).
const RK4_SELF: f64 = 1e-11;

fn check_against_rk4(theory: Theory, rate: impl Fn(f64) -> f64 + Copy) {
    let (tau0, h, steps) = (-9.5, 1.0 / 256.0, 256 * 30); // G from 7.5e-5 to 8e8
    let coarse = rk4_reference(rate, tau0, h, steps);
    let fine = rk4_reference(rate, tau0, h / 2.0, steps * 2);
    let stride = 64;
    let mut gs = Vec::new();
    let mut want = Vec::new();
    for i in (0..=steps).step_by(stride) {
        let d = (coarse[i] - fine[2 * i]).abs();
        assert!(d < RK4_SELF, "{theory:?}: RK4 self-check {d:e} at i = {i}");
        gs.push((tau0 + i as f64 * h).exp());
        want.push(fine[2 * i]);
    }
    let sols = theory.contact_fractions(&gs, 1e-12).unwrap();
    let mut worst: f64 = 0.0;
    for ((g, w), s) in gs.iter().zip(&want).zip(&sols) {
        let d = (s.contact_fraction - w).abs();
        worst = worst.max(d);
        assert!(
            d < THEORY_ABS,
            "{theory:?} at G = {g:e}: {} vs {w}, diff {d:e}",
            s.contact_fraction
        );
        // The reported bound is honest (plus the reference's own error).
        assert!(
            d <= s.error + RK4_SELF / 15.0,
            "{theory:?} at G = {g:e}: diff {d:e} > bound {:e}",
            s.error
        );
        assert!((s.complement - (1.0 - s.contact_fraction)).abs() < 1e-15);
    }
    eprintln!(
        "{theory:?}: max |A − A_ref| = {worst:e} over {} loads",
        gs.len()
    );
}

#[test]
fn yang_persson_matches_rk4() {
    let g = corrected::YANG_PERSSON_GAMMA;
    check_against_rk4(Theory::yang_persson(), move |a| g + (1.0 - g) * a * a);
    check_against_rk4(Theory::YangPersson { gamma: 0.1 }, |a| 0.1 + 0.9 * a * a);
}

#[test]
fn wang_muser_matches_rk4() {
    let g = corrected::WANG_MUSER_GAMMA;
    check_against_rk4(Theory::wang_muser(), move |a| {
        g - 2.0 / 9.0 * a * a + (11.0 / 9.0 - g) * a.powi(4)
    });
    check_against_rk4(Theory::WangMuser { gamma: 1.2 }, |a| {
        1.2 - 2.0 / 9.0 * a * a + (11.0 / 9.0 - 1.2) * a.powi(4)
    });
}

/// Xu's implicit equation by plain bisection to the last bit.
fn xu_bisection(g: f64, gamma: f64) -> f64 {
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        // rhs = erf(σ0/√(2 h V_c)) = erf(1/(2√(h G))), h = γ + (1 − γ) A
        let rhs = libm::erf(0.5 / ((gamma + (1.0 - gamma) * mid) * g).sqrt());
        if mid - rhs > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn xu_matches_bisection() {
    for gamma in [corrected::XU_GAMMA, 0.05, 0.9] {
        for g in [1e-4, 0.01, 0.1, 0.6, 2.0, 10.0, 1e3, 1e8] {
            let s = Theory::Xu { gamma }
                .contact_fraction(g, 0.0, 1e-12)
                .unwrap();
            let want = xu_bisection(g, gamma);
            let d = (s.contact_fraction - want).abs();
            assert!(
                d < THEORY_ABS && d <= s.error + 4.0 * f64::EPSILON,
                "γ={gamma} G={g}: diff {d:e}, bound {:e}",
                s.error
            );
        }
    }
}

/// erf evaluated the same way: equal up to the rounding of 1/(2√G).
const SAME_FORMULA_ABS: f64 = 4.0 * f64::EPSILON;
/// γ = 1 makes the ODE rate 1 up to rounding: Newton stops at 1e-13·G residual.
const GAMMA_ONE_ABS: f64 = 1e-13;

#[test]
fn original_is_erf_and_gamma_one_recovers_it() {
    for g in [1e-6, 1e-3, 0.05, 0.6, 2.0, 37.0, 1e4, 1e9] {
        let want = persson::theory::contact_fraction(g, 0.0).unwrap().fraction;
        let o = Theory::Original.contact_fraction(g, 0.0, 1e-12).unwrap();
        assert!((o.contact_fraction - want).abs() <= SAME_FORMULA_ABS);
        for t in [
            Theory::YangPersson { gamma: 1.0 },
            Theory::Xu { gamma: 1.0 },
        ] {
            let s = t.contact_fraction(g, 0.0, 1e-12).unwrap();
            assert!(
                (s.contact_fraction - want).abs() < GAMMA_ONE_ABS,
                "{t:?} G={g}: {} vs {want}",
                s.contact_fraction
            );
        }
    }
}

/// ln(G)/G correction of the low-load limit at G = 1e10 (module docs of
/// `corrected`): (1 − γ) ln G /(π γ² G) ≈ 2e-9 for γ = 0.45; 1e-7 leaves room.
const KAPPA_REL: f64 = 1e-7;

#[test]
fn low_load_kappa_limits() {
    let g: f64 = 1e10;
    for t in [
        Theory::yang_persson(),
        Theory::YangPersson { gamma: 0.3 },
        Theory::wang_muser(),
        Theory::xu(),
    ] {
        let a = t.contact_fraction(g, 0.0, 1e-12).unwrap().contact_fraction;
        // A/A0 = κ σ0/(E*√⟨|∇h|²⟩) = κ / √(8G)
        let kappa = a * (8.0 * g).sqrt();
        let mut want = t.low_load_kappa();
        if let Theory::Xu { gamma } = t {
            // Xu's correction is first order in A: V = γ V_c (1 + (1 − γ)A/γ),
            // so κ_eff = κ (1 − (1 − γ) A/(2γ) + O(A²)), A ≈ 9e-6 here.
            want *= 1.0 - (1.0 - gamma) * a / (2.0 * gamma);
        }
        assert!(
            ((kappa - want) / want).abs() < KAPPA_REL,
            "{t:?}: κ = {kappa}, want {want}"
        );
    }
    let yp = (8.0 / (std::f64::consts::PI * 0.45)).sqrt();
    assert!((Theory::yang_persson().low_load_kappa() - yp).abs() < 1e-15);
}

#[test]
fn stable_over_the_whole_range() {
    // Every theory at the edges of its γ range, G from 0 to 1e300: finite,
    // error within the tolerance, A/A0 non-increasing in G.
    let wm_min = corrected::WANG_MUSER_GAMMA_MIN;
    let theories = [
        Theory::Original,
        Theory::YangPersson {
            gamma: corrected::GAMMA_MIN,
        },
        Theory::YangPersson { gamma: 1.0 },
        Theory::WangMuser { gamma: wm_min },
        Theory::WangMuser { gamma: 11.0 / 9.0 },
        Theory::Xu {
            gamma: corrected::GAMMA_MIN,
        },
        Theory::Xu { gamma: 1.0 },
    ];
    let gs: Vec<f64> = std::iter::once(0.0)
        .chain((-300..=300).step_by(7).map(|k| 10f64.powi(k)))
        .collect();
    for t in theories {
        let sols = t
            .contact_fractions(&gs, 1e-12)
            .unwrap_or_else(|e| panic!("{t:?}: {e}"));
        let mut last = 1.0;
        for (g, s) in gs.iter().zip(&sols) {
            assert!(
                s.contact_fraction.is_finite() && s.error <= 1e-12,
                "{t:?} G={g:e}: {s:?}"
            );
            assert!(s.contact_fraction <= last + s.error, "{t:?} G={g:e}");
            last = s.contact_fraction;
        }
    }
}

#[test]
fn corrected_theories_lie_between_original_and_bush() {
    // κ: Persson √(8/π) < corrected ≈ 2.1–2.4 < Bush √(2π) (Campañá & Müser, EPL 77, 38005 (2007): numerics ≈ 2).
    for t in Theory::all_defaults() {
        let k = t.low_load_kappa();
        let (persson, bush) = (Kappa::Persson.value(), Kappa::Bush.value());
        assert!((persson..bush).contains(&k), "{t:?}: {k}");
        assert_eq!(k == persson, t == Theory::Original);
    }
    // At every load the corrections raise the area above the original theory.
    for g in [0.05, 0.3, 1.0, 10.0, 1e3] {
        let o = Theory::Original
            .contact_fraction(g, 0.0, 1e-12)
            .unwrap()
            .contact_fraction;
        for t in [Theory::yang_persson(), Theory::xu()] {
            assert!(t.contact_fraction(g, 0.0, 1e-12).unwrap().contact_fraction > o);
        }
    }
}

#[test]
fn many_loads_equal_single_solves_in_any_order() {
    let gs = [3.0, 0.01, 1e5, 0.7, 0.7, 40.0, 1e-5];
    for t in Theory::all_defaults() {
        let many = t.contact_fractions(&gs, 1e-12).unwrap();
        for (g, m) in gs.iter().zip(&many) {
            let one = t.contact_fraction(*g, 0.0, 1e-12).unwrap();
            assert!(
                (one.contact_fraction - m.contact_fraction).abs() < 2e-12 + one.error + m.error,
                "{t:?} G={g}"
            );
        }
    }
}

fn surface() -> SelfAffine {
    // 4 decades, roll-off at 10 q_l, unit rms slope.
    SelfAffine::new(1e3, 1e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

#[test]
fn load_curve_uses_g_of_the_core() {
    let s = surface();
    let model = Persson::new(&s, 1.0).unwrap();
    let pressures = [1e-4, 1e-3, 0.01, 0.1, 1.0];
    let zeta = model.zeta_max();
    let core = model.load_curve(&pressures, zeta).unwrap();
    let pts = corrected::load_curve(&model, Theory::Original, zeta, &pressures, 1e-12).unwrap();
    for (c, p) in core.iter().zip(&pts) {
        assert_eq!(c.g, p.g);
        assert!((c.contact_fraction - p.contact_fraction).abs() <= SAME_FORMULA_ABS);
    }
    let yp =
        corrected::load_curve(&model, Theory::yang_persson(), zeta, &pressures, 1e-12).unwrap();
    for (c, p) in core.iter().zip(&yp) {
        assert!(p.contact_fraction > c.contact_fraction && p.error_bound < 1e-11);
    }
}

#[test]
fn bad_input_is_a_clear_error() {
    for t in [
        Theory::YangPersson { gamma: 0.0 },
        Theory::YangPersson { gamma: 1.5 },
        Theory::Xu { gamma: -0.1 },
        Theory::Xu { gamma: f64::NAN },
        Theory::WangMuser { gamma: 0.01 },
        Theory::WangMuser { gamma: 2.0 },
    ] {
        let e = t.contact_fraction(1.0, 0.0, 1e-12).unwrap_err();
        assert!(
            matches!(e, Error::InvalidParameter { ref name, .. } if name == "gamma"),
            "{t:?}: {e}"
        );
    }
    assert!(Theory::from_name("original", Some(0.5)).is_err());
    assert!(Theory::from_name("bogus", None).is_err());
    assert_eq!(
        Theory::from_name("wang-muser", None).unwrap(),
        Theory::wang_muser()
    );
    let s = surface();
    let model = Persson::new(&s, 1.0).unwrap();
    for p in [0.0, -1.0, f64::NAN] {
        let e = corrected::load_curve(&model, Theory::xu(), 10.0, &[1.0, p], 1e-12).unwrap_err();
        assert!(
            matches!(e, Error::InvalidParameter { ref name, .. } if name == "nominal_pressure")
        );
        let sep = Separation::new(&s, 1.0).unwrap();
        assert!(matches!(
            sep.mean_separation(p),
            Err(Error::InvalidParameter { .. })
        ));
    }
}

// ------------------------------------------------------- separation

/// Relative tolerance of the separation integrals in the tests: the default.
/// (At 1e-11 the ∫ q²C w ln w of the low-load law stalls at ~1.2e-11: near
/// q_l, w ∝ (q − q_l)^{−1/2} amplifies the rounding of q inside the spectrum's
/// moment.)
const SEP_TOL: f64 = persson::separation::DEFAULT_TOLERANCE;
/// Agreement of two independent quadratures each at ~SEP_TOL.
const SEP_REL: f64 = 1e-9;

fn separation(s: &SelfAffine) -> Separation<'_> {
    Separation::new(s, 1.0)
        .unwrap()
        .with_tolerance(SEP_TOL)
        .unwrap()
        .with_breaks(&[s.q_r()])
}

#[test]
fn mean_separation_matches_nested_quadrature() {
    // Narrow band (1 decade) so that the nested reference stays cheap.
    let s = SelfAffine::new(1e3, 2e3, 1e4, 0.7, Amplitude::RmsSlope(0.5)).unwrap();
    let sep = separation(&s);
    for p in [1e-3, 0.03, 0.3] {
        let got = sep.mean_separation(p).unwrap();
        // Reference: outer integral in ln q (split at q_r), inner p′ integral
        // numerically in ln p′ up to where the exponent is 40.
        let pi = std::f64::consts::PI;
        let outer = |lnq: f64| {
            let q = lnq.exp();
            let m3 = s.moment(3, s.q_min(), q).unwrap().value;
            let w = 1.0 / (pi * m3).sqrt();
            let top = (40f64.sqrt() / w).max(p * 2.0).ln();
            let inner = if top <= p.ln() {
                0.0
            } else {
                oracle::integrate(
                    "inner",
                    |lp: f64| (-(w * lp.exp()).powi(2)).exp(),
                    p.ln(),
                    top,
                    1e-300,
                    1e-13,
                    100_000,
                )
            };
            pi.sqrt() * q * q * s.c(q) * w * inner * q
        };
        let mut want = 0.0;
        for (a, b) in [(s.q_min(), s.q_r()), (s.q_r(), s.q_max())] {
            // the w ~ (ln q − ln q_l)^{-1/2} singularity at q_l: bilby's GK handles it adaptively
            want += oracle::integrate("outer", outer, a.ln(), b.ln(), 1e-300, 1e-11, 400_000);
        }
        let rel = ((got.value - want) / want).abs();
        assert!(rel < SEP_REL, "p={p}: {} vs {want}, rel {rel:e}", got.value);
    }
}

#[test]
fn stiffness_and_energy_are_consistent_with_separation() {
    let s = surface();
    let sep = separation(&s);
    let (p1, p2) = (0.01, 0.2);
    // ū(p1) − ū(p2) = ∫_{p1}^{p2} dp/K = ∫ (p/K) d ln p
    let du = sep.mean_separation(p1).unwrap().value - sep.mean_separation(p2).unwrap().value;
    let int = oracle::integrate(
        "1/K",
        |lp: f64| lp.exp() / sep.stiffness(lp.exp()).unwrap().value,
        p1.ln(),
        p2.ln(),
        1e-300,
        1e-10,
        10_000,
    );
    assert!(((du - int) / du).abs() < SEP_REL, "{du} vs {}", int);
    // U(p) = ∫_0^p p′ (−dū/dp′) dp′ = ∫_0^p p′/K(p′) dp′ (the work of the load)
    let p = 0.05;
    let work = oracle::integrate(
        "work",
        |x: f64| {
            if x == 0.0 {
                0.0
            } else {
                x / sep.stiffness(x).unwrap().value
            }
        },
        0.0,
        p,
        1e-300,
        1e-10,
        10_000,
    );
    let u = sep.elastic_energy(p).unwrap();
    assert!(
        ((u.value - work) / u.value).abs() < SEP_REL,
        "{} vs {}",
        u.value,
        work
    );
}

/// |ū − u0 ln(p_ref/p)| = O(p): the excess shrinks at least ~linearly in p.
#[test]
fn small_load_logarithmic_law() {
    let s = surface();
    let sep = separation(&s);
    let law = sep.low_load_law().unwrap();
    let u0 = law.length.value;
    let excess = |p: f64| {
        let u = sep.mean_separation(p).unwrap().value;
        (u - u0 * (law.reference_pressure.value / p).ln()).abs() / u0
    };
    let (e1, e2) = (excess(1e-6), excess(1e-8));
    assert!(e1 < 1e-3, "excess at 1e-6: {e1:e}");
    assert!(e2 < 0.03 * e1 + 1e-9, "excess not O(p): {e1:e} → {e2:e}");
    // u0 from mpmath (tanh-sinh at 30 digits, split at q_r and each decade).
    assert!(
        ((u0 - U0_MPMATH) / U0_MPMATH).abs() < SEP_REL,
        "{u0} vs {U0_MPMATH}"
    );
    // −dū/d ln p → u0: p/K → u0.
    let p = 1e-9;
    let slope = p / sep.stiffness(p).unwrap().value;
    assert!(((slope - u0) / u0).abs() < 1e-3);
}

/// u0 = √π ∫ q² C w dq for `surface()` (E* = 1), mpmath 1.4 at 30 digits.
const U0_MPMATH: f64 = 2.144_547_791_291_467_2e-5;

/// (p, ū, K, U) for `surface()` with E* = 1, mpmath 1.4 at 25 digits
/// (tanh-sinh, split at q_r and each decade, mpmath's own e1/erf).
const SEPARATION_MPMATH: [(f64, f64, f64, f64); 2] = [
    (
        1e-3,
        6.843_276_361_740_707_7e-5,
        49.786_660_286_707_084,
        2.068_807_518_369_856_9e-8,
    ),
    (
        0.1,
        2.324_030_532_712_050_6e-6,
        23_728.964_054_463_912,
        9.274_453_979_774_364_1e-7,
    ),
];

#[test]
fn separation_matches_mpmath() {
    let s = surface();
    let sep = separation(&s);
    for (p, u, k, e) in SEPARATION_MPMATH {
        let pt = sep.point(p).unwrap();
        for (name, got, err, want) in [
            ("ū", pt.mean_separation, pt.mean_separation_error_bound, u),
            ("K", pt.stiffness, pt.stiffness_error_bound, k),
            ("U", pt.elastic_energy, pt.elastic_energy_error_bound, e),
        ] {
            let d = (got - want).abs();
            assert!(
                d / want < SEP_REL,
                "{name}({p}) = {got}, want {want}, rel {:e}",
                d / want
            );
            assert!(
                d <= err + 1e-15 * want,
                "{name}({p}): |error| {d:e} > estimate {err:e}"
            );
        }
    }
}

#[test]
fn tabulated_spectrum_gives_the_same_separation() {
    // Log-log interpolation reproduces each power-law piece exactly when q_r
    // is a node: the table *is* the self-affine spectrum (to rounding).
    let s = surface();
    let mut pts = vec![(s.q_min(), s.c(s.q_min())), (s.q_r(), s.c(s.q_r()))];
    pts.extend((1..=30).map(|i| {
        let q = s.q_r() * 1e3f64.powf(i as f64 / 30.0);
        (q.min(s.q_max()), s.c(q.min(s.q_max())))
    }));
    let t = persson::spectrum::Tabulated::new(&pts).unwrap();
    let (a, b) = (separation(&s), Separation::new(&t, 1.0).unwrap());
    for p in [1e-4, 0.01, 0.3] {
        let (x, y) = (a.point(p).unwrap(), b.point(p).unwrap());
        for (got, want) in [
            (y.mean_separation, x.mean_separation),
            (y.stiffness, x.stiffness),
            (y.elastic_energy, x.elastic_energy),
        ] {
            assert!(
                ((got - want) / want).abs() < SEP_REL,
                "p={p}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn full_contact_limit() {
    let s = surface();
    let sep = separation(&s);
    let u0 = sep.low_load_law().unwrap().length.value;
    let mut last = f64::INFINITY;
    for p in [1e-3, 0.1, 1.0, 10.0] {
        let pt = sep.point(p).unwrap();
        assert!(pt.mean_separation < last && pt.stiffness > 0.0 && pt.stiffness.is_finite());
        last = pt.mean_separation;
    }
    // at 100 E* the stiffness, ~e^{x²} with x² ≈ 2e4, leaves f64: +∞, the
    // full-contact limit, while ū and U stay finite
    let pt = sep.point(100.0).unwrap();
    assert!(pt.mean_separation < last && pt.stiffness == f64::INFINITY);
    let last = pt.mean_separation;
    // ū → 0 and U → (π/2)E*∫q²C dq as p → ∞.
    assert!(last / u0 < 1e-6, "ū(100 E*)/u0 = {:e}", last / u0);
    let full = sep.full_contact_energy().unwrap().value;
    let u = sep.elastic_energy(100.0).unwrap().value;
    assert!(((u - full) / full).abs() < 1e-9);
}

// ------------------------------------------------------------- CLI

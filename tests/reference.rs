//! The Hertz closed forms of `persson::reference` against Johnson's other
//! forms of the same results, the load balance ∫ p dA = F by an in-test
//! quadrature, and the contact condition of the displacement.
//!
//! K. L. Johnson, *Contact Mechanics* (CUP 1985): ball §4.2 (eqs. 4.22–4.24),
//! cylinder §4.3 (eqs. 4.43–4.45), displacement §3.9 (eqs. 3.41a, 3.42a).

use std::f64::consts::PI;

use persson::reference::{ball_displacement, pressure_profile, Ball, Cylinder};
use persson::stress::HertzContact;

/// Two formulas for one quantity evaluated in f64: a handful of roundings
/// each (cbrt, sqrt, products), a few ulps.
const FORMULA_REL_TOL: f64 = 1e-14;
/// Composite Simpson with 20 000 panels on a smooth integrand (the pressure
/// in θ, r = a sin θ): truncation ~(h⁴/180)·max|f⁗| ~ 1e-19, summation
/// rounding ~1e-15 relative.
const LOAD_REL_TOL: f64 = 1e-13;
const PANELS: usize = 20_000;
/// Johnson 3.42a as written cancels only mildly at r ≤ 2a (its two terms
/// are within a factor 10 of their sum): 1e-14 relative.
const AS_WRITTEN_REL_TOL: f64 = 1e-14;

/// Inputs (R, F, E*) spanning a lab ball to a stiff, light contact.
const BALLS: [(f64, f64, f64); 4] = [
    (0.01, 10.0, 1e9),
    (1.0, 4e-3 / 3.0, 1.0),
    (2.5e-3, 0.2, 2.1e11),
    (0.5, 1e3, 3e6),
];
/// Inputs (R, F', E*) of the cylinder.
const CYLINDERS: [(f64, f64, f64); 3] = [(0.01, 1e3, 1e9), (1.0, 1e-3, 1.0), (0.2, 5e4, 1.1e11)];

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// ∫₀^{π/2} f(θ) dθ by composite Simpson.
fn simpson(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let h = (hi - lo) / PANELS as f64;
    let mut s = f(lo) + f(hi);
    for i in 1..PANELS {
        s += f(lo + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * h / 3.0
}

#[test]
fn ball_matches_johnsons_other_forms() {
    for (r, f, e) in BALLS {
        let b = Ball::from_load(r, f, e).unwrap();
        // 4.22 as a³ = 3FR/(4E*)
        assert!(rel(b.contact_radius.powi(3), 3.0 * f * r / (4.0 * e)) < FORMULA_REL_TOL);
        // 4.24, second form: p₀ = (6 F E*²/(π³ R²))^{1/3}
        let p0 = (6.0 * f * e * e / (PI.powi(3) * r * r)).cbrt();
        assert!(rel(b.peak_pressure, p0) < FORMULA_REL_TOL, "{r} {f} {e}");
        // 4.23: δ = (9F²/(16 R E*²))^{1/3}
        let delta = (9.0 * f * f / (16.0 * r * e * e)).cbrt();
        assert!(rel(b.penetration(), delta) < FORMULA_REL_TOL);
        // σ0 = 2p₀/3
        assert!(rel(b.nominal_pressure(), 2.0 * p0 / 3.0) < FORMULA_REL_TOL);
        // the inverse construction from a gives back F and p₀
        let c = Ball::from_contact_radius(r, b.contact_radius, e).unwrap();
        assert!(rel(c.load, f) < FORMULA_REL_TOL && rel(c.peak_pressure, p0) < FORMULA_REL_TOL);
    }
}

#[test]
fn ball_pressure_carries_the_load() {
    for (r, f, e) in BALLS {
        let b = Ball::from_load(r, f, e).unwrap();
        let a = b.contact_radius;
        // ∫ p 2πr dr with r = a sin θ
        let load = simpson(
            |t| b.pressure(a * t.sin()) * 2.0 * PI * a * t.sin() * a * t.cos(),
            0.0,
            PI / 2.0,
        );
        assert!(rel(load, f) < LOAD_REL_TOL, "{load} vs {f}");
        assert_eq!(b.pressure(a), 0.0);
        assert_eq!(b.pressure(1.5 * a), 0.0);
    }
}

#[test]
fn cylinder_matches_johnson_and_carries_the_load() {
    for (r, f, e) in CYLINDERS {
        let c = Cylinder::from_load_per_length(r, f, e).unwrap();
        let a = c.half_width;
        assert!(rel(a * a, 4.0 * f * r / (PI * e)) < FORMULA_REL_TOL);
        // 4.44, second form: p₀ = (F' E*/(π R))^{1/2}
        assert!(rel(c.peak_pressure, (f * e / (PI * r)).sqrt()) < FORMULA_REL_TOL);
        assert!(rel(c.nominal_pressure(), PI * c.peak_pressure / 4.0) < FORMULA_REL_TOL);
        // ∫ p dx over (−a, a) with x = a sin θ
        let load = simpson(
            |t| c.pressure(a * t.sin()) * a * t.cos(),
            -PI / 2.0,
            PI / 2.0,
        );
        assert!(rel(load, f) < LOAD_REL_TOL, "{load} vs {f}");
        assert_eq!(c.pressure(-a), 0.0);
    }
}

#[test]
fn displacement_meets_the_contact_condition_and_the_far_field() {
    for (r, f, e) in BALLS {
        let b = Ball::from_load(r, f, e).unwrap();
        let (a, delta) = (b.contact_radius, b.penetration());
        // inside: the surface follows the ball, u = δ − r²/(2R)
        for k in 0..=10 {
            let x = a * k as f64 / 10.0;
            let want = delta - x * x / (2.0 * r);
            assert!(rel(b.displacement(x), want) < FORMULA_REL_TOL, "r = {x}");
        }
        // outside, near the edge: Johnson 3.42a as written
        for t in [1.01, 1.2, 1.5, 2.0] {
            let x = t * a;
            let want = b.peak_pressure / (2.0 * a * e)
                * ((2.0 * a * a - x * x) * (a / x).asin() + a * (x * x - a * a).sqrt());
            assert!(
                rel(b.displacement(x), want) < AS_WRITTEN_REL_TOL,
                "r = {t} a"
            );
        }
        // far away: the point load F/(π E* r), to (a/r)² relative
        for t in [1e2, 1e4, 1e6] {
            let x = t * a;
            let far = f / (PI * e * x);
            assert!(rel(b.displacement(x), far) < 1.0 / (t * t), "r = {t} a");
        }
    }
    // the free function is the method
    let b = Ball::from_load(0.01, 10.0, 1e9).unwrap();
    let x = 3.0 * b.contact_radius;
    assert_eq!(
        ball_displacement(x, b.contact_radius, b.peak_pressure, 1e9),
        b.displacement(x)
    );
    assert_eq!(
        pressure_profile(0.5 * b.contact_radius, b.contact_radius, b.peak_pressure),
        b.pressure(0.5 * b.contact_radius)
    );
}

/// The stress starts are built on these closed forms: the same numbers,
/// bit for bit, and the same as before they were (the formulas of
/// `HertzContact` in persson 0.1).
#[test]
fn hertz_contact_starts_are_the_reference() {
    for (r, f, e) in BALLS {
        let (h, b) = (
            HertzContact::ball(r, f, e).unwrap(),
            Ball::from_load(r, f, e).unwrap(),
        );
        assert_eq!(h.contact_radius, b.contact_radius);
        assert_eq!(h.peak_pressure, b.peak_pressure);
        assert_eq!(h.nominal_pressure, b.nominal_pressure());
        // the numbers HertzContact::ball printed before it used the module
        let a = (0.75 * f * r / e).cbrt();
        let area = PI * a * a;
        assert_eq!(
            (h.contact_radius, h.peak_pressure, h.nominal_pressure),
            (a, 1.5 * f / area, f / area)
        );
    }
    for (r, f, e) in CYLINDERS {
        let h = HertzContact::cylinder(r, f, e).unwrap();
        let c = Cylinder::from_load_per_length(r, f, e).unwrap();
        assert_eq!(h.contact_radius, c.half_width);
        assert_eq!(h.peak_pressure, c.peak_pressure);
        assert_eq!(h.nominal_pressure, c.nominal_pressure());
        let a = (4.0 * f * r / (PI * e)).sqrt();
        assert_eq!(
            (h.contact_radius, h.peak_pressure, h.nominal_pressure),
            (a, 2.0 * f / (PI * a), f / (2.0 * a))
        );
    }
}

/// The BEM validation case uses the same closed forms.
#[cfg(feature = "bem")]
#[test]
fn bem_hertz_case_is_the_reference() {
    use persson::bem::{hertz::HertzCase, Boundary};
    let case = HertzCase::new(64, Boundary::Free);
    let b = Ball::from_contact_radius(case.radius, case.contact_radius, case.e_star).unwrap();
    assert_eq!(case.peak_pressure(), b.peak_pressure);
    assert_eq!(case.mean_pressure(), b.load / (case.size * case.size));
    // the formulas of bem::hertz before it used the module
    let (a, r, e) = (case.contact_radius, case.radius, case.e_star);
    assert_eq!(case.peak_pressure(), 2.0 * e * a / (PI * r));
    assert_eq!(
        case.mean_pressure(),
        4.0 * e * a.powi(3) / (3.0 * r) / (case.size * case.size)
    );
    let f = 4e-3 / 3.0;
    assert_eq!(
        persson::reference::ball_contact_radius(f, 1.0, 1.0),
        (3.0 * f / 4.0f64).cbrt()
    );
}

#[test]
fn bad_inputs_are_errors() {
    assert!(Ball::from_load(-1.0, 1.0, 1.0).is_err());
    assert!(Ball::from_load(1.0, f64::NAN, 1.0).is_err());
    assert!(Ball::from_contact_radius(1.0, 0.0, 1.0).is_err());
    assert!(Cylinder::from_load_per_length(1.0, 1.0, f64::INFINITY).is_err());
}

//! The roughness of two rough bodies (issue 25, item 3): C = C₁ + C₂.
//!
//! Oracles: closed forms of the self-affine moments written out here (not
//! the crate's), and the linearity of G in C for one E*.

use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Sum};
use persson::theory::Persson;

/// Closed-form moments against the crate's exact ones: 1e-13 relative.
const CLOSED_FORM: f64 = 1e-13;
/// G of the sum against G₁ + G₂ (both exact moments): 1e-14 relative.
const LINEAR: f64 = 1e-14;

/// ⟨h²⟩ = 2π ∫ q C dq of C = C_r (q/q_l)^(−2(1+H)) on [q_l, q_s] (no roll-off):
/// 2π C_r q_l² (1 − (q_s/q_l)^(−2H)) / (2H).
fn variance(c_r: f64, hurst: f64, q_l: f64, q_s: f64) -> f64 {
    std::f64::consts::TAU * c_r * q_l * q_l * (1.0 - (q_s / q_l).powf(-2.0 * hurst)) / (2.0 * hurst)
}

fn part(q_l: f64, q_s: f64, hurst: f64, c_r: f64) -> Box<dyn Spectrum> {
    Box::new(SelfAffine::new(q_l, q_l, q_s, hurst, Amplitude::CR(c_r)).unwrap())
}

#[test]
fn rms_height_squared_adds_over_different_bands() {
    let (a, b) = ((1e4, 1e6, 0.8, 1e-26), (1e5, 1e8, 0.5, 3e-28));
    let s = Sum::new(vec![part(a.0, a.1, a.2, a.3), part(b.0, b.1, b.2, b.3)]).unwrap();
    assert_eq!((s.q_min(), s.q_max()), (1e4, 1e8));
    let expected = variance(a.3, a.2, a.0, a.1) + variance(b.3, b.2, b.0, b.1);
    let h = s.rms_height(s.q_min(), s.q_max()).unwrap();
    assert!((h.value.powi(2) / expected - 1.0).abs() < CLOSED_FORM);
    assert!(h.error < CLOSED_FORM * h.value);
    // Where only one body is rough the sum is that body's spectrum.
    assert_eq!(s.c(5e4), a.3 * (5e4f64 / a.0).powf(-2.0 * 1.8));
    assert_eq!(s.c(5e7), b.3 * (5e7f64 / b.0).powf(-3.0));
    assert_eq!(s.c(2e8), 0.0);
    assert!((s.band_mismatch() - 100.0).abs() < 1e-12);
}

#[test]
fn g_adds_for_the_same_contact_modulus() {
    let (e, sigma) = (1e9, 1e6);
    let make = || (part(1e4, 1e7, 0.8, 1e-26), part(1e4, 1e8, 0.3, 2e-27));
    let (p1, p2) = make();
    let g1 = Persson::new(p1.as_ref(), e).unwrap();
    let g2 = Persson::new(p2.as_ref(), e).unwrap();
    let (q1, q2) = make();
    let s = Sum::new(vec![q1, q2]).unwrap();
    let g = Persson::new(&s, e).unwrap();
    for zeta in [1.5, 10.0, 1e3, 1e3 - 1e-9] {
        let sum = g1.g(zeta, sigma).unwrap().value + g2.g(zeta, sigma).unwrap().value;
        let v = g.g(zeta, sigma).unwrap().value;
        assert!((v / sum - 1.0).abs() < LINEAR, "ζ = {zeta}: {v} vs {sum}");
    }
}

#[test]
fn fewer_than_two_parts_is_an_error() {
    let e = Sum::new(vec![part(1e4, 1e6, 0.8, 1e-26)]).unwrap_err();
    assert!(e.to_string().contains("at least 2"), "{e}");
}

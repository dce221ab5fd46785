//! Exact integrals of power laws, stable for every exponent.

use crate::special::one_minus_exp_over;

/// `∫_{a/s}^{b/s} t^p dt` for `0 < a ≤ b`, `s > 0`, stable for every real `p`
/// including `p → −1` (where it tends to `ln(b/a)`), and for `b → a`.
///
/// # Formula
/// ```text
/// e = p + 1, L = ln(b/a) = ln_1p((b − a)/a)
/// e ≥ 0:  (b/s)^e · L · (1 − e^{−eL})/(eL)
/// e < 0:  (a/s)^e · L · (1 − e^{ eL})/(−eL)
/// ```
/// Both factors `(1 − e^{−x})/x` lie in (0, 1] and are computed with `expm1`,
/// so nothing cancels and nothing overflows beyond the end-point power. L is
/// taken from the unscaled end points, where `b − a` is exact when b ≈ a
/// (Sterbenz), so a narrow interval keeps its relative accuracy.
pub(crate) fn integral(a: f64, b: f64, p: f64, s: f64) -> f64 {
    debug_assert!(0.0 < a && a <= b && s > 0.0);
    let e = p + 1.0;
    let l = ((b - a) / a).ln_1p();
    if e >= 0.0 {
        (b / s).powf(e) * l * one_minus_exp_over(e * l)
    } else {
        (a / s).powf(e) * l * one_minus_exp_over(-e * l)
    }
}

/// `∫_1^{e^l} t^{e−1} dt = (e^{el} − 1)/e` for `l ≥ 0`, from the log-length `l`:
/// `l · expm1(el)/(el)`, exact as `e → 0` (one `expm1`, no power).
#[inline]
pub(crate) fn integral_log(l: f64, e: f64) -> f64 {
    let x = e * l;
    if x == 0.0 {
        l
    } else {
        l * x.exp_m1() / x
    }
}

#[cfg(test)]
mod tests {
    use super::{integral, integral_log};

    #[test]
    fn matches_elementary_forms() {
        let cases = [
            (1.0, 2.0, 2.0, 7.0 / 3.0),
            (1.0, 10.0, -1.0, 10f64.ln()),
            (2.0, 8.0, -2.0, 0.375),
        ];
        for (a, b, p, exact) in cases {
            let v = integral(a, b, p, 1.0);
            assert!(
                ((v - exact) / exact).abs() < 4e-16,
                "{a} {b} {p}: {v} vs {exact}"
            );
        }
    }

    #[test]
    fn log_form_agrees() {
        for (a, b, p) in [
            (1.0f64, 2.0f64, 2.0),
            (3.0, 30.0, -2.3),
            (1.0, 1e5, -1.0 + 1e-9),
        ] {
            let v = integral_log((b / a).ln(), p + 1.0);
            let w = integral(a, b, p, a);
            assert!(((v - w) / w).abs() < 1e-14, "{a} {b} {p}: {v} vs {w}");
        }
    }

    #[test]
    fn continuous_through_minus_one() {
        // d/dp at p = −1 is finite: values at −1 ± 1e-12 differ from ln(b/a) by ~1e-12·L²/2.
        let l = 1e3f64.ln();
        for p in [-1.0 - 1e-12, -1.0 + 1e-12] {
            let v = integral(1.0, 1e3, p, 1.0);
            assert!((v - l).abs() / l < 1e-11);
        }
    }
}

//! Exact integrals of power laws, stable for every exponent.

use crate::special::one_minus_exp_over;

/// `∫_a^b q^p dq` for `0 < a ≤ b`, stable for every real `p` including
/// `p → −1` (where it tends to `ln(b/a)`).
///
/// # Formula
/// ```text
/// e = p + 1, L = ln(b/a)
/// e ≥ 0:  b^e · L · (1 − e^{−eL})/(eL)
/// e < 0:  a^e · L · (1 − e^{ eL})/(−eL)
/// ```
/// Both factors `(1 − e^{−x})/x` lie in (0, 1] and are computed with `expm1`,
/// so nothing cancels and nothing overflows beyond `b^e` itself.
pub(crate) fn integral(a: f64, b: f64, p: f64) -> f64 {
    debug_assert!(0.0 < a && a <= b);
    let e = p + 1.0;
    let l = ((b - a) / a).ln_1p(); // b − a is exact when b ≈ a (Sterbenz)
    if e >= 0.0 {
        b.powf(e) * l * one_minus_exp_over(e * l)
    } else {
        a.powf(e) * l * one_minus_exp_over(-e * l)
    }
}

#[cfg(test)]
mod tests {
    use super::integral;

    #[test]
    fn matches_elementary_forms() {
        let cases = [
            (1.0, 2.0, 2.0, 7.0 / 3.0),
            (1.0, 10.0, -1.0, 10f64.ln()),
            (2.0, 8.0, -2.0, 0.375),
        ];
        for (a, b, p, exact) in cases {
            let v = integral(a, b, p);
            assert!(
                ((v - exact) / exact).abs() < 4e-16,
                "{a} {b} {p}: {v} vs {exact}"
            );
        }
    }

    #[test]
    fn continuous_through_minus_one() {
        // d/dp at p = −1 is finite: values at −1 ± 1e-12 differ from ln(b/a) by ~1e-12·L²/2.
        let l = 1e3f64.ln();
        for p in [-1.0 - 1e-12, -1.0 + 1e-12] {
            let v = integral(1.0, 1e3, p);
            assert!((v - l).abs() / l < 1e-11);
        }
    }
}

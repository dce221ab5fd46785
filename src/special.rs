//! Special functions, accurate to a few ulp over the whole f64 range.
//!
//! erf, erfc, J1 come from `libm` (musl port; ≤ 2e-16 relative in
//! `../shared/deps.md`), erfcx from `errorfunctions` (Faddeeva port). This
//! module adds only the combinations the theory needs.

use errorfunctions::RealErrorFunctions;

/// Error function.
#[inline]
pub fn erf(x: f64) -> f64 {
    libm::erf(x)
}

/// Complementary error function 1 − erf(x), with full relative accuracy.
#[inline]
pub fn erfc(x: f64) -> f64 {
    libm::erfc(x)
}

/// Scaled complementary error function erfcx(x) = e^{x²} erfc(x).
#[inline]
pub fn erfcx(x: f64) -> f64 {
    x.erfcx()
}

/// ln erfc(x) for x ≥ 0, to full relative accuracy: `ln_1p(−erf x)` near 0
/// (where erfc ≈ 1), and `ln erfcx(x) − x²` beyond the underflow of erfc (x ≈ 27).
#[inline]
pub fn ln_erfc(x: f64) -> f64 {
    if x < 0.5 {
        (-erf(x)).ln_1p()
    } else if x < 1.0 {
        erfc(x).ln()
    } else {
        erfcx(x).ln() - x * x
    }
}

/// Bessel function of the first kind, order one.
#[inline]
pub fn j1(x: f64) -> f64 {
    libm::j1(x)
}

/// `(1 − e^{−x})/x` for x ≥ 0, equal to 1 at x = 0, without cancellation.
#[inline]
pub fn one_minus_exp_over(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        -(-x).exp_m1() / x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ln erfc(x) from mpmath (30 digits).
    const LN_ERFC: [(f64, f64); 4] = [
        (0.5, -0.735_011_129_837_084_4),
        (5.0, -27.200_889_545_537_434),
        (30.0, -903.974_117_110_643_9),
        (1e5, -10_000_000_012.085_29),
    ];

    #[test]
    fn ln_erfc_matches_mpmath() {
        for (x, v) in LN_ERFC {
            let got = ln_erfc(x);
            assert!(((got - v) / v).abs() < 1e-15, "x={x}: {got} vs {v}");
        }
    }
}

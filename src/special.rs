//! Special functions, accurate to a few ulp over the whole f64 range.
//!
//! erf, erfc, J1 come from `libm` (musl port; ≤ 2e-16 relative, measured
//! when it was chosen: docs/design-notes.md), erfcx from `errorfunctions`
//! (Faddeeva port). This
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

/// Euler–Mascheroni constant γ_E.
pub const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Below this argument [`e1`] uses the power series, above it the continued fraction.
const E1_SERIES_MAX: f64 = 1.0;

/// Term cap of the E1 series and continued fraction: the series needs ≤ 20
/// terms for x ≤ 1, the continued fraction 170 at x = 1 and fewer above.
const E1_MAX_TERMS: usize = 200;

/// Depth constant of the backward continued fraction: n = 10 + ⌈160/x⌉.
const E1_CF_DEPTH: f64 = 160.0;

/// Exponential integral E1(x) = ∫ₓ^∞ e^{−t}/t dt for x > 0.
///
/// # Formula
/// ```text
/// x ≤ 1:  E1(x) = −γ_E − ln x − Σ_{k≥1} (−x)^k / (k·k!)
/// x > 1:  E1(x) = e^{−x} / (x + 1 − 1²/(x + 3 − 2²/(x + 5 − …)))   (n = 10 + ⌈160/x⌉ levels)
/// ```
/// The series loses at most ~2 bits near x = 1 (E1(1) ≈ 0.22 against terms of
/// size ~0.8); the continued fraction is evaluated backward (stable) for
/// x > 1. Relative error ≤ 1.1e-15 (at x = 1, series cancellation), ≤ 3e-16
/// for x > 1, against mpmath over 1e-300 ≤ x ≤ 700 (tests/theories.rs). E1 underflows to 0 above x ≈ 740;
/// use [`e1_scaled`] there.
///
/// Returns `+∞` at x = 0 and NaN for x < 0 or NaN (like `libm`).
///
/// # References
/// Abramowitz & Stegun, Handbook of Mathematical Functions, Eqs. 5.1.11
/// (series) and 5.1.22 (continued fraction).
///
/// mpmath: E1(1) = 0.21938393439552027368 (checked with the table in the
/// tests below).
pub fn e1(x: f64) -> f64 {
    if x.is_nan() || x < 0.0 {
        f64::NAN
    } else if x == 0.0 {
        f64::INFINITY
    } else if x <= E1_SERIES_MAX {
        e1_series(x)
    } else {
        (-x).exp() * e1_continued_fraction(x)
    }
}

/// Scaled exponential integral e^x E1(x) for x > 0, finite where E1 underflows.
///
/// # Formula
/// ```text
/// e^x E1(x) ~ 1/x − 1/x² + 2/x³ − …   (x → ∞)
/// ```
/// Same methods and accuracy as [`e1`]. `+∞` at 0, NaN for x < 0.
#[cfg_attr(not(test), allow(dead_code))] // kept, and tested, beside e1
pub fn e1_scaled(x: f64) -> f64 {
    if x.is_nan() || x < 0.0 {
        f64::NAN
    } else if x == 0.0 {
        f64::INFINITY
    } else if x <= E1_SERIES_MAX {
        x.exp() * e1_series(x)
    } else if x.is_infinite() {
        0.0
    } else {
        e1_continued_fraction(x)
    }
}

/// Power series of E1 for 0 < x ≤ 1 (A&S 5.1.11).
fn e1_series(x: f64) -> f64 {
    let mut sum = 0.0;
    let mut term = 1.0; // (−x)^k / k!
    for k in 1..E1_MAX_TERMS {
        let kf = k as f64;
        term *= -x / kf;
        let add = term / kf;
        sum += add;
        if add.abs() <= f64::EPSILON * 0.25 * sum.abs() {
            break;
        }
    }
    -EULER_GAMMA - x.ln() - sum
}

/// e^x E1(x) for x > 1 from the even continued fraction (A&S 5.1.22),
/// evaluated backward from a fixed depth.
///
/// Backward evaluation `t ← (x + 2k − 1) − k²/t` is contracting, so rounding
/// does not accumulate (forward Lentz evaluation lost up to 20 ulps near
/// x = 1). The depth `10 + ⌈160/x⌉` was chosen against mpmath: relative error
/// ≤ 2.9e-16 for 1 ≤ x ≤ 21 in steps of 0.01; the truncation error decays like
/// e^{−4√(n x)}.
fn e1_continued_fraction(x: f64) -> f64 {
    let n = (10.0 + (E1_CF_DEPTH / x).ceil()).min(E1_MAX_TERMS as f64) as usize;
    let mut t = x + (2 * n + 1) as f64;
    for k in (1..=n).rev() {
        let kf = k as f64;
        t = (x + 2.0 * kf - 1.0) - kf * kf / t;
    }
    1.0 / t
}

#[cfg(test)]
// Reference values keep the digits mpmath printed; f64 rounds them.
#[allow(clippy::excessive_precision)]
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

    /// E1(x) and e^x E1(x) from mpmath 1.4 at 30 digits.
    const E1_TABLE: [(f64, f64, f64); 13] = [
        (1e-300, 690.198_312_233_312_17, 690.198_312_233_312_17),
        (1e-10, 22.448_635_265_138_924, 22.448_635_267_383_788),
        (0.1, 1.822_923_958_419_390_7, 2.014_642_544_708_451_7),
        (0.5, 0.559_773_594_776_160_81, 0.922_910_632_483_730_47),
        (1.0, 0.219_383_934_395_520_27, 0.596_347_362_323_194_07),
        (
            1.000_000_1,
            0.219_383_897_607_579_84,
            0.596_347_321_957_933_29,
        ),
        (1.5, 0.100_019_582_406_632_65, 0.448_256_669_291_582_95),
        (2.0, 0.048_900_510_708_061_12, 0.361_328_616_888_222_58),
        (5.0, 0.001_148_295_591_275_325_8, 0.170_422_176_284_732_2),
        (10.0, 4.156_968_929_685_324_3e-6, 0.091_563_333_939_788_082),
        (50.0, 3.783_264_029_550_459e-24, 0.019_615_109_930_114_87),
        (
            700.0,
            1.406_518_766_234_032_9e-307,
            0.001_426_536_418_300_886_7,
        ),
        (740.0, 0.0, 0.001_349_530_116_516_854_3),
    ];

    /// Relative accuracy of e1/e1_scaled: the series loses ~2 bits to
    /// cancellation near x = 1 (measured 1.07e-15 there on a 0.05 grid over
    /// [0.5, 3.5]; ≤ 3e-16 for the backward continued fraction above 1).
    const E1_REL: f64 = 1.5e-15;

    #[test]
    fn e1_matches_mpmath() {
        for (x, want, scaled) in E1_TABLE {
            let got = e1(x);
            if want == 0.0 {
                // 5.65e-325 is below the smallest subnormal: underflows to 0 (or the last subnormal).
                assert!(got < 1e-320, "x={x}: {got}");
            } else {
                let rel = ((got - want) / want).abs();
                assert!(rel < E1_REL, "E1({x}) = {got}, want {want}, rel {rel:e}");
            }
            let got = e1_scaled(x);
            let rel = ((got - scaled) / scaled).abs();
            assert!(
                rel < E1_REL,
                "e^x E1({x}) = {got}, want {scaled}, rel {rel:e}"
            );
        }
        assert!(e1(-1.0).is_nan());
        assert_eq!(e1(0.0), f64::INFINITY);
    }
}

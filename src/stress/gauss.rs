//! Gauss–Legendre rules (cached) and the Bernstein-ellipse error bound.
//!
//! # Formula
//! ```text
//! |∫₋₁¹ ω f − Σ wⱼ f(tⱼ)| ≤ 2 W E₂ₙ₋₁(f),   E_m(f) ≤ 2 M ρ^{−m} / (ρ − 1)
//! ```
//! for f analytic inside the Bernstein ellipse E_ρ (foci ±1, semi-axes
//! α = (ρ + 1/ρ)/2, β = (ρ − 1/ρ)/2) with |f| ≤ M there, W = ∫ ω
//! (Gauss rules are exact to degree 2n − 1 and have positive weights).
//!
//! # References
//! L. N. Trefethen, *Approximation Theory and Approximation Practice*, Thm 8.2
//! and Thm 19.3 (SIAM 2013).

use std::sync::OnceLock;

/// An n-point Gauss–Legendre rule on [−1, 1].
pub(crate) struct Rule {
    /// Nodes, ascending.
    pub x: Vec<f64>,
    /// Weights.
    pub w: Vec<f64>,
}

/// Rule sizes available.
pub(crate) const SIZES: [usize; 14] = [8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768];

static RULES: [OnceLock<Rule>; 14] = [const { OnceLock::new() }; 14];

/// The cached rule with `SIZES[i]` points.
pub(crate) fn rule(i: usize) -> &'static Rule {
    RULES[i].get_or_init(|| legendre(SIZES[i]))
}

/// The n-point rule ([`crate::quad::gauss_legendre`]).
fn legendre(n: usize) -> Rule {
    let (x, w) = crate::quad::gauss_legendre(n);
    Rule { x, w }
}

/// ln of the Gauss error bound `4 W M ρ^{−(2n−1)}/(ρ − 1)` for one ellipse
/// parameter β (semi-minor axis), given `ln_m` = ln M(β).
#[inline]
pub(crate) fn ln_bound(n: usize, beta: f64, ln_m: f64, weight_integral: f64) -> f64 {
    let rho = beta + (1.0 + beta * beta).sqrt();
    (4.0 * weight_integral).ln() + ln_m - (2 * n - 1) as f64 * rho.ln() - (rho - 1.0).ln()
}

/// Ellipse semi-minor axes tried when minimising the bound.
pub(crate) const BETAS: [f64; 12] = [0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.8, 1.0, 1.3, 1.7, 2.2, 3.0];

/// The smallest cached rule whose bound (minimised over [`BETAS`], `ln_m(β)`)
/// is ≤ `tol`; returns (index, bound). When none is small enough, the largest
/// rule and its bound.
pub(crate) fn choose(tol: f64, weight_integral: f64, ln_m: impl Fn(f64) -> f64) -> (usize, f64) {
    let lms: Vec<f64> = BETAS.iter().map(|&b| ln_m(b)).collect();
    let mut last = (SIZES.len() - 1, f64::INFINITY);
    for (i, &n) in SIZES.iter().enumerate() {
        let b = BETAS
            .iter()
            .zip(&lms)
            .map(|(&beta, &lm)| ln_bound(n, beta, lm, weight_integral))
            .fold(f64::INFINITY, f64::min)
            .exp();
        last = (i, b);
        if b <= tol {
            return last;
        }
    }
    last
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_integrate_polynomials_and_exp() {
        for (i, n) in SIZES.iter().enumerate() {
            let r = rule(i);
            let s: f64 = r.w.iter().sum();
            assert!((s - 2.0).abs() < 1e-13, "n={n} sum={s}");
            let e: f64 = r.x.iter().zip(&r.w).map(|(x, w)| w * x.exp()).sum();
            let exact = std::f64::consts::E - 1.0 / std::f64::consts::E;
            assert!((e - exact).abs() < 1e-13, "n={n} {e}");
        }
    }
}

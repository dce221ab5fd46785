//! Height-resolved summit weights of the BGT theory, tabulated once per
//! surface, and the fast separation integrals built on them.
//!
//! # Formula
//! With ξ the standardised summit height and u | ξ ~ N(ξ/√α, 2/3 − 1/α)
//! ([`super::bush`]):
//! ```text
//! g_γ(ξ)  = ∫_0^∞ N(u; ξ/√α, 2/3 − 1/α) · 3 u^{2+2γ} K_γ(3u²/2) du
//! J(δ)/φ(δ) = ∫_0^∞ t^k e^{−δt − t²/2} g_γ(δ + t) dt = ∫_0^W 2 w^{2k+1} e^{−δw² − w⁴/2} g_γ(δ + w²) dw
//! ```
//! the same J_{k,γ} as the u-form of [`super::bush`] (Fubini over the
//! bivariate normal of ξ and u), with (k, γ) = (0, 1), (1, ½), (3/2, ¾).
//!
//! # Method
//! ln g_γ is interpolated by a Chebyshev series of [`TERMS`] terms on
//! ξ ∈ [[`XI_MIN`], [`XI_MAX`]], its values at the nodes by adaptive
//! Gauss–Kronrod in u (relative 1e-14) around the peak of u^p N; g is entire
//! in ξ and positive, ln g is smooth. The separation integral runs over
//! w = √(ξ − δ) (analytic: the t^{3/2} branch point is gone) with
//! [`NODES`]-point Gauss–Legendre up to e^{−δt − t²/2} < e^{−45}
//! ([`NODES_POSITIVE`] for δ ≥ 0, where the integrand is one bump at w = 0). Tested
//! against the direct u-form to 1e-12 relative for δ ∈ [−6, 12] and
//! α ≥ [`MIN_ALPHA`] (tests/asperity.rs); used for δ ≤ [`DELTA_MAX`] there.
//! Below α = 4 the transition of ln g from its Gaussian tail (ξ < 0) to its
//! power law (ξ > 0) sharpens (u | ξ narrows as α → 3/2) and 64 terms no
//! longer reach 1e-12 (8e-13 at α = 4, 1e-10 at α = 3): the direct path is used.

use super::kernel::{Chebyshev, Kernel, Kernels};
use crate::error::Result;
use crate::quad::gauss_legendre;
use crate::quad::integrate;

/// Table range in ξ.
pub(crate) const XI_MIN: f64 = -10.0;
/// Upper end of the table (δ ≤ 12 needs ξ ≤ 15.3).
pub(crate) const XI_MAX: f64 = 16.0;
/// Smallest α served by the table.
pub(crate) const MIN_ALPHA: f64 = 4.0;
/// Largest δ served by the table.
pub(crate) const DELTA_MAX: f64 = 12.0;
/// Chebyshev terms of each ln g.
pub(crate) const TERMS: usize = 64;
/// Gauss–Legendre nodes of the w-integral.
pub(crate) const NODES: usize = 64;
/// Gauss–Legendre nodes of the w-integral for δ ≥ 0 (a single bump).
pub(crate) const NODES_POSITIVE: usize = 32;
/// e^{−CUT} is the relative size of the neglected tail of the w-integral.
const CUT: f64 = 45.0;

/// ln g for count, area and load, and the w-rule.
#[derive(Debug, Clone)]
pub(crate) struct SummitTable {
    ln_g: [Chebyshev; 3],
    rule: (Vec<f64>, Vec<f64>),
    rule_positive: (Vec<f64>, Vec<f64>),
}

/// Exponents p = 2 + 2γ of the three weights.
const POWERS: [f64; 3] = [4.0, 3.0, 3.5];

impl SummitTable {
    /// Tabulate for √α and s_u = √(2/3 − 1/α).
    pub(crate) fn build(sqrt_alpha: f64, s_u: f64, kernels: &Kernels) -> Result<Self> {
        let ks: [&Kernel; 3] = [&kernels.count, &kernels.area, &kernels.load];
        let mut ln_g: Vec<Chebyshev> = Vec::with_capacity(3);
        for (i, kernel) in ks.iter().enumerate() {
            let vals = Chebyshev::nodes(XI_MIN, XI_MAX, TERMS)
                .map(|xi| ln_weight(xi / sqrt_alpha, s_u, POWERS[i], kernel))
                .collect::<Result<Vec<f64>>>()?;
            ln_g.push(Chebyshev::from_values(XI_MIN, XI_MAX, &vals));
        }
        let [a, b, c]: [Chebyshev; 3] =
            ln_g.try_into().map_err(|_| crate::Error::Inconsistent {
                name: "summit table".into(),
                requirement: "three weights".into(),
            })?;
        Ok(SummitTable {
            ln_g: [a, b, c],
            rule: gauss_legendre(NODES),
            rule_positive: gauss_legendre(NODES_POSITIVE),
        })
    }

    /// J/φ(δ) for count, area and load, and J_{½,¾}/φ(δ) (the load's
    /// δ-derivative is −(3/2) J_{½,¾}), or `None` outside the table.
    pub(crate) fn scaled(&self, delta: f64) -> Option<[f64; 4]> {
        if delta > DELTA_MAX {
            return None;
        }
        // t_max: e^{−δt − t²/2} = e^{−CUT} (beyond the peak at t = −δ when δ < 0).
        let t_max = if delta >= 0.0 {
            -delta + (delta * delta + 2.0 * CUT).sqrt()
        } else {
            -delta + (2.0 * CUT).sqrt()
        };
        let t_max = t_max.min(XI_MAX - delta);
        let t_min = (XI_MIN - delta).max(0.0);
        if t_max <= t_min {
            return Some([0.0; 4]);
        }
        let (w0, w1) = (t_min.sqrt(), t_max.sqrt());
        let (half, mid) = (0.5 * (w1 - w0), 0.5 * (w1 + w0));
        let mut out = [0.0; 4];
        let rule = if delta >= 0.0 {
            &self.rule_positive
        } else {
            &self.rule
        };
        for (x, wt) in rule.0.iter().zip(&rule.1) {
            let w = mid + half * x;
            let t = w * w;
            let e = (-(delta + 0.5 * t) * t).exp() * 2.0 * w * wt * half;
            let xi = delta + t;
            let [g_count, g_area, g_load] = Chebyshev::eval3(&self.ln_g, xi).map(f64::exp);
            out[0] += e * g_count;
            out[1] += e * t * g_area;
            out[2] += e * t * w * g_load;
            out[3] += e * w * g_load;
        }
        Some(out)
    }
}

/// Relative tolerance of the tabulated weights.
const WEIGHT_TOLERANCE: f64 = 1e-14;

/// ln g, g = ∫_0^∞ N(u; μ, s²) 3u^p K(3u²/2) du, by adaptive Gauss–Kronrod
/// around the peak u* of u^p N (u*(u* − μ) = p s²), the integrand scaled by
/// its value there so that nothing underflows far in the tail (μ ≪ 0).
pub(crate) fn ln_weight(mu: f64, s: f64, p: f64, kernel: &Kernel) -> Result<f64> {
    let u_star = 0.5 * (mu + (mu * mu + 4.0 * p * s * s).sqrt());
    let width = 1.0 / (1.0 / (s * s) + p / (u_star * u_star)).sqrt();
    let lo = (u_star - 16.0 * width).max(0.0);
    let hi = u_star + 16.0 * s;
    let ln_at = |u: f64| {
        let x = (u - mu) / s;
        p * u.ln() + (3.0 * kernel.eval(1.5 * u * u)).ln() - 0.5 * x * x
    };
    let peak = ln_at(u_star);
    let f = |u: f64| {
        if u > 0.0 {
            (ln_at(u) - peak).exp()
        } else {
            0.0
        }
    };
    let q = integrate(
        "BGT summit weight",
        f,
        lo,
        hi,
        1e-300,
        WEIGHT_TOLERANCE,
        20_000,
    )?;
    Ok(peak + q.value.ln() - (s * super::gaussian::SQRT_TAU).ln())
}

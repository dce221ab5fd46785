//! The diffusion ∂P/∂t = ∂²P/∂σ² above a moving absorbing boundary
//! σ = b(t), started from δ(σ − x0): a Volterra integral equation of the
//! second kind for the detachment rate g(t), solved by the product
//! trapezoidal rule on a given mesh.
//!
//! # Formula
//! With f(x, t | y, τ) = e^{−(x−y)²/(4(t−τ))}/√(4π(t−τ)) and Φ the standard
//! normal distribution, g(t) = −dA/dt is the first-passage density; for
//! x ≤ b(t) the free density is reached only through the boundary, which at
//! x = b(t) gives Fortet's equation Φ(u₀) = ∫₀^t g(τ) Φ(u(t, τ)) dτ,
//! u₀ = (b(t) − x0)/√(2t), u = (b(t) − b(τ))/√(2(t − τ)). Its t-derivative,
//! with (b′/2)·(the same identity for densities) subtracted, is
//! ```text
//! g(t) = 2Ψ₀(t) − 2 ∫₀^t g(τ) Ψ(t, τ) dτ
//! Ψ₀(t)   = f(b(t), t | x0, 0) [b′(t)/2 − (b(t) − x0)/(2t)]
//! Ψ(t, τ) = f(b(t), t | b(τ), τ) [b′(t)/2 − (b(t) − b(τ))/(2(t − τ))]  → 0 as τ → t
//! A(t)   = erf((x0 − b(t))/(2√t)) + ∫₀^t g(τ) erf((b(t) − b(τ))/(2√(t−τ))) dτ
//! A_t(t) = ½[erf((x0 − b)/(2√t)) − erf(x0/(2√t))] − ½∫₀^t g [erf(−b(τ)/s) − erf((b(t) − b(τ))/s)] dτ
//! L(t)   = M(x0, √(2t)) − ∫₀^t g(τ) M(b(τ), √(2(t − τ))) dτ,   s = 2√(t − τ)
//! M(y, s) = y Φ̄((b(t) − y)/s) + s φ((b(t) − y)/s)
//! ```
//! A is A/A0 = ∫_b^∞ P dσ (written so that a constant b gives erf exactly:
//! the integral vanishes), A_t the part under tension ∫_b^0 P dσ (b < 0), L
//! the pressure carried by the contact ∫_b^∞ σ P dσ, and D = ∫₀^t g the
//! fraction that detached. Identities: A + D = 1 and L − ∫₀^t (−b) g dτ = x0
//! (the free diffusion is a martingale).
//!
//! # Method
//! Product trapezoidal rule on the mesh t₀ = 0 < t₁ < … (Ψ(t, t) = 0 makes it
//! explicit): g_n = 2Ψ₀(t_n) − 2 Σ_{j<n} w_j g_j Ψ(t_n, t_j), O(N²). The
//! integrands behave like √(t − τ) at τ = t, so the error falls like h^{3/2}
//! or faster; the caller compares two meshes for its estimate.
//!
//! # References
//! A. Buonocore, A. G. Nobile, L. M. Ricciardi, Adv. Appl. Probab. 19, 784
//! (1987), doi:10.2307/1427102 (the regular kernel); R. Fortet, J. Math. Pures
//! Appl. 22, 177 (1943) (the first-kind equation).

use crate::special::{erf, erfc};

const FRAC_1_SQRT_4PI: f64 = 0.282_094_791_773_878_14;
const FRAC_1_SQRT_2PI: f64 = 0.398_942_280_401_432_7;

/// The solution at the requested mesh nodes.
#[derive(Debug, Clone)]
pub(crate) struct Solution {
    /// A/A0.
    pub contact: Vec<f64>,
    /// ∫_b^0 P dσ.
    pub tensile: Vec<f64>,
    /// ∫₀^t g dτ.
    pub detached: Vec<f64>,
    /// ∫_b^∞ σ P dσ.
    pub carried: Vec<f64>,
    /// ∫₀^t (−b) g dτ.
    pub released: Vec<f64>,
}

/// f(x, t | y, τ) at Δ = t − τ > 0.
#[inline]
fn heat(dx: f64, dt: f64) -> f64 {
    (-(dx * dx) / (4.0 * dt)).exp() * FRAC_1_SQRT_4PI / dt.sqrt()
}

/// Trapezoid weights of the nodes before the last one of any [t₀, t_k]:
/// (t₁ − t₀)/2 for j = 0, (t_{j+1} − t_{j−1})/2 for 0 < j < k (independent of k).
fn weights(t: &[f64]) -> Vec<f64> {
    let n = t.len();
    (0..n)
        .map(|j| match j {
            0 if n > 1 => 0.5 * (t[1] - t[0]),
            j if j + 1 < n => 0.5 * (t[j + 1] - t[j - 1]),
            _ => 0.0,
        })
        .collect()
}

/// Solve for g on the mesh (t, b, db) from x0 > b[0], t[0] = 0, and return
/// the outputs at the nodes `at`.
pub(crate) fn solve(t: &[f64], b: &[f64], db: &[f64], x0: f64, at: &[usize]) -> Solution {
    let n = t.len();
    let w = weights(t);
    let mut g = vec![0.0; n];
    for k in 1..n {
        let (tk, bk, half_db) = (t[k], b[k], 0.5 * db[k]);
        if tk <= 0.0 {
            continue; // still at t = 0 (ζ rounded to 1): g = 0
        }
        let d0 = bk - x0;
        let psi0 = heat(d0, tk) * (half_db - d0 / (2.0 * tk));
        let mut s = 0.0;
        for j in 0..k {
            if g[j] == 0.0 {
                continue;
            }
            let dt = tk - t[j];
            if dt <= 0.0 {
                continue; // a repeated time: the diagonal, where Ψ = 0
            }
            let dx = bk - b[j];
            s += w[j] * g[j] * heat(dx, dt) * (half_db - dx / (2.0 * dt));
        }
        g[k] = 2.0 * psi0 - 2.0 * s;
    }
    let mut sol = Solution {
        contact: Vec::with_capacity(at.len()),
        tensile: Vec::with_capacity(at.len()),
        detached: Vec::with_capacity(at.len()),
        carried: Vec::with_capacity(at.len()),
        released: Vec::with_capacity(at.len()),
    };
    for &k in at {
        let o = outputs_at(t, b, x0, &g, &w, k);
        sol.contact.push(o[0]);
        sol.tensile.push(o[1]);
        sol.detached.push(o[2]);
        sol.carried.push(o[3]);
        sol.released.push(o[4]);
    }
    sol
}

/// [A, A_t, D, L, released] at node k from g.
fn outputs_at(t: &[f64], b: &[f64], x0: f64, g: &[f64], w: &[f64], k: usize) -> [f64; 5] {
    if k == 0 || t[k] <= 0.0 {
        return [1.0, if x0 < 0.0 { 1.0 } else { 0.0 }, 0.0, x0, 0.0];
    }
    let (tk, bk) = (t[k], b[k]);
    let s0 = 2.0 * tk.sqrt();
    let mut a = erf((x0 - bk) / s0);
    let mut at = 0.5 * (erf((x0 - bk) / s0) - erf(x0 / s0));
    let mut carried = moment(x0, bk, s0);
    let (mut det, mut rel) = (0.0, 0.0);
    for j in 0..k {
        let wj = w[j] * g[j];
        det += wj;
        rel -= wj * b[j];
        if tk - t[j] <= 0.0 {
            // a repeated time: the limits of the last node below
            at -= if bk < 0.0 { 0.5 * wj } else { 0.0 };
            carried -= wj * 0.5 * bk;
            continue;
        }
        let s = 2.0 * (tk - t[j]).sqrt();
        let u = (bk - b[j]) / s;
        a += wj * erf(u);
        at -= 0.5 * wj * (erf(-b[j] / s) - erf(u));
        carried -= wj * moment(b[j], bk, s);
    }
    // the last node, weight (t_k − t_{k−1})/2; limits τ → t: erf(u) → 0,
    // erf(−b(τ)/s) → 1 (b < 0) or 0, M → b/2
    let wk = 0.5 * (tk - t[k - 1]) * g[k];
    det += wk;
    rel -= wk * bk;
    at -= if bk < 0.0 { 0.5 * wk } else { 0.0 };
    carried -= wk * 0.5 * bk;
    [a, at, det, carried, rel]
}

/// ∫_b^∞ σ N(σ; y, s²/2) dσ = y Φ̄(z) + (s/√2) φ(z), z = (b − y)√2/s.
#[inline]
fn moment(y: f64, b: f64, s: f64) -> f64 {
    let sd = s * std::f64::consts::FRAC_1_SQRT_2;
    let z = (b - y) / sd;
    y * 0.5 * erfc(z * std::f64::consts::FRAC_1_SQRT_2)
        + sd * FRAC_1_SQRT_2PI * (-0.5 * z * z).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A constant boundary: g is Lévy's first-passage density and A = erf
    /// (the method of images, Persson, Bucher & Chiaia (2002) Eq. 3).
    #[test]
    fn constant_boundary_is_the_image_solution() {
        let t: Vec<f64> = (0..=200).map(|i| (i as f64 / 200.0).powi(2)).collect();
        let b = vec![-0.3; t.len()];
        let db = vec![0.0; t.len()];
        let k = t.len() - 1;
        let s = solve(&t, &b, &db, 0.2, &[k]);
        let exact = erf(0.5 / (2.0 * t[k].sqrt()));
        assert!(
            (s.contact[0] - exact).abs() < 1e-15,
            "{} {exact}",
            s.contact[0]
        );
        // normalisation by the trapezoid rule on a coarse mesh
        assert!((s.contact[0] + s.detached[0] - 1.0).abs() < 1e-3);
    }
}

#[cfg(test)]
mod boundary_tests {
    use super::*;

    fn phi(z: f64) -> f64 {
        0.5 * erfc(-z * std::f64::consts::FRAC_1_SQRT_2)
    }

    /// Survival above b(t) = b0 + c t: Φ((d − ct)/√(2t)) − e^{cd} Φ((−d − ct)/√(2t)), d = x0 − b0
    /// (Bachelier–Lévy; the kernel Ψ vanishes, Ψ₀ and the outputs are tested).
    fn linear_exact(c: f64, d: f64, t: f64) -> f64 {
        phi((d - c * t) / (2.0 * t).sqrt()) - (c * d).exp() * phi((-d - c * t) / (2.0 * t).sqrt())
    }

    /// A geometric mesh from d²/120 to `end` with ratio r, t₀ = 0.
    fn graded(d: f64, end: f64, r: f64) -> Vec<f64> {
        let mut t = vec![0.0];
        let mut v = d * d / 120.0;
        while v < end {
            t.push(v);
            v *= r;
        }
        t.push(end);
        t
    }

    #[test]
    fn linear_boundary_matches_bachelier_levy() {
        for (c, x0) in [(-2.0, 0.1), (2.0, 0.3), (-10.0, 0.05)] {
            let b0 = -0.1;
            let mut last = f64::INFINITY;
            for n in [200usize, 400, 800] {
                let t: Vec<f64> = (0..=n).map(|i| 0.04 * i as f64 / n as f64).collect();
                let b: Vec<f64> = t.iter().map(|t| b0 + c * t).collect();
                let s = solve(&t, &b, &vec![c; t.len()], x0, &[n]);
                let err = (s.contact[0] - linear_exact(c, x0 - b0, t[n])).abs();
                // h^{3/2}: each halving divides the error by 2√2 ≈ 2.83
                assert!(err < 6e-6 && err < last / 2.5, "c = {c}, n = {n}: {err:e}");
                last = err;
            }
        }
    }

    /// A start just above a fast receding boundary (the pull-off regime): a
    /// Lévy spike at t ~ d² on a geometric mesh, second order in ln r.
    #[test]
    fn receding_boundary_near_the_start() {
        let (c, d, b0) = (-194.0, 7.3e-4, -0.073);
        let exact = linear_exact(c, d, 2e-5);
        let mut last = f64::INFINITY;
        for r in [1.1, 1.05, 1.025] {
            let t = graded(d, 2e-5, r);
            let b: Vec<f64> = t.iter().map(|t| b0 + c * t).collect();
            let k = t.len() - 1;
            let s = solve(&t, &b, &vec![c; t.len()], b0 + d, &[k]);
            let err = (s.contact[0] - exact).abs();
            assert!(err < last / 3.5, "r = {r}: {err:e}");
            last = err;
        }
        assert!(last < 3e-5, "{last:e}");
    }

    /// A curved boundary (Ψ ≠ 0): the differences between successive meshes
    /// shrink at second order.
    #[test]
    fn curved_boundary_converges() {
        let (c, kap, d, b0) = (-194.0, 3e6, 7.3e-4, -0.073);
        let mut values = Vec::new();
        for r in [1.1, 1.05, 1.025, 1.0125] {
            let t = graded(d, 2e-5, r);
            let b: Vec<f64> = t.iter().map(|t| b0 + c * t + 0.5 * kap * t * t).collect();
            let db: Vec<f64> = t.iter().map(|t| c + kap * t).collect();
            let k = t.len() - 1;
            values.push(solve(&t, &b, &db, b0 + d, &[k]).contact[0]);
        }
        let diffs: Vec<f64> = values.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
        for w in diffs.windows(2) {
            assert!(w[1] < w[0] / 3.0, "{diffs:?}");
        }
    }
}

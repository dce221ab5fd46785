//! Chebyshev–Lobatto panels: nested Clenshaw–Curtis weights, cumulative
//! (indefinite) integration and interpolation on 17 points.
//!
//! # Formula
//! On t ∈ [0, 1] the nodes are t_j = (1 − cos(jπ/16))/2, j = 0..16 (both ends
//! included). The degree-16 interpolant p(t) = Σ_m c_m T_m(2t − 1) of the
//! values f_j gives
//! ```text
//! c_m = (2/16) Σ″_j f_j T_m(s_j)   (first and last terms halved; c_0, c_16 halved)
//! ∫_0^{t_j} p dt = Σ_k S_jk f_k      (S: the cumulative-integration matrix)
//! ∫_0^1 p dt = Σ_k w16_k f_k,        w16_k = S_16,k   (Clenshaw–Curtis, 17 points)
//! ```
//! and `w8` are the 9-point Clenshaw–Curtis weights on the even nodes (nested),
//! so |Σ (w16 − w8) f| estimates the error of the 9-point rule at no cost; it
//! bounds the error of the 17-point value generously for smooth f.
//!
//! A panel [a, b] is mapped to t either linearly (x = a + h t) or, when the
//! integrand has a (x − a)^{k+1/2} singularity at its left end (a kink of a
//! log-log interpolated modulus entering the angular integral, see
//! [`super::angular`]), by x = a + h t², which turns it into a polynomial in t.
//!
//! # References
//! - L. N. Trefethen, *Approximation Theory and Approximation Practice*
//!   (SIAM, 2013), chapters 2–3 and 19 (Chebyshev points, coefficients,
//!   Clenshaw–Curtis quadrature).
//! - C. W. Clenshaw, A. R. Curtis, Numer. Math. 2, 197 (1960),
//!   doi:10.1007/BF01386223.

use std::sync::OnceLock;

/// Panel degree (intervals); the panel has `NODES` points.
pub(crate) const DEGREE: usize = 16;
/// Points per panel.
pub(crate) const NODES: usize = DEGREE + 1;

/// The nodes, weights and matrices of one 17-point panel on [0, 1].
pub(crate) struct Rule {
    /// Nodes t_j on [0, 1], ascending, t_0 = 0, t_16 = 1.
    pub t: [f64; NODES],
    /// 17-point Clenshaw–Curtis weights on [0, 1].
    pub w16: [f64; NODES],
    /// 9-point Clenshaw–Curtis weights on the even nodes (0 on odd ones).
    pub w8: [f64; NODES],
    /// Cumulative integration: ∫_0^{t_j} p = Σ_k cum[j][k] f_k.
    pub cum: [[f64; NODES]; NODES],
    /// Values to Chebyshev coefficients: c_m = Σ_k coef[m][k] f_k.
    pub coef: [[f64; NODES]; NODES],
}

/// The shared rule (built once).
pub(crate) fn rule() -> &'static Rule {
    static RULE: OnceLock<Rule> = OnceLock::new();
    RULE.get_or_init(build)
}

/// θ_j with s_j = cos θ_j = −cos(jπ/n) (ascending s).
fn theta(j: usize, n: usize) -> f64 {
    std::f64::consts::PI * (n - j) as f64 / n as f64
}

/// Values → Chebyshev coefficients for n intervals (n + 1 Lobatto points).
fn coefficient_matrix(n: usize) -> Vec<Vec<f64>> {
    let mut v = vec![vec![0.0; n + 1]; n + 1];
    for (m, row) in v.iter_mut().enumerate() {
        for (k, x) in row.iter_mut().enumerate() {
            let end = |i: usize| if i == 0 || i == n { 0.5 } else { 1.0 };
            *x = 2.0 / n as f64 * end(k) * end(m) * (m as f64 * theta(k, n)).cos();
        }
    }
    v
}

/// ∫_{−1}^{cos θ} T_m(σ) dσ.
fn t_integral(m: usize, th: f64) -> f64 {
    let s = th.cos();
    match m {
        0 => s + 1.0,
        1 => 0.5 * (s * s - 1.0),
        _ => {
            let mf = m as f64;
            let at = |k: f64| ((k * th).cos(), if (k as i64) % 2 == 0 { 1.0 } else { -1.0 });
            let (tp, sp) = at(mf + 1.0);
            let (tm, sm) = at(mf - 1.0);
            0.5 * (tp / (mf + 1.0) - tm / (mf - 1.0)) - 0.5 * (sp / (mf + 1.0) - sm / (mf - 1.0))
        }
    }
}

/// Cumulative-integration matrix on [0, 1] for n intervals.
fn cumulative_matrix(n: usize) -> Vec<Vec<f64>> {
    let v = coefficient_matrix(n);
    let mut s = vec![vec![0.0; n + 1]; n + 1];
    for (j, row) in s.iter_mut().enumerate() {
        let th = theta(j, n);
        for (k, x) in row.iter_mut().enumerate() {
            *x = 0.5 * (0..=n).map(|m| t_integral(m, th) * v[m][k]).sum::<f64>();
        }
    }
    s
}

fn build() -> Rule {
    let mut r = Rule {
        t: [0.0; NODES],
        w16: [0.0; NODES],
        w8: [0.0; NODES],
        cum: [[0.0; NODES]; NODES],
        coef: [[0.0; NODES]; NODES],
    };
    for j in 0..NODES {
        r.t[j] = 0.5 * (1.0 + theta(j, DEGREE).cos());
    }
    r.t[0] = 0.0;
    r.t[DEGREE] = 1.0;
    let cum = cumulative_matrix(DEGREE);
    let coef = coefficient_matrix(DEGREE);
    for j in 0..NODES {
        r.cum[j].copy_from_slice(&cum[j]);
        r.coef[j].copy_from_slice(&coef[j]);
    }
    r.w16 = r.cum[DEGREE];
    let half = DEGREE / 2;
    let w8 = &cumulative_matrix(half)[half];
    for (i, w) in w8.iter().enumerate() {
        r.w8[2 * i] = *w;
    }
    r
}

/// How a panel [a, b] is mapped to t ∈ [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Map {
    /// x = a + h t.
    Linear,
    /// x = a + h t² (a (x − a)^{k+1/2} singularity at the left end).
    LeftSingular,
}

impl Map {
    /// (x, dx/dt) at t for the panel [a, a + h].
    #[inline]
    pub fn at(self, a: f64, h: f64, t: f64) -> (f64, f64) {
        match self {
            Map::Linear => (a + h * t, h),
            Map::LeftSingular => (a + h * t * t, 2.0 * h * t),
        }
    }

    /// t of x in the panel [a, a + h] (clamped to [0, 1]).
    #[inline]
    pub fn inverse(self, a: f64, h: f64, x: f64) -> f64 {
        let u = ((x - a) / h).clamp(0.0, 1.0);
        match self {
            Map::Linear => u,
            Map::LeftSingular => u.sqrt(),
        }
    }
}

/// Chebyshev coefficients of the values `f` at the 17 nodes.
pub(crate) fn coefficients(f: &[f64; NODES]) -> [f64; NODES] {
    let r = rule();
    let mut c = [0.0; NODES];
    for (m, cm) in c.iter_mut().enumerate() {
        *cm = r.coef[m].iter().zip(f).map(|(a, b)| a * b).sum();
    }
    c
}

/// Σ c_m T_m(2t − 1) by Clenshaw's recurrence.
#[inline]
pub(crate) fn clenshaw(c: &[f64], t: f64) -> f64 {
    let s = 2.0 * t - 1.0;
    let (mut b1, mut b2) = (0.0, 0.0);
    for &cm in c.iter().skip(1).rev() {
        let b0 = 2.0 * s * b1 - b2 + cm;
        b2 = b1;
        b1 = b0;
    }
    s * b1 - b2 + c[0]
}

/// Solve the dense system `m x = r` (n ≤ 17) by Gaussian elimination with
/// partial pivoting, in place; `false` when singular.
#[allow(clippy::needless_range_loop)] // row and column indices, as in the textbook
pub(crate) fn solve(m: &mut [[f64; NODES]; NODES], r: &mut [f64; NODES], n: usize) -> bool {
    for col in 0..n {
        let p = (col..n)
            .max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))
            .unwrap_or(col);
        if m[p][col] == 0.0 || !m[p][col].is_finite() {
            return false;
        }
        m.swap(col, p);
        r.swap(col, p);
        for row in col + 1..n {
            let f = m[row][col] / m[col][col];
            for k in col..n {
                m[row][k] -= f * m[col][k];
            }
            r[row] -= f * r[col];
        }
    }
    for col in (0..n).rev() {
        let s: f64 = (col + 1..n).map(|k| m[col][k] * r[k]).sum();
        r[col] = (r[col] - s) / m[col][col];
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Weights and matrices from f64 cosines: a few ulps of rounding.
    const RULE_TOL: f64 = 1e-14;

    #[test]
    fn weights_integrate_polynomials() {
        let r = rule();
        for deg in 0..=16 {
            let f: Vec<f64> = r.t.iter().map(|t| t.powi(deg)).collect();
            let i16: f64 = r.w16.iter().zip(&f).map(|(w, f)| w * f).sum();
            assert!(
                (i16 - 1.0 / (deg + 1) as f64).abs() < RULE_TOL,
                "w16 deg {deg}"
            );
            if deg <= 8 {
                let i8: f64 = r.w8.iter().zip(&f).map(|(w, f)| w * f).sum();
                assert!(
                    (i8 - 1.0 / (deg + 1) as f64).abs() < RULE_TOL,
                    "w8 deg {deg}"
                );
            }
            for j in 0..NODES {
                let c: f64 = r.cum[j].iter().zip(&f).map(|(w, f)| w * f).sum();
                let exact = r.t[j].powi(deg + 1) / (deg + 1) as f64;
                assert!((c - exact).abs() < RULE_TOL, "cum deg {deg} node {j}");
            }
        }
    }

    #[test]
    fn interpolation_is_exact_for_polynomials() {
        let r = rule();
        let f: [f64; NODES] = std::array::from_fn(|j| 3.0 * r.t[j].powi(7) - r.t[j] + 0.5);
        let c = coefficients(&f);
        for &t in &[0.0, 0.123, 0.5, 0.77, 1.0] {
            let exact = 3.0 * f64::powi(t, 7) - t + 0.5;
            assert!((clenshaw(&c, t) - exact).abs() < RULE_TOL);
        }
    }

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn dense_solve() {
        let mut m = [[0.0; NODES]; NODES];
        let mut r = [0.0; NODES];
        let n = 5;
        for i in 0..n {
            for j in 0..n {
                m[i][j] = 1.0 / (1 + i + j) as f64 + if i == j { 1.0 } else { 0.0 };
            }
        }
        let x = [1.0, -2.0, 3.0, 0.5, 0.25];
        for i in 0..n {
            r[i] = (0..n).map(|j| m[i][j] * x[j]).sum();
        }
        assert!(solve(&mut m, &mut r, n));
        for i in 0..n {
            assert!((r[i] - x[i]).abs() < 1e-13);
        }
    }
}

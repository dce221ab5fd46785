//! One ζ-node's band of wavevector nodes and its three sums at any load:
//! the inner loop of [`super::table`], with the nodes where E1's argument
//! is below 1 summed as power series from stored moments.
//!
//! # Formula
//! With x = (w r)² per node (r = p/E*) and c the rule's coefficient, the
//! sums of [`super::table`] are
//! ```text
//! S0 = Σ c w ½E1(x),   S1 = Σ c w e^{−x},   S2 = Σ c w³ (½E1(x) − e^{−x}).
//! ```
//! The nodes are stored by decreasing w, so x decreases along the band and
//! the nodes with x < 1 are a tail i, i + 1, …. On the tail
//! (Abramowitz & Stegun 5.1.11, 4.2.1)
//! ```text
//! ½E1(x) = ½(−γ − ln x) + ½ Σ_{k≥1} a_k x^k,   a_k = (−1)^{k+1}/(k·k!)
//! e^{−x} = Σ_{k≥0} b_k x^k,                    b_k = (−1)^k/k!
//! ```
//! and with y = (w_i r)² ≤ 1 (w_i the tail's largest w) and the tail's
//! scaled moments M_k = Σ c w (w/w_i)^{2k} (all ≤ M_0, no overflow),
//! Λ1 = Σ c w ln w, Λ3 = Σ c w (w/w_i)² ln w:
//! ```text
//! S0 = ½(−γ − 2 ln r) M_0 − Λ1 + ½ Σ_{k≥1} a_k y^k M_k
//! S1 = Σ_{k≥0} b_k y^k M_k
//! S2 = w_i² [½(−γ − 2 ln r) M_1 − Λ3 + Σ_{k≥1} (½a_k − b_k) y^k M_{k+1} − b_0 M_1]
//! ```
//! The series stop at k = [`TERMS`]: the remainders are below
//! 1/(19·19!) and 1/19! ≈ 8e−18 of M_0, so the tail costs a few multiply-adds
//! per term instead of an exp, a log and a Chebyshev sum per node. The nodes
//! before the tail (x ≥ 1) are summed directly, E1 by
//! [`super::fast_e1`]; those with x ≥ 745 (e^{−x} underflows) are left out.

use super::fast_e1::{e1_fast, e1_fast_pair};
use crate::special::EULER_GAMMA;

/// Series terms of the tail sums (module docs).
const TERMS: usize = 18;

/// Values stored per tail and rule: M_0 … M_{TERMS+1}, Λ1, Λ3.
const ROW: usize = TERMS + 4;

/// Arguments of e^{−x} and E1(x) beyond which both underflow.
const UNDERFLOW_ARG: f64 = 745.0;

/// One wavevector node of a band: Kronrod and Gauss coefficients of
/// √π q² C (Jacobian included) and w_ζ(q).
#[derive(Debug, Clone, Copy)]
pub(super) struct QNode {
    pub(super) kronrod: f64,
    pub(super) gauss: f64,
    pub(super) w: f64,
}

/// A band's nodes by decreasing w and the moments of every tail (module docs).
#[derive(Debug, Clone, Default)]
pub(super) struct Band {
    nodes: Vec<QNode>,
    /// Per tail start i, at row n − 1 − i: Kronrod row then Gauss row, `ROW` values each.
    tails: Vec<f64>,
}

/// a_k = (−1)^{k+1}/(k·k!) and b_k = (−1)^k/k!, k = 0 … TERMS + 1.
fn coefficients() -> ([f64; TERMS + 2], [f64; TERMS + 2]) {
    let (mut a, mut b) = ([0.0; TERMS + 2], [0.0; TERMS + 2]);
    let mut factorial = 1.0;
    for k in 0..TERMS + 2 {
        if k > 0 {
            factorial *= k as f64;
        }
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        b[k] = sign / factorial;
        if k > 0 {
            a[k] = -sign / (k as f64 * factorial);
        }
    }
    (a, b)
}

impl Band {
    /// The band of `nodes` (any order); nodes with w not finite and positive are dropped.
    pub(super) fn new(mut nodes: Vec<QNode>) -> Band {
        nodes.retain(|n| n.w.is_finite() && n.w > 0.0);
        nodes.sort_by(|a, b| b.w.total_cmp(&a.w));
        let n = nodes.len();
        // backwards: the tail at i from the tail at i + 1, rescaled by
        // (w_{i+1}/w_i)^{2k}; stored in that order (the tail at i is row n − 1 − i)
        let mut tails = Vec::with_capacity(2 * ROW * n);
        let mut next = [[0.0; ROW]; 2];
        for i in (0..n).rev() {
            let node = nodes[i];
            let ratio2 = nodes
                .get(i + 1)
                .map_or(0.0, |after| (after.w / node.w) * (after.w / node.w));
            let ln_w = node.w.ln();
            for (rule, c) in [node.kronrod, node.gauss].into_iter().enumerate() {
                let row = &mut next[rule];
                let term = c * node.w;
                let mut scale = 1.0;
                for m in row.iter_mut().take(TERMS + 2) {
                    *m = term + scale * *m;
                    scale *= ratio2;
                }
                row[TERMS + 2] += term * ln_w;
                row[TERMS + 3] = term * ln_w + ratio2 * row[TERMS + 3];
                tails.extend_from_slice(row);
            }
        }
        Band { nodes, tails }
    }

    /// [S0, S1, S2] at r = p/E* (module docs), as (Kronrod, |Kronrod − Gauss|
    /// plus rounding).
    pub(super) fn sums(&self, r: f64) -> ([f64; 3], [f64; 3]) {
        let x_of = |n: &QNode| (n.w * r) * (n.w * r);
        let start = self.nodes.partition_point(|n| x_of(n) >= UNDERFLOW_ARG);
        let tail = self.nodes.partition_point(|n| x_of(n) >= 1.0);
        let (mut k, mut g) = ([0.0; 3], [0.0; 3]);
        // the direct nodes two at a time (two E1 sums in one loop)
        let mut add = |n: &QNode, ex: f64, e1: f64| {
            let half_e1 = 0.5 * e1;
            let v = [n.w * half_e1, n.w * ex, n.w * n.w * n.w * (half_e1 - ex)];
            for i in 0..3 {
                k[i] += n.kronrod * v[i];
                g[i] += n.gauss * v[i];
            }
        };
        let mut pairs = self.nodes[start..tail].chunks_exact(2);
        for pair in &mut pairs {
            let x = [x_of(&pair[0]), x_of(&pair[1])];
            let ex = [(-x[0]).exp(), (-x[1]).exp()];
            let e1 = e1_fast_pair(x, ex);
            add(&pair[0], ex[0], e1[0]);
            add(&pair[1], ex[1], e1[1]);
        }
        for n in pairs.remainder() {
            let x2 = x_of(n);
            let ex = (-x2).exp();
            add(n, ex, e1_fast(x2, ex));
        }
        if let Some(first) = self.nodes.get(tail) {
            let y = x_of(first);
            let w2 = first.w * first.w;
            let log_term = 0.5 * (-EULER_GAMMA - 2.0 * r.ln());
            let at = 2 * (self.nodes.len() - 1 - tail) * ROW;
            let (mk, mg) = self.tails[at..at + 2 * ROW].split_at(ROW);
            let [sk, sg] = tail_sums([mk, mg], y);
            for (out, m, s) in [(&mut k, mk, sk), (&mut g, mg, sg)] {
                out[0] += log_term * m[0] - m[TERMS + 2] + s[0];
                out[1] += s[1];
                out[2] += w2 * (log_term * m[1] - m[TERMS + 3] + s[2]);
            }
        }
        let mut e = [0.0; 3];
        for i in 0..3 {
            e[i] = (k[i] - g[i]).abs() + 8.0 * f64::EPSILON * k[i].abs();
        }
        (k, e)
    }
}

/// [½ Σ_{k≥1} a_k y^k M_k, Σ_{k≥0} b_k y^k M_k, Σ_{k≥1}(½a_k − b_k) y^k M_{k+1} − b_0 M_1]
/// for the Kronrod and the Gauss moments at once, by Horner's rule in y
/// from the last term that matters: the first left out, y^{K+1}/(K+1)!, is
/// below 1e−18 (K = 8, 11, 14 for
/// y ≤ 0.01, 0.1, 0.4; else [`TERMS`]).
fn tail_sums(m: [&[f64]; 2], y: f64) -> [[f64; 3]; 2] {
    let (a, b) = coefficients_cached();
    let top = if y <= 0.01 {
        8
    } else if y <= 0.1 {
        11
    } else if y <= 0.4 {
        14
    } else {
        TERMS
    };
    let mut s = [[0.0; 3]; 2];
    for k in (1..=top).rev() {
        let (ha, bk, c) = (0.5 * a[k], b[k], 0.5 * a[k] - b[k]);
        for (s, m) in s.iter_mut().zip(m) {
            s[0] = s[0] * y + ha * m[k];
            s[1] = s[1] * y + bk * m[k];
            s[2] = s[2] * y + c * m[k + 1];
        }
    }
    let finish =
        |s: [f64; 3], m: &[f64]| [s[0] * y, s[1] * y + b[0] * m[0], s[2] * y - b[0] * m[1]];
    [finish(s[0], m[0]), finish(s[1], m[1])]
}

/// [`coefficients`], computed once.
fn coefficients_cached() -> &'static ([f64; TERMS + 2], [f64; TERMS + 2]) {
    static COEFFICIENTS: std::sync::OnceLock<([f64; TERMS + 2], [f64; TERMS + 2])> =
        std::sync::OnceLock::new();
    COEFFICIENTS.get_or_init(coefficients)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::e1;

    /// The direct sums with the crate's E1 (checked against mpmath).
    fn direct(nodes: &[QNode], r: f64) -> [f64; 3] {
        let mut k = [0.0; 3];
        for n in nodes {
            let x = (n.w * r) * (n.w * r);
            if x >= UNDERFLOW_ARG {
                continue;
            }
            let (h, ex) = (0.5 * e1(x), (-x).exp());
            let v = [n.w * h, n.w * ex, n.w * n.w * n.w * (h - ex)];
            for i in 0..3 {
                k[i] += n.kronrod * v[i];
            }
        }
        k
    }

    /// The tail series against direct summation, for loads that put the
    /// tail at every node of a band whose w spans 12 decades.
    #[test]
    fn tail_series_equal_direct_sums() {
        let nodes: Vec<QNode> = (0..60)
            .map(|i| {
                let w = 10f64.powf(6.0 - 12.0 * f64::from(i) / 59.0);
                QNode {
                    kronrod: 1.0 + 0.1 * f64::from(i % 7),
                    gauss: 0.9,
                    w,
                }
            })
            .collect();
        let band = Band::new(nodes.clone());
        let mut worst: f64 = 0.0;
        for j in 0..=200 {
            let r = 10f64.powf(-7.5 + 14.0 * f64::from(j) / 200.0);
            let (fast, _) = band.sums(r);
            let reference = direct(&nodes, r);
            for i in 0..3 {
                if reference[i] != 0.0 {
                    worst = worst.max(((fast[i] - reference[i]) / reference[i]).abs());
                }
            }
        }
        assert!(worst < 1e-13, "worst relative difference {worst:e}");
    }
}

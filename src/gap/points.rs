//! P_nc(u) as a fixed set of weighted points: expectations of many functions
//! (the steps of a root search) at the cost of one sum each.
//!
//! # Method
//! Each ζ-node's folded Gaussian φ_h(u − u1) + φ_h(u + u1) on its window
//! [max(0, u1 − 10h), u1 + 10h], split at u1, by a fixed G7/K15 panel per
//! half (a point mass where the window is below 1e−6 u1, as in
//! [`super::SeparationDensity::expectation`]). The weights carry the ζ-rule's
//! coefficients, so Σ w f(u) = ∫ P_nc f du. The error of an expectation is
//! the ζ-rule's |Kronrod − Gauss| per panel plus the u-rule's per node,
//! both evaluated on f. Each node's Kronrod u-weights are scaled to the
//! Gaussian's unit mass on its window (a 1e−8 correction), so that a
//! constant f is integrated exactly.

use super::{SeparationDensity, NARROW, WG, WGK, WINDOW, XGK};
use crate::quad::Estimate;

/// Point weight below which a point does not set the largest separation.
const NEGLIGIBLE_POINT: f64 = 1e-20;

/// One point: separation and its three weights (Kronrod in both rules;
/// Gauss in ζ; Gauss in u), with the ζ-panel and node it belongs to.
#[derive(Debug, Clone, Copy)]
struct Point {
    u: f64,
    kronrod: f64,
    gauss_zeta: f64,
    gauss_u: f64,
    panel: u32,
    node: u32,
}

/// The image term's smallest argument b = (u + u1)/h on a window above which e^{−b²/2} underflows
/// to 0 (b²/2 > 745).
const MIRROR_CUT: f64 = 38.7;

/// One point of an unclipped window in units of h (see [`PointSet::new`]).
#[derive(Debug, Clone, Copy)]
struct Standard {
    offset: f64,
    density: f64,
    kronrod: f64,
    gauss: f64,
}

/// The G7/K15 rule on [−1, 1] as (node, Kronrod weight, Gauss weight),
/// ascending.
fn rule() -> impl Iterator<Item = (f64, f64, f64)> {
    (0..15).map(|i| {
        let j = if i < 8 { i } else { 14 - i };
        let sign = if i < 7 { -1.0 } else { 1.0 };
        let gauss = if j % 2 == 1 { WG[j / 2] } else { 0.0 };
        (sign * XGK[j], WGK[j], gauss)
    })
}

/// The points of a window clipped at 0 (u1 ≤ 10h): [0, u1] and
/// [u1, u1 + 10h], one G7/K15 panel each, pushed as (u, Kronrod weight,
/// Gauss weight) with the folded density times the half-width as the
/// weight factor.
///
/// # Method
/// With μ = u1/h and the rule's nodes ±x, the density's two terms need a
/// few exponentials per pair instead of two per point:
/// ```text
/// [0, u1]:        u = (u1/2)(1 + x), a = (μ/2)(x − 1),
///                 e^{−a²/2} = e^{−(μ²/8)(x² + 1)} · P^{±1},  P = e^{(μ²/4)x},
///                 image/direct = e^{−b²/2}/e^{−a²/2} = e^{−μ²} P^{∓4}
/// [u1, u1 + 10h]: u = u1 + 5h(1 + x), a = 5(1 + x) (fixed: `upper`),
///                 image/direct = e^{−2μ² − 10μ} Q^{±1},  Q = e^{−10μx}
/// ```
/// For μ ≤ 10 every factor stays within e^{±100}: no overflow or underflow.
fn clipped(u1: f64, h: f64, upper: &[(f64, f64); 8], push: &mut impl FnMut(f64, f64, f64)) {
    let mu = u1 / h;
    if mu > 0.0 {
        let scale = 0.5 * mu / std::f64::consts::TAU.sqrt();
        let image = (-mu * mu).exp();
        for (j, &x) in XGK.iter().enumerate() {
            let gauss = if j % 2 == 1 { WG[j / 2] } else { 0.0 };
            let e0 = (-0.125 * mu * mu * (x * x + 1.0)).exp();
            let p = (0.25 * mu * mu * x).exp();
            let p4 = (p * p) * (p * p);
            let plus = scale * e0 * p * (1.0 + image / p4);
            push(0.5 * u1 * (1.0 + x), WGK[j] * plus, gauss * plus);
            if x != 0.0 {
                let minus = scale * e0 / p * (1.0 + image * p4);
                push(0.5 * u1 * (1.0 - x), WGK[j] * minus, gauss * minus);
            }
        }
    }
    let c = (-2.0 * mu * mu - WINDOW * mu).exp();
    let half = 0.5 * WINDOW * h;
    for (j, &x) in XGK.iter().enumerate() {
        let gauss = if j % 2 == 1 { WG[j / 2] } else { 0.0 };
        let q = (-WINDOW * mu * x).exp();
        let (dp, dm) = upper[j];
        let plus = dp * (1.0 + c * q);
        push(u1 + half * (1.0 + x), WGK[j] * plus, gauss * plus);
        if x != 0.0 {
            let minus = dm * (1.0 + c / q);
            push(u1 + half * (1.0 - x), WGK[j] * minus, gauss * minus);
        }
    }
}

/// P_nc(u) as weighted points (module docs).
#[derive(Debug, Clone)]
pub struct PointSet {
    points: Vec<Point>,
    panels: usize,
    nodes: usize,
    weight_left_out: f64,
}

impl PointSet {
    /// The points of `density` (module docs).
    pub fn new(density: &SeparationDensity) -> Self {
        // an unclipped window's 30 points in units of h from u1, with
        // e^{−a²/2}/√(2π) × (half-width/h): the density times the panel's
        // half-width, in which h cancels
        let half_width = 0.5 * WINDOW / std::f64::consts::TAU.sqrt();
        let standard: Vec<Standard> = [-0.5 * WINDOW, 0.5 * WINDOW]
            .iter()
            .flat_map(|&mid| {
                rule().map(move |(x, wk, wg)| {
                    let offset = mid + 0.5 * WINDOW * x;
                    Standard {
                        offset,
                        density: (-0.5 * offset * offset).exp() * half_width,
                        kronrod: wk,
                        gauss: wg,
                    }
                })
            })
            .collect();
        // e^{−a²/2} × half-width/h at a = 5(1 ± x_j), the upper half of a
        // clipped window (see `clipped`)
        let upper: [(f64, f64); 8] = std::array::from_fn(|j| {
            let (p, m) = (0.5 * WINDOW * (1.0 + XGK[j]), 0.5 * WINDOW * (1.0 - XGK[j]));
            (
                (-0.5 * p * p).exp() * half_width,
                (-0.5 * m * m).exp() * half_width,
            )
        });
        let mut points = Vec::new();
        let mut node_id = 0u32;
        for (panel_id, panel) in density.panels.iter().enumerate() {
            for n in &panel.nodes {
                node_id += 1;
                if n.loss == 0.0 || !n.u1.is_finite() {
                    continue;
                }
                let (zk, zg) = (n.kronrod * n.loss, n.gauss * n.loss);
                let first = points.len();
                let mut push = |u: f64, wk: f64, wg: f64| {
                    points.push(Point {
                        u,
                        kronrod: zk * wk,
                        gauss_zeta: zg * wk,
                        gauss_u: zk * wg,
                        panel: panel_id as u32,
                        node: node_id,
                    })
                };
                if n.h <= 0.0 || WINDOW * n.h <= NARROW * n.u1 {
                    push(n.u1, 1.0, 1.0);
                    continue;
                }
                let lo = (n.u1 - WINDOW * n.h).max(0.0);
                // the image term φ_h(u + u1) underflows everywhere on the
                // window when (u1 − 10h + u1)/h > MIRROR_CUT
                let image = 2.0 * n.u1 / n.h - WINDOW <= MIRROR_CUT;
                if lo > 0.0 {
                    // the whole window: fixed standardised points (no exp
                    // unless the image term is alive)
                    for s in &standard {
                        let u = n.u1 + n.h * s.offset;
                        let mut d = s.density;
                        if image {
                            let b = s.offset + 2.0 * n.u1 / n.h;
                            d += (-0.5 * b * b).exp() * half_width;
                        }
                        push(u, s.kronrod * d, s.gauss * d);
                    }
                } else {
                    clipped(n.u1, n.h, &upper, &mut push);
                }
                // the folded Gaussian has unit mass on its window (to 1e−22):
                // scale the Kronrod u-rule to it, so a constant f is exact
                let mass: f64 = points[first..].iter().map(|p| p.kronrod).sum::<f64>() / zk;
                if mass > 0.0 {
                    for p in &mut points[first..] {
                        p.kronrod /= mass;
                        p.gauss_zeta /= mass;
                    }
                }
            }
        }
        PointSet {
            points,
            panels: density.panels.len(),
            nodes: node_id as usize + 1,
            weight_left_out: density.weight_left_out,
        }
    }

    /// Σ w f(u) and its derivative's sum Σ w f′(u) for a pair (f, f′)
    /// given as one function returning both: the Kronrod values only.
    pub fn sum2(&self, f: impl Fn(f64) -> (f64, f64)) -> (f64, f64) {
        let (mut a, mut b) = (0.0, 0.0);
        for p in &self.points {
            let (v, d) = f(p.u);
            a += p.kronrod * v;
            b += p.kronrod * d;
        }
        (a, b)
    }

    /// ∫ P_nc f du with its error (module docs; the weight the table left
    /// out counts at the largest |f| over the points).
    pub fn expectation(&self, f: impl Fn(f64) -> f64) -> Estimate {
        let mut bound: f64 = 0.0;
        let mut zeta = vec![0.0; self.panels];
        let mut u = vec![0.0; self.nodes];
        let mut total = 0.0;
        for p in &self.points {
            let v = f(p.u);
            bound = bound.max(v.abs());
            total += p.kronrod * v;
            zeta[p.panel as usize] += (p.kronrod - p.gauss_zeta) * v;
            u[p.node as usize] += (p.kronrod - p.gauss_u) * v;
        }
        let e: f64 = zeta.iter().chain(u.iter()).map(|d| d.abs()).sum();
        Estimate {
            value: total,
            error: e + self.weight_left_out * bound + 16.0 * f64::EPSILON * total.abs(),
        }
    }

    /// Largest separation of the points of weight above 1e−20, m (near
    /// ζ = 1, u1 grows without bound while −A′ vanishes faster).
    pub(crate) fn largest_separation(&self) -> f64 {
        self.points
            .iter()
            .filter(|p| p.kronrod > NEGLIGIBLE_POINT)
            .map(|p| p.u)
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `clipped`'s weights against the folded density at the same points
    /// (φ_h(u − u1) + φ_h(u + u1) times the half-width), across μ = u1/h.
    #[test]
    fn clipped_weights_are_the_folded_density() {
        let half_width = 0.5 * WINDOW / std::f64::consts::TAU.sqrt();
        let upper: [(f64, f64); 8] = std::array::from_fn(|j| {
            let (p, m) = (0.5 * WINDOW * (1.0 + XGK[j]), 0.5 * WINDOW * (1.0 - XGK[j]));
            (
                (-0.5 * p * p).exp() * half_width,
                (-0.5 * m * m).exp() * half_width,
            )
        });
        let h = 3e-7;
        for mu in [0.0, 1e-3, 0.3, 1.0, 4.0, 9.9] {
            let u1 = mu * h;
            let mut worst: f64 = 0.0;
            let mut count = 0;
            clipped(u1, h, &upper, &mut |u: f64, wk: f64, _wg: f64| {
                // the panel's half-width: u1/2 below u1, 5h above
                let half = if u < u1 { 0.5 * u1 } else { 0.5 * WINDOW * h };
                let c = 1.0 / (std::f64::consts::TAU.sqrt() * h);
                let (a, b) = ((u - u1) / h, (u + u1) / h);
                let direct = c * ((-0.5 * a * a).exp() + (-0.5 * b * b).exp()) * half;
                let j = (0..8)
                    .find(|&j| {
                        let x = ((u - if u < u1 { 0.5 * u1 } else { u1 + half }) / half).abs();
                        (x - XGK[j]).abs() < 1e-9
                    })
                    .unwrap_or(7);
                worst = worst.max((wk / WGK[j] / direct - 1.0).abs());
                count += 1;
            });
            assert_eq!(count, if mu > 0.0 { 30 } else { 15 }, "μ = {mu}");
            assert!(worst < 1e-13, "μ = {mu}: {worst:e}");
        }
    }
}

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

use super::{folded, SeparationDensity, NARROW, WG, WGK, WINDOW, XGK};
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
                let hi = n.u1 + WINDOW * n.h;
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
                    for (a, b) in [(lo, n.u1), (n.u1, hi)] {
                        if b <= a {
                            continue;
                        }
                        let (half, mid) = (0.5 * (b - a), 0.5 * (a + b));
                        for (x, wk, wg) in rule() {
                            let u = mid + half * x;
                            let d = folded(u, n.u1, n.h) * half;
                            push(u, wk * d, wg * d);
                        }
                    }
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
    pub fn largest_separation(&self) -> f64 {
        self.points
            .iter()
            .filter(|p| p.kronrod > NEGLIGIBLE_POINT)
            .map(|p| p.u)
            .fold(0.0, f64::max)
    }
}

//! Polonsky–Keer constrained conjugate gradient for frictionless, non-adhesive
//! contact of a rigid rough surface with an elastic half-space.
//!
//! # What it solves
//! Given the rigid surface heights `h` on an `N × N` grid (peaks touch first)
//! and the compliance operator 𝒢 ([`Operator`]), find nodal pressures `p`
//! minimising the complementary energy under the contact constraints:
//! ```text
//! minimise  ½ ⟨p, 𝒢p⟩ − ⟨p, h⟩        subject to  p ≥ 0  and either
//!   mean pressure control:  (1/N²) Σ p = p̄           (the approach δ is the multiplier)
//!   penetration control:    gap = 𝒢p − (h − max h) − δ with δ given
//! KKT:  gap ≥ 0,  p ≥ 0,  p · gap = 0
//! ```
//! The gap is `g = u − (h − max h) − δ` with `u = 𝒢p` the displacement of
//! the elastic surface and δ the approach (rigid-body penetration) measured
//! from first touch. With the periodic operator the mean of `u` is zero, so
//! δ is measured from the mean plane of the deformed elastic surface.
//!
//! # Algorithm
//! Polonsky & Keer (1999), §2: conjugate gradient on the contact set
//! `I_c = {p > 0}`, restarted when the active set grows (points with `p = 0`
//! and `g < 0` re-enter with `p = −τ g`), with the mean gap on `I_c` removed
//! and the pressure rescaled to the target mean after each step (mean
//! pressure control). Two applications of 𝒢 per iteration; when the active
//! set did not change during a step (or changed at a few nodes, whose
//! correction is summed directly) the displacement is updated linearly
//! (`u ← s(u − τ 𝒢t)`) instead, and it is always recomputed from `p` before
//! convergence is declared.
//!
//! Only the gap is stored (the displacement is `g + h` up to the offset), the
//! step's rescaling of p is applied by the next step (which rewrites p
//! anyway), and the search direction is formed row by row as the transform
//! of 𝒢t reads it, whose output rows feed the step's sums: four `N × N`
//! fields, and two passes per iteration besides the transform's (the solve
//! is bound by memory traffic as much as by the FFTs).
//!
//! # Convergence criterion
//! ```text
//! ε = Σ_i p_i (g_i − min_{I_c} g) / (Σ_i p_i · σ_h)      (mean pressure control)
//! ε = Σ_i p_i |g_i| / (Σ_i p_i · σ_h)                     (penetration control)
//! σ_h = sqrt(Σ (h_i − h̄)² / (N² − 1))
//! ```
//! the pressure-weighted mean gap over the contact, relative to the rms
//! height: dimensionless and independent of the units of p and h. A solve
//! stops when ε ≤ `tol` and no points with `p = 0` overlap (`g < 0`);
//! otherwise it fails with [`Error::NotConverged`] after `max_iter`
//! iterations, reporting the last ε. This is the criterion Tamaas 2.9 reports
//! for its `PolonskyKeerRey` solver (measured: equal to 15 digits on the
//! same state), so equal `tol` means equal stopping rules.
//!
//! # References
//! I. A. Polonsky & L. M. Keer, Wear 231, 206–219 (1999),
//! doi:10.1016/S0043-1648(99)00113-1 (the constrained conjugate gradient).
//! Frérot, Anciaux, Rey & Molinari, J. Open Source Softw. 5, 2121 (2020)
//! (Tamaas), for the error measure.

use std::cell::Cell;
use std::time::Instant;

use super::kernel::Operator;
use crate::error::{check, Error, Result};

/// What is prescribed: the mean pressure or the penetration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Control {
    /// Nominal mean pressure p̄ = load / L² (same unit as E*), > 0.
    MeanPressure(f64),
    /// Approach δ from first touch (unit of L), ≥ 0.
    Penetration(f64),
}

/// Accuracy knobs of the solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Relative tolerance on ε (see the module docs), in `[1e-15, 0.1]`.
    pub tolerance: f64,
    /// Maximum number of CG iterations.
    pub max_iterations: usize,
    /// Start from the previous solution (rescaled to the new load) when the
    /// workspace holds one: speeds up load sweeps.
    pub warm_start: bool,
    /// Yield stress σY (hardness, unit of E*): pressures are bounded by
    /// `0 ≤ p ≤ σY` (the saturated problem, see [`super::saturated`]).
    /// `None`: the elastic problem, solved exactly as without this field.
    pub yield_stress: Option<f64>,
}

impl Default for Options {
    /// `tolerance = 1e-10`, `max_iterations = 10 000`, no warm start, no yield stress.
    fn default() -> Self {
        Options {
            tolerance: 1e-10,
            max_iterations: 10_000,
            warm_start: false,
            yield_stress: None,
        }
    }
}

/// One iteration's state, reported to an observer (progress bars, logs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Iteration {
    /// Iteration number, from 0.
    pub iteration: usize,
    /// Convergence measure ε before this iteration's step.
    pub residual: f64,
    /// Fraction of nodes in contact.
    pub contact_fraction: f64,
}

/// A converged contact solution.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Solution {
    /// Nodal pressures, `N × N` row-major (unit of E*).
    pub pressure: Vec<f64>,
    /// Gap between the surfaces, ≥ 0 up to the tolerance, 0 on the contact (unit of L).
    pub gap: Vec<f64>,
    /// Normal displacement of the elastic surface `u = 𝒢p` (unit of L).
    pub displacement: Vec<f64>,
    /// Mean pressure Σp/N² (equals the target under mean pressure control).
    pub mean_pressure: f64,
    /// Approach δ from first touch (see the module docs), unit of L.
    pub approach: f64,
    /// A/A0: fraction of nodes with p > 0 (elastic + plastic).
    pub contact_fraction: f64,
    /// Fraction of nodes with 0 < p < σY (all of the contact without a yield stress).
    pub elastic_fraction: f64,
    /// Fraction of nodes with p = σY (0 without a yield stress).
    pub plastic_fraction: f64,
    /// Mean interpenetration (plastic displacement, −gap) over the nodes at
    /// p = σY, unit of L (0 without plastic nodes).
    pub plastic_displacement_mean: f64,
    /// Largest interpenetration over the nodes at p = σY, unit of L.
    pub plastic_displacement_max: f64,
    /// CG iterations used.
    pub iterations: usize,
    /// Final ε (≤ tol).
    pub residual: f64,
    /// Wall-clock time of the solve, s.
    pub seconds: f64,
}

/// The Polonsky–Keer solver with its preallocated workspace.
///
/// All buffers (4 N² values plus the operator's) are allocated by
/// [`Solver::new`]; an iteration allocates nothing. The gap and displacement
/// buffers move into the returned [`Solution`] and are allocated again by the
/// next solve.
#[derive(Debug)]
pub struct Solver {
    pub(super) op: Operator,
    pub(super) p: Vec<f64>,
    pub(super) g: Vec<f64>,
    pub(super) t: Vec<f64>,
    pub(super) r: Vec<f64>,
    /// Indices and values of the sparse correction of one step.
    sparse_idx: Vec<usize>,
    sparse_val: Vec<f64>,
    pub(super) warm: bool,
}

/// Independent partial sums per reduction (lets the compiler vectorise).
const LANES: usize = 4;

/// The pending part of a step's gap update, applied in the next gap pass
/// if `update`: `g ← s·(g + h − o − τ r) − h + o` (that is `u ← s·(u − τ𝒢t)`).
/// (The step's rescaling of p is deferred to the next step, which writes p
/// anyway: p is held as `p_scale · p` in memory.)
#[derive(Debug, Clone, Copy)]
struct Pending {
    g_scale: f64,
    tau: f64,
    update: bool,
}

impl Pending {
    const NONE: Pending = Pending {
        g_scale: 1.0,
        tau: 0.0,
        update: false,
    };
}

/// `Σ_c (g − ḡ)²` over the contact `p > 0`.
fn contact_norm(g: &[f64], p: &[f64], g_bar: f64) -> f64 {
    let mut acc = [0.0f64; LANES];
    for (gc, pc) in g.chunks(LANES).zip(p.chunks(LANES)) {
        for l in 0..gc.len() {
            let v = gc[l] - g_bar;
            let m = if pc[l] > 0.0 { 1.0 } else { 0.0 };
            acc[l] += m * v * v;
        }
    }
    acc.iter().sum()
}

/// One row of the search direction, `t ← m (g − ḡ + β t)` with `m = [p > 0]`,
/// written to `t` and `out`; returns `[Σ t, Σ (g − ḡ) t]` over the row.
fn direction_row(
    p: &[f64],
    g: &[f64],
    t: &[Cell<f64>],
    g_bar: f64,
    beta: f64,
    out: &mut [f64],
) -> [f64; 2] {
    let mut acc = [[0.0f64; LANES]; 2];
    let chunks = p
        .chunks(LANES)
        .zip(g.chunks(LANES))
        .zip(t.chunks(LANES))
        .zip(out.chunks_mut(LANES));
    for (((pc, gc), tc), oc) in chunks {
        for l in 0..pc.len() {
            let m = if pc[l] > 0.0 { 1.0 } else { 0.0 };
            let dg = gc[l] - g_bar;
            let v = m * (dg + beta * tc[l].get());
            tc[l].set(v);
            oc[l] = v;
            acc[0][l] += v;
            acc[1][l] += dg * v;
        }
    }
    acc.map(|a| a.iter().sum())
}

/// One row of the response `r = 𝒢t`, copied to `r`; returns
/// `[Σ_c r, Σ r t]` over the row (t vanishes off the contact).
fn response_row(p: &[f64], t: &[Cell<f64>], row: &[f64], r: &mut [f64]) -> [f64; 2] {
    let mut acc = [[0.0f64; LANES]; 2];
    let chunks = p
        .chunks(LANES)
        .zip(t.chunks(LANES))
        .zip(row.chunks(LANES))
        .zip(r.chunks_mut(LANES));
    for (((pc, tc), xc), rc) in chunks {
        for l in 0..pc.len() {
            let m = if pc[l] > 0.0 { 1.0 } else { 0.0 };
            let x = xc[l];
            rc[l] = x;
            acc[0][l] += m * x;
            acc[1][l] += x * tc[l].get();
        }
    }
    acc.map(|a| a.iter().sum())
}

/// Most nodes whose step is corrected by direct summation rather than by
/// recomputing `𝒢p` with two FFTs: log₂(N²) (18 at 512², 20 at 1024²). One
/// node costs N² multiply-adds against the FFT's ~N² log₂(N²). Best of 2–3
/// rough solves (`persson bem rough`, H = 0.8, tol 1e-10) with ½×, 1× and
/// 1.5× log₂(N²): 0.876 / 0.850 / 0.868 s at 512², 7.82 / 7.26 / 7.33 s at
/// 1024².
fn sparse_limit(n2: usize) -> usize {
    n2.max(2).ilog2() as usize
}

/// Sums over the contact set gathered in one pass.
#[derive(Default)]
struct GapStats {
    sum_p: f64,
    sum_pg: f64,
    sum_pabs: f64,
    g_min: f64,
    /// Σ_c (g − g_ref) and Σ_c (g − g_ref)² over the contact.
    sum_dg: f64,
    sum_dg2: f64,
    count: usize,
    /// Lowest gap outside the contact set.
    g_min_off: f64,
}

impl Solver {
    /// A solver for the operator's grid.
    pub fn new(op: Operator) -> Self {
        let n2 = op.n() * op.n();
        Solver {
            op,
            p: vec![0.0; n2],
            g: vec![0.0; n2],
            t: vec![0.0; n2],
            r: vec![0.0; n2],
            sparse_idx: Vec::with_capacity(sparse_limit(n2)),
            sparse_val: Vec::with_capacity(sparse_limit(n2)),
            warm: false,
        }
    }

    /// The compliance operator.
    pub fn operator(&mut self) -> &mut Operator {
        &mut self.op
    }

    /// Solve for the rigid surface `heights` (`N × N`, unit of L).
    ///
    /// # Errors
    /// Heights of the wrong length or not finite, a target ≤ 0 (or a
    /// penetration beyond what a periodic system can carry), an invalid
    /// tolerance; [`Error::NotConverged`] after `max_iter` iterations.
    pub fn solve(&mut self, heights: &[f64], control: Control, opts: &Options) -> Result<Solution> {
        self.solve_observed(heights, control, opts, &mut |_| {})
    }

    /// [`Solver::solve`], calling `observer` once per iteration.
    ///
    /// # Errors
    /// As [`Solver::solve`].
    pub fn solve_observed(
        &mut self,
        heights: &[f64],
        control: Control,
        opts: &Options,
        observer: &mut dyn FnMut(Iteration),
    ) -> Result<Solution> {
        match opts.yield_stress {
            Some(y) => super::saturated::solve(self, heights, control, y, opts, observer),
            None => self.solve_elastic(heights, control, opts, observer),
        }
    }

    /// The elastic problem (`opts.yield_stress` is not read).
    pub(super) fn solve_elastic(
        &mut self,
        heights: &[f64],
        control: Control,
        opts: &Options,
        observer: &mut dyn FnMut(Iteration),
    ) -> Result<Solution> {
        let start = Instant::now();
        let n = self.op.n();
        let n2 = n * n;
        check::tolerance("tol", opts.tolerance)?;
        for buf in [&mut self.g, &mut self.t, &mut self.r] {
            if buf.len() != n2 {
                *buf = vec![0.0; n2];
            }
        }
        if heights.len() != n2 {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!("N² = {n2} values, got {}", heights.len()),
            });
        }
        if let Some(k) = heights.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid(
                format!("height[{}, {}]", k / n, k % n),
                heights[k],
                "finite",
            ));
        }
        let h_max = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let h_mean = heights.iter().sum::<f64>() / n2 as f64;
        let sigma_h =
            (heights.iter().map(|h| (h - h_mean).powi(2)).sum::<f64>() / (n2 as f64 - 1.0)).sqrt();
        let (target, delta) = match control {
            Control::MeanPressure(pm) => (Some(check::positive("pressure", pm)?), 0.0),
            Control::Penetration(d) => {
                check::non_negative("penetration", d)?;
                if self.op.boundary() == super::Boundary::Periodic && d >= h_max - h_mean {
                    return Err(Error::invalid(
                        "penetration",
                        d,
                        format!(
                            "below max(h) − mean(h) = {:e} in a periodic system (full contact needs infinite load)",
                            h_max - h_mean
                        ),
                    ));
                }
                (None, d)
            }
        };
        if sigma_h == 0.0 {
            return self.flat(target, delta, start);
        }

        // A stiffness guess E* π/Δ (pressure per unit overlap) for starting
        // points: any p ≥ 0 works, this one is of the right order.
        let stiffness = self.op.e_star() * std::f64::consts::PI * n as f64 / self.op.size();
        // Initial pressure.
        match target {
            Some(pm) => {
                let mean = self.p.iter().sum::<f64>() / n2 as f64;
                if opts.warm_start && self.warm && mean > 0.0 {
                    let s = pm / mean;
                    self.p.iter_mut().for_each(|v| *v *= s);
                } else {
                    self.p.fill(pm);
                }
            }
            None => {
                if !(opts.warm_start && self.warm) {
                    for (p, h) in self.p.iter_mut().zip(heights) {
                        *p = stiffness * (h - h_max + delta).max(0.0);
                    }
                }
            }
        }
        self.warm = false;
        // The gap is g = u − (h − o), o = max h − δ (δ = 0 under mean
        // pressure control, whose gap is shifted by its contact mean each
        // step). h − o is always formed first: it is the size of the
        // roughness, so a large mean height costs no digits in the gap (with
        // u − h + o instead, heights shifted by +100 stalled a 64² solve at
        // ε ≈ 4e-10).
        let offset = h_max - delta;

        self.refresh_gap(heights, offset, 1.0)?;
        let mut fresh = true;
        let mut g_old = 1.0;
        let mut conjugate = false;
        // The step's linear gap update (with its rescaling s) is applied
        // lazily, in the next gap pass.
        let mut pending = Pending::NONE;
        // The pressure is `p_scale · p` (the step's rescaling is applied by
        // the next step, which rewrites p anyway).
        let mut p_scale = 1.0;
        let mut g_ref = 0.0;
        self.t.fill(0.0);
        let mut k = 0usize;
        let (residual, stats) = loop {
            let st = self.gap_stats(heights, offset, pending, g_ref, p_scale);
            pending = Pending::NONE;
            let eps = match target {
                Some(_) if st.sum_p > 0.0 => {
                    (st.sum_pg - st.g_min * st.sum_p) / (st.sum_p * sigma_h)
                }
                None if st.sum_p > 0.0 => st.sum_pabs / (st.sum_p * sigma_h),
                _ => 0.0,
            };
            observer(Iteration {
                iteration: k,
                residual: eps,
                contact_fraction: st.count as f64 / n2 as f64,
            });
            // Points outside the contact that overlap the rigid surface by
            // more than the tolerance (gap measured from the contact level).
            let level = if target.is_some() { st.g_min } else { 0.0 };
            let overlap = st.g_min_off < level - opts.tolerance * sigma_h;
            if eps <= opts.tolerance && !overlap {
                if fresh {
                    break (eps, st);
                }
                self.refresh_gap(heights, offset, p_scale)?;
                fresh = true;
                continue;
            }
            if k >= opts.max_iterations {
                return Err(Error::NotConverged {
                    what: "Polonsky–Keer contact solver".into(),
                    iterations: k,
                    residual: eps,
                    tolerance: opts.tolerance,
                });
            }
            if st.count == 0 && target.is_none() {
                // No contact but overlap: start the pressure there.
                conjugate = false;
            }
            // Gap relative to its contact mean ḡ (load control) and its norm
            // Σ_c (g − ḡ)², from sums about the reference g_ref (the last ḡ);
            // recomputed directly when that cancels more than 6 digits.
            let (g_bar, g_norm) = match target {
                Some(_) if st.count > 0 => {
                    let c = st.count as f64;
                    let d = st.sum_dg / c;
                    let norm = st.sum_dg2 - c * d * d;
                    let g_bar = g_ref + d;
                    if norm > 1e-6 * st.sum_dg2 {
                        (g_bar, norm)
                    } else {
                        (g_bar, contact_norm(&self.g, &self.p, g_bar))
                    }
                }
                _ => (0.0, contact_norm(&self.g, &self.p, 0.0)),
            };
            g_ref = g_bar;
            let beta = if conjugate { g_norm / g_old } else { 0.0 };
            g_old = g_norm;
            let [s_r, s_t, s_gt, s_rt] = self.direction_and_response(g_bar, beta)?;
            let denom = match target {
                Some(_) if st.count > 0 => s_rt - s_r / st.count as f64 * s_t,
                _ => s_rt,
            };
            let tau = if denom > 0.0 && denom.is_finite() {
                s_gt / denom
            } else {
                0.0
            };
            // Step, projection onto p ≥ 0, and re-entry of overlapping points.
            // `changed` counts the nodes where the step is not linear in τ;
            // their corrections c are kept while there are few of them.
            let limit = sparse_limit(n2);
            self.sparse_idx.clear();
            self.sparse_val.clear();
            let mut changed = 0usize;
            let mut overlap = false;
            let mut sums = [0.0f64; LANES];
            // Overlapping points enter with p = −τ g (degenerate step τ = 0:
            // with the overlap times the stiffness guess).
            let entry = if tau > 0.0 { -tau } else { -stiffness };
            let (sparse_idx, sparse_val) = (&mut self.sparse_idx, &mut self.sparse_val);
            let (p, t, g) = (&mut self.p[..n2], &self.t[..n2], &self.g[..n2]);
            let mut node = |k: usize, l: usize| {
                // p − τt (t = 0 off the contact, where p = 0 too), clamped.
                let linear = p_scale * p[k] - tau * t[k];
                let clamped = if linear > 0.0 { linear } else { 0.0 };
                let gs = g[k] - g_bar;
                let enters = (clamped == 0.0) & (gs < 0.0);
                let v = if enters { entry * gs } else { clamped };
                overlap |= enters;
                p[k] = v;
                sums[l] += v;
                if v != linear {
                    changed += 1;
                    if changed <= limit {
                        sparse_idx.push(k);
                        sparse_val.push(v - linear);
                    }
                }
            };
            let body = n2 - n2 % LANES;
            for i in (0..body).step_by(LANES) {
                for l in 0..LANES {
                    node(i + l, l);
                }
            }
            for k in body..n2 {
                node(k, 0);
            }
            let sum_p: f64 = sums.iter().sum();
            conjugate = !overlap;
            let scale = match target {
                Some(pm) if sum_p > 0.0 => pm * n2 as f64 / sum_p,
                _ => 1.0,
            };
            let sparse = changed <= limit
                && self
                    .op
                    .add_sparse(&self.sparse_idx, &self.sparse_val, &mut self.g);
            if changed == 0 || sparse {
                // u = s (u − τ 𝒢t + 𝒢c), c the sparse correction (just added).
                pending = Pending {
                    g_scale: scale,
                    tau,
                    update: true,
                };
                fresh = false;
            } else {
                // u = 𝒢(s p) = s 𝒢p.
                self.refresh_gap(heights, offset, scale)?;
                fresh = true;
            }
            p_scale = scale;
            k += 1;
        };
        self.p.iter_mut().for_each(|p| *p *= p_scale);

        // Final gap: zero at the lowest contact point (load control).
        let shift = match target {
            Some(_) if stats.count > 0 => stats.g_min,
            _ => 0.0,
        };
        // The gap and displacement buffers move into the solution (the next
        // solve allocates new ones): no copies at the peak of memory use.
        // The last gap was computed from a fresh 𝒢p (convergence is declared
        // only then), so u = g + (h − o) needs no further transform.
        let mut gap = std::mem::take(&mut self.g);
        let mut displacement = std::mem::take(&mut self.r);
        for ((u, g), h) in displacement.iter_mut().zip(gap.iter_mut()).zip(heights) {
            *u = *g + (h - offset);
            *g -= shift;
        }
        let mean_pressure = self.p.iter().sum::<f64>() / n2 as f64;
        let approach = match target {
            // g = u − (h − max h) − g_min = 0 on the contact  ⇒  δ = g_min.
            Some(_) => shift,
            None => delta,
        };
        self.warm = true;
        // The pressure moves out too; the solver keeps a copy for warm
        // starts in the (no longer needed) search-direction buffer.
        let pressure = std::mem::take(&mut self.p);
        self.p = std::mem::take(&mut self.t);
        self.p.copy_from_slice(&pressure);
        Ok(Solution {
            pressure,
            gap,
            displacement,
            mean_pressure,
            approach,
            contact_fraction: stats.count as f64 / n2 as f64,
            elastic_fraction: stats.count as f64 / n2 as f64,
            plastic_fraction: 0.0,
            plastic_displacement_mean: 0.0,
            plastic_displacement_max: 0.0,
            iterations: k,
            residual,
            seconds: start.elapsed().as_secs_f64(),
        })
    }

    /// `g = s·𝒢p − h + o` from a fresh application of the operator.
    fn refresh_gap(&mut self, heights: &[f64], offset: f64, scale: f64) -> Result<()> {
        let n = self.op.n();
        let Solver { op, p, g, .. } = self;
        op.apply_rows(
            &mut |i, row| row.copy_from_slice(&p[i * n..(i + 1) * n]),
            &mut |i, row| {
                let range = i * n..(i + 1) * n;
                for ((g, u), h) in g[range.clone()].iter_mut().zip(row).zip(&heights[range]) {
                    *g = scale * u - (h - offset);
                }
            },
        )
    }

    /// The search direction `t` (written row by row as the transform reads
    /// it) and the response `r = 𝒢t`, with the step's sums
    /// `[Σ_c r, Σ t, Σ (g − ḡ) t, Σ r t]`.
    fn direction_and_response(&mut self, g_bar: f64, beta: f64) -> Result<[f64; 4]> {
        let n = self.op.n();
        let Solver { op, p, g, t, r, .. } = self;
        // Both passes see t: `fill` writes row i before `emit` reads it.
        let t = Cell::from_mut(&mut t[..]).as_slice_of_cells();
        let (mut s_t, mut s_gt, mut s_r, mut s_rt) = (0.0, 0.0, 0.0, 0.0);
        op.apply_rows(
            &mut |i, row| {
                let k = i * n..(i + 1) * n;
                let [a, b] = direction_row(&p[k.clone()], &g[k.clone()], &t[k], g_bar, beta, row);
                s_t += a;
                s_gt += b;
            },
            &mut |i, row| {
                let k = i * n..(i + 1) * n;
                let [a, b] = response_row(&p[k.clone()], &t[k.clone()], row, &mut r[k]);
                s_r += a;
                s_rt += b;
            },
        )?;
        Ok([s_r, s_t, s_gt, s_rt])
    }

    /// Apply the pending gap update, then gather the contact sums of the gap
    /// with the pressure `p_scale · p`.
    fn gap_stats(
        &mut self,
        heights: &[f64],
        offset: f64,
        step: Pending,
        g_ref: f64,
        p_scale: f64,
    ) -> GapStats {
        // Branch-free, in LANES independent partial sums (vectorisable); the
        // contact set is an irregular pattern that defeats branch prediction.
        let mut acc = [[0.0f64; LANES]; 6]; // Σp, Σpg, Σp|g|, Σ_c δg, Σ_c δg², count
        let mut g_min = [f64::INFINITY; LANES];
        let mut g_off = [f64::INFINITY; LANES];
        let Pending {
            g_scale,
            tau,
            update,
        } = step;
        let n2 = self.p.len();
        let (p, g, r, h) = (
            &self.p[..n2],
            &mut self.g[..n2],
            &self.r[..n2],
            &heights[..n2],
        );
        let mut lane = |k: usize, l: usize| {
            let pk = p_scale * p[k];
            let gi = if update {
                // h − o first: the same rounding every time (a fixed
                // perturbation of the heights, not noise in the gap).
                let hk = h[k] - offset;
                let v = g_scale * (g[k] + hk - tau * r[k]) - hk;
                g[k] = v;
                v
            } else {
                g[k]
            };
            let c = pk > 0.0;
            let m = if c { 1.0 } else { 0.0 };
            let dg = m * (gi - g_ref);
            acc[0][l] += pk;
            acc[1][l] += pk * gi;
            acc[2][l] += pk * gi.abs();
            acc[3][l] += dg;
            acc[4][l] += dg * dg;
            acc[5][l] += m;
            let (on, off) = if c {
                (gi, f64::INFINITY)
            } else {
                (f64::INFINITY, gi)
            };
            g_min[l] = if on < g_min[l] { on } else { g_min[l] };
            g_off[l] = if off < g_off[l] { off } else { g_off[l] };
        };
        let body = n2 - n2 % LANES;
        for i in (0..body).step_by(LANES) {
            for l in 0..LANES {
                lane(i + l, l);
            }
        }
        for k in body..n2 {
            lane(k, 0);
        }
        let sum = |a: &[f64; LANES]| a.iter().sum::<f64>();
        let min = |a: &[f64; LANES]| a.iter().copied().fold(f64::INFINITY, f64::min);
        let mut st = GapStats {
            sum_p: sum(&acc[0]),
            sum_pg: sum(&acc[1]),
            sum_pabs: sum(&acc[2]),
            sum_dg: sum(&acc[3]),
            sum_dg2: sum(&acc[4]),
            count: sum(&acc[5]) as usize,
            g_min: min(&g_min),
            g_min_off: min(&g_off),
        };
        if st.count == 0 {
            st.g_min = 0.0;
        }
        st
    }

    /// A flat rigid surface: uniform pressure, full contact (load control).
    fn flat(&mut self, target: Option<f64>, delta: f64, start: Instant) -> Result<Solution> {
        let n2 = self.p.len();
        let pm = match target {
            Some(pm) => pm,
            None => return Err(Error::invalid(
                "penetration",
                delta,
                "used with a non-flat surface (a flat surface has no finite penetration solution)",
            )),
        };
        self.p.fill(pm);
        let mut u = vec![0.0; n2];
        self.op.apply(&self.p, &mut u)?;
        let u0 = u.first().copied().unwrap_or(0.0);
        self.warm = true;
        Ok(Solution {
            pressure: self.p.clone(),
            gap: vec![0.0; n2],
            displacement: u,
            mean_pressure: pm,
            approach: u0,
            contact_fraction: 1.0,
            elastic_fraction: 1.0,
            plastic_fraction: 0.0,
            plastic_displacement_mean: 0.0,
            plastic_displacement_max: 0.0,
            iterations: 0,
            residual: 0.0,
            seconds: start.elapsed().as_secs_f64(),
        })
    }
}

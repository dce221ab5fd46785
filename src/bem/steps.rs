//! The passes over the fields that the Polonsky–Keer loops (plain and
//! preconditioned) share: the gap statistics that give ε, a fresh gap from
//! `𝒢p`, and the projected step with its sparse correction.
//!
//! Every pass is branch-free in [`LANES`] independent partial sums (the
//! contact set is an irregular pattern that defeats branch prediction, and
//! independent sums let the compiler vectorise).

use super::kernel::Operator;
use super::problem::Problem;
use super::solution::Solution;
use super::workspace::{Finish, Workspace};
use crate::error::Result;

/// Independent partial sums per reduction.
pub(crate) const LANES: usize = 4;

/// The pending part of a step's gap update, applied in the next gap pass
/// if `update`: `g ← s·(g + h − o − τ r) − h + o` (that is `u ← s·(u − τ𝒢t)`).
/// (The step's rescaling of p is deferred to the next step, which writes p
/// anyway: p is held as `p_scale · p` in memory.)
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pending {
    pub g_scale: f64,
    pub tau: f64,
    pub update: bool,
}

impl Pending {
    pub const NONE: Pending = Pending {
        g_scale: 1.0,
        tau: 0.0,
        update: false,
    };
}

/// `Σ_c (g − ḡ)²` over the contact `p > 0`.
pub(crate) fn contact_norm(g: &[f64], p: &[f64], g_bar: f64) -> f64 {
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

/// Sums over the contact set gathered in one pass.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct GapStats {
    pub sum_p: f64,
    pub sum_pg: f64,
    pub sum_pabs: f64,
    pub g_min: f64,
    /// Σ_c (g − g_ref) and Σ_c (g − g_ref)² over the contact.
    pub sum_dg: f64,
    pub sum_dg2: f64,
    pub count: usize,
    /// Lowest gap outside the contact set.
    pub g_min_off: f64,
    /// Largest pressure.
    pub p_max: f64,
}

impl GapStats {
    /// ε of the state (module docs of [`super::solver`]): under load control
    /// the gap is measured from its lowest contact value.
    pub fn residual(&self, load_control: bool, sigma_h: f64) -> f64 {
        match load_control {
            _ if self.sum_p <= 0.0 => 0.0,
            true => (self.sum_pg - self.g_min * self.sum_p) / (self.sum_p * sigma_h),
            false => self.sum_pabs / (self.sum_p * sigma_h),
        }
    }

    /// Points outside the contact overlap the rigid surface by more than
    /// `tolerance · σ_h` (gap measured from the contact level under load
    /// control).
    pub fn overlap(&self, load_control: bool, tolerance: f64, sigma_h: f64) -> bool {
        let level = if load_control { self.g_min } else { 0.0 };
        self.g_min_off < level - tolerance * sigma_h
    }

    /// The contact mean ḡ of the gap and `Σ_c (g − ḡ)²`, from the sums about
    /// `g_ref` (the last ḡ); recomputed directly when that cancels more than
    /// 6 digits. Penetration control (or no contact): `ḡ = 0`.
    pub fn contact_mean(&self, load_control: bool, g_ref: f64, g: &[f64], p: &[f64]) -> (f64, f64) {
        if load_control && self.count > 0 {
            let c = self.count as f64;
            let d = self.sum_dg / c;
            let norm = self.sum_dg2 - c * d * d;
            let g_bar = g_ref + d;
            if norm > 1e-6 * self.sum_dg2 {
                (g_bar, norm)
            } else {
                (g_bar, contact_norm(g, p, g_bar))
            }
        } else {
            (0.0, contact_norm(g, p, 0.0))
        }
    }
}

/// `g = s·𝒢p − h + o` from a fresh application of the operator.
pub(crate) fn refresh_gap(
    op: &mut Operator,
    p: &[f64],
    g: &mut [f64],
    heights: &[f64],
    offset: f64,
    scale: f64,
) -> Result<()> {
    let n = op.n();
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

/// Apply the pending gap update `step`, then gather the contact sums of the
/// gap with the pressure `p_scale · p` (`r` holds 𝒢t of the step).
#[allow(clippy::too_many_arguments)]
pub(crate) fn gap_stats(
    p: &[f64],
    g: &mut [f64],
    r: &[f64],
    heights: &[f64],
    offset: f64,
    step: Pending,
    g_ref: f64,
    p_scale: f64,
) -> GapStats {
    let mut acc = [[0.0f64; LANES]; 6]; // Σp, Σpg, Σp|g|, Σ_c δg, Σ_c δg², count
    let mut g_min = [f64::INFINITY; LANES];
    let mut g_off = [f64::INFINITY; LANES];
    let mut p_max = [0.0f64; LANES];
    let Pending {
        g_scale,
        tau,
        update,
    } = step;
    let n2 = p.len();
    let (g, r, h) = (&mut g[..n2], &r[..n2], &heights[..n2]);
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
        p_max[l] = if pk > p_max[l] { pk } else { p_max[l] };
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
        p_max: p_max.iter().copied().fold(0.0, f64::max),
    };
    if st.count == 0 {
        st.g_min = 0.0;
    }
    st
}

/// How nodes at `p = 0` that overlap enter during a step.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Entry {
    /// With `p = coeff · (g − ḡ)` (coeff < 0), Polonsky & Keer's re-entry.
    Overlap { g_bar: f64, coeff: f64 },
    /// Only through the step itself (the direction covers them).
    Direction,
}

/// The outcome of [`project_step`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct Step {
    /// Σp after the step.
    pub sum_p: f64,
    /// Nodes where the step is not linear in τ (clamped or entered).
    pub changed: usize,
    /// Whether any overlapping node entered ([`Entry::Overlap`]).
    pub entered: bool,
}

/// Step `p ← max(p_scale·p − τ t, 0)` (t = 0 off the contact, where p = 0
/// too), with the re-entry `entry`. The corrections `v − linear` of the
/// first `limit` changed nodes are pushed to `sparse_idx`/`sparse_val`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn project_step(
    p: &mut [f64],
    t: &[f64],
    g: &[f64],
    p_scale: f64,
    tau: f64,
    entry: Entry,
    limit: usize,
    sparse_idx: &mut Vec<usize>,
    sparse_val: &mut Vec<f64>,
) -> Step {
    sparse_idx.clear();
    sparse_val.clear();
    let n2 = p.len();
    let mut changed = 0usize;
    let mut entered = false;
    let mut sums = [0.0f64; LANES];
    let (t, g) = (&t[..n2], &g[..n2]);
    let (g_bar, coeff, reenter) = match entry {
        Entry::Overlap { g_bar, coeff } => (g_bar, coeff, true),
        Entry::Direction => (0.0, 0.0, false),
    };
    let mut node = |k: usize, l: usize| {
        let linear = p_scale * p[k] - tau * t[k];
        let clamped = if linear > 0.0 { linear } else { 0.0 };
        let gs = g[k] - g_bar;
        let enters = reenter & (clamped == 0.0) & (gs < 0.0);
        let v = if enters { coeff * gs } else { clamped };
        entered |= enters;
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
    Step {
        sum_p: sums.iter().sum(),
        changed,
        entered,
    }
}

/// The pressure and gap of a Polonsky–Keer loop between passes, as both
/// loops (plain and preconditioned) keep them: the step's rescaling of p and
/// its linear gap update are deferred to the next pass over the fields.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LazyGap {
    /// The gap was computed from a fresh `𝒢p` (convergence is declared only then).
    pub fresh: bool,
    /// The step's linear gap update (with its rescaling s), applied lazily
    /// in the next gap pass.
    pending: Pending,
    /// The pressure is `p_scale · p` (the step's rescaling is applied by the
    /// next step, which rewrites p anyway).
    pub p_scale: f64,
    /// ḡ of the last step: the reference of the gap pass's contact sums.
    pub g_ref: f64,
}

impl LazyGap {
    /// The first gap, from the start pressure the workspace holds (and a
    /// zero direction).
    pub fn start(problem: &Problem, ws: &mut Workspace) -> Result<Self> {
        let mut lazy = LazyGap {
            fresh: true,
            pending: Pending::NONE,
            p_scale: 1.0,
            g_ref: 0.0,
        };
        lazy.refresh(problem, ws)?;
        ws.fields().direction.fill(0.0);
        Ok(lazy)
    }

    /// Apply the pending update and gather the gap statistics.
    pub fn measure(&mut self, problem: &Problem, ws: &mut Workspace) -> GapStats {
        let f = ws.fields();
        let st = gap_stats(
            f.pressure,
            f.gap,
            f.response,
            problem.heights(),
            problem.offset(),
            self.pending,
            self.g_ref,
            self.p_scale,
        );
        self.pending = Pending::NONE;
        st
    }

    /// A fresh gap `𝒢(p_scale·p)` before convergence is declared.
    pub fn refresh(&mut self, problem: &Problem, ws: &mut Workspace) -> Result<()> {
        let f = ws.fields();
        refresh_gap(
            f.op,
            f.pressure,
            f.gap,
            problem.heights(),
            problem.offset(),
            self.p_scale,
        )?;
        self.fresh = true;
        Ok(())
    }

    /// Apply the deferred rescaling: the workspace holds the pressure itself.
    pub fn hand_over(&mut self, ws: &mut Workspace) {
        let s = self.p_scale;
        ws.fields().pressure.iter_mut().for_each(|p| *p *= s);
        self.p_scale = 1.0;
    }

    /// After [`project_step`] with step length `tau`: rescale p to the load
    /// (load control) and update the gap, linearly with the sparse
    /// correction of at most `limit` changed nodes (deferred to the next
    /// [`LazyGap::measure`]), or from a fresh `𝒢p` when more changed.
    pub fn advance(
        &mut self,
        problem: &Problem,
        ws: &mut Workspace,
        step: Step,
        tau: f64,
        limit: usize,
    ) -> Result<()> {
        let f = ws.fields();
        let scale = match problem.target_total() {
            Some(total) if step.sum_p > 0.0 => total / step.sum_p,
            _ => 1.0,
        };
        let sparse = step.changed <= limit && f.op.add_sparse(f.sparse_idx, f.sparse_val, f.gap);
        if step.changed == 0 || sparse {
            // u = s (u − τ 𝒢t + 𝒢c), c the sparse correction (just added).
            self.pending = Pending {
                g_scale: scale,
                tau,
                update: true,
            };
            self.fresh = false;
        } else {
            // u = 𝒢(s p) = s 𝒢p.
            refresh_gap(
                f.op,
                f.pressure,
                f.gap,
                problem.heights(),
                problem.offset(),
                scale,
            )?;
            self.fresh = true;
        }
        self.p_scale = scale;
        Ok(())
    }
}

/// The converged solution of an elastic Polonsky–Keer loop (the pressure
/// handed over) after `iterations`, with ε = `residual`: under load control
/// the final gap is shifted to zero at the lowest contact point
/// (g = u − (h − max h) − g_min = 0 on the contact ⇒ δ = g_min), under
/// penetration control the approach is the prescribed one.
pub(crate) fn finish_elastic(
    problem: &Problem,
    ws: &mut Workspace,
    stats: &GapStats,
    (iterations, residual): (usize, f64),
    start: crate::clock::Instant,
) -> Solution {
    let load = problem.target_total().is_some();
    let shift = if load && stats.count > 0 {
        stats.g_min
    } else {
        0.0
    };
    let approach = if load { shift } else { problem.penetration() };
    let mut done = Finish::elastic(shift, approach, stats.count, iterations, residual);
    done.seconds = start.elapsed().as_secs_f64();
    ws.finish(problem, done)
}

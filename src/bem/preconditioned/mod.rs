//! Preconditioned constrained conjugate gradient ([`Method::Preconditioned`],
//! the default): Polonsky & Keer's projected CG with the half-space stiffness
//! as preconditioner, corrected at the contact edges.
//!
//! # What it solves
//! The problem of [`super::solver`] (`p ≥ 0`, load or penetration control),
//! with the same stopping rule ε: equal tolerances give equal answers.
//!
//! # Method
//! ```text
//! free set     F = {p > 0} ∪ {p = 0, g < ḡ}          (ḡ: contact mean of g; 0 under penetration control)
//!              N = the other nodes (p held at its bound)
//! residual     r = [F] (g − ḡ)
//! precondition z = [F] (𝒦r − 𝒦_loc w),   w = ω [N] 𝒦r / d        (one FFT convolution and a 7 × 7 stencil)
//!              𝒦 = E*|q|/2 ≈ 𝒢⁻¹,  d = 𝒦(0) its diagonal,  𝒦_loc: 𝒦's kernel for |Δx|, |Δy| ≤ 3,
//!              ω = 1.25 + n_N/8 per node, n_N of its 8 neighbours in N (the padding: 2.25)
//! direction    t = [F] (z + β t_old − μ),   β = ⟨r, z⟩/⟨r_old, z_old⟩  (Fletcher–Reeves),
//!              μ = mean of z + β t_old over F   (load control: Σ t = 0 keeps the load)
//! step         τ = ⟨r, t⟩ / ⟨t, 𝒢t⟩,   p ← max(p − τ t, 0),   p ← p · N² p̄ / Σp
//! ```
//! The linear problem on a fixed free set is `𝒢_FF p = u`. The exact
//! inverse of the restricted operator is the Schur complement of the
//! stiffness, `𝒢_FF⁻¹ = 𝒦_FF − 𝒦_FN 𝒦_NN⁻¹ 𝒦_NF`; the FFT preconditioner
//! `[F]𝒦[F]` keeps its first term only, so every eigenvalue of
//! `[F]𝒦[F]𝒢_FF` is ≥ 1 (Cauchy interlacing) and the large ones belong to
//! modes at the contact edges (Zhao, Vollebregt & Oosterlee 2014). The
//! missing term corrects them: `𝒦_NF r = [N]𝒦r` is already at hand (the
//! same convolution, off F), and 𝒦's kernel decays like |Δx|⁻³, so the
//! correction is local, with `𝒦_NN⁻¹ ≈ ω/d` (a weighted Jacobi) and `𝒦_FN`
//! by the 7 × 7 window of 𝒦's kernel (read from 𝒦 of a unit pressure once
//! per solve; exactly symmetric, so the preconditioner is).
//!
//! The weight follows the node's 3 × 3 neighbourhood, ω = ω₀ + ω₁ n_N/8
//! with n_N its held neighbours (the padding counts as held; its own nodes
//! take 2.25), ω₀ = 1.25, ω₁ = 1, because the exact `𝒦_NN⁻¹` grows inside a
//! held cluster. Measured on the rough case (iterations, σ0 = 0.005 /
//! 0.05 E*, periodic), the correction with this weight takes 24 / 23 at
//! 256² and 50 / 59 at 2048² where `[F]𝒦[F]` alone takes 30 / 34 and
//! 62 / 84 (docs/bem.md); the window, the weights and the alternatives
//! measured are in docs/design-notes.md. Only ω ≤ d/λ_max(𝒦) ≈ 0.54
//! guarantees a positive definite preconditioner; a direction that does
//! not descend restarts β and then hands over to the plain loop (below),
//! which none of the rough cases measured needed. The saturated stage
//! (box constraints, [`super::saturated`]) takes the same corrected
//! preconditioner, with the nodes held at σY in N beside those held at 0;
//! its elastic stage is this loop. Overlapping nodes at `p = 0` belong to
//! the free set, so they enter through the preconditioned step itself and
//! conjugacy is kept across active-set changes (restarting β at each change
//! costs 30–60 % more iterations). The free boundary uses 𝒦 of the 2N
//! padded grid; the padding is held at p = 0 just as the non-contact nodes
//! are, so its nodes within R of the window belong to N too: the operator
//! returns 𝒦r on that margin (R nodes wide; the pruned transform keeps
//! N + 2R of the 2N rows) and w there is that 𝒦r.
//!
//! Two convolutions per iteration (𝒦r and 𝒢t) and the correction's
//! stencil pass (sums of the rows i ± dy, then of the columns j ± dx:
//! 16 multiplications per node, skipped in blocks of 8 nodes with no free
//! node or no non-zero w within reach) besides a fresh `𝒢p` when
//! more than log₂ N² nodes were clamped (else the gap is updated linearly,
//! as in [`super::polonsky_keer`]); the same four fields.
//!
//! # Memory
//! Nothing beyond the plain loop's: per solve, the four N² fields of the
//! [`Workspace`] (pressure p, gap g, direction t, response — 𝒦r, then 𝒢t),
//! the operator's buffers (2.25 N² values periodic: row spectra, multiplier,
//! real-space kernel; 3 N² free: padded row spectra (N + 2R rows) and
//! multiplier, plus 2R rows and columns of the margin's 𝒦r — 𝒦 uses
//! 𝒢's multiplier, no table of its own) and the heights (N², the caller's):
//! 7.25 N² doubles periodic, 8 N² free, plus the sparse-correction lists
//! (≤ 2 log₂ N² entries) and the correction's ring (10 rows of w and of
//! m_F, one row of sums, three rows of the held nodes and their column
//! sums: about 25 N values); with the surface synthesis's two transient
//! fields 9.25 N² and 10 N² ([`super::required_bytes`]), within 10 N².
//!
//! # Why this method
//! Vollebregt (2014) made the FFT-based approximate inverse of the influence
//! matrix the preconditioner of his bound-constrained CG (BCCG). The
//! stiffness preconditioner costs one convolution, no memory, and applies
//! unchanged to the saturated loop (box constraints) and to gap-based loops
//! (whose operator is 𝒦, preconditioned by 𝒢). Deflation, a two-level
//! preconditioner on aggregates, a nested-iteration start and variants of
//! the edge correction were measured against it and were slower in time or
//! no better (docs/design-notes.md).
//!
//! # Stall and fallback
//! ε is not monotone in a projected CG. When the best ε has not halved
//! within `stall_iterations` iterations, or a step is degenerate (no descent
//! direction, τ not finite), the loop stops and reports `Outcome::Stalled`;
//! the caller finishes with [`super::polonsky_keer`] from the current
//! pressure and flags the solution ([`super::Fallback`]).
//!
//! # References
//! I. A. Polonsky & L. M. Keer, Wear 231, 206–219 (1999),
//! doi:10.1016/S0043-1648(99)00113-1.
//! E. A. H. Vollebregt, J. Comput. Phys. 257, 333–351 (2014),
//! doi:10.1016/j.jcp.2013.09.043 (BCCG, FFT-based preconditioner).
//! J. Zhao, E. A. H. Vollebregt & C. W. Oosterlee, Numer. Linear Algebra
//! Appl. 21, 256–274 (2014), doi:10.1002/nla.1873 (the FFT preconditioner's
//! smooth components).
//! C. H. Venner & A. A. Lubrecht, *Multilevel Methods in Lubrication*
//! (Elsevier 2000).
//! R. Fletcher & C. M. Reeves, Comput. J. 7, 149–154 (1964),
//! doi:10.1093/comjnl/7.2.149.
//!
//! [`Method::Preconditioned`]: super::Method::Preconditioned

use crate::clock::Instant;
use std::cell::Cell;

use super::driver::{drive, Check, Limits, Measured, Step};
use super::problem::{Options, Problem};
use super::solution::{Fallback, Iteration, Solution};
use super::steps::{finish_elastic, project_step, Entry, GapStats, LazyGap, LANES};
use super::workspace::{sparse_limit, Workspace};
use crate::error::Result;

mod edge;
pub(crate) use edge::Edge;

/// How the preconditioned loop ended.
#[derive(Debug)]
pub(crate) enum Outcome {
    /// Converged: the solution.
    Converged(Solution),
    /// Stalled: the pressure in the workspace is the last iterate (feasible,
    /// on the load); the plain loop is to finish.
    Stalled(Fallback),
    /// The [`Cap`] was exceeded after this many iterations: the pressure in
    /// the workspace is the last iterate, for the saturated stage.
    Capped(usize),
}

/// Stop early, once ε ≤ `tolerance`, if the pressure exceeds `yield_stress`
/// (the elastic stage of a saturated solve: its answer is to be clipped, so
/// it need not be converged further). Below the cap the loop runs on,
/// unchanged.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Cap {
    /// σY.
    pub yield_stress: f64,
    /// ε at which the cap is tested.
    pub tolerance: f64,
}

/// Solve `problem` from the pressure [`Workspace::start`] wrote.
///
/// # Errors
/// [`Error::NotConverged`](crate::Error::NotConverged) after
/// `opts.max_iterations` iterations.
pub(crate) fn solve(
    problem: &Problem,
    ws: &mut Workspace,
    opts: &Options,
    stall_iterations: usize,
    cap: Option<Cap>,
    observer: &mut dyn FnMut(Iteration),
) -> Result<Outcome> {
    let start = Instant::now();
    let state = State::new(problem, ws)?;
    let mut run = Preconditioned {
        problem,
        ws,
        tolerance: opts.tolerance,
        cap,
        state,
        stats: GapStats::default(),
        start,
    };
    drive(
        &mut run,
        Limits::new(opts.max_iterations, opts.tolerance).with_stall(stall_iterations),
        Some(observer),
    )
}

/// The preconditioned loop as the driver runs it.
struct Preconditioned<'a> {
    problem: &'a Problem<'a>,
    ws: &'a mut Workspace,
    tolerance: f64,
    cap: Option<Cap>,
    state: State,
    /// The sums of the last measure.
    stats: GapStats,
    start: Instant,
}

impl Step for Preconditioned<'_> {
    type Output = Outcome;
    const WHAT: &'static str = "preconditioned Polonsky–Keer contact solver";

    fn measure(&mut self) -> Result<Measured> {
        self.stats = self.state.gap.measure(self.problem, self.ws);
        Ok(Measured {
            iteration: self.state.k,
            residual: self.stats.residual(self.state.load, self.problem.sigma_h()),
        })
    }

    fn contact_fraction(&self) -> f64 {
        self.stats.count as f64 / self.problem.nodes() as f64
    }

    fn check(&mut self, m: Measured) -> Result<Check<Outcome>> {
        let (problem, st, eps) = (self.problem, &self.stats, m.residual);
        if eps <= self.tolerance && !st.overlap(self.state.load, self.tolerance, problem.sigma_h())
        {
            if !self.state.gap.fresh {
                self.state.gap.refresh(problem, self.ws)?;
                return Ok(Check::Again);
            }
            self.state.gap.hand_over(self.ws);
            return Ok(Check::Stop(Outcome::Converged(finish_elastic(
                problem,
                self.ws,
                st,
                (self.state.k, eps),
                self.start,
            ))));
        }
        if self
            .cap
            .is_some_and(|c| eps <= c.tolerance && st.p_max > c.yield_stress)
        {
            self.state.gap.hand_over(self.ws);
            return Ok(Check::Stop(Outcome::Capped(self.state.k)));
        }
        Ok(Check::Go)
    }

    fn step(&mut self, _: &mut dyn FnMut(Iteration)) -> Result<bool> {
        let st = self.stats;
        self.state.iterate(self.problem, self.ws, &st)
    }

    fn stalled(&mut self, m: Measured) -> Result<Outcome> {
        self.state.gap.hand_over(self.ws);
        Ok(Outcome::Stalled(Fallback {
            iterations: m.iteration,
            residual: m.residual,
        }))
    }
}

/// The iteration's state between passes.
struct State {
    load: bool,
    /// Pressure scale, pending gap update, freshness.
    gap: LazyGap,
    conjugacy: Conjugacy,
    /// Stiffness of the mean mode in the preconditioner (see [`Operator::fundamental_stiffness`]).
    ///
    /// [`Operator::fundamental_stiffness`]: super::kernel::Operator
    mean_stiffness: f64,
    /// The edge correction of the preconditioner (`None` on grids smaller
    /// than its stencil).
    edge: Option<Edge>,
    k: usize,
}

/// Sums of the preconditioner pass.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Precond {
    /// Nodes in the free set.
    free: f64,
    /// Σ_F r, ⟨r, t_old⟩, Σ_F t_old, ⟨r, z⟩, Σ_F z.
    sum_r: f64,
    r_t: f64,
    sum_t: f64,
    r_z: f64,
    sum_z: f64,
}

impl State {
    fn new(problem: &Problem, ws: &mut Workspace) -> Result<Self> {
        let mean_stiffness = ws.fields().op.fundamental_stiffness();
        let edge = Edge::new(ws, mean_stiffness)?;
        let gap = LazyGap::start(problem, ws)?;
        Ok(State {
            load: problem.target_total().is_some(),
            gap,
            conjugacy: Conjugacy::default(),
            mean_stiffness,
            edge,
            k: 0,
        })
    }

    fn iterate(&mut self, problem: &Problem, ws: &mut Workspace, st: &GapStats) -> Result<bool> {
        let g_bar = if self.load && st.count > 0 {
            self.gap.g_ref + st.sum_dg / st.count as f64
        } else {
            0.0
        };
        self.gap.g_ref = g_bar;
        let pc = match self.edge.as_mut() {
            Some(edge) => edge.precondition(ws, g_bar, f64::INFINITY, self.mean_stiffness)?,
            None => precondition(ws, g_bar, f64::INFINITY, self.mean_stiffness)?,
        };
        let Some((beta, mu)) = self.conjugacy.next(&pc, self.load) else {
            return Ok(false);
        };
        let [r_t, t_gt] = direction_and_response(ws, g_bar, f64::INFINITY, beta, mu)?;
        let tau = r_t / t_gt;
        if !(tau > 0.0 && tau.is_finite()) {
            return Ok(false);
        }
        let f = ws.fields();
        let limit = sparse_limit(f.pressure.len());
        let step = project_step(
            f.pressure,
            f.direction,
            f.gap,
            self.gap.p_scale,
            tau,
            Entry::Direction,
            limit,
            f.sparse_idx,
            f.sparse_val,
        );
        self.gap.advance(problem, ws, step, tau, limit)?;
        self.k += 1;
        Ok(true)
    }
}

/// Fletcher–Reeves conjugacy of the preconditioned directions.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Conjugacy {
    /// ⟨r, z⟩ of the last step (0: restart).
    rz_old: f64,
}

impl Conjugacy {
    /// β (restarted when the direction would not descend) and the mean μ
    /// removed from the direction under load control; `None` if even the
    /// preconditioned residual does not descend.
    pub(crate) fn next(&mut self, pc: &Precond, load: bool) -> Option<(f64, f64)> {
        let free = pc.free.max(1.0);
        let mean = |beta: f64| {
            if load {
                (pc.sum_z + beta * pc.sum_t) / free
            } else {
                0.0
            }
        };
        // ⟨r, t⟩ for t = z + β t_old − μ on F.
        let descent = |beta: f64, mu: f64| pc.r_z + beta * pc.r_t - mu * pc.sum_r;
        let mut beta = if self.rz_old > 0.0 {
            pc.r_z / self.rz_old
        } else {
            0.0
        };
        let mut mu = mean(beta);
        if !(descent(beta, mu) > 0.0 && beta.is_finite()) {
            beta = 0.0;
            mu = mean(0.0);
        }
        self.rz_old = pc.r_z;
        (descent(beta, mu) > 0.0).then_some((beta, mu))
    }
}

/// `m_F` of a node for pressures in `[0, y]` (`y = ∞`: the elastic
/// problem): strictly inside, or at a bound that the gap pushes it off
/// (`p = 0` below the level ḡ, `p = y` above it).
#[inline(always)]
fn free(p: f64, g: f64, g_bar: f64, y: f64) -> f64 {
    let inside = (p > 0.0) & (p < y);
    let lower = (p <= 0.0) & (g < g_bar);
    let upper = (p >= y) & (g > g_bar);
    if inside | lower | upper {
        1.0
    } else {
        0.0
    }
}

/// The preconditioner pass `z = [F] 𝒦 r` (z into `response`), with its sums;
/// pressures bounded by `y` (∞ for the elastic problem).
pub(crate) fn precondition(
    ws: &mut Workspace,
    g_bar: f64,
    y: f64,
    mean_stiffness: f64,
) -> Result<Precond> {
    let f = ws.fields();
    let n = f.op.n();
    let (p, g, t) = (&*f.pressure, &*f.gap, &*f.direction);
    let z = &mut *f.response;
    let mut acc = Precond::default();
    let mut fill_sums = [0.0f64; 4];
    let mut emit_sums = [0.0f64; 2];
    f.op.apply_stiffness_rows_with_mean(
        mean_stiffness,
        &mut |i, row| {
            let k = i * n..(i + 1) * n;
            let s = residual_row(&p[k.clone()], &g[k.clone()], &t[k], g_bar, y, row);
            for (a, b) in fill_sums.iter_mut().zip(s) {
                *a += b;
            }
        },
        &mut |i, row| {
            let k = i * n..(i + 1) * n;
            let s = restrict_row(&p[k.clone()], &g[k.clone()], g_bar, y, row, &mut z[k]);
            for (a, b) in emit_sums.iter_mut().zip(s) {
                *a += b;
            }
        },
    )?;
    [acc.free, acc.sum_r, acc.r_t, acc.sum_t] = fill_sums;
    [acc.r_z, acc.sum_z] = emit_sums;
    Ok(acc)
}

/// One row of `r = [F](g − ḡ)` into `out`; returns `[|F|, Σ r, Σ r t, Σ_F t]`.
fn residual_row(p: &[f64], g: &[f64], t: &[f64], g_bar: f64, y: f64, out: &mut [f64]) -> [f64; 4] {
    let mut acc = [[0.0f64; LANES]; 4];
    let chunks = p
        .chunks(LANES)
        .zip(g.chunks(LANES))
        .zip(t.chunks(LANES))
        .zip(out.chunks_mut(LANES));
    for (((pc, gc), tc), oc) in chunks {
        for l in 0..pc.len() {
            let m = free(pc[l], gc[l], g_bar, y);
            let r = m * (gc[l] - g_bar);
            oc[l] = r;
            acc[0][l] += m;
            acc[1][l] += r;
            acc[2][l] += r * tc[l];
            acc[3][l] += m * tc[l];
        }
    }
    acc.map(|a| a.iter().sum())
}

/// One row of `z = [F] 𝒦r` into `z`; returns `[Σ r z, Σ z]`.
fn restrict_row(p: &[f64], g: &[f64], g_bar: f64, y: f64, kr: &[f64], z: &mut [f64]) -> [f64; 2] {
    let mut acc = [[0.0f64; LANES]; 2];
    let chunks = p
        .chunks(LANES)
        .zip(g.chunks(LANES))
        .zip(kr.chunks(LANES))
        .zip(z.chunks_mut(LANES));
    for (((pc, gc), kc), zc) in chunks {
        for l in 0..pc.len() {
            let m = free(pc[l], gc[l], g_bar, y);
            let v = m * kc[l];
            zc[l] = v;
            acc[0][l] += m * (gc[l] - g_bar) * v;
            acc[1][l] += v;
        }
    }
    acc.map(|a| a.iter().sum())
}

/// The direction `t = [F](z + β t − μ)` (written row by row as the
/// transform reads it) and `r = 𝒢t` into `response`; returns
/// `[⟨g − ḡ, t⟩, ⟨t, 𝒢t⟩]`.
pub(crate) fn direction_and_response(
    ws: &mut Workspace,
    g_bar: f64,
    y: f64,
    beta: f64,
    mu: f64,
) -> Result<[f64; 2]> {
    let f = ws.fields();
    let n = f.op.n();
    let (p, g) = (&*f.pressure, &*f.gap);
    // `fill` reads z from `response` and writes t; `emit` (after every
    // fill) reads t and overwrites `response` with 𝒢t.
    let t = Cell::from_mut(f.direction).as_slice_of_cells();
    let r = Cell::from_mut(f.response).as_slice_of_cells();
    let (mut r_t, mut t_gt) = (0.0, 0.0);
    f.op.apply_rows(
        &mut |i, row| {
            let k = i * n..(i + 1) * n;
            r_t += direction_row(
                &p[k.clone()],
                &g[k.clone()],
                &r[k.clone()],
                &t[k],
                [g_bar, y, beta, mu],
                row,
            );
        },
        &mut |i, row| {
            let k = i * n..(i + 1) * n;
            let mut acc = [0.0f64; LANES];
            let chunks = t[k.clone()]
                .chunks(LANES)
                .zip(r[k].chunks(LANES))
                .zip(row.chunks(LANES));
            for ((tc, rc), xc) in chunks {
                for l in 0..tc.len() {
                    rc[l].set(xc[l]);
                    acc[l] += tc[l].get() * xc[l];
                }
            }
            t_gt += acc.iter().sum::<f64>();
        },
    )?;
    Ok([r_t, t_gt])
}

/// One row of `t ← [F](z + β t − μ)`, zero where a bound binds (`p = 0`
/// and `t > 0`, or `p = y` and `t < 0`), written to `t` and `out`; returns
/// `Σ (g − ḡ) t` over the row.
fn direction_row(
    p: &[f64],
    g: &[f64],
    z: &[Cell<f64>],
    t: &[Cell<f64>],
    [g_bar, y, beta, mu]: [f64; 4],
    out: &mut [f64],
) -> f64 {
    let mut acc = [0.0f64; LANES];
    let chunks = p
        .chunks(LANES)
        .zip(g.chunks(LANES))
        .zip(z.chunks(LANES).zip(t.chunks(LANES)))
        .zip(out.chunks_mut(LANES));
    for (((pc, gc), (zc, tc)), oc) in chunks {
        for l in 0..pc.len() {
            let m = free(pc[l], gc[l], g_bar, y);
            let v = m * (zc[l].get() + beta * tc[l].get() - mu);
            // Nodes at a bound that the step would push out stay put (their
            // clamp would make the step nonlinear: a fresh 𝒢p or a sparse
            // correction per iteration).
            let bind = ((pc[l] <= 0.0) & (v > 0.0)) | ((pc[l] >= y) & (v < 0.0));
            let v = if bind { 0.0 } else { v };
            tc[l].set(v);
            oc[l] = v;
            acc[l] += (gc[l] - g_bar) * v;
        }
    }
    acc.iter().sum()
}

#[cfg(test)]
mod tests {
    use super::edge::{EDGE_RADIUS, EDGE_WEIGHT, EDGE_WEIGHT_RISE};
    use super::*;
    use crate::bem::{Boundary, Operator};

    /// `x = 𝒦 u` (with the preconditioner's mean stiffness).
    fn stiffness(op: &mut Operator, mean: f64, u: &[f64]) -> Vec<f64> {
        let n = op.n();
        let mut x = vec![0.0; n * n];
        op.apply_stiffness_rows_with_mean(
            mean,
            &mut |i, row| row.copy_from_slice(&u[i * n..(i + 1) * n]),
            &mut |i, row| x[i * n..(i + 1) * n].copy_from_slice(row),
        )
        .unwrap();
        x
    }

    /// `𝒦 u` on the window and its margin: rows and columns −m … N + m − 1.
    fn stiffness_with_margin(op: &mut Operator, mean: f64, u: &[f64]) -> Vec<f64> {
        let (n, m) = (op.n(), op.margin());
        let w = n + 2 * m;
        let mut x = vec![0.0; w * w];
        op.apply_stiffness_rows_with_margin(
            mean,
            &mut |i, row| row.copy_from_slice(&u[i * n..(i + 1) * n]),
            &mut |i, row| {
                let i = (i + m as isize) as usize;
                x[i * w..(i + 1) * w].copy_from_slice(row)
            },
        )
        .unwrap();
        x
    }

    /// The edge-corrected preconditioner against direct sums with the
    /// operator's own entries: `z = [F](𝒦r − ω Σ_j 𝒦(x, j) [N]𝒦r(j) / d)`
    /// over the nodes j within R of x (each column 𝒦(·, j) from 𝒦 of a unit
    /// pressure at j, so neither the stencil nor the row ring is reused),
    /// periodic (wrapping) and free (no wrap; j also on the padding, where
    /// every node is held at p = 0: 𝒦(x, j) = 𝒦(j, x) from 𝒦 of a unit
    /// pressure at x, read on the margin), on a grid whose rows are not a
    /// whole number of blocks.
    #[test]
    fn edge_correction_equals_direct_sums() {
        for boundary in [Boundary::Periodic, Boundary::Free] {
            for n in [16usize, 21] {
                let mut ws = Workspace::new(Operator::new(boundary, n, 1.0, 1.0).unwrap());
                let mean = ws.fields().op.fundamental_stiffness();
                let mut seed = 7u64;
                let mut rand = move || {
                    seed = seed
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    (seed >> 11) as f64 / (1u64 << 53) as f64
                };
                let (g_bar, y) = (0.5, f64::INFINITY);
                {
                    let f = ws.fields();
                    for k in 0..n * n {
                        let u = rand();
                        f.pressure[k] = if u < 0.4 { 0.0 } else { u };
                        f.gap[k] = rand();
                        f.direction[k] = rand() - 0.5;
                    }
                }
                let f = ws.fields();
                let (p, g) = (f.pressure.to_vec(), f.gap.to_vec());
                let m: Vec<f64> = (0..n * n).map(|k| free(p[k], g[k], g_bar, y)).collect();
                let r: Vec<f64> = (0..n * n).map(|k| m[k] * (g[k] - g_bar)).collect();
                let kr = stiffness(f.op, mean, &r);
                let mut unit = vec![0.0; n * n];
                unit[(n / 2) * n + n / 2] = 1.0;
                let d = stiffness(f.op, mean, &unit)[(n / 2) * n + n / 2];
                let mut z_ref: Vec<f64> = (0..n * n).map(|k| m[k] * kr[k]).collect();
                let reach = EDGE_RADIUS as i64;
                for j in 0..n * n {
                    if m[j] > 0.0 {
                        continue;
                    }
                    unit.fill(0.0);
                    unit[j] = 1.0;
                    let column = stiffness(f.op, mean, &unit);
                    // ω₀ + ω₁ · (held neighbours) / 8, counted here by
                    // coordinates (the padding is held).
                    let (ji, jj) = ((j / n) as i64, (j % n) as i64);
                    let mut held = 0;
                    for a in ji - 1..=ji + 1 {
                        for b in jj - 1..=jj + 1 {
                            if (a, b) == (ji, jj) {
                                continue;
                            }
                            let wrap = |v: i64| v.rem_euclid(n as i64) as usize;
                            let inside = |v: i64| (0..n as i64).contains(&v);
                            held += match boundary {
                                Boundary::Periodic => (m[wrap(a) * n + wrap(b)] == 0.0) as i32,
                                Boundary::Free if inside(a) && inside(b) => {
                                    (m[a as usize * n + b as usize] == 0.0) as i32
                                }
                                Boundary::Free => 1,
                            };
                        }
                    }
                    let w = (EDGE_WEIGHT + EDGE_WEIGHT_RISE * f64::from(held) / 8.0) * kr[j] / d;
                    for x in 0..n * n {
                        let (dy, dx) = (
                            (x / n) as i64 - (j / n) as i64,
                            (x % n) as i64 - (j % n) as i64,
                        );
                        let near = |v: i64| match boundary {
                            Boundary::Periodic => {
                                v.rem_euclid(n as i64).min((-v).rem_euclid(n as i64)) <= reach
                            }
                            Boundary::Free => v.abs() <= reach,
                        };
                        if x != j && near(dy) && near(dx) {
                            z_ref[x] -= m[x] * column[x] * w;
                        }
                    }
                }
                if boundary == Boundary::Free {
                    let mg = f.op.margin();
                    assert_eq!(mg, EDGE_RADIUS);
                    let wd = n + 2 * mg;
                    let kr_margin = stiffness_with_margin(f.op, mean, &r);
                    let mut padding_terms = 0;
                    for x in 0..n * n {
                        let (xi, xj) = ((x / n + mg) as i64, (x % n + mg) as i64);
                        unit.fill(0.0);
                        unit[x] = 1.0;
                        let row = stiffness_with_margin(f.op, mean, &unit);
                        for a in (xi - reach).max(0)..=(xi + reach).min(wd as i64 - 1) {
                            for b in (xj - reach).max(0)..=(xj + reach).min(wd as i64 - 1) {
                                let inside = |v: i64| (mg as i64..(n + mg) as i64).contains(&v);
                                if inside(a) && inside(b) {
                                    continue;
                                }
                                let j = a as usize * wd + b as usize;
                                let w = (EDGE_WEIGHT + EDGE_WEIGHT_RISE) * kr_margin[j] / d;
                                z_ref[x] -= m[x] * row[j] * w;
                                padding_terms += 1;
                            }
                        }
                    }
                    assert!(padding_terms > 0);
                }
                let mut edge = Edge::new(&mut ws, mean).unwrap().expect("grid ≥ 8");
                let pc = edge.precondition(&mut ws, g_bar, y, mean).unwrap();
                let z = ws.fields().response.to_vec();
                let scale = z_ref.iter().fold(0.0f64, |a, v| a.max(v.abs()));
                let err = z
                    .iter()
                    .zip(&z_ref)
                    .fold(0.0f64, |a, (u, v)| a.max((u - v).abs()));
                assert!(
                    err <= 1e-12 * scale,
                    "{boundary:?} N = {n}: {err:e} of {scale:e}"
                );
                let change = (0..n * n).fold(0.0f64, |a, k| a.max((m[k] * kr[k] - z_ref[k]).abs()));
                assert!(
                    change > 0.01 * scale,
                    "{boundary:?} N = {n}: correction {change:e}"
                );
                let r_z: f64 = r.iter().zip(&z_ref).map(|(a, b)| a * b).sum();
                let sum_z: f64 = z_ref.iter().sum();
                assert!(
                    (pc.r_z - r_z).abs() <= 1e-12 * r_z.abs(),
                    "{boundary:?} N = {n}"
                );
                assert!((pc.sum_z - sum_z).abs() <= 1e-10 * scale * (n * n) as f64);
            }
        }
    }
}

//! The plain Polonsky–Keer constrained conjugate gradient ([`Method::Plain`]).
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
//! # References
//! I. A. Polonsky & L. M. Keer, Wear 231, 206–219 (1999),
//! doi:10.1016/S0043-1648(99)00113-1.
//!
//! [`Method::Plain`]: super::Method::Plain

use crate::clock::Instant;
use std::cell::Cell;

use super::driver::{drive, Check, Limits, Measured, Step};
use super::problem::{Options, Problem};
use super::solution::{Iteration, Solution};
use super::steps::{finish_elastic, project_step, Entry, GapStats, LazyGap, LANES};
use super::workspace::{sparse_limit, Workspace};
use crate::error::Result;

/// Solve `problem` from the pressure [`Workspace::start`] (or
/// [`Workspace::resume`]) wrote; `k0` iterations were spent before (by a
/// stalled loop), and count against `opts.max_iterations`.
///
/// # Errors
/// [`Error::NotConverged`](crate::Error::NotConverged) after `opts.max_iterations` iterations in all.
pub(crate) fn solve(
    problem: &Problem,
    ws: &mut Workspace,
    opts: &Options,
    k0: usize,
    observer: &mut dyn FnMut(Iteration),
) -> Result<Solution> {
    let start = Instant::now();
    let state = State::new(problem, ws, k0)?;
    let mut run = Plain {
        problem,
        ws,
        tolerance: opts.tolerance,
        state,
        stats: GapStats::default(),
        start,
    };
    drive(
        &mut run,
        Limits::new(opts.max_iterations, opts.tolerance),
        Some(observer),
    )
}

/// The plain loop as the driver runs it.
struct Plain<'a> {
    problem: &'a Problem<'a>,
    ws: &'a mut Workspace,
    tolerance: f64,
    state: State,
    /// The sums of the last measure.
    stats: GapStats,
    start: Instant,
}

impl Step for Plain<'_> {
    type Output = Solution;
    const WHAT: &'static str = "Polonsky–Keer contact solver";

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

    fn check(&mut self, m: Measured) -> Result<Check<Solution>> {
        let (problem, st) = (self.problem, &self.stats);
        if m.residual > self.tolerance
            || st.overlap(self.state.load, self.tolerance, problem.sigma_h())
        {
            return Ok(Check::Go);
        }
        if !self.state.gap.fresh {
            self.state.gap.refresh(problem, self.ws)?;
            return Ok(Check::Again);
        }
        self.state.gap.hand_over(self.ws);
        Ok(Check::Stop(finish_elastic(
            problem,
            self.ws,
            st,
            (self.state.k, m.residual),
            self.start,
        )))
    }

    fn step(&mut self, _: &mut dyn FnMut(Iteration)) -> Result<bool> {
        let st = self.stats;
        self.state.iterate(self.problem, self.ws, &st)?;
        Ok(true)
    }
}

/// The iteration's state between passes.
struct State {
    load: bool,
    /// Pressure scale, pending gap update, freshness.
    gap: LazyGap,
    g_old: f64,
    conjugate: bool,
    k: usize,
}

impl State {
    /// The first gap, from the start pressure.
    fn new(problem: &Problem, ws: &mut Workspace, k0: usize) -> Result<Self> {
        Ok(State {
            load: problem.target_total().is_some(),
            gap: LazyGap::start(problem, ws)?,
            g_old: 1.0,
            conjugate: false,
            k: k0,
        })
    }

    /// One conjugate-gradient step: direction, step length, projection,
    /// re-entry, rescaling, and the gap update (linear, sparse or fresh).
    fn iterate(&mut self, problem: &Problem, ws: &mut Workspace, st: &GapStats) -> Result<()> {
        if st.count == 0 && !self.load {
            // No contact but overlap: start the pressure there.
            self.conjugate = false;
        }
        let f = ws.fields();
        let (g_bar, g_norm) = st.contact_mean(self.load, self.gap.g_ref, f.gap, f.pressure);
        self.gap.g_ref = g_bar;
        let beta = if self.conjugate {
            g_norm / self.g_old
        } else {
            0.0
        };
        self.g_old = g_norm;
        let [s_r, s_t, s_gt, s_rt] = direction_and_response(ws, g_bar, beta)?;
        let denom = if self.load && st.count > 0 {
            s_rt - s_r / st.count as f64 * s_t
        } else {
            s_rt
        };
        let tau = if denom > 0.0 && denom.is_finite() {
            s_gt / denom
        } else {
            0.0
        };
        // Overlapping points enter with p = −τ g (degenerate step τ = 0:
        // with the overlap times the stiffness guess).
        let coeff = if tau > 0.0 {
            -tau
        } else {
            -problem.stiffness()
        };
        let f = ws.fields();
        let limit = sparse_limit(f.pressure.len());
        let step = project_step(
            f.pressure,
            f.direction,
            f.gap,
            self.gap.p_scale,
            tau,
            Entry::Overlap { g_bar, coeff },
            limit,
            f.sparse_idx,
            f.sparse_val,
        );
        self.conjugate = !step.entered;
        self.gap.advance(problem, ws, step, tau, limit)?;
        self.k += 1;
        Ok(())
    }
}

/// The search direction `t` (written row by row as the transform reads
/// it) and the response `r = 𝒢t`, with the step's sums
/// `[Σ_c r, Σ t, Σ (g − ḡ) t, Σ r t]`.
fn direction_and_response(ws: &mut Workspace, g_bar: f64, beta: f64) -> Result<[f64; 4]> {
    let f = ws.fields();
    let n = f.op.n();
    let (p, g, r) = (&*f.pressure, &*f.gap, f.response);
    // Both passes see t: `fill` writes row i before `emit` reads it.
    let t = Cell::from_mut(f.direction).as_slice_of_cells();
    let (mut s_t, mut s_gt, mut s_r, mut s_rt) = (0.0, 0.0, 0.0, 0.0);
    f.op.apply_rows(
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

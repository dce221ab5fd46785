//! The saturated (elastic–perfectly-plastic) contact: pressures bounded by
//! the yield stress, `0 ≤ p ≤ σY`.
//!
//! # What it solves
//! The model of Persson's finite-σY theory: the material yields where the
//! local pressure reaches the hardness σY, and there the surfaces
//! interpenetrate by the plastic deformation. With the compliance operator 𝒢
//! and the rigid heights `h` (see [`super::solver`]):
//! ```text
//! minimise  ½ ⟨p, 𝒢p⟩ − ⟨p, h⟩   subject to  0 ≤ p ≤ σY  and the load (or the approach)
//! KKT, gap g = 𝒢p − (h − max h) − δ:
//!   p = 0       ⇒ g ≥ 0
//!   0 < p < σY  ⇒ g = 0
//!   p = σY      ⇒ g ≤ 0   (−g is the plastic displacement)
//! ```
//! The problem is convex (𝒢 is positive definite), so the solution is unique.
//!
//! # Algorithm
//! First the elastic problem is solved by the solver's method
//! ([`super::Method`]: preconditioned by default, see
//! [`super::preconditioned`]); if its largest pressure is ≤ σY it is the
//! saturated solution too (returned as it is: bit for bit the elastic
//! answer).
//! Otherwise, starting from the elastic pressure clipped at σY, the
//! Polonsky–Keer conjugate gradient (Polonsky & Keer 1999) runs on the free
//! set `{0 < p < σY}` with the box projection of the bound-constrained
//! variants (Almqvist et al. 2007; Bugnicourt et al. 2018; Frérot et al.
//! 2020, Tamaas' `KatoSaturated` solves the same problem by a projected
//! gradient): after each step the pressure is clipped to `[0, σY]`, nodes at
//! `p = 0` that overlap (`g < ḡ`) and nodes at `p = σY` that open (`g > ḡ`)
//! re-enter the free set (restarting the conjugation), and under load
//! control the pressure below σY is scaled back to the load with the bound
//! kept: `Σ_{p<σY} min(s p, σY) + σY N_pl = N² p̄`, solved for `s` by
//! Newton's method from below
//! (exact in a few steps: the sum is piecewise linear and concave in `s`).
//! ḡ is the mean gap over the free set (the approach), 0 under penetration
//! control. When every contact node is at σY and the load is short, the
//! overlapping nodes enter with the missing load shared in proportion to
//! their overlap. When ε has not dropped by 10 % in 100 iterations (the
//! active sets cycle: seen in 3 of 135 random 32²–128² cases), an
//! accelerated projected gradient (FISTA with gradient restart, exact
//! projection onto the box and the load) finishes the solve; it cannot
//! cycle, and the same criterion ends it. The gap is recomputed from `p` every iteration (two applications
//! of 𝒢 per iteration).
//!
//! # Convergence criterion
//! ```text
//! ε = [Σ_{0<p<σY} p |g − ḡ| + Σ_{p=σY} σY max(0, g − ḡ)] / (Σ p · σ_h)
//! ```
//! the elastic solver's measure on the free set plus the violation at the
//! plastic nodes; a solve stops when ε ≤ `tolerance` and no node at `p = 0`
//! overlaps by more than `tolerance · σ_h` and (load control) |Σp − N² p̄| ≤
//! `tolerance` · N² p̄; it fails with
//! [`Error::NotConverged`](crate::Error::NotConverged) (with ε) after `max_iterations` iterations (both
//! stages together).
//!
//! # References
//! I. A. Polonsky & L. M. Keer, Wear 231, 206–219 (1999),
//! doi:10.1016/S0043-1648(99)00113-1.
//! A. Almqvist, F. Sahlin, R. Larsson & S. Glavatskih, Tribol. Int. 40,
//! 574–579 (2007), doi:10.1016/j.triboint.2005.11.008 (elastic–perfectly
//! plastic contact with the pressure bounded by the hardness).
//! A. Beck & M. Teboulle, SIAM J. Imaging Sci. 2, 183–202 (2009),
//! doi:10.1137/080716542 (FISTA); B. O'Donoghue & E. Candès, Found. Comput.
//! Math. 15, 715–732 (2015), doi:10.1007/s10208-013-9150-3 (restart).
//! R. Bugnicourt, P. Sainsot, D. Dureisseix, C. Gauthier & A. A. Lubrecht,
//! Tribol. Lett. 66, 29 (2018), doi:10.1007/s11249-017-0980-z.
//! L. Frérot, G. Anciaux, V. Rey, S. Pham-Ba & J.-F. Molinari, J. Open
//! Source Softw. 5, 2121 (2020), doi:10.21105/joss.02121 (Tamaas).

use crate::clock::Instant;

mod fista;
mod measure;
mod projection;

use fista::projected_gradient;
use measure::{measure, Measure};
use projection::{fill_nearest, project_load};

use super::driver::{drive, Check, Limits, Measured, Stall, Step};
use super::elastic::{self, Stage};
use super::kernel::Operator;
use super::preconditioned::{direction_and_response, precondition, Cap, Conjugacy, Edge};
use super::problem::{Control, Method, Options, Problem};
use super::solution::{Fallback, Iteration, Solution};
use super::workspace::{Displacement, Finish, Workspace};
use crate::error::{check, Result};

/// Check a yield stress: finite and > 0, and above the mean pressure under
/// load control.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) naming `yield_stress`.
pub(crate) fn check_yield_stress(y: f64, control: Control) -> Result<f64> {
    let mean = match control {
        Control::MeanPressure(pm) if pm.is_finite() && pm > 0.0 => vec![pm],
        _ => vec![],
    };
    check::yield_stress("yield_stress", y, &mean)
}

/// Solve `problem` with the yield stress `y` (validated by the caller):
/// the elastic solve by `method`, then the saturated stage if needed.
///
/// # Errors
/// [`Error::NotConverged`](crate::Error::NotConverged) after `opts.max_iterations` iterations in all.
pub(crate) fn solve(
    problem: &Problem,
    ws: &mut Workspace,
    y: f64,
    opts: &Options,
    method: Method,
    observer: &mut dyn FnMut(Iteration),
) -> Result<Solution> {
    let start = Instant::now();
    let cap = Cap {
        yield_stress: y,
        tolerance: ELASTIC_STAGE_TOLERANCE.max(opts.tolerance),
    };
    let (k0, fallback) =
        match elastic::solve_capped(problem, ws, opts, method, Some(cap), observer)? {
            Stage::Solved(mut sol) => {
                if sol.pressure.iter().all(|&p| p <= y) {
                    // The elastic solution satisfies the bound: it is the saturated one.
                    sol.seconds = start.elapsed().as_secs_f64();
                    return Ok(sol);
                }
                // The workspace keeps the elastic pressure; the solution's fields go.
                (sol.iterations, sol.fallback)
            }
            Stage::Capped(k) => (k, None),
        };
    let mut run = Run::new(problem, ws, y, k0, method)?;
    run.fallback = fallback;
    let mut stage = Saturated {
        problem,
        ws,
        opts,
        run,
        last: None,
        contact: 0,
    };
    let (residual, g_bar) = drive(
        &mut stage,
        Limits::new(opts.max_iterations, opts.tolerance),
        Some(observer),
    )?;
    let Saturated { ws, run, .. } = stage;
    let mut done = run.finish(ws, g_bar);
    done.approach = match problem.target_total() {
        Some(_) => g_bar,
        None => problem.penetration(),
    };
    done.residual = residual;
    done.seconds = start.elapsed().as_secs_f64();
    let mut sol = ws.finish(problem, done);
    sol.fallback = run.fallback;
    Ok(sol)
}

/// The saturated stage as the driver runs it.
struct Saturated<'a> {
    problem: &'a Problem<'a>,
    ws: &'a mut Workspace,
    opts: &'a Options,
    run: Run,
    /// The last measure.
    last: Option<Measure>,
    /// Nodes in contact at the last measure.
    contact: usize,
}

impl Step for Saturated<'_> {
    /// ε and ḡ of the converged iterate.
    type Output = (f64, f64);
    const WHAT: &'static str = "saturated Polonsky–Keer contact solver (yield stress)";

    fn measure(&mut self) -> Result<Measured> {
        self.run.gap(self.problem, self.ws)?;
        let f = self.ws.fields();
        let (p, g) = (&*f.pressure, &*f.gap);
        let run = &self.run;
        let m = measure(p, g, run.y, run.target.is_some(), self.problem.sigma_h());
        self.contact = p.iter().filter(|&&v| v > 0.0).count();
        self.last = Some(m);
        Ok(Measured {
            iteration: run.k,
            residual: m.eps,
        })
    }

    fn contact_fraction(&self) -> f64 {
        self.contact as f64 / self.problem.nodes() as f64
    }

    fn check(&mut self, _: Measured) -> Result<Check<(f64, f64)>> {
        let Some(m) = self.last else {
            return Ok(Check::Go);
        };
        // Under load control the load must be carried too: with every
        // contact node at σY, ε is 0 whatever the load they carry.
        let tol = self.opts.tolerance;
        if m.eps <= tol && m.off_min >= -tol * self.problem.sigma_h() && self.load_error(&m) <= tol
        {
            return Ok(Check::Stop((m.eps, m.g_bar)));
        }
        Ok(Check::Go)
    }

    fn step(&mut self, observer: &mut dyn FnMut(Iteration)) -> Result<bool> {
        let Some(m) = self.last else {
            return Ok(true);
        };
        let problem = self.problem;
        // Progress of the preconditioned steps: ε, the load error and the
        // overlap off the contact (ε alone is 0 while every contact node
        // sits at σY and the load is short, and they could cycle there).
        let overlap = (-m.off_min / problem.sigma_h()).max(0.0);
        let progress = m.eps.max(self.load_error(&m)).max(overlap);
        let (run, ws) = (&mut self.run, &mut *self.ws);
        if run.preconditioned_step(ws, &m, progress)? {
            return Ok(true);
        }
        if run.stalled(m.eps) {
            // A cycle of active sets (seen on 0.3 % of random 32²–128²
            // cases) makes no progress: finish with the projected
            // gradient, which cannot cycle.
            projected_gradient(problem, ws, run.y, self.opts, &mut run.k, observer)?;
            run.conjugate = false;
            return Ok(true);
        }
        if run.refill(ws, &m) {
            return Ok(true);
        }
        run.cg_step(problem, ws, &m)?;
        Ok(true)
    }
}

impl Saturated<'_> {
    /// |load − Σp|/load under load control, else 0.
    fn load_error(&self, m: &Measure) -> f64 {
        self.run
            .target
            .map_or(0.0, |total| (total - m.sum_p).abs() / total)
    }
}

/// The saturated stage's state.
struct Run {
    y: f64,
    target: Option<f64>,
    k: usize,
    /// The preconditioned steps' state while they run (`None`: plain steps).
    preconditioned: Option<Preconditioned>,
    /// The preconditioner's edge correction (`None`: plain steps, or a grid
    /// too small for its stencil).
    edge: Option<Edge>,
    fallback: Option<Fallback>,
    conjugate: bool,
    g_old: f64,
    best: f64,
    stalled: usize,
}

/// State of the preconditioned steps of the saturated stage.
#[derive(Debug, Clone, Copy)]
struct Preconditioned {
    stall: Stall,
    conjugacy: Conjugacy,
    mean_stiffness: f64,
}

impl Run {
    /// Start from the elastic pressure in the workspace, clipped at σY and
    /// put back on the load.
    ///
    /// # Errors
    /// None in practice: the FFT's sizes are computed here (a failure
    /// would be a bug and panics: `bem::fft`). The `Result` stays for the API.
    fn new(
        problem: &Problem,
        ws: &mut Workspace,
        y: f64,
        k0: usize,
        method: Method,
    ) -> Result<Self> {
        let target = problem.target_total();
        let preconditioned = match method {
            Method::Preconditioned { stall_iterations } => Some(Preconditioned {
                stall: Stall::new(stall_iterations),
                conjugacy: Conjugacy::default(),
                mean_stiffness: ws.operator().fundamental_stiffness(),
            }),
            Method::Plain => None,
        };
        let edge = match &preconditioned {
            Some(pre) => Edge::new(ws, pre.mean_stiffness)?,
            None => None,
        };
        let f = ws.fields();
        f.pressure.iter_mut().for_each(|v| *v = v.min(y));
        if let Some(total) = target {
            project_load(f.pressure, y, total);
        }
        f.direction.fill(0.0);
        Ok(Run {
            y,
            target,
            k: k0,
            preconditioned,
            edge,
            fallback: None,
            conjugate: false,
            g_old: 1.0,
            best: f64::INFINITY,
            stalled: 0,
        })
    }

    /// `r = 𝒢p` and the gap `g = r − (h − o)`, fresh every iteration.
    fn gap(&self, problem: &Problem, ws: &mut Workspace) -> Result<()> {
        let f = ws.fields();
        displacement_and_gap(f.op, f.pressure, f.response, f.gap, problem)
    }

    /// One preconditioned step on the free set of the box (see
    /// [`super::preconditioned`] with `p ≤ σY`), or a refill of a missing
    /// load; false when the plain steps are to run (they do from now on if
    /// the preconditioned ones stalled or degenerated: flagged). `progress`
    /// (ε, load error, overlap: the largest) must halve in every stall window.
    fn preconditioned_step(
        &mut self,
        ws: &mut Workspace,
        m: &Measure,
        progress: f64,
    ) -> Result<bool> {
        let Some(mut pre) = self.preconditioned else {
            return Ok(false);
        };
        let taken = !pre.stall.stalled(self.k, progress) && self.pcg_step(ws, m, &mut pre)?;
        if taken {
            self.preconditioned = Some(pre);
            return Ok(true);
        }
        // Stalled or degenerate: the plain steps finish, from this pressure.
        self.preconditioned = None;
        self.fallback = Some(Fallback {
            iterations: self.k,
            residual: m.eps,
        });
        self.conjugate = false;
        Ok(false)
    }

    /// A refill of a missing load (restarting the conjugacy) or one
    /// preconditioned step; false when the step is degenerate.
    fn pcg_step(
        &mut self,
        ws: &mut Workspace,
        m: &Measure,
        pre: &mut Preconditioned,
    ) -> Result<bool> {
        if self.refill(ws, m) {
            pre.conjugacy = Conjugacy::default();
            return Ok(true);
        }
        let (y, g_bar) = (self.y, m.g_bar);
        let pc = match self.edge.as_mut() {
            Some(edge) => edge.precondition(ws, g_bar, y, pre.mean_stiffness)?,
            None => precondition(ws, g_bar, y, pre.mean_stiffness)?,
        };
        let Some((beta, mu)) = pre.conjugacy.next(&pc, self.target.is_some()) else {
            return Ok(false);
        };
        let [r_t, t_gt] = direction_and_response(ws, g_bar, y, beta, mu)?;
        let tau = r_t / t_gt;
        if !(tau > 0.0 && tau.is_finite()) {
            return Ok(false);
        }
        let f = ws.fields();
        for (pk, &tk) in f.pressure.iter_mut().zip(&*f.direction) {
            *pk = (*pk - tau * tk).clamp(0.0, y);
        }
        if let Some(total) = self.target {
            project_load(f.pressure, y, total);
        }
        self.k += 1;
        Ok(true)
    }

    /// No 10 % drop of ε in [`STALL_ITERATIONS`] iterations (counted here).
    fn stalled(&mut self, eps: f64) -> bool {
        if eps < 0.9 * self.best {
            self.best = eps;
            self.stalled = 0;
        } else {
            self.stalled += 1;
        }
        if self.stalled >= STALL_ITERATIONS {
            self.stalled = 0;
            self.best = f64::INFINITY;
            return true;
        }
        false
    }

    /// Every contact node is at σY and they carry less than the load: the
    /// free set is empty, so no step exists. New nodes take the missing
    /// load; true if a step of this kind was taken.
    fn refill(&mut self, ws: &mut Workspace, m: &Measure) -> bool {
        let (Some(total), 0) = (self.target, m.nf) else {
            return false;
        };
        let (y, g_bar) = (self.y, m.g_bar);
        let f = ws.fields();
        let (p, g) = (f.pressure, &*f.gap);
        let missing = total - m.sum_p;
        // The overlapping nodes enter with the missing load shared in
        // proportion to their overlap (a step from the stiffest mode would
        // overshoot them all to σY, and scaling back would empty the
        // plastic set: a cycle of two states).
        let weight: f64 = p
            .iter()
            .zip(g)
            .filter(|(&pk, &gk)| pk <= 0.0 && gk < g_bar)
            .map(|(_, &gk)| g_bar - gk)
            .sum();
        if missing > 0.0 && weight > 0.0 {
            for (pk, &gk) in p.iter_mut().zip(g) {
                if *pk <= 0.0 && gk < g_bar {
                    *pk = (missing * (g_bar - gk) / weight).min(y);
                }
            }
            project_load(p, y, total);
        } else if missing > 0.0 {
            // No node overlaps the level of the plastic set: the body must
            // move in. The nodes off the contact enter in the order they
            // would touch (smallest gap first), each with σY until the load
            // is carried; the last one takes the remainder and is the free
            // set the conjugate gradient starts from.
            fill_nearest(p, g, y, missing);
        } else {
            return false;
        }
        self.conjugate = false;
        self.k += 1;
        true
    }

    /// One conjugate-gradient step on the free set `{0 < p < σY}`: box
    /// projection, re-entry at both bounds, load projection.
    fn cg_step(&mut self, problem: &Problem, ws: &mut Workspace, m: &Measure) -> Result<()> {
        let (y, g_bar) = (self.y, m.g_bar);
        let f = ws.fields();
        let (p, g, t) = (&mut *f.pressure, &*f.gap, &mut *f.direction);
        // Search direction on the free set, conjugate to the last one.
        let g_norm: f64 = p
            .iter()
            .zip(g)
            .filter(|(&pk, _)| pk > 0.0 && pk < y)
            .map(|(_, &gk)| (gk - g_bar).powi(2))
            .sum();
        let beta = if self.conjugate && self.g_old > 0.0 {
            g_norm / self.g_old
        } else {
            0.0
        };
        self.g_old = g_norm;
        for ((tk, &pk), &gk) in t.iter_mut().zip(&*p).zip(g) {
            *tk = if pk > 0.0 && pk < y {
                gk - g_bar + beta * *tk
            } else {
                0.0
            };
        }
        f.op.apply(t, f.response)?;
        let tau = step_length(p, g, t, f.response, y, g_bar, self.target.is_some(), m.nf);
        // Step, box projection, re-entry at both bounds.
        let entry = if tau > 0.0 { tau } else { problem.stiffness() };
        let mut changed = false;
        for ((pk, &tk), &gk) in p.iter_mut().zip(&*t).zip(g) {
            let dg = gk - g_bar;
            let v = if *pk <= 0.0 {
                if dg < 0.0 {
                    changed = true;
                    -entry * dg
                } else {
                    0.0
                }
            } else if *pk >= y {
                if dg > 0.0 {
                    changed = true;
                    y - entry * dg
                } else {
                    y
                }
            } else {
                *pk - tau * tk
            };
            *pk = v.clamp(0.0, y);
        }
        self.conjugate = !changed;
        if let Some(total) = self.target {
            project_load(p, y, total);
        }
        self.k += 1;
        Ok(())
    }

    /// The final counts (the gap is measured from the free set's level `g_bar`).
    fn finish(&self, ws: &mut Workspace, g_bar: f64) -> Finish {
        let y = self.y;
        let f = ws.fields();
        let mut contact = 0usize;
        let mut plastic = 0usize;
        let (mut d_sum, mut d_max) = (0.0, 0.0f64);
        for (&pk, &gk) in f.pressure.iter().zip(f.gap.iter()) {
            if pk > 0.0 {
                contact += 1;
            }
            if pk >= y {
                plastic += 1;
                let d = (-(gk - g_bar)).max(0.0);
                d_sum += d;
                d_max = d_max.max(d);
            }
        }
        Finish {
            gap_shift: g_bar,
            contact,
            plastic,
            plastic_displacement_mean: if plastic > 0 {
                d_sum / plastic as f64
            } else {
                0.0
            },
            plastic_displacement_max: d_max,
            iterations: self.k,
            displacement: Displacement::InResponse,
            ..Finish::default()
        }
    }
}

/// `τ` of a step along `t` with the response `r = 𝒢t`: the sums over the
/// free set `{0 < p < σY}` (with the load constraint's mean correction).
#[allow(clippy::too_many_arguments)]
fn step_length(
    p: &[f64],
    g: &[f64],
    t: &[f64],
    r: &[f64],
    y: f64,
    g_bar: f64,
    load_control: bool,
    nf: usize,
) -> f64 {
    let (mut s_t, mut s_r, mut s_rt, mut s_gt) = (0.0, 0.0, 0.0, 0.0);
    for (((&pk, &gk), &tk), &rk) in p.iter().zip(g).zip(t).zip(r) {
        if pk > 0.0 && pk < y {
            s_t += tk;
            s_r += rk;
            s_rt += rk * tk;
            s_gt += (gk - g_bar) * tk;
        }
    }
    let denom = if load_control && nf > 0 {
        s_rt - s_r / nf as f64 * s_t
    } else {
        s_rt
    };
    if denom > 0.0 && denom.is_finite() {
        s_gt / denom
    } else {
        0.0
    }
}

/// `r = 𝒢p` and `g = r − (h − o)`.
fn displacement_and_gap(
    op: &mut Operator,
    p: &[f64],
    r: &mut [f64],
    g: &mut [f64],
    problem: &Problem,
) -> Result<()> {
    op.apply(p, r)?;
    let offset = problem.offset();
    for ((g, u), h) in g.iter_mut().zip(&*r).zip(problem.heights()) {
        *g = u - (h - offset);
    }
    Ok(())
}

/// ε at which the preconditioned elastic stage hands a pressure above σY
/// over to the saturated stage (which clips it): converging the elastic
/// answer further is wasted.
const ELASTIC_STAGE_TOLERANCE: f64 = 1e-1;

/// Iterations of the conjugate gradient without a 10 % drop of ε after which
/// [`projected_gradient`] takes over.
const STALL_ITERATIONS: usize = 100;

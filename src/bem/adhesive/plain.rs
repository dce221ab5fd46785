//! The plain adhesive iteration: Rey, Anciaux & Molinari's conjugate
//! gradient (module docs of [`super`], "Method"), as a [`Step`] of the BEM's
//! loop driver.

use super::{AdhesiveOptions, AdhesiveSolver, CohesiveLaw, Target};
use crate::bem::driver::{drive, Check, Limits, Measured, Step};
use crate::bem::problem::Heights;
use crate::bem::solution::Iteration;
use crate::error::{Error, Result};

impl AdhesiveSolver {
    /// Rey, Anciaux & Molinari's conjugate gradient (module docs,
    /// "Method"), from the current gap, `done` iterations already spent;
    /// returns (p̄, iterations, ε, converged). At the iteration limit, or
    /// when the step degenerates, it returns the last iterate unconverged.
    pub(super) fn plain(
        &mut self,
        heights: Heights<'_>,
        law: &CohesiveLaw,
        target: Target,
        opts: &AdhesiveOptions,
        done: usize,
    ) -> Result<(f64, usize, f64, bool)> {
        self.search.iter_mut().for_each(|t| *t = 0.0);
        let mut run = Plain {
            solver: self,
            heights,
            law,
            target,
            tolerance: opts.tolerance,
            g_old: 1.0,
            delta: 0.0,
            residual: f64::INFINITY,
            iterations: done,
            mean: 0.0,
        };
        let limits = Limits {
            limit_first: true,
            ..Limits::new(opts.max_iterations, opts.tolerance)
        };
        drive(&mut run, limits, None)
    }

    /// Closed surface nodes over the surface's (A/A0 of the iterate).
    pub(super) fn closed_fraction(&self) -> f64 {
        let layout = self.layout;
        let closed = (self.gap.iter().enumerate())
            .filter(|&(k, g)| *g <= 0.0 && layout.window(k).is_some())
            .count();
        closed as f64 / (layout.n * layout.n) as f64
    }
}

/// The plain iteration's state, as the driver runs it.
struct Plain<'a> {
    solver: &'a mut AdhesiveSolver,
    heights: Heights<'a>,
    law: &'a CohesiveLaw,
    target: Target,
    tolerance: f64,
    /// |r|² of the last step (Fletcher–Reeves).
    g_old: f64,
    /// 1 to keep the conjugacy, 0 to restart it.
    delta: f64,
    /// ε at the top of the last iteration.
    residual: f64,
    iterations: usize,
    /// p̄'s negative of the last gradient.
    mean: f64,
}

impl Plain<'_> {
    /// (p̄, iterations, ε, converged) of the current iterate, unconverged
    /// or not: the best ε of the last two.
    fn last(&self, eps: f64) -> (f64, usize, f64, bool) {
        (
            -self.mean,
            self.iterations,
            eps.min(self.residual),
            eps <= self.tolerance,
        )
    }

    /// r on the free set, centred, and the search direction centred on it
    /// too (periodic); returns nothing, writes `grad` and `search`.
    fn direction(&mut self) {
        let layout = self.solver.layout;
        let mean = self.mean;
        let sv = &mut *self.solver;
        let mut norm = 0.0;
        for (kk, (r, g)) in sv.grad.iter_mut().zip(&sv.gap).enumerate() {
            if *g > 0.0 || layout.window(kk).is_none() {
                *r -= mean;
                norm += *r * *r;
            } else {
                *r = 0.0;
            }
        }
        let beta = self.delta * norm / self.g_old;
        self.g_old = norm;
        let (mut sum, mut free) = (0.0, 0usize);
        for (kk, ((t, r), g)) in sv.search.iter_mut().zip(&sv.grad).zip(&sv.gap).enumerate() {
            if *g > 0.0 || layout.window(kk).is_none() {
                *t = *r + beta * *t;
                sum += *t;
                free += 1;
            } else {
                *t = 0.0;
            }
        }
        if layout.periodic() {
            let t_mean = sum / free.max(1) as f64;
            for (t, g) in sv.search.iter_mut().zip(&sv.gap) {
                if *g > 0.0 {
                    *t -= t_mean;
                }
            }
        }
    }
}

impl Step for Plain<'_> {
    type Output = (f64, usize, f64, bool);
    const WHAT: &'static str = "adhesive BEM";

    fn measure(&mut self) -> Result<Measured> {
        let (mean, eps) = self.solver.gradient(self.heights.values(), self.law)?;
        self.mean = mean;
        Ok(Measured {
            iteration: self.iterations,
            residual: eps,
        })
    }

    fn contact_fraction(&self) -> f64 {
        self.solver.closed_fraction()
    }

    fn check(&mut self, m: Measured) -> Result<Check<Self::Output>> {
        let eps = m.residual;
        self.residual = eps;
        if eps <= self.tolerance || self.solver.round_off {
            return Ok(Check::Stop((-self.mean, self.iterations, eps, true)));
        }
        if self.solver.detach(self.heights, self.law, self.target) {
            return Ok(Check::Stop((0.0, self.iterations, 0.0, true)));
        }
        Ok(Check::Go)
    }

    fn step(&mut self, _: &mut dyn FnMut(Iteration)) -> Result<bool> {
        self.iterations += 1;
        self.direction();
        let (heights, law) = (self.heights.values(), self.law);
        let sv = &mut *self.solver;
        let layout = sv.layout;
        sv.ops.stiffness(&sv.search, &mut sv.projected)?;
        let (mut num, mut den) = (0.0, 0.0);
        for ((t, r), q) in sv.search.iter().zip(&sv.grad).zip(&sv.projected) {
            num += r * t;
            den += q * t;
        }
        if den.is_nan() || den <= 0.0 {
            return Ok(false);
        }
        let tau = num / den;
        // a node crossing the end of the cohesive zone changes W′ by a
        // jump: the conjugacy restarts (steepest descent for one step)
        let mut crossed = false;
        for (kk, (g, t)) in sv.gap.iter_mut().zip(&sv.search).enumerate() {
            if layout.window(kk).is_some() {
                let new = (*g - tau * t).max(0.0);
                crossed |= law.jumps_between(*g, new);
                *g = new;
            } else {
                *g -= tau * t;
            }
        }
        // contact nodes that pull re-enter: r = 𝒦(g+h) + W′(0) + p̄ < 0 there
        self.delta = if crossed { 0.0 } else { 1.0 };
        let reenter = sv.reenter(heights, law, tau)?;
        if reenter > 0 {
            self.delta = 0.0;
        }
        if let Target::MeanGap(mean_gap) = self.target {
            if sv.mean_of_gap() <= 0.0 {
                return Err(Error::NotConverged {
                    what: "adhesive BEM: every node closed".into(),
                    iterations: self.iterations,
                    residual: self.residual,
                    tolerance: self.tolerance,
                });
            }
            sv.scale_to(mean_gap);
        }
        Ok(true)
    }

    /// A degenerate step: the last iterate, unconverged.
    fn stalled(&mut self, m: Measured) -> Result<Self::Output> {
        Ok(self.last(m.residual))
    }

    /// At the limit: the last iterate, unconverged.
    fn exhausted(&mut self, m: Measured, _: f64) -> Result<Self::Output> {
        Ok(self.last(m.residual))
    }
}

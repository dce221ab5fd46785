//! The one loop driver of the BEM's iterations: the elastic loops
//! ([`super::polonsky_keer`], [`super::preconditioned`]), the saturated
//! stage ([`super::saturated`]) and the adhesive ones ([`super::adhesive`])
//! each state only their step; the driver owns what is around it.
//!
//! # What the driver does
//! ```text
//! loop {
//!     m = step.measure()                  (iteration k and ε of the current iterate)
//!     observer(k, ε, A/A0)                (if any)
//!     k ≥ max_iterations → exhausted      (checked first where the loop says so)
//!     step.check(m): stop (converged, capped, detached) | measure again | go on
//!     k ≥ max_iterations → exhausted      (Error::NotConverged unless the loop says otherwise)
//!     stall test fires, or the step degenerates → stalled   (the fallback's hand-over)
//! }
//! ```
//! The stall test ([`Stall`]) is the driver's: the best ε must halve within
//! every window of `stall_iterations` iterations. A loop that has no
//! fallback runs without one.
//!
//! # References
//! The problem / solver / executor split of argmin (S. Kroboth, argmin,
//! `argmin::core::Executor`: observers and termination around any solver's
//! `next_iter`).

use super::solution::Iteration;
use crate::error::{Error, Result};

/// The iteration number and ε of the current iterate.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Measured {
    /// Iterations taken so far (a fallback's predecessor's included).
    pub iteration: usize,
    /// Convergence measure ε of the current iterate.
    pub residual: f64,
}

/// What a loop decides after measuring.
pub(crate) enum Check<O> {
    /// Stop with this output (converged, or an early stop of the loop's own).
    Stop(O),
    /// The iterate was refreshed (a gap recomputed from the pressure): measure again.
    Again,
    /// Take a step.
    Go,
}

/// One iteration of a loop: what it measures, when it stops, its step.
pub(crate) trait Step {
    /// What the loop returns.
    type Output;
    /// The solver named in [`Error::NotConverged`].
    const WHAT: &'static str;

    /// Measure the current iterate.
    ///
    /// # Errors
    /// The loop's own (an operator application).
    fn measure(&mut self) -> Result<Measured>;

    /// A/A0 of the current iterate, for the observer (called only when there
    /// is one, after [`Step::measure`]).
    fn contact_fraction(&self) -> f64;

    /// Stop, measure again or step (converged, capped, detached …).
    ///
    /// # Errors
    /// The loop's own.
    fn check(&mut self, m: Measured) -> Result<Check<Self::Output>>;

    /// One iteration from the current iterate; `false` when the step
    /// degenerates (no descent direction, τ not finite): the loop stalls.
    /// Nested iterations report to `observer`.
    ///
    /// # Errors
    /// The loop's own.
    fn step(&mut self, observer: &mut dyn FnMut(Iteration)) -> Result<bool>;

    /// The output of a stalled loop: the iterate handed over to the fallback.
    ///
    /// # Errors
    /// A loop without a fallback never stalls: an internal error.
    fn stalled(&mut self, m: Measured) -> Result<Self::Output> {
        Err(Error::Inconsistent {
            name: Self::WHAT.into(),
            requirement: format!(
                "a loop without a fallback, yet it stalled after {} iterations",
                m.iteration
            ),
        })
    }

    /// The output at the iteration limit.
    ///
    /// # Errors
    /// [`Error::NotConverged`] with ε, unless the loop hands over instead.
    fn exhausted(&mut self, m: Measured, tolerance: f64) -> Result<Self::Output> {
        Err(Error::NotConverged {
            what: Self::WHAT.into(),
            iterations: m.iteration,
            residual: m.residual,
            tolerance,
        })
    }
}

/// The driver's settings: termination and the stall test.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Limits {
    /// Iterations in all (a predecessor's included).
    pub max_iterations: usize,
    /// The requested ε (for [`Error::NotConverged`]).
    pub tolerance: f64,
    /// The stall test, for a loop with a fallback.
    pub stall: Option<Stall>,
    /// Test the limit before [`Step::check`] (a loop that stops at the
    /// limit without looking at its last iterate).
    pub limit_first: bool,
}

impl Limits {
    /// At most `max_iterations` iterations toward `tolerance`, no stall test.
    pub fn new(max_iterations: usize, tolerance: f64) -> Self {
        Limits {
            max_iterations,
            tolerance,
            stall: None,
            limit_first: false,
        }
    }

    /// With the stall test of `window` iterations.
    pub fn with_stall(self, window: usize) -> Self {
        Limits {
            stall: Some(Stall::new(window)),
            ..self
        }
    }
}

/// Run `step` to its output (module docs).
///
/// # Errors
/// The step's; [`Step::exhausted`]'s at the limit.
pub(crate) fn drive<S: Step>(
    step: &mut S,
    mut limits: Limits,
    mut observer: Option<&mut dyn FnMut(Iteration)>,
) -> Result<S::Output> {
    let mut quiet = |_: Iteration| {};
    loop {
        let m = step.measure()?;
        if let Some(observe) = observer.as_deref_mut() {
            observe(Iteration {
                iteration: m.iteration,
                residual: m.residual,
                contact_fraction: step.contact_fraction(),
            });
        }
        let exhausted = m.iteration >= limits.max_iterations;
        if limits.limit_first && exhausted {
            return step.exhausted(m, limits.tolerance);
        }
        match step.check(m)? {
            Check::Stop(out) => return Ok(out),
            Check::Again => continue,
            Check::Go => {}
        }
        if exhausted {
            return step.exhausted(m, limits.tolerance);
        }
        let stalled = limits
            .stall
            .as_mut()
            .is_some_and(|s| s.stalled(m.iteration, m.residual));
        let nested: &mut dyn FnMut(Iteration) = match observer.as_deref_mut() {
            Some(o) => o,
            None => &mut quiet,
        };
        if stalled || !step.step(nested)? {
            return step.stalled(m);
        }
    }
}

/// Ratio by which the best ε must fall within a stall window.
const STALL_FACTOR: f64 = 0.5;

/// The stall test: the best ε must fall by [`STALL_FACTOR`] in every window.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Stall {
    window: usize,
    since: usize,
    checkpoint: f64,
    best: f64,
}

impl Stall {
    /// A test with windows of `window` iterations (at least 1).
    pub fn new(window: usize) -> Self {
        Stall {
            window: window.max(1),
            since: 0,
            checkpoint: f64::INFINITY,
            best: f64::INFINITY,
        }
    }

    /// Record ε of iteration `k`; true when the window closed without progress.
    pub fn stalled(&mut self, k: usize, eps: f64) -> bool {
        if !eps.is_finite() {
            return true;
        }
        self.best = self.best.min(eps);
        if k < self.since + self.window {
            return false;
        }
        let stalled = self.best > STALL_FACTOR * self.checkpoint;
        self.checkpoint = self.best;
        self.since = k;
        stalled
    }
}

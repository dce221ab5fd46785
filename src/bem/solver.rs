//! The contact solver for frictionless, non-adhesive contact of a rigid
//! rough surface with an elastic half-space: what it solves, its stopping
//! rule, its methods, and the load path (warm starts).
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
//! # Methods
//! - [`Method::Preconditioned`] (default): the projected conjugate gradient
//!   preconditioned by the half-space stiffness ([`super::preconditioned`]),
//!   whose iteration count grows slowly with the grid; it falls back to the
//!   plain loop when it stalls, and says so ([`Solution::fallback`]).
//! - [`Method::Plain`]: Polonsky & Keer's (1999) constrained conjugate
//!   gradient ([`super::polonsky_keer`]).
//!
//! Both read the same set-up ([`Problem`]) and work in the same buffers
//! ([`Workspace`]); so do the saturated loop ([`super::saturated`]) and any
//! loop added later. [`LoadPath`] solves a sequence of loads on one surface,
//! each from the previous solution.
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
//! otherwise it fails with [`Error::NotConverged`](crate::Error::NotConverged) after `max_iter`
//! iterations, reporting the last ε. This is the criterion Tamaas 2.9 reports
//! for its `PolonskyKeerRey` solver (measured: equal to 15 digits on the
//! same state), so equal `tol` means equal stopping rules.
//!
//! # References
//! I. A. Polonsky & L. M. Keer, Wear 231, 206–219 (1999),
//! doi:10.1016/S0043-1648(99)00113-1 (the constrained conjugate gradient).
//! Frérot, Anciaux, Rey & Molinari, J. Open Source Softw. 5, 2121 (2020)
//! (Tamaas), for the error measure.

use super::elastic;
use super::kernel::Operator;
pub use super::problem::{Control, Method, Options, Problem};
use super::saturated;
pub use super::solution::{Fallback, Iteration, Solution};
use super::workspace::Workspace;
use crate::error::{check, Result};

/// A contact solver: a [`Workspace`] (the operator and the fields, allocated
/// once) and the [`Method`].
///
/// All buffers (4 N² values plus the operator's) are allocated by
/// [`Solver::new`]; an iteration allocates nothing. The gap and displacement
/// buffers move into the returned [`Solution`] and are allocated again by the
/// next solve.
#[derive(Debug)]
pub struct Solver {
    ws: Workspace,
    method: Method,
}

impl Solver {
    /// A solver for the operator's grid, with the default (preconditioned) method.
    pub fn new(op: Operator) -> Self {
        Solver::with_method(op, Method::default())
    }

    /// A solver for the operator's grid with the given method.
    pub fn with_method(op: Operator, method: Method) -> Self {
        Solver {
            ws: Workspace::new(op),
            method,
        }
    }

    /// The method.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The compliance operator.
    pub fn operator(&mut self) -> &mut Operator {
        self.ws.operator()
    }

    /// The workspace (the operator and the fields), for a loop of one's own.
    pub fn workspace(&mut self) -> &mut Workspace {
        &mut self.ws
    }

    /// Solve for the rigid surface `heights` (`N × N`, unit of L).
    ///
    /// # Errors
    /// Heights of the wrong length or not finite, a target ≤ 0 (or a
    /// penetration beyond what a periodic system can carry), an invalid
    /// tolerance or yield stress; a mean pressure so far above full contact
    /// that its rounding exceeds the tolerance (p̄ > τ E* h'_rms/(8ε),
    /// naming `nominal_pressure`); [`Error::NotConverged`] after `max_iter`
    /// iterations.
    ///
    /// [`Error::NotConverged`]: crate::Error::NotConverged
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
        check_options(opts, control)?;
        let problem = Problem::new(heights, self.ws.operator(), control)?;
        problem.check_round_off(opts.tolerance)?;
        self.run(&problem, opts, observer)
    }

    /// A load path on the surface `heights`: each [`LoadPath::solve`] starts
    /// from the previous one's solution (rescaled to the new load), whatever
    /// `Options::warm_start` says; the first starts cold.
    pub fn load_path<'s, 'h>(&'s mut self, heights: &'h [f64]) -> LoadPath<'s, 'h> {
        LoadPath {
            solver: self,
            heights,
            problem: None,
            warm: true,
        }
    }

    fn run(
        &mut self,
        problem: &Problem,
        opts: &Options,
        observer: &mut dyn FnMut(Iteration),
    ) -> Result<Solution> {
        match opts.yield_stress {
            Some(y) => saturated::solve(problem, &mut self.ws, y, opts, self.method, observer),
            None => elastic::solve(problem, &mut self.ws, opts, self.method, observer),
        }
    }
}

/// The checks of the options: the yield stress (positive, above the mean
/// pressure), the tolerance, at least one iteration.
fn check_options(opts: &Options, control: Control) -> Result<()> {
    if let Some(y) = opts.yield_stress {
        saturated::check_yield_stress(y, control)?;
    }
    check::tolerance("tolerance", opts.tolerance)?;
    if opts.max_iterations == 0 {
        return Err(crate::Error::invalid("max_iterations", 0.0, ">= 1"));
    }
    Ok(())
}

/// A sequence of solves on one surface, each starting from the last
/// solution (see [`Solver::load_path`]): the set-up (height statistics) is
/// built once, and a warm start saves iterations along a load curve.
///
/// # Examples
/// ```
/// use persson::bem::{Boundary, Control, Operator, Options, Solver};
/// # fn main() -> persson::Result<()> {
/// let n = 32;
/// let h: Vec<f64> = (0..n * n)
///     .map(|k| -(((k / n) as f64 / n as f64 - 0.5).powi(2) + ((k % n) as f64 / n as f64 - 0.5).powi(2)))
///     .collect();
/// let mut solver = Solver::new(Operator::new(Boundary::Periodic, n, 1.0, 1.0)?);
/// let mut path = solver.load_path(&h);
/// let a = path.solve(Control::MeanPressure(1e-3), &Options::default())?;
/// let b = path.solve(Control::MeanPressure(2e-3), &Options::default())?;
/// assert!(b.contact_fraction > a.contact_fraction);
/// # Ok(()) }
/// ```
#[derive(Debug)]
pub struct LoadPath<'s, 'h> {
    solver: &'s mut Solver,
    heights: &'h [f64],
    problem: Option<Problem<'h>>,
    warm: bool,
}

impl LoadPath<'_, '_> {
    /// Start every solve cold instead (`warm = false`; the set-up is still
    /// shared): for comparisons and for callers whose
    /// `Options::warm_start` is off.
    pub(crate) fn warm(self, warm: bool) -> Self {
        LoadPath { warm, ..self }
    }

    /// Solve at `control`, from the previous solution of this path.
    ///
    /// # Errors
    /// As [`Solver::solve`].
    pub fn solve(&mut self, control: Control, opts: &Options) -> Result<Solution> {
        self.solve_observed(control, opts, &mut |_| {})
    }

    /// [`LoadPath::solve`], calling `observer` once per iteration.
    ///
    /// # Errors
    /// As [`Solver::solve`].
    pub(crate) fn solve_observed(
        &mut self,
        control: Control,
        opts: &Options,
        observer: &mut dyn FnMut(Iteration),
    ) -> Result<Solution> {
        check_options(opts, control)?;
        let problem = match &self.problem {
            Some(p) => p.with_control(control)?,
            None => {
                // The first solve of a path never starts from another surface's solution.
                self.solver.ws.forget();
                Problem::new(self.heights, self.solver.ws.operator(), control)?
            }
        };
        problem.check_round_off(opts.tolerance)?;
        let warm = Options {
            warm_start: self.warm,
            ..*opts
        };
        let sol = self.solver.run(&problem, &warm, observer)?;
        self.problem = Some(problem);
        Ok(sol)
    }
}

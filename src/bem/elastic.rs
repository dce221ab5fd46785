//! The elastic problem by the chosen [`Method`]: a flat surface directly,
//! otherwise the preconditioned loop with the plain one as its fallback (or
//! the plain loop alone).

use crate::clock::Instant;

use super::polonsky_keer;
use super::preconditioned::{self, Cap, Outcome};
use super::problem::{Method, Options, Problem};
use super::solution::{Iteration, Solution};
use super::workspace::{Start, Workspace};
use crate::error::{Error, Result};

/// Solve the elastic `problem` (`opts.yield_stress` is not read), starting
/// warm if `opts.warm_start` and the workspace holds a solution.
///
/// # Errors
/// A penetration on a flat surface; [`Error::NotConverged`] after
/// `opts.max_iterations` iterations (all stages together).
pub(crate) fn solve(
    problem: &Problem,
    ws: &mut Workspace,
    opts: &Options,
    method: Method,
    observer: &mut dyn FnMut(Iteration),
) -> Result<Solution> {
    match solve_capped(problem, ws, opts, method, None, observer)? {
        Stage::Solved(sol) => Ok(sol),
        Stage::Capped(k) => Err(Error::Inconsistent {
            name: "elastic stage".into(),
            requirement: format!(
                "no cap was set, yet the loop stopped at one after {k} iterations"
            ),
        }),
    }
}

/// How the elastic stage ended.
#[derive(Debug)]
pub(crate) enum Stage {
    /// Converged.
    Solved(Solution),
    /// Stopped at the cap after this many iterations (the pressure is in the
    /// workspace); only the preconditioned loop stops so.
    Capped(usize),
}

/// [`solve`], stopping at `cap` (see [`Cap`]) with [`Method::Preconditioned`].
///
/// # Errors
/// As [`solve`].
pub(crate) fn solve_capped(
    problem: &Problem,
    ws: &mut Workspace,
    opts: &Options,
    method: Method,
    cap: Option<Cap>,
    observer: &mut dyn FnMut(Iteration),
) -> Result<Stage> {
    let start = Instant::now();
    if problem.is_flat() {
        return flat(problem, ws, start).map(Stage::Solved);
    }
    let warm = match method {
        _ if !opts.warm_start => Start::Cold,
        Method::Plain => Start::Rescaled,
        Method::Preconditioned { .. } => Start::Predicted,
    };
    ws.start(problem, warm)?;
    let mut sol = match method {
        Method::Plain => polonsky_keer::solve(problem, ws, opts, 0, observer)?,
        Method::Preconditioned { stall_iterations } => {
            match preconditioned::solve(problem, ws, opts, stall_iterations, cap, observer)? {
                Outcome::Converged(sol) => sol,
                Outcome::Capped(k) => return Ok(Stage::Capped(k)),
                Outcome::Stalled(fallback) => {
                    // Never a wrong answer: the plain loop finishes from the
                    // last (feasible) pressure, and the solution says so.
                    ws.resume(problem);
                    let mut sol =
                        polonsky_keer::solve(problem, ws, opts, fallback.iterations, observer)?;
                    sol.fallback = Some(fallback);
                    sol
                }
            }
        }
    };
    sol.seconds = start.elapsed().as_secs_f64();
    Ok(Stage::Solved(sol))
}

/// A flat rigid surface: uniform pressure, full contact (load control).
fn flat(problem: &Problem, ws: &mut Workspace, start: Instant) -> Result<Solution> {
    let Some(pm) = problem.target_mean() else {
        return Err(Error::invalid(
            "penetration",
            problem.penetration(),
            "used with a non-flat surface (a flat surface has no finite penetration solution)",
        ));
    };
    let n2 = problem.nodes();
    let f = ws.fields();
    f.pressure.fill(pm);
    let mut u = vec![0.0; n2];
    f.op.apply(f.pressure, &mut u)?;
    let u0 = u.first().copied().unwrap_or(0.0);
    let pressure = f.pressure.to_vec();
    ws.set_warm();
    Ok(Solution {
        pressure,
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
        fallback: None,
    })
}

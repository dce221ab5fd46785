//! The FFT-BEM's entries (feature `bem`): Hertz η against the grid for both
//! boundaries, the rough contact fraction against the grid, and the solver's
//! tolerance knob.

use persson::bem::fft::Complex64;

use super::accuracy::{AccuracyRow, Extent, Knob, MethodAccuracy};
use persson::bem::fft::Fft2;
use persson::bem::surface::{synthesize, GridSurface};
use persson::bem::{hertz, Boundary, Control, Operator, Options, Solver};
use persson::error::Result;
use persson::spectrum::{Amplitude, SelfAffine};

/// Solver tolerance of the grid studies: far below the discretisation
/// errors measured (η ≥ 1e-4 up to 1024²; Molinari, EPFL lecture "From
/// single asperity to multi asperity contact", Table 1).
const GRID_STUDY_TOL: f64 = 1e-12;

/// Tolerance of the reference solve of the tolerance study.
const REFERENCE_TOL: f64 = 1e-14;

/// Coarsest grid of the rough study: the spectrum is resolved on it.
const ROUGH_COARSE: usize = 32;

/// Seed of the rough study's surface.
const ROUGH_SEED: u64 = 2026;

/// Mean pressure of the rough study, unit of E* (A/A0 ≈ 0.1 at rms slope 0.1).
const ROUGH_PRESSURE: f64 = 5e-3;

mod surrogates;

/// Every BEM row of the accuracy report.
///
/// # Errors
/// A solve that fails (none should).
pub(super) fn accuracy(extent: Extent) -> Result<Vec<MethodAccuracy>> {
    let mut methods = hertz_grid(extent)?;
    methods.push(rough_grid(extent)?);
    methods.push(tolerance()?);
    methods.extend(surrogates::accuracy(extent)?);
    Ok(methods)
}

/// Hertz η (energy norm against the exact Hertz pressure, what
/// [`hertz::validate`] reports) for grids 32 … 256 (to 1024 with
/// [`Extent::Full`]), periodic and free boundary; seconds = the solve.
/// The periodic rows level off near η ≈ 9e-4 (measured 9.85e-4 at 512²,
/// 8.94e-4 at 1024²): the periodic images of the contact, a modelling error
/// of the periodic boundary against the isolated Hertz solution.
fn hertz_grid(extent: Extent) -> Result<Vec<MethodAccuracy>> {
    let mut grids = vec![32, 64, 128, 256];
    if extent == Extent::Full {
        grids.extend([512, 1024]);
    }
    let opts = Options {
        tolerance: GRID_STUDY_TOL,
        ..Options::default()
    };
    let mut methods = Vec::new();
    for boundary in [Boundary::Periodic, Boundary::Free] {
        let mut rows = Vec::new();
        for &n in &grids {
            let case = hertz::HertzCase::new(n, boundary);
            let (r, seconds) = median_solve(|| {
                let r = hertz::validate(&case, &opts)?;
                Ok((r, r.seconds))
            })?;
            rows.push(AccuracyRow {
                setting: n as f64,
                error: r.energy_error,
                error_bound: None,
                residual: None,
                seconds,
            });
        }
        methods.push(MethodAccuracy {
            method: match boundary {
                Boundary::Periodic => "bem-hertz-periodic",
                Boundary::Free => "bem-hertz-free",
            },
            title: format!(
                "BEM, Hertz contact (a = 0.1 L), {} boundary: energy-norm error η",
                name(boundary)
            ),
            knob: Knob::Grid,
            reference:
                "exact Hertz pressure at the nodes (Johnson, Contact Mechanics 1985, §4.2); \
                        error relative in the energy norm; time per solve"
                    .into(),
            rows,
        });
    }
    Ok(methods)
}

/// Rough contact fraction against the grid: one seeded self-affine surface
/// whose spectrum (q_l, q_r, q_s = 1, 2, 8 × 2π/L) is resolved on the
/// coarsest grid, sampled on finer grids by exact trigonometric
/// interpolation (same random phases on every grid); error
/// `|A(N) − A(N_ref)| / A(N_ref)` against the finest grid (256, Full 1024).
fn rough_grid(extent: Extent) -> Result<MethodAccuracy> {
    let (grids, finest): (&[usize], usize) = match extent {
        Extent::Default => (&[32, 64, 128], 256),
        Extent::Full => (&[32, 64, 128, 256, 512], 1024),
    };
    let coarse = rough_surface()?;
    let opts = Options {
        tolerance: GRID_STUDY_TOL,
        ..Options::default()
    };
    let solve = |n: usize| -> Result<(f64, f64)> {
        let s = refine(&coarse, n)?;
        let mut solver = Solver::new(Operator::new(Boundary::Periodic, n, s.size, 1.0)?);
        median_solve(|| {
            let sol = solver.solve(&s.heights, Control::MeanPressure(ROUGH_PRESSURE), &opts)?;
            Ok((sol.contact_fraction, sol.seconds))
        })
    };
    let (a_ref, _) = solve(finest)?;
    let rows = grids
        .iter()
        .map(|&n| {
            let (a, seconds) = solve(n)?;
            Ok(AccuracyRow {
                setting: n as f64,
                error: (a - a_ref).abs() / a_ref,
                error_bound: None,
                residual: None,
                seconds,
            })
        })
        .collect::<Result<_>>()?;
    Ok(MethodAccuracy {
        method: "bem-rough-grid",
        title: format!(
            "BEM, rough contact fraction, periodic, σ0 = {} E*: A/A0 = {}",
            crate::table::number(ROUGH_PRESSURE, 6),
            crate::table::number(a_ref, 4)
        ),
        knob: Knob::Grid,
        reference: format!(
            "the same surface on the {finest}² grid; error relative; time per solve"
        ),
        rows,
    })
}

/// The rough study's surface on the coarsest grid: L = 1, H = 0.8, rms
/// slope 0.1 (continuum value), seed [`ROUGH_SEED`].
fn rough_surface() -> Result<GridSurface> {
    let dq = std::f64::consts::TAU;
    let s = SelfAffine::new(dq, 2.0 * dq, 8.0 * dq, 0.8, Amplitude::RmsSlope(0.1))?;
    synthesize(&s, ROUGH_COARSE, 1.0, ROUGH_SEED)
}

/// The trigonometric interpolant of `s` sampled on an `n × n` grid
/// (`n ≥ s.n`): zero-padding of its spectrum. Exact for a surface without
/// content at the coarse Nyquist wavenumber (true here: q_s is a quarter of it).
///
/// # Formula
/// ```text
/// h_n(x) = (1/N₀²) Σ_{|k| < N₀/2} H_k e^{2πi k·x/L}
/// ```
fn refine(s: &GridSurface, n: usize) -> Result<GridSurface> {
    let n0 = s.n;
    if n == n0 {
        return Ok(s.clone());
    }
    let mut f0 = Fft2::new(n0, n0)?;
    let mut x = s.heights.clone();
    let mut spec0 = vec![Complex64::new(0.0, 0.0); f0.spectrum_len()];
    f0.forward(&mut x, &mut spec0)?;
    let mut f1 = Fft2::new(n, n)?;
    let mut spec1 = vec![Complex64::new(0.0, 0.0); f1.spectrum_len()];
    let scale = 1.0 / (n0 * n0) as f64;
    let half = n0 / 2;
    for kj in 0..half {
        for ki in 0..n0 {
            if ki == half {
                continue; // the coarse Nyquist row (empty here)
            }
            let target = if ki < half { ki } else { ki + n - n0 };
            spec1[kj * n + target] = spec0[kj * n0 + ki] * scale;
        }
    }
    let mut heights = vec![0.0; n * n];
    f1.inverse(&mut spec1, &mut heights)?;
    GridSurface::new(n, s.size, heights)
}

/// The solver's tolerance at a fixed grid (rough surface, 64², periodic):
/// energy-norm distance of the pressure to that of a tol 1e-14 solve.
fn tolerance() -> Result<MethodAccuracy> {
    let n = 64;
    let s = refine(&rough_surface()?, n)?;
    let mut solver = Solver::new(Operator::new(Boundary::Periodic, n, s.size, 1.0)?);
    let control = Control::MeanPressure(ROUGH_PRESSURE);
    let solve = |solver: &mut Solver, tol: f64| {
        solver.solve(
            &s.heights,
            control,
            &Options {
                tolerance: tol,
                ..Options::default()
            },
        )
    };
    let reference = solve(&mut solver, REFERENCE_TOL)?;
    let mut solver2 = Solver::new(Operator::new(Boundary::Periodic, n, s.size, 1.0)?);
    let mut work = vec![0.0; n * n];
    let norm =
        solver
            .operator()
            .energy_product(&reference.pressure, &reference.pressure, &mut work)?;
    let rows = [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]
        .iter()
        .map(|&tol| {
            let (sol, seconds) = median_solve(|| {
                let sol = solve(&mut solver2, tol)?;
                let t = sol.seconds;
                Ok((sol, t))
            })?;
            let diff: Vec<f64> = sol
                .pressure
                .iter()
                .zip(&reference.pressure)
                .map(|(a, b)| a - b)
                .collect();
            let e = solver.operator().energy_product(&diff, &diff, &mut work)?;
            Ok(AccuracyRow {
                setting: tol,
                error: (e.max(0.0) / norm).sqrt(),
                error_bound: None,
                residual: Some(sol.residual),
                seconds,
            })
        })
        .collect::<Result<_>>()?;
    Ok(MethodAccuracy {
        method: "bem-tolerance",
        title: format!("BEM, rough pressure field, {n}² periodic: solver tolerance"),
        knob: Knob::Tolerance,
        reference: format!(
            "a solve to tolerance {}; error relative in the energy norm; time per solve",
            crate::table::number(REFERENCE_TOL, 6)
        ),
        rows,
    })
}

/// Budget of repeated solves per row, s: small solves are repeated and the
/// median solve time reported (the first solve pays for cold caches).
const TIME_BUDGET: f64 = 0.05;

/// Run `f` (returning a value and its own solve time) until `TIME_BUDGET`
/// is spent (at least once, at most 25 times); the first value and the
/// median solve time.
fn median_solve<T>(mut f: impl FnMut() -> Result<(T, f64)>) -> Result<(T, f64)> {
    let (first, t0) = f()?;
    let mut times = vec![t0];
    let mut spent = t0;
    while spent < TIME_BUDGET && times.len() < 25 {
        let (_, t) = f()?;
        times.push(t);
        spent += t;
    }
    times.sort_by(f64::total_cmp);
    Ok((first, times[times.len() / 2]))
}

fn name(b: Boundary) -> &'static str {
    match b {
        Boundary::Periodic => "periodic",
        Boundary::Free => "free",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refinement_interpolates_the_coarse_surface() {
        // The interpolant passes through the coarse nodes (every 4th fine
        // node): equal up to FFT rounding, ~1e-15 of the rms height.
        let coarse = rough_surface().unwrap();
        let fine = refine(&coarse, 4 * ROUGH_COARSE).unwrap();
        let (n0, n) = (coarse.n, fine.n);
        let rms = coarse.rms_height();
        let mut worst = 0.0f64;
        for i in 0..n0 {
            for j in 0..n0 {
                let d = fine.heights[4 * i * n + 4 * j] - coarse.heights[i * n0 + j];
                worst = worst.max(d.abs() / rms);
            }
        }
        assert!(worst < 1e-13, "{worst:e}");
        // Same spectrum: the rms slope of the trigonometric interpolant is
        // the same on both grids.
        let (a, b) = (coarse.rms_slope().unwrap(), fine.rms_slope().unwrap());
        assert!((a - b).abs() < 1e-12 * a, "{a} vs {b}");
    }
}

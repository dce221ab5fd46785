//! Rough contact: one rigid rough surface pressed onto the elastic
//! half-space at a list of nominal pressures (one solve each, warm-started
//! along the list).
//!
//! [`solve`] is the one loop used by `persson bem rough`, by scenes and by the
//! resolution sweep of the studies crate (`persson-studies`); [`rough_contact`] wraps it into
//! the typed report that `persson bem rough` prints.
//!
//! # Example
//! ```
//! use persson::bem::histogram::integral;
//! use persson::bem::rough::{solve, RoughOptions};
//! use persson::bem::surface::synthesize;
//! use persson::spectrum::{Amplitude, SelfAffine};
//! # fn main() -> persson::Result<()> {
//! let q_l = std::f64::consts::TAU; // L = 1
//! let s = SelfAffine::new(q_l, 2.0 * q_l, 8.0 * q_l, 0.8, Amplitude::RmsSlope(0.1))?;
//! let surface = synthesize(&s, 32, 1.0, 1)?;
//! let options = RoughOptions { bins: Some(20), ..RoughOptions::default() };
//! let points = solve(&surface, 1.0, &[0.002, 0.005], &options, &mut ())?;
//! for p in &points {
//!     // the histogram integrates to A/A0; the load is carried
//!     let h = p.histogram.as_ref().unwrap();
//!     assert!((integral(h) - p.contact_fraction).abs() < 1e-12);
//! }
//! assert!(points[0].contact_fraction < points[1].contact_fraction);
//! # Ok(()) }
//! ```

use std::path::Path;

use serde::Serialize;

use super::histogram::{pressure_histogram, saturated_histogram, HistogramBin};
use super::{check_memory, surface, Boundary, Control, Iteration, Operator, Options, Solution};
use super::{Fallback, GridSurface, Method, Solver};
use crate::error::{check, Error, Result};
use crate::spectrum::Spectrum;

/// How the rough solves run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughOptions {
    /// Boundary condition of the half-space.
    pub boundary: Boundary,
    /// Solver accuracy; `warm_start` carries each solution to the next pressure.
    pub solver: Options,
    /// Bins of the pressure histogram of each solve (`None`: no histogram).
    pub bins: Option<usize>,
    /// The solver's method (default: preconditioned, falling back to the
    /// plain loop when it stalls; [`RoughPoint::fallback`] says so).
    pub method: Method,
}

impl Default for RoughOptions {
    /// Periodic, the solver's defaults with warm start, no histogram, the
    /// preconditioned method.
    fn default() -> Self {
        RoughOptions {
            boundary: Boundary::Periodic,
            solver: Options {
                warm_start: true,
                ..Options::default()
            },
            bins: None,
            method: Method::default(),
        }
    }
}

/// One solve of a rough contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct RoughPoint {
    /// Nominal pressure σ0 (unit of E*).
    pub nominal_pressure: f64,
    /// A/A0: fraction of nodes with p > 0.
    pub contact_fraction: f64,
    /// Mean gap ū = Σ gap / N² (unit of L); with a yield stress the
    /// plastic nodes' interpenetration enters it as a negative gap.
    pub mean_separation: f64,
    /// Approach from first touch (unit of L).
    pub approach: f64,
    /// Solver iterations.
    pub iterations: usize,
    /// Final residual ε (≤ tolerance).
    pub residual: f64,
    /// Wall time of the solve, s.
    pub seconds: f64,
    /// P(σ) of the solve, when bins were asked for (with a yield stress:
    /// the nodes below σY, on `[0, σY)`; the δ-peak at σY is
    /// `plastic_fraction`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub histogram: Option<Vec<HistogramBin>>,
    /// With a yield stress: fraction of nodes with 0 < p < σY.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub elastic_fraction: Option<f64>,
    /// With a yield stress: fraction of nodes at p = σY.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_fraction: Option<f64>,
    /// With a yield stress: mean plastic displacement (interpenetration)
    /// over the nodes at σY (unit of L).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_displacement_mean: Option<f64>,
    /// With a yield stress: largest plastic displacement (unit of L).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_displacement_max: Option<f64>,
    /// Set when the preconditioned solver stalled and the plain one
    /// finished this solve (same answer, more time): the application layer
    /// warns about it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fallback: Option<Fallback>,
}

/// Progress of [`solve`], once per solver iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct RoughProgress {
    /// Index of the current pressure in the caller's list.
    pub index: usize,
    /// Number of pressures.
    pub total: usize,
    /// Nominal pressure of the current solve.
    pub nominal_pressure: f64,
    /// The solver's state.
    pub iteration: Iteration,
}

/// What the caller sees of [`solve`] while it runs; `()` sees nothing.
pub trait Observer {
    /// Called once per solver iteration.
    fn iteration(&mut self, _progress: RoughProgress) {}
    /// Called with each converged solution (its index in the pressure list),
    /// e.g. to write or accumulate the pressure field.
    ///
    /// # Errors
    /// Whatever the caller's handling returns; it stops the loop.
    fn solution(&mut self, _index: usize, _solution: &Solution) -> Result<()> {
        Ok(())
    }
}

impl Observer for () {}

/// Solve the contact of `surface` at each nominal pressure, in the given
/// order, along one [`LoadPath`](super::LoadPath): each solve starts from the
/// previous solution when `options.solver.warm_start`.
///
/// # Errors
/// No pressure, a pressure not finite and positive, `bins == Some(0)`;
/// as [`check_memory`], [`Operator::new`] and [`Solver::solve`]
/// ([`Error::NotConverged`]); whatever the observer returns.
pub fn solve(
    surface: &GridSurface,
    contact_modulus: f64,
    pressures: &[f64],
    options: &RoughOptions,
    observer: &mut dyn Observer,
) -> Result<Vec<RoughPoint>> {
    if pressures.is_empty() {
        return Err(Error::invalid("nominal_pressure", 0.0, "at least one"));
    }
    for &p in pressures {
        check::positive("nominal_pressure", p)?;
    }
    if options.bins == Some(0) {
        return Err(Error::invalid("bins", 0.0, ">= 1"));
    }
    check_memory(surface.n, options.boundary)?;
    let op = Operator::new(options.boundary, surface.n, surface.size, contact_modulus)?;
    let mut solver = Solver::with_method(op, options.method);
    let mut path = solver
        .load_path(&surface.heights)
        .warm(options.solver.warm_start);
    let total = pressures.len();
    let mut points = Vec::with_capacity(total);
    for (index, &p) in pressures.iter().enumerate() {
        let sol = path.solve_observed(
            Control::MeanPressure(p),
            &options.solver,
            &mut |iteration| {
                observer.iteration(RoughProgress {
                    index,
                    total,
                    nominal_pressure: p,
                    iteration,
                })
            },
        )?;
        observer.solution(index, &sol)?;
        let yield_stress = options.solver.yield_stress;
        let histogram = match (options.bins, yield_stress) {
            (Some(b), Some(y)) => Some(saturated_histogram(&sol.pressure, b, y)?.bins),
            (Some(b), None) => Some(pressure_histogram(&sol.pressure, b)?),
            (None, _) => None,
        };
        let plastic = |v: f64| yield_stress.map(|_| v);
        points.push(RoughPoint {
            nominal_pressure: p,
            contact_fraction: sol.contact_fraction,
            mean_separation: sol.gap.iter().sum::<f64>() / sol.gap.len() as f64,
            approach: sol.approach,
            iterations: sol.iterations,
            residual: sol.residual,
            seconds: sol.seconds,
            histogram,
            elastic_fraction: plastic(sol.elastic_fraction),
            plastic_fraction: plastic(sol.plastic_fraction),
            plastic_displacement_mean: plastic(sol.plastic_displacement_mean),
            plastic_displacement_max: plastic(sol.plastic_displacement_max),
            fallback: sol.fallback,
        });
    }
    Ok(points)
}

/// Read a height map (.npy or text matrix) of side `size`, checking first
/// that a solve on the largest grid the file can hold fits in memory.
///
/// # Errors
/// As [`check_memory`] and [`surface::height_map_from_bytes`].
pub fn read_surface(path: &Path, size: f64, boundary: Boundary) -> Result<GridSurface> {
    check::positive("size", size)?;
    let bytes = crate::io::read(path)?;
    // A float32 file of this length holds at most len/4 values.
    let n_max = ((bytes.len() / 4) as f64).sqrt() as usize;
    if n_max > super::MIN_GRID {
        check_memory(n_max.min(super::MAX_GRID), boundary)?;
    }
    surface::height_map_from_bytes(path, &bytes, size)
}

/// The spectrum a surface was synthesised from, as echoed in reports.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SpectrumSummary {
    /// Lower cut-off q_l (1/unit of L).
    pub q_l: f64,
    /// Upper cut-off q_s.
    pub q_s: f64,
    /// rms height over [q_l, q_s].
    pub rms_height: f64,
    /// rms slope over [q_l, q_s].
    pub rms_slope: f64,
}

impl SpectrumSummary {
    /// The summary of `spectrum` over its whole band.
    ///
    /// # Errors
    /// As [`Spectrum::rms_height`] and [`Spectrum::rms_slope`].
    pub fn of(spectrum: &dyn Spectrum) -> Result<Self> {
        let (q_l, q_s) = (spectrum.q_min(), spectrum.q_max());
        Ok(SpectrumSummary {
            q_l,
            q_s,
            rms_height: spectrum.rms_height(q_l, q_s)?.value,
            rms_slope: spectrum.rms_slope(q_l, q_s)?.value,
        })
    }
}

/// Where the rigid surface of a rough contact came from: a file, or a
/// spectrum and a seed.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
#[non_exhaustive]
pub enum SurfaceOrigin {
    /// A height map read from a file.
    HeightMap {
        /// The file, as given.
        file: String,
    },
    /// Synthesised from a spectrum ([`surface::synthesize`]).
    Synthesised {
        /// Seed of the Pcg64Mcg generator.
        seed: u64,
        /// The spectrum.
        spectrum: SpectrumSummary,
    },
}

/// The name of [`SurfaceOrigin`] in persson 0.3.
#[deprecated(since = "0.4.0", note = "renamed SurfaceOrigin")]
pub type SurfaceSource = SurfaceOrigin;

impl SurfaceOrigin {
    /// A synthesised surface's source.
    ///
    /// # Errors
    /// As [`SpectrumSummary::of`].
    pub fn synthesised(spectrum: &dyn Spectrum, seed: u64) -> Result<Self> {
        Ok(SurfaceOrigin::Synthesised {
            seed,
            spectrum: SpectrumSummary::of(spectrum)?,
        })
    }

    /// The seed of a synthesised surface (`None` for a height map).
    pub fn seed(&self) -> Option<u64> {
        match self {
            SurfaceOrigin::Synthesised { seed, .. } => Some(*seed),
            SurfaceOrigin::HeightMap { .. } => None,
        }
    }

    /// A height map's source.
    pub fn height_map(file: &Path) -> Self {
        SurfaceOrigin::HeightMap {
            file: file.display().to_string(),
        }
    }
}

/// The report of `persson bem rough`: the surface, the solver settings and
/// one point per nominal pressure.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct RoughReport {
    /// Grid side N.
    pub grid: usize,
    /// Side L of the surface.
    pub size: f64,
    /// Boundary condition.
    pub boundary: Boundary,
    /// Contact modulus E*.
    pub contact_modulus: f64,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// Yield stress σY (unit of E*), when the pressures are bounded by it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// rms height of the surface on the grid (unit of L).
    pub surface_rms_height: f64,
    /// rms slope of the surface on the grid (its trigonometric interpolant).
    pub surface_rms_slope: f64,
    /// Where the surface came from.
    pub surface: SurfaceOrigin,
    /// One point per nominal pressure, in the caller's order.
    pub points: Vec<RoughPoint>,
    /// The pressure field of one solve in partial contact (A/A0 nearest
    /// [`MAPPED_CONTACT_FRACTION`]), kept only by [`rough_contact_mapped`]
    /// (for a pressure map); not serialised.
    #[serde(skip)]
    pub pressure_map: Option<PressureMap>,
}

/// The pressure field of one solve (row-major N × N, unit of E*).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct PressureMap {
    /// Index of the solve in the pressure list.
    pub index: usize,
    /// Its nominal pressure σ0.
    pub nominal_pressure: f64,
    /// The nodal pressures, `p[i·N + j]`.
    pub pressure: Vec<f64>,
}

/// The contact fraction of the solve whose field [`rough_contact_mapped`]
/// keeps: the one nearest it, a partial contact whose islands a map shows
/// (the last load of a curve is often near full contact, a map of noise).
pub const MAPPED_CONTACT_FRACTION: f64 = 0.1;

/// Keeps the pressure of the solution whose A/A0 is nearest
/// [`MAPPED_CONTACT_FRACTION`] (the first of equals), forwarding everything else.
struct Keep<'a> {
    inner: &'a mut dyn Observer,
    /// (index, |A/A0 − target|, pressure field).
    kept: Option<(usize, f64, Vec<f64>)>,
}

impl Observer for Keep<'_> {
    fn iteration(&mut self, progress: RoughProgress) {
        self.inner.iteration(progress);
    }
    fn solution(&mut self, index: usize, solution: &Solution) -> Result<()> {
        self.inner.solution(index, solution)?;
        let distance = (solution.contact_fraction - MAPPED_CONTACT_FRACTION).abs();
        match &mut self.kept {
            Some((_, d, _)) if *d <= distance => {}
            Some((k, d, p)) => {
                (*k, *d) = (index, distance);
                p.clone_from(&solution.pressure);
            }
            None => self.kept = Some((index, distance, solution.pressure.clone())),
        }
        Ok(())
    }
}

/// [`rough_contact`], keeping in [`RoughReport::pressure_map`] the pressure
/// field of the solve whose A/A0 is nearest [`MAPPED_CONTACT_FRACTION`]
/// (at most one N² copy per solve; [`rough_contact`] keeps none).
///
/// # Errors
/// As [`rough_contact`].
pub fn rough_contact_mapped(
    surface: &GridSurface,
    source: SurfaceOrigin,
    contact_modulus: f64,
    pressures: &[f64],
    options: &RoughOptions,
    observer: &mut dyn Observer,
) -> Result<RoughReport> {
    let mut keep = Keep {
        inner: observer,
        kept: None,
    };
    let mut report = rough_contact(
        surface,
        source,
        contact_modulus,
        pressures,
        options,
        &mut keep,
    )?;
    report.pressure_map = keep.kept.map(|(index, _, pressure)| PressureMap {
        index,
        nominal_pressure: pressures[index],
        pressure,
    });
    Ok(report)
}

/// [`solve`] and its report.
///
/// # Errors
/// As [`solve`] and [`GridSurface::rms_slope`].
pub fn rough_contact(
    surface: &GridSurface,
    source: SurfaceOrigin,
    contact_modulus: f64,
    pressures: &[f64],
    options: &RoughOptions,
    observer: &mut dyn Observer,
) -> Result<RoughReport> {
    let points = solve(surface, contact_modulus, pressures, options, observer)?;
    Ok(RoughReport {
        grid: surface.n,
        size: surface.size,
        boundary: options.boundary,
        contact_modulus,
        tolerance: options.solver.tolerance,
        yield_stress: options.solver.yield_stress,
        surface_rms_height: surface.rms_height(),
        surface_rms_slope: surface.rms_slope()?,
        surface: source,
        points,
        pressure_map: None,
    })
}

//! Rough contact: one rigid rough surface pressed onto the elastic
//! half-space at a list of nominal pressures (one solve each, warm-started
//! along the list).
//!
//! [`solve`] is the one loop used by `persson bem rough`, by scenes and by the
//! resolution sweep of [`crate::validation`]; [`rough_contact`] wraps it into
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
use super::{Fallback, Solver, Surface};
use crate::error::{check, Error, Result};
use crate::spectrum::Spectrum;
use crate::table::{number, Cell, Table, Tabulate};

/// How the rough solves run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughOptions {
    /// Boundary condition of the half-space.
    pub boundary: Boundary,
    /// Solver accuracy; `warm_start` carries each solution to the next pressure.
    pub solver: Options,
    /// Bins of the pressure histogram of each solve (`None`: no histogram).
    pub bins: Option<usize>,
}

impl Default for RoughOptions {
    /// Periodic, the solver's defaults with warm start, no histogram.
    fn default() -> Self {
        RoughOptions {
            boundary: Boundary::Periodic,
            solver: Options {
                warm_start: true,
                ..Options::default()
            },
            bins: None,
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
    surface: &Surface,
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
    let mut solver = Solver::new(op);
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
pub fn read_surface(path: &Path, size: f64, boundary: Boundary) -> Result<Surface> {
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

/// Where the rigid surface of a rough contact came from.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
#[non_exhaustive]
pub enum SurfaceSource {
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

impl SurfaceSource {
    /// A synthesised surface's source.
    ///
    /// # Errors
    /// As [`SpectrumSummary::of`].
    pub fn synthesised(spectrum: &dyn Spectrum, seed: u64) -> Result<Self> {
        Ok(SurfaceSource::Synthesised {
            seed,
            spectrum: SpectrumSummary::of(spectrum)?,
        })
    }

    /// The seed of a synthesised surface (`None` for a height map).
    pub fn seed(&self) -> Option<u64> {
        match self {
            SurfaceSource::Synthesised { seed, .. } => Some(*seed),
            SurfaceSource::HeightMap { .. } => None,
        }
    }

    /// A height map's source.
    pub fn height_map(file: &Path) -> Self {
        SurfaceSource::HeightMap {
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
    pub surface: SurfaceSource,
    /// One point per nominal pressure, in the caller's order.
    pub points: Vec<RoughPoint>,
    /// The pressure field of the last solve, kept only by
    /// [`rough_contact_mapped`] (for `bem rough --plot`); not serialised.
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

/// Keeps the last solution's pressure, forwarding everything else.
struct Keep<'a> {
    inner: &'a mut dyn Observer,
    last: Option<(usize, Vec<f64>)>,
}

impl Observer for Keep<'_> {
    fn iteration(&mut self, progress: RoughProgress) {
        self.inner.iteration(progress);
    }
    fn solution(&mut self, index: usize, solution: &Solution) -> Result<()> {
        self.inner.solution(index, solution)?;
        match &mut self.last {
            Some((k, p)) => {
                *k = index;
                p.clone_from(&solution.pressure);
            }
            None => self.last = Some((index, solution.pressure.clone())),
        }
        Ok(())
    }
}

/// [`rough_contact`], keeping the pressure field of the last solve in
/// [`RoughReport::pressure_map`] (one N² copy per solve; [`rough_contact`]
/// keeps none).
///
/// # Errors
/// As [`rough_contact`].
pub fn rough_contact_mapped(
    surface: &Surface,
    source: SurfaceSource,
    contact_modulus: f64,
    pressures: &[f64],
    options: &RoughOptions,
    observer: &mut dyn Observer,
) -> Result<RoughReport> {
    let mut keep = Keep {
        inner: observer,
        last: None,
    };
    let mut report = rough_contact(
        surface,
        source,
        contact_modulus,
        pressures,
        options,
        &mut keep,
    )?;
    report.pressure_map = keep.last.map(|(index, pressure)| PressureMap {
        index,
        nominal_pressure: pressures[index],
        pressure,
    });
    Ok(report)
}

/// [`solve`] and its report.
///
/// # Errors
/// As [`solve`] and [`Surface::rms_slope`].
pub fn rough_contact(
    surface: &Surface,
    source: SurfaceSource,
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

impl Tabulate for RoughReport {
    fn tables(&self) -> Vec<Table> {
        let n = self.grid;
        let mut t = Table::new(
            "bem_rough",
            format!(
                "Rough contact (FFT-BEM, Polonsky & Keer 1999), {n}×{n} grid, {} boundary",
                self.boundary.name()
            ),
        )
        .scalar("grid", "N", n)
        .scalar("size", "L", self.size)
        .scalar("contact_modulus", "E*", self.contact_modulus)
        .scalar("tolerance", "tolerance ε", self.tolerance)
        .scalar(
            "surface_rms_height",
            "h_rms on the grid",
            self.surface_rms_height,
        )
        .scalar(
            "surface_rms_slope",
            "h'_rms on the grid",
            self.surface_rms_slope,
        );
        if let Some(y) = self.yield_stress {
            t = t.scalar("yield_stress", "σY", y);
        }
        match &self.surface {
            SurfaceSource::HeightMap { file } => t = t.scalar("file", "surface", file.as_str()),
            SurfaceSource::Synthesised { seed, spectrum } => {
                t = t.scalar("seed", "seed", Cell::Int(*seed as i64)).scalar(
                    "q_s",
                    "q_l … q_s",
                    format!("{} … {}", number(spectrum.q_l, 6), number(spectrum.q_s, 6)),
                );
            }
        }
        let mut t = t
            .column("nominal_pressure", "σ0")
            .column("contact_fraction", "A/A0")
            .column("mean_separation", "ū")
            .column("approach", "δ")
            .column("iterations", "iterations")
            .column_digits("residual", "residual", 2)
            .column_digits("seconds", "time (s)", 3);
        let saturated = self.yield_stress.is_some();
        if saturated {
            t = t
                .column("elastic_fraction", "A_el/A0")
                .column("plastic_fraction", "A_pl/A0")
                .column("plastic_displacement_mean", "u_pl mean")
                .column("plastic_displacement_max", "u_pl max");
        }
        for p in &self.points {
            let mut row: Vec<Cell> = vec![
                p.nominal_pressure.into(),
                p.contact_fraction.into(),
                p.mean_separation.into(),
                p.approach.into(),
                p.iterations.into(),
                p.residual.into(),
                p.seconds.into(),
            ];
            if saturated {
                for v in [
                    p.elastic_fraction,
                    p.plastic_fraction,
                    p.plastic_displacement_mean,
                    p.plastic_displacement_max,
                ] {
                    row.push(v.unwrap_or(0.0).into());
                }
            }
            t.push(row);
        }
        let mut tables = vec![t];
        if self.points.iter().any(|p| p.histogram.is_some()) {
            // With a yield stress, the δ-peak at σY is a row of its own
            // (σ low = σ high = σY, no density) with its weight in the
            // column `plastic_fraction`, empty on the bins' rows.
            let mut h = Table::new("bem_histogram", "Pressure histograms P(σ) of the FFT-BEM")
                .column("nominal_pressure", "σ0")
                .column("sigma_low", "σ low")
                .column("sigma_high", "σ high")
                .column("density", "P(σ)");
            if saturated {
                h = h.column("plastic_fraction", "A_pl/A0 (δ-peak at σY)");
            }
            for p in &self.points {
                let Some(bins) = &p.histogram else { continue };
                for b in bins {
                    let mut row: Vec<Cell> = vec![
                        p.nominal_pressure.into(),
                        b.sigma_low.into(),
                        b.sigma_high.into(),
                        b.density.into(),
                    ];
                    if saturated {
                        row.push(Cell::Empty);
                    }
                    h.push(row);
                }
                if let Some(y) = self.yield_stress {
                    h.push(vec![
                        p.nominal_pressure.into(),
                        y.into(),
                        y.into(),
                        Cell::Empty,
                        p.plastic_fraction.into(),
                    ]);
                }
            }
            tables.push(h);
        }
        tables
    }
}

//! [`ensemble`]: the FFT-BEM on an ensemble of independent surfaces (seeds ×
//! grids, each solved at every nominal pressure), gathered into one table of
//! means and standard errors over the seeds, per grid and pressure.
//!
//! # The ensemble
//! A job is one (seed, N): its surface is synthesised from the spectrum, the
//! seed and the grids (the same nested, band-limited realisation as
//! `persson compare`'s sweep, [`super::sweep::sweep_one`]: the surface of a
//! seed on the finest grid, this grid's copy of it), then solved at every
//! pressure (ascending, with the solver's warm start when set). Jobs share
//! nothing, so they run in any order and anywhere: [`ensemble`] runs them on
//! local threads, the Python package on Dask workers (which get the
//! spectrum, the seed and N, never a height map); [`gather`] sorts them and
//! forms the statistics, so the table is the same, to the last digit,
//! whatever ran the jobs and in whatever order they finished.
//!
//! The spectrum is clipped to the q_s the coarsest grid resolves
//! ([`SweepSettings::band`], with a warning when clipped), as in `compare`.
//!
//! # Formula
//! Over the K seeds, per grid N and nominal pressure σ0, for A/A0 and ū:
//! ```text
//! mean            x̄ = (1/K) Σₖ xₖ
//! standard error  s = √( Σₖ (xₖ − x̄)² / (K (K − 1)) )      (none for K = 1)
//! ```
//! ([`super::mean_and_error`]).
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005
//! (ensembles of seeds and grids for the contact area).

use serde::Serialize;

use super::continuum::mean_and_error;
use super::limits::SeedMean;
use super::resolution::{ResolvedBand, SweepConfig, SweepSettings};
use super::sweep::sweep_one;
use crate::table::{Cell, Table, Tabulate};
use crate::Warning;
use persson::error::{check, Error, Result};
use persson::spectrum::{BandLimited, Spectrum};

/// What [`ensemble`] solves.
#[derive(Debug, Clone, PartialEq)]
pub struct EnsembleConfig {
    /// Contact modulus E*.
    pub contact_modulus: f64,
    /// Nominal pressures σ0 (unit of E*), at least one.
    pub nominal_pressure: Vec<f64>,
    /// Grids (finest and levels), seeds, q_s resolution and solver accuracy.
    pub sweep: SweepSettings,
}

/// One independent unit of an ensemble: a seed on a grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct EnsembleJob {
    /// The seed of the surface.
    pub seed: u64,
    /// The grid side N.
    pub grid: usize,
}

/// One job's results: A/A0 and ū at every pressure (the caller's order).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct EnsembleSolve {
    /// The seed of the surface.
    pub seed: u64,
    /// The grid side N.
    pub grid: usize,
    /// A/A0, one per pressure.
    pub contact_fraction: Vec<f64>,
    /// Mean gap ū (unit of L), one per pressure.
    pub mean_separation: Vec<f64>,
    /// rms slope of the surface (trigonometric interpolant).
    pub surface_rms_slope: f64,
    /// CG iterations of the job's solves.
    pub iterations: usize,
    /// Largest final residual ε of the job's solves.
    pub residual: f64,
    /// Wall-clock seconds of the job's solves.
    pub seconds: f64,
}

impl EnsembleSolve {
    /// A job's results from their parts (as a remote worker sends them back).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        job: EnsembleJob,
        contact_fraction: Vec<f64>,
        mean_separation: Vec<f64>,
        surface_rms_slope: f64,
        iterations: usize,
        residual: f64,
        seconds: f64,
    ) -> Self {
        EnsembleSolve {
            seed: job.seed,
            grid: job.grid,
            contact_fraction,
            mean_separation,
            surface_rms_slope,
            iterations,
            residual,
            seconds,
        }
    }
}

/// The statistics of one grid over the seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct EnsembleGrid {
    /// The grid side N.
    pub grid: usize,
    /// A/A0, mean over the seeds, per pressure.
    pub contact_fraction: Vec<f64>,
    /// Its standard error over the seeds (`None` for one seed), per pressure.
    pub contact_fraction_standard_error: Vec<Option<f64>>,
    /// ū (unit of L), mean over the seeds, per pressure.
    pub mean_separation: Vec<f64>,
    /// Its standard error over the seeds (`None` for one seed), per pressure.
    pub mean_separation_standard_error: Vec<Option<f64>>,
    /// CG iterations of the grid's solves.
    pub iterations: usize,
    /// Largest final residual ε of the grid's solves.
    pub residual: f64,
    /// Wall-clock seconds of the grid's solves (summed over jobs).
    pub seconds: f64,
}

/// An ensemble's results: the statistics per grid and every job's numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct EnsembleReport {
    /// E*.
    pub contact_modulus: f64,
    /// Nominal pressures, in the caller's order.
    pub nominal_pressure: Vec<f64>,
    /// The seeds.
    pub seeds: Vec<u64>,
    /// The q_s of the surfaces (clipped to what the coarsest grid resolves).
    #[serde(flatten)]
    pub band: ResolvedBand,
    /// One per grid, ascending.
    pub grids: Vec<EnsembleGrid>,
    /// Every job, by grid then seed (the order of `grids` and `seeds`).
    pub solves: Vec<EnsembleSolve>,
    /// Remarks on the input (q_s clipped, a pressure near E*): printed on
    /// stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<Warning>,
}

/// The sweep configuration and band of an ensemble on `spectrum`.
fn setup(spectrum: &dyn Spectrum, config: &EnsembleConfig) -> Result<(SweepConfig, ResolvedBand)> {
    check::positive("contact_modulus", config.contact_modulus)?;
    if config.nominal_pressure.is_empty() {
        return Err(Error::invalid("nominal_pressure", 0.0, "at least one"));
    }
    for &p in &config.nominal_pressure {
        check::positive("nominal_pressure", p)?;
    }
    let q_l = spectrum.q_min();
    let sweep = config.sweep.config(q_l)?;
    let band = config.sweep.band(q_l, Some(spectrum.q_max()))?;
    Ok((sweep, band))
}

/// Every job of the ensemble, finest grid first (the longest jobs first, so
/// that a pool of workers ends together), then by seed.
///
/// # Errors
/// As [`SweepSettings::config`] and [`SweepSettings::band`]; E* or a
/// pressure not finite and positive; no pressure.
pub fn jobs(spectrum: &dyn Spectrum, config: &EnsembleConfig) -> Result<Vec<EnsembleJob>> {
    let (sweep, _) = setup(spectrum, config)?;
    Ok(sweep
        .grids
        .iter()
        .rev()
        .flat_map(|&grid| {
            sweep
                .seeds
                .iter()
                .map(move |&seed| EnsembleJob { seed, grid })
        })
        .collect())
}

/// Solve one job: the surface of `job.seed` on `job.grid` at every pressure.
///
/// # Errors
/// As [`jobs`] and [`super::sweep::sweep_one`] (a grid not of the ensemble,
/// a solve that does not converge).
pub fn solve(
    spectrum: &dyn Spectrum,
    config: &EnsembleConfig,
    job: EnsembleJob,
) -> Result<EnsembleSolve> {
    let (sweep, band) = setup(spectrum, config)?;
    let clipped = BandLimited::new(spectrum, band.q_s)?;
    let g = sweep_one(
        &clipped,
        config.contact_modulus,
        &config.nominal_pressure,
        &sweep,
        job.seed,
        job.grid,
    )?;
    Ok(EnsembleSolve {
        seed: job.seed,
        grid: job.grid,
        contact_fraction: g.contact_fraction.into_iter().next().unwrap_or_default(),
        mean_separation: g.mean_separation.into_iter().next().unwrap_or_default(),
        surface_rms_slope: g.surface_rms_slope.first().copied().unwrap_or(f64::NAN),
        iterations: g.iterations,
        residual: g.residual,
        seconds: g.seconds,
    })
}

/// The report of the ensemble from its jobs' results, in any order.
///
/// # Errors
/// A job missing, given twice or not of this ensemble, or with a number of
/// values other than the pressures'; as [`jobs`].
pub fn gather(
    spectrum: &dyn Spectrum,
    config: &EnsembleConfig,
    mut solves: Vec<EnsembleSolve>,
) -> Result<EnsembleReport> {
    let (sweep, band) = setup(spectrum, config)?;
    let np = config.nominal_pressure.len();
    let rank = |s: &EnsembleSolve| {
        let g = sweep.grids.iter().position(|&g| g == s.grid);
        let k = sweep.seeds.iter().position(|&k| k == s.seed);
        g.zip(k)
    };
    for s in &solves {
        if rank(s).is_none() || s.contact_fraction.len() != np || s.mean_separation.len() != np {
            return Err(Error::Inconsistent {
                name: "solves".into(),
                requirement: format!(
                    "a job (seed {}, grid {}) of this ensemble with {np} values",
                    s.seed, s.grid
                ),
            });
        }
    }
    solves.sort_by_key(|s| rank(s));
    let expected = sweep.grids.len() * sweep.seeds.len();
    let distinct = solves.windows(2).all(|w| rank(&w[0]) != rank(&w[1]));
    if solves.len() != expected || !distinct {
        return Err(Error::Inconsistent {
            name: "solves".into(),
            requirement: format!(
                "each of the {expected} jobs (seeds × grids) exactly once, got {} results",
                solves.len()
            ),
        });
    }
    let grids = sweep
        .grids
        .iter()
        .zip(solves.chunks(sweep.seeds.len()))
        .map(|(&grid, runs)| grid_statistics(grid, runs, np))
        .collect();
    Ok(EnsembleReport {
        contact_modulus: config.contact_modulus,
        nominal_pressure: config.nominal_pressure.clone(),
        seeds: sweep.seeds.clone(),
        band,
        grids,
        solves,
        warnings: warnings(spectrum, config, &sweep, band),
    })
}

/// Mean and standard error over the seeds of one grid's jobs.
fn grid_statistics(grid: usize, runs: &[EnsembleSolve], np: usize) -> EnsembleGrid {
    let per_pressure = |f: &dyn Fn(&EnsembleSolve) -> &[f64]| {
        let (mean, standard_error) = (0..np)
            .map(|k| {
                let m = mean_and_error(&runs.iter().map(|s| f(s)[k]).collect::<Vec<_>>());
                (m.mean, m.standard_error)
            })
            .unzip();
        SeedMean {
            mean,
            standard_error,
        }
    };
    let a = per_pressure(&|s| &s.contact_fraction);
    let u = per_pressure(&|s| &s.mean_separation);
    EnsembleGrid {
        grid,
        contact_fraction: a.mean,
        contact_fraction_standard_error: a.standard_error,
        mean_separation: u.mean,
        mean_separation_standard_error: u.standard_error,
        iterations: runs.iter().map(|s| s.iterations).sum(),
        residual: runs.iter().map(|s| s.residual).fold(0.0, f64::max),
        seconds: runs.iter().map(|s| s.seconds).sum(),
    }
}

/// The warnings of an ensemble: q_s clipped, a pressure near E*.
fn warnings(
    spectrum: &dyn Spectrum,
    config: &EnsembleConfig,
    sweep: &SweepConfig,
    band: ResolvedBand,
) -> Vec<Warning> {
    let mut w = Vec::new();
    if let (true, Some(q)) = (band.clipped, band.q_s_requested) {
        w.push(Warning::ClippedBand {
            q_s_requested: q,
            q_s: band.q_s,
            q_l: spectrum.q_min(),
            grid: sweep.grids.first().copied().unwrap_or_default(),
            pixels_per_wavelength: config.sweep.pixels_per_wavelength,
        });
    }
    crate::warning::push(
        &mut w,
        Warning::high_pressure(&config.nominal_pressure, config.contact_modulus),
    );
    w
}

/// Run the ensemble on `threads` local threads (0: one per core) and gather it.
///
/// Each thread takes the next job of [`jobs`] until none is left; the report
/// does not depend on the number of threads.
///
/// # Errors
/// As [`jobs`], [`solve`] (the first failing job's error) and [`gather`].
pub fn ensemble(
    spectrum: &dyn Spectrum,
    config: &EnsembleConfig,
    threads: usize,
) -> Result<EnsembleReport> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Mutex;
    let all = jobs(spectrum, config)?;
    let threads = match threads {
        0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
        n => n,
    }
    .min(all.len())
    .max(1);
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<(usize, Result<EnsembleSolve>)>> = Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                loop {
                    let index = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&job) = all.get(index) else { break };
                    let r = solve(spectrum, config, job);
                    let failed = r.is_err();
                    if let Ok(mut list) = results.lock() {
                        list.push((index, r));
                    }
                    if failed {
                        // Stop handing out jobs: the first error is the answer.
                        next.store(all.len(), Ordering::Relaxed);
                    }
                }
            });
        }
    });
    let mut list = results
        .into_inner()
        .map_err(|_| Error::invalid("threads", threads as f64, "a worker thread panicked"))?;
    list.sort_by_key(|(i, _)| *i);
    let solves = list
        .into_iter()
        .map(|(_, r)| r)
        .collect::<Result<Vec<_>>>()?;
    gather(spectrum, config, solves)
}

impl Tabulate for EnsembleReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "ensemble",
            format!(
                "FFT-BEM ensemble: {} seed(s) × {} grid(s), mean ± standard error over seeds",
                self.seeds.len(),
                self.grids.len()
            ),
        )
        .scalar("contact_modulus", "E*", self.contact_modulus)
        .scalar("q_s", "q_s", self.band.q_s)
        .column("grid", "N")
        .column("nominal_pressure", "σ0")
        .column_digits("contact_fraction", "A/A0", 6)
        .column_digits("contact_fraction_standard_error", "± s.e.", 2)
        .column_digits("mean_separation", "ū", 6)
        .column_digits("mean_separation_standard_error", "± s.e.", 2);
        for g in &self.grids {
            for (k, &p) in self.nominal_pressure.iter().enumerate() {
                let err = |e: &[Option<f64>]| e[k].map_or(Cell::Empty, Cell::Num);
                t.push(vec![
                    Cell::from(g.grid),
                    Cell::Num(p),
                    Cell::Num(g.contact_fraction[k]),
                    err(&g.contact_fraction_standard_error),
                    Cell::Num(g.mean_separation[k]),
                    err(&g.mean_separation_standard_error),
                ]);
            }
        }
        vec![t]
    }
}

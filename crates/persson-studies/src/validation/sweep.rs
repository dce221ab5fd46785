//! The resolution sweep (feature `bem`): one physical surface on several
//! grids, solved at every nominal pressure for every seed.
//!
//! # The resolution sweep
//! The physical surface is fixed: side `L = 2π/q_l`, spectrum `C(q)` on
//! `[q_l, q_s]`, one random realisation per seed. A grid of `N × N` nodes has
//! the pixel `L/N`; the grids are `N/2^(levels−1), …, N/2, N` (the finest is
//! `--grid`; [`super::resolution_grids`]). The surface is synthesised once on
//! the finest grid and the coarser grids take every `r`-th node
//! ([`persson::bem::resample::nested_surfaces`]). Because every mode of the
//! spectrum lies below the coarsest grid's Nyquist wavevector (enforced,
//! [`super::resolve_q_s`]), the coarse samples are the same band-limited
//! surface exactly, so `A(N)` converges for one realisation as the
//! discretisation refines; its continuum limit is [`Sweep::extrapolate`].
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005:
//! κ from the linear low-load regime, A(N) = A∞ + c N^{−α} with α ≈ 0.7,
//! Gaussian vs exponential pressure tails.

use super::resolution::SweepConfig;
use persson::bem::histogram::PressureCounts;
use persson::bem::resample::{band_limited_copies, coarsened, nested_surfaces};
use persson::bem::rough::{self, RoughOptions, RoughProgress};
use persson::bem::{self, Boundary, GridSurface, Iteration, Solution};
use persson::error::{check, Error, Result};
use persson::spectrum::Spectrum;

/// Progress of a sweep, reported once per solver iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SweepProgress {
    /// Solves finished so far.
    pub done: usize,
    /// Solves in total.
    pub total: usize,
    /// Grid of the current solve.
    pub grid: usize,
    /// Seed of the current solve.
    pub seed: u64,
    /// Nominal pressure of the current solve.
    pub nominal_pressure: f64,
    /// The solver's state.
    pub iteration: Iteration,
}

/// Results of one grid: per seed and pressure.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct GridResult {
    /// Grid side N.
    pub grid: usize,
    /// A/A0, `[seed][pressure]`.
    pub contact_fraction: Vec<Vec<f64>>,
    /// Mean gap ū = Σ gap / N² (unit of L), `[seed][pressure]`.
    pub mean_separation: Vec<Vec<f64>>,
    /// rms slope of each seed's surface (trigonometric interpolant).
    pub surface_rms_slope: Vec<f64>,
    /// With a yield stress: fraction of nodes with 0 < p < σY,
    /// `[seed][pressure]` (without: equal to `contact_fraction`).
    pub elastic_fraction: Vec<Vec<f64>>,
    /// With a yield stress: fraction of nodes at p = σY, `[seed][pressure]`
    /// (without: 0).
    pub plastic_fraction: Vec<Vec<f64>>,
    /// With a yield stress: mean plastic displacement over the nodes at σY
    /// (unit of L), `[seed][pressure]` (without: 0).
    pub plastic_displacement_mean: Vec<Vec<f64>>,
    /// CG iterations, all solves of this grid.
    pub iterations: usize,
    /// Largest final residual ε of this grid's solves.
    pub residual: f64,
    /// Wall-clock seconds of this grid's solves.
    pub seconds: f64,
    /// The solves the plain loop finished after the preconditioned one
    /// stalled (σ0 and the preconditioned iterations, by seed and pressure
    /// ascending); empty when none fell back.
    pub fallbacks: Vec<(f64, usize)>,
}

/// The resolution sweep: every grid, seed and pressure.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Sweep {
    /// Nominal pressures, in the caller's order.
    pub nominal_pressure: Vec<f64>,
    /// One entry per grid, ascending.
    pub grids: Vec<GridResult>,
    /// Contact-pressure counts of the finest grid, one per pressure,
    /// accumulated over seeds (with a yield stress: the nodes below σY only;
    /// the δ-peak at σY is the finest grid's `plastic_fraction`).
    pub histograms: Vec<PressureCounts>,
    /// The yield stress of the solves (`None`: elastic).
    pub yield_stress: Option<f64>,
}

/// Solve every pressure on every grid for every seed.
///
/// Pressures are solved in ascending order with the solver's warm start (if
/// `config.options.warm_start`), results returned in the caller's order.
///
/// # Errors
/// Pressures not finite and positive; no seed; as [`nested_surfaces`],
/// [`bem::check_memory`] and [`rough::solve`] (NotConverged).
pub fn sweep(
    spectrum: &dyn Spectrum,
    contact_modulus: f64,
    pressures: &[f64],
    config: &SweepConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Sweep> {
    sweep_source(
        SweepSource::Synthesised(spectrum),
        contact_modulus,
        pressures,
        config,
        progress,
    )
}

/// Where a sweep's surfaces come from.
#[derive(Clone, Copy)]
pub enum SweepSource<'a> {
    /// Synthesised from a spectrum, one periodic realisation per seed
    /// ([`nested_surfaces`]).
    Synthesised(&'a dyn Spectrum),
    /// A height map on the finest grid, one realisation (the first seed
    /// only), and its block-averaged copies on the coarser grids
    /// ([`coarsened`]), solved with the given boundary.
    Map(&'a GridSurface, Boundary),
    /// A periodic height map low-passed at `q_s` (1/unit of L) and sampled on
    /// every grid ([`band_limited_copies`]): one surface on every grid, as
    /// for [`SweepSource::Synthesised`]; the first seed only.
    BandLimitedMap(&'a GridSurface, f64),
}

/// [`sweep`] on the surfaces of `source`.
///
/// # Errors
/// As [`sweep`] and [`coarsened`].
pub fn sweep_source(
    source: SweepSource<'_>,
    contact_modulus: f64,
    pressures: &[f64],
    config: &SweepConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Sweep> {
    sweep_source_observed(source, contact_modulus, pressures, config, progress, None)
}

/// What a sweep hands each solution to: (grid index, seed index, pressure
/// index in the caller's order, the solution).
pub type SolutionHook<'a> = &'a mut dyn FnMut(usize, usize, usize, &Solution) -> Result<()>;

/// [`sweep_source`], handing every solution to `hook` as it arrives (the
/// patch statistics of `compare`, [`super::patches`]).
///
/// # Errors
/// As [`sweep_source`]; the hook's.
pub fn sweep_source_observed(
    source: SweepSource<'_>,
    contact_modulus: f64,
    pressures: &[f64],
    config: &SweepConfig,
    progress: &mut dyn FnMut(SweepProgress),
    mut hook: Option<SolutionHook<'_>>,
) -> Result<Sweep> {
    let (boundary, seeds) = source.boundary_and_seeds(&config.seeds);
    check_input(contact_modulus, pressures, seeds, config, boundary)?;
    let mut order: Vec<usize> = (0..pressures.len()).collect();
    order.sort_by(|&a, &b| pressures[a].total_cmp(&pressures[b]));
    let sorted: Vec<f64> = order.iter().map(|&k| pressures[k]).collect();
    let (ns, np) = (seeds.len(), pressures.len());
    let mut grids: Vec<GridResult> = config
        .grids
        .iter()
        .map(|&g| GridResult::zeros(g, ns, np))
        .collect();
    let mut histograms: Vec<PressureCounts> =
        pressures.iter().map(|&p| PressureCounts::new(p)).collect();
    let total = ns * np * config.grids.len();
    let options = RoughOptions {
        boundary,
        solver: config.options,
        bins: None,
        method: config.method,
    };
    let mut done = 0;
    for (si, &seed) in seeds.iter().enumerate() {
        let surfaces = source.surfaces(config, seed)?;
        for (gi, surf) in surfaces.iter().enumerate() {
            grids[gi].surface_rms_slope[si] = surf.rms_slope()?;
            let mut observer = SweepObserver {
                progress: &mut *progress,
                done,
                total,
                grid: surf.n,
                seed,
                order: &order,
                counts: (gi + 1 == surfaces.len()).then_some(&mut histograms),
                yield_stress: config.options.yield_stress,
                hook: hook.as_mut().map(|h| {
                    // Shorten the trait object's lifetime to this solve's borrow.
                    let h: SolutionHook<'_> = &mut **h;
                    (gi, si, h)
                }),
            };
            let points = rough::solve(surf, contact_modulus, &sorted, &options, &mut observer)?;
            done += points.len();
            grids[gi].record(si, &points, &order);
        }
    }
    Ok(Sweep {
        nominal_pressure: pressures.to_vec(),
        grids,
        histograms,
        yield_stress: config.options.yield_stress,
    })
}

/// One seed on one grid of a synthesised sweep: the same surface
/// ([`nested_surfaces`] of `seed` on all of `config.grids`, this grid's
/// copy), the same pressures in the same order and the same solver, so the
/// result is, number for number, row `seed` of grid `grid` in [`sweep`] of
/// the same `config` (its one seed row; `config.seeds` is not used). The
/// independent unit of an ensemble ([`super::ensemble()`]).
///
/// # Errors
/// `grid` not one of `config.grids`; as [`sweep`].
pub fn sweep_one(
    spectrum: &dyn Spectrum,
    contact_modulus: f64,
    pressures: &[f64],
    config: &SweepConfig,
    seed: u64,
    grid: usize,
) -> Result<GridResult> {
    check_input(
        contact_modulus,
        pressures,
        &[seed],
        config,
        Boundary::Periodic,
    )?;
    let gi = config
        .grids
        .iter()
        .position(|&g| g == grid)
        .ok_or_else(|| {
            Error::invalid(
                "grid",
                grid as f64,
                format!("one of the ensemble's grids {:?}", config.grids),
            )
        })?;
    let mut order: Vec<usize> = (0..pressures.len()).collect();
    order.sort_by(|&a, &b| pressures[a].total_cmp(&pressures[b]));
    let sorted: Vec<f64> = order.iter().map(|&k| pressures[k]).collect();
    let surfaces = nested_surfaces(spectrum, &config.grids, config.size, seed)?;
    let surf = &surfaces[gi];
    let mut result = GridResult::zeros(grid, 1, pressures.len());
    result.surface_rms_slope[0] = surf.rms_slope()?;
    let options = RoughOptions {
        boundary: Boundary::Periodic,
        solver: config.options,
        bins: None,
        method: config.method,
    };
    let mut observer = SweepObserver {
        progress: &mut |_| {},
        done: 0,
        total: pressures.len(),
        grid,
        seed,
        order: &order,
        counts: None,
        yield_stress: config.options.yield_stress,
        hook: None,
    };
    let points = rough::solve(surf, contact_modulus, &sorted, &options, &mut observer)?;
    result.record(0, &points, &order);
    Ok(result)
}

/// The inputs of a sweep: E* and every pressure finite and positive, a seed,
/// a grid, and memory for the finest grid's solve.
fn check_input(
    contact_modulus: f64,
    pressures: &[f64],
    seeds: &[u64],
    config: &SweepConfig,
    boundary: Boundary,
) -> Result<()> {
    check::positive("contact_modulus", contact_modulus)?;
    if pressures.is_empty() {
        return Err(Error::invalid("nominal_pressure", 0.0, "at least one"));
    }
    for &p in pressures {
        check::positive("nominal_pressure", p)?;
    }
    if seeds.is_empty() {
        return Err(Error::invalid("seeds", 0.0, ">= 1"));
    }
    let finest = *config
        .grids
        .last()
        .ok_or_else(|| Error::invalid("grids", 0.0, "at least one grid"))?;
    bem::check_memory(finest, boundary)
}

impl SweepSource<'_> {
    /// The boundary of the solves and the seeds used (a map is one
    /// realisation: the first seed only).
    fn boundary_and_seeds<'s>(&self, seeds: &'s [u64]) -> (Boundary, &'s [u64]) {
        match *self {
            SweepSource::Synthesised(_) => (Boundary::Periodic, seeds),
            SweepSource::BandLimitedMap(..) => {
                (Boundary::Periodic, seeds.get(..1).unwrap_or_default())
            }
            SweepSource::Map(_, b) => (b, seeds.get(..1).unwrap_or_default()),
        }
    }

    /// The surface of `seed` on every grid of `config`.
    fn surfaces(&self, config: &SweepConfig, seed: u64) -> Result<Vec<GridSurface>> {
        match *self {
            SweepSource::Synthesised(spectrum) => {
                nested_surfaces(spectrum, &config.grids, config.size, seed)
            }
            SweepSource::Map(map, _) => coarsened(map, &config.grids),
            SweepSource::BandLimitedMap(map, q_s) => band_limited_copies(map, q_s, &config.grids),
        }
    }
}

impl GridResult {
    /// A grid's results before its solves: `ns` seeds × `np` pressures of zeros.
    fn zeros(grid: usize, ns: usize, np: usize) -> Self {
        GridResult {
            grid,
            contact_fraction: vec![vec![0.0; np]; ns],
            mean_separation: vec![vec![0.0; np]; ns],
            surface_rms_slope: vec![0.0; ns],
            elastic_fraction: vec![vec![0.0; np]; ns],
            plastic_fraction: vec![vec![0.0; np]; ns],
            plastic_displacement_mean: vec![vec![0.0; np]; ns],
            iterations: 0,
            residual: 0.0,
            seconds: 0.0,
            fallbacks: Vec::new(),
        }
    }

    /// The solves of seed `si` (pressures ascending; `order[i]` the caller's
    /// index of the i-th) in the caller's order.
    fn record(&mut self, si: usize, points: &[rough::RoughPoint], order: &[usize]) {
        for (pt, &k) in points.iter().zip(order) {
            self.contact_fraction[si][k] = pt.contact_fraction;
            self.mean_separation[si][k] = pt.mean_separation;
            self.elastic_fraction[si][k] = pt.elastic_fraction.unwrap_or(pt.contact_fraction);
            self.plastic_fraction[si][k] = pt.plastic_fraction.unwrap_or(0.0);
            self.plastic_displacement_mean[si][k] = pt.plastic_displacement_mean.unwrap_or(0.0);
            self.iterations += pt.iterations;
            self.residual = self.residual.max(pt.residual);
            self.seconds += pt.seconds;
            if let Some(f) = pt.fallback {
                self.fallbacks.push((pt.nominal_pressure, f.iterations));
            }
        }
    }
}

/// Progress and the finest grid's histograms, seen from [`rough::solve`].
struct SweepObserver<'a> {
    progress: &'a mut dyn FnMut(SweepProgress),
    done: usize,
    total: usize,
    grid: usize,
    seed: u64,
    order: &'a [usize],
    counts: Option<&'a mut Vec<PressureCounts>>,
    yield_stress: Option<f64>,
    /// The caller's hook with this grid's and seed's indices.
    hook: Option<(usize, usize, SolutionHook<'a>)>,
}

impl rough::Observer for SweepObserver<'_> {
    fn iteration(&mut self, p: RoughProgress) {
        (self.progress)(SweepProgress {
            done: self.done + p.index,
            total: self.total,
            grid: self.grid,
            seed: self.seed,
            nominal_pressure: p.nominal_pressure,
            iteration: p.iteration,
        });
    }

    fn solution(&mut self, index: usize, solution: &Solution) -> Result<()> {
        if let Some((gi, si, hook)) = self.hook.as_mut() {
            hook(*gi, *si, self.order[index], solution)?;
        }
        if let Some(h) = self.counts.as_deref_mut() {
            match self.yield_stress {
                // The nodes at σY are the δ-peak, counted apart (plastic_fraction).
                Some(y) => {
                    let below: Vec<f64> = solution
                        .pressure
                        .iter()
                        .map(|&p| if p >= y { 0.0 } else { p })
                        .collect();
                    h[self.order[index]].add(&below);
                }
                None => h[self.order[index]].add(&solution.pressure),
            }
        }
        Ok(())
    }
}

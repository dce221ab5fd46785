//! Theory against the FFT-BEM at several resolutions of one physical surface
//! (feature `bem`): nested surfaces, the resolution sweep, its continuum
//! extrapolation, κ from the low-load regime and pressure histograms.
//!
//! # The resolution sweep
//! The physical surface is fixed: side `L = 2π/q_l`, spectrum `C(q)` on
//! `[q_l, q_s]`, one random realisation per seed. A grid of `N × N` nodes has
//! the pixel `L/N`; the grids are `N/2^(levels−1), …, N/2, N` (the finest is
//! `--grid`). The surface is synthesised once on the finest grid
//! ([`crate::bem::surface::synthesize`]) and the coarser grids take every
//! `r`-th node. Because every mode of the spectrum lies below the coarsest
//! grid's Nyquist wavevector (enforced, see below), the coarse samples are the
//! same band-limited surface exactly (its trigonometric interpolant is
//! identical, tested through the rms slope), so `A(N)` converges for one
//! realisation as the discretisation refines.
//!
//! # Resolution of q_s
//! The shortest wavelength `2π/q_s` must span at least `p` pixels of the
//! coarsest grid (default [`DEFAULT_PIXELS_PER_WAVELENGTH`] = 4):
//! ```text
//! q_s ≤ q_s,max = N_coarsest q_l / p
//! ```
//! A larger q_s is **clipped** to q_s,max ([`BandLimited`]): the theories are
//! then evaluated for the clipped spectrum too, so that theory and BEM see the
//! same surface; the CLI says so on stderr and in its JSON.
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007) (seed 002): κ from the linear
//! low-load regime, A(N) = A∞ + c N^{−α} with α ≈ 0.7, Gaussian vs exponential
//! pressure tails.

use crate::bem::{self, surface, Boundary, Control, Iteration, Operator, Options, Solver, Surface};
use crate::compare::{extrapolate, fit_kappa, Extrapolation};
use crate::error::{check, Error, Result};
use crate::quad::Estimate;
use crate::spectrum::Spectrum;

/// Pixels per shortest wavelength 2π/q_s required on the coarsest grid.
pub const DEFAULT_PIXELS_PER_WAVELENGTH: f64 = 4.0;

/// Number of grids of the default sweep (N/4, N/2, N).
pub const DEFAULT_LEVELS: usize = 3;

/// Fine histogram bins per nominal pressure σ0 (rebinned to the requested
/// number of bins at the end, on edges that are multiples of σ0/200).
const FINE_BINS_PER_SIGMA0: f64 = 200.0;

/// The grids of a sweep: `finest/2^(levels−1), …, finest`.
///
/// # Errors
/// `levels < 2`; `finest` not divisible by `2^(levels−1)`; the coarsest grid
/// below [`bem::MIN_GRID`] or the finest above [`bem::MAX_GRID`].
pub fn resolution_grids(finest: usize, levels: usize) -> Result<Vec<usize>> {
    bem::check_grid(finest)?;
    if !(2..=12).contains(&levels) {
        return Err(Error::invalid("levels", levels as f64, "from 2 to 12"));
    }
    let step = 1usize << (levels - 1);
    if !finest.is_multiple_of(step) || finest / step < bem::MIN_GRID {
        return Err(Error::invalid(
            "grid",
            finest as f64,
            format!(
                "a multiple of {step} with grid/{step} >= {} (the {levels} grids halve the finest)",
                bem::MIN_GRID
            ),
        ));
    }
    Ok((0..levels).rev().map(|k| finest >> k).collect())
}

/// The largest q_s the coarsest grid resolves with `pixels` pixels per
/// shortest wavelength.
///
/// # Formula
/// ```text
/// q_s,max = N_coarsest q_l / p        (pixel L/N, L = 2π/q_l)
/// ```
pub fn resolvable_q_max(q_l: f64, coarsest: usize, pixels: f64) -> f64 {
    coarsest as f64 * q_l / pixels
}

/// A spectrum cut off at `q_max` (C = 0 above), zero outside the inner band.
#[derive(Clone, Copy)]
pub struct BandLimited<'a> {
    inner: &'a dyn Spectrum,
    q_max: f64,
}

impl<'a> BandLimited<'a> {
    /// `inner` cut at `min(q_max, inner.q_max())`.
    ///
    /// # Errors
    /// `q_max` not above `inner.q_min()`.
    pub fn new(inner: &'a dyn Spectrum, q_max: f64) -> Result<Self> {
        if !(q_max.is_finite() && q_max > inner.q_min()) {
            return Err(Error::invalid(
                "q_s",
                q_max,
                format!("above q_l = {:e}", inner.q_min()),
            ));
        }
        Ok(BandLimited {
            inner,
            q_max: q_max.min(inner.q_max()),
        })
    }

    /// Whether the cut removed part of the inner spectrum.
    pub fn clipped(&self) -> bool {
        self.q_max < self.inner.q_max()
    }
}

impl std::fmt::Debug for BandLimited<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BandLimited")
            .field("q_min", &self.inner.q_min())
            .field("q_max", &self.q_max)
            .finish()
    }
}

impl Spectrum for BandLimited<'_> {
    fn c(&self, q: f64) -> f64 {
        if q > self.q_max {
            0.0
        } else {
            self.inner.c(q)
        }
    }
    fn q_min(&self) -> f64 {
        self.inner.q_min()
    }
    fn q_max(&self) -> f64 {
        self.q_max
    }
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        self.inner.moment(k, a, b.min(self.q_max))
    }
}

/// One realisation on every grid of `grids` (ascending, each dividing the
/// finest): synthesised on the finest grid, subsampled on the others.
///
/// # Formula
/// ```text
/// h_N′(i, j) = h_N(r i, r j),  r = N/N′   (exact when all modes |k| < N′/2)
/// ```
///
/// # Errors
/// Grids not ascending powers-of-two fractions of the finest; the spectrum
/// has modes at or above the coarsest grid's Nyquist wavevector
/// (`q_max L/2π + 1 ≥ N′/2`: the cell-averaged synthesis touches the mode
/// next to q_max); as [`surface::synthesize`].
pub fn nested_surfaces(
    spectrum: &dyn Spectrum,
    grids: &[usize],
    size: f64,
    seed: u64,
) -> Result<Vec<Surface>> {
    check::positive("size", size)?;
    let (&coarsest, &finest) = match (grids.first(), grids.last()) {
        (Some(a), Some(b)) => (a, b),
        _ => return Err(Error::invalid("grids", 0.0, "at least one grid")),
    };
    for w in grids.windows(2) {
        if !(w[0] < w[1] && w[1].is_multiple_of(w[0])) {
            return Err(Error::Inconsistent {
                name: "grids".into(),
                requirement: format!("ascending, each dividing the next (got {grids:?})"),
            });
        }
    }
    let k_max = spectrum.q_max() * size / std::f64::consts::TAU;
    if k_max + 1.0 >= coarsest as f64 / 2.0 {
        return Err(Error::invalid(
            "q_s",
            spectrum.q_max(),
            format!(
                "below the coarsest grid's Nyquist wavevector: q_s L/2π + 1 < {coarsest}/2 (L = {size:e})"
            ),
        ));
    }
    let fine = surface::synthesize(spectrum, finest, size, seed)?;
    grids
        .iter()
        .map(|&n| {
            let r = finest / n;
            let heights = (0..n * n)
                .map(|k| fine.heights[(k / n) * r * finest + (k % n) * r])
                .collect();
            Surface::new(n, size, heights)
        })
        .collect()
}

/// Counts of contact pressures in fine bins of width σ0/200, accumulated over
/// seeds; rebinned by [`Histogram::density`].
#[derive(Debug, Clone, PartialEq)]
pub struct Histogram {
    /// Fine bin width.
    pub width: f64,
    /// Counts per fine bin (p > 0 only).
    pub counts: Vec<u64>,
    /// Nodes seen (contact or not), over all seeds.
    pub nodes: u64,
}

impl Histogram {
    /// An empty histogram for nominal pressure `sigma0`.
    pub fn new(sigma0: f64) -> Self {
        Histogram {
            width: sigma0 / FINE_BINS_PER_SIGMA0,
            counts: Vec::new(),
            nodes: 0,
        }
    }

    /// Add a pressure field.
    pub fn add(&mut self, pressure: &[f64]) {
        self.nodes += pressure.len() as u64;
        for &p in pressure.iter().filter(|p| **p > 0.0 && p.is_finite()) {
            let k = (p / self.width) as usize;
            if k >= self.counts.len() {
                self.counts.resize(k + 1, 0);
            }
            self.counts[k] += 1;
        }
    }

    /// `bins` equal bins from 0 past the largest pressure (edges on the fine
    /// grid): `(lower edges, upper edges, density)`.
    ///
    /// # Formula
    /// ```text
    /// P_k = #{p ∈ bin k, p > 0} / (nodes Δσ),   Σ_k P_k Δσ = A/A0 (mean over seeds)
    /// ```
    pub fn density(&self, bins: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        if bins == 0 || self.counts.is_empty() || self.nodes == 0 {
            return (Vec::new(), Vec::new(), Vec::new());
        }
        let per = self.counts.len().div_ceil(bins).max(1);
        let width = per as f64 * self.width;
        let norm = 1.0 / (self.nodes as f64 * width);
        let mut lo = Vec::with_capacity(bins);
        let mut hi = Vec::with_capacity(bins);
        let mut d = Vec::with_capacity(bins);
        for k in 0..bins {
            let c: u64 = self.counts.iter().skip(k * per).take(per).sum();
            lo.push(k as f64 * width);
            hi.push((k + 1) as f64 * width);
            d.push(c as f64 * norm);
        }
        (lo, hi, d)
    }
}

/// What the sweep solves and how.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepConfig {
    /// Grids, ascending ([`resolution_grids`]).
    pub grids: Vec<usize>,
    /// Seeds of the realisations.
    pub seeds: Vec<u64>,
    /// Solver accuracy (warm start is used across pressures when set).
    pub options: Options,
    /// Side L of the surface (unit of 1/q).
    pub size: f64,
}

/// Progress of a sweep, reported once per solver iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
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
    pub pressure: f64,
    /// The solver's state.
    pub iteration: Iteration,
}

/// Results of one grid: per seed and pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct GridResult {
    /// Grid side N.
    pub grid: usize,
    /// A/A0, `[seed][pressure]`.
    pub contact_fraction: Vec<Vec<f64>>,
    /// Mean gap ū = Σ gap / N² (unit of L), `[seed][pressure]`.
    pub mean_gap: Vec<Vec<f64>>,
    /// rms slope of each seed's surface (trigonometric interpolant).
    pub surface_rms_slope: Vec<f64>,
    /// CG iterations, all solves of this grid.
    pub iterations: usize,
    /// Largest final residual ε of this grid's solves.
    pub residual: f64,
    /// Wall-clock seconds of this grid's solves.
    pub seconds: f64,
}

/// The resolution sweep: every grid, seed and pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// Nominal pressures, in the caller's order.
    pub pressures: Vec<f64>,
    /// One entry per grid, ascending.
    pub grids: Vec<GridResult>,
    /// Contact-pressure histograms of the finest grid, one per pressure,
    /// accumulated over seeds.
    pub histograms: Vec<Histogram>,
}

/// Solve every pressure on every grid for every seed.
///
/// Pressures are solved in ascending order with the solver's warm start (if
/// `config.options.warm_start`), results returned in the caller's order.
///
/// # Errors
/// Pressures not finite and positive; no seed; as [`nested_surfaces`],
/// [`bem::check_memory`] and [`Solver::solve`] (NotConverged).
pub fn sweep(
    spectrum: &dyn Spectrum,
    contact_modulus: f64,
    pressures: &[f64],
    config: &SweepConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Sweep> {
    check::positive("contact_modulus", contact_modulus)?;
    if pressures.is_empty() {
        return Err(Error::invalid("pressures", 0.0, "at least one"));
    }
    for &p in pressures {
        check::positive("pressure", p)?;
    }
    if config.seeds.is_empty() {
        return Err(Error::invalid("seeds", 0.0, ">= 1"));
    }
    let finest = *config
        .grids
        .last()
        .ok_or_else(|| Error::invalid("grids", 0.0, "at least one grid"))?;
    bem::check_memory(finest, Boundary::Periodic)?;
    let mut order: Vec<usize> = (0..pressures.len()).collect();
    order.sort_by(|&a, &b| pressures[a].total_cmp(&pressures[b]));
    let ns = config.seeds.len();
    let np = pressures.len();
    let mut grids: Vec<GridResult> = config
        .grids
        .iter()
        .map(|&g| GridResult {
            grid: g,
            contact_fraction: vec![vec![0.0; np]; ns],
            mean_gap: vec![vec![0.0; np]; ns],
            surface_rms_slope: vec![0.0; ns],
            iterations: 0,
            residual: 0.0,
            seconds: 0.0,
        })
        .collect();
    let mut histograms: Vec<Histogram> = pressures.iter().map(|&p| Histogram::new(p)).collect();
    let total = ns * np * config.grids.len();
    let mut done = 0;
    for (si, &seed) in config.seeds.iter().enumerate() {
        let surfaces = nested_surfaces(spectrum, &config.grids, config.size, seed)?;
        for (gi, surf) in surfaces.iter().enumerate() {
            let op = Operator::new(Boundary::Periodic, surf.n, surf.size, contact_modulus)?;
            let mut solver = Solver::new(op);
            let finest_grid = gi + 1 == surfaces.len();
            grids[gi].surface_rms_slope[si] = surf.rms_slope()?;
            for &k in &order {
                let p = pressures[k];
                let sol = solver.solve_observed(
                    &surf.heights,
                    Control::MeanPressure(p),
                    &config.options,
                    &mut |it| {
                        progress(SweepProgress {
                            done,
                            total,
                            grid: surf.n,
                            seed,
                            pressure: p,
                            iteration: it,
                        })
                    },
                )?;
                done += 1;
                let g = &mut grids[gi];
                g.contact_fraction[si][k] = sol.contact_fraction;
                g.mean_gap[si][k] = sol.gap.iter().sum::<f64>() / sol.gap.len() as f64;
                g.iterations += sol.iterations;
                g.residual = g.residual.max(sol.residual);
                g.seconds += sol.seconds;
                if finest_grid {
                    histograms[k].add(&sol.pressure);
                }
            }
        }
    }
    Ok(Sweep {
        pressures: pressures.to_vec(),
        grids,
        histograms,
    })
}

/// Mean and standard error of the mean (0 for a single value).
///
/// # Formula
/// ```text
/// x̄ = Σx/K,   se = sqrt(Σ(x − x̄)² / (K (K − 1)))
/// ```
pub fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let k = values.len();
    if k == 0 {
        return (f64::NAN, f64::NAN);
    }
    let m = values.iter().sum::<f64>() / k as f64;
    if k == 1 {
        return (m, 0.0);
    }
    let ss: f64 = values.iter().map(|v| (v - m).powi(2)).sum();
    (m, (ss / (k * (k - 1)) as f64).sqrt())
}

/// The continuum limit at one pressure, from the seed-averaged A(N).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Continuum {
    /// The fit of the seed-averaged A(N) ([`extrapolate`]).
    pub fit: Extrapolation,
    /// Standard error of A∞ over seeds (each seed extrapolated alone; 0 for one seed).
    pub seed_scatter: f64,
    /// Combined uncertainty `sqrt(fit.uncertainty² + seed_scatter²)`.
    pub uncertainty: f64,
}

impl Sweep {
    /// Seed-averaged A/A0 and its standard error over seeds, per grid: `[grid][pressure]`.
    pub fn mean_contact_fraction(&self) -> Vec<(Vec<f64>, Vec<f64>)> {
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.contact_fraction, self.pressures.len()))
            .collect()
    }

    /// Seed-averaged mean gap and its standard error, per grid.
    pub fn mean_gap(&self) -> Vec<(Vec<f64>, Vec<f64>)> {
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.mean_gap, self.pressures.len()))
            .collect()
    }

    /// A(N) of one seed at one pressure, over the grids.
    fn seed_curve(&self, seed: usize, k: usize) -> Vec<f64> {
        self.grids
            .iter()
            .map(|g| g.contact_fraction[seed][k])
            .collect()
    }

    /// The continuum limit at each pressure (see [`Continuum`]).
    ///
    /// # Errors
    /// Fewer than two grids; as [`extrapolate`].
    pub fn extrapolate(&self, alpha: Option<f64>) -> Result<Vec<Continuum>> {
        let n: Vec<f64> = self.grids.iter().map(|g| g.grid as f64).collect();
        let means = self.mean_contact_fraction();
        let seeds = self.grids.first().map_or(0, |g| g.contact_fraction.len());
        (0..self.pressures.len())
            .map(|k| {
                let a: Vec<f64> = means.iter().map(|m| m.0[k]).collect();
                let fit = extrapolate(&n, &a, alpha)?;
                let per_seed: Vec<f64> = (0..seeds)
                    .map(|s| {
                        extrapolate(&n, &self.seed_curve(s, k), Some(fit.alpha)).map(|e| e.value)
                    })
                    .collect::<Result<_>>()?;
                let seed_scatter = mean_and_error(&per_seed).1;
                Ok(Continuum {
                    fit,
                    seed_scatter,
                    uncertainty: fit.uncertainty.hypot(seed_scatter),
                })
            })
            .collect()
    }

    /// κ from the low-load regime (A/A0 < `max_fraction`) of each grid and of
    /// the continuum limit, fitted per seed and averaged.
    ///
    /// # Formula
    /// ```text
    /// κ_s = fit_kappa(σ0, A_s(σ0)),   κ = mean_s κ_s,   se = sqrt(se_fit² + se_seeds²)
    /// ```
    /// with `rms_slope` the spectrum's full-band rms slope (what the grids
    /// resolve), `se_fit` the fit's standard error of the seed-averaged curve.
    ///
    /// # Errors
    /// No point below `max_fraction` on some curve; as [`Sweep::extrapolate`].
    pub fn kappa(
        &self,
        contact_modulus: f64,
        rms_slope: f64,
        max_fraction: f64,
        alpha: Option<f64>,
    ) -> Result<SweepKappa> {
        let seeds = self.grids.first().map_or(0, |g| g.contact_fraction.len());
        let fit_of = |curves: &[Vec<f64>], mean: &[f64]| -> Result<KappaEstimate> {
            let avg = fit_kappa(
                &self.pressures,
                mean,
                contact_modulus,
                rms_slope,
                max_fraction,
            )?;
            let per: Vec<f64> = curves
                .iter()
                .map(|c| {
                    fit_kappa(&self.pressures, c, contact_modulus, rms_slope, max_fraction)
                        .map(|f| f.kappa)
                })
                .collect::<Result<_>>()?;
            let (m, se) = mean_and_error(&per);
            Ok(KappaEstimate {
                kappa: m,
                standard_error: avg.standard_error.hypot(se),
                seed_scatter: se,
                pressure_range: avg.pressure_range,
                points: avg.points,
            })
        };
        let means = self.mean_contact_fraction();
        let mut per_grid = Vec::new();
        for (g, m) in self.grids.iter().zip(&means) {
            per_grid.push((g.grid, fit_of(&g.contact_fraction, &m.0)?));
        }
        let n: Vec<f64> = self.grids.iter().map(|g| g.grid as f64).collect();
        let cont = self.extrapolate(alpha)?;
        let mean_inf: Vec<f64> = cont.iter().map(|c| c.fit.value).collect();
        let per_seed_inf: Vec<Vec<f64>> = (0..seeds)
            .map(|s| {
                (0..self.pressures.len())
                    .map(|k| {
                        extrapolate(&n, &self.seed_curve(s, k), Some(cont[k].fit.alpha))
                            .map(|e| e.value)
                    })
                    .collect::<Result<Vec<f64>>>()
            })
            .collect::<Result<_>>()?;
        let extrapolated = fit_of(&per_seed_inf, &mean_inf)?;
        Ok(SweepKappa {
            per_grid,
            extrapolated,
        })
    }
}

fn per_pressure_mean(v: &[Vec<f64>], np: usize) -> (Vec<f64>, Vec<f64>) {
    (0..np)
        .map(|k| mean_and_error(&v.iter().map(|s| s[k]).collect::<Vec<_>>()))
        .unzip()
}

/// κ with its uncertainty from a sweep.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct KappaEstimate {
    /// κ, mean over seeds.
    pub kappa: f64,
    /// Combined standard error (fit and seeds).
    pub standard_error: f64,
    /// Standard error over seeds alone (0 for one seed).
    pub seed_scatter: f64,
    /// Lowest and highest nominal pressure used (seed-averaged curve).
    pub pressure_range: (f64, f64),
    /// Points used (seed-averaged curve).
    pub points: usize,
}

/// κ of every grid and of the continuum limit.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SweepKappa {
    /// `(grid, κ)` per grid, ascending.
    pub per_grid: Vec<(usize, KappaEstimate)>,
    /// κ of the extrapolated curve.
    pub extrapolated: KappaEstimate,
}

/// Log–log interpolation of `y(x)` at `at` (x ascending after sorting);
/// `None` outside `[min x, max x]` or where y ≤ 0.
pub fn interpolate_log(x: &[f64], y: &[f64], at: f64) -> Option<f64> {
    let mut pts: Vec<(f64, f64)> = x.iter().copied().zip(y.iter().copied()).collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    for w in pts.windows(2) {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        if (x0..=x1).contains(&at) {
            if x0 == x1 || at == x0 {
                return (y0 > 0.0).then_some(y0);
            }
            if y0 <= 0.0 || y1 <= 0.0 || x0 <= 0.0 {
                return None;
            }
            let t = (at / x0).ln() / (x1 / x0).ln();
            return Some(y0 * (y1 / y0).powf(t));
        }
    }
    match pts.as_slice() {
        [(x0, y0)] if *x0 == at => Some(*y0),
        _ => None,
    }
}

/// Default nominal pressures: `count` pressures, log-spaced, whose
/// linear-law contact fraction with κ = 2 runs from `a_lo` to `a_hi`.
///
/// # Formula
/// ```text
/// σ0,k = E* s A_k / 2,   A_k = a_lo (a_hi/a_lo)^{k/(count−1)}
/// ```
pub fn default_pressures(
    contact_modulus: f64,
    rms_slope: f64,
    count: usize,
    a_lo: f64,
    a_hi: f64,
) -> Vec<f64> {
    let count = count.max(1);
    (0..count)
        .map(|k| {
            let t = if count == 1 {
                0.0
            } else {
                k as f64 / (count - 1) as f64
            };
            contact_modulus * rms_slope * a_lo * (a_hi / a_lo).powf(t) / 2.0
        })
        .collect()
}

//! The resolution sweep (feature `bem`): one physical surface on several
//! grids, solved at every nominal pressure for every seed, and its continuum
//! limit.
//!
//! # The resolution sweep
//! The physical surface is fixed: side `L = 2π/q_l`, spectrum `C(q)` on
//! `[q_l, q_s]`, one random realisation per seed. A grid of `N × N` nodes has
//! the pixel `L/N`; the grids are `N/2^(levels−1), …, N/2, N` (the finest is
//! `--grid`). The surface is synthesised once on the finest grid
//! ([`persson::bem::surface::synthesize`]) and the coarser grids take every
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
//! A larger q_s is **clipped** to q_s,max ([`resolve_q_s`], [`BandLimited`]):
//! the theories are then evaluated for the clipped spectrum too, so that
//! theory and BEM see the same surface; the report says so.
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005:
//! κ from the linear low-load regime, A(N) = A∞ + c N^{−α} with α ≈ 0.7,
//! Gaussian vs exponential pressure tails.

use serde::Serialize;

use super::continuum::{extrapolate, mean_and_error, Extrapolation};
use persson::bem::histogram::PressureCounts;
use persson::bem::rough::{self, RoughOptions, RoughProgress};
use persson::bem::{self, surface, Boundary, Iteration, Options, Solution, Surface};
use persson::error::{check, Error, Result};
use persson::spectrum::Spectrum;
use persson::Estimate;

/// Pixels per shortest wavelength 2π/q_s required on the coarsest grid.
pub const DEFAULT_PIXELS_PER_WAVELENGTH: f64 = 4.0;

/// Number of grids of the default sweep (N/4, N/2, N).
pub const DEFAULT_LEVELS: usize = 3;

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

/// The q_s a sweep uses: the requested one, clipped to what the coarsest
/// grid resolves ([`resolvable_q_max`]); the one rule of `persson compare`
/// and `persson compare kappa`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ResolvedBand {
    /// q_s used by the BEM and the theories.
    pub q_s: f64,
    /// q_s asked for (`None`: none asked, the resolvable maximum is used).
    pub q_s_requested: Option<f64>,
    /// Whether the requested q_s was above the resolvable maximum.
    pub clipped: bool,
}

/// The q_s of a sweep on grids whose coarsest is `coarsest` (see [`ResolvedBand`]).
///
/// # Formula
/// ```text
/// q_s = min(q_s,requested, N_coarsest q_l / p)
/// ```
///
/// # Errors
/// Non-positive `q_l` or `pixels_per_wavelength`.
pub fn resolve_q_s(
    q_l: f64,
    requested: Option<f64>,
    coarsest: usize,
    pixels_per_wavelength: f64,
) -> Result<ResolvedBand> {
    check::positive("q_l", q_l)?;
    check::positive("pixels_per_wavelength", pixels_per_wavelength)?;
    let q_max = resolvable_q_max(q_l, coarsest, pixels_per_wavelength);
    Ok(match requested {
        Some(q) if q > q_max => ResolvedBand {
            q_s: q_max,
            q_s_requested: Some(q),
            clipped: true,
        },
        Some(q) => ResolvedBand {
            q_s: q,
            q_s_requested: Some(q),
            clipped: false,
        },
        None => ResolvedBand {
            q_s: q_max,
            q_s_requested: None,
            clipped: false,
        },
    })
}

/// The BEM side of a comparison, as the user sets it.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepSettings {
    /// Finest grid side N.
    pub grid: usize,
    /// Number of grids, each half the next ([`resolution_grids`]).
    pub levels: usize,
    /// Seeds of the realisations.
    pub seeds: Vec<u64>,
    /// Exponent α of A(N) = A∞ + c N^−α; `None`: fitted from three grids.
    pub alpha: Option<f64>,
    /// Pixels of the coarsest grid per shortest wavelength ([`resolve_q_s`]).
    pub pixels_per_wavelength: f64,
    /// Solver accuracy (warm start across pressures when set).
    pub options: Options,
}

impl Default for SweepSettings {
    /// 256², three levels, seed 1, α = 0.7, 4 pixels per wavelength,
    /// tolerance 1e-10 with warm start.
    fn default() -> Self {
        SweepSettings {
            grid: 256,
            levels: DEFAULT_LEVELS,
            seeds: vec![1],
            alpha: Some(super::DEFAULT_ALPHA),
            pixels_per_wavelength: DEFAULT_PIXELS_PER_WAVELENGTH,
            options: Options {
                warm_start: true,
                ..Options::default()
            },
        }
    }
}

impl SweepSettings {
    /// The grids, ascending.
    ///
    /// # Errors
    /// As [`resolution_grids`].
    pub fn grids(&self) -> Result<Vec<usize>> {
        resolution_grids(self.grid, self.levels)
    }

    /// The q_s the sweep uses for a spectrum from `q_l` up to `requested`.
    ///
    /// # Errors
    /// As [`resolution_grids`] and [`resolve_q_s`].
    pub fn band(&self, q_l: f64, requested: Option<f64>) -> Result<ResolvedBand> {
        let grids = self.grids()?;
        resolve_q_s(q_l, requested, grids[0], self.pixels_per_wavelength)
    }

    /// The q_s of a sweep on a periodic `n × n` map (its grids `n/2^(levels−1)
    /// … n`) whose spectrum runs from `q_l` up to `q_max`: the same rule as
    /// [`SweepSettings::band`], with the map's grid as the finest.
    ///
    /// # Errors
    /// As [`resolution_grids`] and [`resolve_q_s`].
    pub fn map_band(&self, q_l: f64, q_max: f64, n: usize) -> Result<ResolvedBand> {
        let grids = resolution_grids(n, self.levels)?;
        resolve_q_s(q_l, Some(q_max), grids[0], self.pixels_per_wavelength)
    }

    /// The sweep's configuration for a surface of lower cut-off `q_l`
    /// (side L = 2π/q_l).
    ///
    /// # Errors
    /// No seed; a tolerance outside [1e-15, 0.1]; as [`resolution_grids`].
    pub fn config(&self, q_l: f64) -> Result<SweepConfig> {
        check::positive("q_l", q_l)?;
        check::tolerance("tolerance", self.options.tolerance)?;
        if let Some(a) = self.alpha {
            check::positive("alpha", a)?;
        }
        if self.seeds.is_empty() {
            return Err(Error::invalid("seeds", 0.0, ">= 1"));
        }
        Ok(SweepConfig {
            grids: self.grids()?,
            seeds: self.seeds.clone(),
            options: self.options,
            size: std::f64::consts::TAU / q_l,
        })
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
    Map(&'a Surface, Boundary),
    /// A periodic height map low-passed at `q_s` (1/unit of L) and sampled on
    /// every grid ([`band_limited_copies`]): one surface on every grid, as
    /// for [`SweepSource::Synthesised`]; the first seed only.
    BandLimitedMap(&'a Surface, f64),
}

/// A periodic map low-passed in Fourier space: every mode with
/// `|q| > q_s` removed (a circular cut, `q = 2π k/L`), the mean kept.
///
/// # Formula
/// ```text
/// h̃(x) = Σ_{|q| ≤ q_s} ĥ_q e^{iq·x},   ĥ_q = N⁻² Σ_x h(x) e^{−iq·x}
/// ```
///
/// # Errors
/// `q_s` not positive; internal FFT errors.
pub fn band_limited_map(map: &Surface, q_s: f64) -> Result<Surface> {
    check::positive("q_s", q_s)?;
    let n = map.n;
    let k_max = q_s * map.size / std::f64::consts::TAU;
    let k2_max = k_max * k_max * (1.0 + 1e-12);
    let mut fft = persson::bem::fft::Fft2::new(n, n)?;
    let mut x = map.heights.clone();
    let mut spec = vec![persson::bem::fft::Complex64::new(0.0, 0.0); fft.spectrum_len()];
    fft.forward(&mut x, &mut spec)?;
    let scale = 1.0 / (n * n) as f64;
    for kj in 0..fft.nc() {
        for ki in 0..n {
            let kx = if ki <= n / 2 {
                ki as f64
            } else {
                ki as f64 - n as f64
            };
            let k2 = kx * kx + (kj * kj) as f64;
            let z = &mut spec[kj * n + ki];
            *z = if k2 <= k2_max { *z * scale } else { 0.0.into() };
        }
    }
    let mut heights = vec![0.0; n * n];
    fft.inverse(&mut spec, &mut heights)?;
    Surface::new(n, map.size, heights)
}

/// A periodic map low-passed at `q_s` ([`band_limited_map`]) and sampled on
/// every grid of `grids` (ascending, each dividing the next, the finest the
/// map's): the band-limited map on its own grid, every `r`-th node of it on
/// the coarser ones. Every mode lies below the coarsest grid's Nyquist
/// wavevector (enforced), so each copy is the same continuous surface: its
/// trigonometric interpolant is the band-limited map's (the coarse samples
/// equal the Fourier-truncated resampling).
///
/// # Errors
/// Grids as for [`coarsened`]; modes at or above the coarsest grid's Nyquist
/// wavevector (`⌊q_s L/2π⌋ ≥ N_coarsest/2`: fewer than 2 pixels per
/// wavelength); as [`band_limited_map`].
pub fn band_limited_copies(map: &Surface, q_s: f64, grids: &[usize]) -> Result<Vec<Surface>> {
    check_map_grids(map, grids)?;
    let coarsest = grids[0];
    let k_max = q_s * map.size / std::f64::consts::TAU;
    if (k_max * (1.0 + 1e-12)).floor() >= (coarsest / 2) as f64 {
        return Err(Error::invalid(
            "q_s",
            q_s,
            format!(
                "below the coarsest grid's Nyquist wavevector: q_s L/2π < {coarsest}/2 (L = {:e}; more than 2 pixels per wavelength)",
                map.size
            ),
        ));
    }
    let fine = band_limited_map(map, q_s)?;
    let nf = fine.n;
    grids
        .iter()
        .map(|&n| {
            let r = nf / n;
            let heights = (0..n * n)
                .map(|k| fine.heights[(k / n) * r * nf + (k % n) * r])
                .collect();
            Surface::new(n, map.size, heights)
        })
        .collect()
}

/// The grids of a map: ascending, each dividing the next, the finest the map's.
fn check_map_grids(map: &Surface, grids: &[usize]) -> Result<()> {
    let nf = map.n;
    let ok = grids.last() == Some(&nf)
        && grids
            .windows(2)
            .all(|w| w[0] < w[1] && w[1].is_multiple_of(w[0]));
    if ok {
        Ok(())
    } else {
        Err(Error::Inconsistent {
            name: "grids".into(),
            requirement: format!(
                "ascending, each dividing the next, the finest the map's {nf} (got {grids:?})"
            ),
        })
    }
}

/// A height map on coarser grids by averaging `r × r` blocks (`r = N/n`):
/// the finest grid is the map itself; each copy keeps the map's modes up to
/// its own Nyquist wavevector (attenuated by the block average's
/// `sinc(q_x Δ/2)·sinc(q_y Δ/2)`, Δ its pixel).
///
/// # Errors
/// The finest grid is not the map's; grids not ascending, each dividing the
/// next; as [`Surface::new`].
pub fn coarsened(map: &Surface, grids: &[usize]) -> Result<Vec<Surface>> {
    let nf = map.n;
    check_map_grids(map, grids)?;
    grids
        .iter()
        .map(|&n| {
            let r = nf / n;
            let w = 1.0 / (r * r) as f64;
            let heights = (0..n * n)
                .map(|k| {
                    let (i, j) = (k / n, k % n);
                    if r == 1 {
                        return map.heights[k];
                    }
                    let mut sum = 0.0;
                    for a in 0..r {
                        let row = (i * r + a) * nf + j * r;
                        sum += map.heights[row..row + r].iter().sum::<f64>();
                    }
                    sum * w
                })
                .collect();
            Surface::new(n, map.size, heights)
        })
        .collect()
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
    let boundary = match source {
        SweepSource::Synthesised(_) | SweepSource::BandLimitedMap(..) => Boundary::Periodic,
        SweepSource::Map(_, b) => b,
    };
    let seeds = match source {
        SweepSource::Synthesised(_) => &config.seeds[..],
        SweepSource::Map(..) | SweepSource::BandLimitedMap(..) => {
            config.seeds.get(..1).unwrap_or_default()
        }
    };
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
    bem::check_memory(finest, boundary)?;
    let mut order: Vec<usize> = (0..pressures.len()).collect();
    order.sort_by(|&a, &b| pressures[a].total_cmp(&pressures[b]));
    let sorted: Vec<f64> = order.iter().map(|&k| pressures[k]).collect();
    let ns = seeds.len();
    let np = pressures.len();
    let mut grids: Vec<GridResult> = config
        .grids
        .iter()
        .map(|&g| GridResult {
            grid: g,
            contact_fraction: vec![vec![0.0; np]; ns],
            mean_separation: vec![vec![0.0; np]; ns],
            surface_rms_slope: vec![0.0; ns],
            elastic_fraction: vec![vec![0.0; np]; ns],
            plastic_fraction: vec![vec![0.0; np]; ns],
            plastic_displacement_mean: vec![vec![0.0; np]; ns],
            iterations: 0,
            residual: 0.0,
            seconds: 0.0,
        })
        .collect();
    let mut histograms: Vec<PressureCounts> =
        pressures.iter().map(|&p| PressureCounts::new(p)).collect();
    let total = ns * np * config.grids.len();
    let options = RoughOptions {
        boundary,
        solver: config.options,
        bins: None,
    };
    let mut done = 0;
    for (si, &seed) in seeds.iter().enumerate() {
        let surfaces = match source {
            SweepSource::Synthesised(spectrum) => {
                nested_surfaces(spectrum, &config.grids, config.size, seed)?
            }
            SweepSource::Map(map, _) => coarsened(map, &config.grids)?,
            SweepSource::BandLimitedMap(map, q_s) => band_limited_copies(map, q_s, &config.grids)?,
        };
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
            };
            let points = rough::solve(surf, contact_modulus, &sorted, &options, &mut observer)?;
            done += points.len();
            let g = &mut grids[gi];
            for (pt, &k) in points.iter().zip(&order) {
                g.contact_fraction[si][k] = pt.contact_fraction;
                g.mean_separation[si][k] = pt.mean_separation;
                g.elastic_fraction[si][k] = pt.elastic_fraction.unwrap_or(pt.contact_fraction);
                g.plastic_fraction[si][k] = pt.plastic_fraction.unwrap_or(0.0);
                g.plastic_displacement_mean[si][k] = pt.plastic_displacement_mean.unwrap_or(0.0);
                g.iterations += pt.iterations;
                g.residual = g.residual.max(pt.residual);
                g.seconds += pt.seconds;
            }
        }
    }
    Ok(Sweep {
        nominal_pressure: pressures.to_vec(),
        grids,
        histograms,
        yield_stress: config.options.yield_stress,
    })
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

/// The continuum limit at one pressure, from the seed-averaged A(N).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct Continuum {
    /// The fit of the seed-averaged A(N) ([`extrapolate`]).
    pub fit: Extrapolation,
    /// Standard error of A∞ over seeds (each seed extrapolated alone;
    /// `None` for one seed).
    pub seed_scatter: Option<f64>,
    /// Combined error `sqrt(fit.uncertainty()² + seed_scatter²)`.
    pub standard_error: f64,
}

/// The continuum limit at each pressure of contact fractions
/// `a[grid][seed][pressure]` on `grids` (see [`Continuum`]).
///
/// # Errors
/// Fewer than two grids, ragged input; as [`extrapolate`].
pub fn continuum_limit(
    grids: &[usize],
    a: &[Vec<Vec<f64>>],
    alpha: Option<f64>,
) -> Result<Vec<Continuum>> {
    let n: Vec<f64> = grids.iter().map(|&g| g as f64).collect();
    let seeds = a.first().map_or(0, Vec::len);
    let np = a.first().and_then(|s| s.first()).map_or(0, Vec::len);
    if a.len() != grids.len()
        || a.iter()
            .any(|g| g.len() != seeds || g.iter().any(|s| s.len() != np))
    {
        return Err(Error::Inconsistent {
            name: "contact fractions".into(),
            requirement: "one value per grid, seed and pressure".into(),
        });
    }
    (0..np)
        .map(|k| {
            let mean: Vec<f64> = a
                .iter()
                .map(|g| mean_and_error(&g.iter().map(|s| s[k]).collect::<Vec<_>>()).0)
                .collect();
            let fit = extrapolate(&n, &mean, alpha)?;
            let per_seed: Vec<f64> = (0..seeds)
                .map(|s| {
                    let curve: Vec<f64> = a.iter().map(|g| g[s][k]).collect();
                    extrapolate(&n, &curve, Some(fit.alpha)).map(|e| e.value)
                })
                .collect::<Result<_>>()?;
            let seed_scatter = mean_and_error(&per_seed).1;
            Ok(Continuum {
                fit,
                seed_scatter,
                standard_error: fit.uncertainty().hypot(seed_scatter.unwrap_or(0.0)),
            })
        })
        .collect()
}

impl Sweep {
    /// Seed-averaged A/A0 and its standard error over seeds, per grid:
    /// `[grid][pressure]`.
    pub fn mean_contact_fraction(&self) -> Vec<(Vec<f64>, Vec<Option<f64>>)> {
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.contact_fraction, self.nominal_pressure.len()))
            .collect()
    }

    /// Seed-averaged mean separation and its standard error, per grid.
    pub fn mean_separation(&self) -> Vec<(Vec<f64>, Vec<Option<f64>>)> {
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.mean_separation, self.nominal_pressure.len()))
            .collect()
    }

    /// Seed-averaged A_el/A0 and A_pl/A0 per grid: `[grid][pressure]` each.
    pub fn mean_plastic_split(&self) -> Vec<(Vec<f64>, Vec<f64>)> {
        let np = self.nominal_pressure.len();
        self.grids
            .iter()
            .map(|g| {
                (
                    per_pressure_mean(&g.elastic_fraction, np).0,
                    per_pressure_mean(&g.plastic_fraction, np).0,
                )
            })
            .collect()
    }

    /// Seed-averaged mean plastic displacement per grid: `[grid][pressure]`.
    pub fn mean_plastic_displacement(&self) -> Vec<Vec<f64>> {
        let np = self.nominal_pressure.len();
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.plastic_displacement_mean, np).0)
            .collect()
    }

    /// The continuum limit of A_el/A0 and of A_pl/A0 at each pressure, each
    /// with the α of the total's limit `cont` at that pressure.
    ///
    /// # Errors
    /// As [`continuum_limit`].
    pub fn extrapolate_plastic_split(
        &self,
        cont: &[Continuum],
    ) -> Result<Vec<(Continuum, Continuum)>> {
        let grids: Vec<usize> = self.grids.iter().map(|g| g.grid).collect();
        let at = |field: fn(&GridResult) -> &Vec<Vec<f64>>, k: usize, alpha: f64| {
            let a: Vec<Vec<Vec<f64>>> = self
                .grids
                .iter()
                .map(|g| field(g).iter().map(|s| vec![s[k]]).collect())
                .collect();
            continuum_limit(&grids, &a, Some(alpha)).and_then(|mut v| {
                v.pop()
                    .ok_or_else(|| Error::invalid("nominal_pressure", 0.0, "at least one"))
            })
        };
        cont.iter()
            .enumerate()
            .map(|(k, c)| {
                Ok((
                    at(|g| &g.elastic_fraction, k, c.fit.alpha)?,
                    at(|g| &g.plastic_fraction, k, c.fit.alpha)?,
                ))
            })
            .collect()
    }

    /// A(N) per seed: `[grid][seed][pressure]`.
    fn fractions(&self) -> Vec<Vec<Vec<f64>>> {
        self.grids
            .iter()
            .map(|g| g.contact_fraction.clone())
            .collect()
    }

    /// The continuum limit at each pressure ([`continuum_limit`]).
    ///
    /// # Errors
    /// As [`continuum_limit`].
    pub fn extrapolate(&self, alpha: Option<f64>) -> Result<Vec<Continuum>> {
        let grids: Vec<usize> = self.grids.iter().map(|g| g.grid).collect();
        continuum_limit(&grids, &self.fractions(), alpha)
    }

    /// A∞ of each seed at each pressure, with the α of `cont`: `[seed][pressure]`.
    pub(crate) fn seed_limits(&self, cont: &[Continuum]) -> Result<Vec<Vec<f64>>> {
        let n: Vec<f64> = self.grids.iter().map(|g| g.grid as f64).collect();
        let seeds = self.grids.first().map_or(0, |g| g.contact_fraction.len());
        (0..seeds)
            .map(|s| {
                cont.iter()
                    .enumerate()
                    .map(|(k, c)| {
                        let curve: Vec<f64> = self
                            .grids
                            .iter()
                            .map(|g| g.contact_fraction[s][k])
                            .collect();
                        extrapolate(&n, &curve, Some(c.fit.alpha)).map(|e| e.value)
                    })
                    .collect()
            })
            .collect()
    }
}

fn per_pressure_mean(v: &[Vec<f64>], np: usize) -> (Vec<f64>, Vec<Option<f64>>) {
    (0..np)
        .map(|k| mean_and_error(&v.iter().map(|s| s[k]).collect::<Vec<_>>()))
        .unzip()
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

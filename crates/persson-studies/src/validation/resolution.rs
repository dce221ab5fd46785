//! The grids and the band of a resolution study: the grids halve the
//! finest, and q_s is what the coarsest resolves.
//!
//! # Resolution of q_s
//! The shortest wavelength `2π/q_s` must span at least `p` pixels of the
//! coarsest grid (default [`DEFAULT_PIXELS_PER_WAVELENGTH`] = 4):
//! ```text
//! q_s ≤ q_s,max = N_coarsest q_l / p
//! ```
//! A larger q_s is **clipped** to q_s,max ([`resolve_q_s`],
//! [`persson::spectrum::BandLimited`]): the theories are then evaluated for
//! the clipped spectrum too, so that theory and BEM see the same surface;
//! the report says so.
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005.

use serde::Serialize;

use persson::bem::{self, Method, Options};
use persson::error::{check, Error, Result};

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
/// Non-positive `q_l` or `pixels_per_wavelength`; `pixels_per_wavelength`
/// at or above the coarsest grid side (no wavevector above q_l resolved).
pub fn resolve_q_s(
    q_l: f64,
    requested: Option<f64>,
    coarsest: usize,
    pixels_per_wavelength: f64,
) -> Result<ResolvedBand> {
    check::positive("q_l", q_l)?;
    check::positive("pixels_per_wavelength", pixels_per_wavelength)?;
    let q_max = resolvable_q_max(q_l, coarsest, pixels_per_wavelength);
    if q_max.is_nan() || q_max <= q_l {
        return Err(persson::Error::invalid(
            "pixels_per_wavelength",
            pixels_per_wavelength,
            format!("below the coarsest grid side {coarsest} (then some wavevector above q_l is resolved)"),
        ));
    }
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
            method: Method::default(),
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
    /// The solver's method (default: preconditioned, falling back to the
    /// plain loop on a stall; [`super::sweep::GridResult::fallbacks`]).
    pub method: Method,
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

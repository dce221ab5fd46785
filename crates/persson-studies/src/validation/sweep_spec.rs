//! The BEM side of `persson compare` and `compare kappa` as the user sets it:
//! one declaration from which the command line derives its flags and against
//! which Python's `compare` keywords are checked.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use persson::bem::Options;
use persson::error::{check, Error, Result};

use super::resolution::{SweepSettings, DEFAULT_LEVELS, DEFAULT_PIXELS_PER_WAVELENGTH};
use super::DEFAULT_ALPHA;

/// The finest grid where none is given.
pub const DEFAULT_SWEEP_GRID: usize = 256;

/// The resolution sweep: the grids, the realisations, the continuum limit's
/// exponent, the band the coarsest grid resolves and the solver.
#[derive(Debug, Clone, Default, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SweepSpec {
    /// Finest grid side N; the BEM runs on N/4, N/2 and N, see `levels`
    /// (default 256).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid: Option<usize>,
    /// Number of grids, each half the next, at least 2 (default 3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub levels: Option<usize>,
    /// Number of realisations K (seeds `seed` … `seed` + K − 1), at least 1;
    /// A is averaged (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seeds: Option<usize>,
    /// First seed (Pcg64Mcg, value-stable; default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Exponent α of A(N) = A∞ + c N^−α, Campañá & Müser 2007 (default 0.7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    /// Fit α from three grids (Richardson) instead of fixing it.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub fit_alpha: bool,
    /// Pixels of the coarsest grid per shortest wavelength 2π/q_s: q_s is
    /// clipped to N_coarsest q_l / this, with a warning (default 4).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pixels_per_wavelength: Option<f64>,
    /// Relative tolerance ε of the solver (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Iterations allowed per solve (default 10000); a solve that needs
    /// more fails, saying so.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<usize>,
}

impl SweepSpec {
    /// The fields a measured map makes meaningless (its file sets the grid,
    /// and it is one realisation), if given.
    pub fn unused_with_surface(&self) -> Option<&'static str> {
        [
            (self.grid.is_some(), "grid"),
            (self.seed.is_some(), "seed"),
            (self.seeds.is_some(), "seeds"),
        ]
        .into_iter()
        .find_map(|(given, field)| given.then_some(field))
    }

    /// The settings, defaults filled in, with the solver's `yield_stress`.
    ///
    /// # Errors
    /// `alpha` with `fit_alpha`; no realisation; a tolerance out of range.
    pub fn settings(&self, yield_stress: Option<f64>) -> Result<SweepSettings> {
        if self.fit_alpha && self.alpha.is_some() {
            return Err(Error::Inconsistent {
                name: "alpha and fit_alpha".into(),
                requirement: "one of them: a fixed exponent or a fitted one".into(),
            });
        }
        let count = self.seeds.unwrap_or(1);
        if count == 0 {
            return Err(Error::invalid("seeds", 0.0, "at least 1"));
        }
        let first = self.seed.unwrap_or(1);
        Ok(SweepSettings {
            grid: self.grid.unwrap_or(DEFAULT_SWEEP_GRID),
            levels: self.levels.unwrap_or(DEFAULT_LEVELS),
            seeds: (0..count as u64).map(|k| first + k).collect(),
            alpha: (!self.fit_alpha).then_some(self.alpha.unwrap_or(DEFAULT_ALPHA)),
            pixels_per_wavelength: self
                .pixels_per_wavelength
                .unwrap_or(DEFAULT_PIXELS_PER_WAVELENGTH),
            options: Options {
                tolerance: check::tolerance("tolerance", self.tolerance.unwrap_or(1e-10))?,
                max_iterations: self
                    .max_iterations
                    .unwrap_or(Options::default().max_iterations),
                warm_start: true,
                yield_stress,
            },
        })
    }
}

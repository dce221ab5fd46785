//! What a resolution sweep's numbers come to: the mean over seeds on each
//! grid, and the continuum limit N → ∞ of A(N) at each pressure (with a
//! yield stress, of A_el and A_pl too).
//!
//! # Formula
//! ```text
//! Ā(N) = mean_s A_s(N),   Ā(N) = A∞ + c N^{−α}  (least squares, α fixed or fitted)
//! se(A∞)² = se_fit² + se_seeds²,   se_seeds: the standard error of A∞,s over seeds
//! ```
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005.

use serde::Serialize;

use super::continuum::{extrapolate, mean_and_error, Extrapolation};
use super::sweep::{GridResult, Sweep};
use persson::error::{Error, Result};

/// A quantity on one grid at each pressure: its mean over seeds and the
/// standard error of that mean.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SeedMean {
    /// Mean over seeds, one value per pressure.
    pub mean: Vec<f64>,
    /// Its standard error over seeds (`None` for one seed), one per pressure.
    pub standard_error: Vec<Option<f64>>,
}

/// With a yield stress: A_el/A0 and A_pl/A0 on one grid at each pressure,
/// mean over seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PlasticSplit {
    /// A_el/A0 (nodes with 0 < p < σY), one value per pressure.
    pub elastic_fraction: Vec<f64>,
    /// A_pl/A0 (nodes at p = σY), one value per pressure.
    pub plastic_fraction: Vec<f64>,
}

/// With a yield stress: the continuum limits of A_el/A0 and A_pl/A0 at one
/// pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ContinuumSplit {
    /// The limit of A_el/A0.
    pub elastic_fraction: Continuum,
    /// The limit of A_pl/A0.
    pub plastic_fraction: Continuum,
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
                .map(|g| mean_and_error(&g.iter().map(|s| s[k]).collect::<Vec<_>>()).mean)
                .collect();
            let fit = extrapolate(&n, &mean, alpha)?;
            let per_seed: Vec<f64> = (0..seeds)
                .map(|s| {
                    let curve: Vec<f64> = a.iter().map(|g| g[s][k]).collect();
                    extrapolate(&n, &curve, Some(fit.alpha)).map(|e| e.value)
                })
                .collect::<Result<_>>()?;
            let seed_scatter = mean_and_error(&per_seed).standard_error;
            Ok(Continuum {
                fit,
                seed_scatter,
                standard_error: fit.uncertainty().hypot(seed_scatter.unwrap_or(0.0)),
            })
        })
        .collect()
}

impl Sweep {
    /// Seed-averaged A/A0 and its standard error over seeds, one per grid.
    pub fn mean_contact_fraction(&self) -> Vec<SeedMean> {
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.contact_fraction, self.nominal_pressure.len()))
            .collect()
    }

    /// Seed-averaged mean separation and its standard error, one per grid.
    pub fn mean_separation(&self) -> Vec<SeedMean> {
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.mean_separation, self.nominal_pressure.len()))
            .collect()
    }

    /// Seed-averaged A_el/A0 and A_pl/A0, one per grid.
    pub fn mean_plastic_split(&self) -> Vec<PlasticSplit> {
        let np = self.nominal_pressure.len();
        self.grids
            .iter()
            .map(|g| PlasticSplit {
                elastic_fraction: per_pressure_mean(&g.elastic_fraction, np).mean,
                plastic_fraction: per_pressure_mean(&g.plastic_fraction, np).mean,
            })
            .collect()
    }

    /// Seed-averaged mean plastic displacement per grid: `[grid][pressure]`.
    pub fn mean_plastic_displacement(&self) -> Vec<Vec<f64>> {
        let np = self.nominal_pressure.len();
        self.grids
            .iter()
            .map(|g| per_pressure_mean(&g.plastic_displacement_mean, np).mean)
            .collect()
    }

    /// The continuum limit of A_el/A0 and of A_pl/A0 at each pressure, each
    /// with the α of the total's limit `cont` at that pressure.
    ///
    /// # Errors
    /// As [`continuum_limit`].
    pub fn extrapolate_plastic_split(&self, cont: &[Continuum]) -> Result<Vec<ContinuumSplit>> {
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
                Ok(ContinuumSplit {
                    elastic_fraction: at(|g| &g.elastic_fraction, k, c.fit.alpha)?,
                    plastic_fraction: at(|g| &g.plastic_fraction, k, c.fit.alpha)?,
                })
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

/// The mean over seeds of `v[seed][pressure]` at each of `np` pressures.
fn per_pressure_mean(v: &[Vec<f64>], np: usize) -> SeedMean {
    let (mean, standard_error) = (0..np)
        .map(|k| {
            let m = mean_and_error(&v.iter().map(|s| s[k]).collect::<Vec<_>>());
            (m.mean, m.standard_error)
        })
        .unzip();
    SeedMean {
        mean,
        standard_error,
    }
}

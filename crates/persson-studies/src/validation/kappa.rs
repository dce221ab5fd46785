//! κ, the slope of the low-load law A/A0 = κ σ0/(E* h'_rms), fitted to
//! contact fractions: of a theory, of the BEM per grid and in the continuum
//! limit, or of the user's data.
//!
//! # References
//! Persson, J. Chem. Phys. 115, 3840 (2001) (κ = √(8/π)); Bush, Gibson &
//! Thomas, Wear 35, 87 (1975) (κ = √(2π)); Campañá & Müser, EPL 77, 38005
//! (2007), doi:10.1209/0295-5075/77/38005 (κ from the BEM's linear regime).

use serde::Serialize;

use persson::error::{Error, Result};

/// κ fitted in the low-load regime.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct KappaFit {
    /// κ in A/A0 = κ σ0/(E* √⟨|∇h|²⟩).
    pub kappa: f64,
    /// Its standard error (`None` with a single point).
    pub standard_error: Option<f64>,
    /// Lowest and highest nominal pressure used.
    pub nominal_pressure_range: [f64; 2],
    /// Number of points used.
    pub points: usize,
}

/// Fit κ through the origin to the points with A/A0 < `max_fraction`.
///
/// # Formula
/// ```text
/// x_i = σ0,i / (E* s),  κ = Σ x_i A_i / Σ x_i²,  se(κ)² = Σ (A_i − κ x_i)² / ((n − 1) Σ x_i²)
/// ```
/// (s the rms slope at the magnification of the data).
///
/// # Errors
/// No point below `max_fraction`; non-positive modulus or slope.
pub fn fit_kappa(
    pressures: &[f64],
    fractions: &[f64],
    contact_modulus: f64,
    rms_slope: f64,
    max_fraction: f64,
) -> Result<KappaFit> {
    persson::error::check::positive("contact_modulus", contact_modulus)?;
    persson::error::check::positive("rms_slope", rms_slope)?;
    let pts: Vec<(f64, f64)> = pressures
        .iter()
        .zip(fractions)
        .filter(|(_, &a)| a > 0.0 && a < max_fraction)
        .map(|(&p, &a)| (p / (contact_modulus * rms_slope), a))
        .collect();
    if pts.is_empty() {
        return Err(Error::Inconsistent {
            name: "pressures".into(),
            requirement: format!("at least one point with 0 < A/A0 < {max_fraction} to fit kappa"),
        });
    }
    let sxx: f64 = pts.iter().map(|p| p.0 * p.0).sum();
    let kappa = pts.iter().map(|p| p.0 * p.1).sum::<f64>() / sxx;
    let n = pts.len();
    let standard_error = (n > 1).then(|| {
        (pts.iter().map(|p| (p.1 - kappa * p.0).powi(2)).sum::<f64>() / ((n - 1) as f64 * sxx))
            .sqrt()
    });
    let scale = contact_modulus * rms_slope;
    let lo = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min) * scale;
    let hi = pts.iter().map(|p| p.0).fold(0.0, f64::max) * scale;
    Ok(KappaFit {
        kappa,
        standard_error,
        nominal_pressure_range: [lo, hi],
        points: n,
    })
}

/// κ with its standard error from a resolution sweep (mean over seeds).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct KappaEstimate {
    /// κ, mean over seeds.
    pub kappa: f64,
    /// Combined standard error of the fit and over seeds (`None` for one seed
    /// and one point).
    pub standard_error: Option<f64>,
    /// Standard error over seeds alone (`None` for one seed).
    pub seed_scatter: Option<f64>,
    /// Lowest and highest nominal pressure used (seed-averaged curve).
    pub nominal_pressure_range: [f64; 2],
    /// Points used (seed-averaged curve).
    pub points: usize,
}

/// κ of one grid of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct GridKappa {
    /// Grid side N.
    pub grid: usize,
    /// κ on this grid.
    #[serde(flatten)]
    pub estimate: KappaEstimate,
}

/// κ of every grid and of the continuum limit.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SweepKappa {
    /// κ per grid, ascending.
    pub per_grid: Vec<GridKappa>,
    /// κ of the extrapolated curve.
    pub extrapolated: KappaEstimate,
}

#[cfg(feature = "bem")]
/// κ from per-seed curves `[seed][pressure]` and their mean.
///
/// # Formula
/// ```text
/// κ_s = fit_kappa(σ0, A_s(σ0)),   κ = mean_s κ_s,   se = sqrt(se_fit² + se_seeds²)
/// ```
fn estimate(
    pressures: &[f64],
    curves: &[Vec<f64>],
    mean: &[f64],
    contact_modulus: f64,
    rms_slope: f64,
    max_fraction: f64,
) -> Result<KappaEstimate> {
    let avg = fit_kappa(pressures, mean, contact_modulus, rms_slope, max_fraction)?;
    let per: Vec<f64> = curves
        .iter()
        .map(|c| fit_kappa(pressures, c, contact_modulus, rms_slope, max_fraction).map(|f| f.kappa))
        .collect::<Result<_>>()?;
    let m = super::continuum::mean_and_error(&per);
    let (kappa, seed_scatter) = (m.mean, m.standard_error);
    let standard_error = match (avg.standard_error, seed_scatter) {
        (None, None) => None,
        (a, b) => Some(a.unwrap_or(0.0).hypot(b.unwrap_or(0.0))),
    };
    Ok(KappaEstimate {
        kappa,
        standard_error,
        seed_scatter,
        nominal_pressure_range: avg.nominal_pressure_range,
        points: avg.points,
    })
}

#[cfg(feature = "bem")]
impl super::sweep::Sweep {
    /// κ from the low-load regime (A/A0 < `max_fraction`) of each grid and of
    /// the continuum limit, fitted per seed and averaged ([`KappaEstimate`]).
    ///
    /// `rms_slope` is the spectrum's full-band rms slope (what the grids
    /// resolve).
    ///
    /// # Errors
    /// No point below `max_fraction` on some curve; as [`Self::extrapolate`].
    pub fn kappa(
        &self,
        contact_modulus: f64,
        rms_slope: f64,
        max_fraction: f64,
        alpha: Option<f64>,
    ) -> Result<SweepKappa> {
        let p = &self.nominal_pressure;
        let means = self.mean_contact_fraction();
        let per_grid = self
            .grids
            .iter()
            .zip(&means)
            .map(|(g, m)| {
                estimate(
                    p,
                    &g.contact_fraction,
                    &m.mean,
                    contact_modulus,
                    rms_slope,
                    max_fraction,
                )
                .map(|estimate| GridKappa {
                    grid: g.grid,
                    estimate,
                })
            })
            .collect::<Result<_>>()?;
        let cont = self.extrapolate(alpha)?;
        let mean_inf: Vec<f64> = cont.iter().map(|c| c.fit.value).collect();
        let per_seed = self.seed_limits(&cont)?;
        let extrapolated = estimate(
            p,
            &per_seed,
            &mean_inf,
            contact_modulus,
            rms_slope,
            max_fraction,
        )?;
        Ok(SweepKappa {
            per_grid,
            extrapolated,
        })
    }
}

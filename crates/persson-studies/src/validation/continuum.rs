//! The continuum limit of a quantity computed at several resolutions,
//! A(N) = A∞ + c N^{−α}, and the mean over realisations.

use serde::Serialize;

use persson::error::{Error, Result};

/// Exponent of the leading resolution correction of numerical contact areas,
/// A(N) = A∞ + c N^{−α}: α ≈ 0.7 (Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005).
pub const DEFAULT_ALPHA: f64 = 0.7;

/// The continuum limit of a quantity computed at several resolutions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct Extrapolation {
    /// A∞, the extrapolated value.
    pub value: f64,
    /// Its standard error, where the fit has more points than parameters
    /// (see [`extrapolate`]).
    pub standard_error: Option<f64>,
    /// The size of the extrapolation step from the finest resolution,
    /// |A∞ − A(N_max)|.
    pub extrapolation_step: f64,
    /// The exponent α used (given, or fitted).
    pub alpha: f64,
    /// The amplitude c of the correction.
    pub coefficient: f64,
}

impl Extrapolation {
    /// The standard error where one was estimated, else the extrapolation step.
    pub fn uncertainty(&self) -> f64 {
        self.standard_error.unwrap_or(self.extrapolation_step)
    }
}

/// Fit `A(N) = A∞ + c N^{−α}` to values at resolutions `n`.
///
/// # Formula
/// With α fixed, ordinary least squares in `x = N^{−α}` (intercept A∞):
/// ```text
/// c = Σ(x − x̄)(A − Ā) / Σ(x − x̄)²,   A∞ = Ā − c x̄,
/// se(A∞)² = s² (1/n + x̄²/Σ(x − x̄)²),   s² = Σ r² / (n − 2)
/// ```
/// With `alpha = None` and three resolutions in a constant ratio r (N, rN, r²N),
/// α is fitted exactly, `α = ln((A₁ − A₂)/(A₂ − A₃)) / ln r` (Richardson), when
/// the differences have one sign; otherwise α = [`DEFAULT_ALPHA`].
/// The standard error above is estimated when there are more points than
/// parameters; [`Extrapolation::uncertainty`] falls back on the size of the
/// extrapolation step from the finest resolution, |A∞ − A(N_max)| (a
/// conservative bound when the law holds).
///
/// # Errors
/// Fewer than two resolutions, non-finite or non-positive N, lengths differ.
pub fn extrapolate(n: &[f64], a: &[f64], alpha: Option<f64>) -> Result<Extrapolation> {
    if n.len() != a.len() || n.len() < 2 {
        return Err(Error::Inconsistent {
            name: "resolutions and values".into(),
            requirement: format!(
                "at least 2 of each and as many values as resolutions ({} vs {})",
                n.len(),
                a.len()
            ),
        });
    }
    for (&ni, &ai) in n.iter().zip(a) {
        persson::error::check::positive("grid", ni)?;
        if !ai.is_finite() {
            return Err(Error::invalid("contact_fraction", ai, "finite"));
        }
    }
    let (alpha, params) = match alpha {
        Some(al) => (persson::error::check::positive("alpha", al)?, 2),
        None => fitted_alpha(n, a).map_or((DEFAULT_ALPHA, 2), |al| (al, 3)),
    };
    let x: Vec<f64> = n.iter().map(|&ni| ni.powf(-alpha)).collect();
    let k = x.len() as f64;
    let (xm, am) = (x.iter().sum::<f64>() / k, a.iter().sum::<f64>() / k);
    let sxx: f64 = x.iter().map(|&xi| (xi - xm).powi(2)).sum();
    let sxa: f64 = x
        .iter()
        .zip(a)
        .map(|(&xi, &ai)| (xi - xm) * (ai - am))
        .sum();
    let c = if sxx > 0.0 { sxa / sxx } else { 0.0 };
    let value = am - c * xm;
    let finest = n
        .iter()
        .zip(a)
        .max_by(|p, q| p.0.total_cmp(q.0))
        .map_or(value, |p| *p.1);
    let standard_error = (n.len() > params && sxx > 0.0).then(|| {
        let dof = (n.len() - params) as f64;
        let s2: f64 = x
            .iter()
            .zip(a)
            .map(|(&xi, &ai)| (ai - value - c * xi).powi(2))
            .sum::<f64>()
            / dof;
        (s2 * (1.0 / k + xm * xm / sxx)).sqrt()
    });
    Ok(Extrapolation {
        value,
        standard_error,
        extrapolation_step: (value - finest).abs(),
        alpha,
        coefficient: c,
    })
}

/// α from three resolutions in a constant ratio, if the differences allow.
fn fitted_alpha(n: &[f64], a: &[f64]) -> Option<f64> {
    if n.len() != 3 {
        return None;
    }
    let r = n[1] / n[0];
    if (n[2] / n[1] - r).abs() > 1e-9 * r || r <= 1.0 {
        return None;
    }
    let (d1, d2) = (a[0] - a[1], a[1] - a[2]);
    let q = d1 / d2;
    (q > 1.0 && q.is_finite()).then(|| q.ln() / r.ln())
}

/// The mean of a sample and the standard error of that mean.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SampleMean {
    /// x̄ (NaN for an empty sample).
    pub mean: f64,
    /// Standard error of x̄ (`None` for fewer than two values).
    pub standard_error: Option<f64>,
}

/// Mean and standard error of the mean (`None` for a single value).
///
/// # Formula
/// ```text
/// x̄ = Σx/K,   se = sqrt(Σ(x − x̄)² / (K (K − 1)))
/// ```
///
/// # Examples
/// ```
/// use persson_studies::validation::mean_and_error;
/// let m = mean_and_error(&[1.0, 2.0, 3.0]);
/// assert_eq!(m.mean, 2.0);
/// assert!((m.standard_error.unwrap() - (1.0f64 / 3.0).sqrt()).abs() < 1e-15);
/// assert_eq!(mean_and_error(&[4.0]).standard_error, None);
/// ```
pub fn mean_and_error(values: &[f64]) -> SampleMean {
    let k = values.len();
    let mean = if k == 0 {
        f64::NAN
    } else {
        values.iter().sum::<f64>() / k as f64
    };
    let standard_error = (k > 1).then(|| {
        let ss: f64 = values.iter().map(|v| (v - mean).powi(2)).sum();
        (ss / (k * (k - 1)) as f64).sqrt()
    });
    SampleMean {
        mean,
        standard_error,
    }
}

//! Validating numerical codes: continuum extrapolation of contact areas from
//! several resolutions, κ from the low-load regime, and scoring a user's own
//! results against the theories.

use std::path::Path;

use serde::Serialize;

use crate::error::{Error, Result};

/// Exponent of the leading resolution correction of numerical contact areas,
/// A(N) = A∞ + c N^{−α}: α ≈ 0.7 (Campañá & Müser, EPL 77, 38005 (2007), seed 002).
pub const DEFAULT_ALPHA: f64 = 0.7;

/// The continuum limit of a quantity computed at several resolutions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Extrapolation {
    /// A∞, the extrapolated value.
    pub value: f64,
    /// Its uncertainty (one standard error; see [`extrapolate`]).
    pub uncertainty: f64,
    /// The exponent α used (given, or fitted).
    pub alpha: f64,
    /// The amplitude c of the correction.
    pub c: f64,
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
/// The uncertainty is the standard error above when there are more points than
/// parameters, and otherwise the size of the extrapolation step from the
/// finest resolution, |A∞ − A(N_max)| (a conservative bound when the law holds).
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
        crate::error::check::positive("grid", ni)?;
        if !ai.is_finite() {
            return Err(Error::invalid("contact_fraction", ai, "finite"));
        }
    }
    let (alpha, params) = match alpha {
        Some(al) => (crate::error::check::positive("alpha", al)?, 2),
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
    let uncertainty = if n.len() > params && sxx > 0.0 {
        let dof = (n.len() - params) as f64;
        let s2: f64 = x
            .iter()
            .zip(a)
            .map(|(&xi, &ai)| (ai - value - c * xi).powi(2))
            .sum::<f64>()
            / dof;
        (s2 * (1.0 / k + xm * xm / sxx)).sqrt()
    } else {
        (value - finest).abs()
    };
    Ok(Extrapolation {
        value,
        uncertainty,
        alpha,
        c,
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

/// κ fitted in the low-load regime.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct KappaFit {
    /// κ in A/A0 = κ σ0/(E* √⟨|∇h|²⟩).
    pub kappa: f64,
    /// Its standard error (0 with a single point).
    pub standard_error: f64,
    /// Lowest and highest nominal pressure used.
    pub pressure_range: (f64, f64),
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
    crate::error::check::positive("contact_modulus", contact_modulus)?;
    crate::error::check::positive("rms_slope", rms_slope)?;
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
    let standard_error = if n > 1 {
        (pts.iter().map(|p| (p.1 - kappa * p.0).powi(2)).sum::<f64>() / ((n - 1) as f64 * sxx))
            .sqrt()
    } else {
        0.0
    };
    let scale = contact_modulus * rms_slope;
    let lo = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min) * scale;
    let hi = pts.iter().map(|p| p.0).fold(0.0, f64::max) * scale;
    Ok(KappaFit {
        kappa,
        standard_error,
        pressure_range: (lo, hi),
        points: n,
    })
}

/// A user's own results: nominal pressures and contact fractions.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UserData {
    /// Nominal pressures (the unit of the modulus).
    pub pressures: Vec<f64>,
    /// A/A0 at each pressure.
    pub contact_fractions: Vec<f64>,
}

impl UserData {
    /// Read a CSV with columns `pressure, contact_fraction` (a header line and
    /// `#` comments allowed).
    ///
    /// # Errors
    /// [`Error::Parse`] naming the line of a missing column or non-numeric cell,
    /// a pressure ≤ 0 or a fraction outside [0, 1].
    pub fn from_csv(path: &Path) -> Result<Self> {
        let bytes = crate::io::read(path)?;
        let text = std::str::from_utf8(&bytes)
            .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
        let (rows, lines) =
            crate::spectrum::parse_columns(path, text, ["pressure", "contact_fraction"])?;
        for (&(p, a), &line) in rows.iter().zip(&lines) {
            if !(p.is_finite() && p > 0.0) {
                return Err(Error::parse(
                    path,
                    line,
                    1,
                    format!("pressure = {p}: must be finite and > 0"),
                ));
            }
            if !(0.0..=1.0).contains(&a) {
                return Err(Error::parse(
                    path,
                    line,
                    2,
                    format!("contact_fraction = {a}: must be in [0, 1]"),
                ));
            }
        }
        let (pressures, contact_fractions) = rows.into_iter().unzip();
        Ok(UserData {
            pressures,
            contact_fractions,
        })
    }
}

/// How far a set of contact fractions lies from a reference curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Score {
    /// (A_user − A_ref)/A_ref at each point.
    pub relative_deviation: Vec<f64>,
    /// Root mean square of the relative deviations.
    pub rms: f64,
    /// Largest |relative deviation|.
    pub max_abs: f64,
}

/// Score `values` against `reference` (same length, reference > 0).
pub fn score(values: &[f64], reference: &[f64]) -> Score {
    let rel: Vec<f64> = values
        .iter()
        .zip(reference)
        .map(|(&v, &r)| (v - r) / r)
        .collect();
    let n = rel.len().max(1) as f64;
    Score {
        rms: (rel.iter().map(|d| d * d).sum::<f64>() / n).sqrt(),
        max_abs: rel.iter().fold(0.0, |m, d| m.max(d.abs())),
        relative_deviation: rel,
    }
}

/// A user's pressure histogram: bin centres (or pressures) and densities
/// P(σ), normalised like Persson's P(σ) (∫ P dσ = A/A0).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UserHistogram {
    /// Pressures σ (the unit of the modulus).
    pub pressures: Vec<f64>,
    /// P(σ) at each pressure (1/unit of σ).
    pub densities: Vec<f64>,
}

impl UserHistogram {
    /// Read a CSV with columns `pressure, density` (a header line and `#`
    /// comments allowed).
    ///
    /// # Errors
    /// [`Error::Parse`] naming the line of a missing column or non-numeric
    /// cell, a pressure < 0 or a density < 0 (or not finite).
    pub fn from_csv(path: &Path) -> Result<Self> {
        let bytes = crate::io::read(path)?;
        let text = std::str::from_utf8(&bytes)
            .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
        let (rows, lines) = crate::spectrum::parse_columns(path, text, ["pressure", "density"])?;
        for (&(p, d), &line) in rows.iter().zip(&lines) {
            if !(p.is_finite() && p >= 0.0) {
                return Err(Error::parse(
                    path,
                    line,
                    1,
                    format!("pressure = {p}: must be finite and >= 0"),
                ));
            }
            if !(d.is_finite() && d >= 0.0) {
                return Err(Error::parse(
                    path,
                    line,
                    2,
                    format!("density = {d}: must be finite and >= 0"),
                ));
            }
        }
        let (pressures, densities) = rows.into_iter().unzip();
        Ok(UserHistogram {
            pressures,
            densities,
        })
    }
}

/// Relative L1 distance between two densities sampled at the same points,
/// `∫|a − b| dx / ∫|b| dx` by the trapezoid rule (0 when they are equal).
///
/// Used to score a user's pressure histogram against Persson's P(σ).
///
/// # Errors
/// Lengths differ, fewer than two points, or ∫|b| = 0.
pub fn density_distance(x: &[f64], a: &[f64], b: &[f64]) -> Result<f64> {
    if x.len() != a.len() || x.len() != b.len() || x.len() < 2 {
        return Err(Error::Inconsistent {
            name: "histogram".into(),
            requirement: "at least two points, with as many densities as pressures".into(),
        });
    }
    let trap = |f: &dyn Fn(usize) -> f64| -> f64 {
        (1..x.len())
            .map(|i| 0.5 * (f(i) + f(i - 1)) * (x[i] - x[i - 1]))
            .sum()
    };
    let den = trap(&|i| b[i].abs());
    if den.is_nan() || den <= 0.0 {
        return Err(Error::Inconsistent {
            name: "histogram".into(),
            requirement: "a reference density with a non-zero integral".into(),
        });
    }
    Ok(trap(&|i| (a[i] - b[i]).abs()) / den)
}

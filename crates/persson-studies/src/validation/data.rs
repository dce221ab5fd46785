//! The user's own results (contact fractions, a pressure histogram) and how
//! far they lie from a reference.

use std::path::Path;

use serde::Serialize;

use persson::error::{Error, Result};

/// A user's own results: nominal pressures and contact fractions.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UserData {
    /// Nominal pressures σ0 (the unit of the modulus).
    pub nominal_pressure: Vec<f64>,
    /// A/A0 at each pressure.
    pub contact_fraction: Vec<f64>,
}

impl UserData {
    /// Read a CSV with two columns, nominal pressure σ0 and A/A0 (a header
    /// line such as `nominal_pressure,contact_fraction` and `#` comments
    /// allowed).
    ///
    /// # Errors
    /// [`Error::Parse`] naming the line of a missing column or non-numeric cell,
    /// a pressure ≤ 0 or a fraction outside [0, 1].
    pub fn from_csv(path: &Path) -> Result<Self> {
        let bytes = persson::io::read(path)?;
        let text = std::str::from_utf8(&bytes)
            .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
        let (rows, lines) =
            persson::spectrum::parse_columns(path, text, ["nominal_pressure", "contact_fraction"])?;
        for (&(p, a), &line) in rows.iter().zip(&lines) {
            if !(p.is_finite() && p > 0.0) {
                return Err(Error::parse(
                    path,
                    line,
                    1,
                    format!("nominal_pressure = {p}: must be finite and > 0"),
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
        let (nominal_pressure, contact_fraction) = rows.into_iter().unzip();
        Ok(UserData {
            nominal_pressure,
            contact_fraction,
        })
    }
}

/// How far a set of contact fractions lies from a reference curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct Score {
    /// (A_user − A_ref)/A_ref at each point.
    pub relative_deviation: Vec<f64>,
    /// Root mean square of the relative deviations.
    pub rms_relative_deviation: f64,
    /// Largest |relative deviation|.
    pub max_relative_deviation: f64,
    /// Points scored.
    pub points: usize,
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
        rms_relative_deviation: (rel.iter().map(|d| d * d).sum::<f64>() / n).sqrt(),
        max_relative_deviation: rel.iter().fold(0.0, |m, d| m.max(d.abs())),
        points: rel.len(),
        relative_deviation: rel,
    }
}

/// A user's pressure histogram: bin centres (or pressures) σ and densities
/// P(σ), normalised like Persson's P(σ) (∫ P dσ = A/A0). Points, not bins:
/// the file gives no bin edges (compare [`persson::bem::HistogramBin`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UserHistogram {
    /// Local pressures σ (the unit of the modulus).
    pub sigma: Vec<f64>,
    /// P(σ) at each σ (1/unit of σ).
    pub density: Vec<f64>,
}

impl UserHistogram {
    /// Read a CSV with two columns, σ and P(σ) (a header line such as
    /// `sigma,density` and `#` comments allowed).
    ///
    /// # Errors
    /// [`Error::Parse`] naming the line of a missing column or non-numeric
    /// cell, a pressure < 0 or a density < 0 (or not finite).
    pub fn from_csv(path: &Path) -> Result<Self> {
        let bytes = persson::io::read(path)?;
        let text = std::str::from_utf8(&bytes)
            .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
        let (rows, lines) = persson::spectrum::parse_columns(path, text, ["sigma", "density"])?;
        for (&(p, d), &line) in rows.iter().zip(&lines) {
            if !(p.is_finite() && p >= 0.0) {
                return Err(Error::parse(
                    path,
                    line,
                    1,
                    format!("sigma = {p}: must be finite and >= 0"),
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
        let (sigma, density) = rows.into_iter().unzip();
        Ok(UserHistogram { sigma, density })
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

//! Moments, power-law fit and table of a spectrum.

use persson::error::{check, Error, Result};
use persson::spectrum::Spectrum;

use crate::study::check_points;
use crate::warning::Warning;

use super::*;

/// Moments over [q_min, q_max] (default the whole band), a power-law fit
/// over the upper half of the band, and C(q) at `points` log-spaced q.
///
/// # Errors
/// A band that is empty or not positive.
pub fn spectrum(
    s: &dyn Spectrum,
    description: Option<String>,
    q_min: Option<f64>,
    q_max: Option<f64>,
    points: usize,
) -> Result<SpectrumReport> {
    check_points(points)?;
    let lo = check::positive("q_min", q_min.unwrap_or(s.q_min()))?;
    let hi = check::positive("q_max", q_max.unwrap_or(s.q_max()))?;
    if hi <= lo {
        return Err(Error::invalid(
            "q_max",
            hi,
            format!("> q_min = {}", crate::table::number(lo, 6)),
        ));
    }
    let (h, m, k) = (
        s.rms_height(lo, hi)?,
        s.rms_slope(lo, hi)?,
        s.rms_curvature(lo, hi)?,
    );
    let (q_l, q_s) = (s.q_min(), s.q_max());
    let mid = (q_l * q_s).sqrt();
    let curve: Vec<SpectrumPoint> = (0..=200)
        .map(|i| (q_l * (q_s / q_l).powf(f64::from(i) / 200.0)).min(q_s))
        .map(|q| SpectrumPoint { q, c: s.c(q) })
        .collect();
    let upper: Vec<(f64, f64)> = curve
        .iter()
        .filter(|p| p.q >= mid)
        .map(|p| (p.q, p.c))
        .collect();
    let fit = persson::spectrum::fit_power_law(&upper)?;
    let n = points;
    let table = (0..n)
        .map(|i| {
            let q = if i + 1 == n {
                q_s
            } else {
                q_l * (q_s / q_l).powf(i as f64 / (n - 1) as f64)
            };
            SpectrumPoint { q, c: s.c(q) }
        })
        .collect();
    Ok(SpectrumReport {
        surface: description,
        q_l,
        q_s,
        q_min: lo,
        q_max: hi,
        rms_height: h.value,
        rms_height_error_bound: h.error,
        rms_slope: m.value,
        rms_slope_error_bound: m.error,
        rms_curvature: k.value,
        rms_curvature_error_bound: k.error,
        mean_curvature_rms: k.value / 2.0,
        power_law_fit: PowerLawFit {
            prefactor: fit.0,
            exponent: fit.1,
            hurst: -fit.1 / 2.0 - 1.0,
            q_min: mid,
            q_max: q_s,
        },
        table,
        curve,
        warnings: Warning::steep_slope(m.value).into_iter().collect(),
    })
}

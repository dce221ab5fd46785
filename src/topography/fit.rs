//! Hurst exponent from the binned spectrum, with its standard error.
//!
//! # Formula
//! Over the bins with q in `[q_lo, q_hi]`, a weighted least-squares line
//! through `(x, y) = (ln q̄_b, ln C̄_b)` with weights `w_b = n_b` (the number of
//! modes: for a Gaussian surface `var(ln C̄_b) ≈ 1/n_b`):
//! ```text
//! s = Σ w (x − x̄)(y − ȳ) / Σ w (x − x̄)²,      C ≈ A q^s,   H = −s/2 − 1
//! se(s)² = [Σ w r² / (m − 2)] / Σ w (x − x̄)²,  se(H) = se(s)/2
//! ```
//! (`x̄`, `ȳ` weighted means, r the residuals, m the number of bins). The
//! standard error is that of the fit's scatter, so it also covers a spectrum
//! that is not a clean power law.
//!
//! Line scans are fitted on their 1D spectrum, `C_1D ≈ A₁ q^s`,
//! `H = −(s + 1)/2`, `se(H) = se(s)/2`; the prefactor of the 2D line is
//! `A = A₁ Γ(H+1)/(√π Γ(H+½))` ([`crate::spectrum::Convention::Profile1D`]),
//! so that the fit is drawn on the 2D spectrum with the same H.
//!
//! # References
//! Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002): self-affine
//! `C ∝ q^{−2(H+1)}`.

use super::{ProfileSpectrum, Psd};
use crate::error::{Error, Result};

/// A power-law fit `C ≈ A q^{−2(H+1)}` over a band.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct HurstFit {
    /// Hurst exponent H.
    pub hurst: f64,
    /// Standard error of H.
    pub hurst_error: f64,
    /// Prefactor A, m⁴ (1/m)^{2(H+1)}.
    pub prefactor: f64,
    /// Bins used.
    pub bins: usize,
}

/// Fit H over the bins of `psd` with `q_lo ≤ q̄ ≤ q_hi` (module docs).
///
/// # Errors
/// [`Error::Inconsistent`] when fewer than 3 bins with C > 0 lie in the band.
pub fn fit_hurst(psd: &Psd, q_lo: f64, q_hi: f64) -> Result<HurstFit> {
    let l = line(&psd.q, &psd.c, &psd.count, q_lo, q_hi)?;
    Ok(HurstFit {
        hurst: -l.slope / 2.0 - 1.0,
        hurst_error: l.slope_error / 2.0,
        prefactor: l.prefactor,
        bins: l.bins,
    })
}

/// Fit H over the bins of a line scan's 1D spectrum with
/// `q_lo ≤ q̄ ≤ q_hi`, `C_1D ∝ q^{−(2H+1)}` (module docs); the prefactor is
/// that of the 2D spectrum.
///
/// # Errors
/// As [`fit_hurst`].
pub fn fit_hurst_profile(p: &ProfileSpectrum, q_lo: f64, q_hi: f64) -> Result<HurstFit> {
    let l = line(&p.q, &p.c_1d, &p.count, q_lo, q_hi)?;
    let h = -(l.slope + 1.0) / 2.0;
    let factor = libm::tgamma(h + 1.0) / (std::f64::consts::PI.sqrt() * libm::tgamma(h + 0.5));
    Ok(HurstFit {
        hurst: h,
        hurst_error: l.slope_error / 2.0,
        prefactor: l.prefactor * factor,
        bins: l.bins,
    })
}

/// Bins with C > 0 and q in the band (ends included up to rounding).
pub(crate) fn in_band(q: &[f64], c: &[f64], q_lo: f64, q_hi: f64) -> usize {
    q.iter()
        .zip(c)
        .filter(|(q, c)| inside(**q, **c, q_lo, q_hi))
        .count()
}

fn inside(q: f64, c: f64, q_lo: f64, q_hi: f64) -> bool {
    q >= q_lo * (1.0 - 1e-12) && q <= q_hi * (1.0 + 1e-12) && c > 0.0
}

/// A weighted least-squares line through (ln q, ln C).
struct Line {
    slope: f64,
    slope_error: f64,
    prefactor: f64,
    bins: usize,
}

fn line(q: &[f64], c: &[f64], count: &[usize], q_lo: f64, q_hi: f64) -> Result<Line> {
    let pts: Vec<(f64, f64, f64)> = q
        .iter()
        .zip(c)
        .zip(count)
        .filter(|((q, c), _)| inside(**q, **c, q_lo, q_hi))
        .map(|((q, c), n)| (q.ln(), c.ln(), *n as f64))
        .collect();
    let m = pts.len();
    if m < 3 {
        return Err(Error::Inconsistent {
            name: "hurst fit".into(),
            requirement: format!(
                "at least 3 spectrum bins between {} and {} 1/m, got {m}",
                crate::error::num(q_lo),
                crate::error::num(q_hi)
            ),
        });
    }
    let sw: f64 = pts.iter().map(|p| p.2).sum();
    let xm = pts.iter().map(|p| p.2 * p.0).sum::<f64>() / sw;
    let ym = pts.iter().map(|p| p.2 * p.1).sum::<f64>() / sw;
    let sxx: f64 = pts.iter().map(|p| p.2 * (p.0 - xm).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| p.2 * (p.0 - xm) * (p.1 - ym)).sum();
    let s = sxy / sxx;
    let a = ym - s * xm;
    let rss: f64 = pts.iter().map(|p| p.2 * (p.1 - a - s * p.0).powi(2)).sum();
    Ok(Line {
        slope: s,
        slope_error: (rss / (m - 2) as f64 / sxx).sqrt(),
        prefactor: a.exp(),
        bins: m,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_power_law() {
        let h = 0.8;
        let q: Vec<f64> = (0..12).map(|i| 1e5 * 1.3f64.powi(i)).collect();
        let psd = Psd {
            c: q.iter().map(|q| 2e-30 * q.powf(-2.0 * (1.0 + h))).collect(),
            count: (0..12).map(|i| 4 + 3 * i).collect(),
            q_min: q[0],
            q_max: q[11],
            q,
            rms_height: 0.0,
            rms_slope: 0.0,
            rms_curvature: 0.0,
            corner_mean: None,
        };
        let f = fit_hurst(&psd, psd.q_min, psd.q_max).unwrap();
        assert!((f.hurst - h).abs() < 1e-12, "{}", f.hurst);
        assert!(f.hurst_error < 1e-12);
        assert_eq!(f.bins, 12);
        assert!(fit_hurst(&psd, 1e5, 1.5e5).is_err());
    }
}

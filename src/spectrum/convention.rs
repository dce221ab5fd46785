//! Conversions from the spectrum conventions users bring into Persson's.
//!
//! The convention is always explicit (an enum value, a CLI flag, a scene
//! field); nothing is guessed from the data.

use crate::error::{Error, Result};

/// The normalisation of a tabulated spectrum.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Convention {
    /// Persson's: columns q \[1/m\], C(q) \[m⁴\] (identity).
    Persson,
    /// SurfaceTopography / contact.engineering isotropic PSD:
    /// `C_Persson(q) = C_ST(q) / (2π)²`.
    SurfaceTopography,
    /// A 1D profile (line-scan) spectrum `C_1D(q)` \[m³\] of an isotropic
    /// surface, in Persson's 1D normalisation `C_1D(q) = (2π)⁻¹ ∫ dx ⟨h(x)h(0)⟩ e^{−iqx}`.
    ///
    /// For a power law `C_1D = A q^{−(2H+1)}` the 2D spectrum is exactly
    /// ```text
    /// C(q) = C_1D(q)/q · Γ(H+1) / (√π Γ(H+½))
    /// ```
    /// (from `C_1D(q_x) = ∫ dq_y C(√(q_x²+q_y²))`). Each point is converted
    /// with the H of the local log-log slope of its neighbours, which is exact
    /// on power-law stretches; a locally non-decaying stretch (slope ≥ −1,
    /// H ≤ 0) has no 2D counterpart of this form and is rejected.
    Profile1D,
    /// Dimensionless FFT-grid spectrum of a periodic surface of side `size` \[m\]:
    /// columns k (wavenumber in units of 2π/L) and φ(k), with
    /// `q = 2πk/L` and `C_Persson(q) = (L/2π)² φ(k)`.
    Grid {
        /// Side L of the periodic surface, m.
        size: f64,
    },
}

impl Convention {
    /// Convert points of this convention to Persson's (q \[1/m\], C \[m⁴\]).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `C[i]` where a profile spectrum is
    /// not decaying, or `size` when it is not finite and positive.
    pub fn to_persson(&self, pts: &[(f64, f64)]) -> Result<Vec<(f64, f64)>> {
        use std::f64::consts::{PI, TAU};
        match *self {
            Convention::Persson => Ok(pts.to_vec()),
            Convention::SurfaceTopography => {
                Ok(pts.iter().map(|&(q, c)| (q, c / (TAU * TAU))).collect())
            }
            Convention::Grid { size } => {
                crate::error::check::positive("size", size)?;
                let f = size / TAU;
                Ok(pts.iter().map(|&(k, phi)| (k / f, f * f * phi)).collect())
            }
            Convention::Profile1D => {
                let n = pts.len();
                if n < 2 {
                    return Err(Error::invalid(
                        "number of spectrum points",
                        n as f64,
                        "at least 2",
                    ));
                }
                (0..n)
                    .map(|i| {
                        let (j0, j1) = (i.saturating_sub(1), (i + 1).min(n - 1));
                        let (qa, ca) = pts[j0];
                        let (qb, cb) = pts[j1];
                        let s = (cb / ca).ln() / (qb / qa).ln();
                        let h = (-s - 1.0) / 2.0;
                        if !(h > 0.0 && h.is_finite()) {
                            return Err(Error::invalid(
                                format!("C[{i}]"),
                                pts[i].1,
                                format!(
                                    "part of a decaying 1D spectrum (local log-log slope {s:.3} must be < -1)"
                                ),
                            ));
                        }
                        let (q, c1) = pts[i];
                        let factor = libm::tgamma(h + 1.0) / (PI.sqrt() * libm::tgamma(h + 0.5));
                        Ok((q, c1 / q * factor))
                    })
                    .collect()
            }
        }
    }
}

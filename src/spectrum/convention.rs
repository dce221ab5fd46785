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
                let out: Vec<(f64, f64)> =
                    pts.iter().map(|&(k, phi)| (k / f, f * f * phi)).collect();
                // q = 2πk/L and C = (L/2π)² φ must stay positive normal f64
                // for every finite, positive (k, φ) of the file: else L is at
                // fault, not the row (3.17 of the issue-37 audit: "psd.csv:2:2:
                // C[0] = inf" for L = 1e300). The bounds follow from the rows'
                // extremes: (L/2π)² max φ ≤ f64::MAX, 2π min k/L ≥
                // f64::MIN_POSITIVE, (L/2π)² min φ ≥ f64::MIN_POSITIVE, and
                // 2π max k/L ≤ f64::MAX.
                let fine = |v: f64| v.is_finite() && v >= f64::MIN_POSITIVE;
                let given = |v: f64| v.is_finite() && v > 0.0;
                if pts
                    .iter()
                    .zip(&out)
                    .any(|(&(k, phi), &(q, c))| given(k) && given(phi) && !(fine(q) && fine(c)))
                {
                    let extreme =
                        |f: fn(f64, f64) -> f64, init: f64, pick: fn(&(f64, f64)) -> f64| {
                            pts.iter().map(pick).filter(|v| given(*v)).fold(init, f)
                        };
                    let (phi_max, phi_min) = (
                        extreme(f64::max, 0.0, |p| p.1),
                        extreme(f64::min, f64::INFINITY, |p| p.1),
                    );
                    let (k_max, k_min) = (
                        extreme(f64::max, 0.0, |p| p.0),
                        extreme(f64::min, f64::INFINITY, |p| p.0),
                    );
                    let hi = (TAU * f64::MAX.sqrt() / phi_max.sqrt())
                        .min(TAU * k_min / f64::MIN_POSITIVE);
                    let lo = (TAU * f64::MIN_POSITIVE.sqrt() / phi_min.sqrt())
                        .max(TAU * k_max / f64::MAX);
                    return Err(Error::invalid(
                        "size",
                        size,
                        format!(
                            "in [{}, {}] m for this table, so that q = 2πk/L and C = (L/2π)² φ \
                             are finite, positive f64",
                            crate::error::approx(lo),
                            crate::error::approx(hi)
                        ),
                    ));
                }
                Ok(out)
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

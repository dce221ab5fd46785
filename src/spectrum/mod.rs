//! Isotropic roughness power spectra C(q) in Persson's normalisation.
//!
//! # Convention
//! ```text
//! C(q) = (2π)⁻² ∫ d²x ⟨h(x) h(0)⟩ e^{−i q·x}      [m⁴], q angular wavevector [1/m]
//! ⟨h²⟩      = 2π ∫ q  C(q) dq
//! ⟨|∇h|²⟩   = 2π ∫ q³ C(q) dq
//! ⟨|∇²h|²⟩  = 2π ∫ q⁵ C(q) dq
//! ```
//! (the crate docs, Conventions; Persson, Bucher & Chiaia, PRB 65, 184106 (2002)).
//! Spectra in other conventions enter only through [`convention`].
//!
//! Every spectrum implements [`Spectrum`]; the moments
//! `m_k(a, b) = ∫_a^b q^k C(q) dq` are exact (closed form or per power-law
//! segment) for [`SelfAffine`] and [`Tabulated`], and come from adaptive
//! quadrature with an error estimate for [`FnSpectrum`].

pub mod anisotropic;
mod band_limited;
pub mod convention;
mod function;
mod power;
mod self_affine;
mod sum;
mod tabulated;

pub use anisotropic::{Radial, Spectrum2d, Stretched};
pub use band_limited::BandLimited;
pub use convention::Convention;
pub use function::FnSpectrum;
pub use self_affine::{Amplitude, SelfAffine};
pub use sum::Sum;
pub use tabulated::Tabulated;
pub use tabulated::{parse_columns, Rows};

use crate::error::{Error, Result};
use crate::quad::Estimate;

/// An isotropic power spectrum C(q) in Persson's normalisation, zero outside
/// `[q_min, q_max]`.
pub trait Spectrum: Send + Sync {
    /// C(q) in m⁴ (q in 1/m); 0 outside the band.
    fn c(&self, q: f64) -> f64;

    /// Lowest wavevector with C > 0 (q_l), 1/m.
    fn q_min(&self) -> f64;

    /// Highest wavevector with C > 0 (q_s), 1/m.
    fn q_max(&self) -> f64;

    /// The moment `m_k(a, b) = ∫_a^b q^k C(q) dq` with its absolute error.
    ///
    /// `a` and `b` are clipped to the band; `a ≥ b` after clipping gives 0.
    ///
    /// # Errors
    /// Only quadrature-based spectra fail (tolerance not reached).
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate>;

    /// rms height `sqrt(2π m_1)` over `[a, b]`, in m.
    fn rms_height(&self, a: f64, b: f64) -> Result<Estimate> {
        rms(self.moment(1, a, b)?)
    }

    /// rms slope `sqrt(2π m_3)` over `[a, b]` (dimensionless).
    fn rms_slope(&self, a: f64, b: f64) -> Result<Estimate> {
        rms(self.moment(3, a, b)?)
    }

    /// The spectrum over the plane when it is anisotropic ([`Stretched`]);
    /// `None` for an isotropic one. The contact area needs only the angular
    /// average (this trait's C(q)); a synthesised surface needs the plane.
    fn as_2d(&self) -> Option<&dyn Spectrum2d> {
        None
    }

    /// rms curvature `sqrt(2π m_5)` over `[a, b]`, in 1/m.
    fn rms_curvature(&self, a: f64, b: f64) -> Result<Estimate> {
        rms(self.moment(5, a, b)?)
    }
}

/// Least-squares power law `C ≈ A q^e` through points (q, C) in log–log
/// coordinates; returns `(A, e)`.
///
/// # Errors
/// Fewer than two points with q, C > 0 and finite, or all at one q.
pub fn fit_power_law(points: &[(f64, f64)]) -> Result<(f64, f64)> {
    let xy: Vec<(f64, f64)> = points
        .iter()
        .filter(|(q, c)| q.is_finite() && c.is_finite() && *q > 0.0 && *c > 0.0)
        .map(|(q, c)| (q.ln(), c.ln()))
        .collect();
    let n = xy.len() as f64;
    let (xm, ym) = (
        xy.iter().map(|p| p.0).sum::<f64>() / n,
        xy.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxx: f64 = xy.iter().map(|p| (p.0 - xm).powi(2)).sum();
    if xy.len() < 2 || sxx <= 0.0 {
        return Err(Error::invalid(
            "number of spectrum points for a power-law fit",
            n,
            "at least 2 distinct q",
        ));
    }
    let e = xy.iter().map(|p| (p.0 - xm) * (p.1 - ym)).sum::<f64>() / sxx;
    Ok(((ym - e * xm).exp(), e))
}

/// `sqrt(2π m)` with its propagated error (`δ√x = δx / (2√x)`).
fn rms(m: Estimate) -> Result<Estimate> {
    let v = (std::f64::consts::TAU * m.value).sqrt();
    let e = if m.value > 0.0 {
        0.5 * v * m.error / m.value + f64::EPSILON * v
    } else {
        (std::f64::consts::TAU * m.error).sqrt()
    };
    Ok(Estimate { value: v, error: e })
}

/// Clip `[a, b]` to `[lo, hi]`; `None` when empty.
pub(crate) fn clip(a: f64, b: f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
    let (a, b) = (a.max(lo), b.min(hi));
    (a < b).then_some((a, b))
}

/// Check a wavevector range argument of [`Spectrum::moment`].
pub(crate) fn check_range(a: f64, b: f64) -> Result<()> {
    if a.is_nan() || b.is_nan() || a < 0.0 {
        return Err(Error::Inconsistent {
            name: "moment range".into(),
            requirement: format!("0 <= a <= b, got a = {a:e}, b = {b:e}"),
        });
    }
    Ok(())
}

//! A spectrum cut off at a wavevector: what a grid resolves of a wider one.

use super::Spectrum;
use crate::error::{Error, Result};
use crate::quad::Estimate;

/// A spectrum cut off at `q_max`: C = 0 above, the inner spectrum below.
///
/// # Formula
/// ```text
/// C_cut(q) = C(q) for q ≤ q_cut,  0 above;   q_cut = min(q_max, q_s)
/// m_k(a, b) of C_cut = m_k(a, min(b, q_cut)) of C
/// ```
/// (q_s the inner spectrum's upper cut-off). The moments are the inner
/// spectrum's over the shortened band, with their error estimates.
///
/// # Examples
/// ```
/// use persson::spectrum::{Amplitude, BandLimited, SelfAffine, Spectrum};
/// # fn main() -> persson::Result<()> {
/// // H = 0.8 from q_l = 1 to q_s = 100, rms slope 0.1: cut at q = 10
/// let s = SelfAffine::new(1.0, 1.0, 100.0, 0.8, Amplitude::RmsSlope(0.1))?;
/// let cut = BandLimited::new(&s, 10.0)?;
/// assert!(cut.clipped());
/// assert_eq!(cut.q_max(), 10.0);
/// assert_eq!(cut.c(20.0), 0.0);
/// // m₃ ∝ ∫ q^{3 − 2(H+1)} dq = ∫ q^{−0.6} dq: (10^0.4 − 1)/(100^0.4 − 1) of the full one
/// let ratio = cut.rms_slope(1.0, 100.0)?.value.powi(2) / 0.01;
/// let want = (10f64.powf(0.4) - 1.0) / (100f64.powf(0.4) - 1.0);
/// assert!((ratio / want - 1.0).abs() < 1e-13);
/// # Ok(()) }
/// ```
#[derive(Clone, Copy)]
pub struct BandLimited<'a> {
    inner: &'a dyn Spectrum,
    q_max: f64,
}

impl<'a> BandLimited<'a> {
    /// `inner` cut at `min(q_max, inner.q_max())`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `q_s` when `q_max` is not finite or
    /// not above `inner.q_min()`.
    pub fn new(inner: &'a dyn Spectrum, q_max: f64) -> Result<Self> {
        if !(q_max.is_finite() && q_max > inner.q_min()) {
            return Err(Error::invalid(
                "q_s",
                q_max,
                format!("above q_l = {:e}", inner.q_min()),
            ));
        }
        Ok(BandLimited {
            inner,
            q_max: q_max.min(inner.q_max()),
        })
    }

    /// Whether the cut removed part of the inner spectrum.
    pub fn clipped(&self) -> bool {
        self.q_max < self.inner.q_max()
    }
}

impl std::fmt::Debug for BandLimited<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BandLimited")
            .field("q_min", &self.inner.q_min())
            .field("q_max", &self.q_max)
            .finish()
    }
}

/// An anisotropic `inner` cut at |q| ≤ q_max over the plane, so that a
/// band-limited anisotropic spectrum still synthesises anisotropic surfaces.
impl super::Spectrum2d for BandLimited<'_> {
    fn c2(&self, qx: f64, qy: f64) -> f64 {
        let q = qx.hypot(qy);
        if q > self.q_max {
            return 0.0;
        }
        self.inner
            .as_2d()
            .map_or_else(|| self.inner.c(q), |s| s.c2(qx, qy))
    }
    fn q_min(&self) -> f64 {
        self.inner.q_min()
    }
    fn q_max(&self) -> f64 {
        self.q_max
    }
    fn band_at(&self, phi: f64) -> (f64, f64) {
        let (lo, hi) = self
            .inner
            .as_2d()
            .map_or((self.inner.q_min(), self.inner.q_max()), |s| s.band_at(phi));
        (lo, hi.min(self.q_max))
    }
    fn edges_at(&self, phi: f64) -> Vec<f64> {
        let mut e: Vec<f64> = self
            .inner
            .as_2d()
            .map_or_else(|| vec![self.inner.q_min()], |s| s.edges_at(phi))
            .into_iter()
            .filter(|&q| q < self.q_max)
            .collect();
        e.push(self.q_max);
        e
    }
}

impl Spectrum for BandLimited<'_> {
    fn as_2d(&self) -> Option<&dyn super::Spectrum2d> {
        self.inner.as_2d().map(|_| self as &dyn super::Spectrum2d)
    }

    fn c(&self, q: f64) -> f64 {
        if q > self.q_max {
            0.0
        } else {
            self.inner.c(q)
        }
    }
    fn q_min(&self) -> f64 {
        self.inner.q_min()
    }
    fn q_max(&self) -> f64 {
        self.q_max
    }
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        self.inner.moment(k, a, b.min(self.q_max))
    }
}

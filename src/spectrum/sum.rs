//! The roughness of two rough bodies in contact: the sum of their spectra.

use super::{check_range, Spectrum, Spectrum2d};
use crate::error::{Error, Result};
use crate::quad::Estimate;

/// The combined roughness of two (or more) rough surfaces pressed together:
/// the sum of their spectra, all in Persson's normalisation.
///
/// # Formula
/// ```text
/// h(x) = h₁(x) + h₂(x)   (the gap between the two bodies, uncorrelated roughness)
/// C(q) = C₁(q) + C₂(q)                                  [m⁴]
/// m_k(a, b) = Σ_i m_k^{(i)}(a, b),   band [min_i q_l^{(i)}, max_i q_s^{(i)}]
/// ```
/// The contact of two elastic bodies with uncorrelated rough surfaces is that
/// of one body with E* (both compliances) on a rigid surface whose roughness
/// is the sum of the two: the theory sees only C, and the spectrum of a sum of
/// independent random fields is the sum of their spectra. Each C_i is zero
/// outside its own band, so where only one body's spectrum is known the sum
/// is that body's alone (a warning in the application layer says when the
/// bands differ much). The moments are the sums of the parts' moments with
/// the sums of their error estimates.
///
/// When a part is anisotropic ([`super::Stretched`]) the sum is too: over
/// the plane `C(q_x, q_y) = Σ_i C_i(q_x, q_y)` (an isotropic part as
/// `C_i(|q|)`), which [`Spectrum::as_2d`] returns, so a surface synthesised
/// from the sum has the summed 2-D spectrum; as a [`Spectrum`] the sum is the
/// angular average, `C̄ = Σ_i C̄_i`.
///
/// # References
/// B. N. J. Persson, J. Chem. Phys. 115, 3840 (2001), doi:10.1063/1.1388626
/// (two rough surfaces: C = C₁ + C₂); B. N. J. Persson, Surf. Sci. Rep. 61,
/// 201 (2006), doi:10.1016/j.surfrep.2006.04.001, Sec. 2.
///
/// # Examples
/// ```
/// use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Sum};
/// # fn main() -> persson::Result<()> {
/// let a = SelfAffine::new(1e4, 1e4, 1e7, 0.8, Amplitude::RmsHeight(1e-6))?;
/// let b = SelfAffine::new(1e4, 1e4, 1e7, 0.8, Amplitude::RmsHeight(2e-6))?;
/// let s = Sum::new(vec![Box::new(a), Box::new(b)])?;
/// // variances add: h_rms² = 1² + 2² µm²
/// let h = s.rms_height(1e4, 1e7)?.value;
/// assert!((h / (5f64.sqrt() * 1e-6) - 1.0).abs() < 1e-13);
/// # Ok(()) }
/// ```
pub struct Sum {
    parts: Vec<Box<dyn Spectrum>>,
}

impl Sum {
    /// The sum of `parts` (at least two).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for fewer than two parts.
    pub fn new(parts: Vec<Box<dyn Spectrum>>) -> Result<Self> {
        if parts.len() < 2 {
            return Err(Error::invalid(
                "number of spectra in a sum",
                parts.len() as f64,
                "at least 2",
            ));
        }
        Ok(Sum { parts })
    }

    /// The parts, in the order given.
    pub fn parts(&self) -> &[Box<dyn Spectrum>] {
        &self.parts
    }

    /// The band `(q_min, q_max)` of each part, 1/m, in the order given.
    pub fn bands(&self) -> Vec<(f64, f64)> {
        self.parts.iter().map(|p| (p.q_min(), p.q_max())).collect()
    }

    /// How far apart the parts' bands are: the largest ratio between the
    /// parts' lower ends and that between their upper ends (1 when all
    /// bands are the same). Outside the common band only some bodies'
    /// roughness is known, so a large ratio means the sum is one body's
    /// roughness alone over that part of the band.
    ///
    /// # Formula
    /// ```text
    /// r = max( max_i q_l⁽ⁱ⁾ / min_i q_l⁽ⁱ⁾ ,  max_i q_s⁽ⁱ⁾ / min_i q_s⁽ⁱ⁾ )
    /// ```
    pub fn band_mismatch(&self) -> f64 {
        let ratio = |v: Vec<f64>| {
            let hi = v.iter().copied().fold(0.0, f64::max);
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            hi / lo
        };
        let b = self.bands();
        ratio(b.iter().map(|x| x.0).collect()).max(ratio(b.iter().map(|x| x.1).collect()))
    }
}

impl std::fmt::Debug for Sum {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let bands: Vec<(f64, f64)> = self.parts.iter().map(|p| (p.q_min(), p.q_max())).collect();
        f.debug_struct("Sum").field("bands", &bands).finish()
    }
}

/// The parts' 2-D spectra summed over the plane (an isotropic part as `C(|q|)`).
impl Spectrum2d for Sum {
    fn c2(&self, qx: f64, qy: f64) -> f64 {
        self.parts
            .iter()
            .map(|p| {
                p.as_2d()
                    .map_or_else(|| p.c(qx.hypot(qy)), |s| s.c2(qx, qy))
            })
            .sum()
    }
    fn q_min(&self) -> f64 {
        Spectrum::q_min(self)
    }
    fn q_max(&self) -> f64 {
        Spectrum::q_max(self)
    }
    /// The union of the parts' bands along φ (the integrals split at its ends).
    fn band_at(&self, phi: f64) -> (f64, f64) {
        self.parts
            .iter()
            .map(|p| p.as_2d().map_or((p.q_min(), p.q_max()), |s| s.band_at(phi)))
            .fold((f64::INFINITY, 0.0), |(lo, hi), (a, b)| {
                (lo.min(a), hi.max(b))
            })
    }
    /// Every part's band edges along φ: C jumps at each.
    fn edges_at(&self, phi: f64) -> Vec<f64> {
        self.parts
            .iter()
            .flat_map(|p| {
                p.as_2d()
                    .map_or_else(|| vec![p.q_min(), p.q_max()], |s| s.edges_at(phi))
            })
            .collect()
    }
}

impl Spectrum for Sum {
    /// The sum over the plane when any part is anisotropic.
    fn as_2d(&self) -> Option<&dyn Spectrum2d> {
        self.parts
            .iter()
            .any(|p| p.as_2d().is_some())
            .then_some(self as &dyn Spectrum2d)
    }

    fn c(&self, q: f64) -> f64 {
        self.parts.iter().map(|p| p.c(q)).sum()
    }
    fn q_min(&self) -> f64 {
        self.parts
            .iter()
            .map(|p| p.q_min())
            .fold(f64::INFINITY, f64::min)
    }
    fn q_max(&self) -> f64 {
        self.parts.iter().map(|p| p.q_max()).fold(0.0, f64::max)
    }
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        check_range(a, b)?;
        let mut total = Estimate {
            value: 0.0,
            error: 0.0,
        };
        for p in &self.parts {
            let m = p.moment(k, a, b)?;
            total.value += m.value;
            total.error += m.error + f64::EPSILON * m.value.abs();
        }
        Ok(total)
    }
}

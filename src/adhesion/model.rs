//! The adhesion problem: spectrum, contact modulus, work of adhesion and the
//! two modelling choices (area enhancement, detachment prefactor).

use crate::error::{check, Error, Result};
use crate::quad::Estimate;
use crate::special::erfcx;
use crate::spectrum::Spectrum;

/// Whether the work of adhesion acts on the true (sloped) surface area.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AreaEnhancement {
    /// Δγ acts on A_true = A0 ∫₀^∞ e^{−x}(1 + ξ²x)^{1/2} dx (Persson & Tosatti 2001).
    #[default]
    Slopes,
    /// Δγ acts on the projected area only (A_true = A0).
    None,
}

crate::names::named! {
    AreaEnhancement, "area_enhancement",
    "Whether the work of adhesion acts on the true (sloped) surface area." {
        Slopes = "slopes": "Δγ on the true area of Gaussian slopes (Persson & Tosatti 2001).",
        None = "none": "Δγ on the projected area only.",
    }
}

/// The adhesion problem for one spectrum, E* and work of adhesion Δγ.
///
/// # Formula
/// ```text
/// ξ²(ζ)      = 2π ∫_{q_l}^{ζq_l} q³ C dq          U_el(ζ)/A0 = (π E*/2) ∫_{q_l}^{ζq_l} q² C dq
/// ξ²_>(ζ)    = 2π ∫_{ζq_l}^{q_s} q³ C dq          U_>(ζ)/A0  = (π E*/2) ∫_{ζq_l}^{q_s} q² C dq
/// ```
/// Units: q in 1/m, C in m⁴, E* in Pa, Δγ in J/m² = Pa·m.
#[derive(Clone, Copy)]
pub struct AdhesionModel<'a> {
    pub(crate) spectrum: &'a dyn Spectrum,
    pub(crate) contact_modulus: f64,
    pub(crate) work_of_adhesion: f64,
    pub(crate) area_enhancement: AreaEnhancement,
    pub(crate) detachment_prefactor: f64,
    /// ε √t_max = ε E* ξ/√8: a detachment stress below it is below the
    /// rounding of the stress axis of the diffusion (whose width at full
    /// magnification is √t_max) and is taken as 0 (`gamma_sigma`).
    pub(crate) stress_floor: f64,
}

impl<'a> AdhesionModel<'a> {
    /// The model for `spectrum`, E* = `contact_modulus` (Pa) and Δγ =
    /// `work_of_adhesion` (J/m²), with the area enhancement of Persson &
    /// Tosatti and the detachment prefactor c_a = 1.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `contact_modulus` (not finite and
    /// positive, or above √(2 f64::MAX/ξ²)) or `work_of_adhesion` (negative
    /// or not finite, e.g. NaN, or above f64::MAX/(16 a(ξ²) E* q_s)): the
    /// bounds under which the diffusion's quantities stay finite (ξ² the
    /// mean-square slope of the band, a the true-area ratio).
    ///
    /// # Examples
    /// ```
    /// use persson::adhesion::AdhesionModel;
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// let s = SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
    /// assert!(AdhesionModel::new(&s, 1e6, 0.05).is_ok());
    /// let err = AdhesionModel::new(&s, 1e6, -0.05).err().unwrap();
    /// assert!(err.to_string().contains("work_of_adhesion"));
    /// ```
    pub fn new(
        spectrum: &'a dyn Spectrum,
        contact_modulus: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        check::non_negative("work_of_adhesion", work_of_adhesion)?;
        let (q_l, q_s) = (spectrum.q_min(), spectrum.q_max());
        if !(q_l > 0.0 && q_s > q_l && q_s.is_finite()) {
            return Err(Error::Inconsistent {
                name: "q_l, q_s".into(),
                requirement: format!("0 < q_l < q_s < ∞, got q_l = {q_l:e}, q_s = {q_s:e}"),
            });
        }
        let mut model = AdhesionModel {
            spectrum,
            contact_modulus,
            work_of_adhesion,
            area_enhancement: AreaEnhancement::Slopes,
            detachment_prefactor: 1.0,
            stress_floor: 0.0,
        };
        model.check_range()?;
        let xi2 = std::f64::consts::TAU * spectrum.moment(3, q_l, q_s)?.value;
        model.stress_floor = f64::EPSILON * contact_modulus * (xi2 / 8.0).sqrt();
        Ok(model)
    }

    /// Refuse an E* or a Δγ for which the diffusion's quantities leave f64.
    ///
    /// # Bounds
    /// The moving-boundary solve forms (σ − b)², 4t and their ratio, with
    /// t ≤ t_max = E*² ξ²/8 (ξ² = 2π ∫_{q_l}^{q_s} q³C dq) and |b| ≤ σ_a,max:
    /// ```text
    /// 4 t_max ≤ f64::MAX                    ⇔  E* ≤ √(2 f64::MAX/ξ²)
    /// σ_a,max² ≤ f64::MAX/16                ⇐  Δγ ≤ f64::MAX/(16 c_a a(ξ²) E* q_s)
    /// ```
    /// since γ_eff(ζ) = Δγ a(ξ²_>) − U_> ≤ Δγ a(ξ²) (a increases with its
    /// argument, U_> ≥ 0) and q ≤ q_s in σ_a² = c_a γ_eff E* q. With
    /// |σ0| ≤ √f64::MAX/4 ([`AdhesiveContact`](super::AdhesiveContact)) every
    /// (σ − b)² is then at most f64::MAX/4. The area factor is taken with the
    /// enhancement (a ≥ 1 = the factor without it), so the bound holds for
    /// both choices.
    fn check_range(&self) -> Result<()> {
        let (q_l, q_s) = (self.spectrum.q_min(), self.spectrum.q_max());
        let xi2 = std::f64::consts::TAU * self.spectrum.moment(3, q_l, q_s)?.value;
        let approx = crate::error::approx;
        // √(2 f64::MAX/ξ²) without overflow of f64::MAX/ξ² for ξ² < 1
        let e_max = std::f64::consts::SQRT_2 * f64::MAX.sqrt() / xi2.sqrt();
        if self.contact_modulus > e_max {
            return Err(Error::invalid(
                "contact_modulus",
                self.contact_modulus,
                format!(
                    "at most {} so that the diffusion time t = E*²ξ²/8 of the adhesive stress \
                     distribution stays finite in f64 (ξ² = {})",
                    approx(e_max),
                    approx(xi2)
                ),
            ));
        }
        let a_max = area_ratio(xi2).value;
        // Δγ · c_a a E* q_s ≤ f64::MAX/16, tested as a product (an overflow
        // of it is a refusal; a quotient would overflow for a factor < 1)
        let factor = self.detachment_prefactor * a_max * self.contact_modulus * q_s;
        let dg_max = f64::MAX / 16.0 / factor;
        let scaled = self.work_of_adhesion * factor;
        if scaled.is_nan() || scaled > f64::MAX / 16.0 {
            return Err(Error::invalid(
                "work_of_adhesion",
                self.work_of_adhesion,
                format!(
                    "at most {} J/m² (E* = {}, q_s = {}) so that the detachment stress \
                     σ_a = (c_a γ_eff E* q)^(1/2) and its square stay finite in f64",
                    approx(dg_max),
                    crate::error::num(self.contact_modulus),
                    crate::error::num(q_s)
                ),
            ));
        }
        Ok(())
    }

    /// Choose whether Δγ acts on the true or the projected area.
    pub fn with_area_enhancement(mut self, area_enhancement: AreaEnhancement) -> Self {
        self.area_enhancement = area_enhancement;
        self
    }

    /// Set c_a in σ_a = [c_a γ_eff E* q]^{1/2} (default 1).
    ///
    /// # Errors
    /// `detachment_prefactor` not finite and > 0; `work_of_adhesion` above
    /// its bound at this c_a (as [`AdhesionModel::new`]).
    pub fn with_detachment_prefactor(mut self, detachment_prefactor: f64) -> Result<Self> {
        self.detachment_prefactor = check::positive("detachment_prefactor", detachment_prefactor)?;
        self.check_range()?;
        Ok(self)
    }

    /// E* (Pa).
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }

    /// Δγ (J/m²).
    pub fn work_of_adhesion(&self) -> f64 {
        self.work_of_adhesion
    }

    /// ζ_max = q_s/q_l.
    pub fn zeta_max(&self) -> f64 {
        self.spectrum.q_max() / self.spectrum.q_min()
    }

    /// Check a magnification: finite and in [1, ζ_max(1 + 1e-12)] (clipped to ζ_max).
    pub(crate) fn check_zeta(&self, zeta: f64) -> Result<f64> {
        let top = self.zeta_max();
        if zeta.is_finite() && zeta >= 1.0 && zeta <= top * (1.0 + 1e-12) {
            Ok(zeta.min(top))
        } else {
            Err(Error::invalid(
                "zeta",
                zeta,
                format!("in [1, q_s/q_l = {top:e}]"),
            ))
        }
    }

    /// (2π m3, (π E*/2) m2) over [a, b] with their error estimates.
    pub(crate) fn band(&self, a: f64, b: f64) -> Result<(Estimate, Estimate)> {
        let m3 = self.spectrum.moment(3, a, b)?;
        let m2 = self.spectrum.moment(2, a, b)?;
        let tau = std::f64::consts::TAU;
        let pre = 0.5 * std::f64::consts::PI * self.contact_modulus;
        Ok((
            Estimate {
                value: tau * m3.value,
                error: tau * m3.error + f64::EPSILON * tau * m3.value,
            },
            Estimate {
                value: pre * m2.value,
                error: pre * m2.error + 2.0 * f64::EPSILON * pre * m2.value,
            },
        ))
    }

    /// The area factor a(ξ²) of this model (1 without enhancement).
    pub(crate) fn area(&self, slope_variance: f64) -> Estimate {
        match self.area_enhancement {
            AreaEnhancement::Slopes => area_ratio(slope_variance),
            AreaEnhancement::None => Estimate {
                value: 1.0,
                error: 0.0,
            },
        }
    }

    /// da/dξ² of this model (0 without enhancement).
    pub(crate) fn area_slope(&self, slope_variance: f64) -> f64 {
        match self.area_enhancement {
            AreaEnhancement::Slopes => area_ratio_slope(slope_variance),
            AreaEnhancement::None => 0.0,
        }
    }
}

/// Below this ξ² the derivative a′ comes from its asymptotic series.
const AREA_SERIES_MAX: f64 = 0.005;

/// a(x) = ∫₀^∞ e^{−s}(1 + x s)^{1/2} ds = 1 + (√π/2)√x erfcx(1/√x), x ≥ 0.
pub(crate) fn area_ratio(x: f64) -> Estimate {
    if x <= 0.0 {
        return Estimate {
            value: 1.0,
            error: 0.0,
        };
    }
    let xi = x.sqrt();
    let v = 1.0 + 0.5 * std::f64::consts::PI.sqrt() * xi * erfcx(1.0 / xi);
    Estimate::rounded(v, 8.0)
}

/// a′(x) = ∫₀^∞ e^{−s} s / (2(1 + x s)^{1/2}) ds.
///
/// # Formula
/// ```text
/// a′(x) = (√π/4)[z erfcx(z) + 2z²/√π − 2z³ erfcx(z)],   z = 1/√x
///       = Σ_{k≥1} C(1/2, k) k·k! x^{k−1}  (asymptotic, x < 0.005: 1/2 − x/2 + …)
/// ```
/// The closed form cancels for large z (it loses log₁₀(4z²/√π) ≈ 2.7 digits
/// at x = 0.005), so small x uses the series (12 terms leave < 1e-18 there).
pub(crate) fn area_ratio_slope(x: f64) -> f64 {
    if x < AREA_SERIES_MAX {
        // C(1/2, k) k·k! = k·Π_{j<k}(1/2 − j)
        let (mut falling, mut sum, mut pow) = (0.5f64, 0.0, 1.0);
        for k in 1..=12 {
            let kf = k as f64;
            sum += falling * kf * pow;
            falling *= 0.5 - kf;
            pow *= x;
        }
        return sum;
    }
    let z = 1.0 / x.sqrt();
    let e = erfcx(z);
    let sp = std::f64::consts::PI.sqrt();
    0.25 * sp * (z * e + 2.0 * z * z / sp - 2.0 * z * z * z * e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn area_slope_branches_agree_and_match_finite_differences() {
        let x = AREA_SERIES_MAX;
        let lo = area_ratio_slope(x * (1.0 - 1e-12));
        let hi = area_ratio_slope(x);
        assert!((lo - hi).abs() < 1e-12, "{lo} {hi}");
        for x in [1e-3, 0.05, 0.7, 5.0, 300.0] {
            let h = 1e-5 * x;
            let fd = (area_ratio(x + h).value - area_ratio(x - h).value) / (2.0 * h);
            let d = area_ratio_slope(x);
            assert!((fd - d).abs() < 1e-7 * d.max(1e-3), "{x}: {fd} {d}");
        }
    }
}

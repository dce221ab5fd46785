//! The energy balance at full contact (Persson & Tosatti 2001), resolved in
//! magnification: is the surface sticky when the roughness up to ζ is flattened?
//!
//! # Formula
//! ```text
//! U_el(ζ)/A0 = (π E*/2) ∫_{q_l}^{ζq_l} q² C dq                                   [J/m²]
//! A_true/A0  = ∫₀^∞ e^{−x} (1 + ξ² x)^{1/2} dx = 1 + (√π ξ/2) erfcx(1/ξ),  ξ² = 2π ∫ q³ C dq
//! Δγ_eff(ζ)  = Δγ A_true(ζ)/A0 − U_el(ζ)/A0                                     [J/m²]
//! ```
//! U_el is ½⟨p u⟩ of the full-contact displacement u = h with p̂ = E* q û/2:
//! ½ ∫ d²q (E* q/2) C(q) = (π E*/2) ∫ q² C dq. A_true: the surface element is
//! (1 + |∇h|²)^{1/2} dA0 and, for Gaussian roughness, |∇h|²/ξ² is exponentially
//! distributed (the sum of the squares of two independent Gaussian slope
//! components of variance ξ²/2); with t = 1 + ξ² x the integral is
//! (e^{1/ξ²}/ξ²)∫₁^∞ t^{1/2} e^{−t/ξ²} dt = e^{a} ξ Γ(3/2, a), a = 1/ξ², and
//! Γ(3/2, a) = √a e^{−a} + (√π/2) erfc(√a) gives the closed form (no cancellation).
//!
//! # References
//! B. N. J. Persson, E. Tosatti, J. Chem. Phys. 115, 5597 (2001),
//! doi:10.1063/1.1398300 (Sec. II: U_el, the true area and Δγ_eff).

use super::model::{area_ratio, AdhesionModel};
use crate::error::Result;
use crate::quad::Estimate;

/// Bisection steps in ln ζ for a sign change of Δγ_eff (2⁻⁶⁰ of a grid step).
const BISECTION_STEPS: usize = 60;
/// Scan points per decade of ζ when looking for sign changes of Δγ_eff.
const SCAN_PER_DECADE: f64 = 64.0;

/// A_true/A0 = 1 + (√π ξ/2) erfcx(1/ξ) for mean-square slope ξ² (Persson &
/// Tosatti 2001, Gaussian slopes).
///
/// # Formula
/// ```text
/// A_true/A0 = ∫₀^∞ e^{−x} (1 + ξ² x)^{1/2} dx = 1 + (√π ξ/2) erfcx(1/ξ)
///           = 1 + ξ²/2 − ξ⁴/4 + …  (ξ → 0),   ≈ √π ξ/2  (ξ → ∞)
/// ```
///
/// # Errors
/// `slope_variance` (ξ²) negative or not finite.
///
/// # Examples
/// ```
/// // ξ² = 1: 1 + (√π/2) erfcx(1) (mpmath, tests/reference/adhesion_energy_mpmath.py)
/// let a = persson::adhesion::true_area_ratio(1.0).unwrap();
/// assert!((a.value - 1.378_936_078_070_656).abs() < 1e-14);
/// ```
///
/// # References
/// Persson & Tosatti, J. Chem. Phys. 115, 5597 (2001), doi:10.1063/1.1398300.
pub fn true_area_ratio(slope_variance: f64) -> Result<Estimate> {
    crate::error::check::non_negative("slope_variance", slope_variance)?;
    Ok(area_ratio(slope_variance))
}

/// The full-contact energy balance at one magnification.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct EnergyPoint {
    /// Magnification ζ.
    pub zeta: f64,
    /// U_el(ζ)/A0 (J/m²), the elastic energy to flatten the roughness up to ζ.
    pub full_contact_energy: f64,
    /// Bound on the absolute error of `full_contact_energy`.
    pub full_contact_energy_error_bound: f64,
    /// rms slope ξ(ζ) of the roughness up to ζ.
    pub rms_slope: f64,
    /// A_true(ζ)/A0 (1 without area enhancement).
    pub true_area_ratio: f64,
    /// Bound on the absolute error of `true_area_ratio`.
    pub true_area_ratio_error_bound: f64,
    /// Δγ_eff(ζ) = Δγ A_true/A0 − U_el/A0 (J/m²).
    pub effective_interfacial_energy: f64,
    /// Bound on the absolute error of `effective_interfacial_energy`.
    pub effective_interfacial_energy_error_bound: f64,
    /// Δγ_eff(ζ) > 0 by more than its error bound.
    pub sticky: bool,
}

/// The stickiness verdict of the full-contact energy balance.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Stickiness {
    /// Δγ (J/m²).
    pub work_of_adhesion: f64,
    /// The balance at each requested ζ.
    pub points: Vec<EnergyPoint>,
    /// Verdict at full magnification ζ_max = q_s/q_l.
    pub sticky: bool,
    /// Δγ_eff at ζ_max (J/m²).
    pub effective_interfacial_energy: f64,
    /// Bound on the absolute error of `effective_interfacial_energy`.
    pub effective_interfacial_energy_error_bound: f64,
    /// The ζ where Δγ_eff changes sign (ascending; empty when it never does).
    pub stickiness_transitions: Vec<f64>,
    /// Δγ at which Δγ_eff(ζ_max) = 0: U_el(ζ_max)/A_true(ζ_max) (J/m²).
    pub threshold_work_of_adhesion: f64,
}

impl AdhesionModel<'_> {
    /// U_el(ζ), A_true(ζ) and Δγ_eff(ζ) (see the module docs).
    ///
    /// # Errors
    /// ζ outside [1, ζ_max] or not finite.
    ///
    /// # Examples
    /// ```
    /// use persson::adhesion::AdhesionModel;
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// // C = C_r on [q_l, q_s] (q_r = q_s would be rejected; q_r = q_l, H → flat part empty)
    /// let s = SelfAffine::new(1.0, 1.0, 10.0, 0.5, Amplitude::CR(1.0)).unwrap();
    /// let m = AdhesionModel::new(&s, 2.0, 0.0).unwrap();
    /// // ∫₁¹⁰ q²·q⁻³ dq = ln 10, U = (π·2/2) ln 10
    /// let p = m.energy_point(10.0).unwrap();
    /// assert!((p.full_contact_energy - std::f64::consts::PI * 10f64.ln()).abs() < 1e-13);
    /// ```
    pub fn energy_point(&self, zeta: f64) -> Result<EnergyPoint> {
        let zeta = self.check_zeta(zeta)?;
        let q_l = self.spectrum.q_min();
        let (xi2, u) = self.band(q_l, zeta * q_l)?;
        let a = self.area(xi2.value);
        // a′ ≤ 1/2 carries the error of ξ² into a
        let a_err = a.error + 0.5 * xi2.error;
        let dg = self.work_of_adhesion;
        let value = dg * a.value - u.value;
        let error = dg * a_err + u.error + 2.0 * f64::EPSILON * (dg * a.value + u.value).abs();
        Ok(EnergyPoint {
            zeta,
            full_contact_energy: u.value,
            full_contact_energy_error_bound: u.error,
            rms_slope: xi2.value.sqrt(),
            true_area_ratio: a.value,
            true_area_ratio_error_bound: a_err,
            effective_interfacial_energy: value,
            effective_interfacial_energy_error_bound: error,
            sticky: value > error,
        })
    }

    /// The stickiness verdict: Δγ_eff at each ζ of `zetas`, at ζ_max, the ζ
    /// where it changes sign and the threshold Δγ.
    ///
    /// # Formula
    /// ```text
    /// sticky ⇔ Δγ_eff(ζ_max) > 0 ⇔ Δγ > U_el(ζ_max)/A_true(ζ_max)
    /// ```
    /// Δγ_eff(1) = Δγ ≥ 0; the sign changes are found on a scan of 64 points
    /// per decade of ζ and refined by bisection in ln ζ to 2⁻⁶⁰ of a scan step
    /// (a pair of changes closer than a scan step can be missed).
    ///
    /// # Errors
    /// A ζ outside [1, ζ_max]; quadrature failure of a function spectrum.
    pub fn stickiness(&self, zetas: &[f64]) -> Result<Stickiness> {
        let points = zetas
            .iter()
            .map(|&z| self.energy_point(z))
            .collect::<Result<Vec<_>>>()?;
        let top = self.energy_point(self.zeta_max())?;
        Ok(Stickiness {
            work_of_adhesion: self.work_of_adhesion,
            points,
            sticky: top.sticky,
            effective_interfacial_energy: top.effective_interfacial_energy,
            effective_interfacial_energy_error_bound: top.effective_interfacial_energy_error_bound,
            stickiness_transitions: self.transitions()?,
            threshold_work_of_adhesion: top.full_contact_energy / top.true_area_ratio,
        })
    }

    /// ζ where Δγ_eff changes sign.
    fn transitions(&self) -> Result<Vec<f64>> {
        let ln_top = self.zeta_max().ln();
        let n = ((ln_top / std::f64::consts::LN_10) * SCAN_PER_DECADE)
            .ceil()
            .max(8.0) as usize;
        let f = |u: f64| -> Result<f64> {
            Ok(self
                .energy_point(u.exp().min(self.zeta_max()))?
                .effective_interfacial_energy)
        };
        let mut out = Vec::new();
        let (mut u0, mut f0) = (0.0, f(0.0)?);
        for i in 1..=n {
            let u1 = ln_top * i as f64 / n as f64;
            let f1 = f(u1)?;
            if (f0 > 0.0) != (f1 > 0.0) {
                let (mut lo, mut hi, flo) = (u0, u1, f0);
                for _ in 0..BISECTION_STEPS {
                    let mid = 0.5 * (lo + hi);
                    if (f(mid)? > 0.0) == (flo > 0.0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                out.push((0.5 * (lo + hi)).exp());
            }
            (u0, f0) = (u1, f1);
        }
        Ok(out)
    }
}

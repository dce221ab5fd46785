//! The stickiness criterion of Pastewka & Robbins (2014), beside the
//! Persson–Tosatti energy balance.
//!
//! # Formula
//! ```text
//! S = (h'_rms E* Δr / (κ_rep Δγ)) · (h'_rms d_rep / (4 Δr))^{2/3},   sticky ⇔ S < 1
//! d_rep = 4 h'_rms / h''_rms,   κ_rep = 2
//! Δγ_c  = (h'_rms E* Δr / κ_rep) · (h'_rms d_rep / (4 Δr))^{2/3}   (S = Δγ_c/Δγ)
//! g₀    = (16/3) h'²_rms / h''_rms;   the theory assumes short-ranged adhesion, Δr/g₀ < 0.1
//! ```
//! h'_rms and h''_rms are the rms slope and curvature of the whole band
//! (⟨|∇h|²⟩ = 2π∫q³C dq, ⟨|∇²h|²⟩ = 2π∫q⁵C dq), Δr the range of the adhesive
//! interaction (m) and κ_rep the slope of the repulsive area–load law
//! A_rep/A0 = κ_rep σ0/(E* h'_rms). The criterion compares the tension pulled
//! by the attractive rim of width d_att ∝ (Δr/h'_rms)^{2/3} d_rep^{1/3} around
//! repulsive patches of size d_rep with the load their area carries: the
//! area–load slope changes sign at S = 1.
//!
//! The constants are those of Pastewka & Robbins' Eq. 10 as its authors' group
//! evaluates it (ContactEngineering/Adhesion, `examples/adhesive_simulation_rough.py`:
//! κ_rep = 2, d_rep = 4h'/h''); g₀ and the range condition follow Monti,
//! Sanner & Pastewka (2021) as used there. The PNAS text itself could not be
//! read from this workplace.
//!
//! # References
//! - L. Pastewka, M. O. Robbins, Proc. Natl. Acad. Sci. 111, 3298 (2014),
//!   doi:10.1073/pnas.1320846111, Eq. 10.
//! - J. M. Monti, A. Sanner, L. Pastewka, Tribol. Lett. (2021),
//!   doi:10.1007/s11249-021-01454-6.
//! - M. Ciavarella, J. Appl. Mech. (2016), doi:10.1115/1.4034530, arXiv:1602.02555
//!   (the criterion against asperity theories).

use super::model::AdhesionModel;
use crate::error::{check, Result};

/// κ_rep of the repulsive area–load law (Pastewka & Robbins 2014).
pub const KAPPA_REP: f64 = 2.0;
/// Δr/g₀ above which the adhesion is not short-ranged enough for the criterion.
const RANGE_LIMIT: f64 = 0.1;

/// The Pastewka–Robbins stickiness criterion for one surface and interaction.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct PastewkaRobbins {
    /// Δγ (J/m²).
    pub work_of_adhesion: f64,
    /// Δr, the range of the adhesive interaction (m).
    pub adhesion_range: f64,
    /// h'_rms over the band.
    pub rms_slope: f64,
    /// h''_rms over the band (1/m).
    pub rms_curvature: f64,
    /// κ_rep.
    pub kappa_rep: f64,
    /// d_rep = 4 h'_rms/h''_rms (m), the size of repulsive patches.
    pub repulsive_patch_size: f64,
    /// S; the surfaces are sticky when S < 1.
    pub stickiness_parameter: f64,
    /// Δγ_c = S Δγ (J/m²), the work of adhesion at which S = 1.
    pub threshold_work_of_adhesion: f64,
    /// S < 1.
    pub sticky: bool,
    /// Δr/g₀ < 0.1, g₀ = (16/3) h'²_rms/h''_rms (short-ranged adhesion, as the criterion assumes).
    pub short_range: bool,
}

/// Both verdicts side by side.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct StickinessComparison {
    /// Persson & Tosatti: Δγ_eff(ζ_max) > 0.
    pub persson_tosatti: bool,
    /// Δγ at which Δγ_eff(ζ_max) = 0 (J/m²).
    pub persson_tosatti_threshold: f64,
    /// Pastewka & Robbins: S < 1.
    pub pastewka_robbins: bool,
    /// Δγ at which S = 1 (J/m²).
    pub pastewka_robbins_threshold: f64,
    /// The two verdicts agree.
    pub agree: bool,
}

impl AdhesionModel<'_> {
    /// The Pastewka–Robbins criterion for an adhesive interaction of range Δr
    /// = `adhesion_range` (m), with κ_rep = 2 (see the module docs).
    ///
    /// # Errors
    /// `adhesion_range` not finite and > 0; a zero work of adhesion
    /// (`work_of_adhesion`, S = ∞ is no verdict to compute); quadrature failure.
    ///
    /// # Examples
    /// ```
    /// use persson::adhesion::AdhesionModel;
    /// use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
    /// let s = SelfAffine::new(1e6, 1e6, 1e9, 0.8, Amplitude::RmsSlope(0.1)).unwrap();
    /// let m = AdhesionModel::new(&s, 1e9, 0.05).unwrap();
    /// let pr = m.pastewka_robbins(1e-10).unwrap();
    /// let (h1, h2) = (0.1, s.rms_curvature(0.0, f64::INFINITY).unwrap().value);
    /// let s_exact = h1 * 1e9 * 1e-10 / (2.0 * 0.05) * (h1 * h1 / (h2 * 1e-10)).powf(2.0 / 3.0);
    /// assert!((pr.stickiness_parameter - s_exact).abs() < 1e-12 * s_exact);
    /// ```
    pub fn pastewka_robbins(&self, adhesion_range: f64) -> Result<PastewkaRobbins> {
        check::positive("adhesion_range", adhesion_range)?;
        let dg = check::positive("work_of_adhesion", self.work_of_adhesion)?;
        let (a, b) = (self.spectrum.q_min(), self.spectrum.q_max());
        let h1 = self.spectrum.rms_slope(a, b)?.value;
        let h2 = self.spectrum.rms_curvature(a, b)?.value;
        let d_rep = 4.0 * h1 / h2;
        let threshold = h1 * self.contact_modulus * adhesion_range / KAPPA_REP
            * (h1 * d_rep / (4.0 * adhesion_range)).powf(2.0 / 3.0);
        let s = threshold / dg;
        let g0 = 16.0 / 3.0 * h1 * h1 / h2;
        Ok(PastewkaRobbins {
            work_of_adhesion: dg,
            adhesion_range,
            rms_slope: h1,
            rms_curvature: h2,
            kappa_rep: KAPPA_REP,
            repulsive_patch_size: d_rep,
            stickiness_parameter: s,
            threshold_work_of_adhesion: threshold,
            sticky: s < 1.0,
            short_range: adhesion_range / g0 < RANGE_LIMIT,
        })
    }

    /// The Persson–Tosatti and Pastewka–Robbins verdicts side by side.
    ///
    /// # Errors
    /// As [`AdhesionModel::pastewka_robbins`] and [`AdhesionModel::stickiness`].
    pub fn compare_stickiness(&self, adhesion_range: f64) -> Result<StickinessComparison> {
        let pr = self.pastewka_robbins(adhesion_range)?;
        let pt = self.energy_point(self.zeta_max())?;
        let pt_threshold = pt.full_contact_energy / pt.true_area_ratio;
        Ok(StickinessComparison {
            persson_tosatti: pt.sticky,
            persson_tosatti_threshold: pt_threshold,
            pastewka_robbins: pr.sticky,
            pastewka_robbins_threshold: pr.threshold_work_of_adhesion,
            agree: pt.sticky == pr.sticky,
        })
    }
}

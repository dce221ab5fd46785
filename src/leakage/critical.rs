//! The critical-junction theory of the leak rate (module docs of
//! [`crate::leakage`]).

use serde::Serialize;

use super::{LeakStatus, Seal, DEFAULT_PERCOLATION_THRESHOLD};
use crate::error::{check, Result};
use crate::gap::magnified::Magnified;
use crate::spectrum::Spectrum;

/// Default relative tolerance of the q-integrals behind u1.
pub const DEFAULT_TOLERANCE: f64 = 1e-10;

/// The critical junction at one nominal pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct CriticalJunctionPoint {
    /// Nominal pressure σ0 (unit of E*).
    pub nominal_pressure: f64,
    /// Whether the seal leaks.
    pub status: LeakStatus,
    /// A(ζ1)/A0 at full magnification.
    pub contact_fraction: f64,
    /// ζ_c with A(ζ_c)/A0 = a_c (`null` when sealed).
    pub critical_zeta: Option<f64>,
    /// Bound on the absolute error of ζ_c.
    pub critical_zeta_error_bound: f64,
    /// u1(ζ_c), the separation of the critical constriction, m (0 when sealed).
    pub critical_separation: f64,
    /// Bound on the absolute error of u1, m.
    pub critical_separation_error_bound: f64,
    /// Q = (L_y/L_x) u1³ Δ/(12η), m³/s (0 when sealed).
    pub leak_rate: f64,
    /// Bound on the absolute error of Q, m³/s.
    pub leak_rate_error_bound: f64,
}

/// The critical-junction leak rate for one spectrum, E* and seal.
pub struct CriticalJunction<'a> {
    spectrum: &'a dyn Spectrum,
    contact_modulus: f64,
    seal: Seal,
    threshold: f64,
    tolerance: f64,
    breaks: Vec<f64>,
}

impl<'a> CriticalJunction<'a> {
    /// The model with the default threshold a_c = 0.42 and tolerance 1e-10.
    ///
    /// # Errors
    /// E* not finite and positive; a bad seal ([`Seal::validate`]).
    pub fn new(spectrum: &'a dyn Spectrum, contact_modulus: f64, seal: Seal) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        seal.validate()?;
        Ok(CriticalJunction {
            spectrum,
            contact_modulus,
            seal,
            threshold: DEFAULT_PERCOLATION_THRESHOLD,
            tolerance: DEFAULT_TOLERANCE,
            breaks: Vec::new(),
        })
    }

    /// Set the percolation threshold a_c.
    ///
    /// # Errors
    /// `percolation_threshold` outside (0, 1).
    pub fn with_threshold(mut self, percolation_threshold: f64) -> Result<Self> {
        self.threshold = check::open("percolation_threshold", percolation_threshold, 0.0, 1.0)?;
        Ok(self)
    }

    /// Set the relative tolerance of the q-integrals.
    ///
    /// # Errors
    /// Outside [1e-15, 0.1].
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        self.tolerance = check::tolerance("tolerance", tolerance)?;
        Ok(self)
    }

    /// Split the q-integrals at these wavevectors (kinks of C, e.g. q_r).
    pub fn with_breaks(mut self, breaks: &[f64]) -> Self {
        self.breaks = breaks.to_vec();
        self
    }

    /// The critical junction at σ0 = `pressure`.
    ///
    /// # Formula
    /// ```text
    /// ζ_c: A(ζ_c)/A0 = a_c;   u1 = ū(ζ_c) + ū′(ζ_c) A/A′;   Q = (L_y/L_x) u1³ Δ/(12η)
    /// δQ = 3 Q δu1/u1
    /// ```
    ///
    /// # Errors
    /// σ0 not finite and positive; quadrature failures; σ0 so low against E*
    /// that ζ_c lies closer to 1 than it is resolved ([`crate::Error::InvalidParameter`]
    /// naming `nominal_pressure` or `contact_modulus`; bound:
    /// σ0 ≥ E* erf⁻¹(a_c) √(π ∫q³C dq over [q_l, q_l(1 + 1e-13)])).
    ///
    /// # Examples
    /// ```
    /// use persson::leakage::{CriticalJunction, Drive, LeakStatus, Seal};
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// # fn main() -> persson::Result<()> {
    /// let s = SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0))?;
    /// let seal = Seal { seal_width: 1e-3, seal_length: 1e-2, viscosity: 1e-3,
    ///                   drive: Drive::Liquid { pressure_drop: 1e5 } };
    /// let cj = CriticalJunction::new(&s, 1e7, seal)?;
    /// let p = cj.point(1e5)?;
    /// assert_eq!(p.status, LeakStatus::Leaking);
    /// // Q is the cube law of u1, with L_y/L_x = 10
    /// let q = 10.0 * p.critical_separation.powi(3) * 1e5 / 12e-3;
    /// assert!((p.leak_rate - q).abs() <= 1e-14 * q);
    /// # Ok(()) }
    /// ```
    pub fn point(&self, pressure: f64) -> Result<CriticalJunctionPoint> {
        let m = Magnified::new(
            self.spectrum,
            self.contact_modulus,
            pressure,
            self.tolerance,
            &self.breaks,
        )?;
        // ζ_c must be resolved apart from ζ = 1 (A = a_c at x_c = erf⁻¹(a_c))
        crate::gap::magnified::check_resolved(
            self.spectrum,
            self.contact_modulus,
            pressure,
            crate::gap::magnified::erf_inverse(self.threshold),
            crate::gap::magnified::CRITICAL_RESOLUTION,
        )?;
        let (a1, _) = m.area(m.zeta_max())?;
        let mut out = CriticalJunctionPoint {
            nominal_pressure: pressure,
            status: LeakStatus::Sealed,
            contact_fraction: a1,
            critical_zeta: None,
            critical_zeta_error_bound: 0.0,
            critical_separation: 0.0,
            critical_separation_error_bound: 0.0,
            leak_rate: 0.0,
            leak_rate_error_bound: 0.0,
        };
        let Some(zc) = m.zeta_at_fraction(self.threshold)? else {
            return Ok(out);
        };
        let pt = m.point(zc.value)?;
        let u1 = pt.critical_separation;
        // ζ_c's own error moves u1 by |du1/dζ| δζ, below δζ/ζ · u1 · O(1): add it.
        let u1_err = u1.error + u1.value * zc.error / zc.value;
        let drive = self.seal.drive.driving_pressure()?;
        let f = self.seal.seal_length / self.seal.seal_width * drive / (12.0 * self.seal.viscosity);
        let q = f * u1.value.powi(3);
        out.status = LeakStatus::Leaking;
        out.critical_zeta = Some(zc.value);
        out.critical_zeta_error_bound = zc.error;
        out.critical_separation = u1.value;
        out.critical_separation_error_bound = u1_err;
        out.leak_rate = q;
        out.leak_rate_error_bound = 3.0 * f * u1.value * u1.value * u1_err + 8.0 * f64::EPSILON * q;
        Ok(out)
    }

    /// [`CriticalJunction::point`] for each pressure.
    ///
    /// # Errors
    /// As [`CriticalJunction::point`], for the first bad pressure.
    pub fn load_curve(&self, pressures: &[f64]) -> Result<Vec<CriticalJunctionPoint>> {
        for &p in pressures {
            check::positive("nominal_pressure", p)?;
        }
        pressures.iter().map(|&p| self.point(p)).collect()
    }
}

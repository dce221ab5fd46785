//! The rubber: its modulus at the reference temperature, the temperature
//! shift, Poisson's ratio and (for the flash temperature) its thermal
//! properties.

use super::heat::Thermal;
use super::shift::{ShiftFactors, TemperatureShift};
use super::viscoelastic::{Modulus, Viscoelastic};
use crate::error::{Error, Result};

/// Poisson's ratio of rubber (incompressible).
pub const DEFAULT_POISSON: f64 = 0.5;

/// A viscoelastic rubber block (on a rigid rough substrate).
///
/// # Formula
/// ```text
/// E(ω, T) = b_T E(a_T ω, T_ref),   E(−ω) = conj E(ω)
/// ```
/// The friction theory uses E(ω, T)/(1 − ν²), the rubber's contact modulus.
#[derive(Debug, Clone, PartialEq)]
pub struct Rubber {
    viscoelastic: Viscoelastic,
    shift: TemperatureShift,
    poisson: f64,
    thermal: Option<Thermal>,
}

impl Rubber {
    /// A rubber with ν = 0.5 and no thermal properties.
    pub fn new(viscoelastic: impl Into<Viscoelastic>, shift: TemperatureShift) -> Self {
        Rubber {
            viscoelastic: viscoelastic.into(),
            shift,
            poisson: DEFAULT_POISSON,
            thermal: None,
        }
    }

    /// The same rubber with Poisson's ratio ν.
    ///
    /// # Errors
    /// `poisson` not finite or outside (−1, 0.5].
    pub fn with_poisson(mut self, poisson: f64) -> Result<Self> {
        self.poisson = crate::material::check_poisson("poisson", poisson)?;
        Ok(self)
    }

    /// The same rubber with thermal properties: the friction then includes
    /// the flash temperature (reported beside the isothermal result).
    pub fn with_thermal(mut self, thermal: Thermal) -> Self {
        self.thermal = Some(thermal);
        self
    }

    /// The modulus at the reference temperature.
    pub fn viscoelastic(&self) -> &Viscoelastic {
        &self.viscoelastic
    }

    /// The temperature shift.
    pub fn shift(&self) -> &TemperatureShift {
        &self.shift
    }

    /// ν.
    pub fn poisson(&self) -> f64 {
        self.poisson
    }

    /// The thermal properties, if any.
    pub fn thermal(&self) -> Option<&Thermal> {
        self.thermal.as_ref()
    }

    /// a_T and b_T at T (K).
    ///
    /// # Errors
    /// As [`TemperatureShift::factors`].
    pub fn shift_factors(&self, temperature: f64) -> Result<ShiftFactors> {
        self.shift.factors(temperature)
    }

    /// E(ω, T) (ω in rad/s, any sign; T in K).
    ///
    /// # Errors
    /// As [`TemperatureShift::factors`]; ω not finite.
    ///
    /// # Examples
    /// ```
    /// use persson::friction::{Prony, Rubber, TemperatureShift};
    /// let sls = Prony::standard_linear_solid(1e9, 1e6, 1.0).unwrap();
    /// let rubber = Rubber::new(sls, TemperatureShift::wlf(300.0, 8.86, 101.6).unwrap());
    /// // At T_ref, ωτ = 1: E″ = (E0 − E∞)/2; E(−ω) = conj E(ω).
    /// let e = rubber.modulus(-1.0, 300.0).unwrap();
    /// assert!((e.loss_modulus + 0.5 * (1e9 - 1e6)).abs() < 1e-6);
    /// ```
    pub fn modulus(&self, omega: f64, temperature: f64) -> Result<Modulus> {
        if !omega.is_finite() {
            return Err(Error::invalid("frequency", omega, "finite"));
        }
        let f = self.shift.factors(temperature)?;
        let e = self.viscoelastic.modulus(f.shift_factor * omega);
        Ok(Modulus::new(
            f.vertical_shift * e.storage_modulus,
            f.vertical_shift * e.loss_modulus,
        ))
    }
}

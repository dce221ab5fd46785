//! Greenwood & Williamson's model: identical spherical summits with Gaussian
//! heights, each in Hertz contact with the flat, independently.
//!
//! # Formula
//! ```text
//! t    = (d − y_s)/σ_s
//! n    = η F_0(t)                                       contacts per area [1/m²]   (GW 1966, Eq. 5)
//! A/A0 = π η β σ_s F_1(t)                               real contact area          (GW 1966, Eq. 6)
//! σ0   = (4/3) η E* β^{1/2} σ_s^{3/2} F_{3/2}(t)        nominal pressure           (GW 1966, Eq. 7)
//! ```
//! d the separation from the mean plane of the surface heights (m), η the
//! summit density (1/m²), β the summit radius (m), y_s and σ_s the mean and
//! standard deviation of the summit heights (m), E* the contact modulus.
//! Each summit of height z > d carries the Hertz area π β (z − d) and load
//! (4/3) E* β^{1/2} (z − d)^{3/2}. GW measure d from the mean of the summit
//! heights; here d is from the mean plane of the surface (McCool 1986), hence
//! the offset y_s, so that every theory shares one separation.
//!
//! With [`GreenwoodWilliamson::from_moments`] the four summit parameters come
//! from m0, m2, m4 ([`super::moments`]: Nayak 1971, McCool 1986).
//!
//! # Method
//! F_n by [`super::gw_integral`] (full relative accuracy, no underflow of the
//! scaled forms); the separation at a given σ0 by bracketing and the
//! Illinois method on ln σ0(d), to 1e-14 of σ_s.
//!
//! # References
//! - J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. Lond. A 295, 300
//!   (1966), Eqs. 5–7, doi:10.1098/rspa.1966.0242.
//! - J. I. McCool, Wear 107, 37 (1986), doi:10.1016/0043-1648(86)90045-1.

use super::gaussian::{ln_scaled_tail_moment, tail_moment, Order, SQRT_TAU};
use super::{
    check_separation, point_validity, solve_separation, AsperityPoint, AsperityTheory,
    SpectralMoments, Validity,
};
use crate::error::{check, Result};

/// The summit parameters of a GW surface.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SummitParameters {
    /// Summits per unit area η, 1/m².
    pub summit_density: f64,
    /// Summit radius β, m.
    pub summit_radius: f64,
    /// Mean summit height above the mean plane y_s, m.
    pub summit_mean_height: f64,
    /// Standard deviation of the summit heights σ_s, m.
    pub summit_rms_height: f64,
}

impl SummitParameters {
    /// Check the ranges.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] naming `summit_density`,
    /// `summit_radius`, `summit_rms_height` (finite and > 0) or
    /// `summit_mean_height` (finite).
    pub fn validated(self) -> Result<Self> {
        check::positive("summit_density", self.summit_density)?;
        check::positive("summit_radius", self.summit_radius)?;
        check::positive("summit_rms_height", self.summit_rms_height)?;
        if !self.summit_mean_height.is_finite() {
            return Err(crate::Error::invalid(
                "summit_mean_height",
                self.summit_mean_height,
                "finite",
            ));
        }
        Ok(self)
    }
}

/// The GW model (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct GreenwoodWilliamson {
    summits: SummitParameters,
    e_star: f64,
    validity: Vec<Validity>,
}

impl GreenwoodWilliamson {
    /// GW with given summit parameters and contact modulus E*.
    ///
    /// # Errors
    /// As [`SummitParameters::validated`]; `contact_modulus` not finite and > 0.
    ///
    /// # Examples
    /// ```
    /// use persson::asperity::{AsperityTheory, GreenwoodWilliamson, SummitParameters};
    /// let s = SummitParameters { summit_density: 1e10, summit_radius: 1e-5,
    ///                            summit_mean_height: 0.0, summit_rms_height: 1e-7 };
    /// let gw = GreenwoodWilliamson::new(s, 1e9).unwrap();
    /// let p = gw.at_separation(0.0).unwrap();
    /// // t = 0: A/A0 = π η β σ_s F_1(0), F_1(0) = 1/√(2π).
    /// let a = std::f64::consts::PI * 1e10 * 1e-5 * 1e-7 / (2.0 * std::f64::consts::PI).sqrt();
    /// assert!((p.contact_fraction - a).abs() < 1e-15 * a);
    /// ```
    pub fn new(summits: SummitParameters, contact_modulus: f64) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        Ok(GreenwoodWilliamson {
            summits: summits.validated()?,
            e_star: contact_modulus,
            validity: Vec::new(),
        })
    }

    /// GW with the summit parameters of an isotropic Gaussian surface of
    /// moments m0, m2, m4 (Nayak 1971, McCool 1986; [`SpectralMoments::summits`]).
    /// Carries [`Validity::SmallBandwidth`] when α < 10.
    ///
    /// # Errors
    /// `contact_modulus` not finite and > 0.
    pub fn from_moments(moments: &SpectralMoments, contact_modulus: f64) -> Result<Self> {
        let s = moments.summits();
        let summits = SummitParameters {
            summit_density: s.summit_density,
            summit_radius: s.summit_radius,
            summit_mean_height: s.summit_mean_height,
            summit_rms_height: s.summit_rms_height,
        };
        let mut gw = GreenwoodWilliamson::new(summits, contact_modulus)?;
        gw.validity = moments.validity();
        Ok(gw)
    }

    /// The summit parameters in use.
    pub fn summits(&self) -> &SummitParameters {
        &self.summits
    }

    /// t = (d − y_s)/σ_s.
    fn standardised(&self, d: f64) -> f64 {
        (d - self.summits.summit_mean_height) / self.summits.summit_rms_height
    }

    /// (4/3) η E* β^{1/2} σ_s^{3/2}.
    fn load_scale(&self) -> f64 {
        let s = &self.summits;
        4.0 / 3.0
            * s.summit_density
            * self.e_star
            * s.summit_radius.sqrt()
            * s.summit_rms_height.powf(1.5)
    }

    /// ln σ0(d), finite where σ0 underflows.
    fn ln_pressure(&self, d: f64) -> f64 {
        let t = self.standardised(d);
        self.load_scale().ln() + ln_scaled_tail_moment(Order::ThreeHalves, t)
            - 0.5 * t * t
            - SQRT_TAU.ln()
    }
}

impl AsperityTheory for GreenwoodWilliamson {
    fn at_separation(&self, separation: f64) -> Result<AsperityPoint> {
        let d = check_separation(separation)?;
        let s = &self.summits;
        let t = self.standardised(d);
        let pi = std::f64::consts::PI;
        let area = pi
            * s.summit_density
            * s.summit_radius
            * s.summit_rms_height
            * tail_moment(Order::One, t);
        Ok(AsperityPoint {
            separation: d,
            contact_fraction: area,
            nominal_pressure: self.load_scale() * tail_moment(Order::ThreeHalves, t),
            contact_number_density: Some(s.summit_density * tail_moment(Order::Zero, t)),
            validity: point_validity(&self.validity, area),
        })
    }

    fn at_pressure(&self, nominal_pressure: f64) -> Result<AsperityPoint> {
        let s = &self.summits;
        let d = solve_separation(
            &|d| Ok(self.ln_pressure(d)),
            nominal_pressure,
            s.summit_rms_height,
            s.summit_mean_height,
        )?;
        let mut p = self.at_separation(d)?;
        // Report the pressure asked for (the solve leaves ~1e-14 relative).
        p.nominal_pressure = nominal_pressure;
        Ok(p)
    }
}

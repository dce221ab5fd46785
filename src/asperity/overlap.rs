//! The overlap (bearing-area, cut-off) model: no mechanics.
//!
//! # Formula
//! The flat at separation d simply cuts the undeformed surface; the contact
//! area is the area of the heights above the cut (Abbott & Firestone's
//! bearing-area curve), and the load follows from a hardness law:
//! ```text
//! Gaussian heights:  A/A0 = Prob(h > d) = F_0(d/h_rms) = ½ erfc(d/(√2 h_rms))
//! a measured map:    A/A0 = #{i : h_i − h̄ > d} / N
//! load:              σ0 = σY · A/A0          (F = H·A, every junction at the flow pressure H = σY)
//! ```
//! d (m) from the mean plane, h_rms (m), σY the hardness (any pressure unit,
//! σ0 comes out in it). The hardness law makes A/A0 exactly proportional to
//! the load while the separation d(σ0) = √2 h_rms erfc⁻¹(2σ0/σY) is not linear
//! in anything: it is the fully plastic limit, the counter-example the lecture
//! sets beside the elastic theories (whose linearity in load needs elasticity
//! and many asperity scales).
//!
//! # References
//! - E. J. Abbott, F. A. Firestone, Mech. Eng. 55, 569 (1933): the bearing-area curve.
//! - F. P. Bowden, D. Tabor, *The Friction and Lubrication of Solids* (Oxford 1950): F = H·A.
//! - J. F. Molinari, EPFL lecture "From single asperity to multi asperity
//!   contact": the overlap model beside GW, BGT and Persson.

use super::gaussian::{bearing_cut, bearing_fraction};
use super::{check_separation, AsperityPoint, AsperityTheory};
use crate::error::{check, Error, Result};

/// The heights the overlap model cuts.
#[derive(Debug, Clone, PartialEq)]
enum Heights {
    /// Gaussian with this rms height, m.
    Gaussian(f64),
    /// A map's heights about their mean, sorted ascending, m.
    Map(Vec<f64>),
}

/// The overlap model (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Overlap {
    heights: Heights,
    yield_stress: f64,
}

impl Overlap {
    /// Gaussian heights of rms `rms_height` (m) and hardness `yield_stress`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `rms_height` or `yield_stress`
    /// unless finite and > 0.
    ///
    /// # Examples
    /// ```
    /// use persson::asperity::{AsperityTheory, Overlap};
    /// let m = Overlap::gaussian(1e-6, 1e9).unwrap();
    /// let p = m.at_separation(0.0).unwrap(); // half the heights above the mean
    /// assert!((p.contact_fraction - 0.5).abs() < 1e-16);
    /// assert!((p.nominal_pressure - 0.5e9).abs() < 1e-6);
    /// ```
    pub fn gaussian(rms_height: f64, yield_stress: f64) -> Result<Self> {
        check::positive("rms_height", rms_height)?;
        check::positive("yield_stress", yield_stress)?;
        Ok(Overlap {
            heights: Heights::Gaussian(rms_height),
            yield_stress,
        })
    }

    /// A measured map's own heights (any layout; m) and the hardness.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming a non-finite height or
    /// `yield_stress`; [`Error::Inconsistent`] for fewer than 2 heights.
    pub fn from_heights(heights: &[f64], yield_stress: f64) -> Result<Self> {
        check::positive("yield_stress", yield_stress)?;
        if heights.len() < 2 {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!("at least 2 heights, got {}", heights.len()),
            });
        }
        if let Some(k) = heights.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid(format!("height[{k}]"), heights[k], "finite"));
        }
        let mean = heights.iter().sum::<f64>() / heights.len() as f64;
        let mut h: Vec<f64> = heights.iter().map(|v| v - mean).collect();
        h.sort_by(f64::total_cmp);
        Ok(Overlap {
            heights: Heights::Map(h),
            yield_stress,
        })
    }

    /// The hardness σY of the load law.
    pub fn yield_stress(&self) -> f64 {
        self.yield_stress
    }

    /// A/A0 at the cut `d` (module docs).
    fn fraction(&self, d: f64) -> f64 {
        match &self.heights {
            Heights::Gaussian(s) => bearing_fraction(d / s),
            Heights::Map(h) => {
                let below = h.partition_point(|&v| v <= d);
                (h.len() - below) as f64 / h.len() as f64
            }
        }
    }

    /// The cut whose bearing fraction is `f` ∈ (0, 1]: for a map the
    /// smallest height h_(k) with #{h > h_(k)} ≤ f N (k = ⌈N(1 − f)⌉).
    fn cut(&self, f: f64) -> f64 {
        match &self.heights {
            Heights::Gaussian(s) => s * bearing_cut(f),
            Heights::Map(h) => {
                let n = h.len();
                let k = ((n as f64) * (1.0 - f)).ceil() as usize;
                h[k.clamp(1, n) - 1]
            }
        }
    }
}

impl AsperityTheory for Overlap {
    fn at_separation(&self, separation: f64) -> Result<AsperityPoint> {
        let d = check_separation(separation)?;
        let f = self.fraction(d);
        Ok(AsperityPoint {
            separation: d,
            contact_fraction: f,
            nominal_pressure: self.yield_stress * f,
            contact_number_density: None,
            validity: Vec::new(),
        })
    }

    /// The hardness law gives A/A0 = σ0/σY exactly; the separation is the cut
    /// with that bearing fraction (for a map, the order statistic of
    /// [`Overlap`]'s docs, whose fraction is within 1/N of σ0/σY).
    fn at_pressure(&self, nominal_pressure: f64) -> Result<AsperityPoint> {
        check::positive("nominal_pressure", nominal_pressure)?;
        if nominal_pressure > self.yield_stress {
            return Err(Error::invalid(
                "nominal_pressure",
                nominal_pressure,
                format!(
                    "<= yield_stress = {} (full contact at σ0 = σY)",
                    self.yield_stress
                ),
            ));
        }
        let f = nominal_pressure / self.yield_stress;
        Ok(AsperityPoint {
            separation: self.cut(f),
            contact_fraction: f,
            nominal_pressure,
            contact_number_density: None,
            validity: Vec::new(),
        })
    }
}

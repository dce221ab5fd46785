//! The stress distribution in physical units: a start with its peak
//! pressure σH (Pa), an optional yield stress σY (Pa), and G(ζ) from a
//! spectrum at the nominal pressure σ0.
//!
//! # Formula
//! ```text
//! P(σ, ζ) = P̃(σ/σH; G(ζ), σY/σH) / σH,   σ0 = (σ0/σH) σH
//! ```
//! with P̃ the dimensionless density of [`super::Solver`].

use super::{distribution, HertzContact, Start, StressMethod};
use crate::error::{check, Error, Result};
use crate::quad::Estimate;
use crate::theory::Persson;

/// A physical stress problem: start condition, its pressures and an optional
/// yield stress, all in Pa.
#[derive(Debug, Clone, PartialEq)]
pub struct StressScene {
    /// Start condition.
    pub start: Start,
    /// σH, peak pressure of the start (Pa).
    pub peak_pressure: f64,
    /// σY (Pa); `None` for elastic.
    pub yield_stress: Option<f64>,
}

/// P(σ, ζ) in physical units at one magnification.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct PhysicalCurve {
    /// Magnification ζ.
    pub zeta: f64,
    /// G(ζ) and its absolute error.
    pub g: Estimate,
    /// σ (Pa).
    pub sigma: Vec<f64>,
    /// P(σ, ζ) (1/Pa).
    pub density: Vec<f64>,
    /// A/A0 = A_el/A0 + A_pl/A0, the total contact fraction.
    pub contact_fraction: f64,
    /// A_el/A0, the elastically loaded fraction.
    pub elastic_fraction: f64,
    /// A_pl/A0, the plastically yielded fraction.
    pub plastic_fraction: f64,
    /// Bound on the absolute error of σH·P (dimensionless; divided by σH,
    /// the bound on P in 1/Pa), not counting the error of G.
    pub scaled_density_error_bound: f64,
    /// Bound on the absolute error of `elastic_fraction`, not counting the
    /// error of G.
    pub elastic_fraction_error_bound: f64,
    /// Bound on the absolute error of `plastic_fraction`, not counting the
    /// error of G.
    pub plastic_fraction_error_bound: f64,
    /// How the density and the fractions were computed.
    pub method: StressMethod,
}

impl StressScene {
    /// A flat punch at nominal pressure σ0 (Pa).
    ///
    /// # Errors
    /// σ0 (`nominal_pressure`) or σY not finite and positive; σY ≤ σ0.
    pub fn flat(nominal_pressure: f64, yield_stress: Option<f64>) -> Result<Self> {
        // the flat start's peak pressure is σ0 itself: name the input given
        check::positive("nominal_pressure", nominal_pressure)?;
        Self::new(Start::Flat, nominal_pressure, yield_stress)
    }

    /// The start of a Hertz contact ([`HertzContact::ball`] / [`HertzContact::cylinder`]).
    ///
    /// # Errors
    /// σY not finite or ≤ σH.
    pub fn hertz(contact: &HertzContact, yield_stress: Option<f64>) -> Result<Self> {
        Self::new(contact.start.clone(), contact.peak_pressure, yield_stress)
    }

    /// A start with peak pressure σH (Pa).
    ///
    /// # Errors
    /// σH not finite and positive; σY not finite or ≤ σH.
    pub fn new(start: Start, peak_pressure: f64, yield_stress: Option<f64>) -> Result<Self> {
        check::positive("peak_pressure", peak_pressure)?;
        if let Some(s) = yield_stress {
            if !(s.is_finite() && s > peak_pressure) {
                return Err(Error::invalid(
                    "yield_stress",
                    s,
                    format!("finite and > the peak pressure {peak_pressure:e}"),
                ));
            }
        }
        Ok(StressScene {
            start,
            peak_pressure,
            yield_stress,
        })
    }

    /// σ0 = (σ0/σH) σH, the nominal mean pressure (Pa).
    pub fn nominal_pressure(&self) -> f64 {
        self.start.mean_ratio() * self.peak_pressure
    }

    /// P(σ, ζ) at each magnification of `zetas`, at pressures `sigma` (Pa),
    /// with G(ζ) from `model` at the nominal pressure σ0.
    ///
    /// # Formula
    /// ```text
    /// P(σ, ζ) = P̃(σ/σH; G(ζ), σY/σH) / σH
    /// ```
    /// # Errors
    /// ζ < 1; as [`super::Solver::new`].
    pub fn curves(
        &self,
        model: &Persson,
        zetas: &[f64],
        sigma: &[f64],
        tol: f64,
    ) -> Result<Vec<PhysicalCurve>> {
        let sh = self.peak_pressure;
        let s: Vec<f64> = sigma.iter().map(|v| v / sh).collect();
        let y = self.yield_stress.map(|v| v / sh);
        zetas
            .iter()
            .map(|&z| {
                let g = model.g(z, self.nominal_pressure())?;
                let c = distribution(&self.start, g.value, y, &s, tol)?;
                Ok(PhysicalCurve {
                    zeta: z,
                    g,
                    sigma: sigma.to_vec(),
                    density: c.scaled_density.iter().map(|p| p / sh).collect(),
                    contact_fraction: c.contact_fraction,
                    elastic_fraction: c.elastic_fraction,
                    plastic_fraction: c.plastic_fraction,
                    scaled_density_error_bound: c.scaled_density_error_bound,
                    elastic_fraction_error_bound: c.elastic_fraction_error_bound,
                    plastic_fraction_error_bound: c.plastic_fraction_error_bound,
                    method: c.method,
                })
            })
            .collect()
    }
}

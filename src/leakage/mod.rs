//! Leak rate of a static seal from Persson's theory: the critical junction
//! and the effective medium.
//!
//! # Formula
//! ```text
//! critical junction:  A(ζ_c)/A0 = a_c,   Q = (L_y/L_x) u1(ζ_c)³ Δ / (12 η)
//! effective medium:   A(ζ1)/A0 · (−1) + ∫ P_nc(u) (σ(u) − σ_eff)/(σ(u) + σ_eff) du = 0,
//!                     σ(u) = u³/(12 η),   Q = (L_y/L_x) σ_eff Δ
//! driving term Δ:     liquid  Δ = P_a − P_b
//!                     ideal gas, isothermal:  Δ = (P_a² − P_b²)/(2 P_b)   (Q at the outlet pressure)
//! ```
//! L_x is the seal's width along the flow (`seal_width`), L_y its length
//! across it (`seal_length`), η the viscosity, P_a and P_b the inlet and
//! outlet pressures. The critical junction is the constriction of the first
//! percolating non-contact channel: increase the magnification until the
//! apparent contact A(ζ)/A0 falls to the percolation threshold a_c (0.42 from
//! simulations, the default), and let the fluid pass one square junction of
//! height u1(ζ_c) ([`crate::gap::magnified`]) per square of the seal; the
//! L_y/L_x junctions in parallel give Q (Persson & Yang 2008; Lorenz &
//! Persson 2009). The effective medium is the 2-D
//! Bruggeman conductivity of the flow factor over the distribution P(u) of
//! [`crate::gap`], the contact at σ = 0 (Lorenz & Persson 2010); its
//! own threshold is A(ζ1)/A0 = ½. For a gas the mass flux is σ ρ ∇p with
//! ρ ∝ p, so p²/2 obeys the liquid's equation: Δ as above gives the
//! volumetric flow at the outlet pressure.
//!
//! A load at which the contact already percolates (A/A0 ≥ a_c at full
//! magnification, or ≥ ½ for the effective medium) gives Q = 0 and
//! [`LeakStatus::Sealed`]: a result, not an error.
//!
//! # References
//! (The papers' full texts were not available where this was written: the
//! formulas are our reading of them, checked by the identities and closed
//! forms in tests/leakage.rs; no equation numbers are cited.)
//! - B. N. J. Persson, C. Yang, J. Phys.: Condens. Matter 20, 315011 (2008),
//!   doi:10.1088/0953-8984/20/31/315011.
//! - B. Lorenz, B. N. J. Persson, EPL 86, 44006 (2009), doi:10.1209/0295-5075/86/44006.
//! - B. Lorenz, B. N. J. Persson, Eur. Phys. J. E 32, 281 (2010),
//!   (effective medium).
//! - D. A. G. Bruggeman, Ann. Phys. 416, 636 (1935) (the effective medium).
//! - W. B. Dapp, A. Lücke, B. N. J. Persson, M. H. Müser, Phys. Rev. Lett.
//!   108, 244301 (2012), doi:10.1103/PhysRevLett.108.244301 (a_c ≈ 0.42).

pub mod critical;
pub mod effective;

pub use critical::{CriticalJunction, CriticalJunctionPoint};
pub use effective::{bruggeman, EffectiveMedium, EffectiveMediumPoint};

use serde::Serialize;

use crate::error::{check, Error, Result};

/// Default percolation threshold a_c of the critical junction (Dapp et al. 2012).
pub const DEFAULT_PERCOLATION_THRESHOLD: f64 = 0.42;

/// The fluid of a seal: what a [`Drive`] drives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fluid {
    /// An incompressible liquid ([`Drive::Liquid`]).
    Liquid,
    /// An isothermal ideal gas ([`Drive::Gas`]).
    Gas,
}

crate::names::named! {
    Fluid, "fluid", "The fluid of a seal." {
        Liquid = "liquid": "Incompressible liquid, driven by ΔP.",
        Gas = "gas": "Isothermal ideal gas from P_a to P_b (Q at P_b).",
    }
}

/// Direction of the mean flow through a seal on a grid `f[i·N + j]` (the
/// BEM's Reynolds flow, `bem::reynolds` with the feature `flow`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlowDirection {
    /// Along the second index j of `f[i·N + j]` (within a row).
    X,
    /// Along the first index i (across rows).
    Y,
}

crate::names::named! {
    FlowDirection, "direction", "Direction of the mean flow on the grid." {
        X = "x": "Along the second index j of `f[i·N + j]`.",
        Y = "y": "Along the first index i.",
    }
}

/// What drives the flow through the seal.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "fluid")]
pub enum Drive {
    /// An incompressible liquid under the pressure drop Δ = P_a − P_b (Pa).
    Liquid {
        /// P_a − P_b, Pa, > 0.
        pressure_drop: f64,
    },
    /// An isothermal ideal gas from P_a to P_b (Pa, absolute); the leak rate
    /// is the volumetric flow at P_b.
    Gas {
        /// Inlet pressure P_a, Pa.
        inlet_pressure: f64,
        /// Outlet pressure P_b, Pa, 0 < P_b < P_a.
        outlet_pressure: f64,
    },
}

impl Drive {
    /// The fluid driven.
    pub fn fluid(&self) -> Fluid {
        match self {
            Drive::Liquid { .. } => Fluid::Liquid,
            Drive::Gas { .. } => Fluid::Gas,
        }
    }

    /// Check the pressures.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `pressure_drop`, `inlet_pressure` or
    /// `outlet_pressure` (not finite and positive, or P_b ≥ P_a).
    pub fn validate(&self) -> Result<()> {
        match *self {
            Drive::Liquid { pressure_drop } => {
                check::positive("pressure_drop", pressure_drop)?;
            }
            Drive::Gas {
                inlet_pressure,
                outlet_pressure,
            } => {
                check::positive("inlet_pressure", inlet_pressure)?;
                check::positive("outlet_pressure", outlet_pressure)?;
                if outlet_pressure >= inlet_pressure {
                    return Err(Error::invalid(
                        "outlet_pressure",
                        outlet_pressure,
                        format!(
                            "below inlet_pressure = {}",
                            crate::error::num(inlet_pressure)
                        ),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The driving term Δ (Pa): P_a − P_b, or (P_a² − P_b²)/(2P_b) for a gas,
    /// the latter as (P_a − P_b)(P_a + P_b)/(2P_b) without cancellation.
    ///
    /// # Errors
    /// As [`Drive::validate`].
    pub fn driving_pressure(&self) -> Result<f64> {
        self.validate()?;
        Ok(match *self {
            Drive::Liquid { pressure_drop } => pressure_drop,
            Drive::Gas {
                inlet_pressure: a,
                outlet_pressure: b,
            } => (a - b) * (a + b) / (2.0 * b),
        })
    }
}

/// The seal and the fluid: everything beyond the surface and E*.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Seal {
    /// L_x, the seal's width along the flow, m.
    pub seal_width: f64,
    /// L_y, the seal's length across the flow (e.g. the circumference of an
    /// O-ring), m.
    pub seal_length: f64,
    /// Dynamic viscosity η, Pa s.
    pub viscosity: f64,
    /// The pressures driving the flow.
    pub drive: Drive,
}

impl Seal {
    /// Check every field.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `seal_width`, `seal_length`,
    /// `viscosity` or a pressure of [`Drive::validate`]; naming the one of
    /// them furthest from 1 in order of magnitude when the leak rate's
    /// prefactor (L_y/L_x) Δ/(12η) exceeds f64::MAX/1e30.
    pub fn validate(&self) -> Result<()> {
        check::positive("seal_width", self.seal_width)?;
        check::positive("seal_length", self.seal_length)?;
        check::positive("viscosity", self.viscosity)?;
        self.drive.validate()?;
        self.check_prefactor()
    }

    /// Refuse a seal whose prefactor f = (L_y/L_x) Δ/(12η) of Q = f u³ (the
    /// cube law; Q = 12η f σ_eff for the effective medium) leaves f64:
    /// Q = ∞ at L_y = 1e300, or at P_b = 1e-300 where Δ = (P_a² − P_b²)/(2P_b)
    /// overflowed.
    ///
    /// # Bound
    /// ln f = ln L_y − ln L_x − ln 12η + ln Δ, with ln Δ = ln(P_a − P_b)
    /// (liquid) or 2 ln P_a + ln(1 − (P_b/P_a)²) − ln 2P_b (gas), must be at
    /// most ln(f64::MAX/1e30): f then leaves room for the u³ ≤ 1e30 m³ it
    /// multiplies (any separation below 1e10 m). Decided in logarithms. The
    /// input furthest from 1 in order of magnitude (the typing error) is
    /// named, with the bound on it that the others leave: its exponent e in
    /// f (+1 for L_y and Δ, −1 for L_x, η and, to leading order, P_b, +2 for
    /// P_a) moves ln f by e ln x, so x ≤ x e^{−excess/e} (e > 0) or
    /// x ≥ x e^{excess/|e|} (e < 0).
    fn check_prefactor(&self) -> Result<()> {
        // (name, value, exponent, contribution to ln f)
        let mut factors: Vec<(&str, f64, f64, f64)> = vec![
            ("seal_length", self.seal_length, 1.0, self.seal_length.ln()),
            ("seal_width", self.seal_width, -1.0, -self.seal_width.ln()),
            (
                "viscosity",
                self.viscosity,
                -1.0,
                -(12.0 * self.viscosity).ln(),
            ),
        ];
        match self.drive {
            Drive::Liquid { pressure_drop } => {
                factors.push(("pressure_drop", pressure_drop, 1.0, pressure_drop.ln()));
            }
            Drive::Gas {
                inlet_pressure: a,
                outlet_pressure: b,
            } => {
                let r = b / a;
                factors.push(("inlet_pressure", a, 2.0, 2.0 * a.ln()));
                factors.push((
                    "outlet_pressure",
                    b,
                    -1.0,
                    (1.0 - r * r).ln() - (2.0 * b).ln(),
                ));
            }
        }
        let ln_f: f64 = factors.iter().map(|f| f.3).sum();
        let ln_max = f64::MAX.ln() - 1e30f64.ln();
        if ln_f <= ln_max {
            return Ok(());
        }
        let (name, value, exponent, _) = factors.iter().copied().fold(factors[0], |a, b| {
            if b.1.ln().abs() > a.1.ln().abs() {
                b
            } else {
                a
            }
        });
        // in logarithms: the factor e^{excess} alone may overflow
        let bound = (value.ln() - (ln_f - ln_max) / exponent).exp();
        Err(Error::invalid(
            name,
            value,
            format!(
                "{} {} (with the seal's other inputs) so that the leak rate's prefactor \
                 (L_y/L_x) Δ/(12η) stays below f64::MAX/1e30",
                if exponent > 0.0 {
                    "at most"
                } else {
                    "at least"
                },
                crate::error::approx(bound)
            ),
        ))
    }

    /// Q = (L_y/L_x) σ Δ for a flow conductivity σ (m³/(Pa s)), m³/s.
    ///
    /// # Errors
    /// As [`Seal::validate`]; σ negative or not finite.
    pub fn leak_rate(&self, flow_conductivity: f64) -> Result<f64> {
        self.validate()?;
        check::non_negative("flow_conductivity", flow_conductivity)?;
        Ok(self.seal_length / self.seal_width
            * flow_conductivity
            * self.drive.driving_pressure()?)
    }
}

/// Whether fluid passes the seal at a load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LeakStatus {
    /// The non-contact area percolates: Q > 0.
    Leaking,
    /// The contact percolates at full magnification (A/A0 at q_s is above
    /// the method's threshold): no channel crosses the seal, Q = 0.
    Sealed,
}

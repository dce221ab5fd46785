//! The effective-medium (2-D Bruggeman) leak rate (module docs of
//! [`crate::leakage`]).

use serde::Serialize;

use super::{LeakStatus, Seal};
use crate::error::{check, Error, Result};
use crate::gap::{DensityOptions, SeparationDensity};
use crate::quad::Estimate;
use crate::spectrum::Spectrum;

/// Relative width of the final bracket of σ_eff.
const ROOT_TOLERANCE: f64 = 1e-13;

/// Absolute tolerance of each node's u-integral of the Bruggeman residual
/// (the residual is a mean of values in [−1, 1]).
const NODE_TOLERANCE: f64 = 1e-11;

/// The 2-D Bruggeman conductivity of a discrete mixture.
///
/// # Formula
/// ```text
/// Σ_i f_i (σ_i − σ_eff)/(σ_i + σ_eff) = 0,   Σ f_i = 1
/// two phases, a at σ = 0 and 1 − a at σ1:  σ_eff = σ1 (1 − 2a)  (a < ½), else 0
/// ```
/// The residual decreases monotonically in σ_eff; the root is bracketed in
/// ln σ_eff and found by the Illinois variant of false position to
/// `ROOT_TOLERANCE` (1e-13) relative. A mixture whose conducting fraction is
/// at most ½ has σ_eff = 0 (below the 2-D threshold).
///
/// # Errors
/// A fraction or conductivity negative or not finite; fractions not summing
/// to 1 within 1e-12.
///
/// # References
/// D. A. G. Bruggeman, Ann. Phys. 416, 636 (1935); S. Kirkpatrick, Rev. Mod.
/// Phys. 45, 574 (1973) (the d-dimensional form; d = 2 here).
///
/// # Examples
/// ```
/// // 30 % blocked, 70 % at σ1 = 2: σ_eff = 2 (1 − 0.6) = 0.8
/// let s = persson::leakage::bruggeman(&[(0.3, 0.0), (0.7, 2.0)]).unwrap();
/// assert!((s - 0.8).abs() < 1e-12); // root bracketed to 1e-13 in ln σ
/// ```
pub fn bruggeman(phases: &[(f64, f64)]) -> Result<f64> {
    let mut sum = 0.0;
    let mut top: f64 = 0.0;
    for &(f, s) in phases {
        check::non_negative("fraction", f)?;
        check::non_negative("flow_conductivity", s)?;
        sum += f;
        top = top.max(s);
    }
    if (sum - 1.0).abs() > 1e-12 {
        return Err(Error::invalid("fraction", sum, "fractions summing to 1"));
    }
    let residual = |s: f64| -> Result<Estimate> {
        Ok(Estimate {
            value: phases.iter().map(|&(f, c)| f * (c - s) / (c + s)).sum(),
            error: 0.0,
        })
    };
    Ok(solve(&residual, top, f64::MIN_POSITIVE.sqrt() * top)?.value)
}

/// Root of a decreasing residual r(σ) on (0, hi]: 0 when r(lo) ≤ 0.
/// The error comes from r's error over its slope at the root.
fn solve(r: &dyn Fn(f64) -> Result<Estimate>, hi: f64, lo: f64) -> Result<Estimate> {
    if hi <= 0.0 {
        return Ok(Estimate {
            value: 0.0,
            error: 0.0,
        });
    }
    let (mut a, mut b) = (lo.ln(), hi.ln());
    let (mut fa, mut fb) = (r(lo)?.value, r(hi)?.value);
    if fa <= 0.0 {
        return Ok(Estimate {
            value: 0.0,
            error: 0.0,
        });
    }
    if fb >= 0.0 {
        return Ok(Estimate {
            value: hi,
            error: 0.0,
        });
    }
    let mut side = 0i32;
    let mut last = Estimate {
        value: 0.0,
        error: 0.0,
    };
    for _ in 0..300 {
        let t = (a * fb - b * fa) / (fb - fa);
        let t = if t > a && t < b { t } else { 0.5 * (a + b) };
        last = r(t.exp())?;
        if last.value > 0.0 {
            a = t;
            fa = last.value;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        } else {
            b = t;
            fb = last.value;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        }
        if (b - a) <= ROOT_TOLERANCE || last.value == 0.0 {
            break;
        }
    }
    let t = 0.5 * (a + b);
    let s = t.exp();
    // |dr/d ln σ| from the bracket; the residual's error moves the root by δr/|r′|.
    let slope = ((fa - fb) / (b - a).max(f64::EPSILON))
        .abs()
        .max(f64::MIN_POSITIVE);
    Ok(Estimate {
        value: s,
        error: s * ((b - a) + last.error / slope),
    })
}

/// The effective medium at one nominal pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct EffectiveMediumPoint {
    /// Nominal pressure σ0 (unit of E*).
    pub nominal_pressure: f64,
    /// Whether the seal leaks (sealed: A(ζ1)/A0 ≥ ½, the 2-D Bruggeman threshold).
    pub status: LeakStatus,
    /// A(ζ1)/A0 at full magnification.
    pub contact_fraction: f64,
    /// σ_eff, m³/(Pa s).
    pub effective_flow_conductivity: f64,
    /// Bound on the absolute error of σ_eff.
    pub effective_flow_conductivity_error_bound: f64,
    /// Q = (L_y/L_x) σ_eff Δ, m³/s.
    pub leak_rate: f64,
    /// Bound on the absolute error of Q, m³/s.
    pub leak_rate_error_bound: f64,
}

/// The effective-medium leak rate for one spectrum, E* and seal.
pub struct EffectiveMedium<'a> {
    spectrum: &'a dyn Spectrum,
    contact_modulus: f64,
    seal: Seal,
    options: DensityOptions,
}

impl<'a> EffectiveMedium<'a> {
    /// The model, with P(u) built with `options`.
    ///
    /// # Errors
    /// E* not finite and positive; a bad seal ([`Seal::validate`]).
    pub fn new(
        spectrum: &'a dyn Spectrum,
        contact_modulus: f64,
        seal: Seal,
        options: DensityOptions,
    ) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        seal.validate()?;
        Ok(EffectiveMedium {
            spectrum,
            contact_modulus,
            seal,
            options,
        })
    }

    /// σ_eff and Q at σ0 = `pressure`.
    ///
    /// # Errors
    /// σ0 not finite and positive; quadrature failures.
    pub fn point(&self, pressure: f64) -> Result<EffectiveMediumPoint> {
        let density =
            SeparationDensity::new(self.spectrum, self.contact_modulus, pressure, &self.options)?;
        self.point_from(&density)
    }

    /// σ_eff and Q from a P(u) already built.
    ///
    /// # Errors
    /// Quadrature failures.
    pub fn point_from(&self, density: &SeparationDensity) -> Result<EffectiveMediumPoint> {
        let eta12 = 12.0 * self.seal.viscosity;
        let a1 = density.contact_fraction();
        let mut out = EffectiveMediumPoint {
            nominal_pressure: density.nominal_pressure(),
            status: LeakStatus::Sealed,
            contact_fraction: a1,
            effective_flow_conductivity: 0.0,
            effective_flow_conductivity_error_bound: 0.0,
            leak_rate: 0.0,
            leak_rate_error_bound: 0.0,
        };
        if a1 >= 0.5 {
            return Ok(out);
        }
        let u_max = density.largest_separation();
        let hi = u_max.powi(3) / eta12;
        let residual = |s: f64| -> Result<Estimate> {
            let cube = s * eta12; // compare u³ with 12η σ_eff
                                  // (u³ − c)/(u³ + c) = 1 − 2c/(u³ + c): finite where u³ overflows
            let f = move |u: f64| 1.0 - 2.0 * cube / (u * u * u + cube);
            let e = density.expectation(&f, NODE_TOLERANCE, 0.0)?;
            Ok(Estimate {
                value: e.value - a1,
                error: e.error,
            })
        };
        let s = solve(&residual, hi, hi * 1e-60)?;
        if s.value > 0.0 {
            out.status = LeakStatus::Leaking;
        }
        let q = self.seal.leak_rate(s.value)?;
        out.effective_flow_conductivity = s.value;
        out.effective_flow_conductivity_error_bound = s.error;
        out.leak_rate = q;
        out.leak_rate_error_bound = self.seal.leak_rate(s.error)? + 8.0 * f64::EPSILON * q;
        Ok(out)
    }

    /// [`EffectiveMedium::point`] for each pressure.
    ///
    /// # Errors
    /// As [`EffectiveMedium::point`], for the first bad pressure.
    pub fn load_curve(&self, pressures: &[f64]) -> Result<Vec<EffectiveMediumPoint>> {
        for &p in pressures {
            check::positive("nominal_pressure", p)?;
        }
        pressures.iter().map(|&p| self.point(p)).collect()
    }
}

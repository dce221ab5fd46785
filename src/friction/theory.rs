//! The friction problem (spectrum, rubber, cut-off, γ, tolerance) and its
//! typed results.

use std::f64::consts::TAU;

use super::angular::AngularModel;
use super::march::{Conditions, Run};
use super::problem::Friction;
use super::result::FrictionPoint;
use super::rubber::Rubber;
use super::viscoelastic::Viscoelastic;
use crate::error::{check, Error, Result};
use crate::spectrum::Spectrum;

/// Default γ of S(q) = γ + (1 − γ) P(q)² (Persson 2006).
pub const DEFAULT_GAMMA: f64 = 0.5;

/// Default relative tolerance of μ, G and the flash temperature.
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

/// Default number of magnifications per decade in the profiles.
pub const DEFAULT_POINTS_PER_DECADE: usize = 4;

/// Bisection steps of the rms-slope criterion (the bracket halves each step).
const CUTOFF_BISECTIONS: usize = 200;

/// The upper cut-off q1 of the friction integrals.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum CutOff {
    /// q1 = the spectrum's upper end q_s.
    SpectrumEnd,
    /// q1 given, 1/m, in (q_l, q_s].
    Wavevector(f64),
    /// q1 where the rms slope of the roughness with q_l ≤ q ≤ q1 reaches this
    /// value: (2π ∫_{q_l}^{q1} q³ C dq)^{1/2} = h′_rms (Lorenz et al. 2011 cut
    /// the spectrum where the rms slope reaches a value of order one; the
    /// value is the caller's).
    RmsSlope(f64),
}

/// Settings of a friction calculation.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionOptions {
    /// γ in S = γ + (1 − γ) P², in [0, 1].
    pub gamma: f64,
    /// The cut-off q1.
    pub cutoff: CutOff,
    /// Relative tolerance of μ, G and the flash temperature, in [1e-15, 0.1].
    pub tolerance: f64,
    /// Wavevectors (1/m) where C(q) has a kink (a roll-off, table nodes):
    /// panel boundaries of the q-integrals.
    pub breaks: Vec<f64>,
    /// Magnifications per decade of the profiles (1 to 100); they are also
    /// panel boundaries.
    pub points_per_decade: usize,
}

impl Default for FrictionOptions {
    fn default() -> Self {
        FrictionOptions {
            gamma: DEFAULT_GAMMA,
            cutoff: CutOff::SpectrumEnd,
            tolerance: DEFAULT_TOLERANCE,
            breaks: Vec::new(),
            points_per_decade: DEFAULT_POINTS_PER_DECADE,
        }
    }
}

impl<'a> Friction<'a> {
    /// Set up the theory: resolve q1, build the angular integrals.
    ///
    /// # Errors
    /// `gamma` outside [0, 1]; `tolerance` outside [1e-15, 0.1];
    /// `points_per_decade` outside 1..=100; a break not finite and > 0; q1
    /// (`q1`) outside (q_l, q_s]; an rms slope (`q1_rms_slope`) not finite and
    /// > 0 or above the spectrum's full rms slope.
    pub fn new(
        spectrum: &'a dyn Spectrum,
        rubber: &'a Rubber,
        options: &FrictionOptions,
    ) -> Result<Self> {
        if !(options.gamma.is_finite() && (0.0..=1.0).contains(&options.gamma)) {
            return Err(Error::invalid("gamma", options.gamma, "in [0, 1]"));
        }
        let tolerance = check::tolerance("tolerance", options.tolerance)?;
        if !(1..=100).contains(&options.points_per_decade) {
            return Err(Error::invalid(
                "points_per_decade",
                options.points_per_decade as f64,
                "an integer in 1..=100",
            ));
        }
        for &b in &options.breaks {
            check::positive("break", b)?;
        }
        let q1 = cutoff(spectrum, options.cutoff)?;
        let angular = AngularModel::new(rubber.viscoelastic(), (1e-3 * tolerance).max(1e-14))?;
        let table_ln = match rubber.viscoelastic() {
            Viscoelastic::MasterCurve(m) => m.ln_frequencies(),
            _ => Vec::new(),
        };
        Ok(Friction {
            spectrum,
            rubber,
            gamma: options.gamma,
            tolerance,
            q1,
            breaks: options.breaks.clone(),
            points_per_decade: options.points_per_decade,
            angular,
            table_ln,
        })
    }

    /// The cut-off q1, 1/m.
    pub fn q1(&self) -> f64 {
        self.q1
    }

    /// Refuse a σ0 so small against the rubber's modulus that G overflows.
    ///
    /// # Bound
    /// The march integrates dG = ½ q³C (b_T/((1 − ν²)σ0))² B(qv a_T) dq with
    /// B(w) = ∫₀¹ |E(wu)|² (1 − u²)^{−1/2} du ≤ (π/2)|E|²_max, so
    /// ```text
    /// G ≤ (E_eff/σ0)² ⟨|∇h|²⟩/8,   E_eff = b_T |E|_max/(1 − ν²)
    /// ```
    /// (⟨|∇h|²⟩ over [q_l, q1]): the bound of `theory::check_g_finite` with
    /// E* replaced by E_eff, σ0 ≥ E_eff/r_max. |E|_max is the glassy modulus
    /// (Prony) or the table's largest (master curve); b_T is the vertical
    /// shift at the background temperature. The moduli themselves are held
    /// below [`super::MAX_MODULUS`].
    fn check_load(&self, nominal_pressure: f64, vertical_shift: f64) -> Result<()> {
        let one_minus = 1.0 - self.rubber.poisson().powi(2);
        let e_eff = vertical_shift * self.rubber.viscoelastic().max_modulus() / one_minus;
        let q_l = self.spectrum.q_min();
        let slope = std::f64::consts::TAU * self.spectrum.moment(3, q_l, self.q1)?.value;
        crate::theory::check_g_finite(e_eff, nominal_pressure, slope).map_err(|_| {
            let r_max = (f64::MAX / (slope / 8.0).max(1.0)).sqrt();
            Error::invalid(
                "nominal_pressure",
                nominal_pressure,
                format!(
                    "at least {} (|E|_max = {} Pa, ν = {}, ⟨|∇h|²⟩ = {}) so that \
                     G = (b_T|E|/((1 − ν²)σ0))²⟨|∇h|²⟩/8 stays finite in f64",
                    crate::error::approx(e_eff / r_max),
                    crate::error::approx(e_eff * one_minus / vertical_shift),
                    self.rubber.poisson(),
                    crate::error::approx(slope)
                ),
            )
        })
    }

    /// The rubber.
    pub fn rubber(&self) -> &Rubber {
        self.rubber
    }

    /// μ, A/A0 and the rest at sliding velocity v (m/s), background
    /// temperature T (K) and nominal pressure σ0 (Pa); with the flash
    /// temperature too when the rubber has thermal properties.
    ///
    /// # Errors
    /// `velocity` or `nominal_pressure` not finite and > 0; `nominal_pressure`
    /// so small against the modulus that G = (b_T|E|_max/((1 − ν²)σ0))²
    /// ⟨|∇h|²⟩/8 overflows f64; `temperature` as in
    /// [`super::TemperatureShift::factors`]; [`Error::NotConverged`] when an
    /// integrand is not finite.
    pub fn point(
        &self,
        velocity: f64,
        temperature: f64,
        nominal_pressure: f64,
    ) -> Result<FrictionPoint> {
        let c = Conditions {
            velocity: check::positive("velocity", velocity)?,
            temperature,
            nominal_pressure: check::positive("nominal_pressure", nominal_pressure)?,
            factors: self.rubber.shift_factors(temperature)?,
        };
        self.check_load(nominal_pressure, c.factors.vertical_shift)?;
        let isothermal = Run::new(self, &c, None).solve()?;
        let flash = match self.rubber.thermal() {
            Some(t) => Some(Run::new(self, &c, Some(t)).solve()?),
            None => None,
        };
        Ok(FrictionPoint {
            velocity,
            temperature,
            nominal_pressure,
            q1: self.q1,
            shift_factor: c.factors.shift_factor,
            vertical_shift: c.factors.vertical_shift,
            isothermal,
            flash,
        })
    }

    /// [`Friction::point`] for every temperature, pressure and velocity
    /// (temperature outermost, velocity innermost).
    ///
    /// # Errors
    /// The first error of [`Friction::point`].
    pub fn sweep(
        &self,
        velocities: &[f64],
        temperatures: &[f64],
        pressures: &[f64],
    ) -> Result<Vec<FrictionPoint>> {
        let mut out = Vec::with_capacity(velocities.len() * temperatures.len() * pressures.len());
        for &t in temperatures {
            for &p in pressures {
                for &v in velocities {
                    out.push(self.point(v, t, p)?);
                }
            }
        }
        Ok(out)
    }
}

/// n velocities log-spaced from v_min to v_max (m/s), both included.
///
/// # Errors
/// `velocity_min`, `velocity_max` not finite and > 0 or v_max < v_min;
/// n < 2 unless v_min = v_max (then n = 1).
pub fn log_velocities(velocity_min: f64, velocity_max: f64, n: usize) -> Result<Vec<f64>> {
    check::positive("velocity_min", velocity_min)?;
    check::positive("velocity_max", velocity_max)?;
    if velocity_max < velocity_min {
        return Err(Error::Inconsistent {
            name: "velocity_min, velocity_max".into(),
            requirement: format!(
                "velocity_min <= velocity_max, got {velocity_min:e} > {velocity_max:e}"
            ),
        });
    }
    if n == 1 && velocity_min == velocity_max {
        return Ok(vec![velocity_min]);
    }
    if n < 2 {
        return Err(Error::invalid(
            "velocity_range.points",
            n as f64,
            "a whole number of at least 2 (1 only when velocity_min = velocity_max)",
        ));
    }
    let r = (velocity_max / velocity_min).ln();
    Ok((0..n)
        .map(|i| match i {
            0 => velocity_min,
            _ if i == n - 1 => velocity_max,
            _ => velocity_min * (r * i as f64 / (n - 1) as f64).exp(),
        })
        .collect())
}

/// Resolve the cut-off on the spectrum.
fn cutoff(spectrum: &dyn Spectrum, c: CutOff) -> Result<f64> {
    let (lo, hi) = (spectrum.q_min(), spectrum.q_max());
    match c {
        CutOff::SpectrumEnd => Ok(hi),
        CutOff::Wavevector(q1) => {
            if q1.is_finite() && q1 > lo && q1 <= hi {
                Ok(q1)
            } else {
                Err(Error::invalid(
                    "q1",
                    q1,
                    format!("in (q_l, q_s] = ({lo:e}, {hi:e}] 1/m"),
                ))
            }
        }
        CutOff::RmsSlope(s) => {
            check::positive("q1_rms_slope", s)?;
            let target = s * s / TAU;
            let full = spectrum.moment(3, lo, hi)?.value;
            if target > full {
                return Err(Error::invalid(
                    "q1_rms_slope",
                    s,
                    format!("<= the spectrum's rms slope {:.6}", (TAU * full).sqrt()),
                ));
            }
            let (mut a, mut b) = (lo.ln(), hi.ln());
            for _ in 0..CUTOFF_BISECTIONS {
                let m = 0.5 * (a + b);
                if m <= a || m >= b {
                    break;
                }
                if spectrum.moment(3, lo, m.exp())?.value < target {
                    a = m;
                } else {
                    b = m;
                }
            }
            Ok(b.exp().min(hi))
        }
    }
}

//! Thermal and electrical contact conductance of a rough interface: through
//! the contact spots from the stiffness (Barber's identity), and through the
//! gap from the distribution of separations.
//!
//! # Formula
//! ```text
//! electrical:  h_e = 2 (K/A0) / ((ρ1 + ρ2) E*)                 [S/m²]
//! thermal:     h_c = 2 κ_s (K/A0) / E*,   1/κ_s = 1/κ1 + 1/κ2  [W/(m² K)]
//! gap:         h_gap = ∫_{0+}^∞ P_nc(u) α(u) du,   gas: α(u) = κ_gas/(u + 2ℓ)
//! ```
//! K/A0 = −dσ0/dū is the contact stiffness per nominal area
//! ([`crate::separation::Separation::stiffness`], Pa/m), E* the contact
//! modulus (Pa), ρ1, ρ2 the bodies' resistivities (Ω m), κ1, κ2 their thermal
//! conductivities (W/(m K)), P_nc the non-contact part of P(u)
//! ([`crate::gap`]), α(u) the heat-transfer coefficient of a gap of width u
//! (W/(m² K)), κ_gas the gas's conductivity and ℓ a length of the order of
//! its mean free path (the temperature-jump distance of each wall).
//!
//! Barber's identity: for frictionless elastic bodies the electrical
//! conductance C of the contact and its incremental stiffness K = dF/dδ obey
//! C = 2K/((ρ1 + ρ2)E*) whatever the shape of the contact (Barber 2003,
//! the proof maps the potential problem on the conductance problem of
//! the same contact set). Check on one circular spot of radius a: the flat
//! punch has K = 2E*a (Boussinesq; Johnson, *Contact Mechanics*, ch. 3), so
//! C = 4a/(ρ1 + ρ2), Holm's constriction conductance of two half-spaces
//! (Holm, *Electric Contacts* (1967)); the Hertz ball has the same
//! K = dF/dδ = 2E*a and an isopotential circular contact, so the same C
//! (tested). The thermal form replaces ρ_i by 1/κ_i: C_th = 2Kκ_s/E*, with
//! 1/κ_s = 1/κ1 + 1/κ2 the series conductivity (Holm: 4aκ1κ2/(κ1 + κ2)).
//! Persson, Lorenz & Volokitin (2010) write the contact part of the heat
//! transfer coefficient the same way, α_contact = 2κ_s(−dσ0/dū)/E* with
//! 1/κ_s = 1/κ1 + 1/κ2 and E* of the pair, to our reading (the paper's text
//! was not at hand here, so no equation number is cited; the factor is the
//! one fixed above by Holm's spot, which the tests check).
//! Per nominal area, K/A0 turns C into h. The gap term counts only where the
//! surfaces do not touch (the δ(u) of the contact is carried by K).
//!
//! # References
//! - J. R. Barber, Proc. R. Soc. Lond. A 459, 53 (2003), doi:10.1098/rspa.2002.1038.
//! - R. Holm, *Electric Contacts*, 4th ed., Springer (1967): constriction
//!   resistance ρ/(4a) of a circular spot on a half-space.
//! - B. N. J. Persson, B. Lorenz, A. I. Volokitin, Eur. Phys. J. E 31, 3 (2010),
//!   (heat transfer; equation numbers not checked here).
//! - B. N. J. Persson, Phys. Rev. Lett. 99, 125502 (2007) (K from ū(σ0)).

use serde::Serialize;

use crate::error::{check, Error, Result};
use crate::gap::{DensityOptions, PointSet, SeparationDensity, SeparationTable};
use crate::quad::Estimate;
use crate::separation::Separation;
use crate::spectrum::Spectrum;

/// Electrical resistivities ρ1, ρ2 of the two bodies, Ω m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Resistivity {
    /// ρ1, Ω m.
    pub resistivity: f64,
    /// ρ2, Ω m.
    pub resistivity2: f64,
}

impl Resistivity {
    /// Two bodies.
    ///
    /// # Errors
    /// Either not finite and positive ([`Error::InvalidParameter`] naming
    /// `resistivity` or `resistivity2`).
    pub fn new(resistivity: f64, resistivity2: f64) -> Result<Self> {
        Ok(Resistivity {
            resistivity: check::positive("resistivity", resistivity)?,
            resistivity2: check::positive("resistivity2", resistivity2)?,
        })
    }

    /// Both bodies of one resistivity.
    ///
    /// # Errors
    /// As [`Resistivity::new`].
    pub fn both(resistivity: f64) -> Result<Self> {
        Self::new(resistivity, resistivity)
    }

    /// ρ1 + ρ2.
    pub fn sum(&self) -> f64 {
        self.resistivity + self.resistivity2
    }
}

/// Thermal conductivities κ1, κ2 of the two bodies, W/(m K).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Conductivity {
    /// κ1, W/(m K).
    pub conductivity: f64,
    /// κ2, W/(m K).
    pub conductivity2: f64,
}

impl Conductivity {
    /// Two bodies.
    ///
    /// # Errors
    /// Either not finite and positive ([`Error::InvalidParameter`] naming
    /// `conductivity` or `conductivity2`).
    pub fn new(conductivity: f64, conductivity2: f64) -> Result<Self> {
        Ok(Conductivity {
            conductivity: check::positive("conductivity", conductivity)?,
            conductivity2: check::positive("conductivity2", conductivity2)?,
        })
    }

    /// Both bodies of one conductivity.
    ///
    /// # Errors
    /// As [`Conductivity::new`].
    pub fn both(conductivity: f64) -> Result<Self> {
        Self::new(conductivity, conductivity)
    }

    /// κ_s = κ1κ2/(κ1 + κ2) (1/κ_s = 1/κ1 + 1/κ2), without overflow.
    pub(crate) fn series(&self) -> f64 {
        let (a, b) = (self.conductivity, self.conductivity2);
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        lo / (1.0 + lo / hi)
    }
}

/// Electrical conductance from a stiffness by Barber's identity (module docs).
///
/// # Formula
/// ```text
/// C = 2 K / ((ρ1 + ρ2) E*)
/// ```
/// K per nominal area (Pa/m) gives h_e (S/m²); a total stiffness (N/m)
/// gives the conductance (S). The error of K is carried over.
///
/// # Errors
/// `contact_modulus` not finite and positive; K negative or NaN (`stiffness`).
///
/// # Examples
/// ```
/// use persson::conductance::{electrical_conductance, Resistivity};
/// use persson::Estimate;
/// // Holm's spot: a flat punch of radius a has K = 2E*a, so C = 4a/(ρ1 + ρ2).
/// let (a, e_star) = (1e-4, 1e11);
/// let rho = Resistivity::new(1.7e-8, 2.8e-8).unwrap();
/// let k = Estimate { value: 2.0 * e_star * a, error: 0.0 };
/// let c = electrical_conductance(k, e_star, &rho).unwrap();
/// assert!((c.value - 4.0 * a / 4.5e-8).abs() < 1e-15 * c.value);
/// ```
pub fn electrical_conductance(
    stiffness: Estimate,
    contact_modulus: f64,
    resistivity: &Resistivity,
) -> Result<Estimate> {
    check::positive("contact_modulus", contact_modulus)?;
    let f = 2.0 / (resistivity.sum() * contact_modulus);
    scale(stiffness, f)
}

/// Thermal conductance from a stiffness by Barber's identity (module docs).
///
/// # Formula
/// ```text
/// C_th = 2 κ_s K / E*,   1/κ_s = 1/κ1 + 1/κ2
/// ```
///
/// # Errors
/// As [`electrical_conductance`].
pub fn thermal_conductance(
    stiffness: Estimate,
    contact_modulus: f64,
    conductivity: &Conductivity,
) -> Result<Estimate> {
    check::positive("contact_modulus", contact_modulus)?;
    let f = 2.0 * conductivity.series() / contact_modulus;
    scale(stiffness, f)
}

/// f·K with its error (K = +∞ at full contact stays +∞).
fn scale(k: Estimate, f: f64) -> Result<Estimate> {
    if k.value.is_nan() || k.value < 0.0 {
        return Err(Error::invalid(
            "stiffness",
            k.value,
            "finite (or +inf) and >= 0",
        ));
    }
    Ok(Estimate {
        value: f * k.value,
        error: f * k.error + 4.0 * f64::EPSILON * f * k.value,
    })
}

/// The heat-transfer coefficient α(u) of a gap of width u, W/(m² K).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "law")]
pub enum GapLaw {
    /// Gas conduction with a temperature jump at each wall: α = κ_gas/(u + 2ℓ).
    Gas {
        /// κ_gas, W/(m K).
        gas_conductivity: f64,
        /// ℓ, the temperature-jump length of each wall (of the order of the
        /// gas's mean free path), m, ≥ 0.
        mean_free_path: f64,
    },
    /// A table of (u, α(u)), u ascending in m, α in W/(m² K), linear in
    /// between and held at the end values outside.
    Table {
        /// The points (u, α).
        points: Vec<(f64, f64)>,
    },
}

impl GapLaw {
    /// Check the law's parameters.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `gas_conductivity`,
    /// `mean_free_path` (gas), `gap_table` (fewer than 2 points) or
    /// `gap_table[i]` (the i-th point, from 0: u negative, not finite or not
    /// above the previous one; α negative or not finite).
    pub fn validate(&self) -> Result<()> {
        match self {
            GapLaw::Gas {
                gas_conductivity,
                mean_free_path,
            } => {
                check::positive("gas_conductivity", *gas_conductivity)?;
                check::non_negative("mean_free_path", *mean_free_path)?;
            }
            GapLaw::Table { points } => {
                if points.len() < 2 {
                    return Err(Error::invalid(
                        "gap_table",
                        points.len() as f64,
                        "at least 2 points",
                    ));
                }
                for (i, &(u, a)) in points.iter().enumerate() {
                    let name = format!("gap_table[{i}]");
                    if !(u.is_finite() && u >= 0.0) {
                        return Err(Error::invalid(
                            name,
                            u,
                            "a separation u finite and >= 0 (m)",
                        ));
                    }
                    if !(a.is_finite() && a >= 0.0) {
                        return Err(Error::invalid(
                            name,
                            a,
                            "a conductance α finite and >= 0 (W/(m² K))",
                        ));
                    }
                    if i > 0 && u <= points[i - 1].0 {
                        return Err(Error::invalid(
                            name,
                            u,
                            format!(
                                "a separation above the previous one ({}): separations strictly ascending",
                                points[i - 1].0
                            ),
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// α(u), W/(m² K) (α(0) = κ_gas/(2ℓ); +∞ for a gas with ℓ = 0 at u = 0).
    pub fn alpha(&self, u: f64) -> f64 {
        match self {
            GapLaw::Gas {
                gas_conductivity,
                mean_free_path,
            } => gas_conductivity / (u + 2.0 * mean_free_path),
            GapLaw::Table { points } => {
                let last = points.len() - 1;
                if u <= points[0].0 {
                    return points[0].1;
                }
                if u >= points[last].0 {
                    return points[last].1;
                }
                let i = points.partition_point(|p| p.0 <= u).clamp(1, last);
                let (u0, a0) = points[i - 1];
                let (u1, a1) = points[i];
                a0 + (a1 - a0) * (u - u0) / (u1 - u0)
            }
        }
    }

    /// A bound on |dα/du| over u ≥ 0 (for the propagation of u1's error).
    fn lipschitz(&self) -> f64 {
        match self {
            GapLaw::Gas {
                gas_conductivity,
                mean_free_path,
            } => gas_conductivity / (2.0 * mean_free_path).powi(2),
            GapLaw::Table { points } => points
                .windows(2)
                .map(|w| ((w[1].1 - w[0].1) / (w[1].0 - w[0].0)).abs())
                .fold(0.0, f64::max),
        }
    }
}

/// The gap conductance h_gap = ∫_{0+} P_nc(u) α(u) du of a theory's P(u), W/(m² K).
///
/// # Errors
/// A bad law ([`GapLaw::validate`]; a gas needs ℓ > 0 here, since P_nc
/// reaches u = 0, and a finite slope κ_gas/(2ℓ)²: a table's slopes finite);
/// quadrature failures.
pub fn gap_conductance(density: &SeparationDensity, law: &GapLaw) -> Result<Estimate> {
    check_for_density(law)?;
    density.expectation(&|u| law.alpha(u), 1e-12, law.lipschitz())
}

/// A law usable over a P(u): valid, a gas with ℓ > 0 (P_nc reaches u = 0),
/// and a finite bound on |dα/du| (the error of u1 is carried through it).
///
/// # Bound
/// Gas: |dα/du| ≤ κ_gas/(2ℓ)², finite iff ℓ ≥ √(κ_gas/f64::MAX)/2 (it also
/// bounds α ≤ κ_gas/(2ℓ) when 2ℓ < 1; else α < κ_gas). Table: the largest
/// slope |α_{i+1} − α_i|/(u_{i+1} − u_i) finite, else the row is named.
/// The gas names `mean_free_path`, or `gas_conductivity` when that is the
/// further from 1 in order of magnitude (κ_gas = 1e300 at ℓ = 1e-300 gave
/// h_gap = ∞).
fn check_for_density(law: &GapLaw) -> Result<()> {
    law.validate()?;
    match law {
        GapLaw::Gas {
            gas_conductivity,
            mean_free_path,
        } => {
            check::positive("mean_free_path", *mean_free_path)?;
            if !law.lipschitz().is_finite() {
                let approx = crate::error::approx;
                let (k, l) = (*gas_conductivity, *mean_free_path);
                return Err(if k.ln().abs() > l.ln().abs() {
                    Error::invalid(
                        "gas_conductivity",
                        k,
                        format!(
                            "at most {} W/(m K) at mean_free_path = {} m so that dα/du at u = 0, \
                             κ_gas/(2ℓ)², stays finite in f64",
                            approx(f64::MAX * (2.0 * l) * (2.0 * l)),
                            crate::error::num(l)
                        ),
                    )
                } else {
                    Error::invalid(
                        "mean_free_path",
                        l,
                        format!(
                            "at least {} m at gas_conductivity = {} W/(m K) so that dα/du at \
                             u = 0, κ_gas/(2ℓ)², stays finite in f64",
                            approx(0.5 * k.sqrt() / f64::MAX.sqrt()),
                            crate::error::num(k)
                        ),
                    )
                });
            }
        }
        GapLaw::Table { points } => {
            for (i, w) in points.windows(2).enumerate() {
                let slope = (w[1].1 - w[0].1) / (w[1].0 - w[0].0);
                if !slope.is_finite() {
                    return Err(Error::invalid(
                        format!("gap_table[{}]", i + 1),
                        w[1].0,
                        format!(
                            "a separation far enough from the previous one ({}) that the slope \
                             of α between them stays finite in f64",
                            crate::error::num(w[0].0)
                        ),
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The gap conductance of a gap field: the mean of α(g) over the nodes out
/// of contact (p = 0), W/(m² K), e.g. of a BEM solution (`gap`, `pressure`).
///
/// # Formula
/// ```text
/// h_gap = (1/N) Σ_{i: p_i = 0} α(max(g_i, 0))
/// ```
///
/// # Errors
/// Slices of different lengths or empty; a bad law.
pub fn gap_conductance_of_field(gap: &[f64], pressure: &[f64], law: &GapLaw) -> Result<f64> {
    law.validate()?;
    if gap.len() != pressure.len() || gap.is_empty() {
        return Err(Error::Inconsistent {
            name: "gap, pressure".into(),
            requirement: format!(
                "equal, non-zero lengths; got {} and {}",
                gap.len(),
                pressure.len()
            ),
        });
    }
    let sum: f64 = gap
        .iter()
        .zip(pressure)
        .filter(|(_, &p)| p <= 0.0)
        .map(|(&g, _)| law.alpha(g.max(0.0)))
        .sum();
    Ok(sum / gap.len() as f64)
}

/// Conductances at one nominal pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ConductancePoint {
    /// Nominal pressure σ0, Pa.
    pub nominal_pressure: f64,
    /// K/A0 = −dσ0/dū, Pa/m.
    pub stiffness: f64,
    /// Bound on the absolute error of K/A0.
    pub stiffness_error_bound: f64,
    /// h_c, W/(m² K) (with conductivities).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal_conductance: Option<f64>,
    /// Bound on the absolute error of h_c.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal_conductance_error_bound: Option<f64>,
    /// h_e, S/m² (with resistivities).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub electrical_conductance: Option<f64>,
    /// Bound on the absolute error of h_e.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub electrical_conductance_error_bound: Option<f64>,
    /// h_gap, W/(m² K) (with a gap law).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_conductance: Option<f64>,
    /// Bound on the absolute error of h_gap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_conductance_error_bound: Option<f64>,
}

/// What [`Conductance`] computes besides the stiffness.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ConductanceOptions {
    /// κ1, κ2: thermal conductance.
    pub conductivity: Option<Conductivity>,
    /// ρ1, ρ2: electrical conductance.
    pub resistivity: Option<Resistivity>,
    /// α(u): the gap conductance (one P(u) per load, built with `density`).
    pub gap_law: Option<GapLaw>,
    /// Accuracy of P(u) (and its q-integrals' tolerance and breaks).
    pub density: DensityOptions,
}

/// Contact conductance from Persson's theory for one spectrum and E*.
pub struct Conductance<'a> {
    spectrum: &'a dyn Spectrum,
    contact_modulus: f64,
    options: ConductanceOptions,
}

impl<'a> Conductance<'a> {
    /// The model.
    ///
    /// # Errors
    /// E* not finite and positive; a bad gap law.
    pub fn new(
        spectrum: &'a dyn Spectrum,
        contact_modulus: f64,
        options: ConductanceOptions,
    ) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        if let Some(law) = &options.gap_law {
            law.validate()?;
        }
        Ok(Conductance {
            spectrum,
            contact_modulus,
            options,
        })
    }

    /// The conductances at σ0 = `pressure` (Pa).
    ///
    /// # Errors
    /// σ0 not finite and positive; quadrature failures.
    ///
    /// # Examples
    /// ```
    /// use persson::conductance::{Conductance, ConductanceOptions, Conductivity};
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// # fn main() -> persson::Result<()> {
    /// let s = SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0))?;
    /// let opts = ConductanceOptions { conductivity: Some(Conductivity::both(50.0)?), ..Default::default() };
    /// let p = Conductance::new(&s, 1e11, opts)?.point(1e6)?;
    /// // h_c = 2 κ_s K / E* with κ_s = 25 W/(m K)
    /// let h = p.thermal_conductance.unwrap();
    /// assert!((h - 50.0 * p.stiffness / 1e11).abs() < 1e-14 * h);
    /// # Ok(()) }
    /// ```
    pub fn point(&self, pressure: f64) -> Result<ConductancePoint> {
        let k = self.stiffness(pressure)?;
        self.point_with(pressure, k, |law| {
            let d = &self.options.density;
            let density = SeparationDensity::new(self.spectrum, self.contact_modulus, pressure, d)?;
            gap_conductance(&density, law)
        })
    }

    /// K = −dσ0/dū at σ0 by the adaptive route ([`Separation::stiffness`]).
    fn stiffness(&self, pressure: f64) -> Result<Estimate> {
        let d = &self.options.density;
        Separation::new(self.spectrum, self.contact_modulus)?
            .with_tolerance(d.tolerance)?
            .with_breaks(&d.breaks)
            .stiffness(pressure)
    }

    /// The conductances at σ0 from the stiffness `k`, with the gap term from `gap(law)`.
    ///
    /// # Errors
    /// A load whose stiffness exponent (w(q_s)σ0/E*)² overflows f64
    /// (`separation::check_stiffness_exponent`, for the table's route as
    /// for the adaptive one: σ0 = 1e300 gave ∞ with a gas law, a "did not
    /// converge" without). A K of +∞ below it, full contact, is kept.
    fn point_with(
        &self,
        pressure: f64,
        k: Estimate,
        gap: impl Fn(&GapLaw) -> Result<Estimate>,
    ) -> Result<ConductancePoint> {
        crate::separation::check_stiffness_exponent(self.spectrum, self.contact_modulus, pressure)?;
        let split = |e: Option<Estimate>| (e.map(|e| e.value), e.map(|e| e.error));
        let (th, th_e) = split(
            self.options
                .conductivity
                .map(|c| thermal_conductance(k, self.contact_modulus, &c))
                .transpose()?,
        );
        let (el, el_e) = split(
            self.options
                .resistivity
                .map(|r| electrical_conductance(k, self.contact_modulus, &r))
                .transpose()?,
        );
        let gap = self.options.gap_law.as_ref().map(gap).transpose()?;
        let (gp, gp_e) = split(gap);
        Ok(ConductancePoint {
            nominal_pressure: pressure,
            stiffness: k.value,
            stiffness_error_bound: k.error,
            thermal_conductance: th,
            thermal_conductance_error_bound: th_e,
            electrical_conductance: el,
            electrical_conductance_error_bound: el_e,
            gap_conductance: gp,
            gap_conductance_error_bound: gp_e,
        })
    }

    /// [`Conductance::point`] for each pressure. With a gap law, the gap
    /// term comes from one [`SeparationTable`] built for the lowest pressure
    /// ([`DensityOptions::table`]: the breaks and `table_panels_per_unit`,
    /// the curve's accuracy knob) and the fixed point rule of
    /// [`PointSet`], with those rules' bounds, and the stiffness from the
    /// table's full band ([`SeparationTable::stiffness`]); without one, the
    /// stiffness by the adaptive route, as [`Conductance::point`].
    ///
    /// # Errors
    /// As [`Conductance::point`], for the first bad pressure.
    pub fn load_curve(&self, pressures: &[f64]) -> Result<Vec<ConductancePoint>> {
        for &p in pressures {
            check::positive("nominal_pressure", p)?;
        }
        let table = match (
            &self.options.gap_law,
            pressures.iter().copied().reduce(f64::min),
        ) {
            (Some(_), Some(lowest)) => Some(SeparationTable::new(
                self.spectrum,
                self.contact_modulus,
                lowest,
                &self.options.density.table(),
            )?),
            _ => None,
        };
        pressures
            .iter()
            .map(|&p| match &table {
                // the table's full band gives K too (1e-13 of the adaptive
                // route on the bench's spectrum, tests/separation_table.rs)
                Some(t) => self.point_with(p, t.stiffness(p)?, |law| {
                    check_for_density(law)?;
                    Ok(PointSet::new(&t.density(p)?).expectation(|u| law.alpha(u)))
                }),
                None => self.point_with(p, self.stiffness(p)?, |_| {
                    unreachable!("a table is built whenever there is a gap law")
                }),
            })
            .collect()
    }
}

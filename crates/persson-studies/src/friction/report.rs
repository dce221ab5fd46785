//! Rubber friction μ and A/A0 against sliding velocity, temperature and
//! nominal pressure, with the flash temperature and the share of μ from each
//! decade of q.

use serde::Serialize;

use crate::table::{number, Table, Tabulate};
use persson::friction::FrictionPoint;

use crate::table::input_digits;

/// Rubber friction (`persson friction`, scene output `friction`; Persson,
/// J. Chem. Phys. 115, 3840 (2001) and J. Phys.: Condens. Matter 18, 7789
/// (2006)): one point per (T, σ0, v), temperature outermost.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct FrictionReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// The spectrum's lower cut-off q_l, 1/m.
    pub q_l: f64,
    /// The cut-off q1 of the friction integrals, 1/m.
    pub q1: f64,
    /// rms slope of the roughness over [q_l, q1].
    pub rms_slope: f64,
    /// γ of S(q) = γ + (1 − γ) P(q)².
    pub gamma: f64,
    /// Relative tolerance of the integrals.
    pub tolerance: f64,
    /// The rubber's Poisson ratio ν.
    pub poisson: f64,
    /// T_ref of the master curve, K.
    pub reference_temperature: f64,
    /// One point per (T, σ0, v): the isothermal result at the top level, the
    /// one with the flash temperature under `flash`.
    pub points: Vec<FrictionPoint>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

impl FrictionReport {
    /// Whether the points carry the flash temperature.
    pub fn has_flash(&self) -> bool {
        self.points.iter().any(|p| p.flash.is_some())
    }
}

fn relative(err: f64, value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        err.abs()
    } else {
        (err / value).abs()
    }
}

impl FrictionReport {
    /// μ and A/A0 per point (the flash columns when computed).
    fn main_table(&self) -> Table {
        let flash = self.has_flash();
        let mut t = Table::new(
            "friction",
            format!(
                "{}Rubber friction (Persson 2001, 2006): q1 = {}, γ = {}, ν = {}, T_ref = {} K",
                crate::table::surface_prefix(&self.surface),
                number(self.q1, 6),
                number(self.gamma, 3),
                number(self.poisson, 3),
                number(self.reference_temperature, 6)
            ),
        )
        .scalar("rms_slope", "rms slope over [q_l, q1]", self.rms_slope)
        .column_digits(
            "temperature",
            "T (K)",
            input_digits(self.points.iter().map(|p| p.temperature)),
        )
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(self.points.iter().map(|p| p.nominal_pressure)),
        )
        .column_digits(
            "velocity",
            "v (m/s)",
            input_digits(self.points.iter().map(|p| p.velocity)).min(6),
        )
        .column("friction_coefficient", "μ")
        .column("contact_fraction", "A/A0");
        if flash {
            t = t
                .column("flash_friction_coefficient", "μ (flash)")
                .column("flash_contact_fraction", "A/A0 (flash)")
                .column_digits("flash_temperature", "ΔT_flash (K)", 4);
        }
        t = t.column_digits("relative_error_bound", "rel. bound", 2);
        for p in &self.points {
            let iso = &p.isothermal;
            let mut rel = relative(
                iso.friction_coefficient_error_bound,
                iso.friction_coefficient,
            )
            .max(relative(
                iso.contact_fraction_error_bound,
                iso.contact_fraction,
            ));
            let mut row = vec![
                p.temperature.into(),
                p.nominal_pressure.into(),
                p.velocity.into(),
                iso.friction_coefficient.into(),
                iso.contact_fraction.into(),
            ];
            if flash {
                match &p.flash {
                    Some(f) => {
                        rel = rel
                            .max(relative(
                                f.friction_coefficient_error_bound,
                                f.friction_coefficient,
                            ))
                            .max(relative(f.contact_fraction_error_bound, f.contact_fraction));
                        row.extend([
                            f.friction_coefficient.into(),
                            f.contact_fraction.into(),
                            f.flash_temperature.into(),
                        ]);
                    }
                    None => row.extend([None.into(), None.into(), None.into()]),
                }
            }
            row.push(rel.into());
            t.push(row);
        }
        t
    }

    /// Δμ per decade of q at every point (isothermal), with its share of μ.
    fn decade_table(&self) -> Table {
        let mut t = Table::new(
            "friction_decades",
            "Where the friction comes from: Δμ from each decade of q (isothermal)",
        )
        .column_digits(
            "temperature",
            "T (K)",
            input_digits(self.points.iter().map(|p| p.temperature)),
        )
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(self.points.iter().map(|p| p.nominal_pressure)),
        )
        .column_digits(
            "velocity",
            "v (m/s)",
            input_digits(self.points.iter().map(|p| p.velocity)).min(6),
        )
        .column_digits("q_min", "q from (1/m)", 4)
        .column_digits("q_max", "q to (1/m)", 4)
        .column("friction_coefficient", "Δμ")
        .column_digits("friction_fraction", "Δμ/μ", 4);
        for p in &self.points {
            let mu = p.isothermal.friction_coefficient;
            for d in &p.isothermal.decades {
                let share = if mu > 0.0 {
                    d.friction_coefficient / mu
                } else {
                    0.0
                };
                t.push(vec![
                    p.temperature.into(),
                    p.nominal_pressure.into(),
                    p.velocity.into(),
                    d.q_min.into(),
                    d.q_max.into(),
                    d.friction_coefficient.into(),
                    share.into(),
                ]);
            }
        }
        t
    }
}

impl Tabulate for FrictionReport {
    fn tables(&self) -> Vec<Table> {
        vec![self.main_table(), self.decade_table()]
    }
}

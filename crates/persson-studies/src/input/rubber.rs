//! The rubber of a scene (its modulus, time–temperature shift, Poisson ratio
//! and thermal properties) and the `friction` output: Persson's viscoelastic
//! rubber friction, `persson::friction`.

use std::path::{Path, PathBuf};

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::naming::required;
use persson::error::{Error, Result};
use persson::friction::{
    FrequencyUnit, MasterCurve, Prony, Rubber, ShiftTable, TemperatureShift, Thermal,
    VerticalShift, Viscoelastic,
};

/// The reference temperature of a rubber without a temperature shift (K):
/// 20 °C, where its modulus does not depend on T and T only labels results.
pub const DEFAULT_REFERENCE_TEMPERATURE: f64 = 293.15;

/// A standard linear solid E(t) = E∞ + (E0 − E∞) e^{−t/τ}.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct StandardLinearSolidSpec {
    /// E0, the instantaneous (glassy, ω → ∞) modulus, Pa.
    pub instantaneous_modulus: f64,
    /// E∞, the relaxed (rubbery, ω → 0) modulus, Pa.
    pub relaxed_modulus: f64,
    /// τ, s.
    pub relaxation_time: f64,
}

/// The Williams–Landel–Ferry shift log10 a_T = −C1 (T − T_ref)/(C2 + T − T_ref).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct WlfSpec {
    /// C1 (dimensionless).
    pub wlf_c1: f64,
    /// C2, K.
    pub wlf_c2: f64,
    /// T_ref, K: the temperature of the master curve.
    pub reference_temperature: f64,
}

/// The rubber: exactly one of `master_curve`, `prony`, `standard_linear_solid`;
/// at most one of `wlf`, `shift_table`; the thermal properties for the flash
/// temperature.
#[derive(Debug, Clone, Default, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RubberSpec {
    /// A DMA master curve at T_ref: columns ω (or f), E′, E″ (Pa); `#` comments.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub master_curve: Option<PathBuf>,
    /// Unit of the master curve's first column (required with it: `rad/s` or `Hz`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<super::ByName<FrequencyUnit>>")]
    pub frequency_unit: Option<FrequencyUnit>,
    /// A Prony series: rows E_k (Pa), τ_k (s); a row with τ = inf gives E∞.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub prony: Option<PathBuf>,
    /// A standard linear solid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub standard_linear_solid: Option<StandardLinearSolidSpec>,
    /// The WLF shift.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wlf: Option<WlfSpec>,
    /// A shift table: rows T (K), a_T[, b_T]; `#` comments.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shift_table: Option<PathBuf>,
    /// T_ref (K) of a shift table (default: where its a_T = 1) or of a rubber
    /// without a shift (default 293.15 K, a label only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reference_temperature: Option<f64>,
    /// The vertical shift b_T (default `none`; `table` is the shift table's third column).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<super::ByName<VerticalShift>>")]
    pub vertical_shift: Option<VerticalShift>,
    /// Poisson ratio ν (default 0.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poisson: Option<f64>,
    /// Thermal conductivity, W/(m K) (for the flash temperature).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal_conductivity: Option<f64>,
    /// Density, kg/m³ (for the flash temperature).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<f64>,
    /// Specific heat capacity, J/(kg K) (for the flash temperature).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heat_capacity: Option<f64>,
}

impl RubberSpec {
    /// The built-in example: a tread compound as a standard linear solid,
    /// glassy modulus 3 GPa, rubbery plateau 3 MPa, τ = 1 µs, so that on the
    /// example surface μ(v) rises from 1 µm/s, peaks near 1 cm/s and falls
    /// by 100 m/s ([`crate::friction::EXAMPLE_VELOCITY_RANGE`]).
    pub fn example() -> Self {
        RubberSpec {
            standard_linear_solid: Some(StandardLinearSolidSpec {
                instantaneous_modulus: 3e9,
                relaxed_modulus: 3e6,
                relaxation_time: 1e-6,
            }),
            ..Default::default()
        }
    }

    /// The rubber, with its thermal properties when `flash` (then required).
    ///
    /// # Errors
    /// Not exactly one modulus; a master curve without its frequency unit;
    /// both shifts; file errors (naming the file and line); invalid values,
    /// named as in the scene file.
    pub fn build(&self, flash: bool) -> Result<Rubber> {
        self.assemble(self.viscoelastic()?, flash)
    }

    /// The modulus at the reference temperature.
    ///
    /// # Errors
    /// As [`RubberSpec::build`].
    pub fn viscoelastic(&self) -> Result<Viscoelastic> {
        let given = [
            self.master_curve.is_some(),
            self.prony.is_some(),
            self.standard_linear_solid.is_some(),
        ];
        if given.iter().filter(|&&g| g).count() != 1 {
            return Err(Error::Inconsistent {
                name: "master_curve, prony, standard_linear_solid".into(),
                requirement: "exactly one of them".into(),
            });
        }
        if let Some(file) = &self.master_curve {
            let unit = self
                .frequency_unit
                .ok_or_else(|| required("frequency_unit (rad/s or Hz, with master_curve)"))?;
            return Ok(MasterCurve::from_file(file, unit)?.into());
        }
        if self.frequency_unit.is_some() {
            return Err(Error::Inconsistent {
                name: "frequency_unit".into(),
                requirement: "only with master_curve".into(),
            });
        }
        if let Some(file) = &self.prony {
            return Ok(Prony::from_file(file)?.into());
        }
        match self.standard_linear_solid {
            Some(s) => Ok(Prony::standard_linear_solid(
                s.instantaneous_modulus,
                s.relaxed_modulus,
                s.relaxation_time,
            )
            .map_err(|e| section("standard_linear_solid.", e))?
            .into()),
            None => Err(required("master_curve, prony or standard_linear_solid")),
        }
    }

    /// The temperature shift.
    ///
    /// # Errors
    /// Both `wlf` and `shift_table`; a shift table whose T_ref is neither given
    /// nor where its a_T = 1; invalid values.
    pub fn shift(&self) -> Result<TemperatureShift> {
        let shift = match (&self.wlf, &self.shift_table) {
            (Some(_), Some(_)) => {
                return Err(Error::Inconsistent {
                    name: "wlf, shift_table".into(),
                    requirement: "at most one of them".into(),
                })
            }
            (Some(w), None) => {
                if let Some(t) = self.reference_temperature {
                    if t != w.reference_temperature {
                        return Err(Error::Inconsistent {
                            name: "reference_temperature".into(),
                            requirement: format!(
                                "the WLF reference temperature {} K (given twice, differently)",
                                w.reference_temperature
                            ),
                        });
                    }
                }
                TemperatureShift::wlf(w.reference_temperature, w.wlf_c1, w.wlf_c2)
                    .map_err(|e| section("wlf.", e))?
            }
            (None, Some(file)) => {
                let table = ShiftTable::from_file(file)?;
                let t_ref = match self.reference_temperature {
                    Some(t) => t,
                    None => table.unit_shift_temperature().ok_or_else(|| {
                        required(&format!(
                            "reference_temperature (the shift table {} has no a_T = 1)",
                            file.display()
                        ))
                    })?,
                };
                TemperatureShift::table(t_ref, table)?
            }
            (None, None) => TemperatureShift::none(
                self.reference_temperature
                    .unwrap_or(DEFAULT_REFERENCE_TEMPERATURE),
            )?,
        };
        match self.vertical_shift {
            Some(v) => shift.with_vertical(v),
            None => Ok(shift),
        }
    }

    /// The thermal properties, if all three are given.
    ///
    /// # Errors
    /// Some but not all of them; invalid values.
    pub fn thermal(&self) -> Result<Option<Thermal>> {
        match (self.thermal_conductivity, self.density, self.heat_capacity) {
            (Some(k), Some(rho), Some(c)) => Ok(Some(Thermal::new(k, rho, c)?)),
            (None, None, None) => Ok(None),
            _ => Err(required(
                "thermal_conductivity, density and heat_capacity (all three, or none)",
            )),
        }
    }

    /// The rubber from its modulus and these shift, Poisson and thermal fields.
    ///
    /// # Errors
    /// As [`RubberSpec::shift`] and [`RubberSpec::thermal`]; `flash` without
    /// the thermal properties; ν outside (−1, 0.5].
    pub fn assemble(&self, viscoelastic: Viscoelastic, flash: bool) -> Result<Rubber> {
        let mut rubber = Rubber::new(viscoelastic, self.shift()?);
        if let Some(nu) = self.poisson {
            rubber = rubber.with_poisson(nu)?;
        }
        let thermal = self.thermal()?;
        if flash {
            let t = thermal.ok_or_else(|| {
                required(
                    "thermal_conductivity, density and heat_capacity (for the flash temperature)",
                )
            })?;
            rubber = rubber.with_thermal(t);
        }
        Ok(rubber)
    }

    /// The files the rubber is read from.
    pub fn files(&self) -> Vec<PathBuf> {
        [&self.master_curve, &self.prony, &self.shift_table]
            .into_iter()
            .flatten()
            .cloned()
            .collect()
    }

    /// Resolve relative file names against `base` (a scene's directory).
    pub fn resolve(&mut self, base: &Path) {
        for f in [
            &mut self.master_curve,
            &mut self.prony,
            &mut self.shift_table,
        ]
        .into_iter()
        .flatten()
        {
            if f.is_relative() {
                *f = base.join(&*f);
            }
        }
    }
}

/// Prefix the parameter name of an error with its section (`wlf.wlf_c1`).
fn section(prefix: &str, e: Error) -> Error {
    match e {
        Error::InvalidParameter {
            name,
            value,
            requirement,
        } => Error::InvalidParameter {
            name: format!("{prefix}{name}"),
            value,
            requirement,
        },
        other => other,
    }
}

//! What a scene asks of the study `stress`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::StartName;

/// Stress distributions: dimensionless at given G (`g`), or in the pressure
/// unit at given magnifications (`zeta`, with the scene's spectrum and material).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct StressOutput {
    /// Start condition P(σ, ζ = 1).
    pub start: StartName,
    /// Dimensionless mode: the values of G (σ in units of σH).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub g: Vec<f64>,
    /// Dimensionless mode: σY/σH (absent: elastic).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_ratio: Option<f64>,
    /// Physical mode: the magnifications ζ.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub zeta: Vec<f64>,
    /// Physical mode: σH (flat: the nominal pressure). Or give `ball` / `cylinder`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub peak_pressure: Option<f64>,
    /// Physical mode: a Hertz ball (start `hertz`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball: Option<BallSpec>,
    /// Physical mode: a Hertz cylinder (start `cylinder`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cylinder: Option<CylinderSpec>,
    /// Physical mode: σY (absent: elastic).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// Number of σ values per curve (default 201).
    #[serde(default = "default_stress_points")]
    pub points: usize,
    /// Absolute tolerance of σH·P and the fractions (default 1e-12).
    #[serde(default = "default_stress_tolerance")]
    pub tolerance: f64,
    /// Draw the family of curves (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

impl StressOutput {
    /// The fields of one mode only: the dimensionless mode (`g`,
    /// `yield_ratio`) or the physical one (`zeta` with `peak_pressure`,
    /// `ball` or `cylinder`, and `yield_stress`), as the command line's flags
    /// conflict.
    ///
    /// # Errors
    /// [`persson::Error::Inconsistent`] naming the fields of the other mode.
    pub fn check_mode(&self) -> persson::Result<()> {
        let physical = !self.zeta.is_empty();
        let other: Vec<&str> = if physical {
            [
                ("g", !self.g.is_empty()),
                ("yield_ratio", self.yield_ratio.is_some()),
            ]
            .into_iter()
            .filter_map(|(n, given)| given.then_some(n))
            .collect()
        } else {
            [
                ("peak_pressure", self.peak_pressure.is_some()),
                ("ball", self.ball.is_some()),
                ("cylinder", self.cylinder.is_some()),
                ("yield_stress", self.yield_stress.is_some()),
            ]
            .into_iter()
            .filter_map(|(n, given)| given.then_some(n))
            .collect()
        };
        match other.is_empty() {
            true => Ok(()),
            false => Err(persson::Error::Inconsistent {
                name: other.join(", "),
                requirement: if physical {
                    "the dimensionless mode's (g, yield_ratio): not with zeta, the physical mode \
                     (its yield stress is yield_stress, in the pressure unit)"
                        .into()
                } else {
                    "the physical mode's: give zeta with them (or g alone, the dimensionless mode, \
                     whose yield stress is yield_ratio)"
                        .into()
                },
            }),
        }
    }
}

fn default_stress_points() -> usize {
    201
}

fn default_stress_tolerance() -> f64 {
    1e-12
}

/// A Hertz ball: radius (m) and load (N).
#[derive(Debug, Clone, Copy, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BallSpec {
    /// Radius R, m.
    pub radius: f64,
    /// Load F, N.
    pub load: f64,
}

/// A Hertz cylinder: radius (m) and load per unit length (N/m).
#[derive(Debug, Clone, Copy, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CylinderSpec {
    /// Radius R, m.
    pub radius: f64,
    /// Load per unit length F, N/m.
    pub load_per_length: f64,
}

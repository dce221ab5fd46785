//! What a scene (or `persson friction`) asks of the study `friction`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Velocities log-spaced from `velocity_min` to `velocity_max` (m/s), both included.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct VelocityRange {
    /// The lowest velocity, m/s.
    pub velocity_min: f64,
    /// The highest velocity, m/s.
    pub velocity_max: f64,
    /// How many (at least 2, or 1 when both ends are equal).
    pub points: usize,
}

/// Rubber friction (Persson 2001, 2006): μ, A/A0 and, with the flash
/// temperature, both against velocity at every temperature and nominal
/// pressure (the scene's `nominal_pressure`, in Pa); needs `rubber` and `spectrum`.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FrictionOutput {
    /// Sliding velocities v, m/s (or `velocity_range`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub velocity: Vec<f64>,
    /// Log-spaced velocities.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity_range: Option<VelocityRange>,
    /// Background temperatures T, K (default: the rubber's T_ref).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub temperature: Vec<f64>,
    /// Upper cut-off q1 of the friction integrals, 1/m (default q_s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q1: Option<f64>,
    /// q1 where the rms slope of the roughness from q_l reaches this value
    /// (Lorenz et al. 2011; instead of `q1`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q1_rms_slope: Option<f64>,
    /// γ of S(q) = γ + (1 − γ) P(q)² (default 0.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// Relative tolerance of μ, G and the flash temperature (default 1e-8).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Magnifications per decade of the profiles (default 4).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub points_per_decade: Option<usize>,
    /// Also with the flash temperature (needs the rubber's thermal properties).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub flash_temperature: bool,
    /// Draw μ against v with A/A0 on a second panel (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

/// The built-in example's velocities: 50 log-spaced from 1 µm/s to 100 m/s,
/// across the rise and fall of μ(v) of [`crate::input::RubberSpec::example`].
pub const EXAMPLE_VELOCITY_RANGE: VelocityRange = VelocityRange {
    velocity_min: 1e-6,
    velocity_max: 1e2,
    points: 50,
};

/// The built-in example's nominal pressure for friction, Pa: a tyre's 0.3 MPa.
pub const EXAMPLE_PRESSURE: f64 = 3e5;

//! What a scene asks of the study `magnification`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Magnification curve: G(ζ) and A/A0 against ζ at one pressure.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MagnificationOutput {
    /// Nominal (mean) pressure σ0, same unit as E*.
    pub nominal_pressure: f64,
    /// Explicit magnifications ζ ≥ 1 (default: `points` log-spaced from 1 to q_s/q_l).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub zeta: Vec<f64>,
    /// Number of log-spaced magnifications (default 41).
    #[serde(default = "default_points")]
    pub points: usize,
    /// Draw A/A0 against ζ (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
    /// Draw G(ζ) (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot_g: Option<PathBuf>,
}

fn default_points() -> usize {
    41
}

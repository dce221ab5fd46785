//! What a scene asks of the study `theories`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::TheorySpec;

/// Corrected-theory load curves at the scene's nominal pressures.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TheoriesOutput {
    /// The theories, e.g. `{"theory": "yang-persson", "gamma": 0.42}` (default: all four with their default γ).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub theories: Vec<TheorySpec>,
    /// Magnification ζ (default full).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    /// Absolute tolerance on A/A0 (default 1e-12).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Draw A/A0 against load for all of them (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

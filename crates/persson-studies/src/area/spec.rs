//! What a scene (or `persson area`) asks of the study `area`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::TheoryName;

/// Load curve: A/A0 against the scene's nominal pressures.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AreaOutput {
    /// Magnification ζ (default q_s/q_l, full magnification).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    /// Contact-area theory (default `original`).
    #[serde(default)]
    pub theory: TheoryName,
    /// γ of a corrected theory (default: the paper's value).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// Absolute tolerance on A/A0 of the corrected theories' solver; for
    /// `bush`, the relative tolerance of its integrals (default 1e-12).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Hardness σY of the `overlap` theory's load law σ0 = σY A/A0 (required
    /// by it, refused by the others).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// Draw A/A0 against load with the Bush and Persson lines (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

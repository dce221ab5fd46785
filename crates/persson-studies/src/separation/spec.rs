//! What a scene asks of the study `separation`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Mean-separation load curve at the scene's nominal pressures (Persson, Phys. Rev. Lett. 99, 125502 (2007)).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SeparationOutput {
    /// Relative tolerance of the wavevector integrals (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Draw ū against load with the low-load law u0 ln(p_ref/σ0) (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
    /// Draw A/A0 against load for the four theories of `theories`, each at
    /// its γ (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot_area: Option<PathBuf>,
    /// Number of log-spaced pressures of the figures, spanning the given ones
    /// (a single σ0: σ0/100 to 100 σ0) (default 60).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot_points: Option<usize>,
}

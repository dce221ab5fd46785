//! What a scene asks of the study `spectrum`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Spectrum summary: rms height, slope and curvature over [q_min, q_max],
/// a power-law fit and C(q).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SpectrumOutput {
    /// Lower end of the band of the moments (default q_l), 1/m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_min: Option<f64>,
    /// Upper end of the band of the moments (default q_s), 1/m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_max: Option<f64>,
    /// Number of log-spaced q in the C(q) table (default 11).
    #[serde(default = "default_spectrum_points")]
    pub points: usize,
    /// Draw C(q) with the fitted power law (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

fn default_spectrum_points() -> usize {
    11
}

//! What a scene asks of the study `surrogates`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::{ByName, SurrogateKindName};
use persson::names::Boundary;

/// Surrogates of the contact: does the scene's height map make contact like
/// random surfaces with the same periodic spectrum? The FFT-BEM on the map
/// and on `count` surrogates of it, at the scene's nominal pressures.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SurrogatesOutput {
    /// Number K of surrogates (default 8, at least 2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub count: Option<usize>,
    /// `phase` (random phases: Gaussian heights, the default) or
    /// `amplitude-adjusted` (the map's own heights, IAAFT).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kind: Option<SurrogateKindName>,
    /// Most IAAFT iterations of an amplitude-adjusted surrogate (default 200).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub iterations: Option<usize>,
    /// Seed of the first surrogate; surrogate k (k = 1 … K) uses seed + k − 1 (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Grid side N of a map synthesised from the scene's spectrum (a height
    /// map sets its own).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid: Option<usize>,
    /// Seed of a map synthesised from the scene's spectrum (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map_seed: Option<u64>,
    /// Boundary condition of every solve (default `periodic`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<Boundary>>")]
    pub boundary: Option<Boundary>,
    /// Solver tolerance ε of every solve (default 1e-8).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Write each surrogate as .npy (N×N float64, unit of the map); `_k`
    /// (k = 1 … K) is added before the extension.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub surfaces: Option<PathBuf>,
    /// Draw A/A0 against σ0, the map's beside the surrogates' band (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
    /// Draw the pressure distributions P(p) of the map and of the pooled
    /// surrogates at the largest pressure, on a log axis (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot_distribution: Option<PathBuf>,
}

//! What a scene asks of the study `separation_density`.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// The distribution of interfacial separations P(u) at the scene's nominal
/// pressures (Almqvist, Campañá, Prodanov & Persson, J. Mech. Phys. Solids
/// 59, 2355 (2011)): the report of `persson separation --separation-density`.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SeparationDensityOutput {
    /// Separations u per pressure, from 0 to where P_nc is negligible
    /// (default 101, at least 2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density_points: Option<usize>,
    /// Relative tolerance of the wavevector integrals (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

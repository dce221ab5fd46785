//! What a scene asks of the study `separation`.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Mean-separation load curve at the scene's nominal pressures (Persson, Phys. Rev. Lett. 99, 125502 (2007)).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SeparationOutput {
    /// Relative tolerance of the wavevector integrals (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

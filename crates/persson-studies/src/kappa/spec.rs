//! What a scene asks of the study `kappa`.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// κ output (no options).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct KappaOutput {}

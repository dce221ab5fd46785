//! The scene file: every field, with serde enums for every closed set,
//! spelled as on the command line (`periodic`, `surface-topography`,
//! `yang-persson`). The same enums are the CLI's value enums, so a scene and
//! a flag accept exactly the same strings.

//!
//! | module | what it holds |
//! |---|---|
//! | this one | the scene ([`Scene`]); its inputs are [`crate::input`]'s |
//! | `outputs` | what a scene asks for, one struct per output |

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

mod outputs;

pub use crate::input::*;
pub use crate::transport::{ConductanceOutput, LeakageOutput, TransportBem};
pub use outputs::*;

/// The scene format version this crate reads.
pub const SCHEMA: u32 = 1;

/// A scene file: one calculation, its inputs and the outputs it asks for.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Format version: must be 1.
    pub schema: u32,
    /// A name for the calculation (printed above its tables).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Free text: what is computed and why.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// The material (needed by every output but `kappa`, `stress` in G and `bem_hertz`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<MaterialSpec>,
    /// The rubber (needed by `friction` only; it has its own modulus, so
    /// `material` is not needed there).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rubber: Option<RubberSpec>,
    /// The roughness spectrum (or, for `bem` only, a height map).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spectrum: Option<SpectrumSpec>,
    /// Nominal (mean) pressures σ0, in the unit of the contact modulus
    /// (`pressures` in persson 0.1).
    #[serde(default, alias = "pressures", skip_serializing_if = "Vec::is_empty")]
    pub nominal_pressure: Vec<f64>,
    /// What to compute; absent outputs are not computed.
    pub outputs: super::Outputs,
}

/// The JSON Schema of a scene file (written to
/// `crates/persson-studies/schema/scene.schema.json`, apart from the scenes).
pub fn json_schema() -> String {
    let schema = schemars::schema_for!(Scene);
    let mut s = serde_json::to_string_pretty(&schema).unwrap_or_default();
    s.push('\n');
    s
}

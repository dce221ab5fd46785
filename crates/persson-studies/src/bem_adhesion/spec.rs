//! What a scene asks of the study `bem_adhesion`.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::ByName;
use crate::naming::names::AdhesiveIteration;
use persson::names::{Boundary, LawKind};

/// The adhesive FFT-BEM (Rey, Anciaux & Molinari, Comput. Mech. 60, 69
/// (2017)) on the scene's surface along a path in and out: per point the
/// mean pressure (negative in tension), the repulsive and cohesive
/// fractions, and the pull-off; the JSON of `bem rough --work-of-adhesion`.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BemAdhesionOutput {
    /// Grid side N of the synthesised surface (a height map sets its own).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid: Option<usize>,
    /// Seed of the synthesised surface (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Boundary condition (default `periodic`; `free` needs `approach`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<Boundary>>")]
    pub boundary: Option<Boundary>,
    /// Solver tolerance ε (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Iterations allowed per solve (default 10000, as the command line's
    /// `--max-iterations`); a solve that needs more fails, saying so.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<usize>,
    /// Work of adhesion Δγ, J/m² (> 0).
    pub work_of_adhesion: f64,
    /// Range ρ of the cohesive law, m (> 0).
    pub adhesion_range: f64,
    /// Cohesive law (default `maugis`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<LawKind>>")]
    pub adhesion: Option<LawKind>,
    /// Mean gaps ḡ of the path, m, in order (periodic).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub mean_gap: Vec<f64>,
    /// Approaches δ from first touch, m, in order (instead of `mean_gap`;
    /// the control of the free boundary).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub approach: Vec<f64>,
    /// Iteration of the adhesive BEM (default `auto`: preconditioned for the
    /// exponential law, plain for Maugis–Dugdale).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub adhesive_iteration: Option<AdhesiveIteration>,
}

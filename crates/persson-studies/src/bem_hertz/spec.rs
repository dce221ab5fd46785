//! What a scene asks of the study `bem_hertz`.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::ByName;
use persson::names::Boundary;

/// FFT-BEM Hertz convergence: sphere R = L, a = 0.1 L, E* = 1 (Molinari,
/// EPFL lecture "From single asperity to multi asperity contact", Table 1).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BemHertzOutput {
    /// Grid sides (default 64, 128, 256).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub grids: Vec<usize>,
    /// Boundary condition (default `free`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<Boundary>>")]
    pub boundary: Option<Boundary>,
    /// Solver tolerance ε (default 1e-10, as `persson bem hertz` and Python).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Yield stress σY (unit of E*; the peak pressure is p₀ = 0.2/π ≈ 0.0637):
    /// adds the plastic disc's radius and fractions per grid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
}

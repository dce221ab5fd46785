//! What a scene asks for: one struct per output, absent outputs not computed.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::{AdhesionLawName, BoundaryName, ConnectivityName};
pub use crate::adhesion::AdhesionOutput;
pub use crate::area::AreaOutput;
pub use crate::friction::{FrictionOutput, VelocityRange};
pub use crate::kappa::KappaOutput;
pub use crate::magnification::MagnificationOutput;
pub use crate::separation::SeparationOutput;
pub use crate::separation_density::SeparationDensityOutput;
pub use crate::spectrum::SpectrumOutput;
pub use crate::stress::{BallSpec, CylinderSpec, StressOutput};
pub use crate::theories::TheoriesOutput;

/// FFT-BEM rough contact: the surface is synthesised from the scene's
/// spectrum (side 2π/q_l, `grid` nodes, `seed`) or read from its height map.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BemOutput {
    /// Grid side N of the synthesised surface (a height map sets its own).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid: Option<usize>,
    /// Seed of the synthesised surface (Pcg64Mcg, value-stable; default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Boundary condition (default `periodic`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub boundary: Option<BoundaryName>,
    /// Solver tolerance ε (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Write the pressure histograms P(σ) as one CSV (nominal_pressure,
    /// sigma_low, sigma_high, density; each pressure's bins integrate to its A/A0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub histogram: Option<PathBuf>,
    /// Number of histogram bins (default 50).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bins: Option<usize>,
    /// Draw A/A0 against load with the Bush linear law (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
    /// Yield stress σY (unit of E*): pressures bounded by 0 ≤ p ≤ σY; each
    /// point reports the elastic and plastic fractions, the histogram keeps
    /// the plastic peak at σY as its own row.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// The connected contact patches of each solve (Hyun, Pei, Molinari &
    /// Robbins 2004) and the fits of its pressure tail.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub patches: Option<PatchesOutput>,
    /// The stress below the surface under each solve, on planes at given depths.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub subsurface: Option<SubsurfaceOutput>,
}

/// `outputs.bem.patches`: contact-patch statistics of each solve.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PatchesOutput {
    /// Neighbourhood of a patch (default `four`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub connectivity: Option<ConnectivityName>,
    /// Log bins per decade of the patch-area distribution (default 5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bins_per_decade: Option<usize>,
    /// Draw the log-binned patch-area distribution n(A) of each solve on
    /// log axes (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

/// `outputs.bem.subsurface`: the stress below each solve.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SubsurfaceOutput {
    /// Depths z of the planes (unit of L; each > 0 and at most L).
    pub depth: Vec<f64>,
    /// Uniaxial yield stress Y of the von Mises criterion (unit of the
    /// pressure): where and at which load factor the subsurface first yields.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tensile_yield_stress: Option<f64>,
    /// Write each plane's von Mises map as .npy (N×N float64); `_k_j`
    /// (pressure k, depth j) is added before the extension.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stress_field: Option<PathBuf>,
    /// Draw the depth profiles of the largest von Mises stress and maximum
    /// shear of each solve (.svg or .png), and beside it each plane's von
    /// Mises map as a colour map (`_k_j` added: pressure k, depth j).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

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
    pub boundary: Option<BoundaryName>,
    /// Solver tolerance ε (default 1e-12).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Yield stress σY (unit of E*; the peak pressure is p₀ = 0.2/π ≈ 0.0637):
    /// adds the plastic disc's radius and fractions per grid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
}

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
    pub boundary: Option<BoundaryName>,
    /// Solver tolerance ε (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Work of adhesion Δγ, J/m² (> 0).
    pub work_of_adhesion: f64,
    /// Range ρ of the cohesive law, m (> 0).
    pub adhesion_range: f64,
    /// Cohesive law (default `maugis`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub adhesion: Option<AdhesionLawName>,
    /// Mean gaps ḡ of the path, m, in order (periodic).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub mean_gap: Vec<f64>,
    /// Approaches δ from first touch, m, in order (instead of `mean_gap`;
    /// the control of the free boundary).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub approach: Vec<f64>,
}

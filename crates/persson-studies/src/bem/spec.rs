//! What a scene asks of the study `bem`.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::ByName;
use persson::names::{Boundary, Connectivity};

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
    #[schemars(with = "Option<ByName<Boundary>>")]
    pub boundary: Option<Boundary>,
    /// Solver tolerance ε (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Iterations allowed per solve (default 10000); a solve that needs more
    /// fails, saying so.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<usize>,
    /// Write the pressure histograms P(σ) as one CSV (nominal_pressure,
    /// sigma_low, sigma_high, density; each pressure's bins integrate to its A/A0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub histogram: Option<PathBuf>,
    /// Number of histogram bins (default 50).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bins: Option<usize>,
    /// Draw A/A0 against load with the Bush linear law (.svg or .png; on
    /// the command line `--area-plot`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
    /// Draw the pressure map of the load in partial contact whose A/A0 is
    /// nearest 0.1 (plastic nodes in red with `yield_stress`) and its
    /// histogram P(σ) (.svg or .png; on the command line `--plot`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure_plot: Option<PathBuf>,
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
    #[schemars(with = "Option<ByName<Connectivity>>")]
    pub connectivity: Option<Connectivity>,
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

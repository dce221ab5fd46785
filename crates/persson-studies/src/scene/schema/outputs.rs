//! What a scene asks for: one struct per output, absent outputs not computed.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::{AdhesionLawName, AreaEnhancementName, BoundaryName, ConnectivityName, StartName};
pub use crate::area::AreaOutput;
pub use crate::kappa::KappaOutput;
pub use crate::magnification::MagnificationOutput;
pub use crate::separation::SeparationOutput;
pub use crate::theories::TheoriesOutput;

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

/// Stress distributions: dimensionless at given G (`g`), or in the pressure
/// unit at given magnifications (`zeta`, with the scene's spectrum and material).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct StressOutput {
    /// Start condition P(σ, ζ = 1).
    pub start: StartName,
    /// Dimensionless mode: the values of G (σ in units of σH).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub g: Vec<f64>,
    /// Dimensionless mode: σY/σH (absent: elastic).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_ratio: Option<f64>,
    /// Physical mode: the magnifications ζ.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub zeta: Vec<f64>,
    /// Physical mode: σH (flat: the nominal pressure). Or give `ball` / `cylinder`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub peak_pressure: Option<f64>,
    /// Physical mode: a Hertz ball (start `hertz`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball: Option<BallSpec>,
    /// Physical mode: a Hertz cylinder (start `cylinder`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cylinder: Option<CylinderSpec>,
    /// Physical mode: σY (absent: elastic).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// Number of σ values per curve (default 201).
    #[serde(default = "default_stress_points")]
    pub points: usize,
    /// Absolute tolerance of σH·P and the fractions (default 1e-12).
    #[serde(default = "default_stress_tolerance")]
    pub tolerance: f64,
    /// Draw the family of curves (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

impl StressOutput {
    /// The fields of one mode only: the dimensionless mode (`g`,
    /// `yield_ratio`) or the physical one (`zeta` with `peak_pressure`,
    /// `ball` or `cylinder`, and `yield_stress`), as the command line's flags
    /// conflict.
    ///
    /// # Errors
    /// [`persson::Error::Inconsistent`] naming the fields of the other mode.
    pub fn check_mode(&self) -> persson::Result<()> {
        let physical = !self.zeta.is_empty();
        let other: Vec<&str> = if physical {
            [
                ("g", !self.g.is_empty()),
                ("yield_ratio", self.yield_ratio.is_some()),
            ]
            .into_iter()
            .filter_map(|(n, given)| given.then_some(n))
            .collect()
        } else {
            [
                ("peak_pressure", self.peak_pressure.is_some()),
                ("ball", self.ball.is_some()),
                ("cylinder", self.cylinder.is_some()),
                ("yield_stress", self.yield_stress.is_some()),
            ]
            .into_iter()
            .filter_map(|(n, given)| given.then_some(n))
            .collect()
        };
        match other.is_empty() {
            true => Ok(()),
            false => Err(persson::Error::Inconsistent {
                name: other.join(", "),
                requirement: if physical {
                    "the dimensionless mode's (g, yield_ratio): not with zeta, the physical mode \
                     (its yield stress is yield_stress, in the pressure unit)"
                        .into()
                } else {
                    "the physical mode's: give zeta with them (or g alone, the dimensionless mode, \
                     whose yield stress is yield_ratio)"
                        .into()
                },
            }),
        }
    }
}

fn default_stress_points() -> usize {
    201
}

fn default_stress_tolerance() -> f64 {
    1e-12
}

/// A Hertz ball: radius (m) and load (N).
#[derive(Debug, Clone, Copy, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BallSpec {
    /// Radius R, m.
    pub radius: f64,
    /// Load F, N.
    pub load: f64,
}

/// A Hertz cylinder: radius (m) and load per unit length (N/m).
#[derive(Debug, Clone, Copy, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CylinderSpec {
    /// Radius R, m.
    pub radius: f64,
    /// Load per unit length F, N/m.
    pub load_per_length: f64,
}

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

/// Adhesion from Persson's theory (Persson & Tosatti, J. Chem. Phys. 115,
/// 5597 (2001); Persson, Eur. Phys. J. E 8, 385 (2002)): the energy balance
/// at full contact per magnification and its stickiness verdict, and A/A0
/// against the scene's nominal pressures (tension ≤ 0 allowed) with the
/// pull-off stress.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AdhesionOutput {
    /// Work of adhesion Δγ, J/m² (≥ 0).
    pub work_of_adhesion: f64,
    /// Magnification ζ of the contact points (default q_s/q_l, full magnification).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    /// Number of log-spaced ζ from 1 to q_s/q_l of the stickiness balance (default 11).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub points: Option<usize>,
    /// Whether Δγ acts on the true (sloped) area (`slopes`, default) or the projected one (`none`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub area_enhancement: Option<AreaEnhancementName>,
    /// Range Δr of the adhesive interaction, m: adds the Pastewka–Robbins criterion.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub adhesion_range: Option<f64>,
    /// Absolute tolerance of the contact fractions (default 1e-5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

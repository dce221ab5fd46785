//! What a scene, `persson bem hertz` and Python's `bem_hertz` ask of the
//! study `bem_hertz`: one declaration for the three.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::ByName;
use persson::names::{Boundary, LawKind};

/// The grid of the Hertz ball where none is given.
pub const DEFAULT_GRID: usize = 256;

/// The Hertz ball on the FFT-BEM (Molinari, EPFL lecture "From single
/// asperity to multi asperity contact", Table 1): by default a sphere R = L
/// pressed to the contact radius a = 0.1 L, E* = 1. On one grid the
/// validation against Hertz's closed form (η, fitted a and p₀); on several,
/// η per grid; with `yield_stress`, the plastic disc per grid beside η; with
/// `subsurface`, the stress on the contact's axis against Johnson's; with
/// `work_of_adhesion`, the adhesive sphere's pull-off per grid against JKR
/// and DMT.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BemHertzOutput {
    /// Grid sides N (nodes per side, at least 8; default 256); one with
    /// `subsurface`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub grids: Vec<usize>,
    /// Boundary condition of the elastic half-space (default `free`: an
    /// isolated contact, zero-padded to 2N; the adhesive sphere needs
    /// `periodic`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<Boundary>>")]
    pub boundary: Option<Boundary>,
    /// Side L of the square domain (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<f64>,
    /// Ball radius R, unit of L (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Contact modulus E* (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_modulus: Option<f64>,
    /// Hertz contact radius a that sets the load (default 0.1 L).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_radius: Option<f64>,
    /// Solver tolerance ε (default 1e-10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Iterations allowed per solve (default 10000); a solve that needs
    /// more fails, saying so.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<usize>,
    /// Yield stress σY, unit of E* (below the Hertz peak pressure p₀ =
    /// 2E*a/(πR), 0.0637 by default, for a plastic zone): adds the plastic
    /// disc's radius and fractions per grid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// The stress below the surface on the contact's axis (z/a = 0.05 … 2)
    /// against Johnson's closed forms, instead of η (one grid).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub subsurface: bool,
    /// Poisson ratio ν of the body, for `subsurface` (default 0.3; the
    /// contact needs only E*).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poisson: Option<f64>,
    /// With `subsurface`, draw the von Mises stress σ_vM/p₀ on the vertical
    /// section through the axis (z/a ≤ 2, |r|/a ≤ 3) as a colour map (.svg
    /// or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stress_plot: Option<PathBuf>,
    /// Work of adhesion Δγ, unit of E* L: the adhesive sphere instead, its
    /// pull-off force on each grid against JKR (1.5πRΔγ) and DMT (2πRΔγ),
    /// on a periodic cell under mean-gap control.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub work_of_adhesion: Option<f64>,
    /// Range ρ of the cohesive law, unit of L (with `work_of_adhesion`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub adhesion_range: Option<f64>,
    /// Cohesive law of the adhesive sphere (default `maugis`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(with = "Option<ByName<LawKind>>")]
    pub adhesion: Option<LawKind>,
}

//! What a scene asks of the study `adhesion`.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use crate::input::ByName;
use persson::adhesion::AreaEnhancement;

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
    #[schemars(with = "Option<ByName<AreaEnhancement>>")]
    pub area_enhancement: Option<AreaEnhancement>,
    /// Range Δr of the adhesive interaction, m: adds the Pastewka–Robbins criterion.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub adhesion_range: Option<f64>,
    /// Absolute tolerance of the contact fractions (default 1e-5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

/// The built-in example's work of adhesion Δγ, J/m²: rubber on glass.
pub const EXAMPLE_WORK_OF_ADHESION: f64 = 0.05;

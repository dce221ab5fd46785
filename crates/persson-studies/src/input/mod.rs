//! The inputs of a calculation, shared by every study: the material, the
//! roughness (a spectrum or a measured height map), the rubber, and the
//! closed sets of names, spelled as on the command line (`periodic`,
//! `surface-topography`, `yang-persson`): the numerics' own enums where the
//! set is one of theirs ([`persson::names::Named`], through [`ByName`] and
//! the value parser `by_name`), the `names!` enums here otherwise. A scene
//! and a flag accept exactly the same strings.
//!
//! | module | what it holds |
//! |---|---|
//! | this one | the material ([`MaterialSpec`]) and the built-in example |
//! | `spectrum` | the roughness: self-affine, tabulated or a measured height map |
//! | `crate::naming::names` (re-exported) | the studies' closed sets (convention, length unit, start, theory, surrogate kind) |
//! | `by_name` | the numerics' closed sets ([`persson::names::Named`]: boundary, window, …) in the scene schema and on the command line |
//! | `rubber` | the rubber and the `friction` output |
//! | `multiscale` | one spectrum from several measurements of a surface, with each one's band |

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use persson::error::{Error, Result};
use persson::material::{Body, Material};

use crate::naming::required;

mod by_name;
mod measured;
pub mod multiscale;
mod rubber;
mod spectrum;

pub use crate::naming::names::*;
pub use by_name::*;
#[cfg(feature = "topography")]
pub use measured::describe;
pub use rubber::*;
pub use spectrum::*;

/// The material: E* directly, or one or two elastic bodies
/// (1/E* = Σ (1 − ν²)/E; a single body is pressed on a rigid one).
#[derive(Debug, Clone, Default, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Contact modulus E* (any pressure unit; the pressures use the same).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_modulus: Option<f64>,
    /// Young's modulus E of the (first) body.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub young: Option<f64>,
    /// Poisson ratio ν of the (first) body.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poisson: Option<f64>,
    /// Young's modulus of the second body (absent: rigid).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub young2: Option<f64>,
    /// Poisson ratio of the second body.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poisson2: Option<f64>,
}

/// The built-in example, in words (help text and titles).
pub const EXAMPLE: &str = "built-in example: self-affine surface, H = 0.8, q_l = 1e4, q_r = 1e5, \
q_s = 1e8 1/m, rms height 1 µm; E* = 1 GPa";

/// The built-in example's nominal pressures, Pa: up to 0.1 E*, the small-strain
/// theory's range (a larger σ0 is warned of, [`crate::warning::HIGH_PRESSURE_RATIO`]).
pub const EXAMPLE_PRESSURES: [f64; 6] = [1e4, 1e5, 1e6, 1e7, 3e7, 1e8];

impl MaterialSpec {
    /// The built-in example: E* = 1 GPa.
    pub fn example() -> Self {
        MaterialSpec {
            contact_modulus: Some(1e9),
            ..Default::default()
        }
    }

    /// Whether no field is given.
    pub fn is_empty(&self) -> bool {
        *self == MaterialSpec::default()
    }

    /// Build the material: E* given (`contact_modulus`, with `poisson` the
    /// body's ν where the stress below the surface needs it), or the bodies'
    /// `young` and `poisson` (and `young2`, `poisson2` of a second elastic
    /// body). Every given field is checked, even one that E* makes unused.
    ///
    /// # Errors
    /// Missing, invalid or contradicting fields, named as in the scene file
    /// (and as the flags' ids: `contact_modulus`, `young2`, …).
    pub fn build(&self) -> Result<Material> {
        if let Some(nu) = self.poisson {
            persson::material::check_poisson("poisson", nu)?;
        }
        let either = |what: &str| Error::Inconsistent {
            name: format!("contact_modulus and {what}"),
            requirement: "give E* (contact_modulus) or the bodies' young and poisson, not both"
                .into(),
        };
        if let Some(e) = self.contact_modulus {
            for (name, given) in [
                ("young", self.young),
                ("young2", self.young2),
                ("poisson2", self.poisson2),
            ] {
                if given.is_some() {
                    return Err(either(name));
                }
            }
            return Material::new(e);
        }
        let (Some(young), Some(poisson)) = (self.young, self.poisson) else {
            return Err(required(match (self.young, self.poisson) {
                (Some(_), None) => "poisson (with young)",
                (None, Some(_)) => "young (with poisson), or contact_modulus",
                _ => "contact_modulus (or young and poisson)",
            }));
        };
        let a = Body { young, poisson };
        match (self.young2, self.poisson2) {
            (Some(young), Some(poisson)) => Material::from_bodies(a, Body { young, poisson }),
            (None, None) => Material::from_body(a),
            (Some(_), None) => Err(required("poisson2 (with young2)")),
            (None, Some(_)) => Err(required("young2 (with poisson2)")),
        }
    }
}

//! The scene file: every field, with serde enums for every closed set,
//! spelled as on the command line (`periodic`, `surface-topography`,
//! `yang-persson`). The same enums are the CLI's value enums, so a scene and
//! a flag accept exactly the same strings.

//!
//! | module | what it holds |
//! |---|---|
//! | this one | the scene ([`Scene`]), its material and the built-in example |
//! | `spectrum` | the roughness: self-affine, tabulated or a measured height map |
//! | `names` | the closed sets (convention, boundary, start, theory, detrend, window) |
//! | `outputs` | what a scene asks for, one struct per output |
//! | `friction` | the rubber and the `friction` output |

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use persson::error::{Error, Result};
use persson::material::{Body, Material};

/// Defines a closed set of names: serde and (feature `cli`) clap spell the
/// variants in kebab-case, the same strings in scenes and on the command line.
macro_rules! names {
    ($(#[$m:meta])* $name:ident { $($(#[$vm:meta])* $v:ident = $s:literal),+ $(,)? }) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
        #[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
        #[serde(rename_all = "kebab-case")]
        pub enum $name { $($(#[$vm])* $v),+ }

        impl $name {
            /// Every value, in order.
            pub const ALL: &'static [$name] = &[$($name::$v),+];
            /// The name as in scene files and on the command line.
            pub fn name(self) -> &'static str {
                match self { $($name::$v => $s),+ }
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }
    };
}

mod friction;
mod names;
mod outputs;
mod spectrum;
mod transport;

pub use friction::*;
pub use names::*;
pub use outputs::*;
pub use spectrum::*;
pub use transport::*;

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

/// A missing input.
pub(crate) fn required(what: &str) -> Error {
    Error::Inconsistent {
        name: what.to_string(),
        requirement: "missing (required for this calculation)".into(),
    }
}

/// The JSON Schema of a scene file (written to
/// `crates/persson-studies/schema/scene.schema.json`, apart from the scenes).
pub fn json_schema() -> String {
    let schema = schemars::schema_for!(Scene);
    let mut s = serde_json::to_string_pretty(&schema).unwrap_or_default();
    s.push('\n');
    s
}

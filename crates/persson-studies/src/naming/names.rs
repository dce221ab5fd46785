//! The closed sets of a scene that are the studies' own, spelled as on the
//! command line: the convention of a spectrum file (whose `grid` takes the
//! side L), the unit of a file's lengths, the stress start, the area theory
//! (Persson's and the asperity ones) and the kind of surrogate. The
//! numerics' closed sets (boundary, window, …) are their own types, by
//! [`crate::input::ByName`].

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use super::required;
use persson::corrected::Theory;
use persson::error::{Error, Result};
use persson::spectrum::Convention;
use persson::stress::Start;

/// Defines a closed set of names: serde and (feature `clap`) clap spell each
/// variant as its string, the same in scenes and on the command line.
macro_rules! names {
    ($(#[$m:meta])* $name:ident { $($(#[$vm:meta])* $v:ident = $s:literal),+ $(,)? }) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
        #[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
        pub enum $name {
            $(
                $(#[$vm])*
                #[serde(rename = $s)]
                #[cfg_attr(feature = "clap", value(name = $s))]
                $v
            ),+
        }

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

names! {
    /// Normalisation of a tabulated spectrum.
    #[derive(Default)]
    ConventionName {
        /// Persson's: q in 1/m, C in m⁴.
        #[default]
        Persson = "persson",
        /// SurfaceTopography / contact.engineering: C_Persson = C / (2π)².
        SurfaceTopography = "surface-topography",
        /// 1D profile spectrum of an isotropic surface (m³).
        Profile1d = "profile1d",
        /// Dimensionless FFT grid: k in units of 2π/L, C_Persson = (L/2π)² φ(k); needs the side L.
        Grid = "grid",
    }
}

impl ConventionName {
    /// The library's convention; `size` is the side L of `grid`.
    ///
    /// # Errors
    /// `grid` without a size; a size with another convention.
    pub fn with(self, size: Option<f64>) -> Result<Convention> {
        Ok(match (self, size) {
            (ConventionName::Grid, Some(size)) => Convention::Grid { size },
            (ConventionName::Grid, None) => return Err(required("size (for the convention grid)")),
            (_, Some(_)) => {
                return Err(Error::Inconsistent {
                    name: "size".into(),
                    requirement: "only with the convention grid".into(),
                })
            }
            (ConventionName::Persson, None) => Convention::Persson,
            (ConventionName::SurfaceTopography, None) => Convention::SurfaceTopography,
            (ConventionName::Profile1d, None) => Convention::Profile1D,
        })
    }
}

names! {
    /// A unit of length, for the numbers of a file that states none.
    LengthUnitName {
        /// Metres.
        M = "m",
        /// Millimetres.
        Mm = "mm",
        /// Micrometres.
        Um = "um",
        /// Nanometres.
        Nm = "nm",
        /// Picometres.
        Pm = "pm",
        /// Ångström (1e-10 m).
        Angstrom = "angstrom",
    }
}

names! {
    /// Start condition P(σ, ζ = 1) of the stress distribution (Persson,
    /// Bucher & Chiaia 2002, Figs. 2–4).
    StartName {
        /// Flat punch, P0 = δ(σ − σ0) (σH = σ0).
        Flat = "flat",
        /// Hertz ball, P0 = 2σ/σH², σ0 = 2σH/3.
        Hertz = "hertz",
        /// Cylinder, P0 = (σ/σH²)(1 − (σ/σH)²)^(−1/2), σ0 = πσH/4.
        Cylinder = "cylinder",
    }
}

impl From<StartName> for Start {
    fn from(s: StartName) -> Self {
        match s {
            StartName::Flat => Start::Flat,
            StartName::Hertz => Start::Hertz,
            StartName::Cylinder => Start::Cylinder,
        }
    }
}

names! {
    /// Contact-area theory.
    #[derive(Default)]
    TheoryName {
        /// Persson, J. Chem. Phys. 115, 3840 (2001).
        #[default]
        Original = "original",
        /// Yang & Persson, J. Phys.: Condens. Matter 20, 215214 (2008), γ = 0.45.
        YangPersson = "yang-persson",
        /// Wang & Müser, Tribol. Lett. 65, 103 (2017), γ = 5/9.
        WangMuser = "wang-muser",
        /// Xu et al., Tribol. Lett. (2024), doi:10.1007/s11249-024-01838-4, γ = 0.42.
        Xu = "xu",
        /// Overlap (bearing-area) model with the hardness law σ0 = σY A/A0
        /// (Abbott & Firestone 1933; needs a yield stress).
        Overlap = "overlap",
        /// Greenwood & Williamson, Proc. R. Soc. Lond. A 295, 300 (1966), summits
        /// from the moments m0, m2, m4 (Nayak 1971, McCool 1986).
        GreenwoodWilliamson = "greenwood-williamson",
        /// Bush, Gibson & Thomas, Wear 35, 87 (1975), at finite load.
        Bush = "bush",
    }
}

impl TheoryName {
    /// Whether this is one of the asperity theories (overlap, Greenwood–
    /// Williamson, Bush–Gibson–Thomas; module `asperity`), not one of
    /// Persson's.
    pub fn is_asperity(self) -> bool {
        matches!(
            self,
            TheoryName::Overlap | TheoryName::GreenwoodWilliamson | TheoryName::Bush
        )
    }
}

/// A theory and (corrected theories) its γ.
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TheorySpec {
    /// The theory.
    pub theory: TheoryName,
    /// γ of a corrected theory (default: the paper's value; none for `original`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
}

impl TheorySpec {
    /// The validated theory.
    ///
    /// # Errors
    /// γ given for `original`, or out of the theory's range; an asperity
    /// theory (it is not one of Persson's, see [`crate::asperity`]).
    pub fn build(&self) -> Result<Theory> {
        if self.theory.is_asperity() {
            return Err(Error::Inconsistent {
                name: "theory".into(),
                requirement: format!(
                    "{} is an asperity theory, not one of Persson's (original, yang-persson, \
                     wang-muser, xu): it has no G and no γ; it is an `area` theory and is in `compare`",
                    self.theory
                ),
            });
        }
        Theory::from_name(self.theory.name(), self.gamma)
    }

    /// Each of Persson's theories (original and the corrected ones) with its default γ.
    pub fn all() -> Vec<TheorySpec> {
        TheoryName::ALL
            .iter()
            .filter(|&&t| !t.is_asperity())
            .map(|&theory| TheorySpec {
                theory,
                gamma: None,
            })
            .collect()
    }
}

names! {
    /// The surrogates of a measured map (`surrogates`).
    #[derive(Default)]
    SurrogateKindName {
        /// The map's periodic spectrum with random phases: a Gaussian surface.
        #[default]
        Phase = "phase",
        /// The map's heights, rearranged to the map's spectrum (IAAFT).
        AmplitudeAdjusted = "amplitude-adjusted",
    }
}

names! {
    /// The iteration of an adhesive BEM path (`bem rough --adhesive-iteration`,
    /// `outputs.bem_adhesion.adhesive_iteration`).
    #[derive(Default)]
    AdhesiveIteration {
        /// The solver's choice by the law: preconditioned for the exponential
        /// law, plain for Maugis–Dugdale.
        #[default]
        Auto = "auto",
        /// Rey, Anciaux & Molinari's conjugate gradient.
        Plain = "plain",
        /// The same, preconditioned by the compliance on the free set: 10–20×
        /// fewer iterations; for Maugis–Dugdale the plain one's answer within
        /// 0.2 % only where the grid resolves the cohesive zone, and along a
        /// loading–unloading path it may follow another branch.
        Preconditioned = "preconditioned",
    }
}

//! The scene file: every field, with serde enums for every closed set,
//! spelled as on the command line (`periodic`, `surface-topography`,
//! `yang-persson`). The same enums are the CLI's value enums, so a scene and
//! a flag accept exactly the same strings.

use std::path::PathBuf;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

use persson::corrected::Theory;
use persson::error::{Error, Result};
use persson::material::{Body, Material};
use persson::spectrum::{Amplitude, Convention, SelfAffine, Spectrum, Tabulated};
use persson::stress::Start;

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
    /// The roughness spectrum (or, for `bem` only, a height map).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spectrum: Option<SpectrumSpec>,
    /// Nominal (mean) pressures σ0, in the unit of the contact modulus
    /// (`pressures` in persson 0.1).
    #[serde(default, alias = "pressures", skip_serializing_if = "Vec::is_empty")]
    pub nominal_pressure: Vec<f64>,
    /// What to compute; absent outputs are not computed.
    pub outputs: Outputs,
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

/// The built-in example's nominal pressures, Pa.
pub const EXAMPLE_PRESSURES: [f64; 6] = [1e4, 1e5, 1e6, 1e7, 1e8, 3e8];

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

    /// Build the material (E* takes precedence over the bodies).
    ///
    /// # Errors
    /// Missing or invalid fields, named as in the scene file.
    pub fn build(&self) -> Result<Material> {
        if let Some(e) = self.contact_modulus {
            return Material::new(e);
        }
        let (Some(young), Some(poisson)) = (self.young, self.poisson) else {
            return Err(required("contact_modulus (or young and poisson)"));
        };
        let a = Body { young, poisson };
        match (self.young2, self.poisson2) {
            (Some(young), Some(poisson)) => Material::from_bodies(a, Body { young, poisson }),
            (None, None) => Material::from_body(a),
            _ => Err(required("young2 and poisson2 together")),
        }
    }
}

/// The roughness of a scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SpectrumSpec {
    /// Self-affine with roll-off: C = C(q_r) for q_l ≤ q < q_r, C(q_r)(q/q_r)^(−2(H+1))
    /// up to q_s; exactly one amplitude (`rms_height`, `rms_slope` or `c_r`).
    SelfAffine {
        /// Hurst exponent H in (0, 1).
        hurst: f64,
        /// Lower cut-off q_l, 1/m.
        q_l: f64,
        /// Roll-off q_r, 1/m (default q_l: no roll-off).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        q_r: Option<f64>,
        /// Upper cut-off q_s, 1/m.
        q_s: f64,
        /// rms height over [q_l, q_s], m.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rms_height: Option<f64>,
        /// rms slope over [q_l, q_s].
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rms_slope: Option<f64>,
        /// C(q_r), m⁴.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        c_r: Option<f64>,
    },
    /// A tabulated spectrum: a CSV file of q and C (relative paths are
    /// relative to the scene file).
    Tabulated {
        /// The file.
        file: PathBuf,
        /// Its normalisation (default `persson`).
        #[serde(default)]
        convention: ConventionName,
        /// Side L (m) of the periodic surface, for the convention `grid`.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        size: Option<f64>,
    },
    /// A measured height map (or line scans): its isotropic spectrum serves
    /// every output, and `outputs.bem` solves on the map itself (relative
    /// paths are relative to the scene file).
    HeightMap(HeightMapSpec),
}

/// A measured surface, read with [`persson::topography::read()`] and
/// conditioned as [`persson::topography::analyse`] does (feature `topography`);
/// the same fields as the flags `--surface`, `--size`, `--pixel-size`,
/// `--periodic`, `--detrend`, `--window`, `--fill-undefined`, `--q-max`,
/// `--height-unit`, `--lateral-unit`, `--transpose`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HeightMapSpec {
    /// The file: `.npy`, text matrix, `.xyz`, `.gsf`, `.x3p` or a two-column line scan.
    pub file: PathBuf,
    /// Physical size: `Lx` (square pixels) or `[Lx, Ly]`, m, `Lx` along a row of a
    /// `.npy` or text matrix (checked against the size of files that store one).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<Sides>,
    /// Pixel size Δ (square pixels), m, instead of `size`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pixel_size: Option<f64>,
    /// Whether the surface repeats itself (default: not, a measurement).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub periodic: bool,
    /// Detrending (default: plane for non-periodic maps, none for periodic ones).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub detrend: Option<DetrendName>,
    /// Window (default: hann for non-periodic maps, none for periodic ones).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub window: Option<WindowName>,
    /// Fill undefined points by harmonic interpolation instead of failing.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub fill_undefined: bool,
    /// Upper end of the band, 1/m (default: the Nyquist wavevector π/Δ).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_max: Option<f64>,
    /// Unit of the heights of a file that states none (default m; a file's
    /// own unit must agree).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height_unit: Option<LengthUnitName>,
    /// Unit of the x (and y) coordinates of a line scan or XYZ file that
    /// states none (default m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lateral_unit: Option<LengthUnitName>,
    /// Swap the axes of the map after reading (a row of the file becomes a
    /// column: for arrays saved in SurfaceTopography's `[ix, iy]` order).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub transpose: bool,
}

/// A physical size: one side `Lx` (square pixels) or both `[Lx, Ly]`, m.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize, JsonSchema)]
#[serde(untagged)]
pub enum Sides {
    /// `Lx`; `Ly = Lx·ny/nx`.
    One(f64),
    /// `[Lx, Ly]`.
    Two([f64; 2]),
}

impl HeightMapSpec {
    /// A spec with every option at its default.
    pub fn new(file: PathBuf) -> Self {
        HeightMapSpec {
            file,
            size: None,
            pixel_size: None,
            periodic: false,
            detrend: None,
            window: None,
            fill_undefined: false,
            q_max: None,
            height_unit: None,
            lateral_unit: None,
            transpose: false,
        }
    }
}

impl SpectrumSpec {
    /// The built-in example (see [`EXAMPLE`]).
    pub fn example() -> Self {
        SpectrumSpec::SelfAffine {
            hurst: 0.8,
            q_l: 1e4,
            q_r: Some(1e5),
            q_s: 1e8,
            rms_height: Some(1e-6),
            rms_slope: None,
            c_r: None,
        }
    }

    /// Build the spectrum (a height map's: its binned isotropic spectrum,
    /// feature `topography`).
    ///
    /// # Errors
    /// Missing or invalid fields (named as in the scene file); file errors.
    pub fn build(&self) -> Result<Box<dyn Spectrum>> {
        match self {
            SpectrumSpec::SelfAffine {
                hurst,
                q_l,
                q_r,
                q_s,
                rms_height,
                rms_slope,
                c_r,
            } => {
                let amp = match (rms_height, rms_slope, c_r) {
                    (Some(x), None, None) => Amplitude::RmsHeight(*x),
                    (None, Some(x), None) => Amplitude::RmsSlope(*x),
                    (None, None, Some(x)) => Amplitude::CR(*x),
                    _ => return Err(required("exactly one of rms_height, rms_slope, c_r")),
                };
                Ok(Box::new(SelfAffine::new(
                    *q_l,
                    q_r.unwrap_or(*q_l),
                    *q_s,
                    *hurst,
                    amp,
                )?))
            }
            SpectrumSpec::Tabulated {
                file,
                convention,
                size,
            } => Ok(Box::new(Tabulated::from_csv(
                file,
                convention.with(*size)?,
            )?)),
            SpectrumSpec::HeightMap(m) => m.spectrum(),
        }
    }

    /// As [`SpectrumSpec::build`], with what a measured surface assumed
    /// (detrend, window, periodicity, band) in words for the report titles.
    ///
    /// # Errors
    /// As [`SpectrumSpec::build`].
    pub fn build_described(&self) -> Result<(Box<dyn Spectrum>, Option<String>)> {
        self.build_warned().map(|b| (b.spectrum, b.description))
    }

    /// As [`SpectrumSpec::build_described`], with the warnings of a measured
    /// surface's analysis (a resampled line scan, no Hurst fit, bins left
    /// out).
    ///
    /// # Errors
    /// As [`SpectrumSpec::build`].
    pub fn build_warned(&self) -> Result<BuiltSpectrum> {
        match self {
            SpectrumSpec::HeightMap(m) => {
                let (s, d, w) = m.spectrum_warned()?;
                Ok(BuiltSpectrum {
                    spectrum: Box::new(s),
                    description: Some(d),
                    warnings: w,
                })
            }
            _ => Ok(BuiltSpectrum {
                spectrum: self.build()?,
                description: None,
                warnings: Vec::new(),
            }),
        }
    }

    /// Where C(q) has a kink inside the band (the roll-off), for the
    /// wavevector integrals of the mean separation.
    pub fn breaks(&self) -> Vec<f64> {
        match self {
            SpectrumSpec::SelfAffine { q_r: Some(q_r), .. } => vec![*q_r],
            _ => vec![],
        }
    }
}

/// A spectrum built from a scene's entry ([`SpectrumSpec::build_warned`]).
pub struct BuiltSpectrum {
    /// The spectrum.
    pub spectrum: Box<dyn Spectrum>,
    /// What a measured surface assumed, in words (`None` for the others).
    pub description: Option<String>,
    /// The warnings of a measured surface's analysis.
    pub warnings: Vec<crate::warning::Warning>,
}

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
    /// Boundary condition of the FFT-BEM.
    BoundaryName {
        /// Periodic surface (the rough-contact default).
        Periodic = "periodic",
        /// Free (non-periodic) surface, zero-padded (the Hertz default).
        Free = "free",
    }
}

#[cfg(feature = "bem")]
impl From<BoundaryName> for persson::bem::Boundary {
    fn from(b: BoundaryName) -> Self {
        match b {
            BoundaryName::Periodic => persson::bem::Boundary::Periodic,
            BoundaryName::Free => persson::bem::Boundary::Free,
        }
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
    /// γ given for `original`, or out of the theory's range.
    pub fn build(&self) -> Result<Theory> {
        Theory::from_name(self.theory.name(), self.gamma)
    }

    /// Each theory with its default γ.
    pub fn all() -> Vec<TheorySpec> {
        TheoryName::ALL
            .iter()
            .map(|&theory| TheorySpec {
                theory,
                gamma: None,
            })
            .collect()
    }
}

/// The outputs a scene asks for; absent ones are not computed.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Outputs {
    /// Moments of the spectrum, a power-law fit and C(q).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spectrum: Option<SpectrumOutput>,
    /// A/A0 against the scene's nominal pressures (load curve).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub area: Option<AreaOutput>,
    /// G(ζ) and A/A0 against magnification at one pressure.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub magnification: Option<MagnificationOutput>,
    /// κ of the linear low-load law; with spectrum, material and pressures
    /// also the linear contact fractions.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kappa: Option<KappaOutput>,
    /// A/A0 against load for several contact-area theories.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub theories: Option<TheoriesOutput>,
    /// Mean interfacial separation, stiffness and elastic energy against load.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub separation: Option<SeparationOutput>,
    /// Stress distributions P(σ, ζ).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stress: Option<StressOutput>,
    /// FFT-BEM rough contact at the scene's nominal pressures (feature `bem`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bem: Option<BemOutput>,
    /// FFT-BEM Hertz convergence, η per grid (feature `bem`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bem_hertz: Option<BemHertzOutput>,
}

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

/// Load curve: A/A0 against the scene's nominal pressures.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AreaOutput {
    /// Magnification ζ (default q_s/q_l, full magnification).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    /// Contact-area theory (default `original`).
    #[serde(default)]
    pub theory: TheoryName,
    /// γ of a corrected theory (default: the paper's value).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// Absolute tolerance on A/A0 of the corrected theories' solver (default 1e-12).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Draw A/A0 against load with the Bush and Persson lines (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

/// Magnification curve: G(ζ) and A/A0 against ζ at one pressure.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MagnificationOutput {
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// Explicit magnifications ζ ≥ 1 (default: `points` log-spaced from 1 to q_s/q_l).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub zeta: Vec<f64>,
    /// Number of log-spaced magnifications (default 41).
    #[serde(default = "default_points")]
    pub points: usize,
    /// Draw A/A0 against ζ (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
    /// Draw G(ζ) (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot_g: Option<PathBuf>,
}

fn default_points() -> usize {
    41
}

/// κ output (no options).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct KappaOutput {}

/// Corrected-theory load curves at the scene's nominal pressures.
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TheoriesOutput {
    /// The theories, e.g. `{"theory": "yang-persson", "gamma": 0.42}` (default: all four with their default γ).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub theories: Vec<TheorySpec>,
    /// Magnification ζ (default full).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    /// Absolute tolerance on A/A0 (default 1e-12).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Draw A/A0 against load for all of them (.svg or .png).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plot: Option<PathBuf>,
}

/// Mean-separation load curve at the scene's nominal pressures (Persson, Phys. Rev. Lett. 99, 125502 (2007)).
#[derive(Debug, Clone, Default, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SeparationOutput {
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

/// A missing input.
pub(crate) fn required(what: &str) -> Error {
    Error::Inconsistent {
        name: what.to_string(),
        requirement: "required by the scene's outputs".into(),
    }
}

/// The JSON Schema of a scene file (written to `scenes/schema.json`).
pub fn json_schema() -> String {
    let schema = schemars::schema_for!(Scene);
    let mut s = serde_json::to_string_pretty(&schema).unwrap_or_default();
    s.push('\n');
    s
}

names! {
    /// Least-squares detrending of a measured surface.
    DetrendName {
        /// Heights as they are.
        None = "none",
        /// The mean height.
        Mean = "mean",
        /// The least-squares plane.
        Plane = "plane",
        /// The least-squares quadratic.
        Curvature = "curvature",
    }
}

names! {
    /// Window applied before the spectrum of a measured surface.
    WindowName {
        /// No window.
        None = "none",
        /// Radial Hann window.
        Hann = "hann",
        /// Radial Blackman window.
        Blackman = "blackman",
    }
}

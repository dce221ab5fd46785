//! Scenes: one calculation described in a versioned JSON document.
//!
//! A scene names the material, the spectrum, the loads and the outputs it
//! wants; [`Scene::run`] computes exactly those outputs and nothing else.
//! Unknown fields are rejected with their name, line and column.
//!
//! ```json
//! { "schema": 1,
//!   "material": { "contact_modulus": 1e9 },
//!   "spectrum": { "kind": "self_affine", "hurst": 0.8, "q_l": 1e4, "q_r": 1e5, "q_s": 1e8, "rms_height": 1e-6 },
//!   "pressures": [1e5, 1e6, 1e7],
//!   "outputs": { "area": {}, "kappa": {} } }
//! ```

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::kappa::Kappa;
use crate::material::{Body, Material};
use crate::spectrum::{Amplitude, Convention, SelfAffine, Spectrum, Tabulated};
use crate::theory::{log_zetas, AreaPoint, Persson};

/// The scene format version this crate reads.
pub const SCHEMA: u32 = 1;

/// A scene file.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Format version: must be 1.
    pub schema: u32,
    /// A name for the calculation.
    #[serde(default)]
    pub name: Option<String>,
    /// Free text.
    #[serde(default)]
    pub description: Option<String>,
    /// The material (needed by every output but `kappa` alone).
    #[serde(default)]
    pub material: Option<MaterialSpec>,
    /// The roughness spectrum.
    #[serde(default)]
    pub spectrum: Option<SpectrumSpec>,
    /// Nominal (mean) pressures, in the unit of the modulus.
    #[serde(default)]
    pub pressures: Vec<f64>,
    /// What to compute.
    pub outputs: Outputs,
}

/// The material: E* directly, or one or two elastic bodies.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// E* directly.
    #[serde(default)]
    pub contact_modulus: Option<f64>,
    /// Young's modulus of the (first) body.
    #[serde(default)]
    pub young: Option<f64>,
    /// Poisson ratio of the (first) body.
    #[serde(default)]
    pub poisson: Option<f64>,
    /// Young's modulus of the second body (absent: rigid).
    #[serde(default)]
    pub young2: Option<f64>,
    /// Poisson ratio of the second body.
    #[serde(default)]
    pub poisson2: Option<f64>,
}

/// The roughness spectrum of a scene.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SpectrumSpec {
    /// Self-affine with roll-off; exactly one amplitude.
    SelfAffine {
        /// Hurst exponent.
        hurst: f64,
        /// Lower cut-off, 1/m.
        q_l: f64,
        /// Roll-off (default q_l), 1/m.
        #[serde(default)]
        q_r: Option<f64>,
        /// Upper cut-off, 1/m.
        q_s: f64,
        /// rms height, m.
        #[serde(default)]
        rms_height: Option<f64>,
        /// rms slope.
        #[serde(default)]
        rms_slope: Option<f64>,
        /// C(q_r), m⁴.
        #[serde(default)]
        c_r: Option<f64>,
    },
    /// A CSV file (relative paths are relative to the scene file).
    Tabulated {
        /// The file.
        file: PathBuf,
        /// Its convention (default Persson's).
        #[serde(default = "persson_convention")]
        convention: Convention,
    },
}

fn persson_convention() -> Convention {
    Convention::Persson
}

/// The outputs a scene asks for; absent ones are not computed.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Outputs {
    /// A/A0 against the scene's pressures (load curve).
    #[serde(default)]
    pub area: Option<AreaOutput>,
    /// G(ζ) and A/A0 against magnification.
    #[serde(default)]
    pub magnification: Option<MagnificationOutput>,
    /// κ and the linear contact fractions.
    #[serde(default)]
    pub kappa: Option<KappaOutput>,
}

/// Load-curve output.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct AreaOutput {
    /// Magnification (default full, q_s/q_l).
    #[serde(default)]
    pub zeta: Option<f64>,
}

/// Magnification-curve output.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MagnificationOutput {
    /// Nominal pressure.
    pub pressure: f64,
    /// Explicit magnifications (default: `points` log-spaced from 1 to q_s/q_l).
    #[serde(default)]
    pub zetas: Vec<f64>,
    /// Number of log-spaced magnifications.
    #[serde(default = "default_points")]
    pub points: usize,
}

fn default_points() -> usize {
    41
}

/// κ output (no options).
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct KappaOutput {}

/// What a scene computed: one entry per output asked for.
#[derive(Debug, Clone, Default, Serialize)]
pub struct SceneReport {
    /// The scene's name.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Load curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub area: Option<Vec<AreaPoint>>,
    /// Magnification curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub magnification: Option<Vec<AreaPoint>>,
    /// κ values.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kappa: Option<KappaReport>,
}

/// κ of both theories and, with a spectrum, the rms slope they use.
#[derive(Debug, Clone, Serialize)]
pub struct KappaReport {
    /// √(2π).
    pub kappa_bush: f64,
    /// √(8/π).
    pub kappa_persson: f64,
}

impl Scene {
    /// Parse a scene from JSON text; `path` is used in errors and to resolve
    /// relative input files.
    ///
    /// # Errors
    /// [`Error::Parse`] with the line and column of a syntax error, a typo
    /// (unknown field, naming it and the expected ones), a wrong type or a
    /// missing field; a schema other than 1.
    pub fn parse(path: &Path, text: &str) -> Result<Self> {
        let mut s: Scene = serde_json::from_str(text)
            .map_err(|e| Error::parse(path, e.line(), e.column(), json_message(&e)))?;
        if s.schema != SCHEMA {
            return Err(Error::parse(
                path,
                0,
                0,
                format!("schema = {}: this version reads schema {SCHEMA}", s.schema),
            ));
        }
        let base = path.parent().unwrap_or(Path::new("."));
        if let Some(SpectrumSpec::Tabulated { file, .. }) = &mut s.spectrum {
            if file.is_relative() {
                *file = base.join(&*file);
            }
        }
        Ok(s)
    }

    /// Read and parse a scene file.
    ///
    /// # Errors
    /// [`Error::Io`], or as [`Scene::parse`].
    pub fn read(path: &Path) -> Result<Self> {
        let bytes = crate::io::read(path)?;
        let text = String::from_utf8(bytes)
            .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
        Self::parse(path, &text)
    }

    /// Build the material.
    ///
    /// # Errors
    /// Missing or invalid material fields, named `material.<field>`.
    pub fn material(&self) -> Result<Material> {
        let m = self.material.as_ref().ok_or_else(|| missing("material"))?;
        let named = |e: Error| prefix("material.", e);
        if let Some(e) = m.contact_modulus {
            return Material::new(e).map_err(named);
        }
        let (Some(young), Some(poisson)) = (m.young, m.poisson) else {
            return Err(missing(
                "material.contact_modulus (or material.young and material.poisson)",
            ));
        };
        let a = Body { young, poisson };
        match (m.young2, m.poisson2) {
            (Some(young), Some(poisson)) => {
                Material::from_bodies(a, Body { young, poisson }).map_err(named)
            }
            (None, None) => Material::from_body(a).map_err(named),
            _ => Err(missing("material.young2 and material.poisson2 together")),
        }
    }

    /// Build the spectrum.
    ///
    /// # Errors
    /// Missing or invalid spectrum fields, named `spectrum.<field>`; file errors.
    pub fn spectrum(&self) -> Result<Box<dyn Spectrum>> {
        let named = |e: Error| prefix("spectrum.", e);
        match self.spectrum.as_ref().ok_or_else(|| missing("spectrum"))? {
            SpectrumSpec::SelfAffine {
                hurst,
                q_l,
                q_r,
                q_s,
                rms_height,
                rms_slope,
                c_r,
            } => {
                let amp =
                    match (rms_height, rms_slope, c_r) {
                        (Some(x), None, None) => Amplitude::RmsHeight(*x),
                        (None, Some(x), None) => Amplitude::RmsSlope(*x),
                        (None, None, Some(x)) => Amplitude::CR(*x),
                        _ => return Err(missing(
                            "exactly one of spectrum.rms_height, spectrum.rms_slope, spectrum.c_r",
                        )),
                    };
                Ok(Box::new(
                    SelfAffine::new(*q_l, q_r.unwrap_or(*q_l), *q_s, *hurst, amp).map_err(named)?,
                ))
            }
            SpectrumSpec::Tabulated { file, convention } => {
                Ok(Box::new(Tabulated::from_csv(file, *convention)?))
            }
        }
    }

    /// Compute every output the scene names, and only those.
    ///
    /// # Errors
    /// The first invalid input or failed computation.
    pub fn run(&self) -> Result<SceneReport> {
        let o = &self.outputs;
        let mut report = SceneReport {
            name: self.name.clone(),
            ..Default::default()
        };
        if o.kappa.is_some() {
            report.kappa = Some(KappaReport {
                kappa_bush: Kappa::Bush.value(),
                kappa_persson: Kappa::Persson.value(),
            });
        }
        if o.area.is_none() && o.magnification.is_none() {
            return Ok(report);
        }
        let spectrum = self.spectrum()?;
        let material = self.material()?;
        let model = Persson::new(spectrum.as_ref(), material.contact_modulus())?;
        if let Some(a) = &o.area {
            if self.pressures.is_empty() {
                return Err(missing("pressures (a non-empty list, for outputs.area)"));
            }
            let zeta = a.zeta.unwrap_or_else(|| model.zeta_max());
            report.area = Some(
                model
                    .load_curve(&self.pressures, zeta)
                    .map_err(|e| prefix("", e))?,
            );
        }
        if let Some(m) = &o.magnification {
            let zetas = if m.zetas.is_empty() {
                log_zetas(model.zeta_max(), m.points)
            } else {
                m.zetas.clone()
            };
            report.magnification = Some(model.magnification_curve(&zetas, m.pressure)?);
        }
        Ok(report)
    }
}

/// serde_json's message without its trailing " at line L column C" (the
/// position is in the error's own fields).
pub(crate) fn json_message(e: &serde_json::Error) -> String {
    let s = e.to_string();
    match s.rfind(" at line ") {
        Some(i) => s[..i].to_string(),
        None => s,
    }
}

fn missing(what: &str) -> Error {
    Error::Inconsistent {
        name: what.to_string(),
        requirement: "required by the scene's outputs".into(),
    }
}

/// Prefix the parameter name of an [`Error::InvalidParameter`] with its section.
fn prefix(section: &str, e: Error) -> Error {
    match e {
        Error::InvalidParameter {
            name,
            value,
            requirement,
        } => Error::InvalidParameter {
            name: format!("{section}{name}"),
            value,
            requirement,
        },
        other => other,
    }
}

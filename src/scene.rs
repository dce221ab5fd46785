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
//!
//! With the feature `bem`, two more outputs: `bem` (FFT-BEM rough contact at
//! the scene's pressures, on a surface synthesised from the spectrum or read
//! from a `{"kind": "height_map", "file": …, "size": L}` spectrum entry) and
//! `bem_hertz` (the Hertz convergence table, η per grid). A build without
//! `bem` rejects a scene naming them.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::corrected::{Theory, TheoryPoint};
use crate::error::{Error, Result};
use crate::kappa::Kappa;
use crate::material::{Body, Material};
use crate::separation::{Separation, SeparationPoint};
use crate::spectrum::{Amplitude, Convention, SelfAffine, Spectrum, Tabulated};
use crate::stress::{HertzContact, Solver, Start, StressScene};
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
    /// A measured height map of the rigid surface, for the BEM outputs only
    /// (`.npy` float64/float32 2-D square, else a whitespace-separated text
    /// matrix; relative paths are relative to the scene file).
    HeightMap {
        /// The file.
        file: PathBuf,
        /// Its physical side L (unit of length of the scene).
        size: f64,
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
    /// A/A0 against load for the corrected theories.
    #[serde(default)]
    pub theories: Option<TheoriesOutput>,
    /// Mean interfacial separation and stiffness against load.
    #[serde(default)]
    pub separation: Option<SeparationOutput>,
    /// Stress distributions P(σ, ζ).
    #[serde(default)]
    pub stress: Option<StressOutput>,
    /// FFT-BEM rough contact at the scene's pressures (feature `bem`).
    #[serde(default)]
    pub bem: Option<BemOutput>,
    /// FFT-BEM Hertz convergence table, η per grid (feature `bem`).
    #[serde(default)]
    pub bem_hertz: Option<BemHertzOutput>,
}

/// FFT-BEM rough contact: the surface is synthesised from the scene's
/// spectrum (side 2π/q_l, `grid` nodes, `seed`) or read from its height map.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BemOutput {
    /// Grid side N of the synthesised surface (a height map sets its own).
    #[serde(default)]
    pub grid: Option<usize>,
    /// Seed of the synthesised surface (Pcg64Mcg, value-stable; default 1).
    #[serde(default)]
    pub seed: Option<u64>,
    /// `periodic` (default) or `free`.
    #[serde(default)]
    pub boundary: Option<String>,
    /// Solver tolerance ε (default 1e-10).
    #[serde(default)]
    pub tolerance: Option<f64>,
    /// Write the pressure histograms P(σ) as one CSV (pressure, pressure_low,
    /// pressure_high, density; each pressure's bins integrate to its A/A0).
    #[serde(default)]
    pub histogram: Option<PathBuf>,
    /// Number of histogram bins (default 50).
    #[serde(default)]
    pub bins: Option<usize>,
    /// Draw A/A0 against load with the Bush linear law (.svg or .png).
    #[serde(default)]
    pub plot: Option<PathBuf>,
}

/// FFT-BEM Hertz convergence: sphere R = L, a = 0.1 L, E* = 1 (lecture 000,
/// Table 1).
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BemHertzOutput {
    /// Grid sides (default 64, 128, 256).
    #[serde(default)]
    pub grids: Vec<usize>,
    /// `free` (default) or `periodic`.
    #[serde(default)]
    pub boundary: Option<String>,
    /// Solver tolerance ε (default 1e-12).
    #[serde(default)]
    pub tolerance: Option<f64>,
}

/// Corrected-theory load curves.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TheoriesOutput {
    /// The theories, e.g. `{"theory": "yang-persson", "gamma": 0.42}` (default: all four with their default γ).
    #[serde(default)]
    pub theories: Vec<Theory>,
    /// Magnification (default full).
    #[serde(default)]
    pub zeta: Option<f64>,
    /// Solver tolerance (default [`crate::corrected::DEFAULT_TOLERANCE`]).
    #[serde(default)]
    pub tolerance: Option<f64>,
    /// Draw A/A0 against load for all of them (.svg or .png).
    #[serde(default)]
    pub plot: Option<PathBuf>,
}

/// Mean-separation load curve.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SeparationOutput {
    /// Relative tolerance (default [`crate::separation::DEFAULT_TOLERANCE`]).
    #[serde(default)]
    pub tolerance: Option<f64>,
}

/// Stress distributions: dimensionless at given G (`g`), or physical at given
/// magnifications (`zetas`, with the scene's spectrum and material).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct StressOutput {
    /// `flat`, `hertz` or `cylinder`.
    pub start: String,
    /// Dimensionless mode: the values of G (σ in units of σH).
    #[serde(default)]
    pub g: Vec<f64>,
    /// Dimensionless mode: σY/σH (absent: elastic).
    #[serde(default)]
    pub yield_ratio: Option<f64>,
    /// Physical mode: the magnifications ζ.
    #[serde(default)]
    pub zetas: Vec<f64>,
    /// Physical mode: σH, Pa (flat: the nominal pressure). Or give `ball` / `cylinder`.
    #[serde(default)]
    pub peak_pressure: Option<f64>,
    /// Physical mode: a Hertz ball (start must be `hertz`).
    #[serde(default)]
    pub ball: Option<BallSpec>,
    /// Physical mode: a Hertz cylinder (start must be `cylinder`).
    #[serde(default)]
    pub cylinder: Option<CylinderSpec>,
    /// Physical mode: σY, Pa (absent: elastic).
    #[serde(default)]
    pub yield_stress: Option<f64>,
    /// Number of σ values per curve.
    #[serde(default = "default_stress_points")]
    pub points: usize,
    /// Absolute tolerance (units of 1/σH).
    #[serde(default = "default_stress_tolerance")]
    pub tolerance: f64,
    /// Draw the family of curves (.svg or .png).
    #[serde(default)]
    pub plot: Option<PathBuf>,
}

fn default_stress_points() -> usize {
    201
}

fn default_stress_tolerance() -> f64 {
    1e-12
}

/// A Hertz ball: radius (m) and load (N).
#[derive(Debug, Clone, Copy, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BallSpec {
    /// Radius, m.
    pub radius: f64,
    /// Load, N.
    pub load: f64,
}

/// A Hertz cylinder: radius (m) and load per unit length (N/m).
#[derive(Debug, Clone, Copy, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CylinderSpec {
    /// Radius, m.
    pub radius: f64,
    /// Load per unit length, N/m.
    pub load_per_length: f64,
}

/// Load-curve output.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct AreaOutput {
    /// Magnification (default full, q_s/q_l).
    #[serde(default)]
    pub zeta: Option<f64>,
    /// Draw A/A0 against load with the Bush and Persson lines (.svg or .png).
    #[serde(default)]
    pub plot: Option<PathBuf>,
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
    /// Draw A/A0 against ζ (.svg or .png).
    #[serde(default)]
    pub plot: Option<PathBuf>,
    /// Draw G(ζ) (.svg or .png).
    #[serde(default)]
    pub plot_g: Option<PathBuf>,
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
    /// Corrected-theory load curves, one per theory.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theories: Option<Vec<TheoryCurve>>,
    /// Mean separation against load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separation: Option<Vec<SeparationPoint>>,
    /// Stress distributions, one per G or ζ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stress: Option<Vec<StressReport>>,
    /// FFT-BEM rough contact.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem: Option<BemReport>,
    /// FFT-BEM Hertz convergence rows, one per grid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_hertz: Option<Vec<BemHertzRow>>,
}

/// The FFT-BEM rough contact of a scene.
#[derive(Debug, Clone, Serialize)]
pub struct BemReport {
    /// Grid side N.
    pub grid: usize,
    /// Side L of the surface.
    pub size: f64,
    /// `periodic` or `free`.
    pub boundary: String,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// Seed of the synthesised surface (absent for a height map).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// rms height of the surface on the grid.
    pub rms_height: f64,
    /// rms slope of the surface on the grid.
    pub rms_slope: f64,
    /// One point per pressure.
    pub points: Vec<BemPoint>,
}

/// One FFT-BEM solve.
#[derive(Debug, Clone, Serialize)]
pub struct BemPoint {
    /// Nominal pressure (unit of the modulus).
    pub pressure: f64,
    /// A/A0: fraction of nodes with p > 0.
    pub contact_fraction: f64,
    /// Solver iterations.
    pub iterations: usize,
    /// Final residual ε (≤ tolerance).
    pub residual: f64,
    /// Approach from first touch (unit of length).
    pub approach: f64,
    /// Wall time of the solve, s.
    pub seconds: f64,
    /// P(σ) when asked for: `[pressure_low, pressure_high, density]` per bin.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub histogram: Option<Vec<[f64; 3]>>,
}

/// One row of the FFT-BEM Hertz convergence table.
#[derive(Debug, Clone, Serialize)]
pub struct BemHertzRow {
    /// Grid side N.
    pub grid: usize,
    /// `periodic` or `free`.
    pub boundary: String,
    /// η: energy-norm error against the exact Hertz pressure.
    pub energy_error: f64,
    /// η of lecture 000, Table 1 (free boundary, where listed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lecture: Option<f64>,
    /// Relative error of the fitted contact radius.
    pub contact_radius_error: f64,
    /// Relative error of the fitted peak pressure.
    pub peak_pressure_error: f64,
    /// A/A0 (exact π a²/L² = 0.0314159…).
    pub contact_fraction: f64,
    /// Solver iterations.
    pub iterations: usize,
    /// Wall time of the solve, s.
    pub seconds: f64,
}

/// One corrected theory's load curve.
#[derive(Debug, Clone, Serialize)]
pub struct TheoryCurve {
    /// The theory and its γ.
    pub theory: Theory,
    /// Its low-load κ.
    pub kappa: f64,
    /// The points.
    pub points: Vec<TheoryPoint>,
}

/// One stress distribution of a scene (dimensionless or physical units).
#[derive(Debug, Clone, Serialize)]
pub struct StressReport {
    /// G of this curve.
    pub g: f64,
    /// ζ (physical mode only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    /// σ (units of σH, or Pa in physical mode).
    pub sigma: Vec<f64>,
    /// P(σ) (1/σH, or 1/Pa).
    pub density: Vec<f64>,
    /// A_el/A0.
    pub contact_fraction: f64,
    /// A_pl/A0.
    pub plastic_fraction: f64,
    /// Bound on the absolute error (dimensionless units).
    pub error_bound: f64,
    /// Which method computed it.
    pub method: String,
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
        if let Some(SpectrumSpec::Tabulated { file, .. } | SpectrumSpec::HeightMap { file, .. }) =
            &mut s.spectrum
        {
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
            SpectrumSpec::HeightMap { .. } => Err(Error::Inconsistent {
                name: "spectrum.kind = height_map".into(),
                requirement: "a height map serves only outputs.bem; the other outputs need a spectrum (self_affine or tabulated)".into(),
            }),
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
        if let Some(st) = o.stress.as_ref().filter(|st| st.zetas.is_empty()) {
            report.stress = Some(self.stress_dimensionless(st)?);
        }
        self.run_bem(&mut report)?;
        let needs_model = o.area.is_some()
            || o.magnification.is_some()
            || o.theories.is_some()
            || o.separation.is_some()
            || o.stress.as_ref().is_some_and(|st| !st.zetas.is_empty());
        if !needs_model {
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
        if let Some(t) = &o.theories {
            let zeta = t.zeta.unwrap_or_else(|| model.zeta_max());
            let tol = t.tolerance.unwrap_or(crate::corrected::DEFAULT_TOLERANCE);
            let list = if t.theories.is_empty() {
                Theory::all_defaults().to_vec()
            } else {
                t.theories.clone()
            };
            let pressures = self.pressures_for("outputs.theories")?;
            report.theories = Some(
                list.into_iter()
                    .map(|th| {
                        let th = th.validate()?;
                        Ok(TheoryCurve {
                            theory: th,
                            kappa: th.low_load_kappa(),
                            points: crate::corrected::load_curve(&model, th, zeta, pressures, tol)?,
                        })
                    })
                    .collect::<Result<Vec<_>>>()?,
            );
        }
        if let Some(sep) = &o.separation {
            let pressures = self.pressures_for("outputs.separation")?;
            let mut m = Separation::new(spectrum.as_ref(), material.contact_modulus())?;
            if let Some(tol) = sep.tolerance {
                m = m.with_tolerance(tol)?;
            }
            if let Some(SpectrumSpec::SelfAffine { q_r: Some(q_r), .. }) = &self.spectrum {
                m = m.with_breaks(&[*q_r]);
            }
            report.separation = Some(m.load_curve(pressures)?);
        }
        if let Some(st) = o.stress.as_ref().filter(|st| !st.zetas.is_empty()) {
            report.stress = Some(self.stress_physical(st, &model, material.contact_modulus())?);
        }
        Ok(report)
    }

    /// The BEM outputs (feature `bem`); without the feature, a scene naming
    /// one is an error.
    #[cfg(not(feature = "bem"))]
    fn run_bem(&self, _report: &mut SceneReport) -> Result<()> {
        let o = &self.outputs;
        for (name, asked) in [
            ("outputs.bem", o.bem.is_some()),
            ("outputs.bem_hertz", o.bem_hertz.is_some()),
        ] {
            if asked {
                return Err(Error::Inconsistent {
                    name: name.into(),
                    requirement: "needs a persson built with the `bem` feature".into(),
                });
            }
        }
        Ok(())
    }

    /// The BEM outputs (feature `bem`).
    #[cfg(feature = "bem")]
    fn run_bem(&self, report: &mut SceneReport) -> Result<()> {
        if let Some(h) = &self.outputs.bem_hertz {
            report.bem_hertz = Some(bem_hertz(h)?);
        }
        if let Some(b) = &self.outputs.bem {
            report.bem = Some(self.bem_rough(b)?);
        }
        Ok(())
    }

    /// The rigid surface of `outputs.bem`: the height map, or synthesised
    /// from the spectrum.
    #[cfg(feature = "bem")]
    fn bem_surface(
        &self,
        b: &BemOutput,
        boundary: crate::bem::Boundary,
    ) -> Result<crate::bem::Surface> {
        use crate::bem::{check_memory, surface};
        let named = |e: Error| prefix("outputs.bem.", e);
        if let Some(SpectrumSpec::HeightMap { file, size }) = &self.spectrum {
            if b.grid.is_some() || b.seed.is_some() {
                return Err(Error::Inconsistent {
                    name: "outputs.bem.grid / outputs.bem.seed".into(),
                    requirement: "not used with a height map (its file sets the grid)".into(),
                });
            }
            let size = crate::error::check::positive("spectrum.size", *size)?;
            let bytes = crate::io::read(file)?;
            // A float32 file of this length holds at most len/4 values.
            let n_max = ((bytes.len() / 4) as f64).sqrt() as usize;
            if n_max > crate::bem::MIN_GRID {
                check_memory(n_max.min(crate::bem::MAX_GRID), boundary).map_err(named)?;
            }
            return surface::height_map_from_bytes(file, &bytes, size);
        }
        let n = b
            .grid
            .ok_or_else(|| missing("outputs.bem.grid (for a synthesised surface)"))?;
        check_memory(n, boundary).map_err(named)?;
        let spectrum = self.spectrum()?;
        let size = std::f64::consts::TAU / spectrum.q_min();
        surface::synthesize(spectrum.as_ref(), n, size, b.seed.unwrap_or(1)).map_err(named)
    }

    /// `outputs.bem`: one solve per pressure, warm-started along the list.
    #[cfg(feature = "bem")]
    fn bem_rough(&self, b: &BemOutput) -> Result<BemReport> {
        use crate::bem::{pressure_histogram, Control, Operator, Options, Solver};
        let named = |e: Error| prefix("outputs.bem.", e);
        let boundary = parse_boundary("outputs.bem.boundary", b.boundary.as_deref(), "periodic")?;
        let tol = crate::error::check::tolerance("tolerance", b.tolerance.unwrap_or(1e-10))
            .map_err(named)?;
        let bins = b.bins.unwrap_or(50);
        if bins == 0 {
            return Err(named(Error::invalid("bins", 0.0, ">= 1")));
        }
        let pressures = self.pressures_for("outputs.bem")?;
        for &p in pressures {
            crate::error::check::positive("pressures", p)?;
        }
        let e_star = self.material()?.contact_modulus();
        let surf = self.bem_surface(b, boundary)?;
        let opts = Options {
            tol,
            warm_start: true,
            ..Options::default()
        };
        let mut solver = Solver::new(Operator::new(boundary, surf.n, surf.size, e_star)?);
        let points = pressures
            .iter()
            .map(|&p| {
                let sol = solver.solve(&surf.heights, Control::MeanPressure(p), &opts)?;
                let histogram = match b.histogram {
                    Some(_) => Some(
                        pressure_histogram(&sol.pressure, bins)?
                            .into_iter()
                            .map(|h| [h.sigma_low, h.sigma_high, h.density])
                            .collect(),
                    ),
                    None => None,
                };
                Ok(BemPoint {
                    pressure: p,
                    contact_fraction: sol.contact_fraction,
                    iterations: sol.iterations,
                    residual: sol.residual,
                    approach: sol.approach,
                    seconds: sol.seconds,
                    histogram,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        let synthesised = !matches!(self.spectrum, Some(SpectrumSpec::HeightMap { .. }));
        Ok(BemReport {
            grid: surf.n,
            size: surf.size,
            boundary: boundary_name(boundary).into(),
            tolerance: tol,
            seed: synthesised.then(|| b.seed.unwrap_or(1)),
            rms_height: surf.rms_height(),
            rms_slope: surf.rms_slope()?,
            points,
        })
    }

    /// The scene's pressures, required non-empty by `what`.
    fn pressures_for(&self, what: &str) -> Result<&[f64]> {
        if self.pressures.is_empty() {
            return Err(missing(&format!(
                "pressures (a non-empty list, for {what})"
            )));
        }
        Ok(&self.pressures)
    }

    /// Stress curves at the values of G, σ in units of σH.
    fn stress_dimensionless(&self, st: &StressOutput) -> Result<Vec<StressReport>> {
        let start = Start::from_name(&st.start).map_err(|e| prefix("outputs.stress.", e))?;
        if st.g.is_empty() {
            return Err(missing(
                "outputs.stress.g (dimensionless) or outputs.stress.zetas (physical)",
            ));
        }
        st.g.iter()
            .map(|&g| {
                let solver = Solver::new(&start, g, st.yield_ratio, st.tolerance)
                    .map_err(|e| prefix("outputs.stress.", e))?;
                let c = solver.curve(&solver.grid(st.points))?;
                Ok(StressReport {
                    g,
                    zeta: None,
                    sigma: c.sigma,
                    density: c.density,
                    contact_fraction: c.contact_fraction,
                    plastic_fraction: c.plastic_fraction,
                    error_bound: c.error_bound,
                    method: c.method,
                })
            })
            .collect()
    }

    /// Stress curves at the magnifications, in Pa and 1/Pa.
    fn stress_physical(
        &self,
        st: &StressOutput,
        model: &Persson,
        e_star: f64,
    ) -> Result<Vec<StressReport>> {
        let named = |e: Error| prefix("outputs.stress.", e);
        let start = Start::from_name(&st.start).map_err(named)?;
        let problem = match (&st.ball, &st.cylinder, st.peak_pressure) {
            (Some(b), None, None) if matches!(start, Start::Hertz) => {
                StressScene::hertz(&HertzContact::ball(b.radius, b.load, e_star).map_err(named)?, st.yield_stress)
            }
            (None, Some(c), None) if matches!(start, Start::Cylinder) => StressScene::hertz(
                &HertzContact::cylinder(c.radius, c.load_per_length, e_star).map_err(named)?,
                st.yield_stress,
            ),
            (None, None, Some(p)) => StressScene::new(start, p, st.yield_stress),
            _ => {
                return Err(missing(
                    "exactly one of outputs.stress.peak_pressure, .ball (start hertz), .cylinder (start cylinder)",
                ))
            }
        }
        .map_err(named)?;
        // σ from 0 to σY, or (elastic) to σH plus four standard deviations
        // √(2G) σ0 of the widest curve.
        let mut g_max = 0.0f64;
        for &z in &st.zetas {
            g_max = g_max.max(model.g(z, problem.nominal_pressure()).map_err(named)?.value);
        }
        let top = st.yield_stress.unwrap_or(
            problem.peak_pressure + 4.0 * (2.0 * g_max).sqrt() * problem.nominal_pressure(),
        );
        let n = st.points.max(2);
        let sigma: Vec<f64> = (0..n).map(|i| top * i as f64 / (n - 1) as f64).collect();
        Ok(problem
            .curves(model, &st.zetas, &sigma, st.tolerance)
            .map_err(named)?
            .into_iter()
            .map(|c| StressReport {
                g: c.g.value,
                zeta: Some(c.zeta),
                sigma: c.sigma,
                density: c.density,
                contact_fraction: c.contact_fraction,
                plastic_fraction: c.plastic_fraction,
                error_bound: c.error_bound,
                method: c.method,
            })
            .collect())
    }

    /// Every file the scene asks to write (plots), relative to `dir`.
    pub fn plot_paths(&self, dir: &Path) -> Vec<PathBuf> {
        let o = &self.outputs;
        [
            o.area.as_ref().and_then(|a| a.plot.clone()),
            o.magnification.as_ref().and_then(|m| m.plot.clone()),
            o.magnification.as_ref().and_then(|m| m.plot_g.clone()),
            o.theories.as_ref().and_then(|t| t.plot.clone()),
            o.stress.as_ref().and_then(|s| s.plot.clone()),
            o.bem.as_ref().and_then(|b| b.plot.clone()),
            o.bem.as_ref().and_then(|b| b.histogram.clone()),
        ]
        .into_iter()
        .flatten()
        .map(|p| dir.join(p))
        .collect()
    }
}

/// `outputs.bem_hertz`: η per grid.
#[cfg(feature = "bem")]
fn bem_hertz(h: &BemHertzOutput) -> Result<Vec<BemHertzRow>> {
    use crate::bem::{check_memory, hertz, Options};
    let named = |e: Error| prefix("outputs.bem_hertz.", e);
    let boundary = parse_boundary("outputs.bem_hertz.boundary", h.boundary.as_deref(), "free")?;
    let tol =
        crate::error::check::tolerance("tolerance", h.tolerance.unwrap_or(1e-12)).map_err(named)?;
    let grids = if h.grids.is_empty() {
        vec![64, 128, 256]
    } else {
        h.grids.clone()
    };
    let opts = Options {
        tol,
        ..Options::default()
    };
    grids
        .iter()
        .map(|&n| {
            check_memory(n, boundary).map_err(named)?;
            let r = hertz::validate(&hertz::HertzCase::new(n, boundary), &opts).map_err(named)?;
            let lecture = hertz::lecture_eta(n).filter(|_| boundary == crate::bem::Boundary::Free);
            Ok(BemHertzRow {
                grid: n,
                boundary: boundary_name(boundary).into(),
                energy_error: r.energy_error,
                lecture,
                contact_radius_error: r.contact_radius_error,
                peak_pressure_error: r.peak_pressure_error,
                contact_fraction: r.contact_fraction,
                iterations: r.iterations,
                seconds: r.seconds,
            })
        })
        .collect()
}

#[cfg(feature = "bem")]
fn parse_boundary(name: &str, v: Option<&str>, default: &str) -> Result<crate::bem::Boundary> {
    match v.unwrap_or(default) {
        "periodic" => Ok(crate::bem::Boundary::Periodic),
        "free" => Ok(crate::bem::Boundary::Free),
        other => Err(Error::Inconsistent {
            name: format!("{name} = {other:?}"),
            requirement: "\"periodic\" or \"free\"".into(),
        }),
    }
}

#[cfg(feature = "bem")]
fn boundary_name(b: crate::bem::Boundary) -> &'static str {
    match b {
        crate::bem::Boundary::Periodic => "periodic",
        crate::bem::Boundary::Free => "free",
    }
}

/// Write the scene's data files (the BEM pressure histograms) into `dir`.
///
/// # Errors
/// A file that cannot be written (written atomically).
pub fn write_data(scene: &Scene, report: &SceneReport, dir: &Path) -> Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    if let (Some(out), Some(r)) = (&scene.outputs.bem, &report.bem) {
        if let Some(file) = &out.histogram {
            let mut s = String::from("pressure,pressure_low,pressure_high,density\n");
            for pt in &r.points {
                for [lo, hi, d] in pt.histogram.iter().flatten() {
                    s.push_str(&format!("{:e},{lo:e},{hi:e},{d:e}\n", pt.pressure));
                }
            }
            let p = dir.join(file);
            crate::io::write_atomic(&p, s.as_bytes())?;
            written.push(p);
        }
    }
    Ok(written)
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

/// Draw every plot the scene names, into `dir` (feature `plot`).
///
/// # Errors
/// A plot that cannot be drawn or written (nothing is left half-written).
#[cfg(feature = "plot")]
pub fn render_plots(scene: &Scene, report: &SceneReport, dir: &Path) -> Result<Vec<PathBuf>> {
    use crate::plot::{self, Axis, Figure, LinearLaw, Series, Style};
    let o = &scene.outputs;
    let mut written = Vec::new();
    let mut draw = |path: &Option<PathBuf>, fig: &dyn Fn() -> Result<Figure>| -> Result<()> {
        if let Some(p) = path {
            let p = dir.join(p);
            plot::render(&fig()?, &p)?;
            written.push(p);
        }
        Ok(())
    };
    let e_star = || scene.material().map(|m| m.contact_modulus());
    if let (Some(out), Some(pts)) = (&o.area, &report.area) {
        draw(&out.plot, &|| {
            let p: Vec<f64> = pts.iter().map(|x| x.pressure).collect();
            let a: Vec<f64> = pts.iter().map(|x| x.contact_fraction).collect();
            let law = LinearLaw {
                contact_modulus: e_star()?,
                rms_slope: pts[0].rms_slope,
            };
            plot::area_vs_load(
                &p,
                &[("Persson (original theory)", &a)],
                "unit of E*",
                Some(law),
            )
        })?;
    }
    if let (Some(out), Some(pts)) = (&o.magnification, &report.magnification) {
        let z: Vec<f64> = pts.iter().map(|x| x.zeta).collect();
        let label = format!("σ0 = {:e}", out.pressure);
        draw(&out.plot, &|| {
            let a: Vec<f64> = pts.iter().map(|x| x.contact_fraction).collect();
            plot::area_vs_zeta(&z, &[(label.as_str(), &a)])
        })?;
        draw(&out.plot_g, &|| {
            let g: Vec<f64> = pts.iter().map(|x| x.g).collect();
            plot::g_vs_zeta(&z, &[(label.as_str(), &g)])
        })?;
    }
    if let (Some(out), Some(curves)) = (&o.theories, &report.theories) {
        draw(&out.plot, &|| {
            let p: Vec<f64> = curves[0].points.iter().map(|x| x.pressure).collect();
            let labels: Vec<String> = curves
                .iter()
                .map(|c| match c.theory.gamma() {
                    None => format!("{} (κ = {:.3})", c.theory.name(), c.kappa),
                    Some(g) => format!("{}, γ = {g:.3} (κ = {:.3})", c.theory.name(), c.kappa),
                })
                .collect();
            let a: Vec<Vec<f64>> = curves
                .iter()
                .map(|c| c.points.iter().map(|x| x.contact_fraction).collect())
                .collect();
            let refs: Vec<(&str, &[f64])> = labels
                .iter()
                .zip(&a)
                .map(|(l, v)| (l.as_str(), v.as_slice()))
                .collect();
            let spectrum = scene.spectrum()?;
            let m = Persson::new(spectrum.as_ref(), e_star()?)?;
            let zeta = curves[0].points[0].zeta;
            let law = LinearLaw {
                contact_modulus: e_star()?,
                rms_slope: m.slope_variance(zeta)?.value.sqrt(),
            };
            plot::area_vs_load(&p, &refs, "unit of E*", Some(law))
        })?;
    }
    if let (Some(out), Some(curves)) = (&o.stress, &report.stress) {
        draw(&out.plot, &|| {
            let physical = !out.zetas.is_empty();
            let (x, y) = if physical {
                ("normal stress σ (Pa)", "P(σ, ζ) (1/Pa)")
            } else {
                ("normal stress σ/σH", "P(σ, ζ) (1/σH)")
            };
            let mut fig = Figure::new(
                format!("Stress distribution P(σ, ζ), {} start", out.start),
                Axis::linear(x),
                Axis::linear(y),
            );
            let styles = [Style::Line, Style::Dashed, Style::Dotted];
            for (i, c) in curves.iter().enumerate() {
                let label = match c.zeta {
                    Some(z) => format!("ζ = {z}, G = {:.3}, A/A0 = {:.3}", c.g, c.contact_fraction),
                    None => format!("G = {}, A/A0 = {:.3}", c.g, c.contact_fraction),
                };
                // A flat start at G = 0 is a δ at σ0: nothing finite to draw.
                let pts = c
                    .sigma
                    .iter()
                    .copied()
                    .zip(c.density.iter().copied())
                    .filter(|p| p.1.is_finite())
                    .collect();
                fig.push(Series::new(label, pts, styles[i % styles.len()]));
            }
            Ok(fig)
        })?;
    }
    if let (Some(out), Some(r)) = (&o.bem, &report.bem) {
        draw(&out.plot, &|| {
            let p: Vec<f64> = r.points.iter().map(|x| x.pressure).collect();
            let a: Vec<f64> = r.points.iter().map(|x| x.contact_fraction).collect();
            let label = format!("FFT-BEM, {0}×{0} {1}", r.grid, r.boundary);
            let law = LinearLaw {
                contact_modulus: e_star()?,
                rms_slope: r.rms_slope,
            };
            plot::area_vs_load(&p, &[(label.as_str(), &a)], "unit of E*", Some(law))
        })?;
    }
    Ok(written)
}

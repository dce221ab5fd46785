//! Scenes: one calculation described in a versioned JSON document.
//!
//! A scene names the material, the spectrum, the loads and the outputs it
//! wants; [`Scene::run`] computes exactly those outputs and nothing else.
//! Unknown fields are rejected with their name, line and column. The file
//! format is [`schema`] (its JSON Schema is `crates/persson-studies/schema/scene.schema.json`), the
//! computation [`run`] and the typed results [`report`]: the subcommands
//! `area`, `magnification`, `kappa`, `separation` and `stress` call the same
//! functions and print the same reports. The output `friction` (rubber
//! friction, with the scene's `rubber` instead of `material`) is computed by
//! [`friction()`], which `persson friction` calls too.
//!
//! ```json
//! { "schema": 1,
//!   "material": { "contact_modulus": 1e9 },
//!   "spectrum": { "kind": "self_affine", "hurst": 0.8, "q_l": 1e4, "q_r": 1e5, "q_s": 1e8, "rms_height": 1e-6 },
//!   "nominal_pressure": [1e5, 1e6, 1e7],
//!   "outputs": { "area": {}, "kappa": {} } }
//! ```
//!
//! With the feature `bem`, two more outputs: `bem` (FFT-BEM rough contact at
//! the scene's pressures, on a surface synthesised from the spectrum or read
//! from a `{"kind": "height_map", "file": …, "size": L}` spectrum entry) and
//! `bem_hertz` (the Hertz convergence table, η per grid). A build without
//! `bem` rejects a scene naming them.

use std::path::{Path, PathBuf};

use persson::error::{Error, Result};
use persson::material::Material;
use persson::spectrum::Spectrum;

use crate::output::Files;

mod list;
pub mod plot;
pub mod report;
pub mod run;
pub mod schema;

pub use crate::adhesion::{
    DEFAULT_STICKINESS_POINTS, DEFAULT_TOLERANCE as DEFAULT_ADHESION_TOLERANCE,
};
pub use crate::friction;
pub use crate::friction::{friction, friction_on, MAX_VELOCITIES};
#[cfg(feature = "topography")]
pub use crate::input::describe;
pub use crate::separation_density;
pub use crate::transport;
pub use crate::transport::bem as transport_bem;
pub use list::{Outputs, SceneReport};
pub use report::*;
pub use run::RoughContact;
pub use schema::*;

use crate::study::{Context, Inputs};

use crate::naming::{prefix, required};

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
        if let Some(spectrum) = &mut s.spectrum {
            for file in spectrum.files_mut() {
                if file.as_os_str().is_empty() {
                    return Err(Error::parse(
                        path,
                        0,
                        0,
                        "spectrum: a file name is empty (\"file\": \"\")",
                    ));
                }
                if file.is_relative() {
                    *file = base.join(&*file);
                }
            }
        }
        if let Some(r) = &mut s.rubber {
            r.resolve(base);
        }
        Ok(s)
    }

    /// Read and parse a scene file.
    ///
    /// # Errors
    /// [`Error::Io`], or as [`Scene::parse`].
    pub fn read(path: &Path) -> Result<Self> {
        let bytes = persson::io::read(path)?;
        let text = String::from_utf8(bytes)
            .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
        Self::parse(path, &text)
    }

    /// Build the material.
    ///
    /// # Errors
    /// Missing or invalid material fields, named `material.<field>`.
    pub fn material(&self) -> Result<Material> {
        let m = self.material.as_ref().ok_or_else(|| required("material"))?;
        m.build().map_err(|e| prefix("material.", e))
    }

    /// Build the spectrum.
    ///
    /// # Errors
    /// Missing or invalid spectrum fields, named `spectrum.<field>`; file errors.
    pub fn spectrum(&self) -> Result<Box<dyn Spectrum>> {
        let s = self.spectrum.as_ref().ok_or_else(|| required("spectrum"))?;
        s.build().map_err(|e| prefix("spectrum.", e))
    }

    /// The spectrum and the material together.
    ///
    /// # Errors
    /// As [`Scene::spectrum`] and [`Scene::material`].
    pub fn contact(&self) -> Result<RoughContact> {
        let s = self.spectrum.as_ref().ok_or_else(|| required("spectrum"))?;
        let m = self.material.as_ref().ok_or_else(|| required("material"))?;
        RoughContact::named(s, m, "spectrum.", "material.")
    }

    /// The scene's inputs, as given.
    pub fn inputs(&self) -> Inputs<'_> {
        Inputs {
            spectrum: self.spectrum.as_ref(),
            material: self.material.as_ref(),
            rubber: self.rubber.as_ref(),
            nominal_pressure: &self.nominal_pressure,
        }
    }

    /// The context the outputs run in: the inputs and, if an output reads
    /// it, the rough contact built from them.
    ///
    /// # Errors
    /// A missing or invalid spectrum or material an output reads.
    pub fn context(&self) -> Result<Context<'_>> {
        let inputs = self.inputs();
        Context::new(inputs, self.outputs.reads(&inputs))
    }

    /// Compute every output the scene names, and only those.
    ///
    /// # Errors
    /// The first invalid input or failed computation.
    pub fn run(&self) -> Result<SceneReport> {
        self.check_unused()?;
        self.run_in(&self.context()?)
    }

    /// Compute every output the scene names, as [`Scene::run`], and stage
    /// every file it asks for into `out` (in `dir`), as reserved by
    /// [`Scene::plan`], on the same context (the rough contact built once);
    /// the caller commits them once the whole run has succeeded.
    ///
    /// # Errors
    /// As [`Scene::run`]; a plot that cannot be drawn; a staged file that
    /// cannot be written.
    pub fn run_and_write(&self, dir: &Path, out: &mut Files) -> Result<SceneReport> {
        self.check_unused()?;
        let ctx = self.context()?;
        let report = self.run_in(&ctx)?;
        self.outputs.write(&report, &ctx, dir, out)?;
        Ok(report)
    }

    fn run_in(&self, ctx: &Context<'_>) -> Result<SceneReport> {
        let mut report = SceneReport {
            name: self.name.clone(),
            description: self.description.clone(),
            ..Default::default()
        };
        if let Some(SpectrumSpec::Tabulated {
            file, convention, ..
        }) = &self.spectrum
        {
            // Whatever output reads it (the BEM's synthesis too).
            report.warnings.push(crate::Warning::PsdConvention {
                file: file.clone(),
                convention: *convention,
            });
        }
        self.outputs.run(ctx, &mut report)?;
        report.collect_warnings();
        Ok(report)
    }

    /// Every section the scene gives is checked, even one no output reads
    /// (a scene is refused for what the command line refuses): the
    /// spectrum, material, rubber and pressures no output uses are built
    /// here (the ones an output uses are built by it); a scene that asks
    /// for nothing is refused.
    fn check_unused(&self) -> Result<()> {
        if self.outputs.is_empty() {
            return Err(Error::Inconsistent {
                name: "outputs".into(),
                requirement:
                    "at least one output (area, spectrum, bem, …): the scene asks for nothing"
                        .into(),
            });
        }
        let reads = self.outputs.reads(&self.inputs());
        if !reads.spectrum && self.spectrum.is_some() {
            self.spectrum()?;
        }
        if !reads.material && self.material.is_some() {
            self.material()?;
        }
        if !reads.rubber {
            if let Some(r) = &self.rubber {
                r.build(false).map_err(|e| prefix("rubber.", e))?;
            }
        }
        if !reads.nominal_pressure {
            for &p in &self.nominal_pressure {
                persson::error::check::positive("nominal_pressure", p)?;
            }
        }
        Ok(())
    }

    /// Every file the scene asks to write, relative to `dir`: its field,
    /// its path and the extensions that pick its format (empty: any).
    pub fn output_files(&self, dir: &Path) -> Vec<(String, PathBuf, &'static [&'static str])> {
        self.outputs
            .files()
            .into_iter()
            .map(|(field, p, formats)| (field, dir.join(p), formats))
            .collect()
    }

    /// The input files the scene reads.
    pub fn input_paths(&self) -> Vec<PathBuf> {
        let mut spectrum = self.spectrum.clone();
        let mut files: Vec<PathBuf> = spectrum
            .as_mut()
            .map(|s| s.files_mut().into_iter().map(|f| f.clone()).collect())
            .unwrap_or_default();
        if let Some(r) = &self.rubber {
            files.extend(r.files());
        }
        files
    }

    /// Before anything is computed: declare the scene's inputs (the scene
    /// file `path` among them) and reserve every file it writes into `dir`
    /// ([`crate::output::Files`]), each named by its field.
    ///
    /// # Errors
    /// An output onto an input or onto another output, of a format its
    /// extension does not name, or in a folder that does not accept it; a
    /// plot in a build without the feature `plot`.
    pub fn plan(&self, path: &Path, dir: &Path, out: &mut Files) -> Result<()> {
        out.input("the scene file", path)?;
        for f in self.input_paths() {
            out.input("an input file of the scene", &f)?;
        }
        for (field, p, formats) in self.output_files(dir) {
            if cfg!(not(feature = "plot")) && !formats.is_empty() {
                return Err(Error::Inconsistent {
                    name: field,
                    requirement: "plots need persson built with the feature `plot`".into(),
                });
            }
            out.reserve(&field, &p, formats)?;
        }
        Ok(())
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

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
use persson::stress::Start;

use crate::output::Files;

mod adhesion;
mod asperity;
#[cfg(feature = "bem")]
mod bem;
pub mod friction;
mod measured;
pub mod multiscale;
#[cfg(feature = "plot")]
pub mod plot;
pub mod report;
pub mod run;
pub mod schema;
pub mod separation_density;
pub mod transport;
#[cfg(feature = "flow")]
pub mod transport_bem;

pub use adhesion::{DEFAULT_STICKINESS_POINTS, DEFAULT_TOLERANCE as DEFAULT_ADHESION_TOLERANCE};
pub use friction::{friction, friction_on, MAX_VELOCITIES};
#[cfg(feature = "topography")]
pub use measured::describe;
pub use report::*;
pub use run::RoughContact;
pub use schema::*;

use run::prefix;

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

    /// Compute every output the scene names, and only those.
    ///
    /// # Errors
    /// The first invalid input or failed computation.
    pub fn run(&self) -> Result<SceneReport> {
        self.check_unused()?;
        let o = &self.outputs;
        let mut report = SceneReport {
            name: self.name.clone(),
            description: self.description.clone(),
            ..Default::default()
        };
        if let Some(st) = o.stress.as_ref().filter(|st| st.zeta.is_empty()) {
            st.check_mode().map_err(|e| prefix("outputs.stress.", e))?;
            report.stress = Some(
                run::stress_dimensionless(
                    &Start::from(st.start),
                    &st.g,
                    st.yield_ratio,
                    st.tolerance,
                    &[],
                    st.points,
                )
                .map_err(|e| prefix("outputs.stress.", e))?,
            );
        }
        if let Some(sp) = &o.spectrum {
            let s = self.spectrum()?;
            let example = self.spectrum == Some(SpectrumSpec::example());
            let mut r = run::spectrum(
                s.as_ref(),
                example.then(|| EXAMPLE.to_string()),
                sp.q_min,
                sp.q_max,
                sp.points,
            )
            .map_err(|e| prefix("outputs.spectrum.", e))?;
            if let Some(spec) = &self.spectrum {
                for w in run::spectrum_warnings(spec, s.as_ref()) {
                    crate::warning::push(&mut r.warnings, Some(w));
                }
            }
            report.spectrum = Some(r);
        }
        self.run_bem(&mut report)?;
        if let Some(f) = &o.friction {
            let s = self.spectrum.as_ref().ok_or_else(|| required("spectrum"))?;
            let r = self
                .rubber
                .as_ref()
                .ok_or_else(|| required("rubber (for outputs.friction)"))?;
            report.friction = Some(friction::friction_named(
                s,
                r,
                &self.nominal_pressure,
                f,
                ["spectrum.", "rubber.", "outputs.friction."],
            )?);
        }
        let surface = if self.needs_surface() {
            Some(self.contact()?)
        } else {
            None
        };
        if o.kappa.is_some() {
            let with = surface
                .as_ref()
                .filter(|_| !self.nominal_pressure.is_empty())
                .map(|s| (s, self.nominal_pressure.as_slice()));
            report.kappa = Some(run::kappa(with)?);
        }
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
        let Some(surface) = surface else {
            report.collect_warnings();
            return Ok(report);
        };
        if let Some(a) = &o.area {
            report.area = Some(
                run::area(&surface, &self.nominal_pressure, a)
                    .map_err(|e| prefix("outputs.area.", e))?,
            );
        }
        if let Some(m) = &o.magnification {
            report.magnification = Some(
                run::magnification(&surface, m).map_err(|e| prefix("outputs.magnification.", e))?,
            );
        }
        if let Some(t) = &o.theories {
            report.theories = Some(
                run::theories(&surface, &self.nominal_pressure, t)
                    .map_err(|e| prefix("outputs.theories.", e))?,
            );
        }
        if let Some(sep) = &o.separation {
            report.separation = Some(
                run::separation(&surface, &self.nominal_pressure, sep, &[])
                    .map_err(|e| prefix("outputs.separation.", e))?,
            );
        }
        if let Some(d) = &o.separation_density {
            report.separation_density = Some(
                separation_density::separation_density(
                    &surface,
                    &self.nominal_pressure,
                    d.density_points.unwrap_or(101),
                    d.tolerance
                        .unwrap_or(persson::separation::DEFAULT_TOLERANCE),
                )
                .map_err(|e| prefix("outputs.separation_density.", e))?,
            );
        }
        if let Some(c) = &o.conductance {
            report.conductance = Some(
                transport::conductance(&surface, &self.nominal_pressure, c)
                    .map_err(|e| prefix("outputs.conductance.", e))?,
            );
        }
        if let Some(l) = &o.leakage {
            report.leakage = Some(
                transport::leakage(&surface, &self.nominal_pressure, l)
                    .map_err(|e| prefix("outputs.leakage.", e))?,
            );
        }
        if let Some(ad) = &o.adhesion {
            report.adhesion = Some(
                run::adhesion(&surface, &self.nominal_pressure, ad)
                    .map_err(|e| prefix("outputs.adhesion.", e))?,
            );
        }
        if let Some(st) = o.stress.as_ref().filter(|st| !st.zeta.is_empty()) {
            report.stress =
                Some(run::stress_physical(&surface, st).map_err(|e| prefix("outputs.stress.", e))?);
        }
        report.collect_warnings();
        Ok(report)
    }

    /// Whether an output reads the rough contact (spectrum and material).
    fn needs_surface(&self) -> bool {
        let o = &self.outputs;
        o.area.is_some()
            || o.magnification.is_some()
            || o.theories.is_some()
            || o.separation.is_some()
            || o.separation_density.is_some()
            || o.conductance.is_some()
            || o.leakage.is_some()
            || o.adhesion.is_some()
            || o.stress.as_ref().is_some_and(|st| !st.zeta.is_empty())
            || (o.kappa.is_some() && self.spectrum.is_some() && !self.nominal_pressure.is_empty())
    }

    /// Every section the scene gives is checked, even one no output reads
    /// (a scene is refused for what the command line refuses): the
    /// spectrum, material, rubber and pressures no output uses are built
    /// here (the ones an output uses are built by it); a scene that asks
    /// for nothing is refused.
    fn check_unused(&self) -> Result<()> {
        let o = &self.outputs;
        let asked =
            serde_json::to_value(o).map_or(true, |v| v.as_object().is_none_or(|m| !m.is_empty()));
        if !asked {
            return Err(Error::Inconsistent {
                name: "outputs".into(),
                requirement:
                    "at least one output (area, spectrum, bem, …): the scene asks for nothing"
                        .into(),
            });
        }
        let surface = self.needs_surface();
        let spectrum = surface
            || o.spectrum.is_some()
            || o.bem.is_some()
            || o.friction.is_some()
            || o.bem_adhesion.is_some();
        if !spectrum && self.spectrum.is_some() {
            self.spectrum()?;
        }
        let material = surface || o.bem.is_some() || o.bem_adhesion.is_some();
        if !material && self.material.is_some() {
            self.material()?;
        }
        if o.friction.is_none() {
            if let Some(r) = &self.rubber {
                r.build(false).map_err(|e| prefix("rubber.", e))?;
            }
        }
        let pressures = surface || o.bem.is_some() || o.friction.is_some();
        if !pressures {
            for &p in &self.nominal_pressure {
                persson::error::check::positive("nominal_pressure", p)?;
            }
        }
        Ok(())
    }

    /// The BEM outputs (feature `bem`); without the feature, a scene naming
    /// one is an error.
    #[cfg(not(feature = "bem"))]
    fn run_bem(&self, _report: &mut SceneReport) -> Result<()> {
        let o = &self.outputs;
        for (name, asked) in [
            ("outputs.bem", o.bem.is_some()),
            ("outputs.bem_hertz", o.bem_hertz.is_some()),
            ("outputs.bem_adhesion", o.bem_adhesion.is_some()),
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
            report.bem_hertz = Some(bem::bem_hertz(h)?);
        }
        if let Some(b) = &self.outputs.bem {
            let (rough, details) = bem::bem_rough(self, b)?;
            report.bem = Some(rough);
            report.bem_patches = details.patches;
            report.bem_subsurface = details.subsurface;
            report.bem_stress_maps = details.maps;
        }
        if let Some(a) = &self.outputs.bem_adhesion {
            report.bem_adhesion = Some(bem::bem_adhesion(self, a)?);
        }
        Ok(())
    }

    /// Every file the scene asks to write, relative to `dir`: its field,
    /// its path and the extensions that pick its format (empty: any).
    pub fn output_files(
        &self,
        dir: &Path,
    ) -> Vec<(&'static str, PathBuf, &'static [&'static str])> {
        const PLOT: &[&str] = &["svg", "png"];
        let o = &self.outputs;
        let bem = o.bem.as_ref();
        let subsurface = bem.and_then(|b| b.subsurface.as_ref());
        [
            (
                "outputs.spectrum.plot",
                o.spectrum.as_ref().and_then(|s| s.plot.clone()),
                PLOT,
            ),
            (
                "outputs.area.plot",
                o.area.as_ref().and_then(|a| a.plot.clone()),
                PLOT,
            ),
            (
                "outputs.magnification.plot",
                o.magnification.as_ref().and_then(|m| m.plot.clone()),
                PLOT,
            ),
            (
                "outputs.magnification.plot_g",
                o.magnification.as_ref().and_then(|m| m.plot_g.clone()),
                PLOT,
            ),
            (
                "outputs.theories.plot",
                o.theories.as_ref().and_then(|t| t.plot.clone()),
                PLOT,
            ),
            (
                "outputs.stress.plot",
                o.stress.as_ref().and_then(|s| s.plot.clone()),
                PLOT,
            ),
            ("outputs.bem.plot", bem.and_then(|b| b.plot.clone()), PLOT),
            (
                "outputs.bem.patches.plot",
                bem.and_then(|b| b.patches.as_ref())
                    .and_then(|p| p.plot.clone()),
                PLOT,
            ),
            (
                "outputs.bem.subsurface.plot",
                subsurface.and_then(|s| s.plot.clone()),
                PLOT,
            ),
            (
                "outputs.conductance.plot",
                o.conductance.as_ref().and_then(|c| c.plot.clone()),
                PLOT,
            ),
            (
                "outputs.leakage.plot",
                o.leakage.as_ref().and_then(|l| l.plot.clone()),
                PLOT,
            ),
            (
                "outputs.friction.plot",
                o.friction.as_ref().and_then(|f| f.plot.clone()),
                PLOT,
            ),
            (
                "outputs.bem.histogram",
                bem.and_then(|b| b.histogram.clone()),
                &[],
            ),
            (
                "outputs.bem.subsurface.stress_field",
                subsurface.and_then(|s| s.stress_field.clone()),
                &[],
            ),
        ]
        .into_iter()
        .filter_map(|(field, p, formats)| p.map(|p| (field, dir.join(p), formats)))
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
                    name: field.into(),
                    requirement: "plots need persson built with the feature `plot`".into(),
                });
            }
            out.reserve(field, &p, formats)?;
        }
        Ok(())
    }
}

/// Stage every file the scene asks for into `out` (plots first, then the
/// data files), as reserved by [`Scene::plan`]; the caller commits them
/// once the whole run has succeeded.
///
/// # Errors
/// A plot that cannot be drawn; a staged file that cannot be written.
pub fn write_outputs(
    scene: &Scene,
    report: &SceneReport,
    dir: &Path,
    out: &mut Files,
) -> Result<()> {
    #[cfg(feature = "plot")]
    write_plots(scene, report, dir, out)?;
    #[cfg(feature = "bem")]
    if let (Some(o), Some(r)) = (&scene.outputs.bem, &report.bem) {
        use crate::table::Tabulate;
        if let Some(file) = &o.histogram {
            if let Some(t) = r.tables().into_iter().find(|t| t.name == "bem_histogram") {
                out.write(&dir.join(file), t.to_csv().as_bytes())?;
            }
        }
        let field = o.subsurface.as_ref().and_then(|s| s.stress_field.as_ref());
        if let Some(file) = field {
            for m in &report.bem_stress_maps {
                let p = crate::bem_detail::indexed(&dir.join(file), m.index, m.depth_index);
                out.write(
                    &p,
                    &persson::io::npy::encode(r.grid, r.grid, &m.von_mises_stress)?,
                )?;
            }
        }
    }
    #[cfg(not(any(feature = "plot", feature = "bem")))]
    let _ = (scene, report, dir, out);
    Ok(())
}

/// Stage every plot the scene names (feature `plot`).
#[cfg(feature = "plot")]
fn write_plots(scene: &Scene, report: &SceneReport, dir: &Path, out: &mut Files) -> Result<()> {
    use crate::plot::{Encode, Figure};
    let o = &scene.outputs;
    let draw =
        |out: &mut Files, path: &Option<PathBuf>, fig: &dyn Fn() -> Result<Figure>| -> Result<()> {
            if let Some(p) = path {
                let p = dir.join(p);
                out.write(&p, &fig()?.encode(&p)?)?;
            }
            Ok(())
        };
    if let (Some(s), Some(r)) = (&o.spectrum, &report.spectrum) {
        draw(out, &s.plot, &|| plot::spectrum(r))?;
    }
    if let (Some(a), Some(r)) = (&o.area, &report.area) {
        draw(out, &a.plot, &|| plot::area(r))?;
    }
    if let (Some(m), Some(r)) = (&o.magnification, &report.magnification) {
        draw(out, &m.plot, &|| plot::magnification_area(r))?;
        draw(out, &m.plot_g, &|| plot::magnification_g(r))?;
    }
    if let (Some(t), Some(r)) = (&o.theories, &report.theories) {
        draw(out, &t.plot, &|| plot::theories(r))?;
    }
    if let (Some(s), Some(r)) = (&o.stress, &report.stress) {
        draw(out, &s.plot, &|| plot::stress(r))?;
    }
    #[cfg(feature = "bem")]
    let mut planes = Vec::new();
    #[cfg(feature = "bem")]
    if let (Some(b), Some(r)) = (&o.bem, &report.bem) {
        draw(out, &b.plot, &|| plot::bem(r))?;
        if let (Some(p), Some(r)) = (&b.patches, &report.bem_patches) {
            draw(out, &p.plot, &|| plot::patch_areas(r))?;
        }
        if let (Some(s), Some(r)) = (&b.subsurface, &report.bem_subsurface) {
            draw(out, &s.plot, &|| plot::subsurface_profiles(r))?;
        }
        if let Some(s) = &b.subsurface {
            if let Some(p) = &s.plot {
                // Each plane's von Mises map beside the depth plot: `_k_j` added.
                planes = crate::plot::stress_map::planes(
                    &report.bem_stress_maps,
                    (r.grid, r.size),
                    &s.depth,
                    &scene.nominal_pressure,
                    if r.contact_modulus == 1.0 { "E*" } else { "Pa" },
                    &dir.join(p),
                );
            }
        }
    }
    if let (Some(c), Some(r)) = (&o.conductance, &report.conductance) {
        draw(out, &c.plot, &|| plot::conductance(r))?;
    }
    if let (Some(l), Some(r)) = (&o.leakage, &report.leakage) {
        draw(out, &l.plot, &|| plot::leakage(r))?;
    }
    #[cfg(feature = "bem")]
    for (p, fig) in planes {
        out.write(&p, &fig.encode(&p)?)?;
    }
    if let (Some(Some(path)), Some(r)) = (o.friction.as_ref().map(|f| &f.plot), &report.friction) {
        let p = dir.join(path);
        out.write(&p, &plot::friction(r)?.encode(&p)?)?;
    }
    Ok(())
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

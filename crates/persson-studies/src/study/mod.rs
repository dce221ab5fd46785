//! One declaration per study.
//!
//! A study is one thing a user computes (`area`, `leakage`, `bem`, …). It is
//! declared once, by an implementation of [`Study`] in its own module: its
//! key (the scene's JSON key, the subcommand and the Python name), its spec
//! (the scene's output section: serde, so also the scene schema), its run,
//! its report (serde for `--json`, [`Tabulate`] for the tables), its warnings
//! and the files it writes. The list of studies, one line per study in
//! `scene/list.rs`, generates with the crate's macro `studies!` everything
//! that enumerates them: the scene's `outputs` ([`crate::scene::Outputs`]), its report
//! ([`crate::scene::SceneReport`]), the dispatcher, the warnings, the tables
//! and the files a scene reserves and writes.
//!
//! Why a trait with associated types and a declarative macro: the spec and
//! the report are different types per study, known at compile time, so the
//! dispatcher is monomorphic (no `dyn`, no `Any`), and the macro is the one
//! place that turns the list into the structs serde and schemars read
//! (a struct with one `Option` per study keeps the scene's JSON and its
//! schema exactly what they were).
//!
//! Adding a study: a folder `src/<key>/` whose `mod.rs` implements [`Study`]
//! for a unit type, and one line in the list (`docs/contributing.md`).

use std::path::{Path, PathBuf};

use schemars::JsonSchema;
use serde::de::DeserializeOwned;
use serde::Serialize;

use persson::error::{Error, Result};

use crate::contact::RoughContact;
use crate::input::{MaterialSpec, RubberSpec, SpectrumSpec};
use crate::naming::required;
use crate::output::Files;
use crate::table::Tabulate;
use crate::warning::Warning;

mod registry;

pub(crate) use registry::studies;

/// A file a study writes: the scene field that names it (`outputs.area.plot`),
/// its path, and the extensions that pick its format (empty: any).
pub type OutFile = (String, PathBuf, &'static [&'static str]);

/// The extensions of a plot.
pub const PLOT: &[&str] = &["svg", "png"];

/// One thing a user computes; see the [module](self).
pub trait Study {
    /// The scene's JSON key, the subcommand and the Python name.
    const KEY: &'static str;
    /// What the scene says of it (its `outputs.<KEY>` section).
    type Spec: Serialize + DeserializeOwned + JsonSchema + Clone + std::fmt::Debug;
    /// What it computed.
    type Report: Serialize + Tabulate + Clone + std::fmt::Debug + PartialEq;

    /// Which of the scene's inputs it reads; the others are validated (a
    /// scene is refused for what the command line refuses) but not used.
    fn reads(spec: &Self::Spec, scene: &Inputs<'_>) -> Reads;

    /// Compute it.
    ///
    /// # Errors
    /// An invalid field (named without its section: the dispatcher prefixes
    /// `outputs.<KEY>.`) or a failed computation.
    fn run(ctx: &Context<'_>, spec: &Self::Spec) -> Result<Self::Report>;

    /// Its remarks on the input (never a change of a number).
    fn warnings(_report: &Self::Report) -> Vec<Warning> {
        Vec::new()
    }

    /// The report's entries in the scene report's JSON: one, under its key,
    /// unless a study reports under several keys.
    ///
    /// # Errors
    /// As the serializer's.
    fn entries<M: serde::ser::SerializeMap>(
        report: &Self::Report,
        map: &mut M,
    ) -> Result<(), M::Error> {
        map.serialize_entry(Self::KEY, report)
    }

    /// The files the spec asks to write, relative to the scene's folder.
    fn files(_spec: &Self::Spec) -> Vec<OutFile> {
        Vec::new()
    }

    /// Stage the files of [`Study::files`] into `out` (in `dir`).
    ///
    /// # Errors
    /// A figure that cannot be drawn; a file that cannot be staged.
    fn write(
        _spec: &Self::Spec,
        _report: &Self::Report,
        _ctx: &Context<'_>,
        _dir: &Path,
        _out: &mut Files,
    ) -> Result<()> {
        Ok(())
    }
}

/// The scene's inputs, as given (before anything is built from them).
#[derive(Debug, Clone, Copy)]
pub struct Inputs<'a> {
    /// The roughness spectrum (or a height map).
    pub spectrum: Option<&'a SpectrumSpec>,
    /// The material.
    pub material: Option<&'a MaterialSpec>,
    /// The rubber.
    pub rubber: Option<&'a RubberSpec>,
    /// The nominal pressures.
    pub nominal_pressure: &'a [f64],
}

/// Which of the scene's inputs a study reads.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Reads {
    /// The spectrum (built by the study itself).
    pub spectrum: bool,
    /// The material (built by the study itself).
    pub material: bool,
    /// The rough contact (spectrum and material, built once for every study).
    pub contact: bool,
    /// The rubber.
    pub rubber: bool,
    /// The nominal pressures.
    pub nominal_pressure: bool,
}

impl Reads {
    /// Nothing of the scene (a study on its spec alone).
    pub const NOTHING: Reads = Reads {
        spectrum: false,
        material: false,
        contact: false,
        rubber: false,
        nominal_pressure: false,
    };

    /// The rough contact and the nominal pressures (the theories' studies).
    pub const CONTACT: Reads = Reads {
        spectrum: true,
        material: true,
        contact: true,
        rubber: false,
        nominal_pressure: true,
    };

    /// Either's.
    pub fn or(self, o: Reads) -> Reads {
        Reads {
            spectrum: self.spectrum || o.spectrum,
            material: self.material || o.material,
            contact: self.contact || o.contact,
            rubber: self.rubber || o.rubber,
            nominal_pressure: self.nominal_pressure || o.nominal_pressure,
        }
    }
}

/// What every study runs in: the scene's inputs and, when a study reads it,
/// the rough contact built once from them.
pub struct Context<'a> {
    /// The scene's inputs.
    pub inputs: Inputs<'a>,
    contact: Option<std::rc::Rc<RoughContact>>,
}

impl<'a> Context<'a> {
    /// The context of `inputs`, its rough contact built if `reads` says so.
    ///
    /// # Errors
    /// A missing or invalid spectrum or material (named under its section).
    pub fn new(inputs: Inputs<'a>, reads: Reads) -> Result<Self> {
        let contact = if reads.contact {
            let s = inputs.spectrum.ok_or_else(|| required("spectrum"))?;
            let m = inputs.material.ok_or_else(|| required("material"))?;
            Some(std::rc::Rc::new(RoughContact::named(
                s,
                m,
                "spectrum.",
                "material.",
            )?))
        } else {
            None
        };
        Ok(Context { inputs, contact })
    }

    /// The context of a study that reads none of the scene's inputs
    /// ([`Reads::NOTHING`]: `bem_hertz`, whose spec says everything).
    pub fn nothing() -> Context<'static> {
        Context {
            inputs: Inputs {
                spectrum: None,
                material: None,
                rubber: None,
                nominal_pressure: &[],
            },
            contact: None,
        }
    }

    /// The context of a rough contact built by the caller (the command
    /// line's, from its flags or a measured surface) and its pressures.
    pub fn with_contact(contact: RoughContact, nominal_pressure: &'a [f64]) -> Self {
        Context {
            inputs: Inputs {
                spectrum: None,
                material: None,
                rubber: None,
                nominal_pressure,
            },
            contact: Some(std::rc::Rc::new(contact)),
        }
    }

    /// The rough contact.
    ///
    /// # Errors
    /// A study that did not say it reads it (a programming error, named).
    pub fn contact(&self) -> Result<&RoughContact> {
        self.contact
            .as_deref()
            .ok_or_else(|| required("spectrum and material"))
    }

    /// The scene's spectrum.
    ///
    /// # Errors
    /// Absent.
    pub fn spectrum(&self) -> Result<&'a SpectrumSpec> {
        self.inputs.spectrum.ok_or_else(|| required("spectrum"))
    }

    /// The scene's material.
    ///
    /// # Errors
    /// Absent.
    pub fn material(&self) -> Result<&'a MaterialSpec> {
        self.inputs.material.ok_or_else(|| required("material"))
    }

    /// The nominal pressures.
    pub fn nominal_pressure(&self) -> &'a [f64] {
        self.inputs.nominal_pressure
    }

    /// The same context at other nominal pressures (a figure's smooth curve).
    pub fn with_pressures<'b>(&self, nominal_pressure: &'b [f64]) -> Context<'b>
    where
        'a: 'b,
    {
        Context {
            inputs: Inputs {
                nominal_pressure,
                ..self.inputs
            },
            contact: self.contact.clone(),
        }
    }

    /// The spectrum, built.
    ///
    /// # Errors
    /// Missing or invalid fields, named `spectrum.<field>`; file errors.
    pub fn build_spectrum(&self) -> Result<Box<dyn persson::spectrum::Spectrum>> {
        self.spectrum()?
            .build()
            .map_err(|e| crate::naming::prefix("spectrum.", e))
    }

    /// The material, built.
    ///
    /// # Errors
    /// Missing or invalid fields, named `material.<field>`.
    pub fn build_material(&self) -> Result<persson::material::Material> {
        self.material()?
            .build()
            .map_err(|e| crate::naming::prefix("material.", e))
    }
}

/// The plot `path` of the field `outputs.<key>.<field>`, if asked for.
pub fn plot_file(key: &str, field: &str, path: Option<&PathBuf>) -> Option<OutFile> {
    path.map(|p| (format!("outputs.{key}.{field}"), p.clone(), PLOT))
}

/// Stage the figure `fig()` at `dir/path`, if a path is given.
///
/// # Errors
/// A figure that cannot be drawn or encoded; a file that cannot be staged.
pub fn draw<F: crate::plot::Encode + ?Sized>(
    out: &mut Files,
    dir: &Path,
    path: Option<&PathBuf>,
    fig: impl FnOnce() -> Result<Box<F>>,
) -> Result<()> {
    if let Some(p) = path {
        let p = dir.join(p);
        out.write(&p, &fig()?.encode(&p)?)?;
    }
    Ok(())
}

/// Points of a figure's curve where a point costs microseconds to
/// milliseconds: enough for the curve to look smooth.
pub const PLOT_POINTS: usize = 60;

/// The nominal pressures of a figure's smooth curve through `given`: `n`
/// log-spaced from the least to the greatest positive one (σ0/100 to 100 σ0
/// for a single σ0); `given` itself if none is positive.
///
/// # Errors
/// `n` < 2 (named `plot_points`).
pub fn plot_pressures(given: &[f64], n: usize) -> Result<Vec<f64>> {
    if n < 2 {
        return Err(Error::invalid(
            "plot_points",
            n as f64,
            ">= 2 (the curve's two ends)",
        ));
    }
    let positive = given.iter().copied().filter(|p| *p > 0.0 && p.is_finite());
    let lo = positive.clone().fold(f64::INFINITY, f64::min);
    let hi = positive.fold(0.0, f64::max);
    if hi <= 0.0 {
        return Ok(given.to_vec());
    }
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        (lo / 100.0, hi * 100.0)
    };
    let (a, b) = (lo.ln(), hi.ln());
    let last = (n - 1) as f64;
    Ok((0..n)
        .map(|i| match i {
            0 => lo,
            i if i == n - 1 => hi,
            i => (a + (b - a) * i as f64 / last).exp(),
        })
        .collect())
}

/// Whether `a` and `b` are the same text (for the list's compile-time check
/// that each study's key is its line's).
pub const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// The report of a study this build cannot run (a feature left out): no
/// value, so never in a report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Unavailable {}

impl Tabulate for Unavailable {
    fn tables(&self) -> Vec<crate::table::Table> {
        match *self {}
    }
}

/// The error of a study whose feature this build leaves out.
pub fn unavailable(key: &str, feature: &str) -> Error {
    Error::Inconsistent {
        name: format!("outputs.{key}"),
        requirement: format!("needs a persson built with the `{feature}` feature"),
    }
}

/// A number of points of a curve or table: at least 2 (its two ends).
pub(crate) fn check_points(points: usize) -> Result<usize> {
    if points < 2 {
        return Err(Error::invalid(
            "points",
            points as f64,
            "an integer >= 2 (the curve's two ends)",
        ));
    }
    Ok(points)
}

//! The flags of `persson bem` (and the solver flags `persson compare` shares).

use persson::bem::{Boundary, Options};
use persson::spectrum::Spectrum;
use persson::Material;
use persson::error::check;

use super::args::{MaterialArgs, SpectrumArgs};
use super::files::{in_file, out_file, InFile, OutFile};
use super::measured_args::MapReadArgs;
use super::output::Format;
use persson_studies::scene::transport::{self, TransportRequest};
use persson_studies::scene::{
    BemAdhesionOutput, BemHertzOutput, BemOutput, ConductanceOutput, LeakageOutput, PatchesOutput,
    SubsurfaceOutput,
};

use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson bem`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub cmd: Cmd,
}

#[derive(clap::Subcommand, Debug)]
pub enum Cmd {
    /// The Hertz ball: the validation (η, fitted contact radius and peak pressure), η per
    /// grid, the plastic disc, the stress on the axis or the adhesive sphere.
    Hertz(HertzArgs),
    /// Rough contact: contact fraction and mean separation at each nominal pressure.
    Rough(Box<RoughArgs>),
}

/// Arguments of `persson bem hertz`: the study `bem_hertz`'s spec, from
/// which every flag is derived, and the output's.
#[derive(clap::Args, Debug)]
pub struct HertzArgs {
    /// The built-in example, which is this command's defaults: a ball of
    /// radius 1 on a free 256² grid of side 1, E* = 1, contact radius 0.1
    /// (every command takes --example).
    #[arg(long)]
    pub example: bool,
    #[command(flatten)]
    pub spec: SpecArgs<BemHertzOutput>,
    /// Text tables with every column (default: each fits 100 characters, the
    /// solver's columns of a wider table left out and named).
    #[arg(long)]
    pub wide: bool,
    #[command(flatten)]
    pub format: Format,
}

impl SpecFlags for BemHertzOutput {
    const RENAMED: &'static [(&'static str, &'static str)] = &[("grids", "grid")];
    const ALIASES: &'static [(&'static str, &'static str)] =
        &[("contact_modulus", "modulus"), ("grids", "grids")];
    const OUTPUTS: &'static [(&'static str, &'static str)] = &[("stress_plot", "FILE.svg|png")];
}

/// What `bem rough` reports besides the load curve: contact patches and the
/// stress below the surface, the flags of the scene's `outputs.bem.patches`
/// and `outputs.bem.subsurface` behind a switch each.
#[derive(clap::Args, Debug)]
pub struct DetailArgs {
    /// Report the connected contact patches of each solve (count, largest,
    /// perimeters, log-binned area distribution, pressure-tail fits).
    #[arg(long)]
    pub patches: bool,
    #[command(flatten)]
    pub patch: SpecArgs<Patches>,
    /// Report the stress below the surface on the planes of --depth.
    #[arg(long)]
    pub subsurface: bool,
    #[command(flatten)]
    pub stress: SpecArgs<Subsurface>,
}

/// [`PatchesOutput`] through its flags: its figure is `--patches-plot`.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(transparent)]
pub struct Patches(pub PatchesOutput);

/// [`SubsurfaceOutput`] through its flags: its figure is `--stress-plot`.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(transparent)]
pub struct Subsurface(pub SubsurfaceOutput);

/// `JsonSchema` of a transparent newtype: its spec's.
macro_rules! schema_of {
    ($newtype:ty, $spec:ty) => {
        impl schemars::JsonSchema for $newtype {
            fn schema_name() -> std::borrow::Cow<'static, str> {
                <$spec>::schema_name()
            }

            fn json_schema(generator: &mut schemars::SchemaGenerator) -> schemars::Schema {
                <$spec>::json_schema(generator)
            }
        }
    };
}

schema_of!(Patches, PatchesOutput);
schema_of!(Subsurface, SubsurfaceOutput);

impl SpecFlags for Patches {
    const RENAMED: &'static [(&'static str, &'static str)] = &[("plot", "patches-plot")];
    const IDS: &'static [(&'static str, &'static str)] = &[("plot", "patches_plot")];
}

impl SpecFlags for Subsurface {
    const RENAMED: &'static [(&'static str, &'static str)] = &[("plot", "stress-plot")];
    const IDS: &'static [(&'static str, &'static str)] = &[("plot", "stress_plot")];
    const OUTPUTS: &'static [(&'static str, &'static str)] = &[("stress_field", "FILE.npy")];
}

impl DetailArgs {
    /// The scene's `patches` and `subsurface` of these flags; a flag of
    /// either without its switch is refused.
    pub fn specs(&self) -> anyhow::Result<(Option<PatchesOutput>, Option<SubsurfaceOutput>)> {
        let stray = |on: bool, given: &[(&str, bool)], switch: &str| {
            let flags: Vec<&str> = given.iter().filter(|g| g.1).map(|g| g.0).collect();
            match (on, flags.is_empty()) {
                (false, false) => Err(anyhow::anyhow!("{}: add {switch}", flags.join(" / "))),
                _ => Ok(()),
            }
        };
        let p = |f: &str| self.patch.has(f);
        stray(
            self.patches,
            &[
                ("--connectivity", p("connectivity")),
                ("--bins-per-decade", p("bins_per_decade")),
                ("--patches-plot", p("plot")),
            ],
            "--patches",
        )?;
        let s = |f: &str| self.stress.has(f);
        stray(
            self.subsurface,
            &[
                ("--depth", s("depth")),
                ("--tensile-yield-stress", s("tensile_yield_stress")),
                ("--stress-field", s("stress_field")),
                ("--stress-plot", s("plot")),
            ],
            "--subsurface",
        )?;
        let patches = match self.patches {
            true => Some(self.patch.spec()?.0),
            false => None,
        };
        let subsurface = match self.subsurface {
            true => Some(self.stress.spec()?.0),
            false => None,
        };
        Ok((patches, subsurface))
    }
}

#[derive(clap::Args, Debug)]
pub struct RoughArgs {
    /// Height map of the rigid surface, square N × N: any format `spectrum
    /// --surface` reads (.npy, text matrix, instrument files), read the same
    /// way, with the file's own size and units.
    #[arg(long, value_parser = in_file)]
    pub surface: Option<InFile>,
    /// Physical side L of the surface (default with a spectrum: 2π/q_l; a
    /// --surface file that states its size needs none, a given one is
    /// checked against the file's).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    pub size: Option<f64>,
    #[command(flatten)]
    pub read: MapReadArgs,
    /// Least-squares trend removed from the --surface heights before the
    /// solve (default: none, the heights as read).
    #[arg(long, requires = "surface", value_parser = persson_studies::scene::by_name::<persson::names::Detrend>())]
    pub detrend: Option<persson::names::Detrend>,
    #[command(flatten)]
    pub spectrum: SpectrumArgs,
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Nominal (mean) pressure, same unit as the modulus; repeatable or comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        required_unless_present_any = ["example", "work_of_adhesion"], value_parser = super::number::number)]
    pub pressure: Vec<f64>,
    #[command(flatten)]
    pub spec: SpecArgs<BemOutput>,
    /// Write each pressure field as .npy (N×N float64); `_k` is added before
    /// the extension when several pressures are given.
    #[arg(long, value_parser = out_file)]
    pub pressure_field: Option<OutFile>,
    /// Write the (synthesised or read) surface heights as .npy.
    #[arg(long, value_parser = out_file)]
    pub surface_out: Option<OutFile>,
    /// Text tables with every column (default: each fits 100 characters, the
    /// solver's columns of a wider table left out and named).
    #[arg(long)]
    pub wide: bool,
    #[command(flatten)]
    pub transport: TransportArgs,
    #[command(flatten)]
    pub detail: DetailArgs,
    #[command(flatten)]
    pub adhesion: AdhesionBemArgs,
    #[command(flatten)]
    pub format: Format,
}

/// `bem rough`'s flags of the scene's `bem` spec: `--plot` is its
/// `pressure_plot` and `--area-plot` its `plot` (the command line's names
/// since 0.3); the patches and the subsurface are [`DetailArgs`].
impl SpecFlags for BemOutput {
    const OWN: &'static [&'static str] = &["patches", "subsurface"];
    const RENAMED: &'static [(&'static str, &'static str)] =
        &[("plot", "area-plot"), ("pressure_plot", "plot")];
    const OUTPUTS: &'static [(&'static str, &'static str)] = &[
        ("histogram", "FILE.csv"),
        ("pressure_plot", "FILE.svg|png"),
    ];
}

/// `bem rough`'s solve, from the scene's `bem` spec its flags give: the
/// spec's defaults resolved once.
pub struct RoughSettings {
    /// The spec as given, with its patches and subsurface.
    pub spec: BemOutput,
    /// The boundary (default periodic).
    pub boundary: Boundary,
    /// The seed of a synthesised surface (default 1).
    pub seed: u64,
    /// The solver's options (warm-started along the pressures), with the
    /// yield stress.
    pub options: Options,
    /// Histogram bins (default 50), checked.
    pub bins: usize,
}

impl RoughArgs {
    /// The settings of the solves, checked before any computation; a grid or
    /// seed beside `--surface` is refused (the file sets the grid).
    pub fn settings(&self) -> anyhow::Result<RoughSettings> {
        let mut spec = self.spec.spec()?;
        (spec.patches, spec.subsurface) = self.detail.specs()?;
        if self.surface.is_some() && (spec.grid.is_some() || spec.seed.is_some()) {
            anyhow::bail!("--grid / --seed: not with --surface (the file sets the grid)");
        }
        let tolerance = spec.tolerance.unwrap_or(1e-10);
        let options = Options {
            tolerance: check::tolerance("tolerance", tolerance)?,
            max_iterations: spec
                .max_iterations
                .unwrap_or(Options::default().max_iterations),
            warm_start: true,
            yield_stress: spec.yield_stress,
        };
        let bins = persson_studies::validation::check_bins(
            spec.bins.unwrap_or(persson_studies::validation::DEFAULT_BINS),
        )?;
        Ok(RoughSettings {
            boundary: spec.boundary.unwrap_or(Boundary::Periodic),
            seed: spec.seed.unwrap_or(1),
            options,
            bins,
            spec,
        })
    }
}

/// The BEM's conductance and leak rate per load (`bem rough`, feature `flow`).
#[derive(clap::Args, Debug, Clone)]
pub struct TransportArgs {
    #[command(flatten)]
    pub conductance: ConductanceArgs,
    /// Reynolds flow on each solve's gap along x and y, and the seal's leak
    /// rate (needs --viscosity and --pressure-drop, or a gas's pressures).
    #[arg(long)]
    pub leakage: bool,
    #[command(flatten)]
    pub seal: SealArgs,
    /// Write the gap field each leak rate was computed on as .npy (N×N
    /// float64, 0 in contact); `_k` is added before the extension when several
    /// pressures are given.
    #[arg(long, value_name = "FILE.npy", value_parser = out_file)]
    pub gap_field: Option<OutFile>,
}

/// The adhesive BEM along a path of mean gaps or approaches (`bem rough
/// --work-of-adhesion`): the flags of the scene's `bem_adhesion` spec, whose
/// surface and solver fields are `bem`'s ([`RoughSettings`]).
#[derive(clap::Args, Debug, Clone)]
pub struct AdhesionBemArgs {
    #[command(flatten)]
    pub spec: SpecArgs<AdhesivePath>,
}

/// [`BemAdhesionOutput`] through its path's flags alone.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(transparent)]
pub struct AdhesivePath(pub BemAdhesionOutput);

schema_of!(AdhesivePath, BemAdhesionOutput);

impl SpecFlags for AdhesivePath {
    const OWN: &'static [&'static str] = &["grid", "seed", "boundary", "tolerance", "max_iterations"];
}

impl AdhesionBemArgs {
    /// The adhesive path, if `--work-of-adhesion` asks for one; a flag of
    /// the path without it is refused.
    pub fn path(&self) -> anyhow::Result<Option<BemAdhesionOutput>> {
        if self.spec.has("work_of_adhesion") {
            return Ok(Some(self.spec.spec()?.0));
        }
        let stray: Vec<String> = [
            "adhesion_range",
            "adhesion",
            "mean_gap",
            "approach",
            "adhesive_iteration",
        ]
        .iter()
        .filter(|f| self.spec.has(f))
        .map(|f| format!("--{}", f.replace('_', "-")))
        .collect();
        match stray.is_empty() {
            true => Ok(None),
            false => anyhow::bail!("{}: add --work-of-adhesion", stray.join(" / ")),
        }
    }
}

// What only the BEM's commands ask of the common flags.

impl SpectrumArgs {
    /// Build the spectrum from the flags.
    pub fn build(&self) -> anyhow::Result<Box<dyn Spectrum>> {
        self.spec()?.build().map_err(|e| self.psd_hint(e))
    }

    /// The warning of a `--psd` file (the convention it was read in), for the
    /// commands that build the spectrum without a [`RoughContact`].
    pub fn file_warnings(&self) -> Vec<persson_studies::Warning> {
        self.psd
            .iter()
            .map(|file| persson_studies::Warning::PsdConvention {
                file: file.to_path_buf(),
                convention: self.psd_convention,
            })
            .collect()
    }
}

impl MaterialArgs {
    /// Build the material (`example` supplies E* when nothing is given).
    pub fn build(&self, example: bool) -> anyhow::Result<Material> {
        Ok(self.spec(example)?.build()?)
    }
}


/// The bodies and the gas of `bem rough`'s and `compare`'s conductance: the
/// flags of `persson conductance`'s spec [`ConductanceOutput`] (the
/// conductivities, the resistivities, the gas law), without the theory's own
/// knobs.
#[derive(clap::Args, Debug, Clone)]
pub struct ConductanceArgs {
    #[command(flatten)]
    pub spec: SpecArgs<Conductances>,
}

/// [`ConductanceOutput`] through the bodies' and the gas's flags alone.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(transparent)]
pub struct Conductances(pub ConductanceOutput);

schema_of!(Conductances, ConductanceOutput);

impl SpecFlags for Conductances {
    const OWN: &'static [&'static str] = &["gap_table", "tolerance", "bem", "plot"];
}

impl ConductanceArgs {
    /// Whether a conductivity, a resistivity or the gas law was given.
    pub fn given(&self) -> bool {
        ["conductivity", "resistivity", "gas_conductivity", "mean_free_path"]
            .iter()
            .any(|f| self.spec.has(f))
    }

    /// The transport request of these flags (κ, ρ, the gap law, each
    /// checked and named as the spec's field) with `seal`.
    pub fn request(
        &self,
        seal: Option<persson::leakage::Seal>,
    ) -> anyhow::Result<TransportRequest> {
        let Conductances(c) = self.spec.spec()?;
        Ok(TransportRequest::new(
            transport::conductivity(&c.conductivity)?,
            transport::resistivity(&c.resistivity)?,
            transport::gap_law(c.gas_conductivity, c.mean_free_path, None)?,
            seal,
        ))
    }
}

/// The seal and its fluid of `bem rough --leakage` and `compare --leakage`:
/// the flags of `persson leakage`'s spec [`LeakageOutput`] (the fluid, its
/// drive and the seal's sides), without the theory's own knobs.
#[derive(clap::Args, Debug, Clone)]
pub struct SealArgs {
    #[command(flatten)]
    pub spec: SpecArgs<Seal>,
}

/// [`LeakageOutput`] through the seal's flags alone: the percolation
/// threshold, the tolerance, the BEM and the figure are the command's.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(transparent)]
pub struct Seal(pub LeakageOutput);

schema_of!(Seal, LeakageOutput);

impl SpecFlags for Seal {
    const OWN: &'static [&'static str] = &["percolation_threshold", "tolerance", "bem", "plot"];
}

impl SealArgs {
    /// Whether the fluid or its drive was given.
    pub fn given(&self) -> bool {
        ["viscosity", "pressure_drop", "inlet_pressure", "outlet_pressure"]
            .iter()
            .any(|f| self.spec.has(f))
    }

    /// The scene's `leakage` output for these flags; with `example`, the example's water seal
    /// ([`LeakageOutput::example`]) where the fluid or its drive is not given.
    pub fn output(
        &self,
        percolation_threshold: f64,
        tolerance: f64,
        example: bool,
    ) -> anyhow::Result<LeakageOutput> {
        let mut spec = self.spec.clone();
        if example {
            let water = LeakageOutput::example();
            spec.or("viscosity", water.viscosity);
            if !spec.has("inlet_pressure") {
                spec.or("pressure_drop", water.pressure_drop.unwrap_or_default());
            }
        }
        let Seal(out) = spec.spec()?;
        Ok(LeakageOutput {
            percolation_threshold: Some(percolation_threshold),
            tolerance: Some(tolerance),
            ..out
        })
    }
}

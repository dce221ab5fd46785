//! The flags of `persson compare` and `persson compare kappa`.

use persson_studies::validation::{CompareSpec, EnsembleSpec, SweepSettings, SweepSpec};

use super::args::{MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::files::{in_file, out_file, InFile, OutFile};
use super::output::Format;
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson compare`.
#[derive(clap::Args, Debug)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct Args {
    #[command(subcommand)]
    pub study: Option<Study>,
    #[command(flatten)]
    pub main: Box<MainArgs>,
}

#[derive(clap::Subcommand, Debug)]
pub enum Study {
    /// κ(H) from the low-load BEM regime, averaged over seeds, next to √(8/π) and √(2π).
    Kappa(Box<KappaArgs>),
    /// The BEM on seeds × grids of independent surfaces, on local cores: A/A0 and ū,
    /// mean and standard error over seeds per grid and pressure.
    Ensemble(Box<EnsembleArgs>),
}

/// The BEM side of `compare` and `compare kappa`: the flags of the spec
/// [`SweepSpec`], every one derived from it.
#[derive(clap::Args, Debug, Clone)]
pub struct BemArgs {
    #[command(flatten)]
    pub spec: SpecArgs<SweepSpec>,
}

impl SpecFlags for SweepSpec {}

/// The Hurst exponents of `compare kappa --example`.
pub const EXAMPLE_HURST: [f64; 3] = [0.2, 0.5, 0.8];

impl SpecFlags for CompareSpec {}

impl SpecFlags for EnsembleSpec {}

impl BemArgs {
    /// The flag a measured map makes meaningless, if given.
    pub fn unused_with_surface(&self) -> anyhow::Result<Option<String>> {
        Ok(self
            .spec
            .spec()?
            .unused_with_surface()
            .map(|field| format!("--{field}")))
    }

    /// The sweep's settings, with the solver's yield stress.
    pub fn settings(&self, yield_stress: Option<f64>) -> anyhow::Result<SweepSettings> {
        Ok(self.spec.spec()?.settings(yield_stress)?)
    }
}

#[derive(clap::Args, Debug)]
pub struct MainArgs {
    #[command(flatten)]
    pub spectrum: SpectrumArgs,
    /// With --surface the BEM solves on the map (square N × N) and coarser copies
    /// (--levels grids): a --periodic map low-passed at the q_s its coarsest copy
    /// resolves (--pixels-per-wavelength) and resampled, plus the map as measured;
    /// a non-periodic one (free boundary) as measured and block-averaged. The map
    /// sets the grid: --grid, --seed and --seeds are errors.
    #[command(flatten)]
    pub measured: MeasuredArgs,
    #[command(flatten)]
    pub material: MaterialArgs,
    #[command(flatten)]
    pub bem: BemArgs,
    /// The pressures, the yield stress, the shown distribution and the
    /// adhesive comparison: the spec [`CompareSpec`].
    #[command(flatten)]
    pub compare: SpecArgs<CompareSpec>,
    /// Your own results: CSV with columns nominal_pressure, contact_fraction (header and # comments allowed).
    #[arg(long, value_name = "FILE.csv", value_parser = in_file)]
    pub data: Option<InFile>,
    /// Your own pressure histogram at --histogram-pressure: CSV with columns sigma, density
    /// (normalised so that ∫ density dσ = A/A0).
    #[arg(long, value_name = "FILE.csv", value_parser = in_file)]
    pub data_histogram: Option<InFile>,
    #[command(flatten)]
    pub transport: super::compare_transport::TransportArgs,
    /// Text tables with every column (default: each fits 100 characters, the coarser
    /// grids' columns of a wider table left out and named).
    #[arg(long)]
    pub wide: bool,
    #[command(flatten)]
    pub format: Format,
    #[command(flatten)]
    pub plot: super::plot::PlotArg,
    /// Draw the pressure distribution (BEM histogram, Persson's P(σ), your histogram) on linear axes.
    #[arg(long, value_name = "FILE.svg|png", value_parser = out_file)]
    pub plot_histogram: Option<OutFile>,
    /// The same with a logarithmic P(σ) axis, to compare the tails.
    #[arg(long, value_name = "FILE.svg|png", value_parser = out_file)]
    pub plot_histogram_log: Option<OutFile>,
}

#[derive(clap::Args, Debug)]
pub struct KappaArgs {
    /// The built-in example: H = 0.2, 0.5 and 0.8 (the guide's) with the defaults
    /// below (every command takes --example).
    #[arg(long)]
    pub example: bool,
    /// Hurst exponents, comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        required_unless_present = "example",
        allow_hyphen_values = true, value_parser = super::number::number)]
    pub hurst: Vec<f64>,
    /// Lower cut-off q_l (sets L = 2π/q_l).
    #[arg(long = "q-l", default_value = "1", allow_hyphen_values = true, value_parser = super::number::number)]
    pub q_l: f64,
    /// Roll-off q_r (default q_l).
    #[arg(long = "q-r", allow_hyphen_values = true, value_parser = super::number::number)]
    pub q_r: Option<f64>,
    /// Upper cut-off q_s (default and maximum: what the coarsest grid resolves).
    #[arg(long = "q-s", allow_hyphen_values = true, value_parser = super::number::number)]
    pub q_s: Option<f64>,
    /// rms slope over [q_l, q_s] of every surface.
    #[arg(long, default_value = "0.1", allow_hyphen_values = true, value_parser = super::number::number)]
    pub rms_slope: f64,
    /// Contact modulus E*.
    #[arg(
        long,
        alias = "modulus",
        default_value = "1",
        allow_hyphen_values = true, value_parser = super::number::number)]
    pub contact_modulus: f64,
    /// Nominal pressures (default: 8 with linear-law A/A0 ≈ 0.005 … 0.09).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pub pressure: Vec<f64>,
    #[command(flatten)]
    pub bem: BemArgs,
    #[command(flatten)]
    pub format: Format,
    #[command(flatten)]
    pub plot: super::plot::PlotArg,
}

#[derive(clap::Args, Debug)]
pub struct EnsembleArgs {
    #[command(flatten)]
    pub spectrum: SpectrumArgs,
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Nominal (mean) pressure, same unit as the modulus; repeatable or comma-separated
    /// (required but with --example, which takes the example's).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pub pressure: Vec<f64>,
    /// The grids, surfaces, band and solver: the spec [`EnsembleSpec`].
    #[command(flatten)]
    pub spec: SpecArgs<EnsembleSpec>,
    /// Worker threads, one job (seed, grid) at a time each (0: one per core).
    #[arg(long, default_value_t = 0, allow_hyphen_values = true, value_parser = super::number::count)]
    pub threads: usize,
    #[command(flatten)]
    pub format: Format,
}

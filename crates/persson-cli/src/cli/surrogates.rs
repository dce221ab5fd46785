//! `persson surrogates`: does the measured map make contact like random
//! surfaces of its spectrum? The FFT-BEM on the map and on K surrogates;
//! the scene output `surrogates`.

use persson::bem::Boundary;
use persson_studies::input::{by_name, SurrogateKindName};
use persson_studies::study::{Context, Inputs, Reads};
use persson_studies::surrogates::{Surrogates, SurrogatesOutput};

use super::args::{pressures, spectrum_spec, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::files::{out_file, OutFile};
use super::number::{count, number};
use super::output::Format;

/// The grid of the example's synthesised map.
const EXAMPLE_GRID: usize = 64;

/// The example's least load, Pa.
const EXAMPLE_LEAST_PRESSURE: f64 = 1e6;

/// Arguments of `persson surrogates`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, Pa; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = number)]
    pressure: Vec<f64>,
    /// Number K of surrogates (at least 2).
    #[arg(long, default_value = "8", allow_hyphen_values = true, value_parser = count)]
    count: usize,
    /// Kind of surrogate: `phase` (random phases, Gaussian heights) or
    /// `amplitude-adjusted` (the map's own heights, IAAFT).
    #[arg(long, default_value = "phase")]
    kind: SurrogateKindName,
    /// Most IAAFT iterations of an amplitude-adjusted surrogate.
    #[arg(long, default_value = "200", allow_hyphen_values = true, value_parser = count)]
    iterations: usize,
    /// Seed of the first surrogate (surrogate k uses seed + k − 1).
    #[arg(long, default_value = "1", allow_hyphen_values = true, value_parser = super::bem_args::seed)]
    seed: u64,
    /// Without --surface: the grid N of a map synthesised from the spectrum flags.
    #[arg(long, conflicts_with = "surface", allow_hyphen_values = true, value_parser = count)]
    grid: Option<usize>,
    /// Without --surface: the seed of that map.
    #[arg(long, conflicts_with = "surface", allow_hyphen_values = true, value_parser = super::bem_args::seed)]
    map_seed: Option<u64>,
    /// Boundary condition of every solve.
    #[arg(long, default_value = "periodic", value_parser = by_name::<Boundary>())]
    boundary: Boundary,
    /// Relative tolerance ε of every solve.
    #[arg(long, default_value = "1e-8", allow_hyphen_values = true, value_parser = number)]
    tolerance: f64,
    /// Write each surrogate as .npy; `_k` (k = 1 … K) is added before the extension.
    #[arg(long, value_name = "FILE.npy", value_parser = out_file)]
    surfaces: Option<OutFile>,
    /// Draw the pressure distributions of the map and the surrogates at the
    /// largest pressure (.svg or .png).
    #[arg(long, value_name = "FILE.svg|png", value_parser = out_file)]
    plot_distribution: Option<OutFile>,
    #[command(flatten)]
    format: Format,
    /// Also draw A/A0 against σ0, the map beside the surrogates' band (.svg or .png).
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson surrogates`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let spectrum = spectrum_spec(&a.spectrum, &a.measured)?;
    let material = a.material.spec(a.spectrum.example)?;
    let mut pressures = pressures(&a.pressure, a.spectrum.example)?;
    // The example: a 64² map synthesised from the example's spectrum, at
    // the example's loads from 1 MPa (below, it touches on a few nodes).
    let example = a.spectrum.example && a.measured.spec(None)?.is_none();
    let grid = a.grid.or(example.then_some(EXAMPLE_GRID));
    if example && a.pressure.is_empty() {
        pressures.retain(|&p| p >= EXAMPLE_LEAST_PRESSURE);
    }
    let spec = SurrogatesOutput {
        count: Some(a.count),
        kind: Some(a.kind),
        iterations: Some(a.iterations),
        seed: Some(a.seed),
        grid,
        map_seed: a.map_seed,
        boundary: Some(a.boundary),
        tolerance: Some(a.tolerance),
        surfaces: a.surfaces.as_deref().map(std::path::Path::to_path_buf),
        plot: a.plot.path(),
        plot_distribution: a.plot_distribution.as_deref().map(std::path::Path::to_path_buf),
    };
    let inputs = Inputs {
        spectrum: Some(&spectrum),
        material: Some(&material),
        rubber: None,
        nominal_pressure: &pressures,
    };
    let ctx = Context::new(inputs, Reads::CONTACT)?;
    super::study::run::<Surrogates>(&ctx, &spec, files, &a.format)
}

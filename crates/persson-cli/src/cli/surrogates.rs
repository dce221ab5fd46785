//! `persson surrogates`: does the measured map make contact like random
//! surfaces of its spectrum? The FFT-BEM on the map and on K surrogates;
//! the scene output `surrogates`.

use persson_studies::study::{Context, Inputs, Reads};
use persson_studies::surrogates::{Surrogates, SurrogatesOutput};

use super::args::{pressures, spectrum_spec, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::number::number;
use super::spec_args::{SpecArgs, SpecFlags};
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
    #[command(flatten)]
    spec: SpecArgs<SurrogatesOutput>,
    #[command(flatten)]
    format: Format,
}

/// The surrogates are written as `.npy`.
impl SpecFlags for SurrogatesOutput {
    const OUTPUTS: &'static [(&'static str, &'static str)] = &[("surfaces", "FILE.npy")];
}

/// Run `persson surrogates`.
pub fn run(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let spectrum = spectrum_spec(&a.spectrum, &a.measured)?;
    let material = a.material.spec(a.spectrum.example)?;
    let mut pressures = pressures(&a.pressure, a.spectrum.example)?;
    // The example: a 64² map synthesised from the example's spectrum, at
    // the example's loads from 1 MPa (below, it touches on a few nodes).
    let example = a.spectrum.example && a.measured.spec(None)?.is_none();
    if example {
        a.spec.or("grid", EXAMPLE_GRID);
        if a.pressure.is_empty() {
            pressures.retain(|&p| p >= EXAMPLE_LEAST_PRESSURE);
        }
    }
    let spec = a.spec.spec()?;
    let inputs = Inputs {
        spectrum: Some(&spectrum),
        material: Some(&material),
        rubber: None,
        nominal_pressure: &pressures,
    };
    let ctx = Context::new(inputs, Reads::CONTACT)?;
    super::study::run::<Surrogates>(&ctx, &spec, files, &a.format)
}

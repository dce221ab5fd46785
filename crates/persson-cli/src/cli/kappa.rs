//! `persson kappa`: κ of the linear low-load law (the scene output `kappa`).

use persson_studies::scene::run;

use super::args::{contact, pressures, MaterialArgs, SpectrumArgs};
use super::output::{print_warned, Format};

/// Arguments of `persson kappa`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal pressures: with a spectrum and material, print the linear contact fractions.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Vec<f64>,
    #[command(flatten)]
    format: Format,
}

/// Run `persson kappa`.
pub fn run(a: Args) -> anyhow::Result<()> {
    let report = if a.spectrum.is_given() {
        let surface = contact(&a.spectrum, &a.material)?;
        let pressures = pressures(&a.pressure, a.spectrum.example)?;
        run::kappa(Some((&surface, &pressures)))?
    } else {
        run::kappa(None)?
    };
    print_warned(&report, &report.warnings, &a.format)
}

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

/// Run `persson kappa`: κ alone, or (as a scene's `kappa` output) with the
/// linear contact fractions when a spectrum, a material and pressures are
/// given (or the example).
pub fn run(a: Args) -> anyhow::Result<()> {
    let material = a.material.spec(false).is_ok();
    let with_surface =
        a.spectrum.example || (a.spectrum.is_given() && (material || !a.pressure.is_empty()));
    let report = if with_surface {
        let surface = contact(&a.spectrum, &a.material)?;
        let pressures = pressures(&a.pressure, a.spectrum.example)?;
        run::kappa(Some((&surface, &pressures)))?
    } else {
        run::kappa(None)?
    };
    print_warned(&report, &report.warnings, &a.format)
}

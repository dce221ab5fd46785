//! `persson area`: A/A0 against nominal pressure (the scene output `area`).

use persson_studies::area::Area;
use persson_studies::scene::AreaOutput;
use persson_studies::study::Context;

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::Format;
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson area`: the shared ones, and the spec's
/// ([`AreaOutput`]) derived from it.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, same unit as E*; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Vec<f64>,
    #[command(flatten)]
    spec: SpecArgs<AreaOutput>,
    #[command(flatten)]
    format: Format,
}

impl SpecFlags for AreaOutput {
    const ALIASES: &'static [(&'static str, &'static str)] = &[("tolerance", "theory-tolerance")];
}

/// Run `persson area`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let ctx = Context::with_contact(surface, &pressures);
    super::study::run::<Area>(&ctx, &a.spec.spec()?, files, &a.format)
}

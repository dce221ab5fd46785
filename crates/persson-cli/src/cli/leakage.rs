//! `persson leakage`: the leak rate of a static seal against load, from the
//! critical-junction and the effective-medium theories; the scene output
//! `leakage`.

use persson_studies::scene::LeakageOutput;

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::number::number;
use super::output::Format;
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson leakage`: the shared ones, and the spec's
/// ([`LeakageOutput`]) derived from it.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0 on the seal, Pa; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = number)]
    pressure: Vec<f64>,
    #[command(flatten)]
    spec: SpecArgs<LeakageOutput>,
    #[command(flatten)]
    format: Format,
}

/// The BEM beside the theories is `persson bem rough --leakage`.
impl SpecFlags for LeakageOutput {
    const OWN: &'static [&'static str] = &["bem"];
}

/// Run `persson leakage`.
pub fn run(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    if a.spectrum.example {
        // The example's water seal where the fluid or its drive is not given.
        let water = LeakageOutput::example();
        a.spec.or("viscosity", water.viscosity);
        if !a.spec.has("inlet_pressure") {
            a.spec
                .or("pressure_drop", water.pressure_drop.unwrap_or_default());
        }
    }
    let out = a.spec.spec()?;
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let ctx = persson_studies::study::Context::with_contact(surface, &pressures);
    super::study::run::<persson_studies::transport::Leakage>(&ctx, &out, files, &a.format)
}

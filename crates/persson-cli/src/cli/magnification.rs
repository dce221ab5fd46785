//! `persson magnification` (alias `g`): G(ζ) and A/A0 against magnification
//! (the scene output `magnification`).

use persson_studies::scene::MagnificationOutput;

use super::args::{measured_contact, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::Format;
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson magnification`: the shared ones, and the spec's
/// ([`MagnificationOutput`]) derived from it.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    #[command(flatten)]
    spec: SpecArgs<MagnificationOutput>,
    #[command(flatten)]
    format: Format,
}

impl SpecFlags for MagnificationOutput {
    const RENAMED: &'static [(&'static str, &'static str)] = &[("nominal_pressure", "pressure")];
}

/// Run `persson magnification`.
pub fn run(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    if a.spectrum.example {
        a.spec
            .or("nominal_pressure", super::args::example::PRESSURES[3]);
    }
    let ctx = persson_studies::study::Context::with_contact(surface, &[]);
    super::study::run::<persson_studies::magnification::Magnification>(
        &ctx,
        &a.spec.spec()?,
        files,
        &a.format,
    )
}

//! `persson adhesion`: whether a rough surface sticks (the full-contact
//! energy balance per magnification and its verdict), the adhesive contact
//! area against nominal pressure (tension ≤ 0 allowed) and the pull-off
//! stress, from Persson's theory (the scene output `adhesion`).

use persson_studies::scene::AdhesionOutput;

use super::args::{measured_contact, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::Format;
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson adhesion`: the shared ones, and the spec's
/// ([`AdhesionOutput`]) derived from it.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, same unit as E*, negative in tension;
    /// repeatable or comma-separated (none: the stickiness balance only).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Vec<f64>,
    #[command(flatten)]
    spec: SpecArgs<AdhesionOutput>,
    #[command(flatten)]
    format: Format,
}

impl SpecFlags for AdhesionOutput {}

/// Run `persson adhesion`.
pub fn run(mut a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let example = a.spectrum.example;
    let pressures = match (a.pressure.is_empty(), example) {
        (true, true) => super::args::example::PRESSURES.to_vec(),
        _ => a.pressure.clone(),
    };
    if example {
        a.spec.or(
            "work_of_adhesion",
            persson_studies::adhesion::EXAMPLE_WORK_OF_ADHESION,
        );
    }
    let ctx = persson_studies::study::Context::with_contact(surface, &pressures);
    super::study::run::<persson_studies::adhesion::Adhesion>(
        &ctx,
        &a.spec.spec()?,
        files,
        &a.format,
    )
}

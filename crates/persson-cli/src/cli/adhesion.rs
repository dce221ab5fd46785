//! `persson adhesion`: whether a rough surface sticks (the full-contact
//! energy balance per magnification and its verdict), the adhesive contact
//! area against nominal pressure (tension ≤ 0 allowed) and the pull-off
//! stress, from Persson's theory (the scene output `adhesion`).

use persson::adhesion::AreaEnhancement;
use persson_studies::scene::{by_name, AdhesionOutput};

use super::args::{measured_contact, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::Format;

/// Arguments of `persson adhesion`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Work of adhesion Δγ (J/m², ≥ 0).
    #[arg(long, required_unless_present = "example", allow_hyphen_values = true, value_parser = super::number::number)]
    work_of_adhesion: Option<f64>,
    /// Nominal (mean) pressure σ0, same unit as E*, negative in tension;
    /// repeatable or comma-separated (none: the stickiness balance only).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Vec<f64>,
    /// Magnification ζ of the contact points (default q_s/q_l).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    zeta: Option<f64>,
    /// Number of log-spaced ζ of the stickiness balance, from 1 to q_s/q_l.
    #[arg(long, default_value_t = persson_studies::scene::DEFAULT_STICKINESS_POINTS, allow_hyphen_values = true, value_parser = super::number::count)]
    points: usize,
    /// Whether Δγ acts on the true (sloped) area or the projected one.
    #[arg(long, value_parser = by_name::<AreaEnhancement>(), default_value_t = AreaEnhancement::Slopes)]
    area_enhancement: AreaEnhancement,
    /// Range Δr of the adhesive interaction (m): adds the Pastewka–Robbins criterion.
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    adhesion_range: Option<f64>,
    /// Absolute tolerance of the contact fractions.
    #[arg(long, default_value = "1e-5", allow_hyphen_values = true, value_parser = super::number::number)]
    tolerance: f64,
    #[command(flatten)]
    format: Format,
}

/// Run `persson adhesion`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let example = a.spectrum.example;
    let pressures = match (a.pressure.is_empty(), example) {
        (true, true) => super::args::example::PRESSURES.to_vec(),
        _ => a.pressure.clone(),
    };
    let out = AdhesionOutput {
        work_of_adhesion: a
            .work_of_adhesion
            .unwrap_or(persson_studies::adhesion::EXAMPLE_WORK_OF_ADHESION),
        zeta: a.zeta,
        points: Some(a.points),
        area_enhancement: Some(a.area_enhancement),
        adhesion_range: a.adhesion_range,
        tolerance: Some(a.tolerance),
    };
    let ctx = persson_studies::study::Context::with_contact(surface, &pressures);
    super::study::run::<persson_studies::adhesion::Adhesion>(&ctx, &out, files, &a.format)
}

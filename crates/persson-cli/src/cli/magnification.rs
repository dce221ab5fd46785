//! `persson magnification` (alias `g`): G(ζ) and A/A0 against magnification
//! (the scene output `magnification`).

use persson_studies::scene::MagnificationOutput;

use super::args::{measured_contact, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::Format;

/// Arguments of `persson magnification`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, same unit as E* (with --example: 1e7).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    pressure: Option<f64>,
    /// Magnifications ζ ≥ 1 (comma-separated; default: --points values from 1 to q_s/q_l).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = super::number::number)]
    zeta: Vec<f64>,
    /// Number of log-spaced magnifications when --zeta is not given.
    #[arg(long, default_value_t = 21, allow_hyphen_values = true, value_parser = super::number::count)]
    points: usize,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
    /// Also draw G(ζ) into this file (.svg or .png).
    #[arg(long, value_name = "FILE.svg|png", value_parser = super::files::out_file)]
    plot_g: Option<super::files::OutFile>,
}

/// Run `persson magnification`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let nominal_pressure = match (a.pressure, a.spectrum.example) {
        (Some(p), _) => p,
        (None, true) => super::args::example::PRESSURES[3],
        (None, false) => anyhow::bail!("no nominal pressure: give --pressure P"),
    };
    let out = MagnificationOutput {
        nominal_pressure,
        zeta: a.zeta.clone(),
        points: a.points,
        plot: a.plot.path(),
        plot_g: a.plot_g.as_deref().map(std::path::Path::to_path_buf),
    };
    let ctx = persson_studies::study::Context::with_contact(surface, &[]);
    super::study::run::<persson_studies::magnification::Magnification>(&ctx, &out, files, &a.format)
}

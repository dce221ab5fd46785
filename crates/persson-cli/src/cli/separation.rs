//! `persson separation`: mean interfacial separation ū, contact stiffness
//! K = −dσ0/dū and elastic energy against nominal pressure (the scene output
//! `separation`; Persson, Phys. Rev. Lett. 99, 125502 (2007)).

use persson_studies::scene::SeparationOutput;

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::{print_warned, Format};
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson separation`: the shared ones, the spec's
/// ([`SeparationOutput`]) derived from it, and the switch to the study
/// `separation_density`.
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
    spec: SpecArgs<SeparationOutput>,
    #[command(flatten)]
    format: Format,
    /// Report the distribution of interfacial separations P(u) at each
    /// pressure instead (the scene output `separation_density`): the
    /// contact's weight A/A0 at u = 0 and the continuous part P_nc(u) (JSON:
    /// on --density-points separations), with the checks A/A0 + ∫P_nc du = 1
    /// and ∫u P du = ū.
    #[arg(long, conflicts_with_all = ["plot", "plot_area"])]
    separation_density: bool,
    /// Separations u (from 0 to where P_nc is negligible) per pressure for
    /// --separation-density.
    #[arg(long, default_value_t = 101, requires = "separation_density", allow_hyphen_values = true, value_parser = super::number::count)]
    density_points: usize,
}

impl SpecFlags for SeparationOutput {}

/// Run `persson separation`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let out = a.spec.spec()?;
    if a.separation_density {
        let report = persson_studies::scene::separation_density::separation_density(
            &surface,
            &pressures,
            a.density_points,
            out.tolerance
                .unwrap_or(persson::separation::DEFAULT_TOLERANCE),
        )?;
        return print_warned(&report, &report.warnings, &a.format);
    }
    let ctx = persson_studies::study::Context::with_contact(surface, &pressures);
    super::study::run::<persson_studies::separation::Separation>(&ctx, &out, files, &a.format)
}

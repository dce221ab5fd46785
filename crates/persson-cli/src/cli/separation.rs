//! `persson separation`: mean interfacial separation ū, contact stiffness
//! K = −dσ0/dū and elastic energy against nominal pressure (the scene output
//! `separation`; Persson, Phys. Rev. Lett. 99, 125502 (2007)).

use persson_studies::scene::{run, SeparationOutput, TheoriesOutput};

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::output::{print_warned, Format};

/// Arguments of `persson separation`.
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
    /// Relative tolerance of the wavevector integrals.
    #[arg(long, default_value = "1e-10", allow_hyphen_values = true, value_parser = super::number::number)]
    tolerance: f64,
    #[command(flatten)]
    format: Format,
    /// Also draw ū against load (with the small-load law) into this file (.svg or .png).
    #[command(flatten)]
    plot: super::plot::PlotArg,
    /// Also draw A/A0 against load for all four theories (default γ) into this file.
    #[arg(long, value_name = "FILE.svg|png", value_parser = super::files::out_file)]
    plot_area: Option<super::files::OutFile>,
    /// Number of log-spaced pressures in the plots, spanning the given pressures
    /// (a single pressure σ0: σ0/100 to 100 σ0).
    #[arg(long, default_value_t = 60, allow_hyphen_values = true, value_parser = super::number::count)]
    plot_points: usize,
    /// Report the distribution of interfacial separations P(u) at each
    /// pressure instead: the contact's weight A/A0 at u = 0 and the continuous
    /// part P_nc(u) (JSON: on --density-points separations), with the checks
    /// A/A0 + ∫P_nc du = 1 and ∫u P du = ū.
    #[arg(long, conflicts_with_all = ["plot", "plot_area"])]
    separation_density: bool,
    /// Separations u (from 0 to where P_nc is negligible) per pressure for
    /// --separation-density.
    #[arg(long, default_value_t = 101, requires = "separation_density", allow_hyphen_values = true, value_parser = super::number::count)]
    density_points: usize,
}

/// Run `persson separation`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    if a.separation_density {
        let report = persson_studies::scene::separation_density::separation_density(
            &surface,
            &pressures,
            a.density_points,
            a.tolerance,
        )?;
        return print_warned(&report, &report.warnings, &a.format);
    }
    let grid = if a.plot.plot.is_some() || a.plot_area.is_some() {
        persson_studies::study::plot_pressures(&pressures, a.plot_points)?
    } else {
        vec![]
    };
    let out = SeparationOutput {
        tolerance: Some(a.tolerance),
    };
    let curve = if a.plot.plot.is_some() {
        &grid[..]
    } else {
        &[]
    };
    let report = run::separation(&surface, &pressures, &out, curve)?;
    {
        use persson_studies::scene::plot;
        a.plot.draw(files, || plot::separation(&report))?;
        if a.plot_area.is_some() {
            let theories = run::theories(&surface, &grid, &TheoriesOutput::default())?;
            super::plot::draw(files, a.plot_area.as_deref(), || plot::theories(&theories))?;
        }
    }
    print_warned(&report, &report.warnings, &a.format)
}

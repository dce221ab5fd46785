//! `persson conductance`: thermal and electrical contact conductance against
//! load, through the contact spots (Barber's identity on Persson's stiffness)
//! and through the gap (over P(u)); the scene output `conductance`.

use std::path::PathBuf;

use persson_studies::scene::{transport, ConductanceOutput};

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::number::number;
use super::output::{print_warned, Format};

/// Arguments of `persson conductance`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, Pa; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = number)]
    pressure: Vec<f64>,
    /// Thermal conductivities κ1[,κ2] of the two bodies, W/(m K) (one value: both).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = number)]
    conductivity: Vec<f64>,
    /// Electrical resistivities ρ1[,ρ2] of the two bodies, Ω m (one value: both).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = number)]
    resistivity: Vec<f64>,
    /// Gap conductance by gas conduction α(u) = κ_gas/(u + 2ℓ): κ_gas in W/(m K).
    #[arg(long, requires = "mean_free_path", allow_hyphen_values = true, value_parser = number)]
    gas_conductivity: Option<f64>,
    /// The temperature-jump length ℓ of the gas law, m.
    #[arg(long, requires = "gas_conductivity", allow_hyphen_values = true, value_parser = number)]
    mean_free_path: Option<f64>,
    /// Gap conductance from a table α(u): a text file of two columns, u (m)
    /// ascending and α (W/(m² K)); `#` starts a comment.
    #[arg(long, conflicts_with = "gas_conductivity", value_name = "FILE")]
    gap_table: Option<PathBuf>,
    /// Relative tolerance of the wavevector integrals.
    #[arg(long, default_value = "1e-9", allow_hyphen_values = true, value_parser = number)]
    tolerance: f64,
    #[command(flatten)]
    format: Format,
    /// Also draw h(σ0) on log axes into this file (.svg or .png).
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson conductance`.
pub fn run(a: Args) -> anyhow::Result<()> {
    a.plot.check()?;
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let gap_table = match &a.gap_table {
        Some(path) => read_gap_table(path)?,
        None => vec![],
    };
    let out = ConductanceOutput {
        conductivity: a.conductivity.clone(),
        resistivity: a.resistivity.clone(),
        gas_conductivity: a.gas_conductivity,
        mean_free_path: a.mean_free_path,
        gap_table,
        tolerance: Some(a.tolerance),
        bem: None,
        plot: None,
    };
    let report = transport::conductance(&surface, &pressures, &out)?;
    #[cfg(feature = "plot")]
    a.plot
        .draw(|| persson_studies::scene::plot::conductance(&report))?;
    print_warned(&report, &report.warnings, &a.format)
}

/// The (u, α) pairs of a `--gap-table` file.
fn read_gap_table(path: &std::path::Path) -> anyhow::Result<Vec<(f64, f64)>> {
    let bytes = persson::io::read(path)?;
    let m = persson::io::text::matrix(path, &bytes)?;
    if m.cols != 2 {
        anyhow::bail!(
            "--gap-table {}: {} columns, need 2 (u in m, α in W/(m² K))",
            path.display(),
            m.cols
        );
    }
    Ok(m.values.chunks(2).map(|r| (r[0], r[1])).collect())
}

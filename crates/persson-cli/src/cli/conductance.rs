//! `persson conductance`: thermal and electrical contact conductance against
//! load, through the contact spots (Barber's identity on Persson's stiffness)
//! and through the gap (over P(u)); the scene output `conductance`.

use persson_studies::scene::ConductanceOutput;
use persson_studies::study::Context;
use persson_studies::transport::Conductance;

use super::args::{measured_contact, pressures, MaterialArgs, MeasuredArgs, SpectrumArgs};
use super::number::number;
use super::output::Format;
use super::spec_args::{SpecArgs, SpecFlags};

/// Arguments of `persson conductance`: the shared ones, the gap table as a
/// file, and the rest of the spec ([`ConductanceOutput`]) derived from it.
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
    /// Gap conductance from a table α(u): a text file of two columns, u (m)
    /// ascending and α (W/(m² K)); `#` starts a comment.
    #[arg(long, value_name = "FILE", value_parser = super::files::in_file)]
    gap_table: Option<super::files::InFile>,
    #[command(flatten)]
    spec: SpecArgs<ConductanceOutput>,
    #[command(flatten)]
    format: Format,
}

/// The gap table is a file here (a list of pairs in a scene); the BEM beside
/// the theory is `persson bem rough --conductivity`.
impl SpecFlags for ConductanceOutput {
    const OWN: &'static [&'static str] = &["gap_table", "bem"];
}

/// Run `persson conductance`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    let surface = measured_contact(&a.spectrum, &a.measured, &a.material)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let mut out = a.spec.spec()?;
    out.gap_table = a.gap_table.as_deref().map(read_gap_table).transpose()?;
    // The example's heat path where the flags name none.
    let none = out.conductivity.is_empty()
        && out.resistivity.is_empty()
        && out.gas_conductivity.is_none()
        && out.gap_table.is_none();
    if a.spectrum.example && none {
        out = ConductanceOutput {
            tolerance: out.tolerance,
            plot: out.plot,
            ..ConductanceOutput::example()
        };
    }
    let ctx = Context::with_contact(surface, &pressures);
    super::study::run::<Conductance>(&ctx, &out, files, &a.format)
}

/// The (u, α) pairs of a `--gap-table` file, checked by the gap law's own
/// validation ([`persson::conductance::GapLaw::validate`]); an error names
/// the file and the line of the point at fault.
fn read_gap_table(path: &std::path::Path) -> anyhow::Result<Vec<(f64, f64)>> {
    let bytes = persson::io::read(path)?;
    let rows = persson::io::text::rows(path, &bytes)?;
    let in_file = |line: usize, what: String| {
        anyhow::Error::from(persson::Error::parse(
            path,
            line,
            0,
            format!("--gap-table: {what}"),
        ))
    };
    let mut points = Vec::with_capacity(rows.rows.len());
    for r in &rows.rows {
        let &[u, alpha] = r.values.as_slice() else {
            let n = r.values.len();
            return Err(in_file(
                r.line,
                format!("{n} columns, need 2 (u in m, α in W/(m² K))"),
            ));
        };
        points.push((u, alpha));
    }
    let law = persson::conductance::GapLaw::Table {
        points: points.clone(),
    };
    match law.validate() {
        Ok(()) => Ok(points),
        Err(persson::Error::InvalidParameter {
            name,
            value,
            requirement,
        }) => {
            let row = name
                .strip_prefix("gap_table[")
                .and_then(|i| i.strip_suffix(']'))
                .and_then(|i| i.parse::<usize>().ok());
            let line = row.and_then(|i| rows.rows.get(i)).map_or(0, |r| r.line);
            let value = persson_studies::table::number(value, 6);
            Err(in_file(line, format!("{value} must be {requirement}")))
        }
        Err(e) => Err(e.into()),
    }
}

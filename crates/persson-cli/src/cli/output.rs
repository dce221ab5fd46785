//! Output formats shared by every subcommand: a readable table (default),
//! one JSON object (`--json`) or CSV (`--csv`).

use std::io::Write;

use anyhow::Context;
use persson_studies::table::{narrow, Tabulate};
use persson_studies::warning::Warned;
use persson_studies::Warning;
use serde::Serialize;

/// How to print a report: text (default), `--json` or `--csv`.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct Format {
    /// Print one JSON object on stdout.
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print the table as CSV on stdout.
    #[arg(long)]
    pub csv: bool,
}

/// Where the input of a calculation was given: on the command line or in a
/// scene file. A warning's text names the input; [`hint`] adds how it is
/// spelled here.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// Flags of a subcommand.
    Flags,
    /// A scene file (`persson run`).
    Scene,
}

/// How the input a warning suggests changing is spelled on the command line
/// or in a scene file, if the warning suggests a change.
pub fn hint(w: &Warning, source: Source) -> Option<&'static str> {
    use persson_studies::scene::ConventionName;
    match (w, source) {
        (_, Source::Scene) => w.scene_hint(),
        (Warning::BandLimited { .. }, Source::Flags) => Some("--grid"),
        (
            Warning::PsdConvention {
                convention: ConventionName::Persson,
                ..
            },
            Source::Flags,
        ) => Some("--psd-convention surface-topography"),
        (Warning::RisingSpectrum { .. }, Source::Flags) => Some("--surface FILE"),
        _ => None,
    }
}

/// Print one warning on stderr: `persson: warning: <text> (<hint>)`.
pub fn print_warning(w: &Warning, source: Source) {
    match hint(w, source) {
        Some(h) => eprintln!("persson: warning: {w} ({h})"),
        None => eprintln!("persson: warning: {w}"),
    }
}

/// Print a typed report in the chosen format, without warnings (see [`print_warned`]).
pub fn print<R: Serialize + Tabulate>(report: &R, f: &Format) -> anyhow::Result<()> {
    print_warned(report, &[], f)
}

/// Print each warning on stderr, then a typed report in the chosen format:
/// its JSON with the warnings (`--json`), the CSV of its main table (`--csv`;
/// the other tables are named on stderr), or every table as text.
pub fn print_warned<R: Serialize + Tabulate>(
    report: &R,
    warnings: &[Warning],
    f: &Format,
) -> anyhow::Result<()> {
    print_from(report, warnings, f, Source::Flags)
}

/// As [`print_warned`], the warnings' hints spelled for `source`.
pub fn print_from<R: Serialize + Tabulate>(
    report: &R,
    warnings: &[Warning],
    f: &Format,
    source: Source,
) -> anyhow::Result<()> {
    print_tables(report, warnings, f, source, None)
}

/// As [`print_warned`], with text tables that fit
/// [`persson_studies::table::TEXT_WIDTH`] characters
/// unless `wide` ([`narrow`]: long titles wrapped, the omittable columns
/// left out and named; CSV and JSON keep every column).
#[cfg(feature = "bem")]
pub fn print_narrowed<R: Serialize + Tabulate>(
    report: &R,
    warnings: &[Warning],
    f: &Format,
    wide: bool,
) -> anyhow::Result<()> {
    print_tables(
        report,
        warnings,
        f,
        Source::Flags,
        (!wide).then_some(persson_studies::table::TEXT_WIDTH),
    )
}

/// Print the warnings and the report; text tables narrowed to `width`. A
/// quantity that came out NaN or infinite is printed as `–` (text), empty
/// (CSV) or `null` (JSON), with a warning that names it.
fn print_tables<R: Serialize + Tabulate>(
    report: &R,
    warnings: &[Warning],
    f: &Format,
    source: Source,
    width: Option<usize>,
) -> anyhow::Result<()> {
    let mut tables = report.tables();
    let mut warnings = warnings.to_vec();
    warnings.extend(persson_studies::warning::not_computed(&tables));
    for w in &warnings {
        print_warning(w, source);
    }
    let mut out = std::io::stdout().lock();
    if f.json {
        serde_json::to_writer_pretty(&mut out, &Warned::new(report, &warnings))?;
        writeln!(out)?;
    } else {
        if let (Some(w), false) = (width, f.csv) {
            for t in &mut tables {
                narrow(t, w, "not shown (--wide shows them)");
            }
        }
        if f.csv {
            if let Some(main) = tables.first() {
                write!(out, "{}", main.to_csv())?;
            }
            let rest: Vec<&str> = tables.iter().skip(1).map(|t| t.name.as_str()).collect();
            if !rest.is_empty() {
                eprintln!(
                    "persson: note: --csv prints the table `{}`; also computed: {} (all in --json)",
                    tables[0].name,
                    rest.join(", ")
                );
            }
        } else {
            for (i, t) in tables.iter().enumerate() {
                if i > 0 {
                    writeln!(out)?;
                }
                write!(out, "{}", t.to_text())?;
            }
        }
    }
    out.flush().context("writing to stdout")
}

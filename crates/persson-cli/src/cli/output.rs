//! Output formats shared by every subcommand: a readable table (default),
//! one JSON object (`--json`) or CSV (`--csv`).

use std::io::Write;

use anyhow::Context;
use persson_studies::table::Tabulate;
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
    for w in warnings {
        eprintln!("persson: warning: {w}");
    }
    let mut out = std::io::stdout().lock();
    if f.json {
        serde_json::to_writer_pretty(&mut out, &Warned::new(report, warnings))?;
        writeln!(out)?;
    } else {
        let tables = report.tables();
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

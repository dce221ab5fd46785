//! Output formats shared by every subcommand: a readable table (default),
//! one JSON object (`--json`) or CSV (`--csv`).

use std::io::Write;

use anyhow::Context;
use persson::table::Tabulate;
use serde::Serialize;

/// How to print a [`Report`].
#[derive(clap::Args, Debug, Clone, Default)]
pub struct Format {
    /// Print one JSON object on stdout.
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print the table as CSV on stdout.
    #[arg(long)]
    pub csv: bool,
}

/// What a subcommand computed: scalars, one table, and the JSON object.
pub struct Report {
    /// Title line of the readable output.
    pub title: String,
    /// Named scalars, printed above the table.
    pub scalars: Vec<(String, f64)>,
    /// Column names of the table.
    pub columns: Vec<String>,
    /// Table rows.
    pub rows: Vec<Vec<f64>>,
    /// The JSON object printed with `--json`.
    pub json: serde_json::Value,
}

impl Report {
    /// Print in the chosen format.
    pub fn print(&self, f: &Format) -> anyhow::Result<()> {
        let mut out = std::io::stdout().lock();
        if f.json {
            serde_json::to_writer_pretty(&mut out, &self.json)?;
            writeln!(out)?;
        } else if f.csv {
            write!(out, "{}", self.csv())?;
        } else {
            writeln!(out, "{}", self.title)?;
            for (k, v) in &self.scalars {
                writeln!(out, "  {k:<24} {}", fmt(*v))?;
            }
            if !self.rows.is_empty() {
                writeln!(out)?;
                let head: Vec<String> = self.columns.iter().map(|c| format!("{c:>16}")).collect();
                writeln!(out, "{}", head.join(" "))?;
                for r in &self.rows {
                    let cells: Vec<String> = r.iter().map(|v| format!("{:>16}", fmt(*v))).collect();
                    writeln!(out, "{}", cells.join(" "))?;
                }
            }
        }
        out.flush().context("writing to stdout")
    }
}

impl Report {
    /// The table as CSV: a header line, then one line per row (shortest round-trip numbers).
    pub fn csv(&self) -> String {
        let mut s = self.columns.join(",");
        s.push('\n');
        for r in &self.rows {
            let cells: Vec<String> = r.iter().map(|v| format!("{v:e}")).collect();
            s.push_str(&cells.join(","));
            s.push('\n');
        }
        s
    }
}

/// Ten significant digits, scientific outside [1e-3, 1e6).
fn fmt(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        format!("{v}")
    } else if (1e-3..1e6).contains(&v.abs()) {
        let decimals = (9 - v.abs().log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.9e}")
    }
}

/// Print a typed report in the chosen format: its JSON (`--json`), the CSV of
/// its main table (`--csv`; the other tables are named on stderr), or every
/// table as text.
pub fn print<R: Serialize + Tabulate>(report: &R, f: &Format) -> anyhow::Result<()> {
    let mut out = std::io::stdout().lock();
    if f.json {
        serde_json::to_writer_pretty(&mut out, report)?;
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

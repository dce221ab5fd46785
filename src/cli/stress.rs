//! `persson stress`: the stress distribution P(σ) at one G, dimensionless
//! (the scene output `stress` in G; Persson, Bucher & Chiaia, Phys. Rev. B 65,
//! 184106 (2002), Figs. 2–4).

use persson::scene::{run, StartName};
use persson::stress::{Start, TabulatedStart};
use persson::Error;

use super::output::{print_warned, Format};

/// Arguments of `persson stress`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Start condition P(σ, ζ = 1).
    #[arg(
        long,
        value_enum,
        required_unless_present = "table",
        conflicts_with = "table"
    )]
    start: Option<StartName>,
    /// A tabulated start instead: a file of two columns σ/σH, σH P0 (comma or
    /// blank separated, `#` comments), piecewise linear, σH = the last σ.
    #[arg(long)]
    table: Option<std::path::PathBuf>,
    /// How far ∫ P0 dσ of a --table may be from 1.
    #[arg(
        long,
        alias = "table-tol",
        default_value = "1e-6",
        allow_negative_numbers = true
    )]
    table_normalisation: f64,
    /// G(ζ) (Persson, Bucher & Chiaia 2002, Eq. 2, with σ0 the nominal mean pressure).
    #[arg(long, allow_negative_numbers = true)]
    g: f64,
    /// σY/σH, the yield stress in units of the peak pressure (absent: elastic).
    #[arg(long, allow_negative_numbers = true)]
    yield_ratio: Option<f64>,
    /// σ/σH where to evaluate P; comma-separated (default: --points values from 0
    /// to the end of the distribution).
    #[arg(
        long,
        alias = "sigma",
        value_delimiter = ',',
        allow_negative_numbers = true
    )]
    sigma_ratio: Vec<f64>,
    /// Number of evenly spaced σ when --sigma-ratio is not given.
    #[arg(long, default_value_t = 201)]
    points: usize,
    /// Absolute tolerance of σH P and of the fractions.
    #[arg(
        long,
        alias = "tol",
        default_value = "1e-12",
        allow_negative_numbers = true
    )]
    tolerance: f64,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson stress`.
pub fn run(a: Args) -> anyhow::Result<()> {
    a.plot.check()?;
    let start = match (a.start, &a.table) {
        (Some(s), _) => Start::from(s),
        (None, Some(path)) => {
            let (s, p) = read_table(path)?;
            Start::Tabulated(
                TabulatedStart::new(&s, &p, a.table_normalisation)
                    .map_err(|e| anyhow::anyhow!("--table {}: {e}", path.display()))?,
            )
        }
        (None, None) => anyhow::bail!("give --start or --table"),
    };
    let report = run::stress_dimensionless(
        &start,
        &[a.g],
        a.yield_ratio,
        a.tolerance,
        &a.sigma_ratio,
        a.points,
    )?;
    #[cfg(feature = "plot")]
    a.plot.draw(|| persson::scene::plot::stress(&report))?;
    print_warned(&report, &report.warnings, &a.format)
}

/// Two columns of numbers; `#` starts a comment.
fn read_table(path: &std::path::Path) -> Result<(Vec<f64>, Vec<f64>), Error> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::Io {
        path: path.to_path_buf(),
        source: e,
    })?;
    let (mut s, mut p) = (Vec::new(), Vec::new());
    for (i, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let cols: Vec<&str> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|c| !c.is_empty())
            .collect();
        if cols.len() != 2 {
            return Err(Error::parse(
                path,
                i + 1,
                1,
                format!("expected two columns σ, P0, found {}", cols.len()),
            ));
        }
        let mut v = [0.0; 2];
        for (k, c) in cols.iter().enumerate() {
            v[k] = c
                .parse()
                .map_err(|_| Error::parse(path, i + 1, k + 1, format!("`{c}` is not a number")))?;
        }
        s.push(v[0]);
        p.push(v[1]);
    }
    Ok((s, p))
}

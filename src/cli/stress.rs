//! `persson stress`: the stress distribution P(σ) at one G, dimensionless.

use persson::stress::{Solver, Start, TabulatedStart};
use persson::Error;
use serde_json::json;

use super::output::{Format, Report};

/// The start conditions of seed 001 Figs. 2–4.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum StartName {
    /// Flat punch, P0 = δ(σ − σ0) (σH = σ0).
    Flat,
    /// Hertz ball, P0 = 2σ/σH², σ0 = 2σH/3.
    Hertz,
    /// Cylinder, P0 = (σ/σH²)(1 − (σ/σH)²)^(-1/2), σ0 = πσH/4.
    Cylinder,
}

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
    /// A tabulated start instead: a file of two columns σ, P0(σ) (comma or
    /// blank separated, `#` comments), piecewise linear, σH = the last σ.
    #[arg(long)]
    table: Option<std::path::PathBuf>,
    /// How far ∫ P0 dσ of a --table may be from 1.
    #[arg(long, default_value_t = 1e-6, allow_negative_numbers = true)]
    table_tol: f64,
    /// G(ζ) (seed 001 Eq. 2, with σ0 the nominal mean pressure).
    #[arg(long, allow_negative_numbers = true)]
    g: f64,
    /// σY/σH, the yield stress in units of the peak pressure (absent: elastic).
    #[arg(long, allow_negative_numbers = true)]
    yield_ratio: Option<f64>,
    /// σ/σH where to evaluate P; comma-separated (default: --points values from 0
    /// to the end of the distribution).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    sigma: Vec<f64>,
    /// Number of evenly spaced σ when --sigma is not given.
    #[arg(long, default_value_t = 201)]
    points: usize,
    /// Absolute tolerance for the density (units of 1/σH) and the fractions.
    #[arg(long, default_value_t = 1e-12, allow_negative_numbers = true)]
    tol: f64,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson stress`.
pub fn run(a: Args) -> anyhow::Result<()> {
    a.plot.check()?;
    report(&a)?.print(&a.format)
}

fn report(a: &Args) -> anyhow::Result<Report> {
    let start = match (a.start, &a.table) {
        (Some(StartName::Flat), _) => Start::Flat,
        (Some(StartName::Hertz), _) => Start::Hertz,
        (Some(StartName::Cylinder), _) => Start::Cylinder,
        (None, Some(path)) => {
            let (s, p) = read_table(path)?;
            Start::Tabulated(
                TabulatedStart::new(&s, &p, a.table_tol)
                    .map_err(|e| anyhow::anyhow!("--table {}: {e}", path.display()))?,
            )
        }
        (None, None) => unreachable!("clap requires --start or --table"),
    };
    let solver = Solver::new(&start, a.g, a.yield_ratio, a.tol)?;
    let sigma = if a.sigma.is_empty() {
        solver.grid(a.points)
    } else {
        a.sigma.clone()
    };
    let c = solver.curve(&sigma)?;
    let label = format!(
        "{} start, G = {:e}, A/A0 = {:.4}",
        start.name(),
        a.g,
        c.contact_fraction
    );
    #[cfg(feature = "plot")]
    a.plot
        .draw(|| persson::plot::stress_family(&c.sigma, &[(label.as_str(), &c.density)]))?;
    #[cfg(not(feature = "plot"))]
    {
        let _ = &label;
        a.plot.unavailable()?;
    }
    Ok(Report {
        title: format!(
            "Stress distribution P(sigma), start {}, G = {:e}, sigma_Y/sigma_H = {}; sigma in units of sigma_H, density in 1/sigma_H\n  method: {}",
            start.name(),
            a.g,
            a.yield_ratio.map_or("inf (elastic)".to_string(), |r| format!("{r:e}")),
            c.method
        ),
        scalars: vec![
            ("contact_fraction".into(), c.contact_fraction),
            ("plastic_fraction".into(), c.plastic_fraction),
            ("non_contact_fraction".into(), c.non_contact_fraction),
            ("tau".into(), c.tau),
            ("error_bound".into(), c.error_bound),
        ],
        columns: ["sigma", "density"].map(String::from).to_vec(),
        rows: c
            .sigma
            .iter()
            .zip(&c.density)
            .map(|(s, p)| vec![*s, *p])
            .collect(),
        json: json!({
            "start": start.name(),
            "g": a.g,
            "yield_ratio": a.yield_ratio,
            "tau": c.tau,
            "mean_ratio": start.mean_ratio(),
            "contact_fraction": c.contact_fraction,
            "plastic_fraction": c.plastic_fraction,
            "non_contact_fraction": c.non_contact_fraction,
            "contact_error": c.contact_error,
            "plastic_error": c.plastic_error,
            "density_error": c.density_error,
            "error_bound": c.error_bound,
            "method": c.method,
            "sigma": c.sigma,
            "density": c.density,
        }),
    })
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

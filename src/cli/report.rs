//! `persson report accuracy|stability`.

use persson::report::{self, Extent};
use serde_json::json;

use super::output::{Format, Report};

/// Arguments of `persson report`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    which: Which,
}

#[derive(clap::Subcommand, Debug)]
enum Which {
    /// Error against run time for every numerical method and accuracy setting.
    Accuracy {
        /// Go further (finer tolerances, larger grids); takes longer.
        #[arg(long)]
        full: bool,
        #[command(flatten)]
        format: Format,
        #[command(flatten)]
        plot: super::plot::PlotArg,
    },
    /// The extreme and stiff cases; exits 1 if any output is non-finite.
    Stability {
        #[command(flatten)]
        format: Format,
    },
}

/// Run `persson report`.
pub fn run(a: Args) -> anyhow::Result<()> {
    match a.which {
        Which::Accuracy { full, format, plot } => {
            plot.check()?;
            let rows = report::accuracy(if full { Extent::Full } else { Extent::Default })?;
            #[cfg(feature = "plot")]
            plot.draw(|| {
                let mut methods: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
                for r in &rows {
                    match methods.iter_mut().find(|m| m.0 == r.method) {
                        Some(m) => m.1.push((r.seconds, r.error)),
                        None => methods.push((r.method.clone(), vec![(r.seconds, r.error)])),
                    }
                }
                let refs: Vec<(&str, &[(f64, f64)])> = methods
                    .iter()
                    .map(|(n, p)| (n.as_str(), p.as_slice()))
                    .collect();
                Ok(persson::plot::error_vs_time(&refs))
            })?;
            Report {
                title: "Error against run time (error: achieved, vs the reference named in --json)"
                    .into(),
                scalars: vec![],
                columns: ["setting", "error", "estimate", "seconds"]
                    .map(String::from)
                    .to_vec(),
                rows: rows
                    .iter()
                    .map(|r| {
                        vec![
                            r.setting,
                            r.error,
                            r.estimate.unwrap_or(f64::NAN),
                            r.seconds,
                        ]
                    })
                    .collect(),
                json: json!({ "rows": rows }),
            }
            .print_grouped(
                &format,
                rows.iter()
                    .map(|r| format!("{} [{}]", r.method, r.knob))
                    .collect(),
            )
        }
        Which::Stability { format } => {
            let cases = report::stability()?;
            let bad = cases.iter().filter(|c| !c.finite).count();
            if format.json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&json!({ "cases": cases, "non_finite": bad }))?
                );
            } else {
                println!(
                    "{:<64} {:>24} {:>12} finite",
                    "case", "value", "error_bound"
                );
                for c in &cases {
                    println!(
                        "{:<64} {:>24e} {:>12.3e} {}",
                        c.case, c.value, c.error_bound, c.finite
                    );
                }
                println!("{} cases, {bad} with a non-finite output", cases.len());
            }
            if bad > 0 {
                std::process::exit(1);
            }
            Ok(())
        }
    }
}

//! `persson report accuracy|stability`.

use persson_studies::report::{self, Extent};

use super::output::{self, Format};

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
    /// The extreme and stiff cases, summed up per family (every case with
    /// --json); exits 1 if any output is non-finite or an error bound fails
    /// against its reference.
    Stability {
        #[command(flatten)]
        format: Format,
    },
}

/// Run `persson report`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    match a.which {
        Which::Accuracy { full, format, plot } => {
            let r = report::accuracy(if full { Extent::Full } else { Extent::Default })?;
            plot.draw(files, || {
                let methods: Vec<(&str, Vec<(f64, f64)>)> = r
                    .methods
                    .iter()
                    .map(|m| {
                        let points = m.rows.iter().map(|r| (r.seconds, r.error)).collect();
                        (m.title.as_str(), points)
                    })
                    .collect();
                let refs: Vec<(&str, &[(f64, f64)])> =
                    methods.iter().map(|(n, p)| (*n, p.as_slice())).collect();
                Ok(persson_studies::plot::error_vs_time(&refs))
            })?;
            output::print(&r, &format)
        }
        Which::Stability { format } => {
            let r = report::stability()?;
            output::print(&r, &format)?;
            let bad = r.non_finite();
            if bad > 0 || !r.bounds_held() {
                eprintln!(
                    "persson: {bad} case(s) with a non-finite output{}",
                    if r.bounds_held() {
                        ""
                    } else {
                        ", and an error bound that failed against its reference"
                    }
                );
                std::process::exit(1);
            }
            Ok(())
        }
    }
}

//! `persson spectrum`: moments of the spectrum, a power-law fit and C(q).

use persson::scene::run;

use super::args::SpectrumArgs;
use super::output::{print, Format};

/// Arguments of `persson spectrum`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    /// Lower end of the q range for the moments (default q_l), 1/m.
    #[arg(long, allow_negative_numbers = true)]
    q_min: Option<f64>,
    /// Upper end of the q range for the moments (default q_s), 1/m.
    #[arg(long, allow_negative_numbers = true)]
    q_max: Option<f64>,
    /// Number of log-spaced q values in the C(q) table.
    #[arg(long, default_value_t = 11)]
    points: usize,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson spectrum`.
pub fn run(a: Args) -> anyhow::Result<()> {
    a.plot.check()?;
    let s = a.spectrum.build()?;
    let description = a
        .spectrum
        .is_example()
        .then(|| persson::scene::EXAMPLE.to_string());
    let report = run::spectrum(s.as_ref(), description, a.q_min, a.q_max, a.points)?;
    #[cfg(feature = "plot")]
    a.plot.draw(|| persson::scene::plot::spectrum(&report))?;
    print(&report, &a.format)
}

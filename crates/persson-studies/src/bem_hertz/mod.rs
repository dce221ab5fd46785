//! `bem_hertz`: the Hertz ball on the FFT-BEM (`persson bem hertz`): the
//! validation on one grid, η per grid with the plastic disc, the stress on
//! the axis, or the adhesive sphere's pull-off.

use std::path::Path;

use persson::error::Result;

mod spec;
pub use spec::*;

// The report and the run need the BEM; without it the study refuses
// (`off.rs`, whose report is uninhabited).
cfg_feature! {
    "bem",
    mod report;
    pub use report::*;
}
#[cfg_attr(not(feature = "bem"), path = "off.rs")]
mod run;

use crate::output::Files;
use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};

/// The study `bem_hertz`.
pub struct BemHertz;

impl Study for BemHertz {
    const KEY: &'static str = "bem_hertz";
    type Spec = BemHertzOutput;
    type Report = run::Report;

    fn reads(_: &BemHertzOutput, _: &Inputs<'_>) -> Reads {
        Reads::NOTHING
    }

    fn run(_: &Context<'_>, h: &BemHertzOutput) -> Result<run::Report> {
        run::bem_hertz(h)
    }

    fn warnings(r: &run::Report) -> Vec<crate::warning::Warning> {
        run::warnings(r)
    }

    fn files(h: &BemHertzOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "stress_plot", h.stress_plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        h: &BemHertzOutput,
        r: &run::Report,
        _: &Context<'_>,
        dir: &Path,
        out: &mut Files,
    ) -> Result<()> {
        run::write(h, r, dir, out)
    }
}

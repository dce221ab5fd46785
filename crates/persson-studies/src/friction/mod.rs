//! `friction`: rubber friction μ and A/A0 against sliding velocity.

use persson::error::Result;

mod plot;
mod report;
mod run;
mod spec;

use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;
pub use plot::friction as figure;
pub use report::*;
pub use run::*;
pub use spec::*;

/// The study `friction`.
pub struct Friction;

impl Study for Friction {
    const KEY: &'static str = "friction";
    type Spec = FrictionOutput;
    type Report = FrictionReport;

    fn reads(_: &FrictionOutput, _: &Inputs<'_>) -> Reads {
        Reads {
            spectrum: true,
            rubber: true,
            nominal_pressure: true,
            ..Reads::NOTHING
        }
    }

    fn run(ctx: &Context<'_>, f: &FrictionOutput) -> Result<FrictionReport> {
        let rubber = ctx
            .inputs
            .rubber
            .ok_or_else(|| crate::naming::required("rubber (for outputs.friction)"))?;
        friction_named(
            ctx.spectrum()?,
            rubber,
            ctx.nominal_pressure(),
            f,
            ["spectrum.", "rubber.", "outputs.friction."],
        )
    }

    fn warnings(r: &FrictionReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(f: &FrictionOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", f.plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        f: &FrictionOutput,
        r: &FrictionReport,
        _: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        crate::study::draw(out, dir, f.plot.as_ref(), || figure(r).map(Box::new))
    }
}

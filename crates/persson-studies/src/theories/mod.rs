//! `theories`: A/A0 against load for several contact-area theories.

use persson::error::Result;

mod plot;
mod report;
mod run;
mod spec;

use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;
pub use plot::theories as figure;
pub use report::*;
pub use run::theories;
pub use spec::*;

/// The study `theories`.
pub struct Theories;

impl Study for Theories {
    const KEY: &'static str = "theories";
    type Spec = TheoriesOutput;
    type Report = TheoriesReport;

    fn reads(_: &TheoriesOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, t: &TheoriesOutput) -> Result<TheoriesReport> {
        theories(ctx.contact()?, ctx.nominal_pressure(), t)
    }

    fn warnings(r: &TheoriesReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(t: &TheoriesOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", t.plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        t: &TheoriesOutput,
        r: &TheoriesReport,
        ctx: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        crate::study::draw(out, dir, t.plot.as_ref(), || {
            let p =
                crate::study::plot_pressures(ctx.nominal_pressure(), crate::study::PLOT_POINTS)?;
            let dense = ctx.contact().and_then(|s| theories(s, &p, t));
            figure(dense.as_ref().unwrap_or(r)).map(Box::new)
        })
    }
}

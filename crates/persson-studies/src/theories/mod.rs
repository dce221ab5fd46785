//! `theories`: A/A0 against load for several contact-area theories.

use persson::error::Result;

use crate::scene::{run, TheoriesOutput, TheoriesReport};
use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;

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
        run::theories(ctx.contact()?, ctx.nominal_pressure(), t)
    }

    fn warnings(r: &TheoriesReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(t: &TheoriesOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", t.plot.as_ref())
            .into_iter()
            .collect()
    }

    #[cfg(feature = "plot")]
    fn write(
        t: &TheoriesOutput,
        r: &TheoriesReport,
        _: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        crate::study::draw(out, dir, t.plot.as_ref(), || {
            crate::scene::plot::theories(r).map(Box::new)
        })
    }
}

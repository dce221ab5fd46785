//! `area`: A/A0 against the scene's nominal pressures (the load curve).

use persson::error::Result;

mod asperity;
mod plot;
mod report;
mod run;
mod spec;

use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;
pub use plot::area as figure;
pub(crate) use report::theory_heading;
pub use report::{AreaReport, LoadPoint};
pub use run::area;
pub use spec::*;

/// The study `area`.
pub struct Area;

impl Study for Area {
    const KEY: &'static str = "area";
    type Spec = AreaOutput;
    type Report = AreaReport;

    fn reads(_: &AreaOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, a: &AreaOutput) -> Result<AreaReport> {
        area(ctx.contact()?, ctx.nominal_pressure(), a)
    }

    fn warnings(r: &AreaReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(a: &AreaOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", a.plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        a: &AreaOutput,
        r: &AreaReport,
        ctx: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        // The curve at enough pressures to look smooth, the table's own kept.
        crate::study::draw(out, dir, a.plot.as_ref(), || {
            let p =
                crate::study::plot_pressures(ctx.nominal_pressure(), crate::study::PLOT_POINTS)?;
            let dense = ctx.contact().and_then(|s| area(s, &p, a));
            figure(dense.as_ref().unwrap_or(r)).map(Box::new)
        })
    }
}

//! `magnification`: G(ζ) and A/A0 against ζ at one pressure.

use persson::error::Result;

mod plot;
mod report;
mod run;
mod spec;

use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;
pub use plot::{magnification_area, magnification_g};
pub use report::*;
pub use run::magnification;
pub use spec::*;

/// The study `magnification`.
pub struct Magnification;

impl Study for Magnification {
    const KEY: &'static str = "magnification";
    type Spec = MagnificationOutput;
    type Report = MagnificationReport;

    fn reads(_: &MagnificationOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, m: &MagnificationOutput) -> Result<MagnificationReport> {
        magnification(ctx.contact()?, m)
    }

    fn warnings(r: &MagnificationReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(m: &MagnificationOutput) -> Vec<OutFile> {
        [
            plot_file(Self::KEY, "plot", m.plot.as_ref()),
            plot_file(Self::KEY, "plot_g", m.plot_g.as_ref()),
        ]
        .into_iter()
        .flatten()
        .collect()
    }

    fn write(
        m: &MagnificationOutput,
        r: &MagnificationReport,
        ctx: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        // The curves at enough magnifications to look smooth.
        let dense = || {
            let spec = MagnificationOutput {
                zeta: Vec::new(),
                points: m.points.max(crate::study::PLOT_POINTS),
                ..m.clone()
            };
            ctx.contact().and_then(|s| magnification(s, &spec))
        };
        crate::study::draw(out, dir, m.plot.as_ref(), || {
            magnification_area(dense().as_ref().unwrap_or(r)).map(Box::new)
        })?;
        crate::study::draw(out, dir, m.plot_g.as_ref(), || {
            magnification_g(dense().as_ref().unwrap_or(r)).map(Box::new)
        })
    }
}

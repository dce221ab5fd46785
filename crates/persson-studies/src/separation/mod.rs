//! `separation`: the mean interfacial separation, the contact stiffness and
//! the elastic energy against load (Persson, Phys. Rev. Lett. 99, 125502 (2007)).

use persson::error::Result;

mod plot;
mod report;
mod run;
mod spec;

use crate::study::{
    draw, plot_file, plot_pressures, Context, Inputs, OutFile, Reads, Study, PLOT_POINTS,
};
use crate::warning::Warning;
pub use plot::separation as figure;
pub use report::*;
pub use run::separation;
pub use spec::*;

/// The study `separation`.
pub struct Separation;

impl Study for Separation {
    const KEY: &'static str = "separation";
    type Spec = SeparationOutput;
    type Report = SeparationReport;

    fn reads(_: &SeparationOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, s: &SeparationOutput) -> Result<SeparationReport> {
        separation(ctx.contact()?, ctx.nominal_pressure(), s, &[])
    }

    fn warnings(r: &SeparationReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(s: &SeparationOutput) -> Vec<OutFile> {
        let plot = plot_file(Self::KEY, "plot", s.plot.as_ref());
        let area = plot_file(Self::KEY, "plot_area", s.plot_area.as_ref());
        plot.into_iter().chain(area).collect()
    }

    /// The figures on `plot_points` pressures through the given ones.
    fn write(
        s: &SeparationOutput,
        _: &SeparationReport,
        ctx: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        let curve = || plot_pressures(ctx.nominal_pressure(), s.plot_points.unwrap_or(PLOT_POINTS));
        draw(out, dir, s.plot.as_ref(), || {
            let dense = separation(ctx.contact()?, ctx.nominal_pressure(), s, &curve()?)?;
            figure(&dense).map(Box::new)
        })?;
        draw(out, dir, s.plot_area.as_ref(), || {
            let all = crate::theories::TheoriesOutput::default();
            let theories = crate::theories::theories(ctx.contact()?, &curve()?, &all)?;
            crate::theories::figure(&theories).map(Box::new)
        })
    }
}

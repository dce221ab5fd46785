//! `conductance`: thermal and electrical contact conductance against load,
//! the theory and (feature `flow`) the FFT-BEM.

use persson::error::Result;

use super::run as transport;
use super::{ConductanceOutput, ConductanceReport};
use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;

/// The study `conductance`.
pub struct Conductance;

impl Study for Conductance {
    const KEY: &'static str = "conductance";
    type Spec = ConductanceOutput;
    type Report = ConductanceReport;

    fn reads(_: &ConductanceOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, c: &ConductanceOutput) -> Result<ConductanceReport> {
        transport::conductance(ctx.contact()?, ctx.nominal_pressure(), c)
    }

    fn warnings(r: &ConductanceReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(c: &ConductanceOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", c.plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        c: &ConductanceOutput,
        r: &ConductanceReport,
        ctx: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        // The theory's curve at enough pressures to look smooth (the BEM's
        // points, a solve each, as computed).
        crate::study::draw(out, dir, c.plot.as_ref(), || {
            let p =
                crate::study::plot_pressures(ctx.nominal_pressure(), crate::study::PLOT_POINTS)?;
            let theory = ConductanceOutput {
                bem: None,
                ..c.clone()
            };
            let dense = ctx
                .contact()
                .and_then(|s| transport::conductance(s, &p, &theory));
            let mut dense = dense.unwrap_or_else(|_| r.clone());
            dense.bem.clone_from(&r.bem);
            super::conductance_figure(&dense).map(Box::new)
        })
    }
}

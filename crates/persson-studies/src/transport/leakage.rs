//! `leakage`: the leak rate of a static seal against load: the critical
//! junction, the effective medium and (feature `flow`) Reynolds flow on the
//! FFT-BEM's gap.

use persson::error::Result;

use super::run as transport;
use super::{LeakageOutput, LeakageReport};
use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;

/// The study `leakage`.
pub struct Leakage;

impl Study for Leakage {
    const KEY: &'static str = "leakage";
    type Spec = LeakageOutput;
    type Report = LeakageReport;

    fn reads(_: &LeakageOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, l: &LeakageOutput) -> Result<LeakageReport> {
        transport::leakage(ctx.contact()?, ctx.nominal_pressure(), l)
    }

    fn warnings(r: &LeakageReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(l: &LeakageOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", l.plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        l: &LeakageOutput,
        r: &LeakageReport,
        ctx: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        // The theory's curve at enough pressures to look smooth (the BEM's
        // points, a solve each, as computed).
        crate::study::draw(out, dir, l.plot.as_ref(), || {
            let p =
                crate::study::plot_pressures(ctx.nominal_pressure(), crate::study::PLOT_POINTS)?;
            let theory = LeakageOutput {
                bem: None,
                ..l.clone()
            };
            let dense = ctx
                .contact()
                .and_then(|s| transport::leakage(s, &p, &theory));
            let mut dense = dense.unwrap_or_else(|_| r.clone());
            dense.bem.clone_from(&r.bem);
            super::leakage_figure(&dense).map(Box::new)
        })
    }
}

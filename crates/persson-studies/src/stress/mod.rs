//! `stress`: the stress distributions P(σ, ζ), dimensionless at given G or
//! in the pressure unit at given magnifications.

use persson::error::Result;
use persson::stress::Start;

mod plot;
mod report;
mod run;
mod spec;

use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;
pub use plot::stress as figure;
pub use report::*;
pub use run::{stress_dimensionless, stress_physical};
pub use spec::*;

/// The study `stress`.
pub struct Stress;

impl Study for Stress {
    const KEY: &'static str = "stress";
    type Spec = StressOutput;
    type Report = StressReport;

    fn reads(st: &StressOutput, _: &Inputs<'_>) -> Reads {
        if st.zeta.is_empty() {
            Reads::NOTHING
        } else {
            Reads::CONTACT
        }
    }

    fn run(ctx: &Context<'_>, st: &StressOutput) -> Result<StressReport> {
        if st.zeta.is_empty() {
            st.check_mode()?;
            stress_dimensionless(
                &Start::from(st.start),
                &st.g,
                st.yield_ratio,
                st.tolerance,
                &[],
                st.points,
            )
        } else {
            stress_physical(ctx.contact()?, st)
        }
    }

    fn warnings(r: &StressReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(st: &StressOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", st.plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        st: &StressOutput,
        r: &StressReport,
        _: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        crate::study::draw(out, dir, st.plot.as_ref(), || figure(r).map(Box::new))
    }
}

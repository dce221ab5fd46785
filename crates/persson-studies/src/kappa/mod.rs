//! `kappa`: κ of the linear low-load law of Bush and of Persson; with a
//! spectrum, a material and pressures, the linear contact fractions.

use persson::error::Result;

mod report;
mod run;
mod spec;

use crate::study::{Context, Inputs, Reads, Study};
use crate::warning::Warning;
pub use report::*;
pub use run::kappa;
pub use spec::*;

/// The study `kappa`.
pub struct Kappa;

impl Study for Kappa {
    const KEY: &'static str = "kappa";
    type Spec = KappaOutput;
    type Report = KappaReport;

    fn reads(_: &KappaOutput, scene: &Inputs<'_>) -> Reads {
        if scene.spectrum.is_some() && !scene.nominal_pressure.is_empty() {
            Reads::CONTACT
        } else {
            Reads::NOTHING
        }
    }

    fn run(ctx: &Context<'_>, _: &KappaOutput) -> Result<KappaReport> {
        let with = ctx.contact().ok().map(|s| (s, ctx.nominal_pressure()));
        kappa(with)
    }

    fn warnings(r: &KappaReport) -> Vec<Warning> {
        r.warnings.clone()
    }
}

//! `adhesion`: the stickiness energy balance and A/A0 against the scene's
//! nominal pressures (which may be ≤ 0) with the pull-off stress.

use persson::error::Result;

mod report;
mod run;
mod spec;

use crate::study::{Context, Inputs, Reads, Study};
use crate::warning::Warning;
pub use report::*;
pub use run::{adhesion, DEFAULT_STICKINESS_POINTS, DEFAULT_TOLERANCE};
pub use spec::*;

/// The study `adhesion`.
pub struct Adhesion;

impl Study for Adhesion {
    const KEY: &'static str = "adhesion";
    type Spec = AdhesionOutput;
    type Report = AdhesionReport;

    fn reads(_: &AdhesionOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, a: &AdhesionOutput) -> Result<AdhesionReport> {
        adhesion(ctx.contact()?, ctx.nominal_pressure(), a)
    }

    fn warnings(r: &AdhesionReport) -> Vec<Warning> {
        r.warnings.clone()
    }
}

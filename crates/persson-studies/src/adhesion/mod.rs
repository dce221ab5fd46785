//! `adhesion`: the stickiness energy balance and A/A0 against the scene's
//! nominal pressures (which may be ≤ 0) with the pull-off stress.

use persson::error::Result;

use crate::scene::{run, AdhesionOutput, AdhesionReport};
use crate::study::{Context, Inputs, Reads, Study};
use crate::warning::Warning;

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
        run::adhesion(ctx.contact()?, ctx.nominal_pressure(), a)
    }

    fn warnings(r: &AdhesionReport) -> Vec<Warning> {
        r.warnings.clone()
    }
}

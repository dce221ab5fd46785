//! `separation`: the mean interfacial separation, the contact stiffness and
//! the elastic energy against load (Persson, Phys. Rev. Lett. 99, 125502 (2007)).

use persson::error::Result;

use crate::scene::{run, SeparationOutput, SeparationReport};
use crate::study::{Context, Inputs, Reads, Study};
use crate::warning::Warning;

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
        run::separation(ctx.contact()?, ctx.nominal_pressure(), s, &[])
    }

    fn warnings(r: &SeparationReport) -> Vec<Warning> {
        r.warnings.clone()
    }
}

//! `separation`: the mean interfacial separation, the contact stiffness and
//! the elastic energy against load (Persson, Phys. Rev. Lett. 99, 125502 (2007)).

use persson::error::Result;

mod plot;
mod report;
mod run;
mod spec;

use crate::study::{Context, Inputs, Reads, Study};
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
}

//! `bem_hertz`: the FFT-BEM's Hertz convergence table, η per grid.

use persson::error::Result;

mod report;
#[cfg_attr(not(feature = "bem"), path = "off.rs")]
mod run;
mod spec;

use crate::study::{Context, Inputs, Reads, Study};
pub use report::*;
pub use spec::*;

/// The study `bem_hertz`.
pub struct BemHertz;

impl Study for BemHertz {
    const KEY: &'static str = "bem_hertz";
    type Spec = BemHertzOutput;
    type Report = BemHertzReport;

    fn reads(_: &BemHertzOutput, _: &Inputs<'_>) -> Reads {
        Reads::NOTHING
    }

    fn run(_: &Context<'_>, h: &BemHertzOutput) -> Result<BemHertzReport> {
        hertz(h)
    }
}

use run::bem_hertz as hertz;

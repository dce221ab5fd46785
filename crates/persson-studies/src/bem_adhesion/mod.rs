//! `bem_adhesion`: the adhesive FFT-BEM along a path of mean gaps or
//! approaches (`bem rough --work-of-adhesion`).

use persson::error::Result;

#[cfg_attr(not(feature = "bem"), path = "off.rs")]
mod run;
mod spec;

use crate::study::{Context, Inputs, Reads, Study};
pub use spec::*;

/// The study `bem_adhesion`.
pub struct BemAdhesion;

impl Study for BemAdhesion {
    const KEY: &'static str = "bem_adhesion";
    type Spec = BemAdhesionOutput;
    type Report = run::Report;

    fn reads(_: &BemAdhesionOutput, _: &Inputs<'_>) -> Reads {
        Reads {
            spectrum: true,
            material: true,
            ..Reads::NOTHING
        }
    }

    fn run(ctx: &Context<'_>, a: &BemAdhesionOutput) -> Result<Self::Report> {
        run::bem_adhesion(ctx, a)
    }

    fn warnings(r: &Self::Report) -> Vec<crate::warning::Warning> {
        run::warnings(r)
    }
}

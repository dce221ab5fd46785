//! `bem_adhesion`: the adhesive FFT-BEM along a path of mean gaps or
//! approaches (`bem rough --work-of-adhesion`).

use persson::error::Result;

#[cfg(feature = "bem")]
mod run;
mod spec;

use crate::study::{Context, Inputs, Reads, Study};
pub use spec::*;

/// The study `bem_adhesion`.
pub struct BemAdhesion;

#[cfg(feature = "bem")]
impl Study for BemAdhesion {
    const KEY: &'static str = "bem_adhesion";
    type Spec = BemAdhesionOutput;
    type Report = crate::bem_detail::AdhesiveBemReport;

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
        crate::bem_detail::adhesive_warnings(r)
    }
}

#[cfg(not(feature = "bem"))]
impl Study for BemAdhesion {
    const KEY: &'static str = "bem_adhesion";
    type Spec = BemAdhesionOutput;
    type Report = crate::study::Unavailable;

    fn reads(_: &BemAdhesionOutput, _: &Inputs<'_>) -> Reads {
        Reads::NOTHING
    }

    fn run(_: &Context<'_>, _: &BemAdhesionOutput) -> Result<Self::Report> {
        Err(crate::study::unavailable(Self::KEY, "bem"))
    }
}

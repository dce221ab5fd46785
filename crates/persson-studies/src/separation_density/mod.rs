//! `separation_density`: P(u), the distribution of interfacial separations
//! (Almqvist, Campañá, Prodanov & Persson, J. Mech. Phys. Solids 59, 2355 (2011)).

use persson::error::Result;

mod density;
mod spec;

use crate::study::{Context, Inputs, Reads, Study};
use crate::warning::Warning;
pub use density::*;
pub use spec::*;

/// The study `separation_density`.
pub struct SeparationDensity;

impl Study for SeparationDensity {
    const KEY: &'static str = "separation_density";
    type Spec = SeparationDensityOutput;
    type Report = SeparationDensityReport;

    fn reads(_: &SeparationDensityOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, d: &SeparationDensityOutput) -> Result<SeparationDensityReport> {
        separation_density(
            ctx.contact()?,
            ctx.nominal_pressure(),
            d.density_points.unwrap_or(101),
            d.tolerance
                .unwrap_or(persson::separation::DEFAULT_TOLERANCE),
        )
    }

    fn warnings(r: &SeparationDensityReport) -> Vec<Warning> {
        r.warnings.clone()
    }
}

//! The adhesive FFT-BEM along a path (feature `bem`).

use persson::error::{check, Error, Result};

use super::spec::BemAdhesionOutput;
use crate::bem::solve::bem_surface;
use crate::naming::prefix;
use persson::names::Boundary;

pub use crate::bem_detail::{adhesive_warnings as warnings, AdhesiveBemReport as Report};

/// `outputs.bem_adhesion`: the adhesive FFT-BEM along the scene's path of
/// mean gaps (or approaches), on the scene's surface
/// ([`crate::bem_detail::adhesive_controlled_path`], the loop of `persson bem
/// rough --work-of-adhesion`).
///
/// # Errors
/// Missing or invalid inputs (named `outputs.bem_adhesion.…`); neither or
/// both of `mean_gap` and `approach`; `mean_gap` on the free boundary; a
/// solve that fails.
pub fn bem_adhesion(
    ctx: &crate::study::Context<'_>,
    a: &BemAdhesionOutput,
) -> Result<crate::bem_detail::AdhesiveBemReport> {
    use crate::bem_detail::{adhesive_controlled_path, PathControl};
    let named = |e: Error| prefix("outputs.bem_adhesion.", e);
    let boundary = a.boundary.unwrap_or(Boundary::Periodic);
    let tol = check::tolerance("tolerance", a.tolerance.unwrap_or(1e-10)).map_err(named)?;
    let control = PathControl::new(&a.mean_gap, &a.approach, boundary).map_err(named)?;
    let e_star = ctx.build_material()?.contact_modulus();
    let surf = bem_surface(ctx, ("outputs.bem_adhesion.", a.grid, a.seed), boundary)?;
    // The command line's and Python's default, not the library's 20 000:
    // every front-end stops a path at the same iteration.
    let options = persson::bem::adhesive::AdhesiveOptions {
        tolerance: tol,
        max_iterations: a
            .max_iterations
            .unwrap_or(persson::bem::Options::default().max_iterations),
    };
    adhesive_controlled_path(
        &surf.heights,
        (surf.n, surf.size, e_star),
        boundary,
        (
            a.adhesion.unwrap_or_default(),
            a.work_of_adhesion,
            a.adhesion_range,
        ),
        control,
        &options,
        a.adhesive_iteration.unwrap_or_default(),
    )
    .map_err(named)
}

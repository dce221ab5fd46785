//! The solves of `bem` (feature `bem`): the rigid surface, one solve per
//! pressure, and the patch and stress studies of the solves.

use persson::bem::patches::PatchOptions;
use persson::bem::rough::{self, RoughOptions, RoughReport, SurfaceOrigin};
use persson::bem::{check_memory, surface, Options};
use persson::error::{check, Error, Result};

use super::spec::{BemOutput, PatchesOutput, SubsurfaceOutput};
use crate::bem_detail::{Details, SubsurfaceOptions, DEFAULT_POISSON};
use crate::input::SpectrumSpec;
use crate::naming::prefix;
use crate::naming::required;
use persson::names::Boundary;

/// The rigid surface of a BEM output (`section`, e.g. `outputs.bem.`): the
/// height map, or synthesised from the spectrum on `grid` nodes with `seed`.
pub(crate) fn bem_surface(
    ctx: &crate::study::Context<'_>,
    (section, grid, seed): (&str, Option<usize>, Option<u64>),
    boundary: persson::bem::Boundary,
) -> Result<surface::GridSurface> {
    let named = |e: Error| prefix(section, e);
    if let Some(SpectrumSpec::HeightMap(m)) = ctx.inputs.spectrum {
        if grid.is_some() || seed.is_some() {
            return Err(Error::Inconsistent {
                name: format!("{section}grid / {section}seed"),
                requirement: "not used with a height map (its file sets the grid)".into(),
            });
        }
        return m.bem_surface(boundary).map_err(|e| match e {
            Error::InvalidParameter {
                name,
                value,
                requirement,
            } if name == "size" => Error::InvalidParameter {
                name: "spectrum.size".into(),
                value,
                requirement,
            },
            e => e,
        });
    }
    let n = grid.ok_or_else(|| required(&format!("{section}grid (for a synthesised surface)")))?;
    check_memory(n, boundary).map_err(named)?;
    let spectrum = ctx.build_spectrum()?;
    let size = std::f64::consts::TAU / spectrum.q_min();
    surface::synthesize(spectrum.as_ref(), n, size, seed.unwrap_or(1)).map_err(named)
}

/// `outputs.bem`: one solve per pressure, warm-started along the list
/// ([`rough::rough_contact`], the loop `persson bem rough` runs).
///
/// # Errors
/// Missing or invalid inputs; a solve that fails.
pub fn bem_rough(ctx: &crate::study::Context<'_>, b: &BemOutput) -> Result<(RoughReport, Details)> {
    let named = |e: Error| prefix("outputs.bem.", e);
    let boundary = b.boundary.unwrap_or(Boundary::Periodic);
    let tol = check::tolerance("tolerance", b.tolerance.unwrap_or(1e-10)).map_err(named)?;
    let bins = crate::validation::check_bins(b.bins.unwrap_or(crate::validation::DEFAULT_BINS))
        .map_err(named)?;
    if ctx.nominal_pressure().is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.bem)",
        ));
    }
    let e_star = ctx.build_material()?.contact_modulus();
    let surf = bem_surface(ctx, ("outputs.bem.", b.grid, b.seed), boundary)?;
    let source = match ctx.inputs.spectrum {
        Some(SpectrumSpec::HeightMap(m)) => SurfaceOrigin::height_map(&m.file),
        _ => SurfaceOrigin::synthesised(ctx.build_spectrum()?.as_ref(), b.seed.unwrap_or(1))?,
    };
    let options = RoughOptions {
        boundary,
        solver: Options {
            tolerance: tol,
            max_iterations: b
                .max_iterations
                .unwrap_or(Options::default().max_iterations),
            warm_start: true,
            yield_stress: b.yield_stress,
        },
        bins: b.histogram.as_ref().map(|_| bins),
        ..RoughOptions::default()
    };
    let mut details = details(ctx, b, (surf.n, surf.size, boundary))?;
    // The pressure map is kept only for its figure.
    let solve = if b.pressure_plot.is_some() {
        rough::rough_contact_mapped
    } else {
        rough::rough_contact
    };
    let report = solve(
        &surf,
        source,
        e_star,
        ctx.nominal_pressure(),
        &options,
        &mut details,
    )
    .map_err(named)?;
    Ok((report, details))
}

/// The patch study's options of `outputs.bem.patches` (`bem rough --patches`)
/// on a grid with `boundary`: four neighbours and 5 bins per decade by default.
pub fn patch_options(p: &PatchesOutput, boundary: persson::bem::Boundary) -> PatchOptions {
    PatchOptions {
        connectivity: p.connectivity.unwrap_or_default(),
        boundary,
        bins_per_decade: p.bins_per_decade.unwrap_or(5),
    }
}

/// The stress study's options of `outputs.bem.subsurface` (`bem rough
/// --subsurface`) for Poisson ratio `poisson`; the planes' maps are kept for
/// the `.npy` files and the maps drawn beside the plot.
pub fn subsurface_options(s: &SubsurfaceOutput, poisson: f64) -> SubsurfaceOptions {
    SubsurfaceOptions {
        depth: s.depth.clone(),
        poisson,
        tensile_yield_stress: s.tensile_yield_stress,
        keep_maps: s.stress_field.is_some() || s.plot.is_some(),
    }
}

/// The patch and stress studies of `outputs.bem.patches` and
/// `outputs.bem.subsurface` (ν from the scene's material, else 0.3).
///
/// # Errors
/// `bins_per_decade` 0; a depth out of (0, L] (named
/// `outputs.bem.subsurface.depth`).
fn details(
    ctx: &crate::study::Context<'_>,
    b: &BemOutput,
    grid: (usize, f64, persson::bem::Boundary),
) -> Result<Details> {
    let patches = b.patches.as_ref().map(|p| patch_options(p, grid.2));
    let poisson = ctx.inputs.material.and_then(|m| m.poisson);
    let subsurface = b
        .subsurface
        .as_ref()
        .map(|s| subsurface_options(s, poisson.unwrap_or(DEFAULT_POISSON)));
    Details::new(grid, ctx.nominal_pressure(), patches, subsurface).map_err(|e| {
        let patches = matches!(
            &e,
            Error::InvalidParameter { name, .. } if name == "bins_per_decade"
        );
        prefix(
            if patches {
                "outputs.bem.patches."
            } else {
                "outputs.bem.subsurface."
            },
            e,
        )
    })
}

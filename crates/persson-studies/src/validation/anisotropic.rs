//! The anisotropy in [`super::compare`]: an anisotropic spectrum's Peklenik
//! number and lay beside those of the surfaces the BEM solved on.
//!
//! # What it reports
//! On an anisotropic spectrum (`--anisotropy γ`, a scene's `stretched` kind,
//! a sum with a stretched part) the theories use the angular average C̄ of
//! the compared (band-limited) spectrum, which is the whole of Persson's G on
//! an anisotropic spectrum (Carbone, Lorenz, Persson & Wohlers, Eur. Phys. J.
//! E 29, 275 (2009), doi:10.1140/epje/i2009-10484-8); the BEM solves on
//! surfaces synthesised from the plane. So that a reader can see the surfaces
//! are the anisotropic ones, the report gives the slope tensor's Peklenik
//! number and lay of the spectrum and of each seed's finest surface:
//! ```text
//! M = ∫ d²q q qᵀ C(q)  (spectrum),   M = Σ_q q qᵀ |h_q|²  (surface)
//! γ = √(λ₁/λ₂),  lay = eigenvector of λ₂
//! ```
//! ([`persson::spectrum::anisotropic::SlopeTensor`]). An isotropic spectrum
//! reports nothing here.

use serde::Serialize;

use crate::table::{Cell, Table};
use persson::bem::surface::synthesize;
use persson::error::Result;
use persson::spectrum::anisotropic::slope_tensor_2d;
use persson::spectrum::Spectrum;

/// The anisotropy of the compared spectrum and of the BEM's surfaces.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ComparedAnisotropy {
    /// Peklenik number of the compared (band-limited) 2-D spectrum, ≥ 1.
    pub peklenik_number: f64,
    /// Its lay (direction of slowest variation), degrees in [0, 180) from x.
    pub principal_direction: f64,
    /// Grid side of the surfaces below (the finest).
    pub grid: usize,
    /// Peklenik number of each seed's surface on the finest grid.
    pub surface_peklenik_number: Vec<f64>,
    /// Lay of each seed's surface on the finest grid, degrees in [0, 180).
    pub surface_principal_direction: Vec<f64>,
}

/// The anisotropy of `band` and of the surfaces the sweep synthesises from
/// it (`synthesize(band, grid, size, seed)`, the finest of the nested
/// surfaces); `None` for an isotropic spectrum.
///
/// # Errors
/// A quadrature that does not converge; a surface that does not vary in
/// some direction (`peklenik_number`).
pub(crate) fn compared_anisotropy(
    band: &dyn Spectrum,
    grid: usize,
    size: f64,
    seeds: &[u64],
) -> Result<Option<ComparedAnisotropy>> {
    let Some(plane) = band.as_2d() else {
        return Ok(None);
    };
    let (peklenik_number, principal_direction) = slope_tensor_2d(plane)?.principal()?;
    let (mut p, mut d) = (Vec::new(), Vec::new());
    for &seed in seeds {
        let (a, b) = synthesize(band, grid, size, seed)?
            .slope_tensor()?
            .principal()?;
        p.push(a);
        d.push(b);
    }
    Ok(Some(ComparedAnisotropy {
        peklenik_number,
        principal_direction,
        grid,
        surface_peklenik_number: p,
        surface_principal_direction: d,
    }))
}

/// The table `anisotropy` of a comparison.
pub(crate) fn anisotropy_table(a: &ComparedAnisotropy, seeds: &[u64]) -> Table {
    let mut t = Table::new(
        "anisotropy",
        "Anisotropy: the theories use the angular average C̄ (Carbone, Lorenz, Persson & \
         Wohlers 2009), the BEM the plane; Peklenik number and lay of the slope tensor",
    )
    .scalar("peklenik_number", "spectrum: Peklenik γ", a.peklenik_number)
    .scalar(
        "principal_direction",
        "spectrum: lay (deg from x)",
        a.principal_direction,
    )
    .column("seed", "seed")
    .column("grid", "N")
    .column("surface_peklenik_number", "Peklenik γ")
    .column("surface_principal_direction", "lay (deg)");
    for ((&s, &p), &d) in seeds
        .iter()
        .zip(&a.surface_peklenik_number)
        .zip(&a.surface_principal_direction)
    {
        t.push(vec![Cell::from(s), Cell::from(a.grid), p.into(), d.into()]);
    }
    t
}

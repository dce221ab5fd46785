//! The von Mises stress on the vertical section through the axis of a BEM
//! Hertz contact (`bem hertz --subsurface --stress-plot`).
//!
//! # Method
//! The stress of [`persson::bem::subsurface`] on [`SECTION_DEPTHS`] planes
//! z_k = (k + ½)·2a/K, k < K, of the solved pressure, each plane's row
//! through the axis node (N/2, N/2) kept over the columns within
//! [`SECTION_HALF_WIDTH`] contact radii of the axis. Values are σ_vM/p0; the
//! column at the axis is the axis profile of [`super::hertz_subsurface`]
//! (Johnson's maximum of τ at z ≈ 0.48 a, σ_vM ≈ 0.62 p0 for ν = 0.3).

use persson::bem::subsurface::Subsurface;
use persson::error::Result;

use super::HertzSubsurface;

/// Planes of the section, from the surface to 2a.
pub const SECTION_DEPTHS: usize = 32;

/// Half-width of the section in contact radii.
pub const SECTION_HALF_WIDTH: f64 = 3.0;

/// σ_vM/p0 on the vertical section through the axis.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct VerticalSection {
    /// Positions across the section (columns).
    pub columns: usize,
    /// Depths (rows, from the top).
    pub depths: usize,
    /// Horizontal range of the cell edges, in units of a (axis at 0).
    pub offset_range: (f64, f64),
    /// Depth range of the cell edges, in units of a.
    pub depth_range: (f64, f64),
    /// σ_vM/p0, row-major (depth rows, offset columns).
    pub von_mises_stress: Vec<f64>,
}

/// The vertical section of the solved Hertz contact `r` (module docs).
///
/// # Errors
/// As [`Subsurface::new`] and [`Subsurface::plane`] (a depth 2a beyond the
/// side L).
pub fn hertz_section(r: &HertzSubsurface) -> Result<VerticalSection> {
    let n = r.grid;
    let a = r.hertz_contact_radius;
    let mut s = Subsurface::new(&r.pressure, n, r.size, r.boundary, r.poisson)?;
    let dx = r.size / n as f64;
    let axis = n / 2;
    let reach = ((SECTION_HALF_WIDTH * a / dx).floor() as usize).min(axis);
    let first = axis - reach;
    let last = (axis + reach).min(n - 1);
    let columns = last - first + 1;
    let dz = 2.0 * a / SECTION_DEPTHS as f64;
    let mut values = Vec::with_capacity(columns * SECTION_DEPTHS);
    for k in 0..SECTION_DEPTHS {
        let plane = s.plane((k as f64 + 0.5) * dz)?;
        let row = &plane.von_mises_stress[axis * n..(axis + 1) * n];
        values.extend(row[first..=last].iter().map(|v| v / r.hertz_peak_pressure));
    }
    let edge = |j: usize| (j as f64 - axis as f64 - 0.5) * dx / a;
    Ok(VerticalSection {
        columns,
        depths: SECTION_DEPTHS,
        offset_range: (edge(first), edge(last + 1)),
        depth_range: (0.0, 2.0),
        von_mises_stress: values,
    })
}

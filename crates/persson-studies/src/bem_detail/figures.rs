//! The study's figures: the von Mises maps of its planes and the vertical
//! section below a Hertz contact (drawn by [`crate::plot::stress_map`]).

use crate::plot::map::tick;
use crate::plot::stress_map::{vertical_section, von_mises_plane, FieldFigure};

use super::{indexed, HertzSubsurface, StressMap, VerticalSection};

/// The figure of every kept von Mises map (`maps`, from
/// [`super::Details::maps`]), each with its file: `path` with
/// `_k_j` added before the extension (solve k, depth j, as the `.npy` of
/// `stress_field`); `depths` and `pressures` are the study's.
pub fn planes(
    maps: &[StressMap],
    (n, size): (usize, f64),
    depths: &[f64],
    pressures: &[f64],
    pressure_unit: &str,
    path: &std::path::Path,
) -> Vec<(std::path::PathBuf, FieldFigure)> {
    maps.iter()
        .map(|m| {
            let depth = depths.get(m.depth_index).copied().unwrap_or(f64::NAN);
            let sigma0 = pressures.get(m.index).copied().unwrap_or(f64::NAN);
            let fig = von_mises_plane(&m.von_mises_stress, n, size, depth, sigma0, pressure_unit);
            (indexed(path, m.index, m.depth_index), fig)
        })
        .collect()
}

/// The figure of the vertical section through a Hertz contact's axis.
pub fn hertz_section_figure(r: &HertzSubsurface, s: &VerticalSection) -> FieldFigure {
    vertical_section(
        format!(
            "Von Mises stress below the Hertz contact (FFT-BEM, {} boundary, N = {}, ν = {})",
            r.boundary.name(),
            r.grid,
            tick(r.poisson)
        ),
        ("distance from the axis / a", "depth z / a", "σ_vM / p0"),
        s.von_mises_stress.clone(),
        (s.columns, s.depths),
        s.offset_range,
        s.depth_range,
    )
}

//! Height maps given as arrays or as SurfaceTopography objects: the map
//! as a `Topography` (its sides from the pixel size), its analysis with the
//! CLI's options, and `persson.analyse_height_map`.

use persson::names::{Detrend, Window};
use persson::topography::{self as topo, AnalysisOptions, Topography};
use pyo3::prelude::*;

use crate::arrays::{floats, map};
use crate::convert::{err, name, to_dict, value_error};

pub(crate) fn heights_topography(
    heights: &Bound<'_, PyAny>,
    sides: impl FnOnce([usize; 2]) -> PyResult<(f64, f64)>,
    periodic: bool,
) -> PyResult<Topography> {
    let a = floats("heights", heights)?;
    if a.as_array().ndim() == 1 {
        let v = a.as_array();
        let nx = v.len();
        let (lx, _) = sides([1, nx])?;
        let h: Vec<f64> = v.iter().copied().collect();
        return Topography::line_scans(nx, 1, lx, h, periodic).map_err(err);
    }
    let ([ny, nx], values) = map("heights", &a)?;
    let (lx, ly) = sides([ny, nx])?;
    Topography::map(nx, ny, lx, ly, values.to_vec(), periodic).map_err(err)
}

fn pixel_sides(pixel_size: &Bound<'_, PyAny>) -> PyResult<(f64, Option<f64>)> {
    let d = crate::arrays::float_list("pixel_size", pixel_size)?;
    match d[..] {
        [dx] => Ok((dx, None)),
        [dx, dy] => Ok((dx, Some(dy))),
        _ => Err(value_error(format!(
            "pixel_size: {} values, expected Δ or (Δx, Δy)",
            d.len()
        ))),
    }
}

pub(crate) fn analysis(
    t: &Topography,
    detrend: Option<&str>,
    window: Option<&str>,
    q_max: Option<f64>,
) -> PyResult<topo::Analysis> {
    let detrend: Option<Detrend> = detrend.map(|d| name("detrend", d)).transpose()?;
    let window: Option<Window> = window.map(|w| name("window", w)).transpose()?;
    let options = AnalysisOptions {
        detrend,
        window,
        q_max,
        bins: None,
    };
    topo::analyse(t, &options).map_err(err)
}

/// The map's sides from its pixel size, as the file readers compute them
/// (Lx = nx·Δx, Ly = ny·Δy).
pub(crate) fn sides_from_pixel(
    pixel_size: &Bound<'_, PyAny>,
) -> PyResult<impl FnOnce([usize; 2]) -> PyResult<(f64, f64)>> {
    let (dx, dy) = pixel_sides(pixel_size)?;
    persson::error::check::positive("pixel_size", dx).map_err(err)?;
    if let Some(dy) = dy {
        persson::error::check::positive("pixel_size", dy).map_err(err)?;
    }
    Ok(move |[ny, nx]: [usize; 2]| Ok((nx as f64 * dx, ny as f64 * dy.unwrap_or(dx))))
}

/// `persson spectrum --surface FILE --json` for a height map given as an
/// array: shape, pixel size, real-space and spectral rms values, the Hurst
/// fit and the binned spectrum `psd` (Persson's normalisation).
#[pyfunction]
#[pyo3(signature = (heights, pixel_size, *, periodic=false, detrend=None, window=None, q_max=None))]
pub fn analyse_height_map<'py>(
    py: Python<'py>,
    heights: &Bound<'py, PyAny>,
    pixel_size: &Bound<'py, PyAny>,
    periodic: bool,
    detrend: Option<&str>,
    window: Option<&str>,
    q_max: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let t = heights_topography(heights, sides_from_pixel(pixel_size)?, periodic)?;
    let a = py.detach(|| analysis(&t, detrend, window, q_max))?;
    to_dict(py, &a)
}

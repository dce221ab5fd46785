//! `persson.anisotropy` and `persson.spectrum_2d`: the anisotropy statistics
//! and the 2-D spectrum of a height map given as an array
//! ([`persson::topography::anisotropy`], as `persson anisotropy --json`).

use numpy::IntoPyArray;
use persson::names::{Detrend, Window};
use persson::topography::{self as topo, Conditioning, Topography};
use pyo3::prelude::*;

use crate::arrays::{float_list, floats, map};
use crate::convert::{err, name, to_dict_warned, value_error};

/// A map from `heights` (ny × nx, a row along x) of physical size `size`:
/// L (square pixels: Ly = L·ny/nx) or (Lx, Ly), in m, as `--size`.
fn topography(
    heights: &Bound<'_, PyAny>,
    size: &Bound<'_, PyAny>,
    periodic: bool,
) -> PyResult<Topography> {
    let a = floats("heights", heights)?;
    let ([ny, nx], values) = map("heights", &a)?;
    let (lx, ly) = match float_list("size", size)?[..] {
        [l] => (l, l * ny as f64 / nx as f64),
        [lx, ly] => (lx, ly),
        ref v => {
            return Err(value_error(format!(
                "size: {} values, expected L or (Lx, Ly)",
                v.len()
            )))
        }
    };
    persson::error::check::positive("size", lx).map_err(err)?;
    persson::error::check::positive("size", ly).map_err(err)?;
    Topography::map(nx, ny, lx, ly, values.to_vec(), periodic).map_err(err)
}

/// The CLI's conditioning: the map's defaults (none for a periodic map,
/// plane and Hann otherwise) unless `detrend`/`window` are given.
fn conditioning(
    t: &Topography,
    detrend: Option<&str>,
    window: Option<&str>,
) -> PyResult<Conditioning> {
    let d = Conditioning::for_topography(t);
    let detrend: Option<Detrend> = detrend.map(|v| name("detrend", v)).transpose()?;
    let window: Option<Window> = window.map(|v| name("window", v)).transpose()?;
    Ok(Conditioning {
        detrend: detrend.unwrap_or(d.detrend),
        window: window.unwrap_or(d.window),
    })
}

/// `persson anisotropy --surface FILE --json` for an array: the Peklenik
/// number and its principal direction, Str, Sal and Std (ISO 25178-2).
#[pyfunction]
#[pyo3(signature = (heights, size, *, periodic=false, detrend=None, window=None))]
pub fn anisotropy<'py>(
    py: Python<'py>,
    heights: &Bound<'py, PyAny>,
    size: &Bound<'py, PyAny>,
    periodic: bool,
    detrend: Option<&str>,
    window: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    let t = topography(heights, size, periodic)?;
    let c = conditioning(&t, detrend, window)?;
    let report = py.detach(|| topo::anisotropy(&t, c)).map_err(err)?;
    // The CLI's --json carries an (empty) warnings list: so does the dict.
    to_dict_warned(py, &report, &[])
}

/// The 2-D spectrum of a map as `(qx, qy, c)`: q_x (nx) and q_y (ny) in 1/m,
/// increasing with q = 0 at index n/2, and C (ny × nx, m⁴) in Persson's
/// normalisation; what `persson anisotropy --spectrum-2d FILE.npy` writes.
#[pyfunction]
#[pyo3(signature = (heights, size, *, periodic=false, detrend=None, window=None))]
pub fn spectrum_2d<'py>(
    py: Python<'py>,
    heights: &Bound<'py, PyAny>,
    size: &Bound<'py, PyAny>,
    periodic: bool,
    detrend: Option<&str>,
    window: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    let t = topography(heights, size, periodic)?;
    let c = conditioning(&t, detrend, window)?;
    let s = py.detach(|| topo::spectrum_2d(&t, c)).map_err(err)?;
    let (nx, ny) = (s.qx.len(), s.qy.len());
    let c = numpy::ndarray::Array2::from_shape_vec((ny, nx), s.c)
        .map_err(|e| value_error(e.to_string()))?;
    let qx = s.qx.into_pyarray(py).into_any();
    let qy = s.qy.into_pyarray(py).into_any();
    Ok((qx, qy, c.into_pyarray(py).into_any())
        .into_pyobject(py)?
        .into_any())
}

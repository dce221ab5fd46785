//! What a BEM pressure field gives besides the area, from numpy: its contact
//! patches with the pressure tail, and the stress below the surface.

use persson::bem::patches::{Connectivity, PatchOptions};
use persson::bem::Boundary;
use persson_studies::bem_detail::{self, PatchReport};
use pyo3::prelude::*;
use pyo3::types::PyList;

use crate::arrays::{float_list, floats, map, square};
use crate::convert::{err, name, to_dict, value_error};

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(contact_patches, m)?)?;
    m.add_function(wrap_pyfunction!(subsurface_stress, m)?)?;
    Ok(())
}

/// An N × N pressure field (square, float64).
fn field(pressure: &Bound<'_, PyAny>) -> PyResult<(usize, Vec<f64>)> {
    let a = floats("pressure", pressure)?;
    let ([rows, cols], values) = map("pressure", &a)?;
    if rows != cols {
        return Err(value_error(format!(
            "pressure: a {rows} × {cols} array; patches and stresses need a square N × N field"
        )));
    }
    Ok((rows, values.to_vec()))
}

fn boundary(b: &str) -> PyResult<Boundary> {
    name::<Boundary>("boundary", b)
}

/// `bem rough --patches` of one pressure field (N × N, side `size`): the
/// number of connected patches of p > 0, the largest, mean and the
/// perimeters, the log-binned area distribution with its exponent τ, and the
/// fits of the pressure tail (Campañá & Müser 2007).
#[pyfunction]
#[pyo3(signature = (pressure, size, *, connectivity="four", boundary="periodic", bins_per_decade=5))]
fn contact_patches<'py>(
    py: Python<'py>,
    pressure: &Bound<'py, PyAny>,
    size: f64,
    connectivity: &str,
    boundary: &str,
    bins_per_decade: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let (n, p) = field(pressure)?;
    let options = PatchOptions {
        connectivity: name::<Connectivity>("connectivity", connectivity)?,
        boundary: self::boundary(boundary)?,
        bins_per_decade,
    };
    let mean = p.iter().sum::<f64>() / p.len().max(1) as f64;
    let mut r = PatchReport::new(n, size, &options);
    r.push(mean, &p).map_err(err)?;
    to_dict(py, &r)
}

/// `bem rough --subsurface`: the stress below a pressure field (N × N, side
/// `size`, compressive positive) on the planes `depth` (each in (0, size]),
/// for a body of Poisson ratio `poisson`; the report's maxima and first
/// yield (with `tensile_yield_stress`), and `von_mises_stress`, one N × N
/// array per depth.
#[pyfunction]
#[pyo3(signature = (pressure, size, depth, *, poisson=0.3, boundary="periodic", tensile_yield_stress=None))]
#[allow(clippy::too_many_arguments)]
fn subsurface_stress<'py>(
    py: Python<'py>,
    pressure: &Bound<'py, PyAny>,
    size: f64,
    depth: &Bound<'py, PyAny>,
    poisson: f64,
    boundary: &str,
    tensile_yield_stress: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let (n, p) = field(pressure)?;
    let depths = float_list("depth", depth)?;
    let b = self::boundary(boundary)?;
    let mean = p.iter().sum::<f64>() / p.len().max(1) as f64;
    let mut maps: Vec<Vec<f64>> = Vec::new();
    let r = py
        .detach(|| {
            bem_detail::subsurface(
                mean,
                &p,
                n,
                size,
                b,
                poisson,
                &depths,
                tensile_yield_stress,
                &mut |_, m| {
                    maps.push(m.to_vec());
                    Ok(())
                },
            )
        })
        .map_err(err)?;
    let d = to_dict(py, &r)?;
    let list = PyList::empty(py);
    for m in maps {
        list.append(square(py, n, m)?)?;
    }
    d.set_item("von_mises_stress", list)?;
    Ok(d)
}

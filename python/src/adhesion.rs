//! Adhesion from Persson's theory as a dict (`persson adhesion --json`).

use persson_studies::scene::{run, AdhesionOutput};
use pyo3::prelude::*;

use crate::arrays::float_list;
use crate::convert::{err, name, to_dict_warned};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(adhesion, m)?)?;
    Ok(())
}

// The signature spells the defaults as literals; these keep them equal.
const _: () = {
    assert!(persson_studies::scene::DEFAULT_ADHESION_TOLERANCE == 1e-5);
    assert!(persson_studies::scene::DEFAULT_STICKINESS_POINTS == 11);
};

/// `persson adhesion --json`: the stickiness balance Δγ_eff(ζ) with its
/// verdict, and A/A0 with the pull-off stress at the nominal pressures
/// (≤ 0 allowed; none: the balance only).
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, work_of_adhesion, pressure=None, *, zeta=None, points=11, area_enhancement="slopes", adhesion_range=None, tolerance=1e-5))]
#[allow(clippy::too_many_arguments)]
fn adhesion<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    work_of_adhesion: f64,
    pressure: Option<&Bound<'py, PyAny>>,
    zeta: Option<f64>,
    points: usize,
    area_enhancement: &str,
    adhesion_range: Option<f64>,
    tolerance: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let pressures = match pressure {
        Some(p) => float_list("pressure", p)?,
        None => Vec::new(),
    };
    let surface = spectrum.contact(contact_modulus)?;
    let out = AdhesionOutput {
        work_of_adhesion,
        zeta,
        points: Some(points),
        area_enhancement: Some(name("area_enhancement", area_enhancement)?),
        adhesion_range,
        tolerance: Some(tolerance),
    };
    let r = py
        .detach(|| run::adhesion(&surface, &pressures, &out))
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

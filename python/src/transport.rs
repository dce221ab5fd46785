//! What passes through the interface: the contact conductance and
//! the leak rate of a seal against load, as dicts of numpy arrays (the
//! `points` of `persson conductance --json` and `persson leakage --json`).

use numpy::IntoPyArray;
use persson_studies::scene::{transport, ConductanceOutput, LeakageOutput};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::float_list;
use crate::convert::{err, value_error};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(conductance, m)?)?;
    m.add_function(wrap_pyfunction!(leakage, m)?)?;
    Ok(())
}

// The signatures spell the library's defaults as literals (so that
// `inspect.signature` shows them); these keep them equal.
const _: () = {
    assert!(transport::DEFAULT_TOLERANCE == 1e-9);
    assert!(persson::leakage::DEFAULT_PERCOLATION_THRESHOLD == 0.42);
};

/// One or two values (a float or a sequence) of a property of the two bodies.
fn pair(arg: &str, v: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<f64>> {
    match v {
        None => Ok(vec![]),
        Some(v) => float_list(arg, v),
    }
}

/// Raise each warning as a Python `UserWarning` (the CLI's stderr line).
fn warn(py: Python<'_>, warnings: &[persson_studies::Warning]) -> PyResult<()> {
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    for w in warnings {
        let text = std::ffi::CString::new(w.to_string()).map_err(|e| value_error(e.to_string()))?;
        PyErr::warn(py, category.as_any(), &text, 2)?;
    }
    Ok(())
}

fn put(d: &Bound<'_, PyDict>, key: &str, v: Vec<f64>) -> PyResult<()> {
    d.set_item(key, v.into_pyarray(d.py()))
}

/// The contact conductance at the nominal pressures σ0 (Pa): the stiffness
/// K/A0 = −dσ0/dū (Pa/m) and, as asked, the thermal conductance
/// h_c = 2κ_s(K/A0)/E* (W/(m² K), `conductivity` κ1 or (κ1, κ2) in W/(m K)),
/// the electrical h_e = 2(K/A0)/((ρ1 + ρ2)E*) (S/m², `resistivity` ρ1 or
/// (ρ1, ρ2) in Ω m; Barber, Proc. R. Soc. Lond. A 459, 53 (2003)) and the
/// gap conductance ∫ P_nc(u) α(u) du (W/(m² K); the gas law
/// α = κ_gas/(u + 2ℓ) with `gas_conductivity` and `mean_free_path`, or
/// `gap_table` = (u, α) arrays), each with its `_error_bound`, as a dict of
/// arrays (the `points` of `persson conductance --json`).
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, *, conductivity=None, resistivity=None, gas_conductivity=None, mean_free_path=None, gap_table=None, tolerance=1e-9))]
#[allow(clippy::too_many_arguments)]
fn conductance<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    conductivity: Option<&Bound<'py, PyAny>>,
    resistivity: Option<&Bound<'py, PyAny>>,
    gas_conductivity: Option<f64>,
    mean_free_path: Option<f64>,
    gap_table: Option<(Bound<'py, PyAny>, Bound<'py, PyAny>)>,
    tolerance: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let pressures = float_list("pressure", pressure)?;
    let surface = spectrum.contact(contact_modulus)?;
    let table = match gap_table {
        None => None,
        Some((u, a)) => {
            let (u, a) = (float_list("gap_table", &u)?, float_list("gap_table", &a)?);
            if u.len() != a.len() {
                return Err(value_error(format!(
                    "invalid gap_table: {} separations and {} values of α",
                    u.len(),
                    a.len()
                )));
            }
            Some(u.into_iter().zip(a).collect())
        }
    };
    let out = ConductanceOutput {
        conductivity: pair("conductivity", conductivity)?,
        resistivity: pair("resistivity", resistivity)?,
        gas_conductivity,
        mean_free_path,
        gap_table: table,
        tolerance: Some(tolerance),
        bem: None,
        plot: None,
    };
    let r = py
        .detach(|| transport::conductance(&surface, &pressures, &out))
        .map_err(err)?;
    warn(py, &r.warnings)?;
    let d = PyDict::new(py);
    let pts = &r.points;
    let col = |f: &dyn Fn(&persson::conductance::ConductancePoint) -> f64| -> Vec<f64> {
        pts.iter().map(f).collect()
    };
    put(&d, "nominal_pressure", col(&|p| p.nominal_pressure))?;
    put(&d, "stiffness", col(&|p| p.stiffness))?;
    put(
        &d,
        "stiffness_error_bound",
        col(&|p| p.stiffness_error_bound),
    )?;
    type Get = fn(&persson::conductance::ConductancePoint) -> Option<f64>;
    let optional: [(&str, Get, Get); 3] = [
        (
            "thermal_conductance",
            |p| p.thermal_conductance,
            |p| p.thermal_conductance_error_bound,
        ),
        (
            "electrical_conductance",
            |p| p.electrical_conductance,
            |p| p.electrical_conductance_error_bound,
        ),
        (
            "gap_conductance",
            |p| p.gap_conductance,
            |p| p.gap_conductance_error_bound,
        ),
    ];
    for (key, value, bound) in optional {
        if pts.first().and_then(value).is_some() {
            put(&d, key, col(&|p| value(p).unwrap_or(0.0)))?;
            put(
                &d,
                &format!("{key}_error_bound"),
                col(&|p| bound(p).unwrap_or(0.0)),
            )?;
        }
    }
    Ok(d)
}

/// The leak rate Q (m³/s) of a static seal at the nominal pressures σ0 (Pa)
/// from the critical-junction theory (Persson & Yang, J. Phys.: Condens.
/// Matter 20, 315011 (2008)) and the effective-medium theory (Lorenz &
/// Persson, Eur. Phys. J. E 32, 281 (2010)): a liquid of `viscosity` η
/// (Pa s) under `pressure_drop` ΔP (Pa), or a gas from `inlet_pressure` to
/// `outlet_pressure` (Pa, absolute); `seal_width` L_x along the flow and
/// `seal_length` L_y across it (m). A dict of arrays: `nominal_pressure`,
/// `contact_fraction` (A/A0 at full magnification), `critical_zeta` (NaN
/// where sealed: no ζ_c), `critical_separation` (0 where sealed),
/// `leak_rate_critical_junction`, `leak_rate_effective_medium`,
/// `effective_flow_conductivity` (the medium's σ_eff), their error bounds,
/// and `leaking_critical_junction`, `leaking_effective_medium` (bool). A
/// sealed load (the contact percolates) has Q = 0 and raises a `UserWarning`.
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, *, viscosity, pressure_drop=None, inlet_pressure=None, outlet_pressure=None, seal_width=1e-3, seal_length=1e-3, percolation_threshold=0.42, tolerance=1e-9))]
#[allow(clippy::too_many_arguments)]
fn leakage<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    viscosity: f64,
    pressure_drop: Option<f64>,
    inlet_pressure: Option<f64>,
    outlet_pressure: Option<f64>,
    seal_width: f64,
    seal_length: f64,
    percolation_threshold: f64,
    tolerance: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let pressures = float_list("pressure", pressure)?;
    let surface = spectrum.contact(contact_modulus)?;
    let out = LeakageOutput {
        viscosity,
        pressure_drop,
        inlet_pressure,
        outlet_pressure,
        seal_width,
        seal_length,
        percolation_threshold: Some(percolation_threshold),
        tolerance: Some(tolerance),
        bem: None,
        plot: None,
    };
    let r = py
        .detach(|| transport::leakage(&surface, &pressures, &out))
        .map_err(err)?;
    warn(py, &r.warnings)?;
    let d = PyDict::new(py);
    let pts = &r.points;
    let col = |f: &dyn Fn(&persson_studies::scene::LeakagePoint) -> f64| -> Vec<f64> {
        pts.iter().map(f).collect()
    };
    put(&d, "nominal_pressure", col(&|p| p.nominal_pressure))?;
    put(
        &d,
        "contact_fraction",
        col(&|p| p.critical_junction.contact_fraction),
    )?;
    put(
        &d,
        "critical_zeta",
        col(&|p| p.critical_junction.critical_zeta.unwrap_or(f64::NAN)),
    )?;
    put(
        &d,
        "critical_separation",
        col(&|p| p.critical_junction.critical_separation),
    )?;
    put(
        &d,
        "critical_separation_error_bound",
        col(&|p| p.critical_junction.critical_separation_error_bound),
    )?;
    put(
        &d,
        "leak_rate_critical_junction",
        col(&|p| p.critical_junction.leak_rate),
    )?;
    put(
        &d,
        "leak_rate_critical_junction_error_bound",
        col(&|p| p.critical_junction.leak_rate_error_bound),
    )?;
    put(
        &d,
        "effective_flow_conductivity",
        col(&|p| p.effective_medium.effective_flow_conductivity),
    )?;
    put(
        &d,
        "effective_flow_conductivity_error_bound",
        col(&|p| p.effective_medium.effective_flow_conductivity_error_bound),
    )?;
    put(
        &d,
        "leak_rate_effective_medium",
        col(&|p| p.effective_medium.leak_rate),
    )?;
    put(
        &d,
        "leak_rate_effective_medium_error_bound",
        col(&|p| p.effective_medium.leak_rate_error_bound),
    )?;
    let leaking =
        |f: &dyn Fn(&persson_studies::scene::LeakagePoint) -> persson::leakage::LeakStatus| {
            pts.iter()
                .map(|p| f(p) == persson::leakage::LeakStatus::Leaking)
                .collect::<Vec<bool>>()
        };
    d.set_item(
        "leaking_critical_junction",
        leaking(&|p| p.critical_junction.status).into_pyarray(py),
    )?;
    d.set_item(
        "leaking_effective_medium",
        leaking(&|p| p.effective_medium.status).into_pyarray(py),
    )?;
    Ok(d)
}

/// The transport keywords of `compare` (`compare --leakage / --conductance`).
pub(crate) struct CompareTransport {
    pub leakage: bool,
    pub viscosity: Option<f64>,
    pub pressure_drop: Option<f64>,
    pub inlet_pressure: Option<f64>,
    pub outlet_pressure: Option<f64>,
    pub seal_width: f64,
    pub seal_length: f64,
    pub percolation_threshold: f64,
    pub conductivity: Option<Vec<f64>>,
    pub resistivity: Option<Vec<f64>>,
    pub gas_conductivity: Option<f64>,
    pub mean_free_path: Option<f64>,
}

/// The transport comparison of `compare`'s keywords (`None`: none asked).
pub(crate) fn compare_transport(
    k: CompareTransport,
    breaks: Vec<f64>,
) -> PyResult<Option<persson_studies::validation::TransportCompareConfig>> {
    let conductance =
        k.conductivity.is_some() || k.resistivity.is_some() || k.gas_conductivity.is_some();
    let seal_given = k.viscosity.is_some()
        || k.pressure_drop.is_some()
        || k.inlet_pressure.is_some()
        || k.outlet_pressure.is_some();
    if seal_given && !k.leakage {
        return Err(value_error(
            "viscosity / pressure_drop / inlet_pressure / outlet_pressure: add leakage=True to compare the leak rate",
        ));
    }
    if !k.leakage && !conductance {
        return Ok(None);
    }
    let seal = if k.leakage {
        let viscosity = k
            .viscosity
            .ok_or_else(|| value_error("viscosity: required with leakage=True (Pa s)"))?;
        let out = LeakageOutput {
            viscosity,
            pressure_drop: k.pressure_drop,
            inlet_pressure: k.inlet_pressure,
            outlet_pressure: k.outlet_pressure,
            seal_width: k.seal_width,
            seal_length: k.seal_length,
            percolation_threshold: Some(k.percolation_threshold),
            tolerance: None,
            bem: None,
            plot: None,
        };
        Some(transport::seal(&out).map_err(err)?)
    } else {
        None
    };
    let request = transport::TransportRequest::new(
        transport::conductivity(&k.conductivity.unwrap_or_default()).map_err(err)?,
        transport::resistivity(&k.resistivity.unwrap_or_default()).map_err(err)?,
        transport::gap_law(k.gas_conductivity, k.mean_free_path, None).map_err(err)?,
        seal,
    );
    let mut config = persson_studies::validation::TransportCompareConfig::new(request);
    config.percolation_threshold = k.percolation_threshold;
    config.breaks = breaks;
    config.validate(None, None).map_err(err)?;
    Ok(Some(config))
}

//! Rubber friction, `persson friction --json` as a dict with numpy arrays.

use std::path::PathBuf;

use numpy::ndarray::Array3;
use numpy::IntoPyArray;
use persson_studies::scene::{
    friction_on, FrictionOutput, FrictionReport, RubberSpec, StandardLinearSolidSpec,
    VelocityRange, WlfSpec,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::float_list;
use crate::convert::{err, name, to_dict_warned, value_error};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(friction, m)?)?;
    Ok(())
}

// The signature spells the library's defaults as literals; these keep them equal.
const _: () = {
    assert!(persson::friction::DEFAULT_TOLERANCE == 1e-8);
    assert!(persson::friction::DEFAULT_GAMMA == 0.5);
    assert!(persson::friction::DEFAULT_POINTS_PER_DECADE == 4);
    assert!(persson::friction::DEFAULT_POISSON == 0.5);
};

/// Three numbers of a tuple argument.
fn triple(arg: &str, v: &[f64]) -> PyResult<(f64, f64, f64)> {
    match *v {
        [a, b, c] => Ok((a, b, c)),
        _ => Err(value_error(format!(
            "{arg}: three numbers expected, got {}",
            v.len()
        ))),
    }
}

/// `persson friction --json` (Persson's rubber friction) as a dict: the
/// report (`points`, one per (T, σ0, v), temperature outermost, with the
/// flash-temperature result under `flash`) plus numpy arrays of shape
/// (temperatures, pressures, velocities): `friction_coefficient`,
/// `contact_fraction` and their `_error_bound`s, and with
/// `flash_temperature=True` `flash_friction_coefficient`,
/// `flash_contact_fraction` and `flash_temperature` (T_{q1} − T, K).
///
/// The rubber: exactly one of `master_curve` (a file, with `frequency_unit`
/// `"rad/s"` or `"Hz"`), `prony` (a file) and `standard_linear_solid`
/// (E0, E∞, τ); optional `wlf` (C1, C2, T_ref) or `shift_table` (a file).
#[pyfunction]
#[pyo3(signature = (spectrum, velocity, pressure, temperature=None, *, master_curve=None,
    frequency_unit=None, prony=None, standard_linear_solid=None, wlf=None, shift_table=None,
    reference_temperature=None, vertical_shift=None, poisson=0.5, q1=None, q1_rms_slope=None,
    gamma=0.5, tolerance=1e-8, points_per_decade=4, flash_temperature=false,
    thermal_conductivity=None, density=None, heat_capacity=None))]
#[allow(clippy::too_many_arguments)]
fn friction<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    velocity: &Bound<'py, PyAny>,
    pressure: &Bound<'py, PyAny>,
    temperature: Option<&Bound<'py, PyAny>>,
    master_curve: Option<PathBuf>,
    frequency_unit: Option<&str>,
    prony: Option<PathBuf>,
    standard_linear_solid: Option<Vec<f64>>,
    wlf: Option<Vec<f64>>,
    shift_table: Option<PathBuf>,
    reference_temperature: Option<f64>,
    vertical_shift: Option<&str>,
    poisson: f64,
    q1: Option<f64>,
    q1_rms_slope: Option<f64>,
    gamma: f64,
    tolerance: f64,
    points_per_decade: usize,
    flash_temperature: bool,
    thermal_conductivity: Option<f64>,
    density: Option<f64>,
    heat_capacity: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let velocities = float_list("velocity", velocity)?;
    let pressures = float_list("pressure", pressure)?;
    let temperatures = temperature
        .map(|t| float_list("temperature", t))
        .transpose()?
        .unwrap_or_default();
    let sls = standard_linear_solid
        .map(|v| triple("standard_linear_solid", &v))
        .transpose()?
        .map(|(e0, e_inf, tau)| StandardLinearSolidSpec {
            instantaneous_modulus: e0,
            relaxed_modulus: e_inf,
            relaxation_time: tau,
        });
    let wlf = wlf
        .map(|v| triple("wlf", &v))
        .transpose()?
        .map(|(c1, c2, t_ref)| WlfSpec {
            wlf_c1: c1,
            wlf_c2: c2,
            reference_temperature: t_ref,
        });
    let rubber = RubberSpec {
        master_curve,
        frequency_unit: frequency_unit
            .map(|u| name("frequency_unit", u))
            .transpose()?,
        prony,
        standard_linear_solid: sls,
        wlf,
        shift_table,
        reference_temperature,
        vertical_shift: vertical_shift
            .map(|v| name("vertical_shift", v))
            .transpose()?,
        poisson: Some(poisson),
        thermal_conductivity,
        density,
        heat_capacity,
    };
    let out = FrictionOutput {
        velocity: velocities.clone(),
        velocity_range: None::<VelocityRange>,
        temperature: temperatures,
        q1,
        q1_rms_slope,
        gamma: Some(gamma),
        tolerance: Some(tolerance),
        points_per_decade: Some(points_per_decade),
        flash_temperature,
        plot: None,
    };
    let r = rubber.build(flash_temperature).map_err(err)?;
    let s = &spectrum.shared;
    let breaks = spectrum.breaks.clone();
    let mut report = py
        .detach(|| friction_on(s, &breaks, &r, &pressures, &out))
        .map_err(err)?;
    report.surface = spectrum.description.clone();
    let mut warnings = spectrum.warnings.clone();
    warnings.append(&mut report.warnings);
    let dict = to_dict_warned(py, &report, &warnings)?;
    let shape = (
        report.points.len() / (pressures.len() * velocities.len()).max(1),
        pressures.len(),
        velocities.len(),
    );
    add_arrays(py, dict.cast::<PyDict>()?, &report, shape)?;
    Ok(dict)
}

/// The per-point values as arrays of `shape` (T, σ0, v).
fn add_arrays(
    py: Python<'_>,
    dict: &Bound<'_, PyDict>,
    report: &FrictionReport,
    shape: (usize, usize, usize),
) -> PyResult<()> {
    type Get = fn(&persson::friction::FrictionPoint) -> Option<f64>;
    let mut columns: Vec<(&str, Get)> = vec![
        ("friction_coefficient", |p| {
            Some(p.isothermal.friction_coefficient)
        }),
        ("friction_coefficient_error_bound", |p| {
            Some(p.isothermal.friction_coefficient_error_bound)
        }),
        ("contact_fraction", |p| Some(p.isothermal.contact_fraction)),
        ("contact_fraction_error_bound", |p| {
            Some(p.isothermal.contact_fraction_error_bound)
        }),
    ];
    if report.has_flash() {
        columns.extend::<[(&str, Get); 3]>([
            ("flash_friction_coefficient", |p| {
                p.flash.as_ref().map(|f| f.friction_coefficient)
            }),
            ("flash_contact_fraction", |p| {
                p.flash.as_ref().map(|f| f.contact_fraction)
            }),
            ("flash_temperature", |p| {
                p.flash.as_ref().map(|f| f.flash_temperature)
            }),
        ]);
    }
    for (key, get) in columns {
        let values: Vec<f64> = report
            .points
            .iter()
            .map(|p| get(p).unwrap_or(f64::NAN))
            .collect();
        let a = Array3::from_shape_vec(shape, values).map_err(|e| value_error(e.to_string()))?;
        dict.set_item(key, a.into_pyarray(py))?;
    }
    let axis = |f: fn(&persson::friction::FrictionPoint) -> f64, stride: usize, n: usize| {
        (0..n)
            .map(|i| report.points.get(i * stride).map_or(f64::NAN, f))
            .collect::<Vec<f64>>()
    };
    let (nt, np, nv) = shape;
    dict.set_item(
        "temperature",
        axis(|p| p.temperature, np * nv, nt).into_pyarray(py),
    )?;
    dict.set_item(
        "nominal_pressure",
        axis(|p| p.nominal_pressure, nv, np).into_pyarray(py),
    )?;
    dict.set_item("velocity", axis(|p| p.velocity, 1, nv).into_pyarray(py))?;
    Ok(())
}

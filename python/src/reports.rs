//! The CLI's reports as dicts (the same keys and digits as its `--json`),
//! and the mean separation as numpy arrays.

use std::path::{Path, PathBuf};

use numpy::IntoPyArray;
use persson::separation::Separation;
use persson::stress::{Start, TabulatedStart};
use persson_studies::scene::{
    run, AreaOutput, BallSpec, CylinderSpec, MagnificationOutput, Scene, SeparationOutput,
    StartName, StressOutput, TheoriesOutput, TheoryName, TheorySpec,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::float_list;
use crate::convert::{err, name, to_dict_warned, value_error};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(area, m)?)?;
    m.add_function(wrap_pyfunction!(magnification, m)?)?;
    m.add_function(wrap_pyfunction!(kappa_report, m)?)?;
    m.add_function(wrap_pyfunction!(theories, m)?)?;
    m.add_function(wrap_pyfunction!(separation, m)?)?;
    m.add_function(wrap_pyfunction!(mean_separation, m)?)?;
    m.add_function(wrap_pyfunction!(separation_density, m)?)?;
    m.add_function(wrap_pyfunction!(stress, m)?)?;
    m.add_function(wrap_pyfunction!(stress_physical, m)?)?;
    m.add_function(wrap_pyfunction!(run_scene, m)?)?;
    Ok(())
}

// The signatures spell the library's default tolerances as literals (so that
// `inspect.signature` shows them, not `Ellipsis`); these keep them equal.
const _: () = {
    assert!(persson::corrected::DEFAULT_TOLERANCE == 1e-12);
    assert!(persson::separation::DEFAULT_TOLERANCE == 1e-10);
};

/// `persson area --json`: A/A0 against the nominal pressures with G, its
/// error bound, the effective G of a corrected theory and the linear laws;
/// with an asperity theory (`overlap`, needing `yield_stress`,
/// `greenwood-williamson`, `bush`) its A/A0, separation and contact density
/// beside Persson's, and the surface's moments and summit statistics.
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, theory="original", gamma=None, *, zeta=None, tolerance=1e-12, yield_stress=None))]
#[allow(clippy::too_many_arguments)]
fn area<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    theory: &str,
    gamma: Option<f64>,
    zeta: Option<f64>,
    tolerance: f64,
    yield_stress: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let pressures = float_list("pressure", pressure)?;
    let surface = spectrum.contact(contact_modulus)?;
    let out = AreaOutput {
        zeta,
        theory: name("theory", theory)?,
        gamma,
        tolerance: Some(tolerance),
        yield_stress,
        plot: None,
    };
    let r = py
        .detach(|| run::area(&surface, &pressures, &out))
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// `persson magnification --json`: G(ζ) and A/A0 against magnification at
/// one nominal pressure; ζ from `zeta`, else `points` log-spaced from 1 to q_s/q_l.
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, zeta=None, *, points=41))]
fn magnification<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: f64,
    zeta: Option<&Bound<'py, PyAny>>,
    points: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let surface = spectrum.contact(contact_modulus)?;
    let out = MagnificationOutput {
        nominal_pressure: pressure,
        zeta: zeta
            .map(|z| float_list("zeta", z))
            .transpose()?
            .unwrap_or_default(),
        points,
        plot: None,
        plot_g: None,
    };
    let r = py
        .detach(|| run::magnification(&surface, &out))
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// `persson kappa --json`: κ of Bush and of Persson and, with a spectrum,
/// modulus and pressures, both linear laws A/A0 = κ σ0/(E* h'_rms).
#[pyfunction]
#[pyo3(signature = (spectrum=None, contact_modulus=None, pressure=None))]
fn kappa_report<'py>(
    py: Python<'py>,
    spectrum: Option<&Spectrum>,
    contact_modulus: Option<f64>,
    pressure: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let r = match (spectrum, contact_modulus) {
        (Some(s), Some(m)) => {
            let pressures = pressure
                .map(|p| float_list("pressure", p))
                .transpose()?
                .unwrap_or_default();
            let surface = s.contact(m)?;
            run::kappa(Some((&surface, &pressures[..])))
        }
        (None, None) => run::kappa(None),
        _ => {
            return Err(value_error(
                "spectrum and contact_modulus: give both or neither",
            ))
        }
    }
    .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// `persson theories --json`: A/A0 against load for every theory (or the
/// names in `theories`, each with its default γ).
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, theories=None, *, zeta=None, tolerance=None))]
fn theories<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    theories: Option<Vec<String>>,
    zeta: Option<f64>,
    tolerance: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let pressures = float_list("pressure", pressure)?;
    let list = theories
        .unwrap_or_default()
        .iter()
        .map(|t| {
            Ok(TheorySpec {
                theory: name::<TheoryName>("theories", t)?,
                gamma: None,
            })
        })
        .collect::<PyResult<Vec<_>>>()?;
    let surface = spectrum.contact(contact_modulus)?;
    let out = TheoriesOutput {
        theories: list,
        zeta,
        tolerance,
        plot: None,
    };
    let r = py
        .detach(|| run::theories(&surface, &pressures, &out))
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// `persson separation --json`: the mean interfacial separation ū, the
/// contact stiffness K = −dσ0/dū and the stored elastic energy per area
/// against load, with error bounds (Persson, Phys. Rev. Lett. 99, 125502 (2007)).
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, *, tolerance=1e-10))]
fn separation<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    tolerance: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let pressures = float_list("pressure", pressure)?;
    let surface = spectrum.contact(contact_modulus)?;
    let out = SeparationOutput {
        tolerance: Some(tolerance),
        ..Default::default()
    };
    let r = py
        .detach(|| run::separation(&surface, &pressures, &out, &[]))
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// `persson separation --separation-density --json`: the distribution of
/// interfacial separations P(u) at each nominal pressure, the contact's
/// weight A/A0 at u = 0 and the continuous part P_nc(u) on `density_points`
/// separations, with A/A0 + ∫P_nc du = 1 and ∫u P du = ū + s_fold beside it
/// (Almqvist, Campañá, Prodanov & Persson, J. Mech. Phys. Solids 59, 2355
/// (2011)).
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, *, density_points=101, tolerance=1e-10))]
fn separation_density<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    density_points: usize,
    tolerance: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let pressures = float_list("pressure", pressure)?;
    if density_points < 2 {
        return Err(value_error(format!(
            "density_points {density_points}: need at least 2"
        )));
    }
    let surface = spectrum.contact(contact_modulus)?;
    let r = py
        .detach(|| {
            persson_studies::scene::separation_density::separation_density(
                &surface,
                &pressures,
                density_points,
                tolerance,
            )
        })
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// The mean separation ū (m), stiffness K (Pa/m, unit of E* per m) and
/// elastic energy U_el (J/m²) at the nominal pressures, as a dict of numpy
/// arrays with their error bounds (the `points` of `separation`).
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, pressure, *, tolerance=1e-10))]
fn mean_separation<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: &Bound<'py, PyAny>,
    tolerance: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let pressures = float_list("pressure", pressure)?;
    let s = &spectrum.shared;
    let breaks = &spectrum.breaks;
    let pts = py
        .detach(|| {
            Separation::new(s, contact_modulus)?
                .with_tolerance(tolerance)?
                .with_breaks(breaks)
                .load_curve(&pressures)
        })
        .map_err(err)?;
    let d = PyDict::new(py);
    let col = |f: &dyn Fn(&persson::separation::SeparationPoint) -> f64| -> Vec<f64> {
        pts.iter().map(f).collect()
    };
    let columns: [(&str, Vec<f64>); 7] = [
        ("nominal_pressure", col(&|p| p.nominal_pressure)),
        ("mean_separation", col(&|p| p.mean_separation)),
        (
            "mean_separation_error_bound",
            col(&|p| p.mean_separation_error_bound),
        ),
        ("stiffness", col(&|p| p.stiffness)),
        ("stiffness_error_bound", col(&|p| p.stiffness_error_bound)),
        ("elastic_energy", col(&|p| p.elastic_energy)),
        (
            "elastic_energy_error_bound",
            col(&|p| p.elastic_energy_error_bound),
        ),
    ];
    for (k, v) in columns {
        d.set_item(k, v.into_pyarray(py))?;
    }
    Ok(d)
}

/// `persson stress --json`: the dimensionless stress distribution σH P(σ)
/// against σ/σH at each G (Persson, Bucher & Chiaia, Phys. Rev. B 65,
/// 184106 (2002), Figs. 2–4) for the start "flat", "hertz" or "cylinder",
/// or a tabulated start `table` = (σ/σH, σH P0) whose integral is 1 within
/// `table_normalisation` (the CLI's `--table`); elastic or with the yield
/// stress σY/σH = `yield_ratio`; at `sigma_ratio` or `points` values over
/// the distribution; with A/A0, its elastic and plastic parts and error bounds.
#[pyfunction]
#[pyo3(signature = (start, g, *, table=None, table_normalisation=1e-6, yield_ratio=None, sigma_ratio=None, points=201, tolerance=1e-12))]
#[allow(clippy::too_many_arguments)]
fn stress<'py>(
    py: Python<'py>,
    start: Option<&str>,
    g: &Bound<'py, PyAny>,
    table: Option<(Bound<'py, PyAny>, Bound<'py, PyAny>)>,
    table_normalisation: f64,
    yield_ratio: Option<f64>,
    sigma_ratio: Option<&Bound<'py, PyAny>>,
    points: usize,
    tolerance: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let start = match (start, table) {
        (Some(s), None) => Start::from(name::<StartName>("start", s)?),
        (None, Some((s, p))) => Start::Tabulated(
            TabulatedStart::new(
                &float_list("table", &s)?,
                &float_list("table", &p)?,
                table_normalisation,
            )
            .map_err(err)?,
        ),
        _ => return Err(value_error("start, table: give exactly one")),
    };
    let g = float_list("g", g)?;
    let sigma = sigma_ratio
        .map(|s| float_list("sigma_ratio", s))
        .transpose()?
        .unwrap_or_default();
    let r = py
        .detach(|| run::stress_dimensionless(&start, &g, yield_ratio, tolerance, &sigma, points))
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// The stress distribution P(σ) in the pressure unit (1/unit of σ) at the
/// magnifications ζ of a rough surface (the scene output `stress` with
/// `zeta`): start "flat" with σ0 = `peak_pressure`, "hertz" with a ball
/// (radius m, load N) or "cylinder" (radius m, load per length N/m), or any
/// start with its peak pressure σH; elastic or with a yield stress σY.
#[pyfunction]
#[pyo3(signature = (spectrum, contact_modulus, zeta, start="flat", *, peak_pressure=None, ball=None, cylinder=None, yield_stress=None, points=201, tolerance=1e-12))]
#[allow(clippy::too_many_arguments)]
fn stress_physical<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    zeta: &Bound<'py, PyAny>,
    start: &str,
    peak_pressure: Option<f64>,
    ball: Option<(f64, f64)>,
    cylinder: Option<(f64, f64)>,
    yield_stress: Option<f64>,
    points: usize,
    tolerance: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let surface = spectrum.contact(contact_modulus)?;
    let out = StressOutput {
        start: name("start", start)?,
        g: vec![],
        yield_ratio: None,
        zeta: float_list("zeta", zeta)?,
        peak_pressure,
        ball: ball.map(|(radius, load)| BallSpec { radius, load }),
        cylinder: cylinder.map(|(radius, load_per_length)| CylinderSpec {
            radius,
            load_per_length,
        }),
        yield_stress,
        points,
        tolerance,
        plot: None,
    };
    let r = py
        .detach(|| run::stress_physical(&surface, &out))
        .map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

/// `persson run SCENE --json`: run a scene given as a path to its JSON file
/// or as a dict of the same content (relative file names in a dict are
/// relative to the working directory). Writes no files and draws no plots.
#[pyfunction]
fn run_scene<'py>(py: Python<'py>, scene: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let parsed = if scene.is_instance_of::<PyDict>() {
        let text: String = py
            .import("json")?
            .call_method1("dumps", (scene,))
            .map_err(|e| value_error(format!("scene: not JSON-serialisable ({e})")))?
            .extract()?;
        Scene::parse(Path::new("<dict>"), &text)
    } else {
        let path: PathBuf = scene
            .extract()
            .map_err(|_| value_error("scene: expected a path (str or os.PathLike) or a dict"))?;
        Scene::read(&path)
    }
    .map_err(err)?;
    let r = py.detach(|| parsed.run()).map_err(err)?;
    to_dict_warned(py, &r, &r.warnings)
}

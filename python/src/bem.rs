//! The FFT boundary-element method from numpy: one solve on a height map
//! (pressure and gap arrays), `persson bem rough` / `bem hertz` and
//! `persson compare` as dicts, surface synthesis.

use std::path::{Path, PathBuf};

use persson::bem::rough::{self, RoughOptions, SurfaceOrigin};
use persson::bem::surface::{synthesize as synth, GridSurface};
use persson::bem::{check_memory, Boundary, Control, Operator, Options, Solver};
use persson::error::check;
use persson::names::Named;
use persson_studies::bem_detail::{
    adhesive_controlled_path, adhesive_warnings, AdhesiveIteration, LawKind, PathControl,
};
use persson_studies::validation::{
    self, CompareSpec, ComparisonConfig, SweepSpec, UserData, UserHistogram,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::{float_list, floats, map, square};
use crate::convert::{err, name, to_dict_warned, value_error, Seed};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(synthesize, m)?)?;
    m.add_function(wrap_pyfunction!(bem_solve, m)?)?;
    m.add_function(wrap_pyfunction!(bem_rough, m)?)?;
    m.add_function(wrap_pyfunction!(bem_hertz, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    Ok(())
}

fn boundary(b: &str) -> PyResult<Boundary> {
    name::<Boundary>("boundary", b)
}

pub(crate) fn options(
    tolerance: f64,
    max_iterations: usize,
    yield_stress: Option<f64>,
) -> PyResult<Options> {
    check::tolerance("tolerance", tolerance).map_err(err)?;
    Ok(Options {
        tolerance,
        max_iterations,
        warm_start: true,
        yield_stress,
    })
}

/// A square height map (N × N, float64, C-contiguous) of side `size` as the
/// solver's surface (one copy: the solver's own buffer).
pub(crate) fn surface(heights: &Bound<'_, PyAny>, size: f64) -> PyResult<GridSurface> {
    let a = floats("heights", heights)?;
    let ([rows, cols], values) = map("heights", &a)?;
    if rows != cols {
        return Err(value_error(format!(
            "heights: a {rows} × {cols} array; the BEM solves on square N × N maps (crop or resample it)"
        )));
    }
    GridSurface::new(rows, size, values.to_vec()).map_err(err)
}

// The Python signatures spell the library's defaults as literals (so that
// `inspect.signature` shows them, not `Ellipsis`); these keep them equal.
const _: () = {
    assert!(validation::DEFAULT_LEVELS == 3);
    assert!(validation::DEFAULT_BINS == 50);
    assert!(validation::DEFAULT_ALPHA == 0.7);
    assert!(validation::DEFAULT_PIXELS_PER_WAVELENGTH == 4.0);
};

/// A Gaussian random surface of the spectrum on an N × N periodic grid of
/// side `size` (default 2π/q_l), heights in m (N × N numpy array),
/// reproducible from `seed` (Pcg64Mcg; the CLI's `bem rough --seed`).
#[pyfunction]
#[pyo3(
    signature = (spectrum, grid, *, size=None, seed=Seed(1)),
    text_signature = "(spectrum, grid, *, size=None, seed=1)"
)]
fn synthesize<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    grid: usize,
    size: Option<f64>,
    seed: Seed,
) -> PyResult<Bound<'py, PyAny>> {
    let Seed(seed) = seed;
    let size = size.unwrap_or(std::f64::consts::TAU / spectrum.shared.0.q_min());
    check::positive("size", size).map_err(err)?;
    let s = &spectrum.shared;
    let surface = py.detach(|| synth(s, grid, size, seed)).map_err(err)?;
    square(py, surface.n, surface.heights)
}

/// One FFT-BEM solve (Polonsky & Keer, Wear 231, 206 (1999)): a rigid rough
/// surface `heights` (N × N float64 array, m) of side `size` (m) pressed on
/// an elastic half-space of contact modulus `contact_modulus`, at the mean pressure
/// `pressure` (unit of E*) or the approach `approach` (m, from first
/// touch); "periodic" or "free" boundary; pressures bounded by
/// `yield_stress` when given. Returns (pressure, gap, summary): two N × N
/// arrays (unit of E*; m) and a dict with the mean pressure, A/A0 (and its
/// elastic and plastic parts with a yield stress), the mean separation,
/// the approach, iterations, residual and seconds.
#[pyfunction]
#[pyo3(signature = (heights, size, contact_modulus, *, pressure=None, approach=None, boundary="periodic", yield_stress=None, tolerance=1e-10, max_iterations=10_000))]
#[allow(clippy::too_many_arguments)]
fn bem_solve<'py>(
    py: Python<'py>,
    heights: &Bound<'py, PyAny>,
    size: f64,
    contact_modulus: f64,
    pressure: Option<f64>,
    approach: Option<f64>,
    boundary: &str,
    yield_stress: Option<f64>,
    tolerance: f64,
    max_iterations: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let control = match (pressure, approach) {
        (Some(p), None) => Control::MeanPressure(check::positive("pressure", p).map_err(err)?),
        (None, Some(d)) => Control::Penetration(check::non_negative("approach", d).map_err(err)?),
        _ => return Err(value_error("pressure, approach: give exactly one")),
    };
    let b = self::boundary(boundary)?;
    let opts = options(tolerance, max_iterations, yield_stress)?;
    let s = surface(heights, size)?;
    let sol = py
        .detach(|| -> persson::Result<_> {
            check_memory(s.n, b)?;
            let op = Operator::new(b, s.n, s.size, contact_modulus)?;
            Solver::new(op).solve(&s.heights, control, &opts)
        })
        .map_err(err)?;
    let summary = PyDict::new(py);
    summary.set_item("nominal_pressure", sol.mean_pressure)?;
    summary.set_item("contact_fraction", sol.contact_fraction)?;
    summary.set_item(
        "mean_separation",
        sol.gap.iter().sum::<f64>() / sol.gap.len() as f64,
    )?;
    summary.set_item("approach", sol.approach)?;
    if yield_stress.is_some() {
        summary.set_item("elastic_fraction", sol.elastic_fraction)?;
        summary.set_item("plastic_fraction", sol.plastic_fraction)?;
        summary.set_item("plastic_displacement_mean", sol.plastic_displacement_mean)?;
        summary.set_item("plastic_displacement_max", sol.plastic_displacement_max)?;
    }
    summary.set_item("iterations", sol.iterations)?;
    summary.set_item("residual", sol.residual)?;
    summary.set_item("seconds", sol.seconds)?;
    let n = s.n;
    let p = square(py, n, sol.pressure)?;
    let g = square(py, n, sol.gap)?;
    Ok((p, g, summary).into_pyobject(py)?.into_any())
}

/// `persson bem rough --json`: solves at each nominal pressure (warm
/// started along the list) on a given height map (`heights` and `size`) or
/// on a surface synthesised from `spectrum` on `grid`² nodes with `seed`
/// (side `size`, default 2π/q_l); with `bins`, each solve's pressure
/// histogram.
///
/// With `work_of_adhesion` Δγ, `adhesion_range` ρ and `mean_gap` (a list,
/// in order) instead of `pressure`: `persson bem rough --work-of-adhesion
/// --json`, the adhesive BEM (`adhesion` "maugis" or "exponential") along
/// the mean-gap path, periodic; or with `approach` (a list of rigid-body
/// approaches from first touch) instead of `mean_gap`, periodic or
/// `boundary="free"`: `--approach`. `adhesive_iteration` ("auto", "plain",
/// "preconditioned") is `--adhesive-iteration`.
#[pyfunction]
#[pyo3(
    signature = (contact_modulus, pressure=None, *, heights=None, size=None, spectrum=None, grid=None, seed=Seed(1), boundary="periodic", yield_stress=None, bins=None, tolerance=1e-10, max_iterations=10_000, work_of_adhesion=None, adhesion_range=None, adhesion="maugis", mean_gap=None, approach=None, adhesive_iteration="auto"),
    text_signature = "(contact_modulus, pressure=None, *, heights=None, size=None, spectrum=None, grid=None, seed=1, boundary='periodic', yield_stress=None, bins=None, tolerance=1e-10, max_iterations=10000, work_of_adhesion=None, adhesion_range=None, adhesion='maugis', mean_gap=None, approach=None, adhesive_iteration='auto')"
)]
#[allow(clippy::too_many_arguments)]
fn bem_rough<'py>(
    py: Python<'py>,
    contact_modulus: f64,
    pressure: Option<&Bound<'py, PyAny>>,
    heights: Option<&Bound<'py, PyAny>>,
    size: Option<f64>,
    spectrum: Option<&Spectrum>,
    grid: Option<usize>,
    seed: Seed,
    boundary: &str,
    yield_stress: Option<f64>,
    bins: Option<usize>,
    tolerance: f64,
    max_iterations: usize,
    work_of_adhesion: Option<f64>,
    adhesion_range: Option<f64>,
    adhesion: &str,
    mean_gap: Option<&Bound<'py, PyAny>>,
    approach: Option<&Bound<'py, PyAny>>,
    adhesive_iteration: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let Seed(seed) = seed;
    let b = self::boundary(boundary)?;
    let source = (heights, size, spectrum, grid, seed);
    if let Some(dg) = work_of_adhesion {
        if pressure.is_some() || yield_stress.is_some() || bins.is_some() {
            return Err(value_error(
                "work_of_adhesion: solves at mean_gap; pressure, yield_stress and bins do not apply",
            ));
        }
        let range = adhesion_range
            .ok_or_else(|| value_error("adhesion_range: required with work_of_adhesion"))?;
        let list = |name: &str, v: Option<&Bound<'py, PyAny>>| -> PyResult<Vec<f64>> {
            v.map(|v| float_list(name, v))
                .transpose()
                .map(Option::unwrap_or_default)
        };
        let (gaps, approaches) = (list("mean_gap", mean_gap)?, list("approach", approach)?);
        // The one check of a path's lists (the command line's and the
        // scene's), every value before any solve.
        let control = PathControl::new(&gaps, &approaches, b).map_err(err)?;
        let kind = law_kind(adhesion)?;
        let iteration: AdhesiveIteration = name("adhesive_iteration", adhesive_iteration)?;
        let opts = persson::bem::adhesive::AdhesiveOptions {
            tolerance: check::tolerance("tolerance", tolerance).map_err(err)?,
            max_iterations,
        };
        let (s, _) = grid_surface(py, source, b)?;
        let r = py
            .detach(|| {
                adhesive_controlled_path(
                    &s.heights,
                    (s.n, s.size, contact_modulus),
                    b,
                    (kind, dg, range),
                    control,
                    &opts,
                    iteration,
                )
            })
            .map_err(err)?;
        return to_dict_warned(py, &r, &adhesive_warnings(&r));
    }
    let pressures = float_list(
        "pressure",
        pressure.ok_or_else(|| value_error("pressure: required (or work_of_adhesion)"))?,
    )?;
    let opts = RoughOptions {
        boundary: b,
        solver: options(tolerance, max_iterations, yield_stress)?,
        bins,
        ..RoughOptions::default()
    };
    let (s, origin) = grid_surface(py, source, b)?;
    let r = py
        .detach(|| rough::rough_contact(&s, origin, contact_modulus, &pressures, &opts, &mut ()))
        .map_err(err)?;
    to_dict_warned(py, &r, &persson_studies::warning::of_rough(&r))
}

/// The cohesive law named by `adhesion`.
fn law_kind(adhesion: &str) -> PyResult<LawKind> {
    LawKind::from_name(adhesion).ok_or_else(|| {
        let names: Vec<_> = LawKind::names().map(|n| format!("'{n}'")).collect();
        value_error(format!(
            "adhesion {adhesion:?}: one of {}",
            names.join(", ")
        ))
    })
}

/// `bem_rough`'s surface arguments: heights, size, spectrum, grid, seed.
type SurfaceArgs<'a, 'py> = (
    Option<&'a Bound<'py, PyAny>>,
    Option<f64>,
    Option<&'a Spectrum>,
    Option<usize>,
    u64,
);

/// The surface of `bem_rough`: a height map given, or one synthesised.
fn grid_surface(
    py: Python<'_>,
    (heights, size, spectrum, grid, seed): SurfaceArgs<'_, '_>,
    b: Boundary,
) -> PyResult<(GridSurface, SurfaceOrigin)> {
    match (heights, spectrum, grid) {
        (Some(h), None, None) => {
            let size = size.ok_or_else(|| value_error("size: required with heights"))?;
            Ok((
                surface(h, size)?,
                SurfaceOrigin::height_map(Path::new("(array)")),
            ))
        }
        (None, Some(sp), Some(n)) => {
            let shared = &sp.shared;
            py.detach(|| -> persson::Result<_> {
                check_memory(n, b)?;
                let size = check::positive(
                    "size",
                    size.unwrap_or(std::f64::consts::TAU / shared.0.q_min()),
                )?;
                Ok((
                    synth(shared, n, size, seed)?,
                    SurfaceOrigin::synthesised(shared, seed)?,
                ))
            })
            .map_err(err)
        }
        _ => Err(value_error(
            "no surface: give heights and size, or spectrum and grid",
        )),
    }
}

/// `persson bem hertz --json`, a scene's `bem_hertz`: the Hertz ball on the
/// FFT-BEM (a ball of radius `radius` on a grid of side `size`, load from the
/// contact radius, default 0.1 L). On one grid (`grid`, or `grids` of one;
/// default 256) the validation against Hertz's closed form: energy-norm
/// error η, contact radius and peak pressure; on several `grids`, η per
/// grid.
///
/// With `yield_stress` σY (unit of `contact_modulus`): beside η, the plastic
/// disc (pressure capped at σY) on each grid, under `plastic`.
///
/// With `subsurface` (one grid): the stress on the contact's axis against
/// Johnson's closed forms, for Poisson ratio `poisson` (default 0.3).
///
/// With `work_of_adhesion` Δγ and `adhesion_range` ρ (`boundary="periodic"`):
/// the adhesive sphere's pull-off on each grid against JKR and DMT, with the
/// cohesive law `adhesion` (default `"maugis"`).
#[pyfunction]
#[pyo3(signature = (*, grid=None, boundary="free", size=1.0, radius=1.0, contact_modulus=1.0, contact_radius=None, tolerance=1e-10, max_iterations=10_000, yield_stress=None, grids=None, subsurface=false, poisson=None, work_of_adhesion=None, adhesion_range=None, adhesion=None))]
#[allow(clippy::too_many_arguments)]
fn bem_hertz<'py>(
    py: Python<'py>,
    grid: Option<usize>,
    boundary: &str,
    size: f64,
    radius: f64,
    contact_modulus: f64,
    contact_radius: Option<f64>,
    tolerance: f64,
    max_iterations: usize,
    yield_stress: Option<f64>,
    grids: Option<Vec<usize>>,
    subsurface: bool,
    poisson: Option<f64>,
    work_of_adhesion: Option<f64>,
    adhesion_range: Option<f64>,
    adhesion: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    use persson_studies::bem_hertz::{BemHertz, BemHertzOutput};
    use persson_studies::study::{Context, Study};
    let grids = match (grid, grids) {
        (Some(_), Some(_)) => return Err(value_error("grid, grids: give one of them")),
        (Some(n), None) => vec![n],
        (None, g) => g.unwrap_or_default(),
    };
    let spec = BemHertzOutput {
        grids,
        boundary: Some(self::boundary(boundary)?),
        size: Some(size),
        radius: Some(radius),
        contact_modulus: Some(contact_modulus),
        contact_radius,
        tolerance: Some(tolerance),
        max_iterations: Some(max_iterations),
        yield_stress,
        subsurface,
        poisson,
        stress_plot: None,
        work_of_adhesion,
        adhesion_range,
        adhesion: adhesion.map(law_kind).transpose()?,
    };
    let r = py
        .detach(|| BemHertz::run(&Context::nothing(), &spec))
        .map_err(err)?;
    to_dict_warned(py, &r, &BemHertz::warnings(&r))
}

/// `persson compare --json`: every theory against the BEM at `levels`
/// resolutions (finest `grid`²) of one synthesised surface over `seeds`
/// seeds from `seed`, the continuum limit A(N) = A∞ + c N^−α (α = `alpha`,
/// or fitted when None), κ, pressure distributions, mean separation, and
/// the user's data (CSV files) scored against them (Campañá & Müser, EPL
/// 77, 38005 (2007)). With `heights` (N × N, m) and `size` (m): the BEM on
/// that map and its coarser copies instead (as `compare --surface`; a
/// `periodic` map on a periodic half-space, otherwise a free one), the
/// theories on `spectrum` (e.g. `Spectrum.from_height_map` of the same map).
/// With `yield_stress` σY (unit of `contact_modulus`, above every pressure): the
/// saturated BEM against Persson's finite-σY P(σ), A_el and A_pl, as
/// `compare --yield-stress`. With `leakage=True` (and `viscosity`,
/// `pressure_drop` or a gas's `inlet_pressure`/`outlet_pressure`, the seal's
/// sizes, `percolation_threshold`) and/or `conductivity`/`resistivity`
/// (κ or ρ, one value or two) or `gas_conductivity` with `mean_free_path`:
/// the theories' leak rate and conductance against the BEM's, as
/// `compare --leakage / --conductance` (key `transport`). With
/// `work_of_adhesion` (one Δγ or a list; `adhesion_range`, `adhesion`):
/// Persson's adhesive theory against the adhesive BEM, as
/// `compare --work-of-adhesion` (key `adhesion`).
#[pyfunction]
#[pyo3(
    signature = (spectrum, contact_modulus, pressure=None, *, heights=None, size=None, periodic=false, grid=256, levels=3, seeds=1, seed=Seed(1), alpha=Some(0.7), pixels_per_wavelength=4.0, tolerance=1e-10, max_iterations=10_000, bins=50, histogram_pressure=None, data=None, data_histogram=None, yield_stress=None, leakage=false, viscosity=None, pressure_drop=None, inlet_pressure=None, outlet_pressure=None, seal_width=1e-3, seal_length=1e-3, percolation_threshold=0.42, conductivity=None, resistivity=None, gas_conductivity=None, mean_free_path=None, work_of_adhesion=None, adhesion_range=None, adhesion="maugis"),
    text_signature = "(spectrum, contact_modulus, pressure=None, *, heights=None, size=None, periodic=False, grid=256, levels=3, seeds=1, seed=1, alpha=0.7, pixels_per_wavelength=4.0, tolerance=1e-10, max_iterations=10000, bins=50, histogram_pressure=None, data=None, data_histogram=None, yield_stress=None, leakage=False, viscosity=None, pressure_drop=None, inlet_pressure=None, outlet_pressure=None, seal_width=0.001, seal_length=0.001, percolation_threshold=0.42, conductivity=None, resistivity=None, gas_conductivity=None, mean_free_path=None, work_of_adhesion=None, adhesion_range=None, adhesion='maugis')"
)]
#[allow(clippy::too_many_arguments)]
fn compare<'py>(
    py: Python<'py>,
    spectrum: &Spectrum,
    contact_modulus: f64,
    pressure: Option<&Bound<'py, PyAny>>,
    heights: Option<&Bound<'py, PyAny>>,
    size: Option<f64>,
    periodic: bool,
    grid: usize,
    levels: usize,
    seeds: usize,
    seed: Seed,
    alpha: Option<f64>,
    pixels_per_wavelength: f64,
    tolerance: f64,
    max_iterations: usize,
    bins: usize,
    histogram_pressure: Option<f64>,
    data: Option<PathBuf>,
    data_histogram: Option<PathBuf>,
    yield_stress: Option<f64>,
    leakage: bool,
    viscosity: Option<f64>,
    pressure_drop: Option<f64>,
    inlet_pressure: Option<f64>,
    outlet_pressure: Option<f64>,
    seal_width: f64,
    seal_length: f64,
    percolation_threshold: f64,
    conductivity: Option<&Bound<'py, PyAny>>,
    resistivity: Option<&Bound<'py, PyAny>>,
    gas_conductivity: Option<f64>,
    mean_free_path: Option<f64>,
    work_of_adhesion: Option<&Bound<'py, PyAny>>,
    adhesion_range: Option<f64>,
    adhesion: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let Seed(seed) = seed;
    // As the command line refuses --grid/--seed/--seeds with --surface and
    // --periodic without it: nothing given is silently left unused.
    if heights.is_some() && (grid != 256 || seeds != 1 || seed != 1) {
        return Err(value_error(
            "grid, seed, seeds: for a synthesised surface; a height map (heights) sets its own grid and is one surface",
        ));
    }
    if heights.is_none() && periodic {
        return Err(value_error(
            "periodic: for a height map (heights); a synthesised surface is periodic",
        ));
    }
    let spec = CompareSpec {
        pressure: pressure
            .map(|p| float_list("pressure", p))
            .transpose()?
            .unwrap_or_default(),
        yield_stress,
        histogram_pressure,
        bins,
        work_of_adhesion: work_of_adhesion
            .map(|w| float_list("work_of_adhesion", w))
            .transpose()?
            .unwrap_or_default(),
        adhesion_range,
        adhesion: law_kind(adhesion)?,
    };
    let sweep = SweepSpec {
        grid: Some(grid),
        levels: Some(levels),
        seeds: Some(seeds),
        seed: Some(seed),
        alpha,
        fit_alpha: alpha.is_none(),
        pixels_per_wavelength: Some(pixels_per_wavelength),
        tolerance: Some(tolerance),
        max_iterations: Some(max_iterations),
    };
    let mut config = spec.config(contact_modulus, &sweep).map_err(err)?;
    let read = |p: &Option<PathBuf>| p.as_deref().map(UserData::from_csv).transpose();
    config.data = read(&data).map_err(err)?;
    config.data_histogram = (data_histogram.as_deref().map(UserHistogram::from_csv))
        .transpose()
        .map_err(err)?;
    config.transport = crate::transport::compare_transport(
        crate::transport::CompareTransport {
            leakage,
            viscosity,
            pressure_drop,
            inlet_pressure,
            outlet_pressure,
            seal_width,
            seal_length,
            percolation_threshold,
            conductivity: conductivity
                .map(|c| float_list("conductivity", c))
                .transpose()?,
            resistivity: resistivity
                .map(|r| float_list("resistivity", r))
                .transpose()?,
            gas_conductivity,
            mean_free_path,
        },
        if heights.is_some() {
            Vec::new()
        } else {
            spectrum.breaks.clone()
        },
    )?;
    let r = compare_on(py, spectrum, (heights, size, periodic), &config)?;
    crate::convert::to_dict_warned(py, &r, &r.warnings)
}

/// `compare`'s run: on a synthesised surface, or on the map `heights` of
/// side `size` (periodic or free).
fn compare_on(
    py: Python<'_>,
    spectrum: &Spectrum,
    (heights, size, periodic): (Option<&Bound<'_, PyAny>>, Option<f64>, bool),
    config: &ComparisonConfig,
) -> PyResult<validation::Comparison> {
    let s = &spectrum.shared;
    match heights {
        None => py.detach(|| validation::compare(s, config, &mut |_| {})),
        Some(h) => {
            let size = size.ok_or_else(|| value_error("size: required with heights"))?;
            let map = surface(h, size)?;
            let b = if periodic {
                Boundary::Periodic
            } else {
                Boundary::Free
            };
            py.detach(|| -> persson::Result<_> {
                check_memory(map.n, b)?;
                validation::compare_surface(s, &map, b, config, &mut |_| {})
            })
        }
    }
    .map_err(err)
}

//! `persson.surrogates` (python/persson/_surrogates.py): the map against
//! random surfaces of its spectrum, as a plan whose jobs (the map, then
//! each surrogate) run here or on Dask workers; the plan and each job's
//! numbers cross processes as Python floats and ints (exact: no decimal
//! text in between), and `gather` forms the report of `persson surrogates
//! --json` from them whatever ran the jobs.

use persson::spectrum::BandLimited;
use persson::theory::Persson;
use persson_studies::study::Study;
use persson_studies::surrogates::{Plan, Solved, SolvedPoint, Surrogates, SurrogatesOutput};
use pyo3::prelude::*;

use crate::arrays::float_list;
use crate::convert::{err, name, to_dict_warned, value_error, Seed};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<SurrogatePlan>()?;
    Ok(())
}

/// A comparison ready to run, picklable for Dask.
#[pyclass(frozen, module = "persson._persson", name = "_SurrogatePlan")]
pub struct SurrogatePlan {
    plan: Plan,
    /// Persson's A/A0 at each pressure on the spectrum given (up to the
    /// grid's πN/L), empty without one.
    theory: Vec<f64>,
}

fn json_error(e: serde_json::Error) -> PyErr {
    value_error(format!("a surrogate plan: {e}"))
}

/// One solve's numbers: A/A0, patches, tail (exponential?, advantage), counts.
type PointState = (f64, usize, Option<(bool, f64)>, Vec<u64>);

/// One job's numbers: index, (skewness, kurtosis), IAAFT figures, the solves.
type SolvedState = (usize, (f64, f64), Option<(f64, usize)>, Vec<PointState>);

fn to_state(s: Solved) -> SolvedState {
    let points = s
        .points
        .into_iter()
        .map(|p| (p.contact_fraction, p.patches, p.tail, p.counts))
        .collect();
    (s.index, s.moments, s.adjusted, points)
}

fn from_state((index, moments, adjusted, points): SolvedState) -> Solved {
    let points = points
        .into_iter()
        .map(|(contact_fraction, patches, tail, counts)| SolvedPoint {
            contact_fraction,
            patches,
            tail,
            counts,
        })
        .collect();
    Solved {
        index,
        moments,
        adjusted,
        points,
    }
}

#[pymethods]
impl SurrogatePlan {
    #[new]
    #[pyo3(signature = (heights, size, contact_modulus, pressure, count, kind, iterations, seed, boundary, tolerance, spectrum))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        heights: &Bound<'_, PyAny>,
        size: f64,
        contact_modulus: f64,
        pressure: &Bound<'_, PyAny>,
        count: usize,
        kind: &str,
        iterations: usize,
        seed: Seed,
        boundary: &str,
        tolerance: f64,
        spectrum: Option<Py<Spectrum>>,
    ) -> PyResult<Self> {
        let map = crate::bem::surface(heights, size)?;
        let pressures = float_list("pressure", pressure)?;
        let spec = SurrogatesOutput {
            count: Some(count),
            kind: Some(name("kind", kind)?),
            iterations: Some(iterations),
            seed: Some(seed.0),
            boundary: Some(name("boundary", boundary)?),
            tolerance: Some(tolerance),
            ..SurrogatesOutput::default()
        };
        let plan = Plan::new(&spec, ("(array)", &map), contact_modulus, &pressures).map_err(err)?;
        let theory = match spectrum {
            None => Vec::new(),
            Some(s) => {
                let s = &s.bind(py).get().shared;
                let band =
                    BandLimited::new(s, std::f64::consts::PI * map.n as f64 / size).map_err(err)?;
                let model = Persson::new(&band, contact_modulus).map_err(err)?;
                model
                    .load_curve(&pressures, model.zeta_max())
                    .map_err(err)?
                    .iter()
                    .map(|p| p.contact_fraction)
                    .collect()
            }
        };
        Ok(SurrogatePlan { plan, theory })
    }

    /// Every job: 0 (the map), 1 … K (the surrogates).
    fn jobs(&self) -> Vec<usize> {
        self.plan.jobs()
    }

    /// Solve job `index` (interpreter released): its numbers as plain data.
    fn solve(&self, py: Python<'_>, index: usize) -> PyResult<SolvedState> {
        let plan = &self.plan;
        let solved = py.detach(|| plan.solve(index)).map_err(err)?;
        Ok(to_state(solved))
    }

    /// The report from the jobs' numbers (any order), as `persson
    /// surrogates --json`, its warnings raised as `UserWarning`.
    fn gather<'py>(
        &self,
        py: Python<'py>,
        solves: Vec<SolvedState>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let solves = solves.into_iter().map(from_state).collect();
        let r = self.plan.gather(solves, &self.theory, 0.0).map_err(err)?;
        to_dict_warned(py, &r, &Surrogates::warnings(&r))
    }

    /// Pickling (Dask): the settings as JSON (names and small integers; the
    /// plan's serde form leaves the heights out), the heights, the other
    /// floats and the theory as floats.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        let p = slf.get();
        let state = (
            serde_json::to_string(&p.plan).map_err(json_error)?,
            p.plan.heights.clone(),
            p.plan.size,
            p.plan.contact_modulus,
            p.plan.pressures.clone(),
            p.plan.tolerance,
            p.theory.clone(),
        );
        let restore = py.get_type::<SurrogatePlan>().getattr("_from_state")?;
        (restore, state).into_pyobject(py).map(|t| t.into_any())
    }

    /// The plan of a pickled state (the floats exactly as they left).
    #[staticmethod]
    fn _from_state(
        settings: &str,
        heights: Vec<f64>,
        size: f64,
        contact_modulus: f64,
        pressures: Vec<f64>,
        tolerance: f64,
        theory: Vec<f64>,
    ) -> PyResult<Self> {
        let settings: Plan = serde_json::from_str(settings).map_err(json_error)?;
        let plan = Plan {
            heights,
            size,
            contact_modulus,
            pressures,
            tolerance,
            ..settings
        };
        Ok(SurrogatePlan { plan, theory })
    }
}

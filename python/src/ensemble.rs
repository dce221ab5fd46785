//! The ensemble study (`persson compare ensemble`) as a plan whose jobs run
//! anywhere: `persson.ensemble` (python/persson/_ensemble.py) runs them here
//! on threads, or ships the plan (a spectrum's recipe and a few numbers,
//! never a height map) to Dask workers, which synthesise each surface from
//! (spectrum, seed, N) and send back its numbers; `gather` forms the same
//! report from them, whatever ran the jobs.

use persson_studies::validation::ensemble::{self, EnsembleConfig, EnsembleJob, EnsembleSolve};
use persson_studies::validation::EnsembleSpec;
use pyo3::prelude::*;

use crate::arrays::float_list;
use crate::convert::{err, to_dict_warned, Seed};
use crate::spectrum::Spectrum;

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<EnsemblePlan>()?;
    Ok(())
}

/// One job's numbers as they cross between processes: seed, grid, A/A0 and
/// ū per pressure, the surface's rms slope, iterations, residual, seconds.
type SolveState = (u64, usize, Vec<f64>, Vec<f64>, f64, usize, f64, f64);

/// An ensemble ready to run: the spectrum, E*, the pressures and the
/// settings (what `persson.ensemble` was given), picklable for Dask.
#[pyclass(frozen, module = "persson._persson", name = "_EnsemblePlan")]
pub struct EnsemblePlan {
    spectrum: Py<Spectrum>,
    config: EnsembleConfig,
    first_seed: u64,
}

#[pymethods]
impl EnsemblePlan {
    #[new]
    #[pyo3(signature = (spectrum, contact_modulus, pressure, grid, levels, seeds, seed, pixels_per_wavelength, tolerance, max_iterations))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        spectrum: Py<Spectrum>,
        contact_modulus: f64,
        pressure: &Bound<'_, PyAny>,
        grid: usize,
        levels: usize,
        seeds: usize,
        seed: Seed,
        pixels_per_wavelength: f64,
        tolerance: f64,
        max_iterations: usize,
    ) -> PyResult<Self> {
        let Seed(first) = seed;
        let spec = EnsembleSpec {
            grid,
            levels,
            seeds,
            seed: first,
            pixels_per_wavelength,
            tolerance,
            max_iterations,
        };
        let plan = EnsemblePlan {
            spectrum,
            config: EnsembleConfig {
                contact_modulus,
                nominal_pressure: float_list("pressure", pressure)?,
                sweep: spec.settings().map_err(err)?,
            },
            first_seed: first,
        };
        Ok(plan)
    }

    /// Every job (seed, grid), finest grid first; a `ValueError` for bad input.
    fn jobs(&self, py: Python<'_>) -> PyResult<Vec<(u64, usize)>> {
        let s = &self.spectrum.bind(py).get().shared;
        Ok(ensemble::jobs(s, &self.config)
            .map_err(err)?
            .into_iter()
            .map(|j| (j.seed, j.grid))
            .collect())
    }

    /// Solve one job (interpreter released): its numbers as plain data.
    fn solve(&self, py: Python<'_>, seed: u64, grid: usize) -> PyResult<SolveState> {
        let s = self.spectrum.bind(py).get().shared.clone();
        let config = &self.config;
        let r = py
            .detach(|| ensemble::solve(&s, config, EnsembleJob { seed, grid }))
            .map_err(err)?;
        Ok((
            r.seed,
            r.grid,
            r.contact_fraction,
            r.mean_separation,
            r.surface_rms_slope,
            r.iterations,
            r.residual,
            r.seconds,
        ))
    }

    /// The report from the jobs' numbers (any order), as `persson compare
    /// ensemble --json`, its warnings raised as `UserWarning`.
    fn gather<'py>(&self, py: Python<'py>, solves: Vec<SolveState>) -> PyResult<Bound<'py, PyAny>> {
        let solves = solves
            .into_iter()
            .map(|(seed, grid, a, u, slope, iterations, residual, seconds)| {
                EnsembleSolve::new(
                    EnsembleJob { seed, grid },
                    a,
                    u,
                    slope,
                    iterations,
                    residual,
                    seconds,
                )
            })
            .collect();
        let s = &self.spectrum.bind(py).get().shared;
        let r = ensemble::gather(s, &self.config, solves).map_err(err)?;
        to_dict_warned(py, &r, &r.warnings)
    }

    /// Run every job here on `threads` threads (0: one per core) and gather.
    fn run<'py>(&self, py: Python<'py>, threads: usize) -> PyResult<Bound<'py, PyAny>> {
        let s = self.spectrum.bind(py).get().shared.clone();
        let config = &self.config;
        let r = py
            .detach(|| ensemble::ensemble(&s, config, threads))
            .map_err(err)?;
        to_dict_warned(py, &r, &r.warnings)
    }

    /// Pickling (Dask): the spectrum (its recipe) and the settings.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        let p = slf.get();
        let c = &p.config;
        let args = (
            p.spectrum.clone_ref(py),
            c.contact_modulus,
            c.nominal_pressure.clone(),
            c.sweep.grid,
            c.sweep.levels,
            c.sweep.seeds.len(),
            p.first_seed,
            c.sweep.pixels_per_wavelength,
            c.sweep.options.tolerance,
            c.sweep.options.max_iterations,
        );
        (py.get_type::<EnsemblePlan>(), args)
            .into_pyobject(py)
            .map(|t| t.into_any())
    }
}

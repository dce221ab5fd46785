//! Python bindings of `persson`: the compiled module `persson._persson`,
//! which the package `persson` (python/persson/) re-exports.
//!
//! Every function is a thin wrapper over one library function, the one the
//! CLI calls for the same job, so a Python result and the CLI's `--json` are
//! the same numbers. Long computations run with the interpreter released
//! (`Python::detach`, pyo3's `allow_threads`). Library errors become
//! `OSError` (files) or `ValueError` (everything else) with the CLI's text.

mod adhesion;
mod anisotropy;
mod arrays;
mod asperity;
mod bem;
mod convert;
mod ensemble;
mod friction;
mod height_map;
mod reports;
mod serde_probe;
mod spectrum;
mod spectrum_build;
mod state;
mod surrogates;
mod theory;
mod to_python;
mod transport;

use pyo3::prelude::*;

/// The version of the persson crate this module was built from.
#[pyfunction]
fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

/// The compiled module.
#[pymodule]
fn _persson(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(version, m)?)?;
    m.add_function(wrap_pyfunction!(serde_probe::_serde_probe, m)?)?;
    m.add_class::<spectrum::Spectrum>()?;
    m.add_function(wrap_pyfunction!(height_map::analyse_height_map, m)?)?;
    m.add_function(wrap_pyfunction!(anisotropy::anisotropy, m)?)?;
    m.add_function(wrap_pyfunction!(anisotropy::spectrum_2d, m)?)?;
    theory::register(m)?;
    reports::register(m)?;
    bem::register(m)?;
    adhesion::register(m)?;
    ensemble::register(m)?;
    surrogates::register(m)?;
    friction::register(m)?;
    transport::register(m)?;
    asperity::register(m)?;
    Ok(())
}

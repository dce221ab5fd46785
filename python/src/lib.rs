//! Python bindings of `persson` (the module `persson._persson`; the package
//! `persson` around it re-exports and documents it).

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
    Ok(())
}

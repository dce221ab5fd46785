//! Between Rust and Python: library errors as Python exceptions, reports as
//! the dicts of the CLI's `--json` with their warnings raised, seeds and the
//! names of closed sets.

use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::to_python;

/// A library error as a Python exception: `OSError` when a file could not
/// be read or written, `ValueError` otherwise; the message is the CLI's.
pub(crate) fn err(e: persson::Error) -> PyErr {
    match e {
        persson::Error::Io { .. } => PyOSError::new_err(e.to_string()),
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// Shorthand for a `ValueError`.
pub(crate) fn value_error(msg: impl Into<String>) -> PyErr {
    PyValueError::new_err(msg.into())
}

/// A typed report as the dict `json.loads` makes of the CLI's `--json`,
/// built directly from the struct (no JSON text in between) by the
/// serializer of [`to_python`], whose mapping is serde_json's: the same keys
/// and the same floats, NaN and ±∞ as None.
pub(crate) fn to_dict<'py, T: Serialize>(
    py: Python<'py>,
    report: &T,
) -> PyResult<Bound<'py, PyAny>> {
    to_python::to_python(py, report)
}

/// A report with warnings as the dict of the CLI's `--json` (its top-level
/// `"warnings"` list), each warning also raised as a Python `UserWarning`
/// (the CLI's `persson: warning:` line on stderr).
pub(crate) fn to_dict_warned<'py, T: Serialize>(
    py: Python<'py>,
    report: &T,
    warnings: &[persson_studies::Warning],
) -> PyResult<Bound<'py, PyAny>> {
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    for w in warnings {
        let text = std::ffi::CString::new(w.to_string()).map_err(|e| value_error(e.to_string()))?;
        PyErr::warn(py, category.as_any(), &text, 2)?;
    }
    to_dict(py, &persson_studies::warning::Warned::new(report, warnings))
}

/// A seed from Python: an integer from 0 to 2⁶⁴ − 1 (a numpy integer too);
/// anything else a `ValueError` naming `seed` (not pyo3's `OverflowError`
/// for a negative one).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Seed(pub u64);

impl<'a, 'py> FromPyObject<'a, 'py> for Seed {
    type Error = PyErr;

    fn extract(obj: pyo3::Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        if let Ok(v) = obj.extract::<u64>() {
            return Ok(Seed(v));
        }
        let shown = obj
            .str()
            .map(|s| s.to_string())
            .unwrap_or_else(|_| "?".into());
        Err(value_error(format!(
            "invalid seed = {shown}: must be an integer from 0 to {} (2^64 − 1)",
            u64::MAX
        )))
    }
}

/// A value of a closed set (theory, boundary, start, convention, detrend,
/// window) spelled as on the command line; a `ValueError` naming `arg` and
/// the allowed values otherwise.
pub(crate) fn name<T: DeserializeOwned>(arg: &str, value: &str) -> PyResult<T> {
    serde_json::from_value(serde_json::Value::String(value.to_string()))
        .map_err(|e| value_error(format!("invalid {arg} = '{value}': {e}")))
}

//! numpy arrays in and out: float64 arrays as they are, arrays and scalars of
//! any other real dtype (int, unsigned, float16/32) converted to float64 (a
//! `ValueError` naming the argument for complex, bool or object data), Python
//! numbers and lists converted, results handed to numpy without a copy.

use numpy::ndarray::{ArrayD, IxDyn};
use numpy::{IntoPyArray, PyReadonlyArrayDyn, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::value_error;

/// `obj` as a read-only float64 array (any shape): an ndarray of dtype
/// float64 as it is (no copy); an array of another real dtype (int, unsigned,
/// float16/32: exact in float64 up to 2⁵³), a numpy scalar, a Python number
/// or a list of them converted.
///
/// # Errors
/// `ValueError` naming `arg`: an array of complex, bool or object dtype, or
/// something numpy cannot read as float64.
pub fn floats<'py>(arg: &str, obj: &Bound<'py, PyAny>) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    if let Ok(a) = obj.extract::<PyReadonlyArrayDyn<'py, f64>>() {
        return Ok(a);
    }
    if let Ok(u) = obj.extract::<Bound<'py, PyUntypedArray>>() {
        let kind = u.dtype().getattr("kind")?.extract::<String>()?;
        if !matches!(kind.as_str(), "i" | "u" | "f") {
            return Err(value_error(format!(
                "{arg}: an array of dtype {}, expected real numbers (float64, or an integer or float dtype)",
                u.dtype()
            )));
        }
    }
    let py = obj.py();
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", "float64")?;
    let converted = py
        .import("numpy")?
        .call_method("asarray", (obj,), Some(&kwargs))
        .map_err(|e| value_error(format!("{arg}: not a number or an array of numbers ({e})")))?;
    converted
        .extract::<PyReadonlyArrayDyn<'py, f64>>()
        .map_err(|e| value_error(format!("{arg}: {e}")))
}

/// `obj` as a list of floats (a 0-d or 1-d input).
///
/// # Errors
/// As [`floats`]; more than one dimension.
pub fn float_list(arg: &str, obj: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    let a = floats(arg, obj)?;
    let v = a.as_array();
    if v.ndim() > 1 {
        return Err(value_error(format!(
            "{arg}: a {}-D array, expected a number or a 1-D array",
            v.ndim()
        )));
    }
    Ok(v.iter().copied().collect())
}

/// A 2-D, C-contiguous float64 array: its shape `[rows, columns]` and values.
///
/// # Errors
/// `ValueError` naming `arg`: another dtype, another number of dimensions, a
/// non-contiguous view.
pub fn map<'a>(arg: &str, a: &'a PyReadonlyArrayDyn<'_, f64>) -> PyResult<([usize; 2], &'a [f64])> {
    let shape = a.shape();
    if shape.len() != 2 {
        return Err(value_error(format!(
            "{arg}: a {}-D array, expected a 2-D height map",
            shape.len()
        )));
    }
    // `as_slice` accepts Fortran order too, which would read the map
    // transposed: only C order is taken as it is.
    let not_c = || {
        value_error(format!(
            "{arg}: not C-contiguous (a transposed or strided view); pass numpy.ascontiguousarray({arg})"
        ))
    };
    if !a.is_c_contiguous() {
        return Err(not_c());
    }
    let values = a.as_slice().map_err(|_| not_c())?;
    Ok(([shape[0], shape[1]], values))
}

/// The broadcast shape of two shapes (numpy's rules).
///
/// # Errors
/// `ValueError` naming both arguments when they do not broadcast.
pub fn broadcast(a: (&str, &[usize]), b: (&str, &[usize])) -> PyResult<Vec<usize>> {
    let n = a.1.len().max(b.1.len());
    let pad = |s: &[usize]| -> Vec<usize> {
        let mut v = vec![1; n - s.len()];
        v.extend_from_slice(s);
        v
    };
    let (x, y) = (pad(a.1), pad(b.1));
    x.iter()
        .zip(&y)
        .map(|(&p, &q)| match (p, q) {
            (p, q) if p == q => Ok(p),
            (1, q) => Ok(q),
            (p, 1) => Ok(p),
            _ => Err(value_error(format!(
                "{} (shape {:?}) and {} (shape {:?}) do not broadcast to one shape",
                a.0, a.1, b.0, b.1
            ))),
        })
        .collect()
}

/// Values of `shape` handed to numpy (the vector becomes the array's buffer;
/// a 0-d result becomes a Python float).
pub fn output<'py>(
    py: Python<'py>,
    shape: &[usize],
    values: Vec<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    if shape.is_empty() {
        return Ok(pyo3::types::PyFloat::new(py, values[0]).into_any());
    }
    let a = ArrayD::from_shape_vec(IxDyn(shape), values).map_err(|e| value_error(e.to_string()))?;
    Ok(a.into_pyarray(py).into_any())
}

/// An N × N map handed to numpy without a copy.
pub fn square<'py>(py: Python<'py>, n: usize, values: Vec<f64>) -> PyResult<Bound<'py, PyAny>> {
    output(py, &[n, n], values)
}

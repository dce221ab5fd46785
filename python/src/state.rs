//! What pickles a `persson.Spectrum`: the recipe that rebuilds it and its
//! measured map's notes, as plain Python values; an estimate as a float or
//! a (value, bound) pair.

use persson::topography::Note;
use persson::Estimate;
use pyo3::prelude::*;

use crate::convert::value_error;

/// What rebuilds a spectrum exactly: a self-affine spec (as scene JSON) or
/// the points of a tabulated one in Persson's normalisation.
#[derive(Clone)]
pub enum Recipe {
    SelfAffine(String),
    Points(Vec<(f64, f64)>),
    /// Two rough bodies: the parts' recipes.
    Sum(Vec<Recipe>),
}

/// The pickled state of a recipe: its kind and payload (a sum: the list of
/// its parts' states).
pub(crate) fn recipe_state<'py>(
    py: Python<'py>,
    r: &Recipe,
) -> PyResult<(&'static str, Bound<'py, PyAny>)> {
    Ok(match r {
        Recipe::SelfAffine(json) => ("self_affine", json.clone().into_pyobject(py)?.into_any()),
        Recipe::Points(p) => ("points", p.clone().into_pyobject(py)?.into_any()),
        Recipe::Sum(parts) => {
            let list = parts
                .iter()
                .map(|p| recipe_state(py, p))
                .collect::<PyResult<Vec<_>>>()?;
            ("sum", list.into_pyobject(py)?.into_any())
        }
    })
}

/// A measured map's note as plain data for pickling: its kind, its
/// integers and its floats.
pub(crate) type NoteState = (String, Vec<usize>, Vec<f64>);

pub(crate) fn note_state(n: &Note) -> NoteState {
    match n {
        Note::Resampled {
            points,
            max_deviation,
        } => ("resampled".into(), vec![*points], vec![*max_deviation]),
        Note::HurstNotFitted { bins } => ("hurst_not_fitted".into(), vec![*bins], vec![]),
        Note::HurstOutOfRange { hurst, hurst_error } => (
            "hurst_out_of_range".into(),
            vec![],
            vec![*hurst, *hurst_error],
        ),
        Note::BinsLeftOut { q, of } => ("bins_left_out".into(), vec![*of], q.clone()),
        Note::CurvatureNotComputed { shape, periodic } => (
            "curvature_not_computed".into(),
            vec![shape[0], shape[1], usize::from(*periodic)],
            vec![],
        ),
    }
}

pub(crate) fn note_of_state((kind, ints, floats): NoteState) -> PyResult<Note> {
    Ok(match (kind.as_str(), &ints[..], &floats[..]) {
        ("resampled", [points], [max_deviation]) => Note::Resampled {
            points: *points,
            max_deviation: *max_deviation,
        },
        ("hurst_not_fitted", [bins], []) => Note::HurstNotFitted { bins: *bins },
        ("hurst_out_of_range", [], [hurst, hurst_error]) => Note::HurstOutOfRange {
            hurst: *hurst,
            hurst_error: *hurst_error,
        },
        ("bins_left_out", [of], q) => Note::BinsLeftOut {
            q: q.to_vec(),
            of: *of,
        },
        ("curvature_not_computed", [ny, nx, periodic], []) => Note::CurvatureNotComputed {
            shape: [*ny, *nx],
            periodic: *periodic != 0,
        },
        _ => return Err(value_error(format!("invalid pickled note '{kind}'"))),
    })
}

pub(crate) fn estimate<'py>(
    py: Python<'py>,
    e: Estimate,
    error_bound: bool,
) -> PyResult<Bound<'py, PyAny>> {
    if error_bound {
        Ok((e.value, e.error).into_pyobject(py)?.into_any())
    } else {
        Ok(pyo3::types::PyFloat::new(py, e.value).into_any())
    }
}

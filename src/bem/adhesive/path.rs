//! What an adhesive path prescribes, point by point: mean gaps ḡ or
//! approaches δ of the rigid surface, with the one check of a path's lists
//! that every front-end (command line, scene, Python) makes.

use crate::bem::Boundary;
use crate::error::{check, Error, Result};

/// What an adhesive path prescribes, point by point
/// ([`super::AdhesiveSolver::path`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathControl<'a> {
    /// Mean gaps ḡ (m): periodic only, stable on the whole curve.
    MeanGap(&'a [f64]),
    /// Approaches δ of the rigid surface from first touch (m; δ < 0 is a
    /// separation): periodic or free. Under approach control the free
    /// boundary's curve is stable too (the rigid surface is held), but a
    /// periodic δ must keep ḡ = max h − mean h − δ > 0.
    Approach(&'a [f64]),
}

impl<'a> PathControl<'a> {
    /// The path of the lists given (`mean_gap` or `approach`, exactly one
    /// non-empty) on `boundary`: the one check of the command line, the
    /// scene and Python. Mean gaps must be finite and > 0, approaches finite.
    ///
    /// # Errors
    /// [`Error::Inconsistent`] naming `mean_gap` / `approach` for both or
    /// neither given, or mean gaps on the free boundary (it runs under
    /// approach control); [`Error::InvalidParameter`] naming `mean_gap[i]` or
    /// `approach[i]`.
    pub fn new(mean_gap: &'a [f64], approach: &'a [f64], boundary: Boundary) -> Result<Self> {
        for (i, &g) in mean_gap.iter().enumerate() {
            check::positive(&format!("mean_gap[{i}]"), g)?;
        }
        for (i, &d) in approach.iter().enumerate() {
            if !d.is_finite() {
                return Err(Error::invalid(format!("approach[{i}]"), d, "finite (m)"));
            }
        }
        match (mean_gap.is_empty(), approach.is_empty()) {
            (false, false) => Err(Error::Inconsistent {
                name: "mean_gap and approach".into(),
                requirement: "give one of the two".into(),
            }),
            (false, true) if boundary != Boundary::Periodic => Err(Error::Inconsistent {
                name: "mean_gap and boundary".into(),
                requirement: "mean gaps need a periodic boundary: the free one runs under \
                              approach control (give approach instead)"
                    .into(),
            }),
            (false, true) => Ok(PathControl::MeanGap(mean_gap)),
            (true, false) => Ok(PathControl::Approach(approach)),
            (true, true) => Err(Error::Inconsistent {
                name: "mean_gap or approach".into(),
                requirement: "the adhesive BEM runs along a path: give mean gaps (m) or \
                              approaches (m)"
                    .into(),
            }),
        }
    }
}

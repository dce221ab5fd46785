//! A line scan: two columns x, h with x equally spaced (increasing). The
//! length is `L = n·Δx`, `Δx = (x_last − x_first)/(n − 1)`.

use std::path::Path;

use super::{text, Raw};
use crate::error::{Error, Result};
use crate::topography::Layout;

/// Relative deviation of a spacing from the mean spacing still taken as
/// regular: coordinates written with 7 significant digits.
pub(crate) const SPACING_TOLERANCE: f64 = 1e-5;

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let rows = text::rows(path, b)?;
    let mut x = Vec::with_capacity(rows.len());
    let mut h = Vec::with_capacity(rows.len());
    for (ln, r) in &rows {
        if r.len() != 2 {
            return Err(Error::parse(
                path,
                *ln,
                0,
                format!(
                    "a line scan has two columns (x, h), this row has {}",
                    r.len()
                ),
            ));
        }
        if !r[0].is_finite() {
            return Err(Error::parse(
                path,
                *ln,
                1,
                format!("x = {} is not finite", r[0]),
            ));
        }
        x.push(r[0]);
        h.push(r[1]);
    }
    let n = x.len();
    if n < 2 {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("the line scan has {n} point(s): need at least 2"),
        ));
    }
    let dx = (x[n - 1] - x[0]) / (n - 1) as f64;
    if dx.is_nan() || dx <= 0.0 {
        return Err(Error::parse(
            path,
            0,
            0,
            "x must increase from the first row to the last",
        ));
    }
    for (i, w) in x.windows(2).enumerate() {
        if ((w[1] - w[0]) - dx).abs() > SPACING_TOLERANCE * dx {
            return Err(Error::parse(
                path,
                rows[i + 1].0,
                1,
                format!(
                    "x is not equally spaced: step {} where the mean step is {}",
                    w[1] - w[0],
                    dx
                ),
            ));
        }
    }
    Ok(Raw {
        nx: n,
        ny: 1,
        heights: h,
        size: Some((n as f64 * dx, 0.0)),
        layout: Layout::LineScans,
    })
}

//! XYZ triples on a regular grid, in any order. The grid is the set of
//! distinct x and y values, which must be equally spaced; a grid point
//! without a triple (or with z = nan) is undefined. Sizes `Lx = nx·Δx`,
//! `Ly = ny·Δy`.

use std::path::Path;

use super::line::SPACING_TOLERANCE;
use super::{text, Raw};
use crate::error::{Error, Result};
use crate::topography::Layout;

/// Distinct values of `v`, their spacing and the index of each value.
fn axis(path: &Path, name: &str, v: &[f64], lines: &[usize]) -> Result<(usize, f64, Vec<usize>)> {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let (lo, hi) = (s[0], s[s.len() - 1]);
    let range = hi - lo;
    let mut distinct: Vec<f64> = Vec::new();
    for &x in &s {
        if distinct
            .last()
            .is_none_or(|&d| x - d > 1e-9 * range.max(f64::MIN_POSITIVE))
        {
            distinct.push(x);
        }
    }
    let n = distinct.len();
    if n < 2 {
        return Ok((1, 0.0, vec![0; v.len()]));
    }
    let d = range / (n - 1) as f64;
    for (k, &x) in distinct.iter().enumerate() {
        if (x - (lo + k as f64 * d)).abs() > SPACING_TOLERANCE * 10.0 * d {
            return Err(Error::parse(
                path,
                0,
                0,
                format!(
                    "not a regular grid: {name} = {x} is not on the grid of {n} equally spaced {name} values from {lo} to {hi} (spacing {d})"
                ),
            ));
        }
    }
    let index = v
        .iter()
        .zip(lines)
        .map(|(&x, &ln)| {
            let k = ((x - lo) / d).round();
            if (x - (lo + k * d)).abs() > 0.01 * d {
                Err(Error::parse(
                    path,
                    ln,
                    0,
                    format!("{name} = {x} is off the grid of spacing {d}"),
                ))
            } else {
                Ok(k as usize)
            }
        })
        .collect::<Result<Vec<_>>>()?;
    Ok((n, d, index))
}

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let rows = text::rows(path, b)?;
    let (mut x, mut y, mut z, mut lines) = (vec![], vec![], vec![], vec![]);
    for (ln, r) in &rows {
        if r.len() != 3 {
            return Err(Error::parse(
                path,
                *ln,
                0,
                format!(
                    "an XYZ file has three columns (x, y, z), this row has {}",
                    r.len()
                ),
            ));
        }
        if !(r[0].is_finite() && r[1].is_finite()) {
            return Err(Error::parse(path, *ln, 0, "x and y must be finite"));
        }
        x.push(r[0]);
        y.push(r[1]);
        z.push(r[2]);
        lines.push(*ln);
    }
    let (nx, dx, ix) = axis(path, "x", &x, &lines)?;
    let (ny, dy, iy) = axis(path, "y", &y, &lines)?;
    if nx < 2 || ny < 2 {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("the points span {nx} distinct x and {ny} distinct y: a map needs at least 2 of each"),
        ));
    }
    let mut heights = vec![f64::NAN; nx * ny];
    let mut seen = vec![false; nx * ny];
    for k in 0..z.len() {
        let p = iy[k] * nx + ix[k];
        if seen[p] {
            return Err(Error::parse(
                path,
                lines[k],
                0,
                format!("a second point at x = {}, y = {}", x[k], y[k]),
            ));
        }
        seen[p] = true;
        heights[p] = z[k];
    }
    Ok(Raw {
        nx,
        ny,
        heights,
        size: Some((nx as f64 * dx, ny as f64 * dy)),
        layout: Layout::Map,
    })
}

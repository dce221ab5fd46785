//! XYZ triples on a regular grid, in any order. The grid is the set of
//! distinct x and y values, which must be equally spaced to the precision
//! written (`|x_k − x_0 − kΔ| ≤ 0.01 Δ + u`, u one unit in the last digit
//! written); a grid point without a triple (or with z = nan) is undefined.
//! Sizes `Lx = nx·Δx`, `Ly = ny·Δy`; units from the column headings
//! (`x [µm]`), if any.

use std::path::Path;

use super::line::SPACING_TOLERANCE;
use super::units::Unit;
use super::{Raw, Stored};
use crate::error::{Error, Result};
use crate::io::text::{cells, Rows};
use crate::topography::Layout;

/// One axis of the grid: its points, spacing, the index of each value, and
/// the relative precision of its written coordinates.
struct Axis {
    n: usize,
    spacing: f64,
    index: Vec<usize>,
    resolution: f64,
}

/// Distinct values of `v` (written to `ulp`), their spacing and the index
/// of each value.
fn axis(path: &Path, name: &str, v: &[f64], ulp: &[f64], lines: &[usize]) -> Result<Axis> {
    let mut order: Vec<usize> = (0..v.len()).collect();
    order.sort_by(|&a, &b| v[a].total_cmp(&v[b]));
    let (lo, hi) = (v[order[0]], v[order[v.len() - 1]]);
    let range = hi - lo;
    // Distinct values with the coarsest written precision of each.
    let mut distinct: Vec<(f64, f64)> = Vec::new();
    for &k in &order {
        let u = if ulp[k].is_finite() { ulp[k] } else { 0.0 };
        match distinct.last_mut() {
            Some((d, du)) if v[k] - *d <= 1e-9 * range.max(f64::MIN_POSITIVE) => *du = du.max(u),
            _ => distinct.push((v[k], u)),
        }
    }
    let n = distinct.len();
    if n < 2 {
        return Ok(Axis {
            n: 1,
            spacing: 0.0,
            index: vec![0; v.len()],
            resolution: 0.0,
        });
    }
    let d = range / (n - 1) as f64;
    for (k, &(x, u)) in distinct.iter().enumerate() {
        if (x - (lo + k as f64 * d)).abs() > SPACING_TOLERANCE * d + u {
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
    let worst = distinct.iter().map(|p| p.1).fold(0.0, f64::max);
    let index = v
        .iter()
        .zip(lines)
        .map(|(&x, &ln)| {
            let k = ((x - lo) / d).round();
            if (x - (lo + k * d)).abs() > 0.5 * d {
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
    Ok(Axis {
        n,
        spacing: d,
        index,
        resolution: worst / range,
    })
}

/// The units of x, y and z from the last header line's three headings.
fn units(path: &Path, r: &Rows) -> Result<[Unit; 3]> {
    let none = || [Unit::Unstated, Unit::Unstated, Unit::Unstated];
    let Some(last) = r.header.last() else {
        return Ok(none());
    };
    let parts: Vec<&str> = if last.text.contains([',', ';', '\t']) {
        last.text.split([',', ';', '\t']).map(str::trim).collect()
    } else {
        cells(&last.text).collect()
    };
    let parts: Vec<&str> = parts.into_iter().filter(|p| !p.is_empty()).collect();
    if parts.len() != 3 {
        return Ok(none());
    }
    let bad = |m: String| Error::parse(path, last.line, 0, m);
    let x = Unit::in_heading("the x coordinates", parts[0]).map_err(bad)?;
    let y = Unit::in_heading("the y coordinates", parts[1]).map_err(bad)?;
    let z = Unit::in_heading("the heights", parts[2]).map_err(bad)?;
    if x != y {
        return Err(bad(format!(
            "the headings give x and y in different units ({:?}, {:?})",
            parts[0], parts[1]
        )));
    }
    Ok([x, y, z])
}

pub(crate) fn parse(path: &Path, rows: &Rows) -> Result<Raw> {
    let [xy_unit, _, z_unit] = units(path, rows)?;
    let n = rows.rows.len();
    let (mut x, mut y, mut z) = (
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
    );
    let (mut ux, mut uy, mut lines) = (
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
    );
    for r in &rows.rows {
        if r.values.len() != 3 {
            return Err(Error::parse(
                path,
                r.line,
                0,
                format!(
                    "an XYZ file has three columns (x, y, z), this row has {}",
                    r.values.len()
                ),
            ));
        }
        if !(r.values[0].is_finite() && r.values[1].is_finite()) {
            return Err(Error::parse(path, r.line, 0, "x and y must be finite"));
        }
        x.push(r.values[0]);
        y.push(r.values[1]);
        z.push(r.values[2]);
        ux.push(r.resolution[0]);
        uy.push(r.resolution[1]);
        lines.push(r.line);
    }
    let ax = axis(path, "x", &x, &ux, &lines)?;
    let ay = axis(path, "y", &y, &uy, &lines)?;
    let (nx, ny) = (ax.n, ay.n);
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
        let p = ay.index[k] * nx + ax.index[k];
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
        size: Some(Stored {
            lx: nx as f64 * ax.spacing,
            ly: ny as f64 * ay.spacing,
            unit: xy_unit,
            resolution: ax.resolution.max(ay.resolution),
        }),
        height_unit: z_unit,
        layout: Layout::Map,
        notes: Vec::new(),
        require_units: false,
    })
}

//! A line scan: columns x, h (or index, x, h; or x, h, valid), x
//! increasing; equally spaced to the precision written, else resampled
//! ([`super`] module docs, "Line scans").

use std::path::Path;

use super::units::Unit;
use super::{Raw, Stored};
use crate::error::{Error, Result};
use crate::io::text::{cells, Rows};
use crate::topography::{Layout, Note};

/// Deviation from the equally spaced grid still taken as equally spaced,
/// in units of the spacing Δ, on top of the written precision of x.
pub(crate) const SPACING_TOLERANCE: f64 = 0.01;

/// Whether the first of three columns counts the rows (0, 1, 2, … or 1,
/// 2, 3, …) of at least three rows whose second column increases: an index
/// before x and h.
pub(crate) fn index_column(r: &Rows) -> bool {
    let Some(first) = r.rows.first().and_then(|row| row.values.first()) else {
        return false;
    };
    r.rows.len() >= 3
        && (*first == 0.0 || *first == 1.0)
        && r.rows
            .iter()
            .enumerate()
            .all(|(k, row)| row.values.len() == 3 && row.values[0] == first + k as f64)
        && r.rows.windows(2).all(|w| w[1].values[1] > w[0].values[1])
}

/// Whether the third of three columns is a validity flag: a heading says
/// `valid` and every value is 0 or 1.
pub(crate) fn valid_column(r: &Rows) -> bool {
    let named = r.header.iter().any(|l| {
        headings(&l.text)
            .get(2)
            .is_some_and(|h| h.to_lowercase().contains("valid"))
    });
    named
        && r.rows
            .iter()
            .all(|row| row.values.len() == 3 && (row.values[2] == 0.0 || row.values[2] == 1.0))
}

/// The column headings of a header line: split at commas, semicolons or
/// tabs where it has them, else at spaces.
fn headings(line: &str) -> Vec<&str> {
    let parts: Vec<&str> = if line.contains([',', ';', '\t']) {
        line.split([',', ';', '\t']).collect()
    } else {
        cells(line).collect()
    };
    parts
        .into_iter()
        .map(str::trim)
        .filter(|h| !h.is_empty())
        .collect()
}

/// Which columns hold x, h and the validity flag.
struct Columns {
    x: usize,
    h: usize,
    valid: Option<usize>,
    count: usize,
}

fn columns(path: &Path, r: &Rows) -> Result<Columns> {
    let count = r.columns();
    let c = match count {
        2 => Columns {
            x: 0,
            h: 1,
            valid: None,
            count,
        },
        3 if index_column(r) => Columns {
            x: 1,
            h: 2,
            valid: None,
            count,
        },
        3 if valid_column(r) => Columns {
            x: 0,
            h: 1,
            valid: Some(2),
            count,
        },
        n => {
            return Err(Error::parse(
                path,
                r.rows[0].line,
                0,
                format!("a line scan has two columns (x, h), this row has {n}"),
            ))
        }
    };
    Ok(c)
}

/// The units the last header line's headings give x and h.
fn units(path: &Path, r: &Rows, c: &Columns) -> Result<(Unit, Unit)> {
    let Some(last) = r.header.last() else {
        return Ok((Unit::Unstated, Unit::Unstated));
    };
    let h = headings(&last.text);
    if h.len() != c.count {
        return Ok((Unit::Unstated, Unit::Unstated));
    }
    let bad = |m: String| Error::parse(path, last.line, 0, m);
    Ok((
        Unit::in_heading("the x positions", h[c.x]).map_err(bad)?,
        Unit::in_heading("the heights", h[c.h]).map_err(bad)?,
    ))
}

pub(crate) fn parse(path: &Path, r: &Rows) -> Result<Raw> {
    let c = columns(path, r)?;
    let (x_unit, h_unit) = units(path, r, &c)?;
    let (mut x, mut h, mut ulp) = (Vec::new(), Vec::new(), Vec::new());
    for row in &r.rows {
        if row.values.len() != c.count {
            return Err(Error::parse(
                path,
                row.line,
                0,
                format!(
                    "this row has {} values, the first row has {}",
                    row.values.len(),
                    c.count
                ),
            ));
        }
        let xi = row.values[c.x];
        if !xi.is_finite() {
            return Err(Error::parse(
                path,
                row.line,
                c.x + 1,
                format!("x = {xi} is not finite"),
            ));
        }
        let valid = c.valid.is_none_or(|k| row.values[k] == 1.0);
        x.push(xi);
        h.push(if valid { row.values[c.h] } else { f64::NAN });
        ulp.push(if c.x < 2 { row.resolution[c.x] } else { 0.0 });
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
    if let Some(k) = (1..n).find(|&k| x[k] <= x[k - 1]) {
        return Err(Error::parse(
            path,
            r.rows[k].line,
            c.x + 1,
            format!(
                "x = {} does not increase (the previous x is {}): a line scan's positions must increase",
                x[k],
                x[k - 1]
            ),
        ));
    }
    // Positions from the first, as SurfaceTopography takes them.
    let x0 = x[0];
    x.iter_mut().for_each(|v| *v -= x0);
    let dx = x[n - 1] / (n - 1) as f64;
    let deviation = |k: usize| (x[k] - k as f64 * dx).abs();
    let uniform = (0..n).all(|k| {
        let u = if ulp[k].is_finite() { ulp[k] } else { 0.0 };
        deviation(k) <= SPACING_TOLERANCE * dx + u
    });
    let mut notes = Vec::new();
    if !uniform {
        let max_deviation = (0..n).map(deviation).fold(0.0, f64::max) / dx;
        h = resample(&x, &h, dx);
        notes.push(Note::Resampled {
            points: n,
            max_deviation,
        });
    }
    let written = |u: f64| if u.is_finite() { u } else { 0.0 };
    Ok(Raw {
        nx: n,
        ny: 1,
        heights: h,
        size: Some(Stored {
            lx: n as f64 * dx,
            ly: 0.0,
            unit: x_unit,
            resolution: (written(ulp[0]) + written(ulp[n - 1])) / x[n - 1],
        }),
        height_unit: h_unit,
        layout: Layout::LineScans,
        notes,
        require_units: false,
    })
}

/// Heights linearly interpolated at `k·dx`, k = 0 … n−1, between the
/// points `(x, h)` (x increasing from 0), clamped to the end values as
/// numpy's `interp` does.
fn resample(x: &[f64], h: &[f64], dx: f64) -> Vec<f64> {
    let n = x.len();
    let mut j = 0;
    (0..n)
        .map(|k| {
            let g = k as f64 * dx;
            if g >= x[n - 1] {
                return h[n - 1];
            }
            while j + 1 < n && x[j + 1] <= g {
                j += 1;
            }
            if x[j] == g {
                return h[j];
            }
            let slope = (h[j + 1] - h[j]) / (x[j + 1] - x[j]);
            slope * (g - x[j]) + h[j]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resample_is_linear_interpolation() {
        let x = [0.0, 1.0, 2.5, 3.0];
        let h = [0.0, 2.0, 5.0, 6.0];
        let r = resample(&x, &h, 1.0);
        assert_eq!(r, vec![0.0, 2.0, 4.0, 6.0]);
    }
}

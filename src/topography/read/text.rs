//! Text files by content: a height matrix (one row of the map per line),
//! XYZ triples, or a line scan ([`crate::io::text`] reads the numbers).
//!
//! The kind is read from the numbers: two columns are a line scan (x, h);
//! three columns are a line scan when the first counts at least three rows
//! and the second increases (index, x, h) or the last heading says `valid`
//! (x, h, valid), XYZ triples when the
//! first two columns take few distinct values, n ≤ n_x·n_y ≤ 2n for n rows
//! with every (x, y) once; anything else is a matrix, and so is any file
//! whose header gives a map's size or shape. A matrix's header gives its
//! size and units ([`super::header`]).

use std::path::Path;

use super::header::{self, Header};
use super::units::{LengthUnit, Unit};
use super::{line, xyz, Raw, Stored};
use crate::error::{Error, Result};
use crate::io::text::Rows;

/// What a text file holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Matrix,
    Xyz,
    LineScan,
}

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let rows = crate::io::text::rows(path, b)?;
    let h = header::parse(rows.header.iter().chain(&rows.comments));
    let map_header = h.width.is_some()
        || h.height.is_some()
        || h.pixel_size.is_some()
        || h.rows.is_some()
        || h.cols.is_some()
        || h.value_unit.is_some();
    if map_header {
        return matrix(path, rows, &h);
    }
    match kind(&rows) {
        Kind::LineScan => line::parse(path, &rows),
        Kind::Xyz => xyz::parse(path, &rows),
        Kind::Matrix => matrix(path, rows, &h),
    }
}

fn kind(r: &Rows) -> Kind {
    match r.columns() {
        2 => Kind::LineScan,
        3 if line::index_column(r) || line::valid_column(r) => Kind::LineScan,
        3 if looks_like_xyz(r) => Kind::Xyz,
        _ => Kind::Matrix,
    }
}

/// Whether the first two columns of three make a grid (module docs).
fn looks_like_xyz(r: &Rows) -> bool {
    let n = r.rows.len();
    if n < 4 || r.rows.iter().any(|row| row.values.len() != 3) {
        return false;
    }
    let distinct = |k: usize| {
        let mut v: Vec<f64> = r.rows.iter().map(|row| row.values[k]).collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        v.len()
    };
    let (nx, ny) = (distinct(0), distinct(1));
    let cells = nx.saturating_mul(ny);
    if nx < 2 || ny < 2 || cells < n || cells > 2 * n {
        return false;
    }
    let mut pairs: Vec<(u64, u64)> = r
        .rows
        .iter()
        .map(|row| (row.values[0].to_bits(), row.values[1].to_bits()))
        .collect();
    pairs.sort_unstable();
    pairs.windows(2).all(|w| w[0] != w[1])
}

/// A height matrix with the size and units of its header.
fn matrix(path: &Path, rows: Rows, h: &Header) -> Result<Raw> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    let m = rows.into_matrix(path)?;
    let (ny, nx) = (m.rows, m.cols);
    if h.rows.is_some_and(|r| r != ny) || h.cols.is_some_and(|c| c != nx) {
        return Err(bad(format!(
            "the header gives h = {} rows and w = {} columns, the file holds {ny} rows of {nx}",
            h.rows.map_or("?".into(), |r| r.to_string()),
            h.cols.map_or("?".into(), |c| c.to_string()),
        )));
    }
    let mut raw = Raw::map(nx, ny, m.values);
    raw.size = size(h, nx, ny).map_err(bad)?;
    match (&h.value_unit, h.to_metres) {
        (_, Some(f)) => {
            raw.heights.iter_mut().for_each(|v| *v *= f);
            raw.height_unit = Unit::of(LengthUnit::Metre);
        }
        (Some(u), None) => {
            raw.height_unit = Unit::declared("the heights", u).map_err(bad)?;
        }
        (None, None) => {}
    }
    Ok(raw)
}

/// The size a header gives, converted to metres where it states units.
fn size(h: &Header, nx: usize, ny: usize) -> std::result::Result<Option<Stored>, String> {
    let metres = |w: &header::Written| match &w.unit {
        Unit::Stated(_, u) => (w.value * u.metres(), true),
        Unit::Unstated => (w.value, false),
    };
    let stored = |lx: f64, ly: f64, stated: bool, resolution: f64| Stored {
        lx,
        ly,
        unit: if stated {
            Unit::of(LengthUnit::Metre)
        } else {
            Unit::Unstated
        },
        resolution,
    };
    match (&h.width, &h.height, &h.pixel_size) {
        (Some(w), Some(v), _) => {
            let ((lx, sx), (ly, sy)) = (metres(w), metres(v));
            if sx != sy {
                return Err("the header gives a unit for one side and not the other".into());
            }
            let r = w.relative_resolution.max(v.relative_resolution);
            Ok(Some(stored(lx, ly, sx, r)))
        }
        (Some(_), None, _) | (None, Some(_), _) => {
            Err("the header gives only one of the width and the height".into())
        }
        (None, None, Some(p)) => {
            let (d, s) = metres(p);
            Ok(Some(stored(
                nx as f64 * d,
                ny as f64 * d,
                s,
                p.relative_resolution,
            )))
        }
        (None, None, None) => Ok(None),
    }
}

//! Plain text: a matrix of heights (one row of the map per line), and the
//! row reader shared with the XYZ and line-scan formats.
//!
//! Cells are separated by whitespace, commas or semicolons; blank lines and
//! text after `#` are ignored; `nan` marks an undefined point. The first line
//! may be a header (skipped when it starts with a letter and does not parse
//! as numbers).

use std::path::Path;

use super::Raw;
use crate::error::{Error, Result};
use crate::topography::Layout;

/// Rows of numbers with their 1-based line numbers.
pub(crate) type Rows = Vec<(usize, Vec<f64>)>;

/// The numeric rows of a text file.
pub(crate) fn rows(path: &Path, b: &[u8]) -> Result<Rows> {
    let text = std::str::from_utf8(b)
        .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
    let mut out = Vec::new();
    let mut first = true;
    for (ln, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let cells: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|t| !t.is_empty())
            .collect();
        if first
            && line.starts_with(|c: char| c.is_alphabetic())
            && cells.iter().any(|c| c.parse::<f64>().is_err())
        {
            first = false;
            continue;
        }
        first = false;
        let mut v = Vec::with_capacity(cells.len());
        for (col, tok) in cells.iter().enumerate() {
            v.push(tok.parse::<f64>().map_err(|_| {
                Error::parse(path, ln + 1, col + 1, format!("{tok:?} is not a number"))
            })?);
        }
        out.push((ln + 1, v));
    }
    if out.is_empty() {
        return Err(Error::parse(path, 0, 0, "no numbers in the file"));
    }
    Ok(out)
}

/// The number of cells of the first data line, if the file is text.
pub(crate) fn columns(b: &[u8]) -> Option<usize> {
    rows(Path::new(""), b).ok()?.first().map(|r| r.1.len())
}

/// A text matrix: every row the same number of columns.
pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let rows = rows(path, b)?;
    let nx = rows[0].1.len();
    let mut heights = Vec::with_capacity(nx * rows.len());
    for (ln, r) in &rows {
        if r.len() != nx {
            return Err(Error::parse(
                path,
                *ln,
                0,
                format!("row has {} values, the first row has {nx}", r.len()),
            ));
        }
        heights.extend_from_slice(r);
    }
    Ok(Raw {
        nx,
        ny: rows.len(),
        heights,
        size: None,
        layout: Layout::Map,
    })
}

//! Text files of numbers: height matrices, columns (x, h), XYZ triples and
//! spectrum tables all go through [`rows`].
//!
//! # Rules
//! - Encoding: UTF-8 (with or without a byte-order mark), UTF-16 with a
//!   byte-order mark (little- or big-endian), else Latin-1 (ISO 8859-1, every
//!   byte one character, as old instrument software writes `µ` = 0xB5).
//!   Bytes with NUL characters outside UTF-16 are binary data, not text.
//! - Cells are separated by whitespace, commas or semicolons; empty cells
//!   (`1,2,,`) are dropped. Text after `#` is a comment. Blank lines are
//!   skipped. `nan` (any case) marks an undefined value.
//! - Header: every line before the first line of numbers (any number of
//!   them), and a leading line holding one number (a count) when the lines
//!   after it hold more. After the first line of numbers, a cell that is
//!   not a number is an error at its line and column.

use std::borrow::Cow;
use std::path::Path;

use super::Matrix;
use crate::error::{Error, Result};

/// A line of text with its 1-based line number.
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    /// 1-based line number.
    pub line: usize,
    /// The text, trimmed (for comments: after the `#`).
    pub text: String,
}

/// A line of numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// 1-based line number.
    pub line: usize,
    /// The numbers, in the order written.
    pub values: Vec<f64>,
    /// One unit in the last written digit of the first two cells
    /// ([`resolution`]) when written with a decimal point or an exponent; 0
    /// for an integer (taken as exact: `0 1 2` are indices, not rounded
    /// positions); NaN where there is no such cell.
    pub resolution: [f64; 2],
}

/// The numbers of a text file with its header and comment lines.
#[derive(Debug, Clone, PartialEq)]
pub struct Rows {
    /// Lines before the numbers (module docs).
    pub header: Vec<Line>,
    /// The text after `#` of every line that has one.
    pub comments: Vec<Line>,
    /// The lines of numbers (at least one).
    pub rows: Vec<Row>,
}

impl Rows {
    /// The number of cells of the first line of numbers.
    pub(crate) fn columns(&self) -> usize {
        self.rows.first().map_or(0, |r| r.values.len())
    }

    /// The numbers as a matrix, one row per line.
    ///
    /// # Errors
    /// [`Error::Parse`] at the first line whose number of cells differs from
    /// the first line's.
    pub fn into_matrix(self, path: &Path) -> Result<Matrix> {
        let cols = self.columns();
        let mut values = Vec::with_capacity(cols * self.rows.len());
        for r in &self.rows {
            if r.values.len() != cols {
                return Err(Error::parse(
                    path,
                    r.line,
                    0,
                    format!(
                        "row has {} values, the first row has {cols}",
                        r.values.len()
                    ),
                ));
            }
            values.extend_from_slice(&r.values);
        }
        Ok(Matrix {
            rows: self.rows.len(),
            cols,
            values,
        })
    }
}

/// Decode the bytes of a text file (module docs: UTF-8, UTF-16 with a
/// byte-order mark, else Latin-1).
///
/// # Errors
/// [`Error::Parse`] naming the file for binary data (a NUL byte outside
/// UTF-16), UTF-16 that ends within a character or holds an unpaired
/// surrogate, or a UTF-8 byte-order mark followed by invalid UTF-8.
///
/// # Examples
/// ```
/// use std::path::Path;
/// use persson::io::text::decode;
/// # fn main() -> persson::Result<()> {
/// let utf16: Vec<u8> = [0xFF, 0xFE].into_iter()
///     .chain("1 µm".encode_utf16().flat_map(u16::to_le_bytes)).collect();
/// assert_eq!(decode(Path::new("a.csv"), &utf16)?, "1 µm");
/// assert_eq!(decode(Path::new("b.csv"), b"1 \xB5m")?, "1 µm"); // Latin-1
/// # Ok(()) }
/// ```
pub fn decode<'a>(path: &Path, b: &'a [u8]) -> Result<Cow<'a, str>> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    if let Some(rest) = b.strip_prefix(b"\xEF\xBB\xBF") {
        return std::str::from_utf8(rest)
            .map(Cow::Borrowed)
            .map_err(|e| bad(format!("a UTF-8 byte-order mark, then invalid UTF-8 ({e})")));
    }
    let utf16 = |rest: &[u8], big: bool| -> Result<Cow<'a, str>> {
        if !rest.len().is_multiple_of(2) {
            return Err(bad(
                "UTF-16 text that ends within a character (truncated?)".into()
            ));
        }
        let units = rest.chunks_exact(2).map(|c| {
            if big {
                u16::from_be_bytes([c[0], c[1]])
            } else {
                u16::from_le_bytes([c[0], c[1]])
            }
        });
        char::decode_utf16(units)
            .collect::<std::result::Result<String, _>>()
            .map(Cow::Owned)
            .map_err(|e| bad(format!("invalid UTF-16 text ({e})")))
    };
    if let Some(rest) = b.strip_prefix(b"\xFF\xFE") {
        return utf16(rest, false);
    }
    if let Some(rest) = b.strip_prefix(b"\xFE\xFF") {
        return utf16(rest, true);
    }
    if let Some(k) = b.iter().position(|&c| c == 0) {
        return Err(bad(format!(
            "not text (UTF-8, UTF-16 or Latin-1): binary data (a NUL byte at byte {k})"
        )));
    }
    Ok(match std::str::from_utf8(b) {
        Ok(s) => Cow::Borrowed(s),
        Err(_) => Cow::Owned(b.iter().map(|&c| char::from(c)).collect()),
    })
}

/// One unit in the last written digit of a number as written: `0.2` → 0.1,
/// `1.3381669e+01` → 1e-6, `100` → 1; NaN for text that is not a plain
/// decimal number (`nan`, `inf`).
///
/// # Examples
/// ```
/// use persson::io::text::resolution;
/// assert_eq!(resolution("0.25"), 0.01);
/// assert!((resolution("1.3381669e+01") - 1e-6).abs() < 1e-21);
/// assert!(resolution("nan").is_nan());
/// ```
pub fn resolution(token: &str) -> f64 {
    let t = token.trim_start_matches(['+', '-']);
    let (mantissa, exponent) = match t.find(['e', 'E']) {
        Some(k) => (&t[..k], t[k + 1..].parse::<i32>().ok()),
        None => (t, Some(0)),
    };
    let Some(exponent) = exponent else {
        return f64::NAN;
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits = |s: &str| s.bytes().all(|c| c.is_ascii_digit());
    if int.is_empty() && frac.is_empty() || !digits(int) || !digits(frac) {
        return f64::NAN;
    }
    let decimals = i32::try_from(frac.len()).unwrap_or(i32::MAX);
    10f64.powi(exponent.saturating_sub(decimals))
}

/// Split a line into cells (whitespace, commas, semicolons; empty cells
/// dropped).
pub fn cells(line: &str) -> impl Iterator<Item = &str> {
    line.split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .filter(|t| !t.is_empty())
}

/// A line of numbers, or `None` when a cell is not a number.
fn numbers(line: &str) -> Option<(Vec<f64>, [f64; 2])> {
    let mut v = Vec::new();
    let mut res = [f64::NAN; 2];
    for (k, tok) in cells(line).enumerate() {
        v.push(tok.parse::<f64>().ok()?);
        if k < 2 {
            res[k] = if tok.contains(['.', 'e', 'E']) {
                resolution(tok)
            } else {
                0.0
            };
        }
    }
    (!v.is_empty()).then_some((v, res))
}

/// The numbers of a text file with its header and comments (module docs).
///
/// # Errors
/// As [`decode`]; [`Error::Parse`] with the line and column of a cell that
/// is not a number after the first line of numbers, or a file without
/// numbers.
///
/// # Examples
/// ```
/// use std::path::Path;
/// use persson::io::text::rows;
/// # fn main() -> persson::Result<()> {
/// let r = rows(Path::new("scan.csv"), b"Scan Data\nLateral um,Raw um,\n0.0,1.5,,\n0.2,-2,,\n")?;
/// assert_eq!(r.header.len(), 2);
/// assert_eq!(r.rows[1].values, vec![0.2, -2.0]);
/// assert_eq!(r.rows[1].resolution[0], 0.1);
/// # Ok(()) }
/// ```
pub fn rows(path: &Path, b: &[u8]) -> Result<Rows> {
    let text = decode(path, b)?;
    let mut out = Rows {
        header: Vec::new(),
        comments: Vec::new(),
        rows: Vec::new(),
    };
    for (k, raw) in text.lines().enumerate() {
        let ln = k + 1;
        let (data, comment) = match raw.split_once('#') {
            Some((d, c)) => (d, Some(c)),
            None => (raw, None),
        };
        if let Some(c) = comment {
            out.comments.push(Line {
                line: ln,
                text: c.trim().to_string(),
            });
        }
        let data = data.trim();
        if data.is_empty() {
            continue;
        }
        match numbers(data) {
            Some((values, resolution)) => out.rows.push(Row {
                line: ln,
                values,
                resolution,
            }),
            None if out.rows.is_empty() => out.header.push(Line {
                line: ln,
                text: data.to_string(),
            }),
            None => return Err(not_a_number(path, ln, data)),
        }
    }
    // A leading count ("23") before the lines of numbers is header.
    while out.rows.len() >= 2 && out.rows[0].values.len() == 1 && out.rows[1].values.len() > 1 {
        let r = out.rows.remove(0);
        let text = text
            .lines()
            .nth(r.line - 1)
            .unwrap_or("")
            .trim()
            .to_string();
        out.header.push(Line { line: r.line, text });
    }
    if out.rows.is_empty() {
        return Err(Error::parse(path, 0, 0, "no numbers in the file"));
    }
    typo_in_header(path, &out)?;
    Ok(out)
}

/// A last header line that is a line of numbers but for one cell that
/// starts like a number (`2.O`) is a damaged first row, not a header: an
/// error at that cell.
fn typo_in_header(path: &Path, r: &Rows) -> Result<()> {
    let Some(last) = r.header.last() else {
        return Ok(());
    };
    let n = cells(&last.text).count();
    let numeric = cells(&last.text)
        .filter(|t| t.parse::<f64>().is_ok())
        .count();
    let mangled = cells(&last.text).any(|t| {
        t.parse::<f64>().is_err()
            && t.starts_with(|c: char| c.is_ascii_digit() || "+-.".contains(c))
    });
    if n >= 2 && n == r.columns() && numeric + 1 == n && mangled {
        return Err(not_a_number(path, last.line, &last.text));
    }
    Ok(())
}

/// The error at the first cell of `data` that is not a number.
fn not_a_number(path: &Path, ln: usize, data: &str) -> Error {
    let (col, tok) = cells(data)
        .enumerate()
        .find(|(_, t)| t.parse::<f64>().is_err())
        .unwrap_or((0, data));
    Error::parse(path, ln, col + 1, format!("{tok:?} is not a number"))
}

/// A table of named columns, one row per line (the tabulated spectra and
/// the friction inputs): rows of between `names.len() − optional` and
/// `names.len()` numbers, split as [`cells`]; blank lines and lines starting
/// with `#` are skipped, and the first other line is a header when it
/// starts with a letter and a cell is not a number (`nan` is one). `names`
/// name the columns in messages.
///
/// # Errors
/// [`Error::Parse`] naming the file and the 1-based line (and the column of
/// a cell that is not a number, with its field): a row with too few or too
/// many cells, a cell that is not a number, a table without rows.
pub(crate) fn columns(
    path: &Path,
    text: &str,
    names: &[&str],
    optional: usize,
) -> Result<Vec<Row>> {
    let (min, max) = (names.len() - optional, names.len());
    let mut rows = Vec::new();
    let mut first = true;
    for (n, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let cells: Vec<&str> = cells(line).collect();
        let header = first
            && cells.iter().any(|c| c.parse::<f64>().is_err())
            && line.starts_with(|ch: char| ch.is_alphabetic());
        first = false;
        if header {
            continue;
        }
        if cells.len() < min || cells.len() > max {
            let want = if min == max {
                format!("{max}")
            } else {
                format!("{min} to {max}")
            };
            let found = cells.len();
            return Err(Error::parse(
                path,
                n + 1,
                0,
                format!(
                    "expected {want} columns ({}), found {found}",
                    names.join(", ")
                ),
            ));
        }
        let mut values = Vec::with_capacity(cells.len());
        for (j, cell) in cells.iter().enumerate() {
            let v = cell.parse::<f64>().map_err(|_| {
                let col = raw.find(cell).map_or(0, |c| c + 1);
                Error::parse(
                    path,
                    n + 1,
                    col,
                    format!("{}: '{cell}' is not a number", names[j]),
                )
            })?;
            values.push(v);
        }
        let resolution = std::array::from_fn(|k| match cells.get(k) {
            Some(t) if t.contains(['.', 'e', 'E']) => resolution(t),
            Some(_) => 0.0,
            None => f64::NAN,
        });
        rows.push(Row {
            line: n + 1,
            values,
            resolution,
        });
    }
    if rows.is_empty() {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("no data rows (expected columns {})", names.join(", ")),
        ));
    }
    Ok(rows)
}

/// A text matrix: one row per line of numbers, every row the same length;
/// header lines are skipped (module docs).
///
/// # Errors
/// As [`rows`] and [`Rows::into_matrix`].
///
/// # Examples
/// ```
/// use std::path::Path;
/// use persson::io::text::matrix;
/// # fn main() -> persson::Result<()> {
/// let m = matrix(Path::new("h.txt"), b"# heights\n1 2 3\n4 5 nan\n")?;
/// assert_eq!((m.rows, m.cols), (2, 3));
/// assert!(m.values[5].is_nan());
/// # Ok(()) }
/// ```
pub fn matrix(path: &Path, b: &[u8]) -> Result<Matrix> {
    rows(path, b)?.into_matrix(path)
}

//! numpy `.npy` files (format versions 1–3) holding a 2-D float array.
//!
//! Read: dtype float32 or float64 (`'<f4'`, `'<f8'`, `'>f4'`, `'>f8'`,
//! native `'=f8'`), C or Fortran order, rank 2. Written: float64,
//! little-endian, C order, version 1.0, atomically.
//!
//! # Format
//! ```text
//! \x93NUMPY  major minor  header_len (u16 LE, v1; u32 LE, v2/3)  header  data
//! header = "{'descr': '<f8', 'fortran_order': False, 'shape': (rows, cols), }" + padding + '\n'
//! ```
//! The data follow the header, `rows·cols` items; in Fortran order column
//! by column (element `(i, j)` at `j·rows + i`), else row by row.
//!
//! # References
//! numpy, "A Simple File Format for NumPy Arrays" (NEP 1,
//! numpy.org/neps/nep-0001-npy-format.html).

use std::path::Path;

use super::Matrix;
use crate::error::{Error, Result};

/// The first six bytes of every `.npy` file.
pub(crate) const MAGIC: &[u8] = b"\x93NUMPY";

/// Byte order and item size of the stored floats.
#[derive(Clone, Copy)]
struct Dtype {
    big_endian: bool,
    size: usize,
}

/// Read a 2-D float `.npy` array from bytes in memory; `path` names it in
/// errors.
///
/// # Errors
/// [`Error::Parse`] naming the file for a missing magic string, an
/// unsupported version, a truncated or unreadable header, a dtype other
/// than float32/float64 (integers are named as such), a rank other than 2,
/// a shape too large to address, or a data block of the wrong length.
///
/// # Examples
/// ```
/// use std::path::Path;
/// use persson::io::npy;
/// # fn main() -> persson::Result<()> {
/// let bytes = npy::encode(2, 3, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0])?;
/// let m = npy::parse(Path::new("a.npy"), &bytes)?;
/// assert_eq!((m.rows, m.cols), (2, 3));
/// assert_eq!(m.values[1 * 3 + 2], 6.0); // row 1, column 2
/// # Ok(()) }
/// ```
pub fn parse(path: &Path, b: &[u8]) -> Result<Matrix> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    let (header, data) = split(b).map_err(bad)?;
    let dtype = dtype(header).map_err(bad)?;
    let fortran = match dict_value(header, "fortran_order") {
        Some("True") => true,
        Some("False") => false,
        _ => return Err(bad("header has no valid 'fortran_order'".into())),
    };
    let (rows, cols) = shape(header).map_err(bad)?;
    let count = rows
        .checked_mul(cols)
        .filter(|c| c.checked_mul(dtype.size).is_some())
        .ok_or_else(|| bad(format!("shape ({rows}, {cols}) is too large")))?;
    if data.len() != count * dtype.size {
        return Err(bad(format!(
            "data holds {} bytes, shape ({rows}, {cols}) of {}-byte floats needs {}",
            data.len(),
            dtype.size,
            count * dtype.size
        )));
    }
    let flat = decode(data, dtype);
    let m = if fortran {
        // Stored column by column: the transpose of a C-order cols × rows array.
        Matrix {
            rows: cols,
            cols: rows,
            values: flat,
        }
        .transposed()
    } else {
        Matrix {
            rows,
            cols,
            values: flat,
        }
    };
    Ok(m)
}

/// The header text and the data bytes.
fn split(b: &[u8]) -> std::result::Result<(&str, &[u8]), String> {
    if !b.starts_with(MAGIC) || b.len() < 10 {
        return Err("not a .npy file (magic string \\x93NUMPY missing)".into());
    }
    let (hlen, start) = match b[6] {
        1 => (usize::from(u16::from_le_bytes([b[8], b[9]])), 10),
        2 | 3 if b.len() >= 12 => (
            u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize,
            12usize,
        ),
        v => return Err(format!(".npy format version {v} not supported (1, 2 or 3)")),
    };
    let header = start
        .checked_add(hlen)
        .and_then(|end| b.get(start..end))
        .ok_or_else(|| "truncated .npy header".to_string())?;
    let header = std::str::from_utf8(header).map_err(|_| ".npy header is not text".to_string())?;
    Ok((header, &b[start + hlen..]))
}

fn dtype(header: &str) -> std::result::Result<Dtype, String> {
    let descr = dict_value(header, "descr").ok_or("header has no 'descr'")?;
    let descr = descr.trim_matches(|c| c == '\'' || c == '"');
    let mut ch = descr.chars();
    let order = ch.next().unwrap_or(' ');
    let kind = ch.next().unwrap_or(' ');
    let size = ch.as_str().parse::<usize>().unwrap_or(0);
    let big_endian = match order {
        '<' | '=' | '|' => false,
        '>' => true,
        _ => return Err(format!("unreadable dtype {descr:?}")),
    };
    match (kind, size) {
        ('f', 4 | 8) => Ok(Dtype { big_endian, size }),
        ('i' | 'u' | 'b', _) => Err(format!(
            "dtype {descr:?} holds integers: heights must be float32 or float64 \
             (convert with numpy's .astype(float) and give the height unit)"
        )),
        _ => Err(format!(
            "dtype {descr:?} not supported: need float64 ('<f8', '>f8') or float32 ('<f4', '>f4')"
        )),
    }
}

fn shape(header: &str) -> std::result::Result<(usize, usize), String> {
    let shape = dict_value(header, "shape").ok_or("header has no 'shape'")?;
    let dims: Vec<usize> = shape
        .trim_matches(|c| c == '(' || c == ')')
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(str::parse::<usize>)
        .collect::<std::result::Result<_, _>>()
        .map_err(|_| format!("unreadable shape {shape}"))?;
    match dims[..] {
        [r, c] => Ok((r, c)),
        _ => Err(format!(
            "array of rank {} (shape {shape}): a height map is a 2-D array",
            dims.len()
        )),
    }
}

fn decode(data: &[u8], dtype: Dtype) -> Vec<f64> {
    // One loop per byte order and size, so that the common little-endian
    // float64 is a plain copy the compiler vectorises.
    fn each<const N: usize>(data: &[u8], f: impl Fn([u8; N]) -> f64) -> Vec<f64> {
        data.as_chunks::<N>().0.iter().map(|&c| f(c)).collect()
    }
    match (dtype.size, dtype.big_endian) {
        (8, false) => each(data, f64::from_le_bytes),
        (8, true) => each(data, f64::from_be_bytes),
        (_, false) => each(data, |b| f64::from(f32::from_le_bytes(b))),
        (_, true) => each(data, |b| f64::from(f32::from_be_bytes(b))),
    }
}

/// The raw text of `'key': value` in a Python dict literal (the value up to
/// the next top-level comma or brace).
fn dict_value<'a>(header: &'a str, key: &str) -> Option<&'a str> {
    let k = header
        .find(&format!("'{key}'"))
        .or_else(|| header.find(&format!("\"{key}\"")))?;
    let rest = &header[k + key.len() + 2..];
    let rest = rest.trim_start().strip_prefix(':')?.trim_start();
    let mut depth = 0i32;
    for (i, c) in rest.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' | '}' if depth == 0 => return Some(rest[..i].trim()),
            _ => {}
        }
    }
    None
}

/// The bytes of a `rows × cols` row-major float64 array as `.npy` (version
/// 1.0, little-endian, C order; the data start on a 64-byte boundary).
///
/// # Errors
/// [`Error::Inconsistent`] when `data` does not hold `rows·cols` values.
pub fn encode(rows: usize, cols: usize, data: &[f64]) -> Result<Vec<u8>> {
    if Some(data.len()) != rows.checked_mul(cols) {
        return Err(Error::Inconsistent {
            name: "npy data".into(),
            requirement: format!("{rows}×{cols} values, got {}", data.len()),
        });
    }
    let mut header =
        format!("{{'descr': '<f8', 'fortran_order': False, 'shape': ({rows}, {cols}), }}");
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut out = Vec::with_capacity(10 + header.len() + 8 * data.len());
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&[1, 0]);
    // A shape's text is far below 64 kB.
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for v in data {
        out.extend_from_slice(&v.to_le_bytes());
    }
    Ok(out)
}

/// Write a `rows × cols` row-major float64 array as `.npy` ([`encode`]),
/// atomically ([`super::write_atomic`]).
///
/// # Errors
/// As [`encode`]; [`Error::Io`] naming the file.
pub fn write(path: &Path, rows: usize, cols: usize, data: &[f64]) -> Result<()> {
    super::write_atomic(path, &encode(rows, cols, data)?)
}

//! numpy `.npy` (format versions 1–3): float32/float64, either byte order,
//! C or Fortran order, rank 2 (`shape = (ny, nx)`).

use std::path::Path;

use super::Raw;
use crate::error::{Error, Result};
use crate::topography::Layout;

pub(crate) const MAGIC: &[u8] = b"\x93NUMPY";

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    if !b.starts_with(MAGIC) || b.len() < 10 {
        return Err(bad(
            "not a .npy file (magic string \\x93NUMPY missing)".into()
        ));
    }
    let (hlen, start) = match b[6] {
        1 => (u16::from_le_bytes([b[8], b[9]]) as usize, 10),
        2 | 3 if b.len() >= 12 => (u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize, 12),
        v => {
            return Err(bad(format!(
                ".npy format version {v} not supported (1, 2 or 3)"
            )))
        }
    };
    let header = b
        .get(start..start + hlen)
        .ok_or_else(|| bad("truncated .npy header".into()))?;
    let header = std::str::from_utf8(header).map_err(|_| bad(".npy header is not text".into()))?;
    let descr = dict_value(header, "descr").ok_or_else(|| bad("header has no 'descr'".into()))?;
    let descr = descr.trim_matches(|c| c == '\'' || c == '"');
    let (order, kind, size) = {
        let mut ch = descr.chars();
        let o = ch.next().unwrap_or(' ');
        let k = ch.next().unwrap_or(' ');
        (o, k, ch.as_str().parse::<usize>().unwrap_or(0))
    };
    let big = match order {
        '<' | '=' | '|' => false,
        '>' => true,
        _ => return Err(bad(format!("unreadable dtype {descr:?}"))),
    };
    match (kind, size) {
        ('f', 4 | 8) => {}
        ('i' | 'u' | 'b', _) => {
            return Err(bad(format!(
                "dtype {descr:?} holds integers: heights must be float32 or float64 \
                 (convert with numpy's .astype(float) and give the height unit)"
            )))
        }
        _ => {
            return Err(bad(format!(
            "dtype {descr:?} not supported: need float64 ('<f8', '>f8') or float32 ('<f4', '>f4')"
        )))
        }
    }
    let fortran = match dict_value(header, "fortran_order") {
        Some("True") => true,
        Some("False") => false,
        _ => return Err(bad("header has no valid 'fortran_order'".into())),
    };
    let shape = dict_value(header, "shape").ok_or_else(|| bad("header has no 'shape'".into()))?;
    let dims: Vec<usize> = shape
        .trim_matches(|c| c == '(' || c == ')')
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse::<usize>())
        .collect::<std::result::Result<_, _>>()
        .map_err(|_| bad(format!("unreadable shape {shape}")))?;
    let (rows, cols) = match dims[..] {
        [r, c] => (r, c),
        _ => {
            return Err(bad(format!(
                "array of rank {} (shape {shape}): a height map has rank 2",
                dims.len()
            )))
        }
    };
    let count = rows
        .checked_mul(cols)
        .filter(|c| c.checked_mul(size).is_some())
        .ok_or_else(|| bad(format!("shape ({rows}, {cols}) is too large")))?;
    let data = &b[start + hlen..];
    if data.len() != count * size {
        return Err(bad(format!(
            "data holds {} bytes, shape ({rows}, {cols}) of {size}-byte floats needs {}",
            data.len(),
            count * size
        )));
    }
    let flat: Vec<f64> = if size == 8 {
        data.chunks_exact(8)
            .map(|c| {
                let a = [c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]];
                if big {
                    f64::from_be_bytes(a)
                } else {
                    f64::from_le_bytes(a)
                }
            })
            .collect()
    } else {
        data.chunks_exact(4)
            .map(|c| {
                let a = [c[0], c[1], c[2], c[3]];
                f64::from(if big {
                    f32::from_be_bytes(a)
                } else {
                    f32::from_le_bytes(a)
                })
            })
            .collect()
    };
    let heights = if fortran {
        let mut t = vec![0.0; count];
        for i in 0..rows {
            for j in 0..cols {
                t[i * cols + j] = flat[j * rows + i];
            }
        }
        t
    } else {
        flat
    };
    Ok(Raw {
        nx: cols,
        ny: rows,
        heights,
        size: None,
        layout: Layout::Map,
    })
}

/// The raw text of `'key': value` in a Python dict literal.
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

/// Write a `rows × cols` row-major float64 array as `.npy` (version 1.0, C
/// order, little-endian), atomically.
///
/// # Errors
/// Wrong length ([`Error::Inconsistent`]); [`Error::Io`] naming the file.
pub fn write_npy(path: &Path, rows: usize, cols: usize, data: &[f64]) -> Result<()> {
    if data.len() != rows * cols {
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
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for v in data {
        out.extend_from_slice(&v.to_le_bytes());
    }
    crate::io::write_atomic(path, &out)
}

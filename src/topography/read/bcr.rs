//! BCR-STM and BCRF files (`.bcr`, `.bcrf`: Image Metrology's SPIP and the
//! scanning-probe software writing for it).
//!
//! A text header of `key = value` lines (`%` and `#` lines are comments),
//! Latin-1 or UTF-16 little-endian (the `_unicode` variants), that starts
//! with `fileformat = bcrstm` (int16 values) or `fileformat = bcrf`
//! (float32 values) and states its own length, `headersize` (characters;
//! two bytes each in UTF-16). Then `ypixels` rows of `xpixels` values, x
//! fastest, little-endian where `intelmode = 1`:
//!
//! ```text
//! h[iy, ix] = bit2nm · value_k   (zunit),   k = iy·xpixels + ix
//! Lx = xlength,  Ly = ylength   (xunit, yunit)
//! ```
//!
//! A value equal to `voidpixels` (within float32 rounding of its decimal
//! text) is undefined.
//!
//! # References
//! The layout as SurfaceTopography's `IO/BCR.py` reads it (which also
//! scales the values by `bit2nm` in the unit `zunit`).

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{not_a_length, LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::Result;

/// The header's opening, as text.
pub(crate) const MAGIC: &str = "fileformat = bcr";
/// A value within this of `voidpixels` (relative) is undefined: the marker
/// is written as decimal text, the values as float32.
const VOID_RELATIVE: f64 = 1.5e-7;

/// Whether `b` starts with the header of a BCR-STM or BCRF file, in
/// Latin-1 or UTF-16 LE.
pub(crate) fn is_bcr(b: &[u8]) -> bool {
    b.starts_with(MAGIC.as_bytes()) || b.starts_with(&utf16(MAGIC))
}

fn utf16(s: &str) -> Vec<u8> {
    s.encode_utf16().flat_map(u16::to_le_bytes).collect()
}

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let f = Bin::new(b, path, "BCR-STM/BCRF");
    let wide = b.starts_with(&utf16(MAGIC));
    if !wide && !b.starts_with(MAGIC.as_bytes()) {
        return Err(f.bad("the file does not start with fileformat = bcrstm or bcrf"));
    }
    let text = |bytes: &[u8]| -> String {
        if wide {
            String::from_utf16_lossy(&super::bin::utf16_units(bytes))
        } else {
            super::bin::latin1(bytes)
        }
    };
    // The header's length is one of its first fields.
    let head = text(&b[..b.len().min(4096)]);
    let fields = |t: &str| -> Vec<(String, String)> {
        t.lines()
            .map(str::trim)
            .filter(|l| !l.starts_with('%') && !l.starts_with('#'))
            .filter_map(|l| l.split_once('='))
            .map(|(k, v)| {
                (
                    k.trim().to_string(),
                    v.trim().trim_end_matches('\0').trim().to_string(),
                )
            })
            .collect()
    };
    let first = fields(&head);
    let find = |all: &[(String, String)], key: &str| -> Result<String> {
        all.iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.clone())
            .ok_or_else(|| f.bad(format!("no header field {key}")))
    };
    let chars: usize = find(&first, "headersize")?
        .parse()
        .map_err(|_| f.bad("headersize: not a count"))?;
    let header_bytes = if wide { 2 * chars } else { chars };
    let all = fields(&text(f.slice(0, header_bytes, "the header")?));
    let count = |key: &str| -> Result<usize> {
        let v = find(&all, key)?;
        v.parse()
            .map_err(|_| f.bad(format!("{key} = {v:?}: not a count")))
    };
    let number = |key: &str| -> Result<(f64, f64)> {
        let v = find(&all, key)?;
        let x: f64 = v
            .parse()
            .map_err(|_| f.bad(format!("{key} = {v:?}: not a number")))?;
        Ok((x, crate::io::text::resolution(&v) / x.abs()))
    };
    let (nx, ny) = (count("xpixels")?, count("ypixels")?);
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!("xpixels × ypixels = {nx} × {ny}: both must be > 0")));
    }
    let float = find(&all, "fileformat")?.starts_with("bcrf");
    let little = count("intelmode").unwrap_or(1) == 1;
    let item = if float { 4 } else { 2 };
    let len = product(nx, ny, item)
        .ok_or_else(|| f.bad(format!("xpixels × ypixels = {nx} × {ny} is too large")))?;
    let data = f.slice(header_bytes, len, "the values")?;
    let scale = number("bit2nm").map_or(1.0, |(v, _)| v);
    let void = number("voidpixels").ok().map(|(v, _)| v);
    let heights = data
        .chunks_exact(item)
        .map(|c| {
            let v = match (float, little) {
                (true, true) => f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])),
                (true, false) => f64::from(f32::from_be_bytes([c[0], c[1], c[2], c[3]])),
                (false, true) => f64::from(i16::from_le_bytes([c[0], c[1]])),
                (false, false) => f64::from(i16::from_be_bytes([c[0], c[1]])),
            };
            match void {
                Some(m) if (v - m).abs() <= VOID_RELATIVE * m.abs() => f64::NAN,
                _ => v * scale,
            }
        })
        .collect();
    let unit = |key: &str, what: &str| -> Result<Unit> {
        let t = find(&all, key)?;
        LengthUnit::parse(&t)
            .map(|u| Unit::Stated(t.clone(), u))
            .ok_or_else(|| f.bad(not_a_length(what, &t)))
    };
    let (lx, rx) = number("xlength")?;
    let (ly, ry) = number("ylength")?;
    let (xu, yu) = (unit("xunit", "lengths")?, unit("yunit", "lengths")?);
    if xu != yu {
        return Err(f.bad("xunit and yunit differ"));
    }
    Ok(Raw {
        size: Some(Stored {
            lx,
            ly,
            unit: xu,
            resolution: rx.max(ry),
        }),
        height_unit: unit("zunit", "heights")?,
        ..Raw::map(nx, ny, heights)
    })
}

//! Wyko `.opd` (the Vision software of Veeco/Bruker Wyko white-light
//! interferometers).
//!
//! Little-endian. Two bytes, then a directory of 24-byte entries
//!
//! ```text
//! 16 bytes name (NUL-padded), i16 type, i32 length, u16 attribute
//! ```
//!
//! the first named `Directory` (its length: the directory's bytes). The
//! blocks follow the directory in its order, each `length` bytes (none where
//! `length ≤ 0`). Arrays (type 3) are
//!
//! ```text
//! u16 nx, u16 ny, u16 item size (1: u8, 2: i16, 4: f32), nx × ny values, y fastest
//! ```
//!
//! stored with the last row first: value `ix·ny + (ny − 1 − iy)` is
//! `h[ix, iy]`, as SurfaceTopography and Gwyddion orient them. Scalars:
//! `Wavelength` (f32, nm), `Mult` (default 1), `Aspect` (default 1),
//! `Pixel_size` (f32, mm); types 6 and 7 of 2 bytes are i16, type 6 of 4
//! bytes i32, type 7 of 4 bytes f32, type 8 f64, type 12 i32. Then
//!
//! ```text
//! h = value · Wavelength / Mult · 1e-6                  (mm)
//! Lx = nx · Pixel_size,   Ly = ny · Pixel_size · Aspect   (mm)
//! ```
//!
//! (without `Pixel_size` the caller gives the size). A value that is not
//! finite or at least 1e38 (compared as f32), or at least 32766 (i16), is undefined.
//!
//! # Channels
//! One per array, named by its block: `RAW DATA`, `RAW_DATA`, `OPD`, `Raw`
//! and `SAMPLE_DATA` hold heights (the first of them is the default, as
//! SurfaceTopography reads); the others (`SecArr_0`, the u8 `Image`) are
//! read by name or index as raw values with no unit (the caller gives the
//! height unit).
//!
//! # References
//! The layout as SurfaceTopography's `IO/OPD.py` and Gwyddion's
//! `modules/file/opdfile.c` read it (no public description by Bruker).

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{channel, Raw, ReadOptions, Stored};
use crate::error::Result;

const MAGIC: &[u8] = b"Directory";
/// The bytes before the directory.
const PRELUDE: usize = 2;
const ENTRY: usize = 24;
const TYPE_ARRAY: i16 = 3;
/// Array names holding heights (SurfaceTopography's list).
const HEIGHT_ARRAYS: &[&str] = &["RAW DATA", "RAW_DATA", "OPD", "Raw", "SAMPLE_DATA"];

/// Whether `bytes` start as this format's files do.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes
        .get(PRELUDE..PRELUDE + 16)
        .is_some_and(|n| n.starts_with(MAGIC) && n[MAGIC.len()..].iter().all(|&c| c == 0))
}

/// A block: name, type and bytes.
struct Block<'b> {
    name: String,
    kind: i16,
    data: &'b [u8],
}

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(b, path, "Wyko .opd");
    if !sniff(b) {
        return Err(f.bad("the file does not start with its Directory entry"));
    }
    let blocks = blocks(&f)?;
    let arrays: Vec<&Block> = blocks.iter().filter(|k| k.kind == TYPE_ARRAY).collect();
    let list: Vec<(&str, bool)> = arrays
        .iter()
        .map(|a| (a.name.as_str(), HEIGHT_ARRAYS.contains(&a.name.as_str())))
        .collect();
    let k = channel::choose(&list, options.channel.as_deref()).map_err(|e| f.bad(e))?;
    let (array, height) = (arrays[k], list[k].1);
    let scalar = |name: &str| -> Result<Option<f64>> {
        match blocks.iter().find(|k| k.name == name) {
            Some(k) => scalar(&f, k).map(Some),
            None => Ok(None),
        }
    };
    let wavelength =
        scalar("Wavelength")?.ok_or_else(|| f.bad("no Wavelength block: the heights' scale"))?;
    let mult = scalar("Mult")?.unwrap_or(1.0);
    let aspect = scalar("Aspect")?.unwrap_or(1.0);
    let pixel = scalar("Pixel_size")?;
    let factor = wavelength / mult * 1e-6;
    if height && !(factor.is_finite() && factor != 0.0) {
        return Err(f.bad(format!(
            "Wavelength / Mult = {wavelength} / {mult}: not a finite scale"
        )));
    }
    let d = array.data;
    let what = format!("the header of array {}", array.name);
    if d.len() < 6 {
        return Err(f.bad(format!("truncated: {what} needs 6 bytes")));
    }
    let at = |k: usize| usize::from(u16::from_le_bytes([d[k], d[k + 1]]));
    let (nx, ny, item) = (at(0), at(2), at(4));
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!(
            "{}: nx × ny = {nx} × {ny}: both must be > 0",
            array.name
        )));
    }
    if ![1, 2, 4].contains(&item) {
        return Err(f.bad(format!(
            "{}: item size {item}: persson reads 1 (u8), 2 (i16) and 4 (f32)",
            array.name
        )));
    }
    let len = product(nx, ny, item).ok_or_else(|| f.bad("nx × ny is too large"))?;
    let values = d.get(6..6 + len).ok_or_else(|| {
        f.bad(format!(
            "truncated: array {} of {nx} × {ny} × {item} bytes has a {}-byte block",
            array.name,
            d.len()
        ))
    })?;
    let mm = || Unit::of(LengthUnit::Millimetre);
    let mut raw = Raw::map(
        nx,
        ny,
        heights(values, nx, ny, item, height.then_some(factor)),
    );
    raw.height_unit = if height { mm() } else { Unit::Unstated };
    // A non-height array (an image) has no unit: the caller must give it.
    raw.require_units = !height;
    raw.size = pixel.map(|p| Stored {
        lx: nx as f64 * p,
        ly: ny as f64 * p * aspect,
        unit: mm(),
        resolution: f64::from(f32::EPSILON),
    });
    Ok(raw)
}

/// The directory's blocks, with their bytes.
fn blocks<'b>(f: &Bin<'b>) -> Result<Vec<Block<'b>>> {
    let length = f.i32(PRELUDE + 18, "the directory's length")?;
    let length = usize::try_from(length)
        .ok()
        .filter(|l| l % ENTRY == 0 && *l >= ENTRY)
        .ok_or_else(|| f.bad(format!("directory length {length}: not a multiple of 24")))?;
    let entries = f.slice(PRELUDE, length, "the directory")?;
    let mut at = PRELUDE + length;
    let mut blocks = Vec::new();
    for e in entries.chunks_exact(ENTRY).skip(1) {
        let name: String = e[..16]
            .iter()
            .take_while(|&&c| c != 0)
            .map(|&c| char::from(c))
            .collect();
        let kind = i16::from_le_bytes([e[16], e[17]]);
        let size = i32::from_le_bytes([e[18], e[19], e[20], e[21]]);
        let Ok(size) = usize::try_from(size) else {
            continue;
        };
        if size == 0 {
            continue;
        }
        let data = f.slice(at, size, &format!("block {name:?}"))?;
        at += size;
        blocks.push(Block { name, kind, data });
    }
    Ok(blocks)
}

/// The number of a scalar block, by its type and length.
fn scalar(f: &Bin, k: &Block) -> Result<f64> {
    let d = k.data;
    let v = match (k.kind, d.len()) {
        (6 | 7, 2) => f64::from(i16::from_le_bytes([d[0], d[1]])),
        (6, 4) | (12, 4..) => f64::from(i32::from_le_bytes([d[0], d[1], d[2], d[3]])),
        (7, 4..) => f64::from(f32::from_le_bytes([d[0], d[1], d[2], d[3]])),
        (8, 8..) => f64::from_le_bytes([d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]]),
        (t, n) => {
            return Err(f.bad(format!(
                "block {:?} of type {t} and {n} bytes is not a number",
                k.name
            )))
        }
    };
    Ok(v)
}

/// `h[ix, iy]` from value `ix·ny + ny − 1 − iy`, times `factor`; NaN where
/// undefined.
fn heights(values: &[u8], nx: usize, ny: usize, item: usize, factor: Option<f64>) -> Vec<f64> {
    let value = |k: usize| -> f64 {
        let c = &values[k * item..(k + 1) * item];
        match item {
            1 => f64::from(c[0]),
            2 => match i16::from_le_bytes([c[0], c[1]]) {
                v if v >= 32766 => f64::NAN,
                v => f64::from(v),
            },
            // Compared as f32, as numpy compares the f32 array with 1e38.
            _ => match f32::from_le_bytes([c[0], c[1], c[2], c[3]]) {
                v if !v.is_finite() || v >= 1e38 => f64::NAN,
                v => f64::from(v),
            },
        }
    };
    let mut h = Vec::with_capacity(nx * ny);
    for iy in 0..ny {
        h.extend((0..nx).map(|ix| value(ix * ny + ny - 1 - iy) * factor.unwrap_or(1.0)));
    }
    h
}

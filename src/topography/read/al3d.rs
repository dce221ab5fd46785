//! Alicona `.al3d` (InfiniteFocus focus-variation microscopes).
//!
//! The magic `AliconaImaging\0\r\n`, then text tags of 52 bytes each: a key
//! (20 bytes), a value (30 bytes, NUL-padded text) and `\r\n`. The first two
//! tags are `Version` and `TagCount` (the number of tags that follow). Read
//! from the tags:
//!
//! ```text
//! Cols, Rows                        nx, ny
//! PixelSizeXMeter, PixelSizeYMeter  Δx, Δy (m)
//! DepthImageOffset                  byte offset of the depth image
//! InvalidPixelValue                 the marker of undefined points
//! ```
//!
//! The depth image is `ny` rows of `nx` little-endian float32 heights in
//! metres, x fastest, each row padded to a multiple of 8 bytes:
//!
//! ```text
//! h[iy, ix] = f32 at DepthImageOffset + iy·⌈4nx/8⌉·8 + 4ix   (m)
//! Lx = nx·Δx,  Ly = ny·Δy  (m)
//! ```
//!
//! A point is undefined where it is NaN or within 1.5e-7 (relative) of
//! `InvalidPixelValue` (the float32 marker compared with its decimal text).
//!
//! # References
//! The layout as Gwyddion's `alicona.c` and SurfaceTopography's `IO/AL3D.py`
//! read it.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::Result;

pub(crate) const MAGIC: &[u8] = b"AliconaImaging\x00\r\n";
/// One tag: key (20), value (30), CR LF.
const TAG: usize = 52;
/// A float32 height within this of the marker (relative) is undefined: the
/// marker is written as decimal text, the heights as float32.
const INVALID_RELATIVE: f64 = 1.5e-7;
/// More tags than this is a corrupt count (files have ~20).
const MAX_TAGS: usize = 10_000;

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let f = Bin::new(b, path, "Alicona .al3d");
    if b.len() < MAGIC.len() && MAGIC.starts_with(b) {
        return Err(f.bad("truncated within the magic AliconaImaging"));
    }
    if !b.starts_with(MAGIC) {
        return Err(f.bad("the file does not start with AliconaImaging"));
    }
    let tags = tags(&f)?;
    let get = |key: &str| -> Result<&str> {
        tags.iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
            .ok_or_else(|| f.bad(format!("no tag {key}")))
    };
    let count = |key: &str| -> Result<usize> {
        get(key)?
            .parse::<usize>()
            .map_err(|_| f.bad(format!("{key} = {:?}: not a count", get(key).unwrap_or(""))))
    };
    let number = |key: &str| -> Result<(f64, f64)> {
        let text = get(key)?;
        let v = text
            .parse::<f64>()
            .map_err(|_| f.bad(format!("{key} = {text:?}: not a number")))?;
        Ok((v, crate::io::text::resolution(text) / v.abs()))
    };
    let (nx, ny) = (count("Cols")?, count("Rows")?);
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!("Cols × Rows = {nx} × {ny}: both must be > 0")));
    }
    let stride = nx
        .checked_mul(4)
        .and_then(|n| n.checked_add(7))
        .map(|n| n / 8 * 8)
        .ok_or_else(|| f.bad(format!("Cols = {nx} is too large")))?;
    let offset = count("DepthImageOffset")?;
    let len = product(stride, ny - 1, 1)
        .and_then(|n| n.checked_add(4 * nx))
        .ok_or_else(|| f.bad(format!("Cols × Rows = {nx} × {ny} is too large")))?;
    let data = f.slice(offset, len, "the depth image")?;
    let (invalid, _) = number("InvalidPixelValue")?;
    let undefined = |h: f64| h.is_nan() || (h - invalid).abs() < INVALID_RELATIVE * invalid.abs();
    let mut heights = Vec::with_capacity(nx * ny);
    for iy in 0..ny {
        let row = &data[iy * stride..iy * stride + 4 * nx];
        heights.extend(row.chunks_exact(4).map(|c| {
            let h = f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]]));
            if undefined(h) {
                f64::NAN
            } else {
                h
            }
        }));
    }
    let (dx, rx) = number("PixelSizeXMeter")?;
    let (dy, ry) = number("PixelSizeYMeter")?;
    let metres = || Unit::of(LengthUnit::Metre);
    Ok(Raw {
        size: Some(Stored {
            lx: nx as f64 * dx,
            ly: ny as f64 * dy,
            unit: metres(),
            resolution: rx.max(ry),
        }),
        height_unit: metres(),
        ..Raw::map(nx, ny, heights)
    })
}

/// The tags as (key, value) text, `Version` and `TagCount` included.
fn tags(f: &Bin) -> Result<Vec<(String, String)>> {
    let tag = |k: usize| -> Result<(String, String)> {
        let at = MAGIC.len() + k * TAG;
        let t = f.slice(at, TAG, &format!("tag {}", k + 1))?;
        if &t[50..] != b"\r\n" {
            return Err(f.bad(format!(
                "tag {} (at byte {at}) does not end with CR LF: corrupt header",
                k + 1
            )));
        }
        let text = |s: &[u8]| {
            let end = s.iter().position(|&c| c == 0).unwrap_or(s.len());
            String::from_utf8_lossy(&s[..end]).trim().to_string()
        };
        Ok((text(&t[..20]), text(&t[20..50])))
    };
    let version = tag(0)?;
    let count = tag(1)?;
    if version.0 != "Version" || count.0 != "TagCount" {
        return Err(f.bad(format!(
            "the first tags are {:?} and {:?}, not Version and TagCount",
            version.0, count.0
        )));
    }
    let n = count
        .1
        .parse::<usize>()
        .ok()
        .filter(|&n| n <= MAX_TAGS)
        .ok_or_else(|| f.bad(format!("TagCount = {:?}: not a count", count.1)))?;
    let mut tags = vec![version, count];
    for k in 0..n {
        tags.push(tag(k + 2)?);
    }
    Ok(tags)
}

//! TrueMap `.tmd` (TrueGage's TrueMap software, version 2 data files).
//!
//! The magic `Binary TrueMap Data File v2.0` (32 bytes with its CR LF NUL),
//! a comment ending with a NUL, then little-endian
//!
//! ```text
//! u32 nx, u32 ny, f32 Lx, f32 Ly, f32 x offset, f32 y offset   (mm)
//! ny rows of nx f32 heights, x fastest                         (mm)
//! ```
//!
//! The unit is millimetres, as SurfaceTopography 1.27 reads the files
//! (its later versions read µm; the example file's 18.96 × 18.96 scan of
//! 300 × 300 points with 0.35 heights is a profilometer's millimetres).
//! NaN heights are undefined.
//!
//! # References
//! The layout as SurfaceTopography's `IO/TMD.py` reads it.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::Result;

pub(crate) const MAGIC: &[u8] = b"Binary TrueMap Data File v2.0";
/// The magic's field, with its CR LF NUL.
const MAGIC_FIELD: usize = 32;

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let f = Bin::new(b, path, "TrueMap .tmd");
    if !b.starts_with(MAGIC) {
        return Err(f.bad("the file does not start with Binary TrueMap Data File v2.0"));
    }
    let comment_end = f
        .slice(
            MAGIC_FIELD,
            b.len().saturating_sub(MAGIC_FIELD),
            "the comment",
        )?
        .iter()
        .position(|&c| c == 0)
        .ok_or_else(|| f.bad("truncated: the comment has no end (NUL)"))?;
    let at = MAGIC_FIELD + comment_end + 1;
    let nx = f.u32(at, "nx")? as usize;
    let ny = f.u32(at + 4, "ny")? as usize;
    let lx = f64::from(f.f32(at + 8, "Lx")?);
    let ly = f64::from(f.f32(at + 12, "Ly")?);
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!("nx × ny = {nx} × {ny}: both must be > 0")));
    }
    for (name, v) in [("Lx", lx), ("Ly", ly)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(f.bad(format!("{name} = {v}: must be finite and > 0")));
        }
    }
    let len =
        product(nx, ny, 4).ok_or_else(|| f.bad(format!("nx × ny = {nx} × {ny} is too large")))?;
    let data = f.slice(at + 24, len, "the heights")?;
    let heights = data
        .chunks_exact(4)
        .map(|c| f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])))
        .collect();
    let mm = || Unit::of(LengthUnit::Millimetre);
    Ok(Raw {
        size: Some(Stored {
            lx,
            ly,
            unit: mm(),
            resolution: f64::from(f32::EPSILON),
        }),
        height_unit: mm(),
        ..Raw::map(nx, ny, heights)
    })
}

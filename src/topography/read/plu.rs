//! Sensofar `.plu` (confocal and interferometric profilers, SensoSCAN).
//!
//! No magic: the file starts with the date as text. A little-endian header
//! of 500 bytes, then the layers. Read from the header (byte offsets):
//!
//! ```text
//!   0  date (128 bytes of text)   128  time (u32)   132  comment (256 bytes)
//! 388  ny (u32)   392  nx (u32)   404  µm per pixel along x (f32)   408  along y (f32)
//! 428  measurement type (u32: 1 profile, 3 topography)
//! 489  number of layers (u8)
//! 500  the first layer: ny, nx (u32), then ny·nx float32 heights (µm), x fastest
//! ```
//!
//! ```text
//! h = value (µm),   Lx = nx·Δx,   Ly = ny·Δy   (µm)
//! ```
//!
//! The value 1000001 marks an undefined point. Only the first layer is read,
//! and only topographies (type 3): a profile or other type is an error
//! naming it. The format has no magic, so it is read only by its
//! extension (`.plu`, `.apx`).
//!
//! # References
//! The layout as Gwyddion's `sensofar.c` and SurfaceTopography's `IO/PLU.py`
//! read it.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::Result;

/// The layers start here (the header's five blocks: 128 + 4 + 256, the
/// calibration 40, the measurement configuration 20 + 40 + 12).
const LAYERS: usize = 500;
/// The measurement type of a topography.
const TOPOGRAPHY: u32 = 3;
/// The value of an undefined point.
const UNDEFINED: f32 = 1_000_001.0;
/// Relative precision of a float32 pixel size.
const F32_RESOLUTION: f64 = 1.2e-7;

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let f = Bin::new(b, path, "Sensofar .plu");
    f.slice(0, LAYERS + 8, "the header")?;
    let kind = f.u32(428, "measurement type")?;
    if kind != TOPOGRAPHY {
        let name = match kind {
            1 => "a profile",
            _ => "not a topography",
        };
        return Err(f.bad(format!(
            "measurement type {kind} ({name}): only topographies (3) are read"
        )));
    }
    if b[489] == 0 {
        return Err(f.bad("the file has no layers"));
    }
    let ny = f.u32(LAYERS, "the layer's ny")? as usize;
    let nx = f.u32(LAYERS + 4, "the layer's nx")? as usize;
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!("nx × ny = {nx} × {ny}: both must be > 0")));
    }
    let len =
        product(nx, ny, 4).ok_or_else(|| f.bad(format!("nx × ny = {nx} × {ny} is too large")))?;
    // The heights and the layer's min and max (two float32) after them.
    let data = f.slice(LAYERS + 8, len.saturating_add(8), "the heights")?;
    let data = &data[..len];
    let heights = data
        .chunks_exact(4)
        .map(|c| match f32::from_le_bytes([c[0], c[1], c[2], c[3]]) {
            h if h == UNDEFINED => f64::NAN,
            h => f64::from(h),
        })
        .collect();
    let dx = f64::from(f.f32(404, "µm per pixel along x")?);
    let dy = f64::from(f.f32(408, "µm per pixel along y")?);
    let micrometres = || Unit::of(LengthUnit::Micrometre);
    Ok(Raw {
        size: Some(Stored {
            lx: nx as f64 * dx,
            ly: ny as f64 * dy,
            unit: micrometres(),
            resolution: F32_RESOLUTION,
        }),
        height_unit: micrometres(),
        ..Raw::map(nx, ny, heights)
    })
}

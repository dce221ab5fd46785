//! Digital Surf `.sur` (MountainsMap's exchange format).
//!
//! A 512-byte little-endian header, then a comment and a private zone of
//! the sizes the header gives, then the points, int16 or int32, x fastest.
//! Read from the header (byte offsets):
//!
//! ```text
//!   0  "DIGITAL SURF"        12  format (0: PC, little-endian)
//!  14  number of objects      18  object type (0 profile, 1 surface, …)
//!  86  special points (1: non-measured points present)
//!  98  bits per point (16, 32)       100  z_min (i32)
//! 108  nx (i32)   112  ny (i32)   116  nx·ny (u32)
//! 120  Δx (f32)   124  Δy (f32)   128  z scale (f32)
//! 180  unit of Δx   196  unit of Δy   212  unit of the scaled z (16 bytes each)
//! 290  inversion (1: z negated, 2: also x reversed, 3: also y reversed)
//! 334  comment size (u16)   336  private zone size (u16)
//! ```
//!
//! ```text
//! h = s·raw · unit(z),   Lx = nx·Δx · unit(Δx),   Ly = ny·Δy · unit(Δy)
//! ```
//! with s = −1 for the inversions 1–3, else 1. A point with raw value
//! z_min − 2 is non-measured (undefined) when "special points" is 1. The
//! offsets stored at bytes 466–477 are not added (a constant, removed by
//! any detrending; SurfaceTopography does not add them either). Units are
//! written in Latin-1 or code page 437 (`µm` as B5 or E6 followed by `m`).
//! Only the first object of a multi-object file is read (as by
//! SurfaceTopography, which names it `Default`): the file's one channel,
//! so [`ReadOptions::channel`](super::ReadOptions::channel) may only be `0`
//! (anything else is an error); a profile (type 0, ny = 1) is a line scan. Compressed files (`DSCOMPRESSED`) are refused,
//! naming the format.
//!
//! # References
//! Digital Surf, "SUR file format" (the header table published with
//! MountainsMap); the layout as Gwyddion's `surffile.c` and
//! SurfaceTopography's `IO/SUR.py` read it.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::Result;
use crate::topography::Layout;

pub(crate) const MAGIC: &[u8] = b"DIGITAL SURF";
pub(crate) const MAGIC_COMPRESSED: &[u8] = b"DSCOMPRESSED";
const HEADER: usize = 512;
/// Relative precision of a float32 size.
const F32_RESOLUTION: f64 = 1.2e-7;

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let f = Bin::new(b, path, "Digital Surf .sur");
    if b.starts_with(MAGIC_COMPRESSED) {
        return Err(f.bad("compressed (DSCOMPRESSED) files are not read: save it uncompressed"));
    }
    if b.len() < MAGIC.len() && MAGIC.starts_with(b) {
        return Err(f.bad("truncated within the magic DIGITAL SURF"));
    }
    if !b.starts_with(MAGIC) {
        return Err(f.bad("the file does not start with DIGITAL SURF"));
    }
    f.slice(0, HEADER, "the 512-byte header")?;
    let endian = f.u16(12, "format")?;
    if endian != 0 {
        return Err(f.bad(format!(
            "format {endian}: only PC (little-endian, 0) files are read"
        )));
    }
    let bits = f.u16(98, "bits per point")?;
    let nx = f.i32(108, "nx")?;
    let ny = f.i32(112, "ny")?;
    let (nx, ny) = match (usize::try_from(nx), usize::try_from(ny)) {
        (Ok(x), Ok(y)) if x > 0 && y > 0 => (x, y),
        _ => return Err(f.bad(format!("nx × ny = {nx} × {ny}: both must be > 0"))),
    };
    let item = match bits {
        16 => 2,
        32 => 4,
        _ => return Err(f.bad(format!("{bits} bits per point: 16 or 32 are read"))),
    };
    let count = product(nx, ny, 1).filter(|c| c.checked_mul(item).is_some());
    let count = count.ok_or_else(|| f.bad(format!("nx × ny = {nx} × {ny} is too large")))?;
    let stated = f.u32(116, "number of points")? as usize;
    if stated != count {
        return Err(f.bad(format!(
            "the header gives {stated} points, nx × ny = {nx} × {ny} = {count}"
        )));
    }
    let start = HEADER
        + usize::from(f.u16(334, "comment size")?)
        + usize::from(f.u16(336, "private size")?);
    let data = f.slice(start, count * item, "the points")?;
    let zmin = f.i32(100, "z_min")?;
    let undefined = (f.u16(86, "special points")? == 1).then(|| i64::from(zmin) - 2);
    let scale = f64::from(f.f32(128, "z scale")?);
    if !scale.is_finite() || scale == 0.0 {
        return Err(f.bad(format!("z scale {scale}: must be finite and not 0")));
    }
    let inversion = f.u16(290, "inversion")?;
    let sign = if (1..=3).contains(&inversion) {
        -1.0
    } else {
        1.0
    };
    let raw: Vec<i64> = if item == 2 {
        data.chunks_exact(2)
            .map(|c| i16::from_le_bytes([c[0], c[1]]).into())
            .collect()
    } else {
        data.chunks_exact(4)
            .map(|c| i32::from_le_bytes([c[0], c[1], c[2], c[3]]).into())
            .collect()
    };
    let mut heights: Vec<f64> = raw
        .into_iter()
        .map(|r| {
            if Some(r) == undefined {
                f64::NAN
            } else {
                sign * scale * r as f64
            }
        })
        .collect();
    flip(&mut heights, nx, inversion);
    let size = size(&f, nx, ny)?;
    let height_unit = unit(&f, 212, "the heights")?;
    let layout = if ny == 1 {
        Layout::LineScans
    } else {
        Layout::Map
    };
    Ok(Raw {
        size: Some(size),
        height_unit,
        layout,
        ..Raw::map(nx, ny, heights)
    })
}

/// Inversion 2 reverses x (each row), 3 reverses y (the order of rows).
fn flip(h: &mut [f64], nx: usize, inversion: u16) {
    match inversion {
        2 => h.chunks_exact_mut(nx).for_each(|row| row.reverse()),
        3 => {
            let rows: Vec<Vec<f64>> = h.chunks_exact(nx).rev().map(<[f64]>::to_vec).collect();
            for (dst, src) in h.chunks_exact_mut(nx).zip(rows) {
                dst.copy_from_slice(&src);
            }
        }
        _ => {}
    }
}

/// `Lx`, `Ly` in the unit of Δx (Δy converted to it).
fn size(f: &Bin, nx: usize, ny: usize) -> Result<Stored> {
    let dx = f64::from(f.f32(120, "Δx")?);
    let dy = f64::from(f.f32(124, "Δy")?);
    let ux = unit(f, 180, "Δx")?;
    let uy = unit(f, 196, "Δy")?;
    let to_x = match (&ux, &uy) {
        (Unit::Stated(_, a), Unit::Stated(_, b)) => b.metres() / a.metres(),
        (Unit::Unstated, Unit::Unstated) => 1.0,
        _ => return Err(f.bad("the units of Δx and Δy must both be given or both empty")),
    };
    Ok(Stored {
        lx: nx as f64 * dx,
        ly: ny as f64 * dy * to_x,
        unit: ux,
        resolution: F32_RESOLUTION,
    })
}

/// A 16-byte unit field: Latin-1 or code page 437, NUL or space padded.
fn unit(f: &Bin, offset: usize, what: &str) -> Result<Unit> {
    let raw = f.slice(offset, 16, what)?;
    let text: String = raw
        .iter()
        .take_while(|&&c| c != 0)
        .map(|&c| match c {
            0xB5 | 0xE6 => 'µ',
            c => char::from(c),
        })
        .collect();
    let text = text.trim();
    if text == "µ" {
        return Ok(Unit::Stated(text.into(), LengthUnit::Micrometre));
    }
    Unit::declared(&format!("the unit of {what}"), text).map_err(|m| f.bad(m))
}

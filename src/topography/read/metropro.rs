//! Zygo MetroPro `.dat` (phase maps of Zygo's optical interferometers).
//!
//! A big-endian header of `header_size` bytes (834 for the magics
//! `88 1B 03 6F` and `88 1B 03 70`, 4096 for `88 1B 03 71`), then the
//! intensity data (`2·buckets·width·height` bytes, skipped), then the phase
//! data: `cn_width × cn_height` big-endian int32, x fastest. Read from the
//! header (byte offsets, big-endian):
//!
//! ```text
//!   6  header size (u32)         52, 54, 56  intensity width, height, buckets (u16)
//!  68, 70  phase width, height (u16)
//! 164  interferometric scale factor S (f32)     168  wavelength λ, m (f32)
//! 176  obliquity factor O (f32)  184  lateral resolution Δ, m/pixel (f32; 0: unknown)
//! 218  phase resolution (i16: 0, 1, 2 → R = 4096, 32768, 131072)
//! 232  sign (i16: ≠ 0 → heights negated)
//! ```
//!
//! ```text
//! h = ±raw · S·O·λ / R  (m),     Lx = width·Δ,  Ly = height·Δ  (m)
//! ```
//!
//! A raw value ≥ 2147483640 marks an undefined point. A file whose lateral
//! resolution is 0 stores no size: the caller gives it.
//!
//! # References
//! Zygo Corporation, "MetroPro Reference Guide", OMP-0347, section "Data
//! Format" (the header table); the layout as Gwyddion's `metropro.c` and
//! SurfaceTopography's `IO/MetroPro.py` read it.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::Result;

/// The three magics of MetroPro files (header formats 1, 2, 3).
pub(crate) const MAGICS: [&[u8]; 3] = [
    b"\x88\x1b\x03\x6f",
    b"\x88\x1b\x03\x70",
    b"\x88\x1b\x03\x71",
];
/// Raw phase values from this one up mark undefined points.
const INVALID: i32 = 2_147_483_640;
/// Relative precision of the float32 lateral resolution.
const F32_RESOLUTION: f64 = 1.2e-7;

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let f = Bin::new(b, path, "Zygo MetroPro .dat");
    let magic = f.slice(0, 4, "the magic")?;
    let Some(kind) = MAGICS.iter().position(|m| *m == magic) else {
        return Err(f.bad("the file does not start with a MetroPro magic (88 1B 03 6F–71)"));
    };
    let header = f.be_u32(6, "header size")? as usize;
    let expected = if kind == 2 { 4096 } else { 834 };
    if header != expected {
        return Err(f.bad(format!(
            "header size {header}: header format {} has {expected}",
            kind + 1
        )));
    }
    f.slice(0, header, "the header")?;
    let intensity = product(
        usize::from(f.be_u16(52, "intensity width")?),
        usize::from(f.be_u16(54, "intensity height")?),
        2 * usize::from(f.be_u16(56, "intensity buckets")?),
    )
    .unwrap_or(usize::MAX);
    let nx = usize::from(f.be_u16(68, "phase width")?);
    let ny = usize::from(f.be_u16(70, "phase height")?);
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!("no phase data (width × height = {nx} × {ny})")));
    }
    let start = header.saturating_add(intensity);
    let data = f.slice(start, nx * ny * 4, "the phase data")?;
    let scale = scale(&f)?;
    let heights = data
        .chunks_exact(4)
        .map(|c| match i32::from_be_bytes([c[0], c[1], c[2], c[3]]) {
            r if r >= INVALID => f64::NAN,
            r => f64::from(r) * scale,
        })
        .collect();
    let dx = f64::from(f.be_f32(184, "lateral resolution")?);
    let metres = || Unit::of(LengthUnit::Metre);
    let size = if dx > 0.0 && dx.is_finite() {
        Some(Stored {
            lx: nx as f64 * dx,
            ly: ny as f64 * dx,
            unit: metres(),
            resolution: F32_RESOLUTION,
        })
    } else {
        None
    };
    Ok(Raw {
        size,
        height_unit: metres(),
        ..Raw::map(nx, ny, heights)
    })
}

/// ±S·O·λ/R, m per raw unit.
fn scale(f: &Bin) -> Result<f64> {
    let s = f64::from(f.be_f32(164, "scale factor")?);
    let lambda = f64::from(f.be_f32(168, "wavelength")?);
    let o = f64::from(f.be_f32(176, "obliquity factor")?);
    let r = match f.be_i16(218, "phase resolution")? {
        0 => 4096.0,
        1 => 32768.0,
        2 => 131072.0,
        p => return Err(f.bad(format!("phase resolution {p}: 0, 1 or 2 are known"))),
    };
    let sign = if f.be_i16(232, "sign")? != 0 {
        -1.0
    } else {
        1.0
    };
    let k = sign * s * o * lambda / r;
    if k.is_finite() && k != 0.0 {
        Ok(k)
    } else {
        Err(f.bad(format!(
            "scale factor × obliquity × wavelength = {s} × {o} × {lambda}: not a finite, \
             non-zero height scale"
        )))
    }
}

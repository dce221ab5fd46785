//! NanoFocus `.nms` (µsurf confocal microscopes; µsoft's files of version
//! `OM_MS_2.0`).
//!
//! A 3468-byte header, the heights, then (where the header says so) an
//! intensity image. Little-endian; the fields read (byte offsets):
//!
//! ```text
//!    0 i32 data type (2: u16)          4 i32 dimension (1: an area; 0: a profile)
//!    8 i32 n_low   12 i32 n_high       16 f64 z_low   24 f64 z_high   (µm)
//!   32 "OM_MS_2.0" (the version)
//! 1368 u32 nx   1372 u32 ny           1376 f64 Δx   1384 f64 Δy      (nm)
//! 1416 i32 intensity (> 0: an intensity image follows the heights)
//! 3468 ny rows of nx u16 values v, x fastest; then ny rows of nx u8 intensities
//! ```
//!
//! ```text
//! h[iy, ix] = z_low + (v − n_low)·(z_high − z_low)/(n_high − n_low)   (µm)
//! Lx = nx·Δx,  Ly = ny·Δy   (nm)
//! ```
//!
//! A point whose intensity is 0 was not measured: undefined. The heights
//! are the file's one channel (the intensity image only marks undefined
//! points, as SurfaceTopography reads it): [`ReadOptions::channel`] may
//! only be `0` (anything else is an error).
//!
//! # The units of Δx and of the heights
//! Δx is in nanometres: the examples' Δx = 312.4999911618964 over
//! 512 × 512 points is a field of 160 µm, the field of a µsurf with its
//! 100× objective (a pixel of 0.3125 µm), and their heights span 2.7 µm to
//! 6.0 µm (z_low, z_high). SurfaceTopography 1.27 reads Δx as millimetres
//! (its `dx_mm`, times 1000 into µm), which makes the example a scan of
//! 160 m with 3 µm of relief. Two public readers of the format read
//! nanometres: musurf-reader (D. Mendroch, `musurf_reader.py`: "step size in
//! um" = the field / 1000) and surfalize (`step_x = dx · 1e-3` in µm).
//!
//! # The height scale
//! The header gives the heights z_low, z_high of the values n_low = 0 and
//! n_high = 65535; the examples' values run from exactly 0 to exactly 65535
//! (once each), so z_low and z_high are the map's lowest and highest
//! points. SurfaceTopography 1.27 divides by 2^16 − 2 = 65534 instead,
//! which puts its highest point (z_high − z_low)/65534 above z_high: its
//! heights above z_low are 65535/65534 of ours.
//!
//! # References
//! musurf-reader's `readImages` (the fields, the scale, zero intensity as
//! not measured; its author's offsets of the single-image file);
//! SurfaceTopography's `IO/NMS.py` (the grid, the orientation: row iy of
//! the file is y = iy·Δy).

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::Result;

const FORMAT: &str = "NanoFocus .nms";
const VERSION: &[u8] = b"OM_MS_2.0";
const VERSION_AT: usize = 32;
const HEADER: usize = 3468;
/// Relative precision of a float64 field.
const F64_RESOLUTION: f64 = 2.3e-16;

/// Whether `bytes` start as this format's files do (the version string).
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.get(VERSION_AT..VERSION_AT + VERSION.len()) == Some(VERSION)
}

fn f64_at(f: &Bin, at: usize, what: &str) -> Result<f64> {
    let s = f.slice(at, 8, what)?;
    let mut a = [0u8; 8];
    a.copy_from_slice(s);
    Ok(f64::from_le_bytes(a))
}

pub(crate) fn parse(path: &Path, bytes: &[u8], _options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(bytes, path, FORMAT);
    let version = f.slice(VERSION_AT, VERSION.len(), "the version")?;
    if version != VERSION {
        return Err(f.bad(format!(
            "version {:?} at byte 32: only OM_MS_2.0 is read",
            String::from_utf8_lossy(version)
        )));
    }
    let kind = f.i32(0, "the data type")?;
    if kind != 2 {
        return Err(f.bad(format!("data type {kind}: only 2 (u16) is read")));
    }
    let dim = f.i32(4, "the dimension")?;
    if dim != 1 {
        return Err(f.bad(format!("dimension {dim}: only 1 (an area) is read")));
    }
    let (n_low, n_high) = (f.i32(8, "n_low")?, f.i32(12, "n_high")?);
    let (z_low, z_high) = (f64_at(&f, 16, "z_low")?, f64_at(&f, 24, "z_high")?);
    if n_high <= n_low || !(z_low.is_finite() && z_high.is_finite()) {
        return Err(f.bad(format!(
            "the height scale (values {n_low}..{n_high} for {z_low}..{z_high} µm) is not a scale"
        )));
    }
    let nx = f.u32(1368, "nx")? as usize;
    let ny = f.u32(1372, "ny")? as usize;
    let (dx, dy) = (f64_at(&f, 1376, "Δx")?, f64_at(&f, 1384, "Δy")?);
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!("nx × ny = {nx} × {ny}: both must be > 0")));
    }
    for (name, v) in [("Δx", dx), ("Δy", dy)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(f.bad(format!("{name} = {v}: must be finite and > 0")));
        }
    }
    let intensity = f.i32(1416, "the intensity flag")? > 0;
    let too_large = || f.bad(format!("nx × ny = {nx} × {ny} is too large"));
    let n = product(nx, ny, 1).ok_or_else(too_large)?;
    let bytes = product(nx, ny, 2).ok_or_else(too_large)?;
    let values = f.slice(HEADER, bytes, "the heights")?;
    let light = if intensity {
        let at = HEADER.checked_add(bytes).ok_or_else(too_large)?;
        Some(f.slice(at, n, "the intensity image")?)
    } else {
        None
    };
    let scale = (z_high - z_low) / (i64::from(n_high) - i64::from(n_low)) as f64;
    let heights = values
        .chunks_exact(2)
        .enumerate()
        .map(|(k, c)| {
            if light.is_some_and(|l| l[k] == 0) {
                f64::NAN
            } else {
                let v = i64::from(u16::from_le_bytes([c[0], c[1]])) - i64::from(n_low);
                z_low + v as f64 * scale
            }
        })
        .collect();
    Ok(Raw {
        size: Some(Stored {
            lx: nx as f64 * dx,
            ly: ny as f64 * dy,
            unit: Unit::of(LengthUnit::Nanometre),
            resolution: F64_RESOLUTION,
        }),
        height_unit: Unit::of(LengthUnit::Micrometre),
        ..Raw::map(nx, ny, heights)
    })
}

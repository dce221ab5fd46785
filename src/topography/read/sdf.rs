//! ISO 25178-71 surface data files `.sdf` (the SDF of the Surface Data
//! File standard, from the SURFSTAND project), ASCII and binary.
//!
//! Both start with a magic, `aISO-1.0` (ASCII) or `bISO-1.0` (binary), and
//! carry the same header fields:
//!
//! ```text
//! NumPoints, NumProfiles        nx (points per profile), ny (profiles)
//! Xscale, Yscale, Zscale        Δx, Δy (m), and the factor of the stored values to m
//! Compression                   0 (no other is defined for reading here)
//! DataType                      5 int16, 6 int32, 7 double
//! ```
//!
//! ASCII: `Key = Value` lines up to a line `*`, then the values (blank
//! separated, `BAD` for an undefined point) up to the next `*`, then a
//! trailer that is not read. Binary: the header packed little-endian,
//! `8s 10s 12s 12s u16 u16 f64 f64 f64 f64 u8 u8 u8` (magic, manufacturer,
//! two dates, NumPoints, NumProfiles, the four scales, Compression,
//! DataType, CheckType; 81 bytes), then the values of DataType, the int
//! type's minimum (or NaN) undefined. A profile is a row along x:
//!
//! ```text
//! h[iy, ix] = Zscale · value_k,  k = iy·nx + ix   (m)
//! Lx = nx·Δx,  Ly = ny·Δy   (m)
//! ```
//!
//! # References
//! ISO 25178-71:2012 (software measurement standards, type F1 file
//! format); the layout as SurfaceTopography's `IO/SDF.py` reads it.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::Result;

pub(crate) const MAGIC_ASCII: &[u8] = b"aISO-1.0";
pub(crate) const MAGIC_BINARY: &[u8] = b"bISO-1.0";
/// The binary header's size in bytes.
const BINARY_HEADER: usize = 81;
const FORMAT: &str = "ISO 25178-71 .sdf";

/// The header fields read.
struct Header {
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
    dz: f64,
    data_type: u8,
    /// Relative precision of Δx, Δy as written.
    resolution: f64,
}

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let f = Bin::new(b, path, FORMAT);
    let (header, heights) = if b.starts_with(MAGIC_ASCII) {
        ascii(&f)?
    } else if b.starts_with(MAGIC_BINARY) {
        binary(&f)?
    } else {
        return Err(f.bad("the file starts with neither aISO-1.0 nor bISO-1.0"));
    };
    let metres = || Unit::of(LengthUnit::Metre);
    Ok(Raw {
        size: Some(Stored {
            lx: header.nx as f64 * header.dx,
            ly: header.ny as f64 * header.dy,
            unit: metres(),
            resolution: header.resolution,
        }),
        height_unit: metres(),
        ..Raw::map(header.nx, header.ny, heights)
    })
}

/// The grid, checked: both counts > 0, the scales finite and > 0, no
/// compression, a known data type.
fn checked(f: &Bin, h: Header, compression: u8) -> Result<Header> {
    if h.nx == 0 || h.ny == 0 {
        return Err(f.bad(format!(
            "NumPoints × NumProfiles = {} × {}: both must be > 0",
            h.nx, h.ny
        )));
    }
    for (name, v) in [("Xscale", h.dx), ("Yscale", h.dy), ("Zscale", h.dz)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(f.bad(format!("{name} = {v}: must be finite and > 0")));
        }
    }
    if compression != 0 {
        return Err(f.bad(format!(
            "Compression = {compression}: only uncompressed files (0) are read"
        )));
    }
    if !(5..=7).contains(&h.data_type) {
        return Err(f.bad(format!(
            "DataType = {}: 5 (int16), 6 (int32) or 7 (double) expected",
            h.data_type
        )));
    }
    Ok(h)
}

/// The ASCII variant: the header, then the values.
fn ascii(f: &Bin) -> Result<(Header, Vec<f64>)> {
    let text = std::str::from_utf8(f.bytes).map_err(|e| f.bad(format!("not ASCII text ({e})")))?;
    let mut sections = text.splitn(3, "\n*");
    let head = sections.next().unwrap_or_default();
    let data = sections
        .next()
        .ok_or_else(|| f.bad("no line * after the header"))?;
    // The values end at the next line `*` (the trailer follows).
    let data = data.split_once('*').map_or(data, |(d, _)| d);
    let field = |key: &str| -> Result<&str> {
        head.lines()
            .filter_map(|l| l.split_once('='))
            .find(|(k, _)| k.trim() == key)
            .map(|(_, v)| v.trim())
            .ok_or_else(|| f.bad(format!("no header field {key}")))
    };
    let count = |key: &str| -> Result<usize> {
        let v = field(key)?;
        v.parse()
            .map_err(|_| f.bad(format!("{key} = {v:?}: not a count")))
    };
    let number = |key: &str| -> Result<(f64, f64)> {
        let v = field(key)?;
        let x: f64 = v
            .parse()
            .map_err(|_| f.bad(format!("{key} = {v:?}: not a number")))?;
        Ok((x, crate::io::text::resolution(v) / x.abs()))
    };
    let (dx, rx) = number("Xscale")?;
    let (dy, ry) = number("Yscale")?;
    let header = Header {
        nx: count("NumPoints")?,
        ny: count("NumProfiles")?,
        dx,
        dy,
        dz: number("Zscale")?.0,
        data_type: count("DataType")?
            .try_into()
            .map_err(|_| f.bad("DataType: 5, 6 or 7 expected"))?,
        resolution: rx.max(ry),
    };
    let compression = count("Compression").unwrap_or(0).min(255) as u8;
    let header = checked(f, header, compression)?;
    let n = product(header.nx, header.ny, 1)
        .ok_or_else(|| f.bad("NumPoints × NumProfiles is too large"))?;
    let mut heights = Vec::with_capacity(n.min(f.bytes.len()));
    for word in data.split_whitespace() {
        let v = if word.eq_ignore_ascii_case("BAD") {
            f64::NAN
        } else {
            word.parse::<f64>().map_err(|_| {
                f.bad(format!(
                    "value {} = {word:?}: not a number",
                    heights.len() + 1
                ))
            })? * header.dz
        };
        heights.push(v);
    }
    if heights.len() != n {
        return Err(f.bad(format!(
            "{} values between the lines *, NumPoints × NumProfiles = {n}",
            heights.len()
        )));
    }
    Ok((header, heights))
}

/// The binary variant: the packed header, then the values.
fn binary(f: &Bin) -> Result<(Header, Vec<f64>)> {
    let h = f.slice(0, BINARY_HEADER, "the header")?;
    let f64_at = |o: usize| {
        let mut a = [0u8; 8];
        a.copy_from_slice(&h[o..o + 8]);
        f64::from_le_bytes(a)
    };
    let header = Header {
        nx: usize::from(f.u16(42, "NumPoints")?),
        ny: usize::from(f.u16(44, "NumProfiles")?),
        dx: f64_at(46),
        dy: f64_at(54),
        dz: f64_at(62),
        data_type: h[79],
        resolution: f64::EPSILON,
    };
    let header = checked(f, header, h[78])?;
    let size = match header.data_type {
        5 => 2,
        6 => 4,
        _ => 8,
    };
    let len = product(header.nx, header.ny, size)
        .ok_or_else(|| f.bad("NumPoints × NumProfiles is too large"))?;
    let data = f.slice(BINARY_HEADER, len, "the values")?;
    let dz = header.dz;
    let heights = data
        .chunks_exact(size)
        .map(|c| match c.len() {
            2 => match i16::from_le_bytes([c[0], c[1]]) {
                i16::MIN => f64::NAN,
                v => f64::from(v) * dz,
            },
            4 => match i32::from_le_bytes([c[0], c[1], c[2], c[3]]) {
                i32::MIN => f64::NAN,
                v => f64::from(v) * dz,
            },
            _ => {
                let mut a = [0u8; 8];
                a.copy_from_slice(c);
                f64::from_le_bytes(a) * dz
            }
        })
        .collect();
    Ok((header, heights))
}

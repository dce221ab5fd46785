//! Park Systems `.tiff` (the atomic force microscopes' TIFF).
//!
//! A little-endian TIFF (`II*\0`) whose first image file directory (IFD)
//! holds, besides an 8-bit preview image, four private tags:
//!
//! ```text
//! 50432  magic, LONG 0x0E031301 (what tells a Park TIFF from another)
//! 50433  version, LONG 0x01000001 or 0x01000002
//! 50434  the data, BYTE[]: ny rows of nx values, x fastest, little-endian
//! 50435  the header, UNDEFINED[], little-endian, packed:
//!          0 image type (u32: 0 map, 1 line profile, 2 spectroscopy)
//!          4 source name (32 UTF-16 characters: the channel, "Z Height")
//!        100 nx (u32)   104 ny (u32)
//!        140 Lx (f64, µm)   148 Ly (f64, µm)
//!        220 data gain (f64)  228 data scale factor (f64, 0 means 1)
//!        236 data offset (f64)  244 data unit (8 UTF-16 characters; empty: µm)
//!        version 2 only: 348 data type (u32: 0 int16, 1 int32, 2 float32);
//!        version 1 data are int16
//! ```
//!
//! ```text
//! h = gain·(scale·raw + offset) · unit,   Lx, Ly in µm
//! ```
//!
//! The first row of the data is the bottom of the image: it is read as the
//! last row (`y` up), as SurfaceTopography and Gwyddion orient it. The
//! file holds one channel, named by its source name; it is a height
//! channel when the data unit is a length (a channel in another unit is an
//! error naming it). NaN values (float32 data) are undefined. A line
//! profile (image type 1) is refused; the scan direction, rotation and
//! `swap_xy` fields are not applied (nor are they by SurfaceTopography).
//!
//! # References
//! The layout as Gwyddion's `psia.c` and SurfaceTopography's `IO/PS.py`
//! read it; TIFF 6.0 (Adobe, 1992) for the container.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{channel, Raw, ReadOptions, Stored};
use crate::error::Result;

const FORMAT: &str = "Park Systems .tiff";
const TIFF_LE: &[u8] = b"II*\0";
const TAG_MAGIC: u16 = 50432;
const TAG_VERSION: u16 = 50433;
const TAG_DATA: u16 = 50434;
const TAG_HEADER: u16 = 50435;
const MAGIC: u32 = 0x0E03_1301;
const VERSION_1: u32 = 0x0100_0001;
const VERSION_2: u32 = 0x0100_0002;
/// The header's bytes read (version 2; version 1 ends at 284).
const HEADER_V1: usize = 284;
const HEADER_V2: usize = 352;

/// Whether `bytes` are a little-endian TIFF whose first IFD holds Park's
/// magic tag.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    let f = Bin::new(bytes, Path::new(""), FORMAT);
    bytes.starts_with(TIFF_LE)
        && first_ifd(&f).is_ok_and(|ifd| {
            ifd.iter()
                .find(|e| e.tag == TAG_MAGIC)
                .is_some_and(|e| long(&f, e, "magic").is_ok_and(|m| m == MAGIC))
        })
}

/// A directory entry.
struct Entry {
    tag: u16,
    kind: u16,
    count: u32,
    /// Where the entry's value field is (the value, or its offset).
    field: usize,
}

/// The entries of the first IFD.
fn first_ifd(f: &Bin) -> Result<Vec<Entry>> {
    let at = f.u32(4, "the offset of the first directory")? as usize;
    let n = usize::from(f.u16(at, "the number of directory entries")?);
    let entries = at
        .checked_add(2)
        .ok_or_else(|| f.bad(format!("the first directory at {at} is past the end")))?;
    f.slice(entries, n * 12, "the first directory")?;
    (0..n)
        .map(|i| {
            let e = entries + 12 * i;
            Ok(Entry {
                tag: f.u16(e, "a tag")?,
                kind: f.u16(e + 2, "a tag's type")?,
                count: f.u32(e + 4, "a tag's count")?,
                field: e + 8,
            })
        })
        .collect()
}

/// The bytes of an entry's value.
fn value<'b>(f: &Bin<'b>, e: &Entry, what: &str) -> Result<&'b [u8]> {
    let item = match e.kind {
        1 | 2 | 6 | 7 => 1,
        3 | 8 => 2,
        4 | 9 | 11 => 4,
        5 | 10 | 12 => 8,
        k => return Err(f.bad(format!("tag {} ({what}) has the unknown type {k}", e.tag))),
    };
    let len = (e.count as usize)
        .checked_mul(item)
        .ok_or_else(|| f.bad(format!("tag {} ({what}) is too large", e.tag)))?;
    let at = if len <= 4 {
        e.field
    } else {
        f.u32(e.field, what)? as usize
    };
    f.slice(at, len, what)
}

/// A LONG tag of count 1.
fn long(f: &Bin, e: &Entry, what: &str) -> Result<u32> {
    if e.kind != 4 || e.count != 1 {
        return Err(f.bad(format!(
            "tag {} ({what}) is of type {} × {}, not one LONG",
            e.tag, e.kind, e.count
        )));
    }
    f.u32(e.field, what)
}

/// A fixed-length UTF-16LE text field, NUL- and space-trimmed.
fn utf16(b: &[u8]) -> String {
    String::from_utf16_lossy(&super::bin::utf16_units(b))
        .trim_matches(|c: char| c == '\0' || c == ' ')
        .to_string()
}

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(b, path, FORMAT);
    if b.starts_with(b"MM\0*") {
        return Err(f.bad("a big-endian TIFF: Park Systems writes little-endian (II) files"));
    }
    if !b.starts_with(TIFF_LE) {
        return Err(f.bad("the file does not start as a little-endian TIFF (II*\\0)"));
    }
    let ifd = first_ifd(&f)?;
    let tag = |t: u16, what: &str| {
        ifd.iter().find(|e| e.tag == t).ok_or_else(|| {
            f.bad(format!(
                "no tag {t} ({what}) in the first directory: not a Park Systems TIFF"
            ))
        })
    };
    let magic = long(&f, tag(TAG_MAGIC, "magic")?, "magic")?;
    if magic != MAGIC {
        return Err(f.bad(format!(
            "magic {magic:#010x}, not {MAGIC:#010x}: not a Park Systems TIFF"
        )));
    }
    let version = long(&f, tag(TAG_VERSION, "version")?, "version")?;
    let h = Bin::new(
        value(&f, tag(TAG_HEADER, "header")?, "the header")?,
        path,
        FORMAT,
    );
    let header = Header::read(&f, &h, version, options)?;
    let (nx, ny) = (header.nx, header.ny);
    let len = product(nx, ny, header.item)
        .ok_or_else(|| f.bad(format!("nx × ny = {nx} × {ny} is too large")))?;
    let d = Bin::new(value(&f, tag(TAG_DATA, "data")?, "the data")?, path, FORMAT);
    let data = d.slice(0, len, "the data (tag 50434)")?;
    let (gain, scale, offset) = (header.gain, header.scale, header.offset);
    let values = values(data, header.data_type);
    let largest = values
        .iter()
        .filter(|r| r.is_finite())
        .fold(0.0f64, |m, r| m.max(r.abs()));
    if [largest, -largest]
        .iter()
        .any(|&r| !(gain * (scale * r + offset)).is_finite())
    {
        return Err(f.bad(format!(
            "data gain {gain:e} · (scale factor {scale:e} · {largest} + offset {offset:e}) \
             overflows: not a finite height"
        )));
    }
    // The first row of the file is the bottom one: y up.
    let heights = values
        .chunks_exact(nx)
        .rev()
        .flatten()
        .map(|&r| gain * (scale * r + offset))
        .collect();
    Ok(Raw {
        size: Some(Stored {
            lx: header.lx,
            ly: header.ly,
            unit: Unit::of(LengthUnit::Micrometre),
            resolution: 4.0 * f64::EPSILON,
        }),
        height_unit: header.height_unit,
        ..Raw::map(nx, ny, heights)
    })
}

/// The fields of the header (tag 50435) that are read.
struct Header {
    height_unit: Unit,
    nx: usize,
    ny: usize,
    data_type: u32,
    /// Bytes per value.
    item: usize,
    gain: f64,
    scale: f64,
    offset: f64,
    lx: f64,
    ly: f64,
}

impl Header {
    /// The header `h` of a file of `version`; chooses its channel.
    fn read(f: &Bin, h: &Bin, version: u32, options: &ReadOptions) -> Result<Header> {
        let header_len = match version {
            VERSION_1 => HEADER_V1,
            VERSION_2 => HEADER_V2,
            v => return Err(f.bad(format!("version {v:#010x}: versions 1 and 2 are read"))),
        };
        h.slice(0, header_len, "the header (tag 50435)")?;
        if h.u32(0, "image type")? == 1 {
            return Err(f.bad("a line profile (image type 1) is not read"));
        }
        let name = utf16(h.slice(4, 64, "source name")?);
        let unit_text = match utf16(h.slice(244, 16, "data unit")?) {
            u if u.is_empty() => "um".to_string(),
            u => u,
        };
        let is_height = LengthUnit::parse(&unit_text).is_some();
        channel::choose(&[(&name, is_height)], options.channel.as_deref()).map_err(|m| f.bad(m))?;
        let height_unit = Unit::declared(&format!("the heights of {name:?}"), &unit_text)
            .map_err(|m| f.bad(m))?;
        let (nx, ny) = (h.u32(100, "nx")? as usize, h.u32(104, "ny")? as usize);
        if nx == 0 || ny == 0 {
            return Err(f.bad(format!("nx × ny = {nx} × {ny}: both must be > 0")));
        }
        let data_type = if version == VERSION_2 {
            h.u32(348, "data type")?
        } else {
            0
        };
        let item = match data_type {
            0 => 2,
            1 | 2 => 4,
            t => {
                return Err(f.bad(format!(
                    "data type {t}: 0 (int16), 1 (int32), 2 (float32) are read"
                )))
            }
        };
        let f64_at = |at: usize, what: &str| -> Result<f64> {
            let s = h.slice(at, 8, what)?;
            let v = f64::from_le_bytes([s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7]]);
            if !v.is_finite() {
                return Err(f.bad(format!("the {what} is {v}, not finite")));
            }
            Ok(v)
        };
        let scale = f64_at(228, "data scale factor")?;
        Ok(Header {
            height_unit,
            nx,
            ny,
            data_type,
            item,
            gain: f64_at(220, "data gain")?,
            scale: if scale == 0.0 { 1.0 } else { scale },
            offset: f64_at(236, "data offset")?,
            lx: f64_at(140, "Lx")?,
            ly: f64_at(148, "Ly")?,
        })
    }
}

/// The raw values of `data` (int16, int32 or float32 by `data_type`).
fn values(data: &[u8], data_type: u32) -> Vec<f64> {
    match data_type {
        0 => data
            .chunks_exact(2)
            .map(|c| f64::from(i16::from_le_bytes([c[0], c[1]])))
            .collect(),
        1 => data
            .chunks_exact(4)
            .map(|c| f64::from(i32::from_le_bytes([c[0], c[1], c[2], c[3]])))
            .collect(),
        _ => data
            .chunks_exact(4)
            .map(|c| f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])))
            .collect(),
    }
}

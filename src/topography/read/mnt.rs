//! Digital Surf Mountains `.mnt` (MountainsMap documents).
//!
//! A Microsoft compound file (OLE, `D0 CF 11 E0 A1 B1 1A E1`) whose stream
//! `ScopedContents` holds the document: a u64 size, then a tree of
//! tag-length-value entries, each a u16 tag, a u64 size and the value
//! (nested entries or data), all little-endian. Text is the byte 04
//! followed by UTF-16LE. Read along the path (tags in hex):
//!
//! ```text
//! 0001 main / 02BD contents / 0002 document / 0001 objects
//!   each object (preceded by a u64 size): 0001 class / 0001 number (u32),
//!   0002 body
//! class 9012, a measured surface: body / FFFF header / 0004 title,
//!   body / 0001 an object of class 9062 whose body / FFFF measurement:
//!     FFFF grid / FFFF header / FFFF description / 0001 name
//!     FFFF grid / 0001 (x), 0002 (y) / FFFF axis: FFFF scale, 0001 n (u32)
//!     FFFF grid / 0003 mask: class 9056, 0002 / 0001 width, 0002 height,
//!                            0005 an array of class 9048
//!     0001 heights: an array of class 9049
//!     0002 height axis / FFFF scale
//!   scale: 0001 step (f64), 0002 unit, 0003 display unit, 0005 origin (f64,
//!          display unit)
//!   array: 0002 / 0001 count (u32), 0002 data: u64 bytes, then blocks of
//!          u64 first element, u32 elements, u32 compressed size, zlib stream
//! ```
//!
//! The heights are int32 (or int16) counts, x fastest, the first row at
//! y = 0 (SurfaceTopography's `h[ix, iy]` is count `iy·nx + ix`):
//!
//! ```text
//! h = count·step_z + origin_z   (in the display unit of z)
//! Lx = nx·step_x,  Ly = ny·step_y   (in their units)
//! ```
//!
//! The mask, when there is one, is an (nx + 2) × (ny + 2) byte image with
//! a border of one pixel: 9 marks a measured point, anything else an
//! undefined one. Each measured surface (class 9012) is a channel, named
//! by its grid's name (else its title); a channel whose heights are not in
//! a unit of length is not a height channel. Derived layers are not stored
//! (Mountains recomputes them), nor read. The compound file is read with
//! 512- or 4096-byte sectors, its FAT (with DIFAT sectors) and its
//! mini stream.
//!
//! A zlib stream inflates at most 1032-fold: counts beyond that many bytes
//! per byte of the file are refused before anything is allocated.
//!
//! # References
//! \[MS-CFB\] Compound File Binary File Format (Microsoft Open
//! Specifications); the document's layout as SurfaceTopography's
//! `IO/MNT.py` reads it.

use std::io::Read;
use std::path::Path;

use super::bin::Bin;
use super::units::{LengthUnit, Unit};
use super::{channel, Raw, ReadOptions, Stored};
use crate::error::Result;

const FORMAT: &str = "Digital Surf Mountains .mnt";
const OLE_MAGIC: &[u8] = b"\xD0\xCF\x11\xE0\xA1\xB1\x1A\xE1";
const STREAM: &str = "ScopedContents";
const CLASS_SURFACE: u32 = 9012;
const CLASS_SURFACE_DATA: u32 = 9062;
const CLASS_MASK: u32 = 9056;
const CLASS_MASK_ARRAY: u32 = 9048;
const CLASS_HEIGHTS: u32 = 9049;
const MASK_MEASURED: u8 = 9;
/// Deflate's largest ratio of inflated to compressed bytes.
const MAX_INFLATE_RATIO: usize = 1032;
const END_OF_CHAIN: u32 = 0xFFFF_FFFE;

/// Whether `bytes` are a compound file holding a `ScopedContents` stream.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    let f = Bin::new(bytes, Path::new(""), FORMAT);
    bytes.starts_with(OLE_MAGIC)
        && Cfb::open_directory(&f).is_ok_and(|c| c.find(&f, STREAM).is_ok_and(|e| e.is_some()))
}

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(b, path, FORMAT);
    if !b.starts_with(OLE_MAGIC) {
        return Err(f.bad("the file is not a compound (OLE) file: no D0 CF 11 E0 magic"));
    }
    let cfb = Cfb::open(&f)?;
    let entry = cfb
        .find(&f, STREAM)?
        .ok_or_else(|| f.bad(format!("the compound file has no {STREAM} stream")))?;
    let stream = cfb.read(&f, &entry)?;
    let s = Bin::new(&stream, path, FORMAT);
    let body = s.slice(8, stream.len().saturating_sub(8), "the document")?;
    let surfaces = surfaces(&s, body)?;
    let channels: Vec<(&str, bool)> = surfaces
        .iter()
        .map(|c| (c.name.as_str(), c.z.display_length().is_some()))
        .collect();
    let k = channel::choose(&channels, options.channel.as_deref()).map_err(|m| s.bad(m))?;
    surfaces[k].read(&s)
}

// ---------------------------------------------------------------------------
// The compound file.

/// A compound file's geometry and its FAT.
struct Cfb {
    sector: usize,
    mini_sector: usize,
    mini_cutoff: u64,
    fat: Vec<u32>,
    mini_fat: Vec<u32>,
    directory: Vec<u8>,
    /// The root entry's stream (the mini stream's container).
    mini_stream: Vec<u8>,
}

/// A directory entry's stream.
struct Stream {
    start: u32,
    size: u64,
}

impl Cfb {
    /// The compound file with its mini FAT and mini stream.
    fn open(f: &Bin) -> Result<Cfb> {
        let mut cfb = Cfb::open_directory(f)?;
        let mini_fat = cfb.chain(f, f.u32(0x3C, "first mini FAT sector")?, None)?;
        cfb.mini_fat = mini_fat.chunks_exact(4).map(le_u32).collect();
        let root = cfb
            .entry(f, 0)?
            .ok_or_else(|| f.bad("the compound file has no root entry"))?;
        cfb.mini_stream = cfb.chain(f, root.start, Some(root.size))?;
        Ok(cfb)
    }

    /// The header, the FAT and the directory only (no stream is read).
    fn open_directory(f: &Bin) -> Result<Cfb> {
        f.slice(0, 512, "the compound file's header")?;
        let shift = f.u16(0x1E, "sector shift")?;
        let mini_shift = f.u16(0x20, "mini sector shift")?;
        if !(shift == 9 || shift == 12) || mini_shift != 6 {
            return Err(f.bad(format!(
                "compound file sector shifts {shift}, {mini_shift}: 9 or 12, and 6 are read"
            )));
        }
        let mut cfb = Cfb {
            sector: 1 << shift,
            mini_sector: 1 << mini_shift,
            mini_cutoff: u64::from(f.u32(0x38, "mini stream cutoff")?),
            fat: Vec::new(),
            mini_fat: Vec::new(),
            directory: Vec::new(),
            mini_stream: Vec::new(),
        };
        let fat_sectors = f.u32(0x2C, "number of FAT sectors")? as usize;
        let per_sector = cfb.sector / 4;
        // At most one FAT sector per sector of the file.
        if fat_sectors > f.bytes.len() / cfb.sector {
            return Err(f.bad(format!(
                "truncated: {fat_sectors} FAT sectors in a {}-byte file",
                f.bytes.len()
            )));
        }
        let mut difat: Vec<u32> = Vec::with_capacity(fat_sectors);
        for i in 0..109.min(fat_sectors) {
            difat.push(f.u32(0x4C + 4 * i, "the DIFAT")?);
        }
        let mut next = f.u32(0x44, "first DIFAT sector")?;
        // Each DIFAT sector adds per_sector - 1 > 0 entries: this ends.
        while difat.len() < fat_sectors {
            let at = cfb.offset(f, next, "a DIFAT sector")?;
            for i in 0..per_sector - 1 {
                if difat.len() < fat_sectors {
                    difat.push(f.u32(at + 4 * i, "a DIFAT sector")?);
                }
            }
            next = f.u32(at + cfb.sector - 4, "the next DIFAT sector")?;
        }
        for s in difat {
            let at = cfb.offset(f, s, "a FAT sector")?;
            let sector = f.slice(at, cfb.sector, "a FAT sector")?;
            cfb.fat.extend(sector.chunks_exact(4).map(le_u32));
        }
        cfb.directory = cfb.chain(f, f.u32(0x30, "first directory sector")?, None)?;
        Ok(cfb)
    }

    /// The file offset of sector `s`.
    fn offset(&self, f: &Bin, s: u32, what: &str) -> Result<usize> {
        let at = (u64::from(s) + 1)
            .checked_mul(self.sector as u64)
            .filter(|&at| at < f.bytes.len() as u64)
            .and_then(|at| usize::try_from(at).ok())
            .ok_or_else(|| f.bad(format!("truncated: {what} is sector {s}, past the end")))?;
        Ok(at)
    }

    /// The sectors of the chain from `start` (`size` bytes of it).
    fn chain(&self, f: &Bin, start: u32, size: Option<u64>) -> Result<Vec<u8>> {
        let mut out = Vec::new();
        let mut s = start;
        // A chain longer than the file has sectors visits one twice.
        let sectors = f.bytes.len() / self.sector;
        let mut steps = 0;
        while s != END_OF_CHAIN && size.is_none_or(|n| (out.len() as u64) < n) {
            if steps >= sectors {
                return Err(f.bad(format!(
                    "the compound file's FAT has a loop (a chain of more than its {sectors} sectors)"
                )));
            }
            let at = self.offset(f, s, "a stream")?;
            out.extend_from_slice(f.slice(at, self.sector, "a stream's sector")?);
            s = *self
                .fat
                .get(s as usize)
                .ok_or_else(|| f.bad(format!("sector {s} is beyond the compound file's FAT")))?;
            steps += 1;
        }
        if let Some(n) = size {
            if (out.len() as u64) < n {
                return Err(f.bad(format!(
                    "truncated: a stream of {n} bytes has {} in its sectors",
                    out.len()
                )));
            }
            out.truncate(n as usize);
        }
        Ok(out)
    }

    /// Directory entry `i` (`None` for an unused one).
    fn entry(&self, f: &Bin, i: usize) -> Result<Option<Stream>> {
        let d = Bin::new(&self.directory, f.path, FORMAT);
        let at = i * 128;
        if d.slice(at + 66, 1, "a directory entry")?[0] == 0 {
            return Ok(None);
        }
        // Version 3 files (512-byte sectors) may leave junk in the high half.
        let low = u64::from(d.u32(at + 120, "a stream size")?);
        let high = u64::from(d.u32(at + 124, "a stream size")?);
        let size = if self.sector > 512 {
            low | (high << 32)
        } else {
            low
        };
        Ok(Some(Stream {
            start: d.u32(at + 116, "a stream start")?,
            size,
        }))
    }

    /// The stream entry named `name`.
    fn find(&self, f: &Bin, name: &str) -> Result<Option<Stream>> {
        let wanted: Vec<u16> = name.encode_utf16().collect();
        for (i, e) in self.directory.chunks_exact(128).enumerate() {
            let len = usize::from(u16::from_le_bytes([e[64], e[65]]));
            let units = super::bin::utf16_units(&e[..len.min(64)]);
            if e[66] == 2 && units.strip_suffix(&[0]).unwrap_or(&units) == wanted {
                return self.entry(f, i);
            }
        }
        Ok(None)
    }

    /// A stream's bytes (from the mini stream below the cutoff).
    fn read(&self, f: &Bin, e: &Stream) -> Result<Vec<u8>> {
        if e.size >= self.mini_cutoff {
            if e.size > f.bytes.len() as u64 {
                return Err(f.bad(format!(
                    "truncated: a {}-byte stream in a {}-byte file",
                    e.size,
                    f.bytes.len()
                )));
            }
            return self.chain(f, e.start, Some(e.size));
        }
        let mut out = Vec::new();
        let mut s = e.start;
        let sectors = self.mini_stream.len() / self.mini_sector;
        let mut steps = 0;
        while (out.len() as u64) < e.size {
            if steps >= sectors {
                return Err(f.bad("the compound file's mini FAT has a loop"));
            }
            steps += 1;
            let sector = (s as usize)
                .checked_mul(self.mini_sector)
                .and_then(|at| self.mini_stream.get(at..at.checked_add(self.mini_sector)?))
                .ok_or_else(|| {
                    f.bad(format!(
                        "truncated: mini sector {s} is past the mini stream"
                    ))
                })?;
            out.extend_from_slice(sector);
            s = *self
                .mini_fat
                .get(s as usize)
                .ok_or_else(|| f.bad(format!("mini sector {s} is beyond the mini FAT")))?;
        }
        out.truncate(e.size as usize);
        Ok(out)
    }
}

fn le_u32(c: &[u8]) -> u32 {
    u32::from_le_bytes([c[0], c[1], c[2], c[3]])
}

fn le_u16(c: &[u8]) -> u16 {
    u16::from_le_bytes([c[0], c[1]])
}

// ---------------------------------------------------------------------------
// The document's tag-length-value entries.

/// The entries of a container: (tag, value); `prefixed` when each entry
/// is preceded by a u64 size.
fn entries<'b>(f: &Bin, b: &'b [u8], prefixed: bool) -> Result<Vec<(u16, &'b [u8])>> {
    let mut out = Vec::new();
    let mut at = 0;
    while at < b.len() {
        if prefixed {
            at += 8;
        }
        let head = at
            .checked_add(10)
            .and_then(|end| b.get(at..end))
            .ok_or_else(|| f.bad("truncated: an entry's header runs past its container"))?;
        let tag = le_u16(&head[..2]);
        let size = u64::from_le_bytes([
            head[2], head[3], head[4], head[5], head[6], head[7], head[8], head[9],
        ]);
        let value = usize::try_from(size)
            .ok()
            .and_then(|n| b.get(at + 10..(at + 10).checked_add(n)?))
            .ok_or_else(|| {
                f.bad(format!(
                    "truncated: entry {tag:#06x} of {size} bytes runs past its container \
                     ({} bytes left)",
                    b.len() - at - 10
                ))
            })?;
        out.push((tag, value));
        at += 10 + value.len();
    }
    Ok(out)
}

/// The value at `tags` below `b`, if there is one.
fn at<'b>(f: &Bin, b: &'b [u8], tags: &[u16]) -> Result<Option<&'b [u8]>> {
    let mut v = b;
    for &t in tags {
        match entries(f, v, false)?.into_iter().find(|(tag, _)| *tag == t) {
            Some((_, x)) => v = x,
            None => return Ok(None),
        }
    }
    Ok(Some(v))
}

/// The value at `tags`, or an error naming `what`.
fn need<'b>(f: &Bin, b: &'b [u8], tags: &[u16], what: &str) -> Result<&'b [u8]> {
    at(f, b, tags)?.ok_or_else(|| f.bad(format!("the document has no {what}")))
}

fn u32_of(f: &Bin, v: &[u8], what: &str) -> Result<u32> {
    v.try_into()
        .map(u32::from_le_bytes)
        .map_err(|_| f.bad(format!("{what} has {} bytes, not 4", v.len())))
}

fn f64_of(f: &Bin, v: &[u8], what: &str) -> Result<f64> {
    v.try_into()
        .map(f64::from_le_bytes)
        .map_err(|_| f.bad(format!("{what} has {} bytes, not 8", v.len())))
}

/// A text entry: 04, then UTF-16LE (`None` for anything else).
fn text(v: &[u8]) -> Option<String> {
    let rest = v.strip_prefix(&[4])?;
    if rest.len() % 2 != 0 {
        return None;
    }
    String::from_utf16(&super::bin::utf16_units(rest))
        .ok()
        .map(|s| s.trim_end_matches('\0').to_string())
}

/// An object's class number.
fn class(f: &Bin, object: &[u8]) -> Result<Option<u32>> {
    at(f, object, &[1, 1])?
        .map(|v| u32_of(f, v, "a class number"))
        .transpose()
}

// ---------------------------------------------------------------------------
// The measured surfaces.

/// An axis's scale.
struct Scale {
    step: f64,
    unit: String,
    display_unit: Option<String>,
    origin: f64,
}

impl Scale {
    fn read(f: &Bin, b: &[u8], what: &str) -> Result<Scale> {
        let step = f64_of(f, need(f, b, &[1], &format!("step of {what}"))?, "a step")?;
        let unit = at(f, b, &[2])?.and_then(text).unwrap_or_default();
        if !step.is_finite() || unit.is_empty() {
            return Err(f.bad(format!(
                "the scale of {what} is incomplete (step {step}, unit {unit:?})"
            )));
        }
        let origin = at(f, b, &[5])?
            .map(|v| f64_of(f, v, "an origin"))
            .transpose()?
            .unwrap_or(0.0);
        if !origin.is_finite() {
            return Err(f.bad(format!("the origin of {what} is {origin}, not finite")));
        }
        Ok(Scale {
            step,
            unit,
            display_unit: at(f, b, &[3])?.and_then(text).filter(|u| !u.is_empty()),
            origin,
        })
    }

    /// The display unit (else the unit), if it is a length.
    fn display_length(&self) -> Option<LengthUnit> {
        LengthUnit::parse(self.display_unit.as_ref().unwrap_or(&self.unit))
    }

    /// The unit of the step, which must be a length.
    fn length(&self, f: &Bin, what: &str) -> Result<LengthUnit> {
        LengthUnit::parse(&self.unit)
            .ok_or_else(|| f.bad(super::units::not_a_length(what, &self.unit)))
    }
}

/// A measured surface: its channel name, grid, scales and arrays.
struct Surface<'b> {
    name: String,
    nx: usize,
    ny: usize,
    x: Scale,
    y: Scale,
    z: Scale,
    heights: &'b [u8],
    mask: Option<&'b [u8]>,
}

/// The measured surfaces (class 9012) of the document.
fn surfaces<'b>(f: &Bin, body: &'b [u8]) -> Result<Vec<Surface<'b>>> {
    let objects = need(f, body, &[1, 0x02BD, 2, 1], "list of objects")?;
    let mut out = Vec::new();
    for (tag, object) in entries(f, objects, true)? {
        if tag != 1 || class(f, object)? != Some(CLASS_SURFACE) {
            continue;
        }
        let body = need(f, object, &[2], "body of a surface")?;
        let Some(data) = at(f, body, &[1])? else {
            continue;
        };
        if class(f, data)? != Some(CLASS_SURFACE_DATA) {
            continue;
        }
        let title = at(f, body, &[0xFFFF, 4])?.and_then(text);
        let m = need(f, data, &[2, 0xFFFF], "measurement of a surface")?;
        out.push(surface(f, m, title)?);
    }
    if out.is_empty() {
        return Err(f.bad("the document holds no measured surface (class 9012)"));
    }
    Ok(out)
}

fn surface<'b>(f: &Bin, m: &'b [u8], title: Option<String>) -> Result<Surface<'b>> {
    let grid = need(f, m, &[0xFFFF], "grid of a surface")?;
    let name = at(f, grid, &[0xFFFF, 0xFFFF, 1])?
        .and_then(text)
        .filter(|n| !n.is_empty())
        .or(title.filter(|n| !n.is_empty()))
        .unwrap_or_else(|| "Default".into());
    let axis = |tag: u16, what: &str| -> Result<(usize, Scale)> {
        let a = need(f, grid, &[tag, 0xFFFF], what)?;
        let n = u32_of(f, need(f, a, &[1], what)?, "a number of points")? as usize;
        let scale = Scale::read(f, need(f, a, &[0xFFFF], what)?, what)?;
        Ok((n, scale))
    };
    let (nx, x) = axis(1, "x axis")?;
    let (ny, y) = axis(2, "y axis")?;
    let heights = need(f, m, &[1], "heights")?;
    if class(f, heights)? != Some(CLASS_HEIGHTS) {
        return Err(f.bad("the heights are not an array of class 9049"));
    }
    let z = Scale::read(f, need(f, m, &[2, 0xFFFF], "height axis")?, "the heights")?;
    let mask = match at(f, grid, &[3])? {
        Some(mask) if class(f, mask)? == Some(CLASS_MASK) => {
            let w = u32_of(f, need(f, mask, &[2, 1], "mask width")?, "mask width")?;
            let h = u32_of(f, need(f, mask, &[2, 2], "mask height")?, "mask height")?;
            let array = need(f, mask, &[2, 5], "mask array")?;
            if (w as usize, h as usize) != (nx, ny) || class(f, array)? != Some(CLASS_MASK_ARRAY) {
                return Err(f.bad(format!(
                    "the mask of {w} × {h} points does not fit the grid of {nx} × {ny}"
                )));
            }
            Some(array)
        }
        _ => None,
    };
    Ok(Surface {
        name,
        nx,
        ny,
        x,
        y,
        z,
        heights,
        mask,
    })
}

impl Surface<'_> {
    fn read(&self, f: &Bin) -> Result<Raw> {
        let (nx, ny) = (self.nx, self.ny);
        let count = nx
            .checked_mul(ny)
            .filter(|&c| c > 0)
            .ok_or_else(|| f.bad(format!("nx × ny = {nx} × {ny}: both must be > 0")))?;
        let (bytes, item) = array(f, self.heights, count, "the heights")?;
        let display = self.z.display_length().ok_or_else(|| {
            let u = self.z.display_unit.as_ref().unwrap_or(&self.z.unit);
            f.bad(super::units::not_a_length(
                &format!("the heights of {:?}", self.name),
                u,
            ))
        })?;
        let step = self.z.step * (self.z.length(f, "the height step")?.metres() / display.metres());
        let origin = self.z.origin;
        let mut heights: Vec<f64> = if item == 2 {
            bytes
                .chunks_exact(2)
                .map(|c| f64::from(i16::from_le_bytes([c[0], c[1]])) * step + origin)
                .collect()
        } else if item == 4 {
            bytes
                .chunks_exact(4)
                .map(|c| f64::from(i32::from_le_bytes([c[0], c[1], c[2], c[3]])) * step + origin)
                .collect()
        } else {
            return Err(f.bad(format!("heights of {item} bytes each: 2 or 4 are read")));
        };
        if let Some(mask) = self.mask {
            let bordered = (nx.checked_add(2), ny.checked_add(2));
            let cells = match bordered {
                (Some(a), Some(b)) => a.checked_mul(b),
                _ => None,
            }
            .ok_or_else(|| {
                f.bad(format!(
                    "a mask of ({nx} + 2) × ({ny} + 2) bytes is too large"
                ))
            })?;
            let (m, item) = array(f, mask, cells, "the mask")?;
            if item != 1 {
                return Err(f.bad(format!("the mask has {item} bytes per point, not 1")));
            }
            for (iy, row) in m.chunks_exact(nx + 2).skip(1).take(ny).enumerate() {
                for (ix, &v) in row[1..=nx].iter().enumerate() {
                    if v != MASK_MEASURED {
                        heights[iy * nx + ix] = f64::NAN;
                    }
                }
            }
        }
        let ux = self.x.length(f, "the x step")?;
        let uy = self.y.length(f, "the y step")?;
        Ok(Raw {
            size: Some(Stored {
                lx: nx as f64 * self.x.step,
                ly: ny as f64 * self.y.step * (uy.metres() / ux.metres()),
                unit: Unit::Stated(self.x.unit.clone(), ux),
                resolution: 4.0 * f64::EPSILON,
            }),
            height_unit: Unit::Stated(
                self.z
                    .display_unit
                    .clone()
                    .unwrap_or_else(|| self.z.unit.clone()),
                display,
            ),
            ..Raw::map(nx, ny, heights)
        })
    }
}

/// The inflated bytes of an array of `count` elements, and the size of an
/// element.
fn array(f: &Bin, object: &[u8], count: usize, what: &str) -> Result<(Vec<u8>, usize)> {
    let stated = u32_of(f, need(f, object, &[2, 1], what)?, "a count")? as usize;
    if stated != count {
        return Err(f.bad(format!("{what}: {stated} values for a grid of {count}")));
    }
    let data = need(f, object, &[2, 2], what)?;
    let d = Bin::new(data, f.path, FORMAT);
    let total = d.u32(0, what)? as u64 | (u64::from(d.u32(4, what)?) << 32);
    let total = usize::try_from(total).unwrap_or(usize::MAX);
    if total % count != 0 || total / count > 8 {
        return Err(f.bad(format!("{what}: {total} bytes for {count} values")));
    }
    if total > data.len().saturating_mul(MAX_INFLATE_RATIO) {
        return Err(f.bad(format!(
            "{what}: {total} bytes cannot inflate from {} compressed bytes",
            data.len()
        )));
    }
    let item = total / count;
    let mut out = vec![0u8; total];
    let mut filled = 0;
    let mut at = 8;
    while at < data.len() {
        let first = u64::from(d.u32(at, "a block's first element")?)
            | u64::from(d.u32(at + 4, "a block's first element")?) << 32;
        let n = d.u32(at + 8, "a block's size")? as usize;
        let packed = d.u32(at + 12, "a block's compressed size")? as usize;
        let z = d.slice(at + 16, packed, "a compressed block")?;
        let start = usize::try_from(first)
            .ok()
            .and_then(|s| s.checked_mul(item))
            .filter(|&s| s <= total);
        let end = start
            .and_then(|s| n.checked_mul(item)?.checked_add(s))
            .filter(|&e| e <= total);
        let (Some(start), Some(end)) = (start, end) else {
            return Err(f.bad(format!(
                "{what}: a block of {n} values at {first} is outside the array"
            )));
        };
        let mut block = Vec::with_capacity(end - start);
        flate2::read::ZlibDecoder::new(z)
            .take((end - start) as u64 + 1)
            .read_to_end(&mut block)
            .map_err(|e| f.bad(format!("{what}: a compressed block is corrupt: {e}")))?;
        if block.len() != end - start {
            return Err(f.bad(format!(
                "{what}: a block inflates to {} bytes, not {}",
                block.len(),
                end - start
            )));
        }
        out[start..end].copy_from_slice(&block);
        filled += block.len();
        at += 16 + packed;
    }
    if filled != total {
        return Err(f.bad(format!("truncated: {what} hold {filled} of {total} bytes")));
    }
    Ok((out, item))
}

//! FRT MicroProf `.frt` (FRT's, now FormFactor's, MicroProf optical
//! profilometers).
//!
//! The magic `FRTM_GLIDERV`, a 4-byte version (`1.00` or `1.01`), a u16
//! count of blocks, then the blocks, each a u16 tag and a size (u32 in
//! version 1.00, u64 in 1.01) followed by that many bytes; all little-endian.
//! The blocks read (others are skipped by their size):
//!
//! ```text
//! 0x0066  u32 nx, u32 ny, u32 bits per value (16 or 32)
//! 0x0067  f64 Lx, f64 Ly (m), f64 x, y offset, f64 factor, u32 scan direction
//! 0x006c  u32 range, f64 z scale (m per count)
//! 0x0070  u32 first valid, u32 last valid value
//! 0x000b  ny rows of nx values (u16 or i32), x fastest: the topography
//! 0x007d  u16 × 4 buffer ids, then images, each
//!         u32 data type, u32 nx, u32 ny, u32 bits, ny rows of nx values
//! ```
//!
//! The first stored row is the bottom line of the image (y = Ly): row
//! `ny − 1 − iy` of the file is row `iy` here, as SurfaceTopography and
//! Gwyddion orient it. Heights are `value × z scale` in metres.
//!
//! # Undefined points
//! A height value outside the file's range of valid values (block 0x0070,
//! `[5, 65529]` in the example files) is undefined (NaN), and so is the
//! value 1 in every channel, with or without that block. The sensor writes 1
//! where it lost the surface; `frt-1.frt` of SurfaceTopography's examples
//! also ends in a row of 500 zeros. SurfaceTopography 1.27 and Gwyddion 2.61
//! mark only the value 1, and so read that row as heights of 0 m, 79 µm
//! below the rest of the scan (about 40 rms heights away): a step that
//! dominates the spectrum's long wavelengths. Here the row is undefined,
//! which a user fills (`fill_undefined`) or crops.
//!
//! # Channels
//! The topography of block 0x000b, named `Topography`, then each image of
//! the multi-image block 0x007d, named by its data type as Gwyddion names it,
//! the sensor and the buffer (`Topography (top sensor) 1`,
//! `Intensity (top sensor) 1`). Images of the types topography (0x4),
//! thickness (0x80), sample thickness (0x800) and AFM (0x1000) are heights;
//! the default is the first height channel (block 0x000b when there is one,
//! as SurfaceTopography reads, which calls it `default`). Another channel
//! (intensity, …) is read by name or index as its raw counts, without the
//! z scale and with no unit: the caller gives the height unit.
//!
//! # References
//! The layout as SurfaceTopography's `IO/FRT.py` and Gwyddion's
//! `modules/file/microprof.c` read it (no public description by FRT).

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{LengthUnit, Unit};
use super::{channel, Raw, ReadOptions, Stored};
use crate::error::Result;

pub(crate) const MAGIC: &[u8] = b"FRTM_GLIDERV";
/// Magic, version and block count.
const PREFIX: usize = 18;
/// The value marking an undefined point.
const UNDEFINED: i64 = 1;
/// Data types of the images that hold heights.
const HEIGHT_TYPES: u32 = 0x0004 | 0x0080 | 0x0800 | 0x1000;
const TYPE_MASK: u32 = 0x0000_ffdf;
const BOTTOM_SENSOR: u32 = 0x1000_0000;
const BUFFER_MASK: u32 = 0x0f00_0000;
/// The header of an image of block 0x007d.
const IMAGE_HEADER: usize = 16;

/// Whether `bytes` start as this format's files do.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

/// One map of the file: its name, whether it holds heights, its grid and
/// its values.
struct Image<'b> {
    name: String,
    height: bool,
    nx: usize,
    ny: usize,
    bits: u32,
    data: &'b [u8],
}

/// The blocks this reader uses.
#[derive(Default)]
struct Blocks<'b> {
    grid: Option<&'b [u8]>,
    size: Option<&'b [u8]>,
    scale: Option<&'b [u8]>,
    single: Option<&'b [u8]>,
    multi: Option<&'b [u8]>,
    valid: Option<&'b [u8]>,
}

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(b, path, "FRT MicroProf .frt");
    if !b.starts_with(MAGIC) {
        return Err(f.bad("the file does not start with FRTM_GLIDERV"));
    }
    let blocks = blocks(&f)?;
    let mut images = Vec::new();
    if let Some(data) = blocks.single {
        let g = blocks
            .grid
            .ok_or_else(|| f.bad("no block 0x0066 (the grid of block 0x000b)"))?;
        if g.len() < 12 {
            return Err(f.bad(format!("block 0x0066 has {} bytes, needs 12", g.len())));
        }
        let at = |k: usize| u32::from_le_bytes([g[k], g[k + 1], g[k + 2], g[k + 3]]);
        images.push(image(
            &f,
            "Topography".into(),
            true,
            at(0),
            at(4),
            at(8),
            data,
        )?);
    }
    if let Some(m) = blocks.multi {
        multi_images(&f, m, &mut images)?;
    }
    let list: Vec<(&str, bool)> = images.iter().map(|i| (i.name.as_str(), i.height)).collect();
    let k = channel::choose(&list, options.channel.as_deref()).map_err(|e| f.bad(e))?;
    let im = &images[k];
    let scale = if im.height {
        let s = blocks
            .scale
            .ok_or_else(|| f.bad("no block 0x006c (the z scale)"))?;
        let z = f64::from_le_bytes(array(&f, s, 4, "the z scale of block 0x006c")?);
        if !(z.is_finite() && z != 0.0) {
            return Err(f.bad(format!(
                "z scale = {z} (block 0x006c): must be finite, not 0"
            )));
        }
        Some(z)
    } else {
        None
    };
    let s = blocks
        .size
        .ok_or_else(|| f.bad("no block 0x0067 (the scan size)"))?;
    let lx = f64::from_le_bytes(array(&f, s, 0, "Lx of block 0x0067")?);
    let ly = f64::from_le_bytes(array(&f, s, 8, "Ly of block 0x0067")?);
    let valid = match (im.height, blocks.valid) {
        (true, Some(v)) => {
            let w = v
                .get(..8)
                .ok_or_else(|| f.bad(format!("block 0x0070 has {} bytes, needs 8", v.len())))?;
            let at = |k: usize| i64::from(u32::from_le_bytes([w[k], w[k + 1], w[k + 2], w[k + 3]]));
            at(0)..=at(4)
        }
        _ => i64::MIN..=i64::MAX,
    };
    let m = || Unit::of(LengthUnit::Metre);
    Ok(Raw {
        size: Some(Stored {
            lx,
            ly,
            unit: m(),
            resolution: f64::EPSILON,
        }),
        height_unit: if scale.is_some() { m() } else { Unit::Unstated },
        // A non-height channel has no unit: the caller must give it.
        require_units: scale.is_none(),
        ..Raw::map(im.nx, im.ny, heights(im, scale, &valid))
    })
}

/// Eight bytes at `at` of a block, or an error naming the field.
fn array(f: &Bin, block: &[u8], at: usize, what: &str) -> Result<[u8; 8]> {
    block
        .get(at..at + 8)
        .and_then(|s| s.try_into().ok())
        .ok_or_else(|| f.bad(format!("{what}: the block has {} bytes", block.len())))
}

/// The blocks of the tag list.
fn blocks<'b>(f: &Bin<'b>) -> Result<Blocks<'b>> {
    let version = f.slice(MAGIC.len(), 4, "the version")?;
    let wide = match version {
        b"1.00" => false,
        b"1.01" => true,
        v => {
            return Err(f.bad(format!(
                "version {:?}: persson reads 1.00 and 1.01",
                String::from_utf8_lossy(v)
            )))
        }
    };
    let count = f.u16(16, "the count of blocks")?;
    let mut at = PREFIX;
    let mut found = Blocks::default();
    for _ in 0..count {
        let tag = f.u16(at, "a block's tag")?;
        let what = format!("the size of block 0x{tag:04x}");
        let (size, head) = if wide {
            let lo = u64::from(f.u32(at + 2, &what)?);
            let hi = u64::from(f.u32(at + 6, &what)?);
            (hi << 32 | lo, 10)
        } else {
            (u64::from(f.u32(at + 2, &what)?), 6)
        };
        let size = usize::try_from(size)
            .map_err(|_| f.bad(format!("block 0x{tag:04x}: size {size} is too large")))?;
        let data = f.slice(at + head, size, &format!("block 0x{tag:04x}"))?;
        match tag {
            0x0066 => found.grid = Some(data),
            0x0067 => found.size = Some(data),
            0x006c => found.scale = Some(data),
            0x000b => found.single = Some(data),
            0x007d => found.multi = Some(data),
            0x0070 => found.valid = Some(data),
            _ => {}
        }
        at += head + size;
    }
    if found.single.is_none() && found.multi.is_none() {
        return Err(f.bad("no height data (neither block 0x000b nor 0x007d)"));
    }
    Ok(found)
}

/// An image of `nx × ny` values of `bits` that fill `data`.
fn image<'b>(
    f: &Bin,
    name: String,
    height: bool,
    nx: u32,
    ny: u32,
    bits: u32,
    data: &'b [u8],
) -> Result<Image<'b>> {
    let (nx, ny) = (nx as usize, ny as usize);
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!("{name}: nx × ny = {nx} × {ny}: both must be > 0")));
    }
    if bits != 16 && bits != 32 {
        return Err(f.bad(format!(
            "{name}: {bits} bits per value: persson reads 16 (u16) and 32 (i32)"
        )));
    }
    let len = product(nx, ny, bits as usize / 8)
        .ok_or_else(|| f.bad(format!("{name}: nx × ny = {nx} × {ny} is too large")))?;
    if data.len() < len {
        return Err(f.bad(format!(
            "truncated: {name} needs {len} bytes ({nx} × {ny} × {bits} bits), the block has {}",
            data.len()
        )));
    }
    Ok(Image {
        name,
        height,
        nx,
        ny,
        bits,
        data: &data[..len],
    })
}

/// The images of the multi-image block 0x007d, appended to `images`.
fn multi_images<'b>(f: &Bin, m: &'b [u8], images: &mut Vec<Image<'b>>) -> Result<()> {
    let mut rest = m
        .get(8..)
        .ok_or_else(|| f.bad("truncated: block 0x007d has no buffer ids"))?;
    while rest.len() > IMAGE_HEADER {
        let at = |k: usize| u32::from_le_bytes([rest[k], rest[k + 1], rest[k + 2], rest[k + 3]]);
        let (kind, nx, ny, bits) = (at(0), at(4), at(8), at(12));
        let im = image(
            f,
            type_name(kind),
            kind & HEIGHT_TYPES != 0,
            nx,
            ny,
            bits,
            &rest[IMAGE_HEADER..],
        )?;
        rest = &rest[IMAGE_HEADER + im.data.len()..];
        images.push(im);
    }
    Ok(())
}

/// The name of an image of block 0x007d (Gwyddion's, as SurfaceTopography
/// names the height images).
fn type_name(kind: u32) -> String {
    let base = match kind & TYPE_MASK {
        0x0001 => "Piezo",
        0x0002 => "Intensity",
        0x0004 => "Topography",
        0x0008 => "Real part",
        0x0010 => "Imaginary part",
        0x0040 => "Camera",
        0x0080 => "Thickness",
        0x0100 => "DIB from file",
        0x0200 => "Absolute value",
        0x0400 => "Phase",
        0x0800 => "Sample thickness",
        0x1000 => "AFM",
        0x2000 => "Quality",
        0x4001 => "Fit",
        _ => "Unknown",
    };
    let sensor = if kind & BOTTOM_SENSOR != 0 {
        "bottom"
    } else {
        "top"
    };
    format!(
        "{base} ({sensor} sensor) {}",
        ((kind & BUFFER_MASK) >> 24) + 1
    )
}

/// The values of `im`, row `ny − 1 − iy` of the file as row `iy`, times
/// `scale`; 1 and a value outside `valid` are NaN.
fn heights(im: &Image, scale: Option<f64>, valid: &std::ops::RangeInclusive<i64>) -> Vec<f64> {
    let value = |k: usize| -> i64 {
        if im.bits == 16 {
            i64::from(u16::from_le_bytes([im.data[2 * k], im.data[2 * k + 1]]))
        } else {
            let c = &im.data[4 * k..4 * k + 4];
            i64::from(i32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        }
    };
    let defined = |v: i64| v != UNDEFINED && valid.contains(&v);
    let mut h = Vec::with_capacity(im.nx * im.ny);
    for iy in 0..im.ny {
        let row = (im.ny - 1 - iy) * im.nx;
        h.extend((0..im.nx).map(|ix| match value(row + ix) {
            v if defined(v) => v as f64 * scale.unwrap_or(1.0),
            _ => f64::NAN,
        }));
    }
    h
}

//! Nanosurf `.nid` (and `.ezd`) files of Nanosurf's scanning probe
//! microscopes (easyScan, FlexAFM, DriveAFM).
//!
//! An INI-style text header, Latin-1 with CR LF, that starts with the line
//! `[DataSet]`, then `#!` at the start of a line and the binary data blocks
//! right after it. `[DataSet]` gives `GroupCount`, per group `Gr<i>-Count`
//! and, for each channel that has data, `Gr<i>-Ch<j>=<section>`; the blocks
//! follow in that order (groups, then channels), each described by its
//! section:
//!
//! ```text
//! Points, Lines                 values per line, lines
//! Frame                         "Scan forward", "Scan backward", …
//! Dim0Range/Dim0Unit, Dim1Range/Dim1Unit    the size along x, y
//! Dim2Name, Dim2Unit, Dim2Range, Dim2Min    the channel, its unit and range
//! SaveMode=Binary, SaveBits (8, 16, 32), SaveSign (Signed|Unsigned),
//! SaveOrder (Intel: little-endian, else big-endian)
//! ```
//!
//! Read, with `b = SaveBits` and `s = Dim2Range/2` for signed values
//! (else 0):
//!
//! ```text
//! h[iy, ix] = value[(Lines − 1 − iy)·Points + ix] · Dim2Range / 2^b + Dim2Min + s   (Dim2Unit)
//! Lx = Dim0Range (Dim0Unit),  Ly = Dim1Range (Dim1Unit)
//! ```
//!
//! The rows are read last first, as SurfaceTopography orients the map
//! (to match Gwyddion's image). No point is undefined.
//!
//! The channels are named `Frame (Dim2Name)` (`Scan forward (Z-Axis)`).
//! The one read is the first whose `Dim2Unit` is a length, or the one named
//! by [`ReadOptions::channel`] (by name, or by index among all the data
//! blocks; SurfaceTopography numbers only the length channels). A channel
//! in another unit (`Deflection`, N) is an error naming it.
//!
//! # References
//! The layout as SurfaceTopography's `IO/EZD.py` reads it (after Gwyddion's
//! `ezdfile.c`).

use std::collections::HashMap;
use std::path::Path;

use super::bin::{product, Bin};
use super::channel;
use super::units::{not_a_length, LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::Result;

const FORMAT: &str = "Nanosurf .nid";
/// Relative precision of the ranges as written (6 significant digits).
const RANGE_RESOLUTION: f64 = 5e-6;

/// Whether `bytes` start as this format's files do.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(b"[DataSet]\r\n") || bytes.starts_with(b"[DataSet]\n")
}

/// Sections of `key=value` lines.
struct Ini(Vec<(String, Vec<(String, String)>)>);

impl Ini {
    fn section(&self, name: &str) -> Option<&[(String, String)]> {
        self.0
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, s)| s.as_slice())
    }
}

fn get<'s>(section: &'s [(String, String)], key: &str) -> Option<&'s str> {
    section
        .iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
}

/// The header's sections and the offset of the first data block.
fn header(f: &Bin) -> Result<(Ini, usize)> {
    let b = f.bytes;
    let mut sections: Vec<(String, Vec<(String, String)>)> = Vec::new();
    let mut at = 0;
    while !b[at..].starts_with(b"#!") {
        let Some(len) = b[at..].iter().position(|&c| c == b'\n') else {
            return Err(f.bad("truncated: the header has no end (`#!`)"));
        };
        let line: String = b[at..at + len].iter().map(|&c| char::from(c)).collect();
        at += len + 1;
        let line = line.trim();
        if let Some(name) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            sections.push((name.to_string(), Vec::new()));
        } else if let (Some((k, v)), Some((_, s))) = (line.split_once('='), sections.last_mut()) {
            s.push((k.to_string(), v.trim().to_string()));
        }
    }
    Ok((Ini(sections), at + 2))
}

/// One data block.
struct Block<'h> {
    name: String,
    meta: &'h [(String, String)],
    offset: usize,
    nx: usize,
    ny: usize,
    bits: usize,
}

/// The data blocks in the order of the data.
fn blocks<'h>(f: &Bin, ini: &'h Ini) -> Result<Vec<Block<'h>>> {
    let top = ini
        .section("DataSet")
        .ok_or_else(|| f.bad("the header has no [DataSet]"))?;
    let int = |s: &[(String, String)], key: &str, what: &str| -> Result<usize> {
        let v = get(s, key).ok_or_else(|| f.bad(format!("{what} has no {key}")))?;
        v.parse::<usize>()
            .map_err(|_| f.bad(format!("{what}: {key} = {v:?} is not a count")))
    };
    let groups = int(top, "GroupCount", "[DataSet]")?;
    // The channels `Gr<i>-Ch<j>` there are, in the order of the data (the
    // first of a repeated key, as `get` finds it): walking all the indices
    // the counts allow would take as long as the counts say.
    let mut keys: Vec<(usize, usize, &str)> = top
        .iter()
        .filter_map(|(k, v)| {
            let (i, j) = k.strip_prefix("Gr")?.split_once("-Ch")?;
            let index = |s: &str| s.parse::<usize>().ok().filter(|n| n.to_string() == s);
            Some((index(i)?, index(j)?, v.as_str()))
        })
        .filter(|&(i, _, _)| i < groups)
        .collect();
    keys.sort_by_key(|&(i, j, _)| (i, j));
    keys.dedup_by_key(|&mut (i, j, _)| (i, j));
    // The sections by name (the first of a repeated name, as `Ini::section`
    // finds it), for many channels in as many sections.
    let mut sections: HashMap<&str, &[(String, String)]> = HashMap::new();
    for (n, s) in &ini.0 {
        sections.entry(n.as_str()).or_insert(s.as_slice());
    }
    let mut out = Vec::new();
    let mut offset = 0usize;
    let mut group = None;
    for (i, j, name) in keys {
        let count = match group {
            Some((g, c)) if g == i => c,
            _ => int(top, &format!("Gr{i}-Count"), "[DataSet]")?,
        };
        group = Some((i, count));
        if j >= count {
            continue;
        }
        let what = format!("[{name}]");
        let meta = sections
            .get(name)
            .copied()
            .ok_or_else(|| f.bad(format!("the header has no {what}")))?;
        if get(meta, "SaveMode") != Some("Binary") {
            return Err(f.bad(format!("{what}: only SaveMode=Binary is read")));
        }
        let (nx, ny) = (int(meta, "Points", &what)?, int(meta, "Lines", &what)?);
        let bits = int(meta, "SaveBits", &what)?;
        if ![8, 16, 32].contains(&bits) {
            return Err(f.bad(format!("{what}: SaveBits = {bits} (8, 16 or 32 are read)")));
        }
        let len = product(nx, ny, bits / 8)
            .ok_or_else(|| f.bad(format!("{what}: {nx} × {ny} points are too many")))?;
        let frame = get(meta, "Frame").unwrap_or("");
        let dim2 = get(meta, "Dim2Name").unwrap_or("");
        out.push(Block {
            name: format!("{frame} ({dim2})"),
            meta,
            offset,
            nx,
            ny,
            bits,
        });
        offset = offset
            .checked_add(len)
            .ok_or_else(|| f.bad("the data blocks are too large"))?;
    }
    Ok(out)
}

pub(crate) fn parse(path: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(bytes, path, FORMAT);
    if !sniff(bytes) {
        return Err(f.bad("the file does not start with [DataSet]"));
    }
    let (ini, start) = header(&f)?;
    let blocks = blocks(&f, &ini)?;
    let unit_of = |b: &Block, key: &str| get(b.meta, key).unwrap_or("").to_string();
    let channels: Vec<(&str, bool)> = blocks
        .iter()
        .map(|b| {
            let u = unit_of(b, "Dim2Unit");
            (b.name.as_str(), LengthUnit::parse(&u).is_some())
        })
        .collect();
    let k = channel::choose(&channels, options.channel.as_deref()).map_err(|m| f.bad(m))?;
    let b = &blocks[k];
    let what = format!("channel \"{}\"", b.name);
    let length = |key: &str| -> Result<(String, LengthUnit)> {
        let u = unit_of(b, key);
        match LengthUnit::parse(&u) {
            Some(l) => Ok((u, l)),
            None => Err(f.bad(not_a_length(&format!("{what}: {key}"), &u))),
        }
    };
    let number = |key: &str| -> Result<f64> {
        let v = get(b.meta, key).ok_or_else(|| f.bad(format!("{what} has no {key}")))?;
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| f.bad(format!("{what}: {key} = {v:?} is not a number")))
    };
    let (z_text, z_unit) = length("Dim2Unit")?;
    let (x_text, x_unit) = length("Dim0Unit")?;
    let (_, y_unit) = length("Dim1Unit")?;
    let range = number("Dim2Range")?;
    let min = get(b.meta, "Dim2Min").map_or(Ok(0.0), |_| number("Dim2Min"))?;
    let signed = get(b.meta, "SaveSign") == Some("Signed");
    let little = get(b.meta, "SaveOrder") == Some("Intel");
    let item = b.bits / 8;
    let at = start
        .checked_add(b.offset)
        .ok_or_else(|| f.bad("the data blocks are too large"))?;
    let len = product(b.nx, b.ny, item).ok_or_else(|| f.bad("the data blocks are too large"))?;
    let data = f.slice(at, len, &format!("the data of {what}"))?;
    let scale = range / 2f64.powi(b.bits as i32);
    let offset = min + if signed { range / 2.0 } else { 0.0 };
    let value = |c: &[u8]| -> f64 {
        let mut a = [0u8; 4];
        a[..item].copy_from_slice(c);
        if !little {
            a[..item].reverse();
        }
        let u = u32::from_le_bytes(a);
        let v = match (signed, item) {
            (true, 1) => f64::from(u as u8 as i8),
            (true, 2) => f64::from(u as u16 as i16),
            (true, _) => f64::from(u as i32),
            (false, _) => f64::from(u),
        };
        v * scale + offset
    };
    let mut heights = Vec::with_capacity(b.nx * b.ny);
    for iy in 0..b.ny {
        let row = &data[(b.ny - 1 - iy) * b.nx * item..][..b.nx * item];
        heights.extend(row.chunks_exact(item).map(value));
    }
    let lx = number("Dim0Range")?;
    let ly = number("Dim1Range")? * y_unit.metres() / x_unit.metres();
    Ok(Raw {
        size: Some(Stored {
            lx,
            ly,
            unit: Unit::Stated(x_text, x_unit),
            resolution: RANGE_RESOLUTION,
        }),
        height_unit: Unit::Stated(z_text, z_unit),
        ..Raw::map(b.nx, b.ny, heights)
    })
}

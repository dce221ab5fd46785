//! Bruker Dektak `.opdx` (the Vision64 software of Dektak XT stylus
//! profilometers): profiles and height maps.
//!
//! The magic `VCA DATA\x01\x00\x00\x55`, then a tree of items, each
//!
//! ```text
//! u32 length, name (UTF-8), u8 type, value
//! ```
//!
//! little-endian; a "varlen" is a u8 width (1, 2 or 4) and an unsigned
//! integer of that width. Containers (types 0x7d, 0x46, 0x47: a varlen
//! length, items, an item of type 0x7f with an empty name, two bytes) nest
//! the items under paths such as `/1D_Data/Raw/Array`. The values: integers
//! and floats of types 0x01 (bool), 0x04–0x07, 0x0a–0x0d; strings (0x12:
//! varlen length, UTF-8); quantities (0x13: varlen length, f64 value, name,
//! symbol); units (0x18: varlen length, name, symbol, f64, 12 bytes); time
//! stamps (0x15, 9 bytes); type ids (0x0e), double arrays (0x40), string
//! lists (0x42: a sequence of names), positions (0x7c) and matrices (0x00:
//! type name, u32, name, varlen length, u32 ny, u32 nx, f32 values; 0x45: type
//! name, varlen length, u32 ny, u32 nx, f32 values), each after a type name.
//!
//! `/MetaData/DataKind` is `Surface Profile` (a line scan) or `Surface
//! Height` (a map; without it, whichever data the file holds):
//!
//! ```text
//! profile  /1D_Data/<c>/Array: 5 bytes, NumPoints f64 values
//!          h = value · DataScale (its unit),  L = Extent · n/(n − 1) (its unit)
//! map      /2D_Data/<c>/Matrix: ny rows of nx f32 values, x fastest
//!          nx = Dimension2Points, ny = Dimension1Points
//!          h = value · DataScale,  Lx = Dimension2Extent · nx/(nx − 1),
//!          Ly = Dimension1Extent · ny/(ny − 1)
//! ```
//!
//! The extent is the distance from the first point to the last (the
//! instrument's text export of `opdx-3.opdx` runs x from 0 to the extent).
//! No point is undefined (NaN would be).
//!
//! # Channels
//! The channels listed in `/MetaData/1D_Channels/Height` (profiles) or
//! `/MetaData/2D_Channels/Height` (maps, `/MetaData/PrimaryData2D` first),
//! named as listed (`Raw`); all hold heights, the default is the first.
//!
//! # References
//! The layout as SurfaceTopography's `IO/OPDx.py` and Gwyddion's
//! `modules/file/dektakvca.c` read it (no public description by Bruker).

use std::collections::HashMap;
use std::path::Path;

use super::bin::{product, Bin};
use super::units::{not_a_length, LengthUnit, Unit};
use super::{channel, Raw, ReadOptions, Stored};
use crate::error::Result;
use crate::topography::Layout;

pub(crate) const MAGIC: &[u8] = b"VCA DATA\x01\x00\x00\x55";
/// Bytes before the values of a double array.
const ARRAY_EXTRA: usize = 5;
/// Containers nest no deeper than this in the files seen (3); a deeper
/// nesting is refused rather than recursed into.
const MAX_DEPTH: usize = 32;

/// Whether `bytes` start as this format's files do.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

/// The values this reader uses.
#[derive(Debug, Clone)]
enum Value {
    Number(f64),
    Text(String),
    Quantity(f64, String),
    List(Vec<String>),
    /// Offset and length of the bytes.
    Array(usize, usize),
    /// Offset and length of the values, nx, ny.
    Matrix(usize, usize, usize, usize),
    Other,
}

/// A cursor over the file.
struct Cursor<'a, 'b> {
    f: &'a Bin<'b>,
    at: usize,
}

impl Cursor<'_, '_> {
    fn take(&mut self, n: usize, what: &str) -> Result<&[u8]> {
        let s = self.f.slice(self.at, n, what)?;
        self.at += n;
        Ok(s)
    }
    fn u8(&mut self, what: &str) -> Result<u8> {
        Ok(self.take(1, what)?[0])
    }
    fn u32(&mut self, what: &str) -> Result<u32> {
        let v = self.f.u32(self.at, what)?;
        self.at += 4;
        Ok(v)
    }
    fn f64(&mut self, what: &str) -> Result<f64> {
        let s = self.take(8, what)?;
        Ok(f64::from_le_bytes([
            s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7],
        ]))
    }
    fn varlen(&mut self, what: &str) -> Result<usize> {
        match self.u8(what)? {
            1 => Ok(usize::from(self.u8(what)?)),
            2 => {
                let v = self.f.u16(self.at, what)?;
                self.at += 2;
                Ok(usize::from(v))
            }
            4 => Ok(self.u32(what)? as usize),
            w => Err(self
                .f
                .bad(format!("{what}: a length of width {w} (1, 2 or 4)"))),
        }
    }
    fn name(&mut self, what: &str) -> Result<String> {
        let n = self.u32(what)? as usize;
        let s = self.take(n, what)?;
        Ok(String::from_utf8_lossy(s).into_owned())
    }
}

type Manifest = HashMap<String, Value>;

/// The items from `c` to their end item and the two bytes after it, under
/// `prefix`; an error if they run past `end`.
fn items(c: &mut Cursor, prefix: &str, end: usize, depth: usize, out: &mut Manifest) -> Result<()> {
    let place = if prefix.is_empty() { "/" } else { prefix };
    loop {
        if c.at >= end {
            return Err(c.f.bad(format!("truncated: {place} has no end item")));
        }
        let name = c.name("an item's name")?;
        let kind = c.u8("an item's type")?;
        let path = format!("{prefix}/{name}");
        let what = path.as_str();
        let value = match kind {
            0x7f => {
                c.take(2, &format!("the end of {place}"))?;
                return Ok(());
            }
            0x7d | 0x46 | 0x47 => {
                if depth >= MAX_DEPTH {
                    return Err(c.f.bad(format!("{path}: containers nested too deep")));
                }
                let len = c.varlen(what)?;
                let stop = c.at.saturating_add(len);
                c.f.slice(c.at, len, what)?;
                items(c, &path, stop, depth + 1, out)?;
                if c.at != stop {
                    return Err(c.f.bad(format!(
                        "{path}: its items end at byte {}, its length says {stop}",
                        c.at
                    )));
                }
                continue;
            }
            _ => value(c, kind, what)?,
        };
        out.insert(path, value);
    }
}

/// The value of an item of type `kind` (not a container), named `what`.
fn value(c: &mut Cursor, kind: u8, what: &str) -> Result<Value> {
    let v = match kind {
        0x01 => Value::Number(f64::from(c.u8(what)?)),
        0x04 | 0x05 => {
            let s = c.take(2, what)?;
            Value::Number(if kind == 0x04 {
                f64::from(i16::from_le_bytes([s[0], s[1]]))
            } else {
                f64::from(u16::from_le_bytes([s[0], s[1]]))
            })
        }
        0x06 | 0x07 | 0x0c => {
            let s = c.take(4, what)?;
            let a = [s[0], s[1], s[2], s[3]];
            Value::Number(match kind {
                0x06 => f64::from(i32::from_le_bytes(a)),
                0x07 => f64::from(u32::from_le_bytes(a)),
                _ => f64::from(f32::from_le_bytes(a)),
            })
        }
        0x0a | 0x0b | 0x0d => {
            let s = c.take(8, what)?;
            let a = [s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7]];
            Value::Number(match kind {
                0x0a => i64::from_le_bytes(a) as f64,
                0x0b => u64::from_le_bytes(a) as f64,
                _ => f64::from_le_bytes(a),
            })
        }
        0x12 => {
            let n = c.varlen(what)?;
            Value::Text(String::from_utf8_lossy(c.take(n, what)?).into_owned())
        }
        0x13 | 0x18 => {
            let n = c.varlen(what)?;
            let stop = c.at.saturating_add(n);
            c.f.slice(c.at, n, what)?;
            let q = if kind == 0x13 {
                let v = c.f64(what)?;
                c.name(what)?;
                Value::Quantity(v, c.name(what)?)
            } else {
                c.name(what)?;
                let symbol = c.name(what)?;
                Value::Quantity(c.f64(what)?, symbol)
            };
            if c.at > stop {
                return Err(c.f.bad(format!(
                    "{what}: a quantity of {n} bytes runs on to byte {} (its length ends at {stop})",
                    c.at
                )));
            }
            c.at = stop;
            q
        }
        0x15 => {
            c.take(9, what)?;
            Value::Other
        }
        0x00 | 0x45 => {
            c.name(what)?;
            if kind == 0x00 {
                c.u32(what)?;
                c.name(what)?;
            }
            let n = c.varlen(what)?;
            let ny = c.u32(what)? as usize;
            let nx = c.u32(what)? as usize;
            let n = n
                .checked_sub(8)
                .ok_or_else(|| c.f.bad(format!("{what}: a matrix of {n} bytes")))?;
            let at = c.at;
            c.take(n, what)?;
            Value::Matrix(at, n, nx, ny)
        }
        0x0e | 0x40 | 0x42 | 0x7c => {
            c.name(what)?;
            let n = c.varlen(what)?;
            let at = c.at;
            c.take(n, what)?;
            match kind {
                0x40 => Value::Array(at, n),
                0x42 => Value::List(names(c, at, n, what)?),
                _ => Value::Other,
            }
        }
        k => {
            return Err(c
                .f
                .bad(format!("{what}: an item of unknown type 0x{k:02x}")))
        }
    };
    Ok(v)
}

/// The names of a string list of `n` bytes at `at`.
fn names(c: &Cursor, at: usize, n: usize, what: &str) -> Result<Vec<String>> {
    let mut l = Cursor { f: c.f, at };
    let mut v = Vec::new();
    while l.at < at + n {
        v.push(l.name(what)?);
    }
    if l.at != at + n {
        return Err(c.f.bad(format!("{what}: the names overrun the list")));
    }
    Ok(v)
}

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(b, path, "Bruker Dektak .opdx");
    if !b.starts_with(MAGIC) {
        return Err(f.bad("the file does not start with VCA DATA"));
    }
    let mut m = Manifest::new();
    let mut c = Cursor {
        f: &f,
        at: MAGIC.len(),
    };
    items(&mut c, "", b.len(), 0, &mut m)?;
    let any = |p: &str| m.keys().any(|k| k.starts_with(p));
    match m.get("/MetaData/DataKind") {
        Some(Value::Text(t)) if t == "Surface Profile" => profile(&f, &m, options),
        Some(Value::Text(t)) if t == "Surface Height" => map(&f, &m, options),
        _ if any("/2D_Data/") => map(&f, &m, options),
        _ if any("/1D_Data/") => profile(&f, &m, options),
        kind => Err(f.bad(format!(
            "DataKind {kind:?}: neither a profile (1D_Data) nor a map (2D_Data)"
        ))),
    }
}

/// A value of the manifest, or an error naming it.
fn get<'m>(f: &Bin, m: &'m Manifest, key: &str) -> Result<&'m Value> {
    m.get(key).ok_or_else(|| f.bad(format!("no {key}")))
}

/// A count (`NumPoints`, `Dimension1Points`), at least 1.
fn count(f: &Bin, m: &Manifest, key: &str) -> Result<usize> {
    match get(f, m, key)? {
        Value::Number(v) if *v >= 1.0 && v.fract() == 0.0 && *v <= 1e15 => Ok(*v as usize),
        v => Err(f.bad(format!("{key} = {v:?}: not a count of points"))),
    }
}

/// A quantity in a unit of length: its value and unit.
fn length(f: &Bin, m: &Manifest, key: &str, what: &str) -> Result<(f64, Unit)> {
    match get(f, m, key)? {
        Value::Quantity(v, s) => match LengthUnit::parse(s) {
            Some(u) => Ok((*v, Unit::Stated(s.clone(), u))),
            None => Err(f.bad(format!("{key}: {}", not_a_length(what, s)))),
        },
        v => Err(f.bad(format!("{key} = {v:?}: not a quantity"))),
    }
}

/// `{prefix}/DataScale`: a finite, non-zero length, and its unit.
fn data_scale(f: &Bin, m: &Manifest, prefix: &str) -> Result<(f64, Unit)> {
    let key = format!("{prefix}/DataScale");
    let (scale, unit) = length(f, m, &key, "the heights")?;
    if !scale.is_finite() || scale == 0.0 {
        return Err(f.bad(format!("{key} = {scale}: not a finite, non-zero scale")));
    }
    Ok((scale, unit))
}

/// The size of `n` points whose first and last are `extent` apart.
fn size(extent: f64, n: usize) -> f64 {
    if n > 1 {
        extent * n as f64 / (n - 1) as f64
    } else {
        extent
    }
}

/// The channel to read among `names`, all heights.
fn chosen<'n>(f: &Bin, names: &'n [String], options: &ReadOptions) -> Result<&'n str> {
    let list: Vec<(&str, bool)> = names.iter().map(|n| (n.as_str(), true)).collect();
    let k = channel::choose(&list, options.channel.as_deref()).map_err(|e| f.bad(e))?;
    Ok(&names[k])
}

/// A line scan of `/1D_Data`.
fn profile(f: &Bin, m: &Manifest, options: &ReadOptions) -> Result<Raw> {
    let names = match get(f, m, "/MetaData/1D_Channels/Height")? {
        Value::List(l) => l.clone(),
        v => return Err(f.bad(format!("/MetaData/1D_Channels/Height = {v:?}: not a list"))),
    };
    let prefix = format!("/1D_Data/{}", chosen(f, &names, options)?);
    let n = count(f, m, &format!("{prefix}/NumPoints"))?;
    let (extent, x_unit) = length(f, m, &format!("{prefix}/Extent"), "the positions")?;
    let (scale, h_unit) = data_scale(f, m, &prefix)?;
    let key = format!("{prefix}/Array");
    let Value::Array(at, len) = *get(f, m, &key)? else {
        return Err(f.bad(format!("{key}: not an array of doubles")));
    };
    let need = product(n, 8, 1)
        .and_then(|v| v.checked_add(ARRAY_EXTRA))
        .ok_or_else(|| f.bad("NumPoints is too large"))?;
    if len != need {
        return Err(f.bad(format!(
            "{key} has {len} bytes; NumPoints = {n} needs {need}"
        )));
    }
    let data = f.slice(at + ARRAY_EXTRA, 8 * n, &key)?;
    let heights = data
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]) * scale)
        .collect();
    Ok(Raw {
        size: Some(Stored {
            lx: size(extent, n),
            ly: 0.0,
            unit: x_unit,
            resolution: f64::EPSILON,
        }),
        height_unit: h_unit,
        layout: Layout::LineScans,
        ..Raw::map(n, 1, heights)
    })
}

/// A height map of `/2D_Data`.
fn map(f: &Bin, m: &Manifest, options: &ReadOptions) -> Result<Raw> {
    let mut names = match m.get("/MetaData/2D_Channels/Height") {
        Some(Value::List(l)) => l.clone(),
        _ => Vec::new(),
    };
    if let Some(Value::Text(p)) = m.get("/MetaData/PrimaryData2D") {
        names.retain(|n| n != p);
        names.insert(0, p.clone());
    }
    names.retain(|n| m.contains_key(&format!("/2D_Data/{n}/Matrix")));
    if names.is_empty() {
        return Err(f.bad("no height map (no /2D_Data/<channel>/Matrix)"));
    }
    let prefix = format!("/2D_Data/{}", chosen(f, &names, options)?);
    let ny = count(f, m, &format!("{prefix}/Dimension1Points"))?;
    let nx = count(f, m, &format!("{prefix}/Dimension2Points"))?;
    let (ey, uy) = length(
        f,
        m,
        &format!("{prefix}/Dimension1Extent"),
        "the y positions",
    )?;
    let (ex, ux) = length(
        f,
        m,
        &format!("{prefix}/Dimension2Extent"),
        "the x positions",
    )?;
    let (scale, h_unit) = data_scale(f, m, &prefix)?;
    let key = format!("{prefix}/Matrix");
    let Value::Matrix(at, len, mx, my) = *get(f, m, &key)? else {
        return Err(f.bad(format!("{key}: not a matrix")));
    };
    let need = product(nx, ny, 4).ok_or_else(|| f.bad("nx × ny is too large"))?;
    if (mx, my) != (nx, ny) || len != need {
        return Err(f.bad(format!(
            "{key}: {mx} × {my} values in {len} bytes; the dimensions say {nx} × {ny}"
        )));
    }
    let heights = f
        .slice(at, len, &key)?
        .chunks_exact(4)
        .map(|c| f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])) * scale)
        .collect();
    let metres = |u: &Unit| match u {
        Unit::Stated(_, l) => l.metres(),
        Unit::Unstated => 1.0,
    };
    let ly = size(ey, ny) * (metres(&uy) / metres(&ux));
    Ok(Raw {
        size: Some(Stored {
            lx: size(ex, nx),
            ly,
            unit: ux,
            resolution: f64::EPSILON,
        }),
        height_unit: h_unit,
        ..Raw::map(nx, ny, heights)
    })
}

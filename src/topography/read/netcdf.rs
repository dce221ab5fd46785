//! NetCDF classic (`.nc`, CDF-1, CDF-2 and CDF-5) as SurfaceTopography and
//! contact.engineering write topographies.
//!
//! The container: big-endian; the magic `CDF` and a version byte (1, 2:
//! 64-bit offsets, 5: 64-bit sizes), the number of records, then lists of
//! dimensions (name, length), global attributes and variables (name,
//! dimension ids, attributes, type, size, offset of the values). Names are
//! padded to 4 bytes, as are attribute values.
//!
//! The conventions read (SurfaceTopography's `IO/NC.py`):
//! - the variable `heights`, dimensions `(x, y)`: a map whose first index is
//!   x (so y runs fastest in the file); dimension `(x)`: a line scan;
//! - attribute `length` of the variables `x` and `y`: the physical sizes;
//!   absent, the caller gives them;
//! - attribute `unit` of `x` (and `y`) and of `heights` (absent: the unit
//!   of `x`);
//! - an optional variable `mask` of the same shape, non-zero where a point is
//!   undefined, and the attributes `_FillValue` (undefined), `scale_factor`
//!   and `add_offset` (`h = raw·scale_factor + add_offset`) as NetCDF's
//!   conventions (and scipy's `maskandscale`) apply them.
//!
//! Types: byte, short, int, float, double (and CDF-5's unsigned and 64-bit
//! integers). Record variables (an unlimited dimension) and nonuniform line
//! scans (dimension `n`) are errors naming them. A file's `periodic`
//! attribute is not read: periodicity is the caller's (`ReadOptions::periodic`).
//!
//! The header is parsed here (a short grammar, every offset bounds-checked,
//! the values read in place) rather than with the `netcdf3` crate, whose
//! reader takes an owned `'static` stream (a copy of the file) and brings a
//! parser-combinator dependency for the same grammar.
//!
//! # References
//! Unidata, "NetCDF Classic and 64-bit Offset File Formats" and "CDF-5"
//! (the grammar of the header); the NetCDF Users Guide, "Attribute
//! Conventions" (`_FillValue`, `scale_factor`, `add_offset`).

use std::path::Path;

use super::units::Unit;
use super::{Raw, Stored};
use crate::error::{Error, Result};
use crate::topography::Layout;

pub(crate) const MAGIC: &[u8] = b"CDF";
const DIMENSION: u32 = 0x0A;
const VARIABLE: u32 = 0x0B;
const ATTRIBUTE: u32 = 0x0C;

/// An attribute's values: numbers or text.
enum Value {
    Numbers(Vec<f64>),
    Text(String),
}

struct Variable {
    name: String,
    dims: Vec<usize>,
    attributes: Vec<(String, Value)>,
    kind: u32,
    begin: u64,
}

impl Variable {
    fn number(&self, key: &str) -> Option<f64> {
        self.attributes.iter().find_map(|(k, v)| match v {
            Value::Numbers(n) if k == key => n.first().copied(),
            _ => None,
        })
    }

    fn text(&self, key: &str) -> Option<&str> {
        self.attributes.iter().find_map(|(k, v)| match v {
            Value::Text(t) if k == key => Some(t.as_str()),
            _ => None,
        })
    }
}

/// Bytes of one value of an external type, or `None` for an unknown type.
fn type_size(kind: u32) -> Option<usize> {
    match kind {
        1 | 2 | 7 => Some(1),
        3 | 8 => Some(2),
        4 | 5 | 9 => Some(4),
        6 | 10 | 11 => Some(8),
        _ => None,
    }
}

fn decode(kind: u32, c: &[u8]) -> f64 {
    match kind {
        1 => f64::from(c[0] as i8),
        2 | 7 => f64::from(c[0]),
        3 => f64::from(i16::from_be_bytes([c[0], c[1]])),
        8 => f64::from(u16::from_be_bytes([c[0], c[1]])),
        4 => f64::from(i32::from_be_bytes([c[0], c[1], c[2], c[3]])),
        9 => f64::from(u32::from_be_bytes([c[0], c[1], c[2], c[3]])),
        5 => f64::from(f32::from_be_bytes([c[0], c[1], c[2], c[3]])),
        _ => {
            let a = [c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]];
            match kind {
                6 => f64::from_be_bytes(a),
                10 => i64::from_be_bytes(a) as f64,
                _ => u64::from_be_bytes(a) as f64,
            }
        }
    }
}

/// The header, read in order, with errors naming the file.
struct Header<'b> {
    b: &'b [u8],
    pos: usize,
    path: &'b Path,
    /// CDF-5: counts and sizes are 8 bytes.
    wide: bool,
    /// CDF-2 and CDF-5: offsets are 8 bytes.
    long_offsets: bool,
}

impl<'b> Header<'b> {
    fn bad(&self, m: impl std::fmt::Display) -> Error {
        Error::parse(self.path, 0, 0, format!("NetCDF .nc: {m}"))
    }

    fn take(&mut self, n: usize) -> Result<&'b [u8]> {
        let end = self
            .pos
            .checked_add(n)
            .filter(|&e| e <= self.b.len())
            .ok_or_else(|| {
                self.bad(format!(
                    "truncated: the header needs {n} bytes at byte {}, the file has {}",
                    self.pos,
                    self.b.len()
                ))
            })?;
        let s = &self.b[self.pos..end];
        self.pos = end;
        Ok(s)
    }

    fn u32(&mut self) -> Result<u32> {
        let s = self.take(4)?;
        Ok(u32::from_be_bytes([s[0], s[1], s[2], s[3]]))
    }

    fn u64(&mut self) -> Result<u64> {
        let s = self.take(8)?;
        Ok(u64::from_be_bytes([
            s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7],
        ]))
    }

    /// A count or size: 4 bytes, 8 in CDF-5.
    fn count(&mut self) -> Result<usize> {
        let n = if self.wide {
            self.u64()?
        } else {
            u64::from(self.u32()?)
        };
        usize::try_from(n).map_err(|_| self.bad(format!("a count of {n} is too large")))
    }

    /// `n` bytes and the padding to 4.
    fn padded(&mut self, n: usize) -> Result<&'b [u8]> {
        let s = self.take(n)?;
        self.take((4 - n % 4) % 4)?;
        Ok(s)
    }

    fn name(&mut self) -> Result<String> {
        let n = self.count()?;
        let s = self.padded(n)?;
        String::from_utf8(s.to_vec()).map_err(|_| self.bad("a name is not UTF-8"))
    }

    /// A list's tag and count; `ABSENT` (two zeros) is an empty list.
    fn list(&mut self, tag: u32) -> Result<usize> {
        let t = self.u32()?;
        let n = self.count()?;
        match (t, n) {
            (0, 0) => Ok(0),
            (t, n) if t == tag => Ok(n),
            _ => Err(self.bad(format!("expected list tag {tag:#x}, found {t:#x}"))),
        }
    }

    fn attributes(&mut self) -> Result<Vec<(String, Value)>> {
        let n = self.list(ATTRIBUTE)?;
        let mut out = Vec::new();
        for _ in 0..n {
            let name = self.name()?;
            let kind = self.u32()?;
            let size = type_size(kind).ok_or_else(|| self.bad(format!("type {kind}")))?;
            let count = self.count()?;
            let bytes = count
                .checked_mul(size)
                .ok_or_else(|| self.bad("an attribute is too large"))?;
            let raw = self.padded(bytes)?;
            let value = if kind == 2 {
                let text = String::from_utf8_lossy(raw);
                Value::Text(text.trim_end_matches('\0').trim().to_string())
            } else {
                Value::Numbers(raw.chunks_exact(size).map(|c| decode(kind, c)).collect())
            };
            out.push((name, value));
        }
        Ok(out)
    }
}

/// Dimensions: (name, length); length 0 is the unlimited (record) one.
type Dims = Vec<(String, usize)>;

/// Dimensions (name, length) and variables of the header.
fn header(path: &Path, b: &[u8]) -> Result<(Dims, Vec<Variable>)> {
    let mut h = Header {
        b,
        pos: 0,
        path,
        wide: false,
        long_offsets: false,
    };
    let magic = h.take(4)?;
    if &magic[..3] != MAGIC {
        return Err(h.bad("the file does not start with CDF"));
    }
    match magic[3] {
        1 => {}
        2 => h.long_offsets = true,
        5 => (h.wide, h.long_offsets) = (true, true),
        v => return Err(h.bad(format!("version {v}: 1, 2 and 5 are read"))),
    }
    h.count()?; // number of records
    let mut dims = Vec::new();
    for _ in 0..h.list(DIMENSION)? {
        let name = h.name()?;
        dims.push((name, h.count()?));
    }
    h.attributes()?;
    let mut vars = Vec::new();
    for _ in 0..h.list(VARIABLE)? {
        let name = h.name()?;
        let mut ids = Vec::new();
        for _ in 0..h.count()? {
            let id = h.count()?;
            ids.push(id);
            if id >= dims.len() {
                return Err(h.bad(format!("variable {name:?}: no dimension {id}")));
            }
        }
        let attributes = h.attributes()?;
        let kind = h.u32()?;
        h.count()?; // vsize
        let begin = if h.long_offsets {
            h.u64()?
        } else {
            u64::from(h.u32()?)
        };
        vars.push(Variable {
            name,
            dims: ids,
            attributes,
            kind,
            begin,
        });
    }
    Ok((dims, vars))
}

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let bad = |m: String| Error::parse(path, 0, 0, format!("NetCDF .nc: {m}"));
    let (dims, vars) = header(path, b)?;
    for v in &vars {
        check_extent(b, &dims, v).map_err(bad)?;
    }
    let var = |name: &str| vars.iter().find(|v| v.name == name);
    let heights = var("heights")
        .ok_or_else(|| bad("no variable 'heights' (the topography convention)".into()))?;
    let shape: Vec<(&str, usize)> = heights
        .dims
        .iter()
        .map(|&d| (dims[d].0.as_str(), dims[d].1))
        .collect();
    let (nx, ny, layout) = match shape[..] {
        [(_, 0), ..] => return Err(bad("'heights' is a record variable: not read".into())),
        [("n", _)] => {
            return Err(bad(
                "a nonuniform line scan (dimension n): export it as x, h text".into(),
            ))
        }
        [(_, n)] => (n, 1, Layout::LineScans),
        [(_, x), (_, y)] => (x, y, Layout::Map),
        _ => {
            return Err(bad(format!(
                "'heights' has {} dimensions: 1 or 2 are read",
                shape.len()
            )))
        }
    };
    let n = nx
        .checked_mul(ny)
        .ok_or_else(|| bad(format!("{nx} × {ny} points are too many")))?;
    let mut h = values(b, heights, n).map_err(bad)?;
    if let Some(m) = var("mask") {
        let m = values(b, m, n).map_err(bad)?;
        h.iter_mut()
            .zip(m)
            .filter(|(_, m)| *m != 0.0)
            .for_each(|(h, _)| *h = f64::NAN);
    }
    // The file is [ix][iy] (y fastest): rows of ours run along x.
    let heights_xy = if ny > 1 {
        let mut t = vec![0.0; nx * ny];
        for ix in 0..nx {
            for iy in 0..ny {
                t[iy * nx + ix] = h[ix * ny + iy];
            }
        }
        t
    } else {
        h
    };
    let size = size(var("x"), var("y"), layout).map_err(bad)?;
    // Without its own unit the heights are in the unit of x (as
    // SurfaceTopography reads them).
    let unit = heights
        .text("unit")
        .or_else(|| var("x").and_then(|x| x.text("unit")));
    let height_unit = match unit {
        Some(u) => Unit::declared("'heights'", u).map_err(bad)?,
        None => Unit::Unstated,
    };
    Ok(Raw {
        size,
        height_unit,
        layout,
        ..Raw::map(nx, ny, heights_xy)
    })
}

/// A fixed-size variable's values lie inside the file (record variables,
/// with an unlimited first dimension, are not checked).
fn check_extent(
    b: &[u8],
    dims: &[(String, usize)],
    v: &Variable,
) -> std::result::Result<(), String> {
    let lengths: Vec<usize> = v.dims.iter().map(|&d| dims[d].1).collect();
    if lengths.first() == Some(&0) {
        return Ok(());
    }
    let size = type_size(v.kind).ok_or_else(|| format!("'{}' has type {}", v.name, v.kind))?;
    let end = lengths
        .iter()
        .try_fold(size, |a, &l| a.checked_mul(l))
        .zip(usize::try_from(v.begin).ok())
        .and_then(|(n, start)| n.checked_add(start));
    match end {
        Some(end) if end <= b.len() => Ok(()),
        _ => Err(format!(
            "truncated: variable '{}' ends past the end of the {}-byte file",
            v.name,
            b.len()
        )),
    }
}

/// The `n` values of a variable, scaled, `_FillValue` as NaN.
fn values(b: &[u8], v: &Variable, n: usize) -> std::result::Result<Vec<f64>, String> {
    let size = type_size(v.kind).ok_or_else(|| format!("'{}' has type {}", v.name, v.kind))?;
    let bytes = n
        .checked_mul(size)
        .ok_or_else(|| format!("'{}' is too large", v.name))?;
    let start = usize::try_from(v.begin).unwrap_or(usize::MAX);
    let data = start
        .checked_add(bytes)
        .and_then(|end| b.get(start..end))
        .ok_or_else(|| {
            format!(
                "truncated: '{}' needs bytes {start}..{} of a {}-byte file",
                v.name,
                start.saturating_add(bytes),
                b.len()
            )
        })?;
    let fill = v.number("_FillValue");
    let scale = v.number("scale_factor").unwrap_or(1.0);
    let offset = v.number("add_offset").unwrap_or(0.0);
    Ok(data
        .chunks_exact(size)
        .map(|c| match decode(v.kind, c) {
            r if Some(r) == fill => f64::NAN,
            r => r * scale + offset,
        })
        .collect())
}

/// Sizes from the `length` attributes of `x` and `y`, in the unit of `x`.
fn size(
    x: Option<&Variable>,
    y: Option<&Variable>,
    layout: Layout,
) -> std::result::Result<Option<Stored>, String> {
    let Some(lx) = x.and_then(|x| x.number("length")) else {
        return Ok(None);
    };
    let unit = |v: Option<&Variable>, what: &str| match v.and_then(|v| v.text("unit")) {
        Some(u) => Unit::declared(what, u),
        None => Ok(Unit::Unstated),
    };
    let ux = unit(x, "the sizes of 'x'")?;
    let ly = match layout {
        Layout::LineScans => 0.0,
        Layout::Map => {
            let ly = y
                .and_then(|y| y.number("length"))
                .ok_or("'x' has a length and 'y' none")?;
            let factor = match (&ux, unit(y, "the sizes of 'y'")?) {
                (Unit::Stated(_, a), Unit::Stated(_, b)) => b.metres() / a.metres(),
                (_, Unit::Unstated) => 1.0,
                (Unit::Unstated, Unit::Stated(t, _)) => {
                    return Err(format!("'y' is in {t}, 'x' states no unit"))
                }
            };
            ly * factor
        }
    };
    Ok(Some(Stored {
        lx,
        ly,
        unit: ux,
        resolution: 0.0,
    }))
}

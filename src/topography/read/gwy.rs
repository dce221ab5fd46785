//! Gwyddion native files (`.gwy`).
//!
//! The magic `GWYP`, then one serialised object, a `GwyContainer`. An
//! object is its type name (NUL-terminated UTF-8), its size in bytes
//! (u32), then its components: a name (NUL-terminated), a type byte and the
//! value, little-endian:
//!
//! ```text
//! b bool (1 byte)   c char (1)   i int32   q int64   d float64
//! s string (NUL-terminated)      o object
//! C I Q D arrays of c i q d: a u32 count, then the values
//! S array of strings             O array of objects (u32 count)
//! ```
//!
//! The container's components `/N/data` are the channels, `GwyDataField`
//! objects with `xres`, `yres` (i), `xreal`, `yreal` (d, the physical
//! size), `si_unit_xy`, `si_unit_z` (`GwySIUnit` objects, `unitstr`) and
//! `data` (D, `xres·yres` values, x fastest, the first row at y = 0). An
//! optional `/N/mask` field of the same shape marks undefined points (value
//! > 0.5).
//!
//! # Channels
//! Every data field `/N/data` is a channel, named by its title
//! (`/N/data/title`, e.g. `Height`, `Phase`), else `/N/data`; its index is
//! its position among the data fields in the file's order (not `N`;
//! SurfaceTopography numbers only the fields in units of length).
//! [`ReadOptions::channel`] chooses one by name or index; a chosen channel
//! whose values are not lengths (`deg`, `V`) is an error naming its unit.
//! By default the channel read is the first (in the file's order) whose
//! values are lengths, as SurfaceTopography reads by default; a file
//! without one, but with a channel whose unit is empty, reads that channel
//! with the units the caller gives (Gwyddion's empty unit is
//! "dimensionless": never taken for metres); channels with other units are
//! an error naming them. Negative sizes are taken by their magnitude, as
//! Gwyddion shows them.
//!
//! # References
//! Gwyddion user guide, "Gwyddion Native File Format"
//! (gwyddion.net/documentation/user-guide-en/gwyfile-format.html).

use std::path::Path;

use super::bin::product;
use super::channel;
use super::units::Unit;
use super::{Raw, ReadOptions, Stored};
use crate::error::{Error, Result};

/// The magic of Gwyddion 2 files (`GWYO`, Gwyddion 1, is not read).
pub(crate) const MAGIC: &[u8] = b"GWYP";

/// Deeper nesting is refused (real files nest 3–4 levels).
const MAX_DEPTH: usize = 32;

/// A component's value; arrays stay bytes in the file.
enum Value<'b> {
    Int(i64),
    Double(f64),
    Text(String),
    Object(Object<'b>),
    /// A `D` array: the bytes of its float64 values.
    Doubles(&'b [u8]),
    Other,
}

/// A serialised object: its type name and components in the file's order.
struct Object<'b> {
    kind: String,
    items: Vec<(String, Value<'b>)>,
}

impl<'b> Object<'b> {
    fn get(&self, name: &str) -> Option<&Value<'b>> {
        self.items.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }
}

/// A position in the file with errors naming it.
struct Reader<'b> {
    b: &'b [u8],
    pos: usize,
    path: &'b Path,
}

impl<'b> Reader<'b> {
    fn bad(&self, m: impl std::fmt::Display) -> Error {
        Error::parse(
            self.path,
            0,
            0,
            format!("Gwyddion .gwy: {m} (at byte {})", self.pos),
        )
    }

    fn take(&mut self, n: usize) -> Result<&'b [u8]> {
        let end = self
            .pos
            .checked_add(n)
            .filter(|&e| e <= self.b.len())
            .ok_or_else(|| {
                self.bad(format!(
                    "truncated: {n} more bytes needed, the file has {}",
                    self.b.len()
                ))
            })?;
        let s = &self.b[self.pos..end];
        self.pos = end;
        Ok(s)
    }

    fn fixed<const N: usize>(&mut self) -> Result<[u8; N]> {
        let mut a = [0u8; N];
        a.copy_from_slice(self.take(N)?);
        Ok(a)
    }

    fn count(&mut self) -> Result<usize> {
        Ok(u32::from_le_bytes(self.fixed()?) as usize)
    }

    fn string(&mut self) -> Result<String> {
        let rest = &self.b[self.pos..];
        let n = rest
            .iter()
            .position(|&c| c == 0)
            .ok_or_else(|| self.bad("truncated: a string has no terminating NUL"))?;
        let s = std::str::from_utf8(&rest[..n])
            .map_err(|_| self.bad("a name or string is not UTF-8"))?
            .to_string();
        self.pos += n + 1;
        Ok(s)
    }

    fn object(&mut self, depth: usize) -> Result<Object<'b>> {
        if depth > MAX_DEPTH {
            return Err(self.bad(format!("objects nested deeper than {MAX_DEPTH}")));
        }
        let kind = self.string()?;
        let size = self.count()?;
        let end = self
            .pos
            .checked_add(size)
            .filter(|&e| e <= self.b.len())
            .ok_or_else(|| {
                self.bad(format!(
                    "truncated: the {kind:?} object of {size} bytes ends past the end of the file"
                ))
            })?;
        let mut items = Vec::new();
        while self.pos < end {
            let name = self.string()?;
            let value = self.value(depth)?;
            items.push((name, value));
        }
        if self.pos != end {
            return Err(self.bad(format!(
                "the components of the {kind:?} object overrun its size ({size} bytes)"
            )));
        }
        Ok(Object { kind, items })
    }

    fn array(&mut self, item: usize) -> Result<&'b [u8]> {
        let n = self.count()?;
        let bytes = n
            .checked_mul(item)
            .ok_or_else(|| self.bad("an array is too large"))?;
        self.take(bytes)
    }

    fn value(&mut self, depth: usize) -> Result<Value<'b>> {
        let [t] = self.fixed()?;
        Ok(match t {
            b'b' | b'c' => {
                self.take(1)?;
                Value::Other
            }
            b'i' => Value::Int(i32::from_le_bytes(self.fixed()?).into()),
            b'q' => Value::Int(i64::from_le_bytes(self.fixed()?)),
            b'd' => Value::Double(f64::from_le_bytes(self.fixed()?)),
            b's' => Value::Text(self.string()?),
            b'o' => Value::Object(self.object(depth + 1)?),
            b'C' => self.array(1).map(|_| Value::Other)?,
            b'I' => self.array(4).map(|_| Value::Other)?,
            b'Q' => self.array(8).map(|_| Value::Other)?,
            b'D' => Value::Doubles(self.array(8)?),
            b'S' => {
                for _ in 0..self.count()? {
                    self.string()?;
                }
                Value::Other
            }
            b'O' => {
                for _ in 0..self.count()? {
                    self.object(depth + 1)?;
                }
                Value::Other
            }
            _ => return Err(self.bad(format!("unknown component type {:?}", t as char))),
        })
    }
}

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let bad = |m: String| Error::parse(path, 0, 0, format!("Gwyddion .gwy: {m}"));
    if !b.starts_with(MAGIC) {
        return Err(bad(if b.starts_with(b"GWYO") {
            "a Gwyddion 1 file (GWYO): open and save it in Gwyddion 2".into()
        } else {
            "the file does not start with GWYP".into()
        }));
    }
    let mut r = Reader {
        b,
        pos: MAGIC.len(),
        path,
    };
    let top = r.object(0)?;
    if top.kind != "GwyContainer" {
        return Err(bad(format!(
            "the top object is a {:?}, not a GwyContainer",
            top.kind
        )));
    }
    let fields = fields(&top);
    let k = choose(&fields, options.channel.as_deref()).map_err(bad)?;
    let (index, ref name, field) = fields[k];
    field_to_raw(&top, index, name, field).map_err(bad)
}

/// The data fields `/N/data` in the file's order: `N`, the channel's name
/// (its title, else `/N/data`) and the field.
fn fields<'o, 'b>(top: &'o Object<'b>) -> Vec<(u64, String, &'o Object<'b>)> {
    top.items
        .iter()
        .filter_map(|(k, v)| {
            let index = k.strip_prefix('/')?.strip_suffix("/data")?.parse().ok()?;
            match v {
                Value::Object(o) if o.kind == "GwyDataField" => {
                    let name = match top.get(&format!("/{index}/data/title")) {
                        Some(Value::Text(t)) if !t.trim().is_empty() => t.trim().to_string(),
                        _ => format!("/{index}/data"),
                    };
                    Some((index, name, o))
                }
                _ => None,
            }
        })
        .collect()
}

/// The position among `fields` of the channel named `wanted`, else the
/// first height channel, else the first without unit (module docs).
fn choose(
    fields: &[(u64, String, &Object)],
    wanted: Option<&str>,
) -> std::result::Result<usize, String> {
    let units: Vec<(String, std::result::Result<Unit, String>)> = fields
        .iter()
        .map(|(_, _, f)| {
            let z = unit(f, "si_unit_z");
            let u = Unit::declared("values", &z);
            (z, u)
        })
        .collect();
    if wanted.is_some() {
        let list: Vec<(&str, bool)> = fields
            .iter()
            .zip(&units)
            .map(|((_, n, _), (_, u))| (n.as_str(), matches!(u, Ok(Unit::Stated(..)))))
            .collect();
        return channel::choose(&list, wanted);
    }
    if let Some(k) = units
        .iter()
        .position(|(_, u)| matches!(u, Ok(Unit::Stated(..))))
    {
        return Ok(k);
    }
    if let Some(k) = units.iter().position(|(_, u)| u == &Ok(Unit::Unstated)) {
        return Ok(k);
    }
    Err(if fields.is_empty() {
        "the file has no data field (channel /N/data)".into()
    } else {
        let others: Vec<String> = fields
            .iter()
            .zip(&units)
            .map(|((i, n, _), (z, _))| format!("{} in {z:?}", label(*i, n)))
            .collect();
        format!(
            "no channel holds heights (a unit of length): {}",
            others.join(", ")
        )
    })
}

/// A channel in the errors: `"Height" (/1/data)`, or `/1/data` untitled.
fn label(index: u64, name: &str) -> String {
    let key = format!("/{index}/data");
    if name == key {
        key
    } else {
        format!("\"{name}\" ({key})")
    }
}

/// The `unitstr` of a `GwySIUnit` component, empty where absent.
fn unit(field: &Object, key: &str) -> String {
    match field.get(key) {
        Some(Value::Object(u)) => match u.get("unitstr") {
            Some(Value::Text(s)) => s.clone(),
            _ => String::new(),
        },
        _ => String::new(),
    }
}

fn int(field: &Object, key: &str) -> std::result::Result<usize, String> {
    match field.get(key) {
        Some(Value::Int(n)) if *n > 0 => usize::try_from(*n).map_err(|e| e.to_string()),
        Some(Value::Int(n)) => Err(format!("{key} = {n}: must be > 0")),
        _ => Err(format!("the data field has no integer {key}")),
    }
}

fn real(field: &Object, key: &str) -> std::result::Result<f64, String> {
    match field.get(key) {
        Some(Value::Double(x)) if x.is_finite() && *x != 0.0 => Ok(x.abs()),
        Some(Value::Double(x)) => Err(format!("{key} = {x}: must be finite and not 0")),
        _ => Err(format!("the data field has no float {key}")),
    }
}

/// The `data` of a field with `n` values.
fn values(field: &Object, n: usize, what: &str) -> std::result::Result<Vec<f64>, String> {
    let Some(Value::Doubles(d)) = field.get("data") else {
        return Err(format!("{what} has no float64 array 'data'"));
    };
    if d.len() != n * 8 {
        return Err(format!(
            "{what}: xres × yres = {n} values, its data array has {}",
            d.len() / 8
        ));
    }
    Ok(d.chunks_exact(8)
        .map(|c| f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]))
        .collect())
}

fn field_to_raw(
    top: &Object,
    index: u64,
    name: &str,
    f: &Object,
) -> std::result::Result<Raw, String> {
    let (nx, ny) = (int(f, "xres")?, int(f, "yres")?);
    let n = product(nx, ny, 8)
        .map(|b| b / 8)
        .ok_or_else(|| format!("xres × yres = {nx} × {ny} is too large"))?;
    let what = format!("channel {}", label(index, name));
    let mut heights = values(f, n, &what)?;
    if let Some(Value::Object(m)) = top.get(&format!("/{index}/mask")) {
        let mask = values(m, n, &format!("mask /{index}/mask"))?;
        for (h, m) in heights.iter_mut().zip(mask) {
            if m > 0.5 {
                *h = f64::NAN;
            }
        }
    }
    let z = unit(f, "si_unit_z");
    let xy = unit(f, "si_unit_xy");
    let height_unit = Unit::declared(&format!("{what}: the values"), &z)?;
    let lateral = Unit::declared(&format!("{what}: the sizes"), &xy)?;
    let require_units = height_unit == Unit::Unstated || lateral == Unit::Unstated;
    Ok(Raw {
        size: Some(Stored {
            lx: real(f, "xreal")?,
            ly: real(f, "yreal")?,
            unit: lateral,
            resolution: 0.0,
        }),
        height_unit,
        require_units,
        ..Raw::map(nx, ny, heights)
    })
}

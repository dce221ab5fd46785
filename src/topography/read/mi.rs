//! Molecular Imaging / Keysight (Agilent) `.mi` images (PicoView, PicoScan).
//!
//! A text header of lines `key value`, the key in a column of 14
//! characters (`xPixels       256`), Latin-1; lines that start with a space
//! continue the previous one and are skipped. Each `bufferLabel` line opens
//! a channel ("buffer") whose lines follow (`bufferRange`, `bufferUnit`,
//! `direction`, …). The line with the key `data` ends the header; its value
//! is the encoding of the buffers that follow it back to back, each
//! `yPixels` rows of `xPixels` little-endian integers, x fastest:
//!
//! ```text
//! data  BINARY_32: i32, t = 2^31        data  BINARY (or empty): i16, t = 2^15
//! h[iy, ix] = bufferRange · value[(yPixels − 1 − iy)·xPixels + ix] / t   (bufferUnit)
//! Lx = xLength,  Ly = yLength   (m)
//! ```
//!
//! The last row of a buffer is the top row of the image, whatever the scan
//! direction (`scanUp`): rows are read in reverse, as SurfaceTopography
//! (and Gwyddion's `mifile.c`) orient the map. `fileType` must be `Image`
//! (spectroscopy files are refused) and `data` binary (ASCII data is
//! refused). No point is undefined.
//!
//! The channel read is the first whose `bufferUnit` is a length (the
//! topography), or the one named by [`ReadOptions::channel`]: its
//! `bufferLabel`, with ` (direction)` appended where two buffers share a
//! label (`Friction (Retrace)`), or its index among the buffers. A channel
//! whose unit is not a length (`Deflection`, V) is an error naming it.
//!
//! # References
//! The layout as SurfaceTopography's `IO/MI.py` reads it (which scales the
//! values the same way and converts the sizes to the unit of the heights).

use std::collections::HashMap;
use std::path::Path;

use super::bin::{latin1, product, Bin};
use super::channel;
use super::units::{not_a_length, LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::Result;

const MAGIC: &[u8] = b"fileType";
/// The width of the key column.
const KEY_WIDTH: usize = 14;
const FORMAT: &str = "Molecular Imaging .mi";

/// Whether `bytes` start as this format's files do.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

/// One buffer's lines.
#[derive(Default)]
struct Buffer {
    label: String,
    range: Option<String>,
    unit: Option<String>,
    direction: String,
}

/// The header: file-wide keys, buffers, and where the data start.
struct Header {
    global: Vec<(String, String)>,
    buffers: Vec<Buffer>,
    data: String,
    start: usize,
}

impl Header {
    fn get(&self, key: &str) -> Option<&str> {
        self.global
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

fn header(f: &Bin) -> Result<Header> {
    let b = f.bytes;
    let mut h = Header {
        global: Vec::new(),
        buffers: Vec::new(),
        data: String::new(),
        start: 0,
    };
    let mut at = 0;
    loop {
        let Some(len) = b[at..].iter().position(|&c| c == b'\n') else {
            return Err(f.bad("truncated: the header has no `data` line"));
        };
        let line = &b[at..at + len];
        at += len + 1;
        let line = line.strip_suffix(b"\r").unwrap_or(line);
        if line.first() == Some(&b' ') || line.is_empty() {
            continue;
        }
        let k = line.len().min(KEY_WIDTH);
        let key = latin1(&line[..k]).trim().to_string();
        let value = latin1(&line[k..]).trim().to_string();
        match key.as_str() {
            "data" => {
                h.data = value;
                h.start = at;
                return Ok(h);
            }
            "bufferLabel" => h.buffers.push(Buffer {
                label: value,
                ..Buffer::default()
            }),
            _ => match h.buffers.last_mut() {
                Some(buf) => match key.as_str() {
                    "bufferRange" => buf.range = Some(value),
                    "bufferUnit" => buf.unit = Some(value),
                    "direction" => buf.direction = value,
                    _ => {}
                },
                None => h.global.push((key, value)),
            },
        }
    }
}

/// The buffers' names: the label, with the direction where labels repeat.
fn names(buffers: &[Buffer]) -> Vec<String> {
    let mut count: HashMap<&str, usize> = HashMap::new();
    for b in buffers {
        *count.entry(b.label.as_str()).or_default() += 1;
    }
    buffers
        .iter()
        .map(|b| {
            let repeated = count[b.label.as_str()] > 1;
            if repeated && !b.direction.is_empty() {
                format!("{} ({})", b.label, b.direction)
            } else {
                b.label.clone()
            }
        })
        .collect()
}

pub(crate) fn parse(path: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(bytes, path, FORMAT);
    if !sniff(bytes) {
        return Err(f.bad("the file does not start with `fileType`"));
    }
    let h = header(&f)?;
    match h.get("fileType") {
        Some("Image") => {}
        other => {
            return Err(f.bad(format!(
                "fileType is {:?}: only images (`Image`) are read",
                other.unwrap_or("")
            )))
        }
    }
    let (item, full_scale) = match h.data.as_str() {
        "BINARY_32" => (4, 2f64.powi(31)),
        "BINARY" | "" => (2, 2f64.powi(15)),
        d => return Err(f.bad(format!("data is {d:?}: only binary data are read"))),
    };
    let number = |key: &str| -> Result<f64> {
        let v = h
            .get(key)
            .ok_or_else(|| f.bad(format!("the header has no {key}")))?;
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| f.bad(format!("{key} = {v:?} is not a number")))
    };
    let count = |key: &str| -> Result<usize> {
        let v = number(key)?;
        if v >= 1.0 && v.fract() == 0.0 && v <= u32::MAX as f64 {
            Ok(v as usize)
        } else {
            Err(f.bad(format!("{key} = {v}: must be a whole number > 0")))
        }
    };
    let (nx, ny) = (count("xPixels")?, count("yPixels")?);
    let names = names(&h.buffers);
    let channels: Vec<(&str, bool)> = names
        .iter()
        .zip(&h.buffers)
        .map(|(n, b)| {
            let unit = b.unit.as_deref().unwrap_or("");
            (n.as_str(), LengthUnit::parse(unit).is_some())
        })
        .collect();
    let k = channel::choose(&channels, options.channel.as_deref()).map_err(|m| f.bad(m))?;
    let buf = &h.buffers[k];
    let unit = buf.unit.as_deref().unwrap_or("");
    let height_unit = match LengthUnit::parse(unit) {
        Some(u) => Unit::Stated(unit.to_string(), u),
        None => {
            return Err(f.bad(not_a_length(
                &format!("the values of buffer \"{}\"", names[k]),
                unit,
            )))
        }
    };
    let range = buf
        .range
        .as_deref()
        .and_then(|r| r.parse::<f64>().ok())
        .filter(|r| r.is_finite())
        .ok_or_else(|| f.bad(format!("buffer \"{}\" has no bufferRange", names[k])))?;
    let block = product(nx, ny, item)
        .ok_or_else(|| f.bad(format!("xPixels × yPixels = {nx} × {ny} is too large")))?;
    let start = block
        .checked_mul(k)
        .and_then(|o| o.checked_add(h.start))
        .ok_or_else(|| f.bad("the buffers are too large"))?;
    let data = f.slice(start, block, &format!("buffer {k} (\"{}\")", names[k]))?;
    let scale = range / full_scale;
    let value = |i: usize| -> f64 {
        let c = &data[i * item..(i + 1) * item];
        match item {
            4 => f64::from(i32::from_le_bytes([c[0], c[1], c[2], c[3]])),
            _ => f64::from(i16::from_le_bytes([c[0], c[1]])),
        }
    };
    let mut heights = Vec::with_capacity(nx * ny);
    for iy in 0..ny {
        let row = (ny - 1 - iy) * nx;
        heights.extend((0..nx).map(|ix| scale * value(row + ix)));
    }
    let (lx, ly) = (number("xLength")?, number("yLength")?);
    let resolution = ["xLength", "yLength"]
        .iter()
        .filter_map(|key| {
            let v = h.get(key)?;
            Some(crate::io::text::resolution(v) / v.parse::<f64>().ok()?.abs())
        })
        .filter(|r| r.is_finite())
        .fold(0.0, f64::max);
    Ok(Raw {
        size: Some(Stored {
            lx,
            ly,
            unit: Unit::of(LengthUnit::Metre),
            resolution,
        }),
        height_unit,
        ..Raw::map(nx, ny, heights)
    })
}

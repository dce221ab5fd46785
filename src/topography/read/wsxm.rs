//! WSxM images (`.stp`, `.top`; Nanotec Electronica's WSxM software).
//!
//! Three lines, `WSxM file copyright …`, `SxM Image file` and
//! `Image header size: N`, then an INI-style header (`[Section]` lines and
//! indented `key: value` lines, Latin-1) up to `[Header end]`; the values
//! start at byte N: `Number of rows` rows of `Number of columns`
//! little-endian values, of the `Image Data Type` (`short` or `integer`:
//! i16, `float`: f32, `double`: f64) of `[General Info]`. Read:
//!
//! ```text
//! float, double:  h = value                                  (unit of Z Amplitude)
//! short, integer: h = value · Z Amplitude / (Maximum − Minimum)   ([Miscellaneous])
//! h[iy, ix] = h(value[(rows − 1 − iy)·columns + (columns − 1 − ix)])
//! Lx = X Amplitude,  Ly = Y Amplitude (default X Amplitude)   ([Control], with units)
//! ```
//!
//! The image is stored rotated by 180°: the values are read in reverse, as
//! SurfaceTopography (and Gwyddion's `wsxmfile.c`) orient the map. The
//! integer scale uses the header's `Maximum` and `Minimum` (in the example
//! `top-1.top` they equal the range of the values, 5927 to 6900); a header
//! whose `Maximum` is not above its `Minimum` gives no scale and is an
//! error. No point is undefined.
//!
//! A WSxM file holds one image (WSxM saves each channel and scan direction
//! in a file of its own): [`ReadOptions::channel`] may only be `0`
//! (anything else is an error).
//!
//! # References
//! The layout as SurfaceTopography's `IO/WSXM.py` reads it.

use std::path::Path;

use super::bin::{product, Bin};
use super::units::{not_a_length, LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::Result;

const MAGIC: &[u8] = b"WSxM file copyright";
const FORMAT: &str = "WSxM";

/// Whether `bytes` start as this format's files do.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

/// `(section, key, value)` of the header's lines.
struct Header(Vec<(String, String, String)>);

impl Header {
    fn get(&self, section: &str, key: &str) -> Option<&str> {
        self.0
            .iter()
            .find(|(s, k, _)| s == section && k == key)
            .map(|(_, _, v)| v.as_str())
    }
}

fn header(f: &Bin, text: &str) -> Result<Header> {
    let mut lines = text.lines();
    if lines
        .next()
        .map(|l| l.trim_end().starts_with("WSxM file copyright"))
        != Some(true)
    {
        return Err(f.bad("the first line does not start with `WSxM file copyright`"));
    }
    if lines.next().map(str::trim) != Some("SxM Image file") {
        return Err(f.bad("the second line is not `SxM Image file`"));
    }
    lines.next();
    let mut section = String::new();
    let mut out = Vec::new();
    for line in lines {
        let line = line.trim();
        if line == "[Header end]" {
            return Ok(Header(out));
        }
        if let Some(name) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            section = name.to_string();
        } else if let Some((k, v)) = line.split_once(':') {
            out.push((section.clone(), k.trim().to_string(), v.trim().to_string()));
        }
    }
    Err(f.bad("truncated: the header has no `[Header end]`"))
}

/// A value and its unit (`600 nm`).
fn amount(f: &Bin, what: &str, text: &str) -> Result<(f64, String, LengthUnit, f64)> {
    let mut it = text.split_whitespace();
    let tok = it.next().unwrap_or("");
    let v = tok
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| f.bad(format!("{what} = {text:?} is not a number and a unit")))?;
    let unit = it.last().unwrap_or("");
    let u = LengthUnit::parse(unit).ok_or_else(|| f.bad(not_a_length(what, unit)))?;
    let r = crate::io::text::resolution(tok) / v.abs();
    Ok((v, unit.to_string(), u, if r.is_finite() { r } else { 0.0 }))
}

pub(crate) fn parse(path: &Path, bytes: &[u8], _options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(bytes, path, FORMAT);
    // The three lines before the header: its size is on the third.
    let head: String = bytes.iter().take(200).map(|&c| char::from(c)).collect();
    let size_line = head
        .lines()
        .nth(2)
        .and_then(|l| l.trim().strip_prefix("Image header size:"))
        .ok_or_else(|| f.bad("the third line is not `Image header size: N`"))?;
    let size: usize = size_line
        .trim()
        .parse()
        .map_err(|_| f.bad(format!("Image header size = {:?}", size_line.trim())))?;
    let text: String = f
        .slice(0, size, "the header (Image header size)")?
        .iter()
        .map(|&c| char::from(c))
        .collect();
    let h = header(&f, &text)?;
    let need = |section: &str, key: &str| -> Result<&str> {
        h.get(section, key)
            .ok_or_else(|| f.bad(format!("the header has no [{section}] {key}")))
    };
    let count = |key: &str| -> Result<usize> {
        let v = need("General Info", key)?;
        v.parse::<usize>()
            .ok()
            .filter(|&n| n > 0)
            .ok_or_else(|| f.bad(format!("{key} = {v:?}: must be a whole number > 0")))
    };
    let (nx, ny) = (count("Number of columns")?, count("Number of rows")?);
    let kind = need("General Info", "Image Data Type")?;
    let item = match kind {
        "short" | "integer" => 2,
        "float" => 4,
        "double" => 8,
        k => return Err(f.bad(format!("Image Data Type {k:?} is not read"))),
    };
    let (z, z_text, z_unit, _) = amount(
        &f,
        "Z Amplitude: the heights",
        need("General Info", "Z Amplitude")?,
    )?;
    let scale = if item == 2 {
        let number = |key: &str| -> Result<f64> {
            let v = need("Miscellaneous", key)?;
            v.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| f.bad(format!("{key} = {v:?} is not a number")))
        };
        let (max, min) = (number("Maximum")?, number("Minimum")?);
        if max <= min {
            return Err(f.bad(format!(
                "Maximum = {max} is not above Minimum = {min}: no scale of the integer values"
            )));
        }
        z / (max - min)
    } else {
        1.0
    };
    let x_text = need("Control", "X Amplitude")?;
    let (lx, x_unit, xu, rx) = amount(&f, "X Amplitude", x_text)?;
    let (ly, _, yu, ry) = amount(
        &f,
        "Y Amplitude",
        h.get("Control", "Y Amplitude").unwrap_or(x_text),
    )?;
    let len = product(nx, ny, item)
        .ok_or_else(|| f.bad(format!("columns × rows = {nx} × {ny} is too large")))?;
    let data = f.slice(size, len, "the values")?;
    let value = |c: &[u8]| -> f64 {
        match item {
            2 => f64::from(i16::from_le_bytes([c[0], c[1]])),
            4 => f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])),
            _ => f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]),
        }
    };
    // Rotated by 180°: the last value is h[0, 0].
    let heights = data
        .chunks_exact(item)
        .rev()
        .map(|c| scale * value(c))
        .collect();
    Ok(Raw {
        size: Some(Stored {
            lx,
            ly: ly * yu.metres() / xu.metres(),
            unit: Unit::Stated(x_unit, xu),
            resolution: rx.max(ry),
        }),
        height_unit: Unit::Stated(z_text, z_unit),
        ..Raw::map(nx, ny, heights)
    })
}

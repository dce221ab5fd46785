//! Bruker / Veeco / Digital Instruments Nanoscope files (`.spm`, `.di`,
//! `.000`, `.001`, …), version 4.3 and later.
//!
//! A Latin-1 text header of lines `\key: value` grouped in sections
//! `\*Name`, from `\*File list` to `\*File list end`, then the images as
//! little-endian integers. Each channel is a `\*Ciao image list` section:
//!
//! ```text
//! \Data offset: 40960            byte offset of the channel's values
//! \Data length: 524288           their size in bytes
//! \Bytes/pixel: 2                2 (int16) or 4 (int32; absent: 2)
//! \Samps/line: 512               nx
//! \Number of lines: 512          ny
//! \Scan Size: 500 500 nm         Lx Ly unit (`~m` is µm)
//! \@2:Image Data: S [Height] "Height"
//! \@2:Z scale: V [Sens. Zsens] (0.005035400 V/LSB) 2.910461 V
//! ```
//!
//! and the sensitivity the Z scale names is in the `\*Scanner list` or
//! `\*Ciao scan list`: `\@Sens. Zsens: V 20.82646 nm/V`. With the hard
//! value Z = 2.910461 V, the sensitivity s = 20.82646 nm/V (its unit is the
//! unit of the heights) and b = 2 or 4 bytes per pixel:
//!
//! ```text
//! h = raw · Z/65536 · s · (1/65536 if b = 4)        (a hard value in mV: × 1e-3)
//! h[iy, ix] = that of raw[(ny − 1 − iy)·nx + ix]    (the file's first line is the top)
//! ```
//!
//! Each image is a channel, named by the bracketed word of its
//! `@2:Image Data` (`ZSensor`, `AmplitudeError`, `Phase`, `Height`, as
//! SurfaceTopography names them), its index the image's position in the
//! header from 0. [`ReadOptions::channel`] chooses one by name or index; a
//! chosen channel whose sensitivity is not a length per volt (`Phase`,
//! `AmplitudeError`) is an error. By default the channel read is the first
//! whose sensitivity is a length per volt (Height, ZSensor); none is an
//! error naming the channels.
//!
//! # References
//! Bruker, "NanoScope Software 8 User Guide", "File Format" (the header
//! keys); the layout as Gwyddion's `nanoscope.c` and SurfaceTopography's
//! `IO/DI.py` read it.

use std::path::Path;

use super::bin::{product, Bin};
use super::channel::choose;
use super::units::{LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::Result;

pub(crate) const MAGIC: &[u8] = b"\\*File list";
const END: &[u8] = b"\\*File list end";
/// A header longer than this is corrupt (real ones are 10–80 kB).
const MAX_HEADER: usize = 1 << 22;

/// A section: its name and its `(key, value)` lines, keys in lower case.
type Section = (String, Vec<(String, String)>);

pub(crate) fn parse(path: &Path, b: &[u8], options: &ReadOptions) -> Result<Raw> {
    let f = Bin::new(b, path, "Nanoscope .spm/.di");
    if b.len() < MAGIC.len() && MAGIC.starts_with(b) {
        return Err(f.bad("truncated within the first line \\*File list"));
    }
    if !b.starts_with(MAGIC) {
        return Err(f.bad("the file does not start with \\*File list"));
    }
    let sections = sections(&f)?;
    let scanner: Vec<&(String, String)> = sections
        .iter()
        .filter(|(n, _)| n == "scanner list" || n == "ciao scan list")
        .flat_map(|(_, kv)| kv.iter())
        .collect();
    let images: Vec<&Vec<(String, String)>> = sections
        .iter()
        .filter(|(n, _)| n == "ciao image list")
        .map(|(_, kv)| kv)
        .collect();
    if images.is_empty() {
        return Err(f.bad("no image (\\*Ciao image list) in the header"));
    }
    let name_of = |image: &[(String, String)]| -> Result<String> {
        let name = get(&f, image, "@2:image data")?;
        Ok(between(name, '[', ']').unwrap_or(name).to_string())
    };
    let scale_of = |image: &[(String, String)], name: &str| {
        scale(&f, get(&f, image, "@2:z scale")?, &scanner, name)
    };
    let Some(wanted) = options.channel.as_deref() else {
        // The first height channel; an image before it that cannot be
        // read is an error.
        let mut names = Vec::new();
        for &image in &images {
            let name = name_of(image)?;
            match scale_of(image, &name)? {
                Some((factor, unit)) => {
                    return channel(&f, &|k| get(&f, image, k), factor, unit, &name)
                }
                None => names.push(name),
            }
        }
        return Err(f.bad(format!(
            "no height channel (a Z scale in a length per volt) among {names:?}"
        )));
    };
    let names = images
        .iter()
        .map(|&image| name_of(image))
        .collect::<Result<Vec<_>>>()?;
    let mut scales: Vec<_> = images
        .iter()
        .zip(&names)
        .map(|(&image, name)| scale_of(image, name))
        .collect();
    let list: Vec<(&str, bool)> = names
        .iter()
        .zip(&scales)
        .map(|(n, s)| (n.as_str(), matches!(s, Ok(Some(_)))))
        .collect();
    let k = choose(&list, Some(wanted)).map_err(|m| f.bad(m))?;
    let (image, name) = (images[k], &names[k]);
    match scales.swap_remove(k)? {
        Some((factor, unit)) => channel(&f, &|k| get(&f, image, k), factor, unit, name),
        None => Err(f.bad(format!(
            "channel \"{name}\": its Z scale {:?} is not in a length per volt: \
             this channel is not a height map",
            get(&f, image, "@2:z scale")?
        ))),
    }
}

/// The value of `key` in an image's section.
fn get<'a>(f: &Bin, image: &'a [(String, String)], key: &str) -> Result<&'a str> {
    image
        .iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
        .ok_or_else(|| f.bad(format!("an image without \\{key}")))
}

/// The header's sections up to `\*File list end`.
fn sections(f: &Bin) -> Result<Vec<Section>> {
    let limit = f.bytes.len().min(MAX_HEADER);
    let end = f.bytes[..limit]
        .windows(END.len())
        .position(|w| w.eq_ignore_ascii_case(END))
        .ok_or_else(|| f.bad("truncated: the header has no \\*File list end"))?;
    let text: String = f.bytes[..end].iter().map(|&c| char::from(c)).collect();
    let mut out: Vec<Section> = Vec::new();
    for line in text.lines().map(str::trim).filter(|l| !l.is_empty()) {
        if let Some(name) = line.strip_prefix("\\*") {
            out.push((name.trim().to_ascii_lowercase(), Vec::new()));
        } else if let Some(kv) = line.strip_prefix('\\') {
            let (k, v) = kv.split_once(": ").unwrap_or((kv, ""));
            if let Some((_, items)) = out.last_mut() {
                items.push((k.trim().to_ascii_lowercase(), v.trim().to_string()));
            }
        } else {
            return Err(f.bad(format!(
                "header line {line:?} does not start with a backslash"
            )));
        }
    }
    Ok(out)
}

/// The text between `open` and the next `close`.
fn between(s: &str, open: char, close: char) -> Option<&str> {
    let a = s.find(open)? + open.len_utf8();
    let b = s[a..].find(close)? + a;
    Some(&s[a..b])
}

/// `Z/65536 · s` and the unit of s's numerator for a `@2:Z scale` value
/// `V [Sens. Zsens] (… V/LSB) Z V`; `None` if s is not a length per volt.
fn scale(
    f: &Bin,
    z: &str,
    scanner: &[&(String, String)],
    name: &str,
) -> Result<Option<(f64, Unit)>> {
    let bad = || {
        f.bad(format!(
            "the Z scale of {name} {z:?} is not `V [Sens. …] (… /LSB) value unit`"
        ))
    };
    let Some(sens) = between(z, '[', ']') else {
        return Ok(None);
    };
    let after = z.find(')').ok_or_else(bad)?;
    let mut hard = z[after + 1..].split_whitespace();
    let (value, hard_unit) = (hard.next().ok_or_else(bad)?, hard.next().unwrap_or(""));
    let value: f64 = value.parse().map_err(|_| bad())?;
    let key = format!("@{}", sens.to_ascii_lowercase());
    let Some((_, s)) = scanner.iter().find(|(k, _)| *k == key) else {
        return Err(f.bad(format!(
            "the sensitivity {sens:?} of {name} is not in the header"
        )));
    };
    let mut words = s.split_whitespace().skip(1);
    let soft: f64 = words
        .next()
        .and_then(|w| w.parse().ok())
        .ok_or_else(|| f.bad(format!("the sensitivity {sens:?} = {s:?} has no number")))?;
    let Some((unit, per)) = words.next().and_then(|u| u.split_once('/')) else {
        return Ok(None);
    };
    let Some(length) = LengthUnit::parse(&unit.replace('~', "µ")) else {
        return Ok(None);
    };
    let hard_to_soft = if hard_unit == per {
        1.0
    } else if hard_unit.strip_prefix('m') == Some(per) {
        1e-3
    } else {
        return Err(f.bad(format!(
            "the Z scale of {name} is in {hard_unit:?}, its sensitivity per {per:?}"
        )));
    };
    let k = value / 65536.0 * hard_to_soft * soft;
    if !k.is_finite() || k == 0.0 {
        return Err(f.bad(format!(
            "the height scale of {name} is {k}: not finite and non-zero"
        )));
    }
    Ok(Some((k, Unit::Stated(unit.to_string(), length))))
}

/// The heights of one channel.
fn channel<'a>(
    f: &Bin,
    get: &dyn Fn(&str) -> Result<&'a str>,
    factor: f64,
    height_unit: Unit,
    name: &str,
) -> Result<Raw> {
    let count = |key: &str| -> Result<usize> {
        let v = get(key)?;
        v.parse()
            .map_err(|_| f.bad(format!("\\{key} of {name} = {v:?}: not a count")))
    };
    let (nx, ny) = (count("samps/line")?, count("number of lines")?);
    if nx == 0 || ny == 0 {
        return Err(f.bad(format!(
            "{name}: {nx} samples × {ny} lines: both must be > 0"
        )));
    }
    let item = if get("bytes/pixel").is_ok() {
        count("bytes/pixel")?
    } else {
        2
    };
    let factor = match item {
        2 => factor,
        4 => factor / 65536.0,
        _ => return Err(f.bad(format!("{name}: {item} bytes per pixel: 2 or 4 are read"))),
    };
    let len =
        product(nx, ny, item).ok_or_else(|| f.bad(format!("{name}: {nx} × {ny} is too large")))?;
    let stated = count("data length")?;
    if stated < len {
        return Err(f.bad(format!(
            "{name}: the data length {stated} is less than {nx} × {ny} × {item} bytes"
        )));
    }
    let data = f.slice(count("data offset")?, len, &format!("channel {name}"))?;
    let raw = |k: usize| -> f64 {
        let c = &data[k * item..(k + 1) * item];
        if item == 2 {
            f64::from(i16::from_le_bytes([c[0], c[1]]))
        } else {
            f64::from(i32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        }
    };
    let mut heights = Vec::with_capacity(nx * ny);
    for iy in 0..ny {
        let row = (ny - 1 - iy) * nx;
        heights.extend((row..row + nx).map(|k| raw(k) * factor));
    }
    Ok(Raw {
        size: Some(size(f, get("scan size")?, nx, ny)?),
        height_unit,
        ..Raw::map(nx, ny, heights)
    })
}

/// `Scan Size: Lx Ly unit` (or `L unit`: Ly = L·ny/nx).
fn size(f: &Bin, text: &str, nx: usize, ny: usize) -> Result<Stored> {
    let bad = || f.bad(format!("Scan Size {text:?} is not `Lx Ly unit`"));
    let words: Vec<&str> = text.split_whitespace().collect();
    let (x, y, unit) = match words[..] {
        [x, y, u] => (x, y, u),
        [x, u] => (x, "", u),
        _ => return Err(bad()),
    };
    let lx: f64 = x.parse().map_err(|_| bad())?;
    let ly: f64 = if y.is_empty() {
        lx * ny as f64 / nx as f64
    } else {
        y.parse().map_err(|_| bad())?
    };
    let length = LengthUnit::parse(&unit.replace('~', "µ")).ok_or_else(bad)?;
    let r = |t: &str, v: f64| crate::io::text::resolution(t) / v.abs();
    Ok(Stored {
        lx,
        ly,
        unit: Unit::Stated(unit.to_string(), length),
        resolution: r(x, lx).max(if y.is_empty() { 0.0 } else { r(y, ly) }),
    })
}

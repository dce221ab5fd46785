//! Gwyddion Simple Field (`.gsf`).
//!
//! A text header, first line `Gwyddion Simple Field 1.0`, then `Key = Value`
//! lines (`XRes`, `YRes` required; `XReal`, `YReal` the physical sizes,
//! optional; `XYUnits`, `ZUnits` the units of sizes and values, optional),
//! then 1–4 NUL bytes so that the header length is a multiple of 4, then
//! `XRes·YRes` little-endian float32 heights, x fastest. NaN marks an
//! undefined point. Units are base SI units (`m`); a `ZUnits` that is not a
//! length (`deg` of a phase channel, `V`, `A` — the ampere) is an error.
//!
//! # References
//! Gwyddion user guide, "Gwyddion Simple Field" file format
//! (gwyddion.net/documentation/user-guide-en/gsf.html).

use std::path::Path;

use super::units::Unit;
use super::{Raw, Stored};
use crate::error::{Error, Result};
use crate::topography::Layout;

pub(crate) const MAGIC: &[u8] = b"Gwyddion Simple Field 1.0\n";

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let bad = |line: usize, m: String| Error::parse(path, line, 0, m);
    if !b.starts_with(MAGIC) {
        return Err(bad(
            1,
            "not a Gwyddion Simple Field: the first line must be 'Gwyddion Simple Field 1.0'"
                .into(),
        ));
    }
    let nul = b.iter().position(|&c| c == 0).ok_or_else(|| {
        bad(
            0,
            "truncated: the header has no NUL padding and no data".into(),
        )
    })?;
    let header = std::str::from_utf8(&b[..nul])
        .map_err(|_| bad(0, "the header is not UTF-8 text".into()))?;
    let data_start = (nul / 4 + 1) * 4;
    if b.len() < data_start || b[nul..data_start].iter().any(|&c| c != 0) {
        return Err(bad(
            0,
            format!("malformed padding: the header must be followed by NUL bytes up to byte {data_start} (a multiple of 4)"),
        ));
    }
    let Fields {
        xres,
        yres,
        xreal,
        yreal,
        xy_unit,
        z_unit,
        resolution,
    } = fields(path, header)?;
    let xres = xres.ok_or_else(|| bad(0, "the header has no XRes".into()))?;
    let yres = yres.ok_or_else(|| bad(0, "the header has no YRes".into()))?;
    let count = xres
        .checked_mul(yres)
        .filter(|c| c.checked_mul(4).is_some())
        .ok_or_else(|| bad(0, format!("XRes × YRes = {xres} × {yres} is too large")))?;
    let data = &b[data_start..];
    if data.len() != 4 * count {
        return Err(bad(
            0,
            format!(
                "{}: XRes × YRes = {xres} × {yres} float32 values need {} bytes of data, the file has {}",
                if data.len() < 4 * count { "truncated" } else { "malformed" },
                4 * count,
                data.len()
            ),
        ));
    }
    let heights = data
        .chunks_exact(4)
        .map(|c| f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])))
        .collect();
    let size = match (xreal, yreal) {
        (Some(x), Some(y)) => Some(Stored {
            lx: x,
            ly: y,
            unit: xy_unit,
            resolution,
        }),
        (None, None) => None,
        _ => {
            return Err(bad(
                0,
                "the header gives only one of XReal and YReal".into(),
            ))
        }
    };
    Ok(Raw {
        size,
        height_unit: z_unit,
        ..Raw::map(xres, yres, heights)
    })
}

/// The fields of the header.
struct Fields {
    xres: Option<usize>,
    yres: Option<usize>,
    xreal: Option<f64>,
    yreal: Option<f64>,
    xy_unit: Unit,
    z_unit: Unit,
    /// Relative precision of `XReal`, `YReal` as written.
    resolution: f64,
}

/// Read the `Key = Value` lines after the first.
fn fields(path: &Path, header: &str) -> Result<Fields> {
    let bad = |line: usize, m: String| Error::parse(path, line, 0, m);
    let mut f = Fields {
        xres: None,
        yres: None,
        xreal: None,
        yreal: None,
        xy_unit: Unit::Unstated,
        z_unit: Unit::Unstated,
        resolution: 0.0,
    };
    for (ln, line) in header.lines().enumerate().skip(1) {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let Some((k, v)) = line.split_once('=') else {
            return Err(bad(ln + 1, format!("{line:?} is not 'Key = Value'")));
        };
        let (k, v) = (k.trim(), v.trim());
        let num = |v: &str| -> Result<f64> {
            v.parse::<f64>()
                .map_err(|_| bad(ln + 1, format!("{k} = {v:?} is not a number")))
        };
        let int = |v: &str| -> Result<usize> {
            v.parse::<usize>()
                .ok()
                .filter(|&n| n > 0)
                .ok_or_else(|| bad(ln + 1, format!("{k} = {v:?} is not a positive integer")))
        };
        match k {
            "XRes" => f.xres = Some(int(v)?),
            "YRes" => f.yres = Some(int(v)?),
            "XReal" | "YReal" => {
                let x = num(v)?;
                let r = crate::io::text::resolution(v) / x.abs();
                if r.is_finite() {
                    f.resolution = f.resolution.max(r);
                }
                if k == "XReal" {
                    f.xreal = Some(x);
                } else {
                    f.yreal = Some(x);
                }
            }
            "XYUnits" => {
                f.xy_unit = Unit::declared("XYUnits: the sizes", v).map_err(|m| bad(ln + 1, m))?
            }
            "ZUnits" => {
                f.z_unit = Unit::declared("ZUnits: the values", v).map_err(|m| bad(ln + 1, m))?
            }
            _ => {}
        }
    }
    Ok(f)
}

/// Write a map as a `.gsf` file (float32 heights, x fastest, sizes in
/// `XReal`/`YReal`), atomically.
///
/// # Errors
/// [`Error::Io`] naming the file; [`Error::Inconsistent`] for line scans.
pub fn write_gsf(path: &Path, t: &crate::topography::Topography) -> Result<()> {
    if t.layout() != Layout::Map {
        return Err(Error::Inconsistent {
            name: "layout".into(),
            requirement: "a 2D map for a .gsf file".into(),
        });
    }
    let (nx, ny, lx, ly, heights) = (t.nx(), t.ny(), t.lx(), t.ly(), t.heights());
    let mut out = MAGIC.to_vec();
    out.extend_from_slice(
        format!(
            "XRes = {nx}\nYRes = {ny}\nXReal = {lx:e}\nYReal = {ly:e}\nXYUnits = m\nZUnits = m\n"
        )
        .as_bytes(),
    );
    let pad = 4 - out.len() % 4;
    out.extend(std::iter::repeat_n(0u8, pad));
    for h in heights {
        out.extend_from_slice(&(*h as f32).to_le_bytes());
    }
    crate::io::write_atomic(path, &out)
}

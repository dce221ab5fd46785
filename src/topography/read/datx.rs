//! Zygo `.datx` (Mx software; an HDF5 container, read by [`super::hdf5`]).
//!
//! The layout, as SurfaceTopography's DATX reader reads it:
//!
//! ```text
//! /MetaData            table of (Source, Link, Destination) strings
//!                      Root --Measurement--> {id} --Surface--> {id} --Path--> "/Measurement/Surface"
//! <Path>               rank-2 data set of heights, shape (ny, nx): rows along y
//!   Unit               one string: MicroMeters, NanoMeters, MilliMeters, Meters
//!   No Data            one value marking undefined points (optional)
//!   X Converter        one compound (Category, BaseUnit, Unit, Parameters):
//!   Y Converter          LateralCat, Pixels, …, Parameters[1] = pixel size in m
//!   Z Converter        HeightCat, base unit = Unit
//! ```
//!
//! Strings may be fixed-length or variable-length. The compound's fields are
//! taken by position (first, second, last), as SurfaceTopography does.
//! Heights are in `Unit` (the Z converter's parameters are not applied);
//! the physical size is `nx·Δx`, `ny·Δy` in metres. Undefined points: the
//! `No Data` value and non-finite values. There is one channel (the
//! surface); naming another is an error.
//!
//! No instrument file was available: this is tested on files written with
//! h5py in this layout (tests/reference/datx_surface_topography.py).
//!
//! # References
//! SurfaceTopography's `IO/DATX.py` (after the description in
//! <https://gist.github.com/g-s-k/ccffb1e84df065a690e554f4b40cfd3a>).

use std::collections::HashMap;
use std::path::Path;

use super::hdf5::{numbers, Type, H5};
use super::units::{LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::Result;

/// How far into the file [`sniff`] looks for the `MetaData` name.
const SNIFF_WINDOW: usize = 4096;

/// Whether `bytes` start as this format's files do: the HDF5 signature and
/// the name `MetaData` in the first 4 kB (the root group's names).
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    super::hdf5::sniff(bytes)
        && bytes[..bytes.len().min(SNIFF_WINDOW)]
            .windows(8)
            .any(|w| w == b"MetaData")
}

pub(crate) fn parse(path: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Raw> {
    let h5 = H5::open(path, bytes, "Zygo .datx")?;
    if let Some(c) = options.channel.as_deref() {
        let c = c.trim();
        if !(c == "0" || c.eq_ignore_ascii_case("Default") || c.eq_ignore_ascii_case("Surface")) {
            return Err(h5.bad(format!("no channel \"{c}\": the file has 0: \"Surface\"")));
        }
    }
    let surface = surface_path(&h5)?;
    let header = h5.object(&surface)?;
    let (shape, values) = h5.read_f64(&header, &surface)?;
    let (ny, nx) = match shape[..] {
        [ny, nx] if nx > 0 && ny > 0 => (ny, nx),
        _ => {
            return Err(h5.bad(format!(
                "the surface {surface} has shape {shape:?}, not (ny, nx)"
            )))
        }
    };
    let text = |name: &str| -> Result<String> {
        let a = h5
            .attribute(&header, name)?
            .ok_or_else(|| h5.bad(format!("the surface has no attribute {name:?}")))?;
        h5.string(&a.ty, &a.data)
    };
    let unit_text = text("Unit")?;
    let unit = LengthUnit::parse(&unit_text)
        .ok_or_else(|| h5.bad(format!("unit {unit_text:?} is not a length")))?;
    let dx = converter(&h5, &header, "X Converter", "LateralCat", Some("Pixels"))?;
    let dy = converter(&h5, &header, "Y Converter", "LateralCat", Some("Pixels"))?;
    let z = converter_base(&h5, &header, "Z Converter", "HeightCat")?;
    if LengthUnit::parse(&z) != Some(unit) {
        return Err(h5.bad(format!(
            "two height units: Unit {unit_text:?} and the Z converter's {z:?}"
        )));
    }
    let no_data = match h5.attribute(&header, "No Data")? {
        Some(a) => numbers(&a.ty, &a.data).and_then(|v| v.first().copied()),
        None => None,
    };
    let heights = values
        .into_iter()
        .map(|v| {
            if !v.is_finite() || Some(v) == no_data {
                f64::NAN
            } else {
                v
            }
        })
        .collect();
    let metres = || Unit::of(LengthUnit::Metre);
    Ok(Raw {
        size: Some(Stored {
            lx: nx as f64 * dx,
            ly: ny as f64 * dy,
            unit: metres(),
            resolution: f64::EPSILON,
        }),
        height_unit: Unit::Stated(unit_text, unit),
        ..Raw::map(nx, ny, heights)
    })
}

/// The surface's path: `/MetaData`'s links Root → Measurement → Surface → Path.
fn surface_path(h5: &H5) -> Result<String> {
    let header = h5
        .object("MetaData")
        .map_err(|_| h5.bad("no /MetaData: not a Zygo .datx file"))?;
    let (_, ty, raw) = h5.read_raw(&header, "MetaData")?;
    let members = match &ty {
        Type::Compound { members, .. } if members.len() >= 3 => members,
        _ => return Err(h5.bad("/MetaData is not a table of (Source, Link, Destination)")),
    };
    let size = ty.size(0).max(1);
    let mut table: HashMap<(String, String), String> = HashMap::new();
    for row in raw.chunks_exact(size) {
        let field = |k: usize| -> Result<String> {
            let (_, offset, t) = &members[k];
            let len = t.size(h5.offset_size());
            let bytes = row
                .get(*offset..offset.saturating_add(len))
                .ok_or_else(|| h5.bad("truncated: a /MetaData row"))?;
            h5.string(t, bytes)
        };
        let (source, link, destination) = (field(0)?, field(1)?, field(2)?);
        table.insert((source, link), destination);
    }
    let mut at = "Root".to_string();
    for link in ["Measurement", "Surface", "Path"] {
        at = table
            .get(&(at.clone(), link.to_string()))
            .cloned()
            .ok_or_else(|| h5.bad(format!("/MetaData has no link {link:?} from {at:?}")))?;
    }
    Ok(at)
}

/// The record of a converter attribute: category, base unit, parameters.
fn record(
    h5: &H5,
    header: &rustyhdf5_format::object_header::ObjectHeader,
    name: &str,
) -> Result<(String, String, Vec<f64>)> {
    let a = h5
        .attribute(header, name)?
        .ok_or_else(|| h5.bad(format!("the surface has no attribute {name:?}")))?;
    let members = match &a.ty {
        Type::Compound { members, .. } if members.len() >= 3 && a.count >= 1 => members,
        t => {
            return Err(h5.bad(format!(
                "{name} is {t:?}, not a (Category, BaseUnit, …, Parameters) record"
            )))
        }
    };
    let field = |k: usize| -> Result<(&Type, &[u8])> {
        let (_, offset, t) = &members[k];
        let bytes = a
            .data
            .get(*offset..offset.saturating_add(t.size(h5.offset_size())))
            .ok_or_else(|| h5.bad(format!("truncated: {name}")))?;
        Ok((t, bytes))
    };
    let (t, b) = field(0)?;
    let category = h5.string(t, b)?;
    let (t, b) = field(1)?;
    let base = h5.string(t, b)?;
    let (t, b) = field(members.len() - 1)?;
    let values = match t {
        Type::Array { base, .. } => numbers(base, b),
        t => numbers(t, b),
    }
    .ok_or_else(|| h5.bad(format!("{name}: its parameters are not numbers")))?;
    Ok((category, base, values))
}

/// The pixel size (m) of a lateral converter.
fn converter(
    h5: &H5,
    header: &rustyhdf5_format::object_header::ObjectHeader,
    name: &str,
    category: &str,
    base: Option<&str>,
) -> Result<f64> {
    let (c, b, values) = record(h5, header, name)?;
    if c != category || base.is_some_and(|u| b != u) {
        return Err(h5.bad(format!(
            "{name} is {c:?} in {b:?}: only {category:?} in {:?} is read",
            base.unwrap_or("")
        )));
    }
    match values.get(1) {
        Some(&d) if d.is_finite() && d > 0.0 => Ok(d),
        _ => Err(h5.bad(format!(
            "{name}: the pixel size (Parameters[1]) {values:?} is not > 0"
        ))),
    }
}

/// The base unit of the height converter.
fn converter_base(
    h5: &H5,
    header: &rustyhdf5_format::object_header::ObjectHeader,
    name: &str,
    category: &str,
) -> Result<String> {
    let (c, b, _) = record(h5, header, name)?;
    if c != category {
        return Err(h5.bad(format!("{name} is {c:?}: only {category:?} is read")));
    }
    Ok(b)
}

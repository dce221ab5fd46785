//! ISO 25178-72 XML 3D surface profile (`.x3p`): a zip archive holding
//! `main.xml` and the binary heights it links to.
//!
//! Read from `main.xml` (element names without namespace):
//! `Record1/FeatureType` = `SUR` (an areal map); `Record1/Axes/CX|CY` with
//! `AxisType` = `I` (incremental) and `Increment` (the pixel size, m);
//! `Record1/Axes/CZ` with `DataType` `I` (u16), `L` (u32), `F` (f32) or `D`
//! (f64) and optional `Increment` and `Offset` (z = raw·Increment + Offset);
//! `Record3/MatrixDimension/SizeX|SizeY|SizeZ` (SizeZ = 1) and
//! `Record3/DataLink/PointDataLink`, the archive member with the
//! little-endian heights, x fastest. NaN marks an undefined point of float
//! data (a `ValidPointsLink` mask of integer data is not read).
//!
//! # References
//! ISO 25178-72:2017; openGPS X3P documentation (sourceforge.net/p/open-gps);
//! the layout as read by SurfaceTopography's `IO/X3P.py`.

use std::io::{Cursor, Read};
use std::path::Path;

use super::Raw;
use crate::error::{Error, Result};
use crate::topography::Layout;

fn child<'a, 'i>(n: roxmltree::Node<'a, 'i>, name: &str) -> Option<roxmltree::Node<'a, 'i>> {
    n.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    let mut zip = zip::ZipArchive::new(Cursor::new(b))
        .map_err(|e| bad(format!("not a readable .x3p (zip) archive: {e}")))?;
    let mut xml = String::new();
    zip.by_name("main.xml")
        .map_err(|e| bad(format!("the archive has no readable main.xml: {e}")))?
        .read_to_string(&mut xml)
        .map_err(|e| bad(format!("main.xml is unreadable or truncated: {e}")))?;
    let doc = roxmltree::Document::parse(&xml).map_err(|e| bad(format!("main.xml: {e}")))?;
    let root = doc.root_element();
    let path_of = |steps: &[&str]| -> Result<roxmltree::Node<'_, '_>> {
        let mut n = root;
        for s in steps {
            n = child(n, s).ok_or_else(|| bad(format!("main.xml has no {}", steps.join("/"))))?;
        }
        Ok(n)
    };
    let text = |steps: &[&str]| -> Result<String> {
        Ok(path_of(steps)?.text().unwrap_or("").trim().to_string())
    };
    let number = |steps: &[&str]| -> Result<f64> {
        let t = text(steps)?;
        t.parse::<f64>().map_err(|_| {
            bad(format!(
                "main.xml: {} = {t:?} is not a number",
                steps.join("/")
            ))
        })
    };
    let optional = |steps: &[&str]| -> Result<Option<f64>> {
        if path_of(steps).is_err() {
            return Ok(None);
        }
        number(steps).map(Some)
    };
    let feature = text(&["Record1", "FeatureType"])?;
    if feature != "SUR" {
        return Err(bad(format!(
            "main.xml: FeatureType {feature:?}: only areal maps ('SUR') are read"
        )));
    }
    for axis in ["CX", "CY"] {
        let t = text(&["Record1", "Axes", axis, "AxisType"])?;
        if t != "I" {
            return Err(bad(format!(
                "main.xml: {axis} AxisType {t:?}: only incremental axes ('I') are read"
            )));
        }
    }
    let dx = number(&["Record1", "Axes", "CX", "Increment"])?;
    let dy = number(&["Record1", "Axes", "CY", "Increment"])?;
    let dtype = text(&["Record1", "Axes", "CZ", "DataType"])?;
    let z_scale = optional(&["Record1", "Axes", "CZ", "Increment"])?.unwrap_or(1.0);
    let z_offset = optional(&["Record1", "Axes", "CZ", "Offset"])?.unwrap_or(0.0);
    let dim = |s: &str| -> Result<usize> {
        let t = text(&["Record3", "MatrixDimension", s])?;
        t.parse::<usize>().map_err(|_| {
            bad(format!(
                "main.xml: MatrixDimension/{s} = {t:?} is not a count"
            ))
        })
    };
    let (nx, ny, nz) = (dim("SizeX")?, dim("SizeY")?, dim("SizeZ")?);
    if nz != 1 {
        return Err(bad(format!(
            "main.xml: SizeZ = {nz}: only one layer (1) is read"
        )));
    }
    let link = text(&["Record3", "DataLink", "PointDataLink"])?;
    let item = match dtype.as_str() {
        "I" => 2,
        "L" | "F" => 4,
        "D" => 8,
        d => {
            return Err(bad(format!(
                "main.xml: CZ DataType {d:?}: need I, L, F or D"
            )))
        }
    };
    let count = nx
        .checked_mul(ny)
        .filter(|c| c.checked_mul(item).is_some())
        .ok_or_else(|| bad(format!("SizeX × SizeY = {nx} × {ny} is too large")))?;
    let mut data = Vec::new();
    zip.by_name(&link)
        .map_err(|e| {
            bad(format!(
                "the archive has no readable data member {link:?}: {e}"
            ))
        })?
        .read_to_end(&mut data)
        .map_err(|e| {
            bad(format!(
                "data member {link:?} is unreadable or truncated: {e}"
            ))
        })?;
    if data.len() < count * item {
        return Err(bad(format!(
            "truncated: {link} holds {} bytes, SizeX × SizeY = {nx} × {ny} values of type {dtype} need {}",
            data.len(),
            count * item
        )));
    }
    let raw: Vec<f64> = data[..count * item]
        .chunks_exact(item)
        .map(|c| match item {
            2 => f64::from(u16::from_le_bytes([c[0], c[1]])),
            8 => f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]),
            _ if dtype == "L" => f64::from(u32::from_le_bytes([c[0], c[1], c[2], c[3]])),
            _ => f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])),
        })
        .collect();
    let heights = raw.into_iter().map(|v| v * z_scale + z_offset).collect();
    Ok(Raw {
        nx,
        ny,
        heights,
        size: Some((nx as f64 * dx, ny as f64 * dy)),
        layout: Layout::Map,
    })
}

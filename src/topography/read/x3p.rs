//! ISO 25178-72 XML 3D surface profile (`.x3p`): a zip archive holding
//! `main.xml` and the binary heights it links to.
//!
//! Read from `main.xml` (element names without namespace):
//! - `Record1/FeatureType`: `SUR` (an areal map) or `PRF` (a profile,
//!   read as a line scan);
//! - `Record1/Axes/CX|CY` with `AxisType` = `I` (incremental) and
//!   `Increment` (the pixel size, m);
//! - `Record1/Axes/CZ` with `DataType` `I` (int16), `L` (int32) — both
//!   signed, as ISO 5436-2, the openGPS library, Gwyddion and
//!   SurfaceTopography read them —, `F` (float32) or `D` (float64), and
//!   optional `Increment` and `Offset` (z = raw·Increment + Offset; an
//!   empty element is absent: Increment 1, Offset 0);
//! - `Record3/MatrixDimension/SizeX|SizeY|SizeZ` (SizeZ = 1);
//! - `Record3/DataLink/PointDataLink`, the archive member with the
//!   little-endian values, x fastest; or `Record3/DataList/Datum`, one
//!   value per element (an empty one is undefined);
//! - `Record3/DataLink/ValidPointsLink`, optional: one bit per point, least
//!   significant bit first, in the order of the values; a 0 bit marks an
//!   undefined point (for integer data the only way to mark one; the raw
//!   value there is arbitrary).
//!
//! NaN marks an undefined point of float data too. Lengths are in metres.
//!
//! # References
//! ISO 25178-72:2017 (ISO 5436-2:2012); the openGPS X3P library and its
//! sample files (sourceforge.net/p/open-gps); Gwyddion's `opengps.c`.

use std::io::Cursor;
use std::path::Path;

use roxmltree::Node;

use super::units::{LengthUnit, Unit};
use super::{Raw, Stored};
use crate::error::{Error, Result};
use crate::topography::Layout;

fn child<'a, 'i>(n: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    n.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

use super::archive::{self, Archive};

/// The largest main.xml parsed (its tree takes ~14× the text; a list of
/// Datum values of a large map fits).
const MAX_XML: u64 = 1 << 28;

/// Access to `main.xml` by element paths, with errors naming the file.
struct Xml<'a, 'i> {
    root: Node<'a, 'i>,
    path: &'a Path,
}

impl<'a, 'i> Xml<'a, 'i> {
    fn bad(&self, m: String) -> Error {
        Error::parse(self.path, 0, 0, m)
    }

    fn node(&self, steps: &[&str]) -> Option<Node<'a, 'i>> {
        let mut n = self.root;
        for s in steps {
            n = child(n, s)?;
        }
        Some(n)
    }

    /// The trimmed text of an element; `None` when it is absent.
    fn text_opt(&self, steps: &[&str]) -> Option<String> {
        self.node(steps)
            .map(|n| n.text().unwrap_or("").trim().to_string())
    }

    fn text(&self, steps: &[&str]) -> Result<String> {
        self.text_opt(steps)
            .ok_or_else(|| self.bad(format!("main.xml has no {}", steps.join("/"))))
    }

    fn number(&self, steps: &[&str]) -> Result<f64> {
        let t = self.text(steps)?;
        t.parse::<f64>().map_err(|_| {
            self.bad(format!(
                "main.xml: {} = {t:?} is not a number",
                steps.join("/")
            ))
        })
    }

    /// An optional number: absent or empty (`<Offset/>`) is `None`.
    fn optional(&self, steps: &[&str]) -> Result<Option<f64>> {
        match self.text_opt(steps) {
            Some(t) if !t.is_empty() => self.number(steps).map(Some),
            _ => Ok(None),
        }
    }

    fn count(&self, name: &str) -> Result<usize> {
        let t = self.text(&["Record3", "MatrixDimension", name])?;
        t.parse::<usize>().map_err(|_| {
            self.bad(format!(
                "main.xml: MatrixDimension/{name} = {t:?} is not a count"
            ))
        })
    }
}

/// The geometry and encoding `main.xml` declares.
struct Declared {
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
    dtype: Dtype,
    z_scale: f64,
    z_offset: f64,
    profile: bool,
}

#[derive(Clone, Copy, PartialEq)]
enum Dtype {
    I16,
    I32,
    F32,
    F64,
}

impl Dtype {
    fn size(self) -> usize {
        match self {
            Dtype::I16 => 2,
            Dtype::I32 | Dtype::F32 => 4,
            Dtype::F64 => 8,
        }
    }

    fn decode(self, c: &[u8]) -> f64 {
        match self {
            Dtype::I16 => f64::from(i16::from_le_bytes([c[0], c[1]])),
            Dtype::I32 => f64::from(i32::from_le_bytes([c[0], c[1], c[2], c[3]])),
            Dtype::F32 => f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])),
            Dtype::F64 => f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]),
        }
    }
}

fn layout(x: &Xml) -> Result<Declared> {
    let feature = x.text(&["Record1", "FeatureType"])?;
    let profile = match feature.as_str() {
        "SUR" => false,
        "PRF" => true,
        f => {
            return Err(x.bad(format!(
            "main.xml: FeatureType {f:?}: only areal maps ('SUR') and profiles ('PRF') are read \
                 (a point cloud 'PCL' is not on a grid)"
        )))
        }
    };
    let axes: &[&str] = if profile { &["CX"] } else { &["CX", "CY"] };
    for axis in axes {
        let t = x.text(&["Record1", "Axes", axis, "AxisType"])?;
        if t != "I" {
            return Err(x.bad(format!(
                "main.xml: {axis} AxisType {t:?}: only incremental axes ('I') are read"
            )));
        }
    }
    let dx = x.number(&["Record1", "Axes", "CX", "Increment"])?;
    let dy = if profile {
        0.0
    } else {
        x.number(&["Record1", "Axes", "CY", "Increment"])?
    };
    let dtype = match x.text(&["Record1", "Axes", "CZ", "DataType"])?.as_str() {
        "I" => Dtype::I16,
        "L" => Dtype::I32,
        "F" => Dtype::F32,
        "D" => Dtype::F64,
        d => return Err(x.bad(format!("main.xml: CZ DataType {d:?}: need I, L, F or D"))),
    };
    let (nx, ny, nz) = (x.count("SizeX")?, x.count("SizeY")?, x.count("SizeZ")?);
    if nz != 1 {
        return Err(x.bad(format!(
            "main.xml: SizeZ = {nz}: only one layer (1) is read"
        )));
    }
    if profile && ny != 1 {
        return Err(x.bad(format!(
            "main.xml: a profile (PRF) with SizeY = {ny}: need 1"
        )));
    }
    Ok(Declared {
        nx,
        ny,
        dx,
        dy,
        dtype,
        z_scale: x
            .optional(&["Record1", "Axes", "CZ", "Increment"])?
            .unwrap_or(1.0),
        z_offset: x
            .optional(&["Record1", "Axes", "CZ", "Offset"])?
            .unwrap_or(0.0),
        profile,
    })
}

/// An archive member, whole (bounded: [`archive::member`]).
fn member(zip: &mut Archive, path: &Path, name: &str) -> Result<Vec<u8>> {
    archive::member(zip, path, "ISO 25178-72 .x3p", name, archive::MAX_MEMBER)
}

/// The raw values from the binary member or the XML data list (NaN for an
/// empty `Datum`).
fn raw_values(x: &Xml, zip: &mut Archive, l: &Declared, count: usize) -> Result<Vec<f64>> {
    if let Some(link) = x.text_opt(&["Record3", "DataLink", "PointDataLink"]) {
        let data = member(zip, x.path, &link)?;
        let item = l.dtype.size();
        if data.len() < count * item {
            return Err(x.bad(format!(
                "truncated: {link} holds {} bytes, {} × {} values of {item} bytes need {}",
                data.len(),
                l.nx,
                l.ny,
                count * item
            )));
        }
        return Ok(data[..count * item]
            .chunks_exact(item)
            .map(|c| l.dtype.decode(c))
            .collect());
    }
    let list = x.node(&["Record3", "DataList"]).ok_or_else(|| {
        x.bad("main.xml has neither Record3/DataLink/PointDataLink nor Record3/DataList".into())
    })?;
    let values = list
        .children()
        .filter(|c| c.is_element() && c.tag_name().name() == "Datum")
        .map(|d| {
            let t = d.text().unwrap_or("").trim();
            if t.is_empty() {
                Ok(f64::NAN)
            } else {
                t.parse::<f64>()
                    .map_err(|_| x.bad(format!("main.xml: Datum {t:?} is not a number")))
            }
        })
        .collect::<Result<Vec<_>>>()?;
    if values.len() != count {
        return Err(x.bad(format!(
            "main.xml: DataList holds {} values, {} × {} needs {count}",
            values.len(),
            l.nx,
            l.ny
        )));
    }
    Ok(values)
}

/// Points the validity mask marks undefined (`ValidPointsLink`), if any.
fn invalid(x: &Xml, zip: &mut Archive, count: usize) -> Result<Option<Vec<bool>>> {
    let Some(link) = x.text_opt(&["Record3", "DataLink", "ValidPointsLink"]) else {
        return Ok(None);
    };
    let bits = member(zip, x.path, &link)?;
    if bits.len() < count.div_ceil(8) {
        return Err(x.bad(format!(
            "truncated: the validity mask {link} holds {} bytes, {count} points need {}",
            bits.len(),
            count.div_ceil(8)
        )));
    }
    Ok(Some(
        (0..count)
            .map(|k| bits[k / 8] >> (k % 8) & 1 == 0)
            .collect(),
    ))
}

pub(crate) fn parse(path: &Path, b: &[u8]) -> Result<Raw> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    let mut zip = zip::ZipArchive::new(Cursor::new(b))
        .map_err(|e| bad(format!("not a readable .x3p (zip) archive: {e}")))?;
    if zip.index_for_name("main.xml").is_none() {
        return Err(bad(format!(
            "not an .x3p: the zip archive has no main.xml; {}",
            super::detect::READS
        )));
    }
    let xml = String::from_utf8(archive::member(
        &mut zip,
        path,
        "ISO 25178-72 .x3p",
        "main.xml",
        MAX_XML,
    )?)
    .map_err(|_| bad("main.xml is not UTF-8".into()))?;
    let doc = roxmltree::Document::parse(&xml).map_err(|e| bad(format!("main.xml: {e}")))?;
    let x = Xml {
        root: doc.root_element(),
        path,
    };
    let l = layout(&x)?;
    let count =
        l.nx.checked_mul(l.ny)
            .filter(|c| c.checked_mul(8).is_some())
            .ok_or_else(|| bad(format!("SizeX × SizeY = {} × {} is too large", l.nx, l.ny)))?;
    let raw = raw_values(&x, &mut zip, &l, count)?;
    let mask = invalid(&x, &mut zip, count)?;
    let heights = raw
        .into_iter()
        .enumerate()
        .map(|(k, v)| {
            if mask.as_ref().is_some_and(|m| m[k]) {
                f64::NAN
            } else {
                v * l.z_scale + l.z_offset
            }
        })
        .collect();
    let metres = || Unit::of(LengthUnit::Metre);
    Ok(Raw {
        nx: l.nx,
        ny: l.ny,
        heights,
        size: Some(Stored {
            lx: l.nx as f64 * l.dx,
            ly: l.ny as f64 * l.dy,
            unit: metres(),
            resolution: 1e-12,
        }),
        height_unit: metres(),
        layout: if l.profile {
            Layout::LineScans
        } else {
            Layout::Map
        },
        notes: Vec::new(),
        require_units: false,
    })
}

//! contact.engineering dataset exports: a zip archive of the measurements
//! of one digital surface twin, with their metadata in `meta.yml` (exports
//! of TopoBank up to 2025) or `index.json` (later ones; the same fields).
//!
//! Each measurement ("topography") is read from its data file inside the
//! archive by the reader of that file's format, then its metadata are
//! applied as SurfaceTopography's container reader (`Container/IO/CE.py`)
//! applies them:
//!
//! | field | read as |
//! |---|---|
//! | `datafile.original`, else `datafile.squeezed-netcdf` | the member read |
//! | `data_source` | the channel of that file (default 0) |
//! | `size` (`[Lx]` or `[Lx, Ly]`) | the physical size where the file stores none (a file's own size wins) |
//! | `unit` | the unit of the heights and of the size where the file states none |
//! | `height_scale` | a factor on the heights where the file states no height unit |
//! | `is_periodic` | periodic |
//! | `fill_undefined_data_mode` other than `do-not-fill` | undefined points filled (harmonic interpolation) |
//! | `detrend_mode` (`center`, `height`, `curvature`; default `center`) | the measurement's detrending ([`DatasetMeasurement::detrend`]): mean, plane, quadratic |
//!
//! A squeezed NetCDF carries the heights with the scale, filling and
//! detrending already applied: none of them is applied again.
//!
//! **`height_scale` of a file with its own scale.** TopoBank records, for a
//! file that scales its raw numbers itself (Nanoscope's sensitivity × Z
//! scale), the factor the file gives; SurfaceTopography 1.27.1 applies it a
//! second time (`container-2.zip`'s AFM map: rms height 0.525 nm through the
//! container against 4.69 nm read directly, the ratio being the recorded
//! factor 0.1121). Here it is applied only to numbers without a unit.
//!
//! A dataset is read one measurement at a time, chosen by
//! [`ReadOptions::channel`] (its name, its data file's name, or its index
//! from 0); [`dataset()`] lists them for a multi-scale spectrum.

use std::borrow::Cow;
use std::io::Cursor;
use std::path::Path;

use yaml_rust2::{Yaml, YamlLoader};

use super::archive::{self, Archive};
use super::units::{LengthUnit, Unit};
use super::{Raw, ReadOptions, Stored};
use crate::error::{Error, Result};
use crate::topography::Detrend;

const META: [&str; 2] = ["index.json", "meta.yml"];
const FORMAT: &str = "contact.engineering dataset";

/// One measurement of a dataset, as its metadata describe it.
#[derive(Debug, Clone, PartialEq)]
pub struct DatasetMeasurement {
    /// Its name in the dataset.
    pub name: String,
    /// The archive member holding its data.
    pub file: String,
    /// The channel of that file.
    pub data_source: usize,
    /// The physical size `[Lx]` or `[Lx, Ly]` in `unit`, if recorded.
    pub size: Vec<f64>,
    /// The unit of the heights and size where the file states none.
    pub unit: Option<LengthUnit>,
    /// The factor on heights without a unit (1 if none).
    pub height_scale: f64,
    /// Periodic.
    pub periodic: bool,
    /// Undefined points are to be filled.
    pub fill_undefined: bool,
    /// The detrending the dataset asks for (none for a squeezed file).
    pub detrend: Detrend,
    /// The member is a squeezed NetCDF (scale, filling and detrending applied).
    pub squeezed: bool,
}

/// The measurements of a dataset of one surface.
#[derive(Debug, Clone, PartialEq)]
pub struct Dataset {
    /// The surface's name.
    pub surface: String,
    /// Its measurements, in the order of the metadata.
    pub measurements: Vec<DatasetMeasurement>,
}

fn bad(path: &Path, m: impl std::fmt::Display) -> Error {
    Error::parse(path, 0, 0, format!("{FORMAT}: {m}"))
}

/// Whether `bytes` are a zip archive holding `meta.yml` or `index.json`.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PK\x03\x04")
        && zip::ZipArchive::new(Cursor::new(bytes))
            .is_ok_and(|z| META.iter().any(|m| z.index_for_name(m).is_some()))
}

/// The measurements of the dataset in the file `path` (module docs), or
/// `None` if it is not a dataset.
///
/// # Errors
/// [`Error::Io`] if the file cannot be read; for a dataset, metadata that do
/// not parse, no surface or several, a measurement without a data file, an
/// unknown unit or detrend mode, a size or scale that is not a positive
/// number.
pub fn dataset(path: &Path) -> Result<Option<Dataset>> {
    // The zip magic first: a map is not read twice (128 MB of a 4096² .npy).
    if crate::io::read_head(path, 4).is_ok_and(|magic| magic != b"PK\x03\x04") {
        return Ok(None);
    }
    let bytes = crate::io::read(path)?;
    if sniff(&bytes) {
        meta(path, &bytes).map(Some)
    } else {
        Ok(None)
    }
}

/// The dataset in `bytes`.
fn meta(path: &Path, bytes: &[u8]) -> Result<Dataset> {
    let mut zip = zip::ZipArchive::new(Cursor::new(bytes))
        .map_err(|e| bad(path, format!("not a readable zip archive: {e}")))?;
    let name = META
        .iter()
        .find(|m| zip.index_for_name(m).is_some())
        .ok_or_else(|| bad(path, "the archive has neither meta.yml nor index.json"))?;
    let text = String::from_utf8(member(&mut zip, path, name)?)
        .map_err(|_| bad(path, format!("{name} is not UTF-8")))?;
    let docs = YamlLoader::load_from_str(&text).map_err(|e| bad(path, format!("{name}: {e}")))?;
    let root = docs.first().unwrap_or(&Yaml::Null);
    let surfaces = root["surfaces"].as_vec().map_or(&[][..], Vec::as_slice);
    let surface = match surfaces {
        [s] => s,
        [] => return Err(bad(path, format!("{name} lists no surface"))),
        many => {
            let names: Vec<&str> = many
                .iter()
                .map(|s| s["name"].as_str().unwrap_or("?"))
                .collect();
            return Err(bad(
                path,
                format!(
                    "{name} lists {} surfaces ({}): a dataset is read as the measurements of one",
                    many.len(),
                    names.join(", ")
                ),
            ));
        }
    };
    let topographies = surface["topographies"]
        .as_vec()
        .map_or(&[][..], Vec::as_slice);
    if topographies.is_empty() {
        return Err(bad(path, format!("{name}: the surface has no measurement")));
    }
    let measurements = topographies
        .iter()
        .enumerate()
        .map(|(i, t)| {
            measurement(t).map_err(|m| bad(path, format!("{name}, measurement {i}: {m}")))
        })
        .collect::<Result<_>>()?;
    Ok(Dataset {
        surface: surface["name"].as_str().unwrap_or("").to_string(),
        measurements,
    })
}

/// A number, written as an integer or a real.
fn number(y: &Yaml) -> Option<f64> {
    y.as_f64().or_else(|| y.as_i64().map(|i| i as f64))
}

/// One measurement's metadata.
fn measurement(t: &Yaml) -> std::result::Result<DatasetMeasurement, String> {
    let name = t["name"].as_str().unwrap_or("").to_string();
    let files = &t["datafile"];
    let (file, squeezed) = match (
        files["original"].as_str(),
        files["squeezed-netcdf"].as_str(),
    ) {
        (Some(f), _) => (f, false),
        (None, Some(f)) => (f, true),
        (None, None) => return Err("no datafile (original or squeezed-netcdf)".into()),
    };
    let size = match &t["size"] {
        Yaml::BadValue | Yaml::Null => Vec::new(),
        s => s
            .as_vec()
            .and_then(|v| v.iter().map(number).collect::<Option<Vec<f64>>>())
            .filter(|v| (1..=2).contains(&v.len()) && v.iter().all(|x| x.is_finite() && *x > 0.0))
            .ok_or("size: not one or two positive numbers")?,
    };
    let unit = match t["unit"].as_str() {
        None => None,
        Some(u) => Some(LengthUnit::parse(u).ok_or_else(|| format!("unit {u:?} is not a length"))?),
    };
    let height_scale = match &t["height_scale"] {
        Yaml::BadValue | Yaml::Null => 1.0,
        h => number(h)
            .filter(|h| h.is_finite() && *h != 0.0)
            .ok_or("height_scale: not a finite non-zero number")?,
    };
    let detrend = match t["detrend_mode"].as_str().unwrap_or("center") {
        _ if squeezed => Detrend::None,
        "center" => Detrend::Mean,
        "height" => Detrend::Plane,
        "curvature" => Detrend::Curvature,
        other => {
            return Err(format!(
                "detrend_mode {other:?}: not center, height or curvature"
            ))
        }
    };
    let data_source = match &t["data_source"] {
        Yaml::BadValue | Yaml::Null => 0,
        d => d
            .as_i64()
            .and_then(|d| usize::try_from(d).ok())
            .ok_or("data_source: not an index")?,
    };
    Ok(DatasetMeasurement {
        name,
        file: file.to_string(),
        data_source,
        size,
        unit,
        height_scale,
        periodic: t["is_periodic"].as_bool().unwrap_or(false),
        fill_undefined: t["fill_undefined_data_mode"]
            .as_str()
            .is_some_and(|m| m != "do-not-fill"),
        detrend,
        squeezed,
    })
}

/// An archive member, whole (bounded: [`archive::member`]).
fn member(zip: &mut Archive, path: &Path, name: &str) -> Result<Vec<u8>> {
    archive::member(zip, path, FORMAT, name, archive::MAX_MEMBER)
}

/// The measurement `options.channel` names: by name, data file or index.
fn chosen<'d>(
    path: &Path,
    d: &'d Dataset,
    options: &ReadOptions,
) -> Result<&'d DatasetMeasurement> {
    let list = || {
        d.measurements
            .iter()
            .enumerate()
            .map(|(i, m)| format!("{i}: \"{}\"", m.name))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let Some(w) = options.channel.as_deref().map(str::trim) else {
        return Err(bad(
            path,
            format!(
                "{} measurements ({}): read one by its name or index (channel), or the \
                 whole dataset as a multi-scale surface",
                d.measurements.len(),
                list()
            ),
        ));
    };
    d.measurements
        .iter()
        .find(|m| m.name == w || m.file == w)
        .or_else(|| w.parse::<usize>().ok().and_then(|i| d.measurements.get(i)))
        .ok_or_else(|| {
            bad(
                path,
                format!("no measurement \"{w}\": the dataset has {}", list()),
            )
        })
}

/// The measurement [`ReadOptions::channel`] chooses, read by its file's
/// format with the metadata applied (module docs), and the options the
/// rest of reading takes (periodic, filling from the metadata).
pub(crate) fn parse<'o>(
    path: &Path,
    bytes: &[u8],
    options: &'o ReadOptions,
) -> Result<(Raw, Cow<'o, ReadOptions>)> {
    if options.size.is_some() || options.height_unit.is_some() || options.lateral_unit.is_some() {
        return Err(bad(
            path,
            "the sizes and units of a dataset's measurements come from its metadata: \
             give no size, pixel size or unit",
        ));
    }
    let d = meta(path, bytes)?;
    let m = chosen(path, &d, options)?;
    let mut zip = zip::ZipArchive::new(Cursor::new(bytes))
        .map_err(|e| bad(path, format!("not a readable zip archive: {e}")))?;
    let data = member(&mut zip, path, &m.file)?;
    let mut inner = ReadOptions {
        channel: Some(m.data_source.to_string()),
        periodic: options.periodic || m.periodic,
        fill_undefined: options.fill_undefined || m.fill_undefined,
        format: options.format,
        transpose: options.transpose,
        ..ReadOptions::default()
    };
    let in_member = |e: Error| match e {
        Error::Parse { message, .. } => Error::parse(
            path,
            0,
            0,
            format!("measurement \"{}\" ({}): {message}", m.name, m.file),
        ),
        e => e,
    };
    let mut raw = super::parse_named(path, Path::new(&m.file), &data, &inner).map_err(in_member)?;
    let meta_unit = || m.unit.map(|u| Unit::Stated(u.to_string(), u));
    let lateral_unstated = raw.size.as_ref().is_none_or(|s| s.unit == Unit::Unstated);
    if m.unit.is_none() && (raw.height_unit == Unit::Unstated || lateral_unstated) {
        return Err(in_member(Error::parse(
            path,
            0,
            0,
            "neither the file nor the dataset's metadata give the unit of its heights or              size (a dataset's measurements are combined in metres: a unit is needed)",
        )));
    }
    if raw.height_unit == Unit::Unstated && !raw.require_units {
        if !m.squeezed && m.height_scale != 1.0 {
            raw.heights.iter_mut().for_each(|h| *h *= m.height_scale);
        }
        inner.height_unit = m.unit;
    }
    match &raw.size {
        None => {
            let lx = m.size.first().copied();
            let ly = m.size.get(1).copied().unwrap_or(0.0);
            if let (Some(lx), Some(unit)) = (lx, meta_unit()) {
                raw.size = Some(Stored {
                    lx,
                    ly,
                    unit,
                    resolution: 1e-12,
                });
            }
        }
        Some(s) if s.unit == Unit::Unstated => inner.lateral_unit = m.unit,
        Some(_) => {}
    }
    Ok((raw, Cow::Owned(inner)))
}

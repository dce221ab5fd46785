//! Reading topographies from files.
//!
//! | format | extension | physical size | undefined points |
//! |---|---|---|---|
//! | numpy array, `f4`/`f8`, either byte order, C or Fortran order, rank 2 | `.npy` | from the caller | NaN |
//! | text matrix (whitespace, comma or semicolon separated, `#` comments) | any other | from the caller | `nan` |
//! | XYZ triples on a regular grid, any order | `.xyz` | from the coordinates | `nan`, or a grid point without a triple |
//! | Gwyddion Simple Field | `.gsf` | `XReal`, `YReal` (else the caller) | NaN |
//! | ISO 25178-72 XML 3D surface profile | `.x3p` | `CX`/`CY` increments | NaN |
//! | line scan: two columns x, h, x equally spaced | text with 2 columns | from x | `nan` |
//!
//! The format is chosen by the extension, else by content (`.npy` magic,
//! `Gwyddion Simple Field` first line, zip signature, two text columns for a
//! line scan), or given in [`ReadOptions::format`]. Every error is an
//! [`Error::Parse`] naming the file (and line where it helps) and what is
//! wrong; undefined points are an error with their count unless
//! [`ReadOptions::fill_undefined`] asks for harmonic interpolation.

mod gsf;
mod line;
mod npy;
mod text;
mod x3p;
mod xyz;

use std::path::Path;

use super::{fill, Layout, Topography};
use crate::error::{Error, Result};

pub use gsf::write_gsf;
pub use npy::write_npy;

/// The physical size, when the caller gives it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SizeSpec {
    /// The pixel size Δ (square pixels), m: `Lx = nx·Δ`, `Ly = ny·Δ`.
    PixelSize(f64),
    /// `Lx` and optionally `Ly`, m (without `Ly`, square pixels: `Ly = Lx·ny/nx`).
    Size(f64, Option<f64>),
}

/// A file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// numpy `.npy`.
    Npy,
    /// Text matrix.
    Text,
    /// XYZ triples.
    Xyz,
    /// Gwyddion Simple Field.
    Gsf,
    /// ISO 25178-72 `.x3p`.
    X3p,
    /// Two-column line scan (x, h).
    LineScan,
}

/// How to read a topography.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReadOptions {
    /// The physical size, for formats that do not store it. Giving it for a
    /// file that stores one is an error (the file's size is not overridden
    /// silently).
    pub size: Option<SizeSpec>,
    /// Whether the surface is periodic.
    pub periodic: bool,
    /// Fill undefined points by harmonic interpolation instead of failing.
    pub fill_undefined: bool,
    /// Force a format instead of detecting it.
    pub format: Option<Format>,
}

/// What a format parser returns: heights (NaN where undefined) and the size
/// if the file stores it.
pub(crate) struct Raw {
    pub nx: usize,
    pub ny: usize,
    pub heights: Vec<f64>,
    pub size: Option<(f64, f64)>,
    pub layout: Layout,
}

/// Read a topography file (module docs).
///
/// # Errors
/// [`Error::Io`] if the file cannot be read; [`Error::Parse`] naming the file
/// for a malformed or truncated file, a wrong dtype or rank, a grid that is
/// not regular, one row or column, constant heights, undefined points
/// (without `fill_undefined`), a missing, zero or negative size, or a size
/// given for a file that stores its own.
pub fn read(path: &Path, options: &ReadOptions) -> Result<Topography> {
    let bytes = crate::io::read(path)?;
    from_bytes(path, &bytes, options)
}

/// [`read()`] from bytes in memory; `path` names the source in errors and its
/// extension selects the format.
///
/// # Errors
/// As [`read()`], without the I/O errors.
///
/// # Examples
/// ```
/// use std::path::Path;
/// use persson::topography::read::{from_bytes, ReadOptions, SizeSpec};
/// # fn main() -> persson::Result<()> {
/// let text = b"0 1 2\n1 2 4\n";
/// let o = ReadOptions { size: Some(SizeSpec::PixelSize(2e-6)), ..Default::default() };
/// let t = from_bytes(Path::new("map.txt"), text, &o)?;
/// assert_eq!(t.shape(), [2, 3]);
/// assert_eq!((t.lx(), t.ly()), (6e-6, 4e-6));
/// // A constant map is refused, naming the file.
/// let e = from_bytes(Path::new("flat.txt"), b"1 1 1\n1 1 1\n", &o).unwrap_err();
/// assert!(e.to_string().starts_with("flat.txt") && e.to_string().contains("not all equal"));
/// # Ok(()) }
/// ```
pub fn from_bytes(path: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Topography> {
    let format = options.format.unwrap_or_else(|| detect(path, bytes));
    let raw = match format {
        Format::Npy => npy::parse(path, bytes)?,
        Format::Text => text::parse(path, bytes)?,
        Format::Xyz => xyz::parse(path, bytes)?,
        Format::Gsf => gsf::parse(path, bytes)?,
        Format::X3p => x3p::parse(path, bytes)?,
        Format::LineScan => line::parse(path, bytes)?,
    };
    finish(path, raw, options)
}

fn detect(path: &Path, bytes: &[u8]) -> Format {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("npy") => return Format::Npy,
        Some("gsf") => return Format::Gsf,
        Some("x3p") => return Format::X3p,
        Some("xyz") => return Format::Xyz,
        _ => {}
    }
    if bytes.starts_with(npy::MAGIC) {
        Format::Npy
    } else if bytes.starts_with(gsf::MAGIC) {
        Format::Gsf
    } else if bytes.starts_with(b"PK\x03\x04") {
        Format::X3p
    } else if text::columns(bytes) == Some(2) {
        Format::LineScan
    } else {
        Format::Text
    }
}

/// Sizes, undefined points, validation; every error names the file.
fn finish(path: &Path, mut raw: Raw, options: &ReadOptions) -> Result<Topography> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    let (nx, ny) = (raw.nx, raw.ny);
    if raw.layout == Layout::Map && (nx < 2 || ny < 2) {
        return Err(bad(format!(
            "the map has {ny} row(s) and {nx} column(s): need at least 2 of each"
        )));
    }
    if nx < 2 {
        return Err(bad(format!(
            "the line scan has {nx} point(s): need at least 2"
        )));
    }
    let given = |name: &str, v: f64| -> Result<f64> {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(bad(format!("{name} = {v}: must be finite and > 0")))
        }
    };
    let (lx, ly) = match (raw.size, options.size) {
        (Some(_), Some(_)) => {
            return Err(bad(
                "the file stores its physical size: do not give a pixel size or size as well"
                    .into(),
            ))
        }
        (Some((lx, ly)), None) => (
            given("size along x (from the file)", lx)?,
            if raw.layout == Layout::Map {
                given("size along y (from the file)", ly)?
            } else {
                0.0
            },
        ),
        (None, Some(SizeSpec::PixelSize(d))) => {
            let d = given("pixel_size", d)?;
            (nx as f64 * d, ny as f64 * d)
        }
        (None, Some(SizeSpec::Size(lx, ly))) => {
            let lx = given("size", lx)?;
            let ly = match ly {
                Some(ly) => given("size along y", ly)?,
                None => lx * ny as f64 / nx as f64,
            };
            (lx, ly)
        }
        (None, None) => {
            return Err(bad(
                "the format stores no physical size: give the pixel size or the size".into(),
            ))
        }
    };
    let undefined = raw.heights.iter().filter(|h| !h.is_finite()).count();
    if undefined > 0 {
        if !options.fill_undefined {
            return Err(bad(format!(
                "{undefined} of {} points are undefined (NaN, infinite or the format's missing-data marker); \
                 fill them by harmonic interpolation with --fill-undefined (scenes: fill_undefined)",
                raw.heights.len()
            )));
        }
        fill::harmonic_fill(&mut raw.heights, nx, ny, raw.layout, options.periodic)
            .map_err(|e| bad(e.to_string()))?;
    }
    let t = match raw.layout {
        Layout::Map => Topography::map(nx, ny, lx, ly, raw.heights, options.periodic),
        Layout::LineScans => Topography::line_scans(nx, ny, lx, raw.heights, options.periodic),
    };
    t.map_err(|e| bad(e.to_string()))
}

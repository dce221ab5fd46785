//! Reading topographies from files.
//!
//! | format | how it is chosen | physical size | height unit | undefined points |
//! |---|---|---|---|---|
//! | numpy array, `f4`/`f8`, either byte order, C or Fortran order, rank 2 | `.npy`, or its magic | from the caller | from the caller (default m) | NaN |
//! | text matrix | text that is not one of the two below | header (Gwyddion export, `h=`/`w=`/`pixel size=`) else the caller | header (`Value units`, `data unit` with `height conversion factor`) else the caller | `nan` |
//! | XYZ triples on a regular grid, any order | `.xyz`, or three columns whose first two take few distinct values | from the coordinates | column headings (`x [µm]`) else the caller | `nan`, or a grid point without a triple |
//! | line scan: x, h (or index, x, h; or x, h, valid) | two columns, or three as shown | from x | column headings else the caller | `nan`, valid = 0 |
//! | Gwyddion Simple Field | `.gsf`, or its first line | `XReal`, `YReal` | `ZUnits` (default: the caller's) | NaN |
//! | ISO 25178-72 XML 3D surface profile | `.x3p`, or a zip archive | `CX`/`CY` increments | m | NaN, `ValidPointsLink` mask |
//! | Gwyddion native (first height channel) | `.gwy`, or `GWYP` | `xreal`, `yreal` | `si_unit_z` (empty: the caller's, required) | `/N/mask` > 0.5 |
//! | Digital Surf | `.sur`, or `DIGITAL SURF` | `nx·Δx`, `ny·Δy` | the unit of the scaled z | z_min − 2 with "special points" |
//! | Zygo MetroPro phase map | its magic (any extension, `.dat`) | `width·Δ`, `height·Δ` (Δ = 0: the caller's) | m | raw ≥ 2147483640 |
//! | NetCDF classic, `heights(x, y)` or `heights(x)` | `.nc`, or `CDF` | `length` of `x`, `y` (absent: the caller's) | `unit` of `heights` (absent: of `x`) | `mask` ≠ 0, `_FillValue` |
//! | Alicona `.al3d` | `.al3d`, or `AliconaImaging` | `Cols·PixelSizeXMeter`, `Rows·PixelSizeYMeter` | m | NaN, `InvalidPixelValue` |
//! | Sensofar `.plu` (topography, first layer) | `.plu`, `.apx` (no magic) | nx·Δx, ny·Δy | µm | 1000001 |
//! | Bruker/Veeco Nanoscope (the first height channel) | `.spm`, `.di`, or `\*File list` (`.000`, `.001`, …) | `Scan Size` | the sensitivity's (`nm/V`) | – |
//! | Igor binary wave `.ibw` v5 (Asylum Research; the first height channel) | `.ibw` | nx·sfA\[0\], ny·sfA\[1\] (no unit of x: the caller's) | `dataUnits` (none: the caller's, required) | NaN |
//! | ISO 25178-71 `.sdf`, ASCII and binary (int16, int32, double) | `.sdf`, or `aISO-1.0`/`bISO-1.0` | NumPoints·Xscale, NumProfiles·Yscale | m (values × Zscale) | `BAD`, the int's minimum, NaN |
//! | TrueMap `.tmd` v2 | `.tmd`, or `Binary TrueMap Data File v2.0` | Lx, Ly of the header (mm) | mm | NaN |
//! | BCR-STM / BCRF (int16 or float32; Latin-1 or UTF-16 header) | `.bcr`, `.bcrf`, or `fileformat = bcr…` | `xlength`, `ylength` in `xunit` | `zunit` (values × `bit2nm`) | `voidpixels` |
//! | FRT MicroProf `.frt` v1.00/1.01 (block 0x000b topography; the images of block 0x007d by name) | `.frt`, or `FRTM_GLIDERV` | Lx, Ly of block 0x0067 (m) | m (values × z scale of block 0x006c); other channels: the caller's | value 1 |
//! | Wyko `.opd` (array `Raw`/`RAW DATA`/`RAW_DATA`/`OPD`/`SAMPLE_DATA`; other arrays by name) | `.opd`, or `Directory` at byte 2 | nx·Pixel_size, ny·Pixel_size·Aspect (mm; no Pixel_size: the caller's) | mm (values × Wavelength/Mult·1e-6); other arrays: the caller's | not finite, ≥ 1e38 (f32), ≥ 32766 (i16) |
//! | Bruker Dektak `.opdx`, profile or map (first channel of `1D_Channels`/`2D_Channels` `Height`, `PrimaryData2D` first) | `.opdx`, or `VCA DATA\x01\x00\x00\x55` | Extent·n/(n − 1) per axis, in its unit | the unit of `DataScale` (values × DataScale) | NaN |
//! | Molecular Imaging / Keysight `.mi` (the first buffer in a length unit, or by `bufferLabel`) | `.mi`, or `fileType` | `xLength`, `yLength` (m) | `bufferUnit` (values × `bufferRange`/2³¹ or 2¹⁵) | – |
//! | WSxM `.stp`, `.top` (double, float, int16) | `.stp`, `.top`, `.wsxm`, or `WSxM file copyright` | `X Amplitude`, `Y Amplitude` | the unit of `Z Amplitude` (int16 × Z Amplitude/(Maximum − Minimum)) | – |
//! | Nanosurf `.nid` (the first channel in a length unit, or by `Frame (Dim2Name)`) | `.nid`, or `[DataSet]` | `Dim0Range`, `Dim1Range` | `Dim2Unit` (values × Dim2Range/2^bits + Dim2Min) | – |
//! | NanoFocus `.nms` (`OM_MS_2.0`) | `.nms`, or `OM_MS_2.0` at byte 32 | nx·Δx, ny·Δy (nm) | µm (z_low … z_high over n_low … n_high) | intensity 0 |
//! | Digital Surf Mountains `.mnt` (the measured surfaces; the first height channel) | `.mnt`, or an OLE file with a `ScopedContents` stream | nx·step_x, ny·step_y | the display unit of z | mask ≠ 9 |
//! | Park Systems `.tiff` | `.tiff`, or a TIFF with Park's tag 50432 | Lx, Ly of the header (µm) | `data_unit` (empty: µm) | NaN |
//! | Mitutoyo SurfTest `.xlsx` (line scan) | `.xlsx`, or a zip with `xl/workbook.xml` | n·Δ of column E (unit of the cut-off) | unit of the first roughness parameter | – |
//! | HDF5 `.h5` (rank-2 numeric data sets; the first index along x) | `.h5`, `.hdf5`, or the HDF5 signature | from the caller | from the caller | NaN |
//! | Zygo `.datx` (HDF5; the `/MetaData` surface) | `.datx`, or the HDF5 signature with `MetaData` in the first 4 kB | `nx·Δx`, `ny·Δy` from the X/Y converters (m) | `Unit` (MicroMeters, NanoMeters, …) | `No Data`, NaN |
//! | contact.engineering dataset (a zip with `meta.yml` or `index.json`): one measurement, chosen by [`ReadOptions::channel`], read by its file's format | a zip holding `meta.yml` or `index.json` (any extension) | the file's, else `size` of the metadata (never the caller's) | the file's, else `unit` of the metadata (× `height_scale`) | as its file's format |
//! | any of these but a dataset, gzip-compressed (`matrix.txt.gz`) | the gzip magic; the inner format by the name without `.gz`, or content | as the inner format | as the inner format | as the inner format |
//!
//! # Axis order
//! A row of a `.npy` array or text matrix runs along x: the array of
//! shape `(ny, nx)` has `nx` points along x (numpy's image convention), and
//! `size: [Lx, Ly]` ([`ReadOptions::size`]) gives `Lx` along a row.
//! SurfaceTopography's `heights()` is indexed the other way round, `[ix, iy]`:
//! save its transpose, or read with [`ReadOptions::transpose`].
//!
//! # Text
//! Text is UTF-8, UTF-16 with a byte-order mark or Latin-1, and may start
//! with any number of header lines ([`crate::io::text`]). The kind of a
//! text file (matrix, XYZ, line scan) is read from its content whatever the
//! extension (`.txt`, `.csv`, `.dat`, `.asc`), except `.xyz`.
//!
//! # Line scans
//! The x positions are tested against the equally spaced grid through the
//! first and last, `x_i = x_0 + iΔ`, `Δ = (x_{n−1} − x_0)/(n − 1)`:
//! ```text
//! |x_i − x_0 − iΔ| ≤ 0.01 Δ + u_i          (u_i: one unit in the last digit written of x_i)
//! ```
//! so that positions rounded on export (6 decimals, 8 significant digits,
//! 0.1 µm) are read as the equally spaced scan the instrument took. A scan
//! beyond that is linearly interpolated onto n equally spaced points from
//! x_0 to x_{n−1} (SurfaceTopography's `to_uniform(nb_points=n)`), with a
//! [`Note::Resampled`]; positions that do not increase are an error. The
//! length is `L = nΔ`.
//!
//! # Units
//! Heights and coordinates end up in metres. Where a file states a unit
//! it is used (and a caller's unit must agree); a stated unit that is not a
//! length (a GSF phase channel in `deg`) is an error naming it. Where a file
//! states none, [`ReadOptions::height_unit`] and
//! [`ReadOptions::lateral_unit`] give it (default m); a file that states
//! one of them but not the other needs the other from the caller.
//!
//! # Unsupported formats
//! Binary instrument formats not in the table (Keyence `.vk3`/`.vk4`/`.vk6`/`.vk7`
//! and `.zon`, Sensofar `.plux`, Olympus `.lext`, `.oir`/`.poir`, Digital
//! Metrology `.os3d`, KLA Zeta `.zmg`, JPK `.jpk`, MATLAB `.mat`, Nanosurf
//! easyScan `.ezd`, NT-MDT `.mdt`, Mahr `.qep`, SIOS NMM scans, NumPy
//! `.npz`, SRTM `.hgt`, `.dzi`, a TIFF or zip archive of none of the
//! formats above, …) are an error that names the format, says what persson
//! reads and how to convert them.
//!
//! # Channels
//! The readers of multi-channel formats (FRT, Wyko, Dektak OPDx, `.mi`,
//! Nanosurf, Mountains, HDF5) list the file's channels and read one:
//! [`ReadOptions::channel`] names it (case-insensitive) or gives its index
//! from 0; without it, the first height channel (the one SurfaceTopography
//! reads by default). A name or index the file does not have is an error
//! listing its channels with their indices. FRT's and Wyko's intensity
//! images are read, when named, as raw numbers with the height unit from
//! the caller; a `.mi`, `.nid` or Park channel in a unit that is not a
//! length is an error naming it. The one channel of a Park, Mitutoyo or
//! `.datx` file answers to its name or 0. The other formats read their
//! first height channel and do not consult `channel`. A contact.engineering
//! dataset is read one measurement at a time: `channel` gives its name or
//! its data file's name (exactly) or its index; without one, reading it is
//! an error listing its measurements.
//!
//! Every error is an [`Error::Parse`] naming the file (and line where it
//! helps); undefined points are an error with their count unless
//! [`ReadOptions::fill_undefined`] asks for harmonic interpolation.

mod al3d;
mod archive;
mod bcr;
mod bin;
mod channel;
mod dataset;
mod datx;
mod detect;
mod di;
mod frt;
mod gsf;
mod gwy;
mod gzip;
mod hdf5;
mod header;
mod ibw;
mod line;
mod metropro;
mod mi;
mod mitutoyo;
mod mnt;
mod netcdf;
mod nid;
mod nms;
mod opdx;
mod park;
mod plu;
mod sdf;
mod sur;
mod text;
mod tmd;
mod units;
mod wsxm;
mod wyko;
mod x3p;
mod xyz;

use std::path::Path;

use super::{fill, Layout, Note, Topography};
use crate::error::{Error, Result};

pub use dataset::{dataset, Dataset, DatasetMeasurement};
pub use gsf::write_gsf;
pub use units::LengthUnit;
use units::Unit;

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
    /// Text: a matrix, XYZ triples or a line scan, by content.
    Text,
    /// XYZ triples.
    Xyz,
    /// Gwyddion Simple Field.
    Gsf,
    /// ISO 25178-72 `.x3p`.
    X3p,
    /// Line scan (x, h).
    LineScan,
    /// Gwyddion native `.gwy`.
    Gwy,
    /// Digital Surf `.sur`.
    Sur,
    /// Zygo MetroPro `.dat`.
    MetroPro,
    /// NetCDF classic `.nc` (SurfaceTopography's conventions).
    NetCdf,
    /// Alicona `.al3d`.
    Al3d,
    /// Sensofar `.plu`.
    Plu,
    /// Igor binary wave `.ibw` (Asylum Research).
    Ibw,
    /// Bruker/Veeco Nanoscope `.spm`, `.di`, `.000`, ….
    Nanoscope,
    /// ISO 25178-71 `.sdf` (ASCII or binary).
    Sdf,
    /// TrueMap `.tmd`.
    TrueMap,
    /// BCR-STM / BCRF `.bcr`, `.bcrf`.
    Bcr,
    /// FRT MicroProf `.frt`.
    Frt,
    /// Molecular Imaging / Keysight `.mi`.
    Mi,
    /// WSxM `.stp`, `.top`.
    Wsxm,
    /// Bruker Dektak `.opdx`.
    Opdx,
    /// Park Systems `.tiff`.
    ParkTiff,
    /// Mitutoyo SurfTest `.xlsx`.
    Mitutoyo,
    /// Digital Surf Mountains `.mnt`.
    Mountains,
    /// Wyko `.opd`.
    Wyko,
    /// Nanosurf `.nid`.
    Nanosurf,
    /// NanoFocus `.nms`.
    NanoFocus,
    /// HDF5 `.h5` (a named or numbered data set).
    Hdf5,
    /// Zygo `.datx` (HDF5).
    Datx,
}

/// How to read a topography.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReadOptions {
    /// The physical size, for formats that do not store it. For a file that
    /// stores one it is checked against the file's (to the precision the
    /// file writes) and an error if they disagree.
    pub size: Option<SizeSpec>,
    /// Whether the surface is periodic.
    pub periodic: bool,
    /// Fill undefined points by harmonic interpolation instead of failing.
    pub fill_undefined: bool,
    /// Force a format instead of detecting it.
    pub format: Option<Format>,
    /// The unit of the heights in a file that states none (default m);
    /// checked against the file's where it states one.
    pub height_unit: Option<LengthUnit>,
    /// The unit of the x (and y) coordinates of a line scan or XYZ file
    /// that states none (default m); checked against the file's.
    pub lateral_unit: Option<LengthUnit>,
    /// Swap the axes of a map after reading: row i of the file becomes
    /// column i (for arrays saved in SurfaceTopography's `[ix, iy]` order).
    /// The size, given or stored, is that of the map as read, before the
    /// swap.
    pub transpose: bool,
    /// The channel of a multi-channel file (a data set of an HDF5 file), by
    /// name (case-insensitive) or by index from 0; default: the first
    /// height channel.
    pub channel: Option<String>,
}

/// The physical size a file stores, in its lateral unit.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Stored {
    /// Size along x.
    pub lx: f64,
    /// Size along y (0 for line scans).
    pub ly: f64,
    /// The unit of `lx`, `ly`.
    pub unit: Unit,
    /// Relative precision to which the file writes the size (a caller's
    /// size within it agrees).
    pub resolution: f64,
}

/// What a format parser returns: heights (NaN where undefined) in the
/// file's unit, and the size if the file stores it.
pub(crate) struct Raw {
    pub nx: usize,
    pub ny: usize,
    pub heights: Vec<f64>,
    pub size: Option<Stored>,
    pub height_unit: Unit,
    pub layout: Layout,
    pub notes: Vec<Note>,
    /// The file states that its numbers have no unit (Gwyddion's empty
    /// unit): the caller must give the units it leaves out, never metres
    /// by default.
    pub require_units: bool,
}

impl Raw {
    /// A map of `nx × ny` heights, no size, units unstated.
    pub(crate) fn map(nx: usize, ny: usize, heights: Vec<f64>) -> Self {
        Raw {
            nx,
            ny,
            heights,
            size: None,
            height_unit: Unit::Unstated,
            layout: Layout::Map,
            notes: Vec::new(),
            require_units: false,
        }
    }
}

/// Read a topography file (module docs).
///
/// # Errors
/// [`Error::Io`] if the file cannot be read; [`Error::Parse`] naming the file
/// for an unsupported format, a malformed or truncated file, a wrong dtype
/// or rank, a grid that is not regular, one row or column, constant
/// heights, undefined points (without `fill_undefined`), a missing, zero or
/// negative size, a given size that disagrees with the file's, a unit that
/// is not a length, or a given unit that disagrees with the file's.
pub fn read(path: &Path, options: &ReadOptions) -> Result<Topography> {
    let bytes = crate::io::read(path)?;
    from_bytes(path, &bytes, options)
}

/// [`read()`] from bytes in memory; `path` names the source in errors and its
/// extension selects the format where it is unambiguous.
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
/// // A binary format persson does not read says so.
/// let e = from_bytes(Path::new("scan.vk4"), b"anything\0\0", &o).unwrap_err();
/// assert!(e.to_string().contains("unsupported format (.vk4)"));
/// # Ok(()) }
/// ```
pub fn from_bytes(path: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Topography> {
    let (raw, options) = parse(path, bytes, options)?;
    finish(path, raw, &options)
}

/// A file's grid, size and heights as read: in metres, NaN where the file
/// marks a point undefined, before any filling, transposing or checks of
/// the heights (what [`read()`] starts from).
#[derive(Debug, Clone, PartialEq)]
pub struct AsRead {
    /// Points along x (a row).
    pub nx: usize,
    /// Rows (1 for a line scan).
    pub ny: usize,
    /// Physical size along x, m.
    pub lx: f64,
    /// Physical size along y, m (0 for a line scan).
    pub ly: f64,
    /// Heights, m, x fastest: `heights[iy·nx + ix]`; NaN where undefined.
    pub heights: Vec<f64>,
}

/// The heights of a file as read ([`AsRead`]), for inspecting undefined
/// points and comparing with another reader.
///
/// # Errors
/// As [`read()`], except that undefined points and a constant map are not
/// errors.
pub fn as_read(path: &Path, options: &ReadOptions) -> Result<AsRead> {
    let bytes = crate::io::read(path)?;
    let (mut raw, options) = parse(path, &bytes, options)?;
    let options = options.as_ref();
    let bad = |m: String| Error::parse(path, 0, 0, m);
    let (z, xy) = unit_factors(&raw, options).map_err(bad)?;
    raw.heights.iter_mut().for_each(|h| *h *= z);
    let (lx, ly) = sizes(&raw, xy, options).map_err(bad)?;
    Ok(AsRead {
        nx: raw.nx,
        ny: raw.ny,
        lx,
        ly,
        heights: raw.heights,
    })
}

/// The format's parser on `bytes`, and the options the rest of reading
/// takes (a dataset's measurement brings its own).
fn parse<'o>(
    path: &Path,
    bytes: &[u8],
    options: &'o ReadOptions,
) -> Result<(Raw, std::borrow::Cow<'o, ReadOptions>)> {
    if bytes.starts_with(gzip::MAGIC) {
        let inner = gzip::inflate(path, bytes)?;
        let raw = parse_named(path, &gzip::inner_name(path), &inner, options)?;
        return Ok((raw, std::borrow::Cow::Borrowed(options)));
    }
    if options.format.is_none() && dataset::sniff(bytes) {
        return dataset::parse(path, bytes, options);
    }
    let raw = parse_named(path, path, bytes, options)?;
    Ok((raw, std::borrow::Cow::Borrowed(options)))
}

/// [`parse`] of `bytes` whose format `name` (its extension) or content
/// tells; errors name `path`.
fn parse_named(path: &Path, name: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Raw> {
    let format = match options.format {
        Some(f) => f,
        None => detect::format(name, bytes).map_err(|e| match e {
            Error::Parse { message, .. } => Error::parse(path, 0, 0, message),
            e => e,
        })?,
    };
    if let (Some(name), Some(wanted)) = (single_channel(format), options.channel.as_deref()) {
        if wanted.trim() != "0" {
            return Err(Error::parse(
                path,
                0,
                0,
                format!(
                    "{name} files hold one channel: channel \"{wanted}\" does not exist \
                     (give none, or 0)"
                ),
            ));
        }
    }
    let raw = match format {
        Format::Npy => {
            let m = crate::io::npy::parse(path, bytes)?;
            Raw::map(m.cols, m.rows, m.values)
        }
        Format::Text => text::parse(path, bytes)?,
        Format::Xyz => xyz::parse(path, &crate::io::text::rows(path, bytes)?)?,
        Format::Gsf => gsf::parse(path, bytes)?,
        Format::X3p => x3p::parse(path, bytes)?,
        Format::LineScan => line::parse(path, &crate::io::text::rows(path, bytes)?)?,
        Format::Gwy => gwy::parse(path, bytes, options)?,
        Format::Sur => sur::parse(path, bytes)?,
        Format::MetroPro => metropro::parse(path, bytes)?,
        Format::NetCdf => netcdf::parse(path, bytes)?,
        Format::Al3d => al3d::parse(path, bytes)?,
        Format::Plu => plu::parse(path, bytes)?,
        Format::Ibw => ibw::parse(path, bytes, options)?,
        Format::Nanoscope => di::parse(path, bytes, options)?,
        Format::Sdf => sdf::parse(path, bytes)?,
        Format::TrueMap => tmd::parse(path, bytes)?,
        Format::Bcr => bcr::parse(path, bytes)?,
        Format::Frt => frt::parse(path, bytes, options)?,
        Format::Mi => mi::parse(path, bytes, options)?,
        Format::Wsxm => wsxm::parse(path, bytes, options)?,
        Format::Opdx => opdx::parse(path, bytes, options)?,
        Format::ParkTiff => park::parse(path, bytes, options)?,
        Format::Mitutoyo => mitutoyo::parse(path, bytes, options)?,
        Format::Mountains => mnt::parse(path, bytes, options)?,
        Format::Wyko => wyko::parse(path, bytes, options)?,
        Format::Nanosurf => nid::parse(path, bytes, options)?,
        Format::NanoFocus => nms::parse(path, bytes, options)?,
        Format::Hdf5 => hdf5::parse(path, bytes, options)?,
        Format::Datx => datx::parse(path, bytes, options)?,
    };
    // Every reader's grid and values agree (a guard for `as_read`, which
    // hands them out as they are).
    if raw.nx.checked_mul(raw.ny) != Some(raw.heights.len()) {
        return Err(Error::parse(
            path,
            0,
            0,
            format!(
                "{nx} × {ny} points, {n} values read: the file is inconsistent",
                nx = raw.nx,
                ny = raw.ny,
                n = raw.heights.len()
            ),
        ));
    }
    Ok(raw)
}

/// The name of a format whose files hold one channel, for the error of
/// [`ReadOptions::channel`] naming another; `None` for the formats whose
/// readers choose among their channels (`channel::choose`). Every format is
/// listed here, so a new one must say which it is.
fn single_channel(format: Format) -> Option<&'static str> {
    match format {
        Format::Gwy
        | Format::Ibw
        | Format::Nanoscope
        | Format::Frt
        | Format::Mi
        | Format::Opdx
        | Format::ParkTiff
        | Format::Mitutoyo
        | Format::Mountains
        | Format::Wyko
        | Format::Nanosurf
        | Format::Hdf5
        | Format::Datx => None,
        Format::Npy => Some("numpy .npy"),
        Format::Text => Some("Text"),
        Format::Xyz => Some("XYZ"),
        Format::Gsf => Some("Gwyddion Simple Field .gsf"),
        Format::X3p => Some("ISO 25178-72 .x3p"),
        Format::LineScan => Some("Line scan"),
        Format::Sur => Some("Digital Surf .sur"),
        Format::MetroPro => Some("Zygo MetroPro .dat"),
        Format::NetCdf => Some("NetCDF .nc"),
        Format::Al3d => Some("Alicona .al3d"),
        Format::Plu => Some("Sensofar .plu"),
        Format::Sdf => Some("ISO 25178-71 .sdf"),
        Format::TrueMap => Some("TrueMap .tmd"),
        Format::Bcr => Some("BCR-STM/BCRF"),
        Format::Wsxm => Some("WSxM"),
        Format::NanoFocus => Some("NanoFocus .nms"),
    }
}

/// Units, sizes, undefined points, transpose, validation; every error
/// names the file.
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
    let (z, xy) = unit_factors(&raw, options).map_err(bad)?;
    if z != 1.0 {
        raw.heights.iter_mut().for_each(|h| *h *= z);
    }
    let (lx, ly) = sizes(&raw, xy, options).map_err(bad)?;
    fill_undefined(&mut raw, options).map_err(bad)?;
    let mut t = match raw.layout {
        Layout::Map => Topography::map(nx, ny, lx, ly, raw.heights, options.periodic),
        Layout::LineScans => Topography::line_scans(nx, ny, lx, raw.heights, options.periodic),
    }
    .map_err(|e| bad(e.to_string()))?;
    if options.transpose {
        if t.layout() != Layout::Map {
            return Err(bad("a line scan cannot be transposed (only maps)".into()));
        }
        t = t.transposed();
    }
    Ok(t.with_notes(raw.notes))
}

/// The factors to metres of the heights and of the stored size.
fn unit_factors(raw: &Raw, options: &ReadOptions) -> std::result::Result<(f64, f64), String> {
    let lateral = raw.size.as_ref().map_or(&Unit::Unstated, |s| &s.unit);
    let one = |what: &str,
               flag: &str,
               file: &Unit,
               given: Option<LengthUnit>,
               other: &Unit|
     -> std::result::Result<f64, String> {
        match (file, given) {
            (Unit::Stated(text, u), Some(g)) if *u != g => Err(format!(
                "the file gives {what} in {text}, the {flag} given is {g}: leave it out \
                 (the file's unit is used)"
            )),
            (Unit::Stated(_, u), _) => Ok(u.metres()),
            (Unit::Unstated, Some(g)) => Ok(g.metres()),
            (Unit::Unstated, None) => match other {
                Unit::Stated(text, _) => Err(format!(
                    "the file gives the unit of the {} ({text}) but not of the {what}: \
                     give the {flag}",
                    if what == "heights" {
                        "coordinates"
                    } else {
                        "heights"
                    }
                )),
                Unit::Unstated if raw.require_units => Err(format!(
                    "the file states no unit of the {what} (an empty unit): give the {flag}"
                )),
                Unit::Unstated => Ok(1.0),
            },
        }
    };
    let z = one(
        "heights",
        "height unit (option `height_unit`)",
        &raw.height_unit,
        options.height_unit,
        lateral,
    )?;
    let xy = match &raw.size {
        Some(s) => one(
            "coordinates",
            "lateral unit (option `lateral_unit`)",
            &s.unit,
            options.lateral_unit,
            &raw.height_unit,
        )?,
        None => 1.0,
    };
    Ok((z, xy))
}

/// `(Lx, Ly)` in metres from the file or the caller, checked against each
/// other when both give one.
fn sizes(raw: &Raw, xy: f64, options: &ReadOptions) -> std::result::Result<(f64, f64), String> {
    let (nx, ny) = (raw.nx as f64, raw.ny as f64);
    let map = raw.layout == Layout::Map;
    let given = |name: &str, v: f64| -> std::result::Result<f64, String> {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(format!("{name} = {v}: must be finite and > 0"))
        }
    };
    let caller = match options.size {
        Some(SizeSpec::PixelSize(d)) => {
            let d = given("pixel_size", d)?;
            Some((nx * d, ny * d, false))
        }
        Some(SizeSpec::Size(lx, ly)) => {
            let lx = given("size", lx)?;
            Some(match ly {
                Some(ly) => (lx, given("size along y", ly)?, false),
                None => (lx, lx * ny / nx, true),
            })
        }
        None => None,
    };
    let Some(s) = &raw.size else {
        return caller.map(|(lx, ly, _)| (lx, ly)).ok_or_else(|| {
            "the format stores no physical size: give the pixel size or the size".into()
        });
    };
    let lx = given("size along x (from the file)", s.lx * xy)?;
    let ly = if map {
        given("size along y (from the file)", s.ly * xy)?
    } else {
        0.0
    };
    if let Some((cx, cy, implied_y)) = caller {
        let tol = s.resolution.max(1e-9);
        let off = |a: f64, b: f64| (a / b - 1.0).abs() > tol;
        if off(cx, lx) || (map && !implied_y && off(cy, ly)) {
            let n = crate::error::num;
            let (file, given) = if map {
                (
                    format!("{} × {} m", n(lx), n(ly)),
                    format!("{} × {} m", n(cx), n(cy)),
                )
            } else {
                (format!("{} m", n(lx)), format!("{} m", n(cx)))
            };
            return Err(format!(
                "the file gives the size {file}; the size given ({given}) disagrees: \
                 leave it out (the file's size is used)"
            ));
        }
    }
    Ok((lx, ly))
}

/// Undefined points: an error with their count, or filled on request.
fn fill_undefined(raw: &mut Raw, options: &ReadOptions) -> std::result::Result<(), String> {
    let undefined = raw.heights.iter().filter(|h| !h.is_finite()).count();
    if undefined == 0 {
        return Ok(());
    }
    if !options.fill_undefined {
        return Err(format!(
            "{undefined} of {} points are undefined (NaN, infinite, the format's missing-data \
             marker or validity mask); fill them by harmonic interpolation with the \
             option `fill_undefined`",
            raw.heights.len()
        ));
    }
    fill::harmonic_fill(
        &mut raw.heights,
        raw.nx,
        raw.ny,
        raw.layout,
        options.periodic,
    )
    .map(drop)
    .map_err(|e| e.to_string())
}

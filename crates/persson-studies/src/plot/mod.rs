//! Figures as SVG or PNG (feature `plot`): a small data-in API.
//!
//! A [`Figure`] is plain data: a title, two [`Axis`] descriptions (label with
//! units, [`Scale::Linear`] or [`Scale::Log`], optional range) and a list of
//! [`Series`] (label, points, [`Style`]). [`render`] draws it to a file whose
//! extension (`.svg` or `.png`) picks the format. Every subcommand that has a
//! curve builds a `Figure` (directly or through one of the builders in
//! [`figures`]) and calls `render`; no other module touches the plotting
//! library.
//!
//! Rendering details that callers can rely on:
//! - **Log axes work for any positive magnitude.** The data are drawn as
//!   `log10` values on linear axes and the ticks are labelled `10ᵏ`, so a
//!   C(q) axis at 10⁻⁴⁰ m⁴ gets labels like any other (the plotting library's
//!   own log scale drops every tick below `f64::EPSILON`).
//! - Non-finite values, and non-positive values on a log axis, are dropped
//!   (the line is broken there). A series left empty is still listed in the
//!   legend; a figure with nothing drawable at all is an error.
//! - Ranges are automatic (data extent plus 4 % padding, anchored at zero
//!   when the data start at zero on a linear axis) unless given.
//! - Colours come from the Okabe–Ito colour-blind-safe [`PALETTE`]; markers
//!   cycle through circle, square, triangle and cross; the legend goes into the
//!   plot corner that covers the fewest data.
//! - The text is laid out with a bundled DejaVu Sans (`assets/DejaVuSans.ttf`,
//!   Bitstream Vera licence), so no system font library is needed. SVG files
//!   name the font family `sans-serif` and the viewer draws the glyphs.
//! - Every figure implements [`Encode`]: the bytes of its `.svg` or `.png`
//!   file, which the output layer writes only once the whole run has
//!   succeeded; [`render`] writes them atomically to one file.
//!
//! # Examples
//! ```
//! use persson_studies::plot::{render, Axis, Figure, Series};
//! let q: Vec<f64> = (0..50).map(|i| 1e4 * 10f64.powf(i as f64 / 10.0)).collect();
//! let c: Vec<f64> = q.iter().map(|&q| 1e-20 * (q / 1e4).powf(-3.6)).collect();
//! let fig = Figure::new("Power spectrum", Axis::log("wavevector q (1/m)"), Axis::log("C(q) (m⁴)"))
//!     .with_series(Series::from_xy("C(q)", &q, &c)?);
//! let path = std::env::temp_dir().join(format!("persson-doc-{}.svg", std::process::id()));
//! render(&fig, &path)?;
//! assert!(std::fs::read_to_string(&path)?.contains("10⁻³⁰"));
//! # std::fs::remove_file(&path)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod figure;
pub mod figures;
pub mod map;
// Everything that touches the plotting library: one gate. Without the
// feature every figure still builds (its data are the report's), and
// encoding one says which feature it needs.
#[cfg_attr(not(feature = "plot"), path = "render_off.rs")]
mod render;
pub mod spectrum_map;
pub mod stress_map;

pub use figure::*;
pub use figures::{
    area_vs_load, area_vs_zeta, error_vs_time, g_vs_zeta, spectrum, stress_family, LinearLaw,
    PowerLaw,
};

use crate::{Error, Result};
use std::path::Path;
/// The output file format, chosen by the file extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Scalable vector graphics (`.svg`).
    Svg,
    /// Portable network graphics (`.png`), 24-bit RGB.
    Png,
}

impl Format {
    /// The format named by `path`'s extension (`svg` or `png`, any case).
    ///
    /// # Errors
    /// [`Error::Io`] of kind `InvalidInput`, naming the path and the allowed
    /// extensions, for any other extension.
    pub fn from_path(path: &Path) -> Result<Self> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("svg") => Ok(Format::Svg),
            Some("png") => Ok(Format::Png),
            _ => Err(Error::Io {
                path: path.to_path_buf(),
                source: std::io::Error::new(
                    std::io::ErrorKind::InvalidInput,
                    "unsupported plot format: the file name must end in .svg or .png",
                ),
            }),
        }
    }
}

/// A figure that encodes itself as the bytes of an `.svg` or `.png` file.
///
/// Every figure of this module implements it; the output layer
/// ([`crate::output::Files`]) writes the bytes, [`render`] writes them
/// straight to a file.
pub trait Encode {
    /// The bytes of the file `path`, whose extension (`.svg` or `.png`)
    /// picks the format; errors name `path`.
    ///
    /// # Errors
    /// - [`Error::Io`] (kind `InvalidInput`) for an extension other than `.svg`/`.png`,
    ///   or a failure of the drawing backend;
    /// - the figure's own checks ([`Error::InvalidParameter`] for a fixed range
    ///   that is not finite, not increasing, or not positive on a log axis, or a
    ///   size outside [`SIZE_LIMITS`]; [`Error::Inconsistent`] when nothing is drawable).
    fn encode(&self, path: &Path) -> Result<Vec<u8>>;
}

/// Draws `fig` into `path` as SVG or PNG (by extension), atomically
/// ([`persson::io::write_atomic`]): a failure never leaves a half-written
/// file and never touches an existing one.
///
/// # Errors
/// As [`Encode::encode`]; [`Error::Io`] naming `path` when the directory is
/// not writable.
pub fn render<F: Encode + ?Sized>(fig: &F, path: &Path) -> Result<()> {
    persson::io::write_atomic(path, &fig.encode(path)?)
}

/// Draws `fig` as an SVG document in memory (for embedding, or tests).
///
/// # Errors
/// As [`Encode::encode`] of a `.svg` file.
pub fn render_svg_string<F: Encode + ?Sized>(fig: &F) -> Result<String> {
    let here = Path::new("figure.svg");
    String::from_utf8(fig.encode(here)?).map_err(|e| Error::Io {
        path: here.to_path_buf(),
        source: std::io::Error::other(e),
    })
}

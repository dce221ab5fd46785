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

mod canvas;
mod draw;
pub mod figures;
pub mod map;
mod prepare;
pub mod spectrum_map;
mod stack;
pub mod stress_map;
mod ticks;

pub use figures::{
    area_vs_load, area_vs_zeta, error_vs_time, g_vs_zeta, spectrum, stress_family, LinearLaw,
    PowerLaw,
};

use crate::{Error, Result};
use std::path::Path;

/// The default figure size in pixels, width × height (readable at this size).
pub const DEFAULT_SIZE: (u32, u32) = (800, 560);

/// The smallest and largest accepted figure side in pixels.
pub const SIZE_LIMITS: (u32, u32) = (200, 8000);

/// An sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rgb(pub u8, pub u8, pub u8);

/// The Okabe–Ito colour-blind-safe palette (without its yellow, which is
/// unreadable on white), in the order series are coloured.
///
/// # References
/// M. Okabe and K. Ito, "Color Universal Design" (2002), <https://jfly.uni-koeln.de/color/>.
pub const PALETTE: [Rgb; 7] = [
    Rgb(0, 114, 178),   // blue
    Rgb(213, 94, 0),    // vermillion
    Rgb(0, 158, 115),   // bluish green
    Rgb(204, 121, 167), // reddish purple
    Rgb(230, 159, 0),   // orange
    Rgb(86, 180, 233),  // sky blue
    Rgb(0, 0, 0),       // black
];

/// How an axis maps values to positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Scale {
    /// Evenly spaced values.
    #[default]
    Linear,
    /// Evenly spaced decades; non-positive values are not drawn.
    Log,
}

/// One axis: its label (with units), scale and optional fixed range.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// The label, with units in parentheses, e.g. `"wavevector q (1/m)"`.
    pub label: String,
    /// Linear or logarithmic.
    pub scale: Scale,
    /// `Some((lo, hi))` in data units fixes the range (`0 < lo` on a log
    /// axis); `None` fits the data with a little padding.
    pub range: Option<(f64, f64)>,
}

impl Axis {
    /// A linear axis with an automatic range.
    pub fn linear(label: impl Into<String>) -> Self {
        Axis {
            label: label.into(),
            scale: Scale::Linear,
            range: None,
        }
    }

    /// A logarithmic axis with an automatic range.
    pub fn log(label: impl Into<String>) -> Self {
        Axis {
            label: label.into(),
            scale: Scale::Log,
            range: None,
        }
    }

    /// The same axis with the range fixed to `[lo, hi]` (data units).
    ///
    /// The range is checked by [`render`]: finite, `lo < hi`, and `lo > 0` on a
    /// log axis.
    pub fn with_range(mut self, lo: f64, hi: f64) -> Self {
        self.range = Some((lo, hi));
        self
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Style {
    /// A solid line through the points.
    #[default]
    Line,
    /// A dashed line.
    Dashed,
    /// A dotted line.
    Dotted,
    /// A marker at each point, no line.
    Markers,
    /// A solid line with a marker at each point.
    LineMarkers,
}

/// One labelled curve or point set.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend text; an empty label leaves the series out of the legend.
    pub label: String,
    /// The `(x, y)` points in data units, in drawing order.
    pub points: Vec<(f64, f64)>,
    /// Line, dashes, dots or markers.
    pub style: Style,
    /// A fixed colour; `None` takes the next colour of [`PALETTE`].
    pub color: Option<Rgb>,
}

impl Series {
    /// A series with the given style and a palette colour.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Self {
        Series {
            label: label.into(),
            points,
            style,
            color: None,
        }
    }

    /// A solid line.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Style::Line)
    }

    /// A dashed line.
    pub fn dashed(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Style::Dashed)
    }

    /// Markers only.
    pub fn markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Style::Markers)
    }

    /// A solid line with markers.
    pub fn line_markers(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self::new(label, points, Style::LineMarkers)
    }

    /// A solid line through `(x[i], y[i])`.
    ///
    /// # Errors
    /// [`Error::Inconsistent`] when `x` and `y` differ in length.
    pub fn from_xy(label: impl Into<String>, x: &[f64], y: &[f64]) -> Result<Self> {
        let label = label.into();
        if x.len() != y.len() {
            return Err(Error::Inconsistent {
                name: format!("series \"{label}\""),
                requirement: format!(
                    "x and y must have the same length (x has {}, y has {})",
                    x.len(),
                    y.len()
                ),
            });
        }
        Ok(Self::line(
            label,
            x.iter().copied().zip(y.iter().copied()).collect(),
        ))
    }

    /// The same series drawn in `style`.
    pub fn with_style(mut self, style: Style) -> Self {
        self.style = style;
        self
    }

    /// The same series in a fixed colour (it then takes no palette slot).
    pub fn with_color(mut self, color: Rgb) -> Self {
        self.color = Some(color);
        self
    }
}

/// Where the legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LegendPosition {
    /// The corner (or edge middle) of the plot that covers the fewest data.
    #[default]
    Auto,
    /// Upper left corner.
    UpperLeft,
    /// Upper right corner.
    UpperRight,
    /// Lower left corner.
    LowerLeft,
    /// Lower right corner.
    LowerRight,
    /// No legend.
    Hidden,
}

/// A complete figure: title, axes, series, size and legend placement.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// The caption above the plot; empty for none.
    pub title: String,
    /// The horizontal axis.
    pub x: Axis,
    /// The vertical axis.
    pub y: Axis,
    /// The curves, drawn in order (later ones on top).
    pub series: Vec<Series>,
    /// Width × height in pixels (SVG user units), each in [`SIZE_LIMITS`].
    pub size: (u32, u32),
    /// Legend placement.
    pub legend: LegendPosition,
}

impl Figure {
    /// An empty figure of [`DEFAULT_SIZE`] with an automatic legend.
    pub fn new(title: impl Into<String>, x: Axis, y: Axis) -> Self {
        Figure {
            title: title.into(),
            x,
            y,
            series: Vec::new(),
            size: DEFAULT_SIZE,
            legend: LegendPosition::Auto,
        }
    }

    /// The same figure with one more series.
    pub fn with_series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Adds a series.
    pub fn push(&mut self, series: Series) {
        self.series.push(series);
    }
}

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

impl Encode for Figure {
    fn encode(&self, path: &Path) -> Result<Vec<u8>> {
        let format = Format::from_path(path)?;
        draw::ensure_font(path)?;
        match format {
            Format::Svg => {
                let prepared = prepare::prepare(self, 1, &draw::measure)?;
                let svg = draw::svg_string(&prepared).map_err(|e| backend_error(path, e))?;
                Ok(svg.into_bytes())
            }
            Format::Png => {
                // Drawn at k× the size (fonts and lines scale along) and
                // averaged down: anti-aliased lines and text.
                let k = draw::supersampling(self.size);
                let big = (self.size.0 * k, self.size.1 * k);
                let prepared = prepare::prepare(self, k, &draw::measure)?;
                let pixels = draw::rgb_pixels(&prepared).map_err(|e| backend_error(path, e))?;
                let pixels = draw::downsample(&pixels, big, k);
                draw::png_bytes(self.size, &pixels).map_err(|source| Error::Io {
                    path: path.to_path_buf(),
                    source,
                })
            }
        }
    }
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
/// As [`render`], except the file errors.
pub fn render_svg_string(fig: &Figure) -> Result<String> {
    let here = Path::new("<svg string>");
    draw::ensure_font(here)?;
    let prepared = prepare::prepare(fig, 1, &draw::measure)?;
    draw::svg_string(&prepared).map_err(|e| backend_error(here, e))
}

fn backend_error(path: &Path, message: String) -> Error {
    Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(format!("plot rendering failed: {message}")),
    }
}

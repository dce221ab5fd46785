//! A figure as plain data: axes, series, styles and the legend's place.

use crate::{Error, Result};

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
    /// The range is checked by [`super::render`]: finite, `lo < hi`, and `lo > 0` on a
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

/// The positive (x, y) pairs of a curve: a log axis has no room for zero
/// (a sealed load's Q = 0 is in the table, not on the figure).
pub(crate) fn positive(points: impl Iterator<Item = (f64, Option<f64>)>) -> Vec<(f64, f64)> {
    points
        .filter_map(|(x, y)| y.map(|y| (x, y)))
        .filter(|&(x, y)| x > 0.0 && y > 0.0 && y.is_finite())
        .collect()
}

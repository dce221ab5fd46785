//! From a [`Figure`] to drawable data: log transform, ranges, ticks, clipping,
//! colours and the pixel layout. Independent of the plotting library.

use super::ticks::{self, Tick, Ticks};
use crate::plot::{Figure, LegendPosition, Rgb, Scale, Style, PALETTE, SIZE_LIMITS};
use crate::{Error, Result};

/// Text measurement: `(text, font size px) → (width, height)` in pixels.
pub(crate) type Measure = dyn Fn(&str, f64) -> (f64, f64);

/// Relative padding added on each side of an automatic range.
const PAD: f64 = 0.04;

/// Minimum gap between neighbouring tick labels, in pixels.
const LABEL_GAP: f64 = 14.0;

/// Smallest scale of fonts and lines, so that text stays readable (13 px
/// tick labels) in figures smaller than 800 × 560.
const MIN_SCALE: f64 = 0.75;

/// Font sizes and margins (pixels) for the default 800 × 560 figure; other
/// sizes scale them by `min(w/800, h/560)`, at least [`MIN_SCALE`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Layout {
    pub caption_font: f64,
    pub tick_font: f64,
    pub desc_font: f64,
    pub legend_font: f64,
    pub line_width: u32,
    /// Axis, frame and grid line width.
    pub thin: u32,
    /// Width of the legend's line sample.
    pub legend_glyph: u32,
    /// Padding inside the legend box.
    pub legend_margin: u32,
    pub marker_size: u32,
    pub tick_size: i32,
    /// top, right, bottom, left
    pub margin: [u32; 4],
    pub x_area: u32,
    pub y_area: u32,
}

impl Layout {
    /// The layout of a figure of `size` pixels drawn `k` times larger.
    fn new(size: (u32, u32), k: u32) -> Self {
        let s = (size.0 as f64 / 800.0)
            .min(size.1 as f64 / 560.0)
            .max(MIN_SCALE)
            * k as f64;
        let px = |v: f64| (v * s).round();
        let tick_font = px(17.0);
        let desc_font = px(19.0);
        Layout {
            caption_font: px(23.0),
            tick_font,
            desc_font,
            legend_font: px(16.0),
            line_width: px(2.5).max(1.0) as u32,
            thin: px(1.0).max(1.0) as u32,
            legend_glyph: px(40.0) as u32,
            legend_margin: px(9.0) as u32,
            marker_size: px(4.0).max(2.0) as u32,
            tick_size: px(6.0) as i32,
            margin: [
                px(12.0) as u32,
                px(30.0) as u32,
                px(8.0) as u32,
                px(10.0) as u32,
            ],
            x_area: (tick_font * 1.2 + desc_font * 1.2 + px(18.0)).round() as u32,
            y_area: 0, // depends on the y tick labels
        }
    }
}

/// An axis ready to draw: range and ticks in plot coordinates.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PlotAxis {
    pub label: String,
    pub lo: f64,
    pub hi: f64,
    pub ticks: Ticks,
}

impl PlotAxis {
    /// The label of the tick nearest to `pos` (the plotting library asks
    /// for labels by position).
    pub(crate) fn label_at(&self, pos: f64) -> String {
        let tol = 1e-9 * (self.hi - self.lo);
        self.ticks
            .major
            .iter()
            .find(|t| (t.pos - pos).abs() <= tol)
            .map(|t| t.label.clone())
            .unwrap_or_default()
    }
}

/// A series ready to draw, in plot coordinates, clipped to the plot.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PlotSeries {
    pub label: String,
    /// Connected pieces of the line (broken at dropped points and at the
    /// plot border).
    pub runs: Vec<Vec<(f64, f64)>>,
    /// The data points inside the plot (for markers).
    pub points: Vec<(f64, f64)>,
    pub style: Style,
    pub color: Rgb,
    /// Index into the marker shapes.
    pub marker: usize,
}

/// Everything the drawing code needs.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Prepared {
    pub title: String,
    pub size: (u32, u32),
    pub x: PlotAxis,
    pub y: PlotAxis,
    pub series: Vec<PlotSeries>,
    pub legend: LegendPosition,
    pub layout: Layout,
}

/// Checks `fig` and computes ranges, ticks, clipped runs, colours and layout.
///
/// # Errors
/// See [`crate::plot::render`].
/// The figure is laid out `k` times larger than its size (supersampling);
/// fonts and lines scale along.
pub(crate) fn prepare(fig: &Figure, k: u32, measure: &Measure) -> Result<Prepared> {
    check_size(fig.size)?;
    let size = (fig.size.0 * k, fig.size.1 * k);
    let xs = fig.x.scale;
    let ys = fig.y.scale;
    // Transformed points, None where a value cannot be drawn.
    let transformed: Vec<Vec<Option<(f64, f64)>>> = fig
        .series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .map(|&(x, y)| Some((to_plot(x, xs)?, to_plot(y, ys)?)))
                .collect()
        })
        .collect();
    let all = || transformed.iter().flatten().flatten().copied();
    if all().next().is_none() {
        return Err(Error::Inconsistent {
            name: format!("figure \"{}\"", fig.title),
            requirement: "at least one point must be drawable (finite, and positive on a log axis)"
                .into(),
        });
    }

    let (x_lo, x_hi) = match fig.x.range {
        Some(r) => fixed_range("x range", r, xs)?,
        None => auto_range(all().map(|p| p.0), xs),
    };
    let (y_lo, y_hi) = match fig.y.range {
        Some(r) => fixed_range("y range", r, ys)?,
        None => {
            let inside = |p: &(f64, f64)| p.0 >= x_lo && p.0 <= x_hi;
            if all().any(|p| inside(&p)) {
                auto_range(all().filter(inside).map(|p| p.1), ys)
            } else {
                auto_range(all().map(|p| p.1), ys)
            }
        }
    };
    let rect = Rect {
        x0: x_lo,
        x1: x_hi,
        y0: y_lo,
        y1: y_hi,
    };

    let mut layout = Layout::new(fig.size, k);
    let (w, h) = (size.0 as f64, size.1 as f64);
    let caption = if fig.title.is_empty() {
        0.0
    } else {
        layout.caption_font * 1.6
    };
    let y_len = h - caption - layout.x_area as f64 - (layout.margin[0] + layout.margin[2]) as f64;
    let tick_font = layout.tick_font;
    let y_fits = |t: &[Tick]| {
        let height = measure("0", tick_font).1.max(tick_font * 0.8);
        spaced(t, y_lo, y_hi, y_len, &|_| height + 0.6 * LABEL_GAP)
    };
    let y_ticks = choose_ticks(y_lo, y_hi, ys, &y_fits);
    let widest = y_ticks
        .major
        .iter()
        .map(|t| measure(&t.label, tick_font).0)
        .fold(0.0, f64::max);
    layout.y_area =
        (widest + 2.0 * layout.tick_size as f64 + layout.desc_font * 1.4 + 10.0).round() as u32;
    let x_len = w - layout.y_area as f64 - (layout.margin[1] + layout.margin[3]) as f64;
    let x_fits = |t: &[Tick]| {
        spaced(t, x_lo, x_hi, x_len, &|label: &str| {
            measure(label, tick_font).0 + LABEL_GAP
        })
    };
    let x_ticks = choose_ticks(x_lo, x_hi, xs, &x_fits);

    let series = plot_series(fig, &transformed, &rect);

    Ok(Prepared {
        title: fig.title.clone(),
        size,
        x: PlotAxis {
            label: fig.x.label.clone(),
            lo: x_lo,
            hi: x_hi,
            ticks: x_ticks,
        },
        y: PlotAxis {
            label: fig.y.label.clone(),
            lo: y_lo,
            hi: y_hi,
            ticks: y_ticks,
        },
        series,
        legend: fig.legend,
        layout,
    })
}

/// Each series' colour, marker, clipped runs and the points inside `rect`.
fn plot_series(
    fig: &Figure,
    transformed: &[Vec<Option<(f64, f64)>>],
    rect: &Rect,
) -> Vec<PlotSeries> {
    let mut palette = PALETTE.iter().cycle();
    let mut markers = 0..;
    fig.series
        .iter()
        .zip(transformed)
        .map(|(s, pts)| {
            let color = s
                .color
                .unwrap_or_else(|| *palette.next().unwrap_or(&PALETTE[0]));
            let marker = match s.style {
                Style::Markers | Style::LineMarkers => markers.next().unwrap_or(0),
                _ => 0,
            };
            PlotSeries {
                label: s.label.clone(),
                runs: clip_runs(pts, rect),
                points: pts
                    .iter()
                    .flatten()
                    .copied()
                    .filter(|&p| rect.contains(p))
                    .collect(),
                style: s.style,
                color,
                marker,
            }
        })
        .collect()
}

fn check_size((w, h): (u32, u32)) -> Result<()> {
    let (min, max) = SIZE_LIMITS;
    let requirement = format!("between {min} and {max} pixels");
    if !(min..=max).contains(&w) {
        return Err(Error::invalid("figure width", w as f64, requirement));
    }
    if !(min..=max).contains(&h) {
        return Err(Error::invalid("figure height", h as f64, requirement));
    }
    Ok(())
}

/// The plot coordinate of a data value: itself, or log10 on a log axis;
/// `None` when it cannot be drawn.
fn to_plot(v: f64, scale: Scale) -> Option<f64> {
    match scale {
        Scale::Linear => v.is_finite().then_some(v),
        Scale::Log => (v.is_finite() && v > 0.0).then(|| v.log10()),
    }
}

/// A user range checked and moved to plot coordinates.
fn fixed_range(name: &str, (lo, hi): (f64, f64), scale: Scale) -> Result<(f64, f64)> {
    if !lo.is_finite() || (scale == Scale::Log && lo <= 0.0) {
        let req = match scale {
            Scale::Log => "finite and > 0 on a log axis",
            Scale::Linear => "finite",
        };
        return Err(Error::invalid(format!("{name} lower bound"), lo, req));
    }
    if !hi.is_finite() || hi <= lo {
        return Err(Error::invalid(
            format!("{name} upper bound"),
            hi,
            format!("finite and > the lower bound {lo:e}"),
        ));
    }
    match scale {
        Scale::Linear => Ok((lo, hi)),
        Scale::Log => Ok((lo.log10(), hi.log10())),
    }
}

/// The extent of `values` (plot coordinates, at least one) plus padding.
///
/// On a linear axis a range that starts (ends) at or near zero is anchored
/// at zero. A single value gets ±½ decade (log) or ±10 % (linear).
fn auto_range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    let span = hi - lo;
    let tiny = 1e-9 * lo.abs().max(hi.abs());
    if span <= tiny || span == 0.0 {
        return match scale {
            Scale::Log => (lo - 0.5, hi + 0.5),
            Scale::Linear if lo == 0.0 && hi == 0.0 => (-1.0, 1.0),
            Scale::Linear => {
                let d = 0.1 * lo.abs().max(hi.abs());
                (lo - d, hi + d)
            }
        };
    }
    let pad = PAD * span;
    let (mut a, mut b) = (lo - pad, hi + pad);
    if scale == Scale::Linear {
        if lo >= 0.0 && a < 0.0 {
            a = 0.0;
        }
        if hi <= 0.0 && b > 0.0 {
            b = 0.0;
        }
    }
    (a, b)
}

fn choose_ticks(lo: f64, hi: f64, scale: Scale, fits: ticks::Fits) -> Ticks {
    match scale {
        Scale::Linear => ticks::linear(lo, hi, fits),
        Scale::Log => ticks::log(lo, hi, fits),
    }
}

/// Whether neighbouring labels are at least `room(label)` apart (half of
/// each label's room on either side) on an axis of `len` pixels.
fn spaced(t: &[Tick], lo: f64, hi: f64, len: f64, room: &dyn Fn(&str) -> f64) -> bool {
    let px = |p: f64| (p - lo) / (hi - lo) * len;
    t.windows(2).all(|w| {
        (px(w[1].pos) - px(w[0].pos)).abs() >= 0.5 * (room(&w[0].label) + room(&w[1].label))
    })
}

/// The plot rectangle in plot coordinates.
#[derive(Debug, Clone, Copy)]
struct Rect {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

impl Rect {
    fn contains(&self, (x, y): (f64, f64)) -> bool {
        x >= self.x0 && x <= self.x1 && y >= self.y0 && y <= self.y1
    }

    /// The part of the segment a→b inside the rectangle (Liang–Barsky).
    fn clip(&self, a: (f64, f64), b: (f64, f64)) -> Option<((f64, f64), (f64, f64))> {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [
            (-dx, a.0 - self.x0),
            (dx, self.x1 - a.0),
            (-dy, a.1 - self.y0),
            (dy, self.y1 - a.1),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        (t0 <= t1).then_some((
            (a.0 + t0 * dx, a.1 + t0 * dy),
            (a.0 + t1 * dx, a.1 + t1 * dy),
        ))
    }
}

/// Splits a polyline at undrawable points and clips it to the rectangle.
fn clip_runs(points: &[Option<(f64, f64)>], rect: &Rect) -> Vec<Vec<(f64, f64)>> {
    let mut runs = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    let mut flush = |run: &mut Vec<(f64, f64)>| {
        if run.len() >= 2 {
            runs.push(std::mem::take(run));
        } else {
            run.clear();
        }
    };
    for w in points.windows(2) {
        match (w[0], w[1]) {
            (Some(a), Some(b)) => match rect.clip(a, b) {
                Some((p, q)) => {
                    if run.last() != Some(&p) {
                        flush(&mut run);
                        run.push(p);
                    }
                    run.push(q);
                    if q != b {
                        flush(&mut run);
                    }
                }
                None => flush(&mut run),
            },
            _ => flush(&mut run),
        }
    }
    flush(&mut run);
    runs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::{Axis, Series};

    fn approx_measure(text: &str, size: f64) -> (f64, f64) {
        (0.6 * size * text.chars().count() as f64, size)
    }

    #[test]
    fn clipping_keeps_inside_parts_and_breaks_runs() {
        let rect = Rect {
            x0: 0.0,
            x1: 1.0,
            y0: 0.0,
            y1: 1.0,
        };
        let pts = [
            Some((-1.0, 0.5)),
            Some((0.5, 0.5)),
            Some((2.0, 0.5)),
            None,
            Some((0.2, 0.2)),
            Some((0.3, 0.3)),
        ];
        let runs = clip_runs(&pts, &rect);
        assert_eq!(
            runs,
            vec![
                vec![(0.0, 0.5), (0.5, 0.5), (1.0, 0.5)],
                vec![(0.2, 0.2), (0.3, 0.3)]
            ]
        );
    }

    #[test]
    fn non_positive_values_are_dropped_on_log_axes() {
        let fig = crate::plot::Figure::new("t", Axis::log("x"), Axis::log("y")).with_series(
            Series::line(
                "a",
                vec![(1.0, 1e-40), (10.0, 0.0), (100.0, -1.0), (1e3, 1e-38)],
            ),
        );
        let p = prepare(&fig, 1, &approx_measure).unwrap();
        assert!(p.series[0].runs.is_empty());
        assert_eq!(p.series[0].points.len(), 2);
        assert!(p.y.lo < -40.0 && p.y.hi > -38.0);
        assert!(p.y.ticks.major.iter().any(|t| t.label == "10⁻⁴⁰"));
    }

    #[test]
    fn auto_range_anchors_at_zero_and_pads() {
        assert_eq!(
            auto_range([0.0, 1.0].into_iter(), Scale::Linear),
            (0.0, 1.04)
        );
        let (a, b) = auto_range([-2.0, -1.0].into_iter(), Scale::Linear);
        assert!((a + 2.04).abs() < 1e-12 && (b + 0.96).abs() < 1e-12);
        assert_eq!(auto_range([3.0].into_iter(), Scale::Log), (2.5, 3.5));
        assert_eq!(auto_range([0.0].into_iter(), Scale::Linear), (-1.0, 1.0));
    }
}

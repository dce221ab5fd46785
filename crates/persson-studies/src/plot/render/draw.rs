//! The only code that talks to `plotters`.

use super::prepare::PlotAxis;
use super::prepare::{PlotSeries, Prepared};
use crate::plot::{LegendPosition, Rgb, Style};
use crate::{Error, Result};
use plotters::chart::SeriesAnno;
use plotters::coord::ranged1d::{KeyPointHint, NoDefaultFormatting, Ranged, ValueFormatter};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::ops::Range;
use std::path::Path;

use std::sync::OnceLock;

/// DejaVu Sans (Bitstream Vera licence, see assets/DejaVuSans-LICENSE.txt).
static FONT: &[u8] = include_bytes!("../../../assets/DejaVuSans.ttf");

/// Outcome of the one-time font registration.
static FONT_OK: OnceLock<bool> = OnceLock::new();

/// The font family every text element uses.
const FAMILY: &str = "sans-serif";

/// Registers the bundled font with plotters (once per process).
///
/// # Errors
/// [`Error::Io`] naming `path` if the bundled font cannot be parsed (a
/// packaging bug).
pub(crate) fn ensure_font(path: &Path) -> Result<()> {
    let ok = *FONT_OK
        .get_or_init(|| plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err(Error::Io {
            path: path.to_path_buf(),
            source: std::io::Error::other("the bundled font assets/DejaVuSans.ttf is invalid"),
        })
    }
}

/// Width and height in pixels of `text` at `size` px in the bundled font
/// (a character-count estimate if the font is unavailable).
pub(crate) fn measure(text: &str, size: f64) -> (f64, f64) {
    match (FAMILY, size).into_font().box_size(text) {
        Ok((w, h)) => (w as f64, h as f64),
        Err(_) => (0.6 * size * text.chars().count() as f64, size),
    }
}

/// The figure as an SVG document.
pub(crate) fn svg_string(p: &Prepared) -> std::result::Result<String, String> {
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, p.size).into_drawing_area();
        draw(root, p).map_err(|e| e.to_string())?;
    }
    Ok(s)
}

/// Supersampling factor for PNG output: 3 (9 samples per pixel), less for
/// figures so large that the supersampled buffer would exceed 16 megapixels.
pub(crate) fn supersampling(size: (u32, u32)) -> u32 {
    let pixels = size.0 as u64 * size.1 as u64;
    (1..=3u32)
        .rev()
        .find(|&k| pixels * (k * k) as u64 <= 16_000_000)
        .unwrap_or(1)
}

/// The figure rasterised as 8-bit RGB rows (`p.size` pixels).
pub(crate) fn rgb_pixels(p: &Prepared) -> std::result::Result<Vec<u8>, String> {
    let mut buf = vec![255u8; p.size.0 as usize * p.size.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, p.size).into_drawing_area();
        draw(root, p).map_err(|e| e.to_string())?;
    }
    Ok(buf)
}

/// Averages `k × k` blocks of an RGB image of `size` pixels (anti-aliasing
/// by supersampling); `size` must be divisible by `k`.
pub(crate) fn downsample(rgb: &[u8], size: (u32, u32), k: u32) -> Vec<u8> {
    if k == 1 {
        return rgb.to_vec();
    }
    let (w, h, k) = (size.0 as usize, size.1 as usize, k as usize);
    let (sw, sh) = (w / k, h / k);
    let mut out = vec![0u8; sw * sh * 3];
    for y in 0..sh {
        for x in 0..sw {
            for c in 0..3 {
                let mut sum = 0u32;
                for dy in 0..k {
                    let row = (y * k + dy) * w;
                    for dx in 0..k {
                        sum += rgb[(row + x * k + dx) * 3 + c] as u32;
                    }
                }
                let n = (k * k) as u32;
                out[(y * sw + x) * 3 + c] = ((sum + n / 2) / n) as u8;
            }
        }
    }
    out
}

/// 8-bit RGB rows of `size` pixels encoded as a PNG file's bytes.
pub(crate) fn png_bytes(size: (u32, u32), rgb: &[u8]) -> std::io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, size.0, size.1);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    // Adaptive row filters: about 7x smaller files than the default for
    // these plots (~40 instead of ~260 KiB at 800 × 560, measured).
    encoder.set_compression(png::Compression::Default);
    encoder.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
    writer
        .write_image_data(rgb)
        .map_err(std::io::Error::other)?;
    writer.finish().map_err(std::io::Error::other)?;
    Ok(bytes)
}

fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

type DrawResult<DB> =
    std::result::Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// Draws the prepared figure on any backend.
fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, p: &Prepared) -> DrawResult<DB> {
    let l = &p.layout;
    root.fill(&WHITE)?;
    let mut builder = ChartBuilder::on(&root);
    builder
        .margin_top(l.margin[0])
        .margin_right(l.margin[1])
        .margin_bottom(l.margin[2])
        .margin_left(l.margin[3])
        .x_label_area_size(l.x_area)
        .y_label_area_size(l.y_area);
    if !p.title.is_empty() {
        builder.caption(&p.title, (FAMILY, l.caption_font));
    }
    let mut chart = builder.build_cartesian_2d(TickAxis(&p.x), TickAxis(&p.y))?;
    chart
        .configure_mesh()
        .x_desc(p.x.label.as_str())
        .y_desc(p.y.label.as_str())
        .label_style((FAMILY, l.tick_font))
        .axis_desc_style((FAMILY, l.desc_font))
        .bold_line_style(RGBColor(205, 205, 205).stroke_width(l.thin))
        .light_line_style(RGBColor(238, 238, 238).stroke_width(l.thin))
        .axis_style(BLACK.stroke_width(l.thin))
        .set_all_tick_mark_size(l.tick_size)
        .draw()?;

    let width = l.line_width;
    let msize = l.marker_size as i32;
    for s in &p.series {
        let style = rgb(s.color).stroke_width(width);
        let mut anno = None;
        if matches!(s.style, Style::Line | Style::LineMarkers) {
            for run in &s.runs {
                anno = Some(chart.draw_series(LineSeries::new(run.iter().copied(), style))?);
            }
        }
        if matches!(s.style, Style::Dashed | Style::Dotted) {
            let (dash, gap) = dash_pattern(s.style, width);
            for run in &s.runs {
                anno = Some(chart.draw_series(DashedLineSeries::new(
                    run.iter().copied(),
                    dash,
                    gap,
                    style,
                ))?);
            }
        }
        if matches!(s.style, Style::Markers | Style::LineMarkers) {
            anno = Some(draw_markers(&mut chart, s, msize, width)?);
        }
        if s.label.is_empty() {
            continue;
        }
        // A series with nothing visible still gets its legend entry.
        let anno = match anno {
            Some(a) => a,
            None => chart.draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?,
        };
        anno.label(s.label.as_str());
        set_legend_glyph(anno, s, width, msize, l.legend_glyph);
    }

    // A frame around the plot.
    chart.plotting_area().draw(&Rectangle::new(
        [(p.x.lo, p.y.lo), (p.x.hi, p.y.hi)],
        BLACK.stroke_width(l.thin),
    ))?;

    let labelled: Vec<&PlotSeries> = p.series.iter().filter(|s| !s.label.is_empty()).collect();
    if !labelled.is_empty() && p.legend != LegendPosition::Hidden {
        let position = legend_position(&chart, p, &labelled);
        chart
            .configure_series_labels()
            .position(position)
            .label_font((FAMILY, l.legend_font))
            .legend_area_size(l.legend_glyph)
            .margin(l.legend_margin)
            .background_style(WHITE.mix(0.88))
            .border_style(RGBColor(140, 140, 140))
            .draw()?;
    }
    root.present()?;
    Ok(())
}

/// A linear plotters coordinate over a prepared axis, with its own ticks and
/// labels (log axes arrive here already in log10).
#[derive(Clone)]
struct TickAxis<'a>(&'a PlotAxis);

impl Ranged for TickAxis<'_> {
    type FormatOption = NoDefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.0.lo) / (self.0.hi - self.0.lo);
        let px = limit.0 as f64 + t * (limit.1 - limit.0) as f64;
        px.round().clamp(-1e9, 1e9) as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.0.ticks.minor.clone()
        } else {
            self.0.ticks.major.iter().map(|t| t.pos).collect()
        }
    }

    fn range(&self) -> Range<f64> {
        self.0.lo..self.0.hi
    }
}

impl ValueFormatter<f64> for TickAxis<'_> {
    fn format_ext(&self, value: &f64) -> String {
        self.0.label_at(*value)
    }
}

/// Dash length and gap for dashed and dotted lines of stroke `width`.
fn dash_pattern(style: Style, width: u32) -> (i32, i32) {
    let w = width as i32;
    match style {
        Style::Dotted => ((w * 6 / 5).max(1), (w * 5 / 2).max(2)),
        _ => (6 * w + 1, 4 * w),
    }
}

/// Draws the markers of `s`: circle, square, triangle or cross by `s.marker`.
fn draw_markers<'a, 'c, DB: DrawingBackend + 'a>(
    chart: &'c mut ChartContext<'a, DB, Cartesian2d<TickAxis<'a>, TickAxis<'a>>>,
    s: &PlotSeries,
    size: i32,
    width: u32,
) -> std::result::Result<&'c mut SeriesAnno<'a, DB>, DrawingAreaErrorKind<DB::ErrorType>> {
    let color = rgb(s.color);
    let fill = color.filled();
    let pts = s.points.iter().copied();
    match s.marker % 4 {
        0 => chart.draw_series(pts.map(|p| Circle::new(p, size, fill))),
        1 => {
            chart.draw_series(pts.map(|p| {
                EmptyElement::at(p) + Rectangle::new([(-size, -size), (size, size)], fill)
            }))
        }
        2 => chart.draw_series(pts.map(|p| TriangleMarker::new(p, size + 1, fill))),
        _ => chart.draw_series(pts.map(|p| Cross::new(p, size, color.stroke_width(width)))),
    }
}

/// The legend sample of a series: a line piece and/or its marker.
fn set_legend_glyph<'a, DB: DrawingBackend + 'a>(
    anno: &mut SeriesAnno<'a, DB>,
    s: &PlotSeries,
    width: u32,
    msize: i32,
    glyph: u32,
) {
    let color = rgb(s.color);
    let fill = color.filled();
    let line = color.stroke_width(width);
    let len = glyph as i32 * 4 / 5;
    let half = len / 2;
    match s.style {
        Style::Line => {
            anno.legend(move |(x, y)| PathElement::new(vec![(x, y), (x + len, y)], line));
        }
        Style::Dashed | Style::Dotted => {
            let (dash, gap) = dash_pattern(s.style, width);
            anno.legend(move |(x, y)| {
                DashedPathElement::new(vec![(x, y), (x + len, y)], dash, gap, line)
            });
        }
        Style::Markers | Style::LineMarkers => {
            let line = if s.style == Style::LineMarkers {
                line
            } else {
                TRANSPARENT.stroke_width(0)
            };
            let path = move || PathElement::new(vec![(-half, 0), (half, 0)], line);
            match s.marker % 4 {
                0 => anno.legend(move |(x, y)| {
                    EmptyElement::at((x + half, y)) + path() + Circle::new((0, 0), msize, fill)
                }),
                1 => anno.legend(move |(x, y)| {
                    EmptyElement::at((x + half, y))
                        + path()
                        + Rectangle::new([(-msize, -msize), (msize, msize)], fill)
                }),
                2 => anno.legend(move |(x, y)| {
                    EmptyElement::at((x + half, y))
                        + path()
                        + TriangleMarker::new((0, 0), msize + 1, fill)
                }),
                _ => anno.legend(move |(x, y)| {
                    EmptyElement::at((x + half, y))
                        + path()
                        + Cross::new((0, 0), msize, color.stroke_width(width))
                }),
            };
        }
    }
}

/// The legend corner that covers the fewest data, or the requested one.
fn legend_position<DB: DrawingBackend, X, Y>(
    chart: &ChartContext<DB, Cartesian2d<X, Y>>,
    p: &Prepared,
    labelled: &[&PlotSeries],
) -> SeriesLabelPosition
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    use SeriesLabelPosition::*;
    let fixed = match p.legend {
        LegendPosition::UpperLeft => Some(UpperLeft),
        LegendPosition::UpperRight => Some(UpperRight),
        LegendPosition::LowerLeft => Some(LowerLeft),
        LegendPosition::LowerRight => Some(LowerRight),
        LegendPosition::Auto | LegendPosition::Hidden => None,
    };
    if let Some(f) = fixed {
        return f;
    }
    let l = &p.layout;
    let (w, h) = chart.plotting_area().dim_in_pixel();
    let (w, h) = (w as i32, h as i32);
    let (bx, by) = chart.plotting_area().get_base_pixel();
    let text_w = labelled
        .iter()
        .map(|s| super::draw::measure(&s.label, l.legend_font).0)
        .fold(0.0, f64::max);
    let box_w = text_w as i32 + (l.legend_glyph + 2 * l.legend_margin) as i32;
    let n = labelled.len() as f64;
    let box_h =
        ((n - 1.0) * 1.25 * l.legend_font + l.legend_font + 2.0 * l.legend_margin as f64) as i32;
    // Data sampled every few pixels along each drawn line, plus the points.
    let mut samples: Vec<(i32, i32)> = Vec::new();
    for s in &p.series {
        for pt in &s.points {
            let (x, y) = chart.backend_coord(pt);
            samples.push((x - bx, y - by));
        }
        if matches!(s.style, Style::Markers) {
            continue;
        }
        for run in &s.runs {
            for seg in run.windows(2) {
                let (a, b) = (chart.backend_coord(&seg[0]), chart.backend_coord(&seg[1]));
                let d = ((b.0 - a.0).abs().max((b.1 - a.1).abs()) / 3).clamp(1, 2000);
                for i in 0..=d {
                    let t = i as f64 / d as f64;
                    let x = a.0 as f64 + t * (b.0 - a.0) as f64;
                    let y = a.1 as f64 + t * (b.1 - a.1) as f64;
                    samples.push((x as i32 - bx, y as i32 - by));
                }
            }
        }
    }
    let inset = 5;
    let candidates = [
        (UpperRight, (w - box_w - inset, inset)),
        (UpperLeft, (inset, inset)),
        (LowerRight, (w - box_w - inset, h - box_h - inset)),
        (LowerLeft, (inset, h - box_h - inset)),
        (MiddleRight, (w - box_w - inset, (h - box_h) / 2)),
        (UpperMiddle, ((w - box_w) / 2, inset)),
        (LowerMiddle, ((w - box_w) / 2, h - box_h - inset)),
        (MiddleLeft, (inset, (h - box_h) / 2)),
    ];
    let covered = |(x0, y0): (i32, i32)| {
        let pad = 4;
        samples
            .iter()
            .filter(|&&(x, y)| {
                x >= x0 - pad && x <= x0 + box_w + pad && y >= y0 - pad && y <= y0 + box_h + pad
            })
            .count()
    };
    candidates
        .into_iter()
        .map(|(pos, at)| (covered(at), pos))
        .min_by_key(|(c, _)| *c)
        .map(|(_, pos)| pos)
        .unwrap_or(UpperRight)
}

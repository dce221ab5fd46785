//! Drawing the pressure map and its histogram ([`MapFigure`]) on a plotters backend.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::DrawResult;
use crate::plot::map::{tick, MapFigure, MAP_CELLS, PRESSURE_LABEL};
use crate::{Error, Result};

/// Colour of the nodes without contact.
const NO_CONTACT: RGBColor = RGBColor(225, 225, 225);

/// Colour of the nodes at the yield stress (and of the plastic peak).
const PLASTIC: RGBColor = RGBColor(214, 39, 40);

/// Colour of the histogram's bars.
const BARS: RGBColor = RGBColor(0, 114, 178);

/// Viridis at 0, ¼, ½, ¾, 1 (interpolated linearly between).
const VIRIDIS: [(u8, u8, u8); 5] = [
    (68, 1, 84),
    (59, 82, 139),
    (33, 145, 140),
    (94, 201, 98),
    (253, 231, 37),
];

/// Viridis at `t` in [0, 1].
pub(super) fn viridis(t: f64) -> RGBColor {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = t * 4.0;
    let i = (x.floor() as usize).min(3);
    let f = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |u: u8, v: u8| (u as f64 + f * (v as f64 - u as f64)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

pub(super) fn font(size: f64, k: u32) -> FontDesc<'static> {
    ("sans-serif", size * k as f64).into_font()
}

/// Draws the figure on any backend at `k` times its size: the map, its
/// colour bar and the histogram side by side.
fn draw_map<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    f: &MapFigure,
    k: u32,
) -> DrawResult<DB> {
    let px = |v: u32| v * k;
    root.fill(&WHITE)?;
    let root = root
        .margin(px(8), 0, 0, 0)
        .titled(&f.title, font(17.0, k))?;
    let (w, h) = root.dim_in_pixel();
    // A square map: its plotting area is as wide as it is high.
    let side = h.saturating_sub(px(45 + 20));
    let map_w = (side + px(70 + 20)).min(w / 2);
    let (map_area, rest) = root.split_horizontally(map_w);
    let (bar_area, right) = rest.split_horizontally(px(110));
    let p_max = f
        .pressure
        .iter()
        .copied()
        .filter(|p| p.is_finite())
        .fold(0.0, f64::max);
    // The top of the colour scale: σY, or the largest pressure.
    let top = f
        .yield_stress
        .unwrap_or(p_max)
        .max(p_max)
        .max(f64::MIN_POSITIVE);
    draw_pressure_map(&map_area, f, k, top)?;
    draw_colour_bar(&bar_area, f, k, top)?;
    draw_histogram(&right, f, k, top)
}

/// The pressure map: one cell per node (or block), viridis up to `top`,
/// no contact in grey, plastic nodes in red.
fn draw_pressure_map<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &MapFigure,
    k: u32,
    top: f64,
) -> DrawResult<DB> {
    let px = |v: u32| v * k;
    let (m, mean, plastic) = f.cells();
    let l = f.side;
    let mut chart = ChartBuilder::on(area)
        .margin(px(10))
        .x_label_area_size(px(45))
        .y_label_area_size(px(70))
        .build_cartesian_2d(0.0..l, 0.0..l)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(format!("x ({})", f.length_unit))
        .y_desc(format!("y ({})", f.length_unit))
        .label_style(font(12.0, k))
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .axis_desc_style(font(14.0, k))
        .x_labels(5)
        .y_labels(5)
        .draw()?;
    let d = l / m as f64;
    chart.draw_series((0..m * m).map(|c| {
        let (i, j) = (c / m, c % m);
        let colour = if plastic[c] {
            PLASTIC
        } else if mean[c] <= 0.0 {
            NO_CONTACT
        } else {
            viridis(mean[c] / top)
        };
        let (x0, y0) = (j as f64 * d, i as f64 * d);
        Rectangle::new([(x0, y0), (x0 + d, y0 + d)], colour.filled())
    }))?;
    Ok(())
}

/// The colour bar from 0 to `top`, with the plastic colour as a band at σY.
fn draw_colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &MapFigure,
    k: u32,
    top: f64,
) -> DrawResult<DB> {
    let label = format!("{PRESSURE_LABEL} ({})", f.pressure_unit);
    let mut bar = colour_bar(area, (0.0, top), &label, 80, k)?;
    if let Some(y) = f.yield_stress {
        let band = 0.03 * top;
        bar.draw_series(std::iter::once(Rectangle::new(
            [(0.0, (y - band).max(0.0)), (1.0, y)],
            PLASTIC.filled(),
        )))?;
    }
    Ok(())
}

/// A colour bar's chart: x in [0, 1], y the value.
pub(super) type BarChart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// The chart of a vertical viridis scale from `lo` to `hi` labelled `label`
/// (`label_area` pixels for the tick labels and the label), at `k` times the
/// figure's size; the caller may draw more on it.
pub(super) fn colour_bar<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    (lo, hi): (f64, f64),
    label: &str,
    label_area: u32,
    k: u32,
) -> std::result::Result<BarChart<'a, DB>, DrawingAreaErrorKind<DB::ErrorType>> {
    let px = |v: u32| v * k;
    let mut bar = ChartBuilder::on(area)
        .margin_top(px(10))
        .margin_bottom(px(55))
        .margin_right(px(5))
        .y_label_area_size(px(label_area))
        .build_cartesian_2d(0.0..1.0, lo..hi)?;
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(label)
        .label_style(font(12.0, k))
        .y_label_formatter(&|v| tick(*v))
        .axis_desc_style(font(14.0, k))
        .y_labels(6)
        .draw()?;
    let steps = 100;
    bar.draw_series((0..steps).map(|s| {
        let (a, b) = (s as f64 / steps as f64, (s + 1) as f64 / steps as f64);
        Rectangle::new(
            [(0.0, lo + a * (hi - lo)), (1.0, lo + b * (hi - lo))],
            viridis(0.5 * (a + b)).filled(),
        )
    }))?;
    Ok(bar)
}

/// The histogram P(σ) with (σY) the plastic δ-peak as a full-height bar.
fn draw_histogram<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &MapFigure,
    k: u32,
    top: f64,
) -> DrawResult<DB> {
    let px = |v: u32| v * k;
    let x_max = f
        .bins
        .iter()
        .map(|b| b.1)
        .fold(f.yield_stress.unwrap_or(0.0), f64::max)
        .max(top);
    let d_max = f.bins.iter().map(|b| b.2).fold(0.0, f64::max);
    let y_max = if d_max > 0.0 { 1.15 * d_max } else { 1.0 };
    let mut hist = ChartBuilder::on(area)
        .margin(px(10))
        .margin_left(px(30))
        .margin_right(px(20))
        .x_label_area_size(px(45))
        .y_label_area_size(px(75))
        .build_cartesian_2d(0.0..1.05 * x_max, 0.0..y_max)?;
    hist.configure_mesh()
        .disable_mesh()
        .x_desc(format!("σ ({})", f.pressure_unit))
        .y_desc(format!("P(σ) (1/{})", f.pressure_unit))
        .label_style(font(12.0, k))
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .axis_desc_style(font(14.0, k))
        .x_labels(6)
        .y_labels(6)
        .draw()?;
    let elastic: f64 = f.bins.iter().map(|b| b.2 * (b.1 - b.0)).sum();
    let bars_label = match f.yield_stress {
        Some(_) => format!(
            "P(σ), σ < σY: A_el/A0 = {}",
            crate::table::number(elastic, 4)
        ),
        None => format!("P(σ): A/A0 = {}", crate::table::number(elastic, 4)),
    };
    hist.draw_series(
        f.bins
            .iter()
            .map(|&(lo, hi, p)| Rectangle::new([(lo, 0.0), (hi, p)], BARS.mix(0.7).filled())),
    )?
    .label(bars_label)
    .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 14, y + 5)], BARS.filled()));
    if let (Some(y), Some(pl)) = (f.yield_stress, f.plastic_fraction) {
        // A δ-peak has no height in P(σ): a full-height bar at σY.
        let w = 0.006 * x_max;
        hist.draw_series(std::iter::once(Rectangle::new(
            [(y - w, 0.0), (y + w, y_max)],
            PLASTIC.filled(),
        )))?
        .label(format!(
            "δ-peak at σY = {}: A_pl/A0 = {}",
            crate::table::number(y, 4),
            crate::table::number(pl, 4)
        ))
        .legend(move |(x, y)| Rectangle::new([(x + 5, y - 6), (x + 9, y + 6)], PLASTIC.filled()));
    }
    hist.configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font(font(13.0, k))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .draw()?;
    Ok(())
}

super::canvas::canvas_figure!(MapFigure, draw_map);

impl MapFigure {
    fn check(&self) -> Result<()> {
        let n = self.grid;
        if n == 0 || self.pressure.len() != n * n {
            return Err(Error::Inconsistent {
                name: "pressure map".into(),
                requirement: format!("N² = {} values, got {}", n * n, self.pressure.len()),
            });
        }
        if !(self.side.is_finite() && self.side > 0.0) {
            return Err(Error::invalid("size", self.side, "finite and > 0"));
        }
        Ok(())
    }

    /// The map in blocks: side in cells, block mean pressures, plastic flags.
    fn cells(&self) -> (usize, Vec<f64>, Vec<bool>) {
        let n = self.grid;
        let k = n.div_ceil(MAP_CELLS).max(1);
        let m = n.div_ceil(k);
        let mut mean = vec![0.0; m * m];
        let mut count = vec![0usize; m * m];
        let mut plastic = vec![0usize; m * m];
        let y = self.yield_stress.unwrap_or(f64::INFINITY);
        for i in 0..n {
            for j in 0..n {
                let c = (i / k) * m + j / k;
                let p = self.pressure[i * n + j];
                let p = if p.is_finite() { p } else { 0.0 };
                mean[c] += p;
                count[c] += 1;
                plastic[c] += usize::from(p >= y);
            }
        }
        let flags = plastic
            .iter()
            .zip(&count)
            .map(|(&p, &c)| 2 * p > c)
            .collect();
        for (v, &c) in mean.iter_mut().zip(&count) {
            *v /= c.max(1) as f64;
        }
        (m, mean, flags)
    }
}

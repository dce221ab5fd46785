//! Drawing the 2-D spectrum ([`SpectrumMapFigure`]) on a plotters backend.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::DrawResult;
use super::map::{colour_bar, font, viridis};
use crate::plot::map::{tick, MAP_CELLS};
use crate::plot::spectrum_map::SpectrumMapFigure;
use crate::{Error, Result};

/// Colour of cells without a positive C.
const EMPTY: RGBColor = RGBColor(225, 225, 225);

/// The colour scale `(bottom, top)` of log10 C: the [`LOW_QUANTILE`] of the
/// finite values and their maximum.
fn scale(v: &[f64]) -> (f64, f64) {
    let mut s: Vec<f64> = v.iter().copied().filter(|x| x.is_finite()).collect();
    if s.is_empty() {
        return (0.0, 1.0);
    }
    s.sort_by(f64::total_cmp);
    let lo = s[((s.len() - 1) as f64 * LOW_QUANTILE) as usize];
    let hi = s[s.len() - 1];
    if hi > lo {
        (lo, hi)
    } else {
        (lo - 0.5, lo + 0.5)
    }
}

fn draw_figure<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    f: &SpectrumMapFigure,
    k: u32,
) -> DrawResult<DB> {
    let px = |v: u32| v * k;
    root.fill(&WHITE)?;
    let root = root
        .margin(px(8), 0, 0, 0)
        .titled(&f.title, font(16.0, k))?;
    let (w, _) = root.dim_in_pixel();
    let (map_area, bar_area) = root.split_horizontally(w.saturating_sub(px(120)));
    let (mx, my, cells) = f.cells();
    let (lo, hi) = scale(&cells);
    let (nx, ny) = (f.qx.len(), f.qy.len());
    let (dqx, dqy) = (f.qx[1] - f.qx[0], f.qy[1] - f.qy[0]);
    let (x0, x1) = (f.qx[0] - 0.5 * dqx, f.qx[nx - 1] + 0.5 * dqx);
    let (y0, y1) = (f.qy[0] - 0.5 * dqy, f.qy[ny - 1] + 0.5 * dqy);
    let mut chart = ChartBuilder::on(&map_area)
        .margin(px(10))
        .x_label_area_size(px(45))
        .y_label_area_size(px(75))
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("q_x (1/m)")
        .y_desc("q_y (1/m)")
        .label_style(font(12.0, k))
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .axis_desc_style(font(14.0, k))
        .x_labels(5)
        .y_labels(5)
        .draw()?;
    let (bw, bh) = ((x1 - x0) / mx as f64, (y1 - y0) / my as f64);
    chart.draw_series((0..mx * my).map(|c| {
        let (j, i) = (c / mx, c % mx);
        let v = cells[c];
        let colour = if v.is_nan() {
            EMPTY
        } else {
            viridis((v - lo) / (hi - lo))
        };
        let (a, b) = (x0 + i as f64 * bw, y0 + j as f64 * bh);
        Rectangle::new([(a, b), (a + bw, b + bh)], colour.filled())
    }))?;
    if let Some(lay) = f.lay {
        // The lay through q = 0, to the edges of the plot.
        let (s, c) = lay.to_radians().sin_cos();
        // Clipped to the plot here: plotters clamps each coordinate of an
        // outside point on its own, which would turn the line.
        let reach = |dir: f64| {
            let along = |d: f64, lo: f64, hi: f64| {
                let d = d * dir;
                if d > 0.0 {
                    hi / d
                } else if d < 0.0 {
                    lo / d
                } else {
                    f64::INFINITY
                }
            };
            along(c, x0, x1).min(along(s, y0, y1))
        };
        let (tp, tn) = (reach(1.0), reach(-1.0));
        let white = WHITE.stroke_width(px(2));
        chart
            .draw_series(DashedLineSeries::new(
                [(-tn * c, -tn * s), (tp * c, tp * s)],
                px(8),
                px(5),
                white,
            ))?
            .label(format!("lay, {}° from x", crate::table::number(lay, 4)))
            .legend(move |(x, y)| {
                PathElement::new([(x, y), (x + 18 * k as i32, y)], BLACK.stroke_width(px(2)))
            });
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperLeft)
            .label_font(font(13.0, k))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.4))
            .draw()?;
    }
    colour_bar(&bar_area, (lo, hi), "log10 C (C in m⁴)", 80, k)?;
    Ok(())
}

super::canvas::canvas_figure!(SpectrumMapFigure, draw_figure);

/// The fraction of the positive values below the colour scale's bottom
/// (drawn in its lowest colour): one map's spectrum spans many decades,
/// most of them in a few noisy modes near the Nyquist corners.
const LOW_QUANTILE: f64 = 0.02;

impl SpectrumMapFigure {
    fn check(&self) -> Result<()> {
        let (nx, ny) = (self.qx.len(), self.qy.len());
        if nx < 2 || ny < 2 || self.c.len() != nx * ny {
            return Err(Error::Inconsistent {
                name: "2-D spectrum".into(),
                requirement: format!(
                    "qx.len() × qy.len() = {nx} × {ny} ≥ 2 × 2 values, got {}",
                    self.c.len()
                ),
            });
        }
        Ok(())
    }

    /// Blocks of k × k modes: columns, rows and the mean log10 C of each
    /// (NaN where no value is positive).
    fn cells(&self) -> (usize, usize, Vec<f64>) {
        let (nx, ny) = (self.qx.len(), self.qy.len());
        let k = nx.max(ny).div_ceil(MAP_CELLS).max(1);
        let (mx, my) = (nx.div_ceil(k), ny.div_ceil(k));
        let mut sum = vec![0.0; mx * my];
        let mut count = vec![0usize; mx * my];
        for j in 0..ny {
            for i in 0..nx {
                let v = self.c[j * nx + i];
                if v > 0.0 && v.is_finite() {
                    let c = (j / k) * mx + i / k;
                    sum[c] += v.log10();
                    count[c] += 1;
                }
            }
        }
        let mean = sum
            .iter()
            .zip(&count)
            .map(|(&s, &n)| if n > 0 { s / n as f64 } else { f64::NAN })
            .collect();
        (mx, my, mean)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::spectrum_map::SPECTRUM_MAP_SIZE;

    #[test]
    fn blocks_average_log10_and_skip_zeros() {
        // 4 × 4 values: one block per mode (no averaging), zero is empty.
        let c: Vec<f64> = (0..16)
            .map(|k| if k == 5 { 0.0 } else { 10f64.powi(k) })
            .collect();
        let f = SpectrumMapFigure {
            title: String::new(),
            qx: vec![-2.0, -1.0, 0.0, 1.0],
            qy: vec![-2.0, -1.0, 0.0, 1.0],
            c,
            lay: Some(30.0),
            size: SPECTRUM_MAP_SIZE,
        };
        let (mx, my, cells) = f.cells();
        assert_eq!((mx, my), (4, 4));
        assert!(cells[5].is_nan());
        assert!((cells[7] - 7.0).abs() < 1e-12);
        let (lo, hi) = scale(&cells);
        assert_eq!((lo, hi), (0.0, 15.0));
        let svg = crate::plot::render_svg_string(&f).unwrap();
        assert!(svg.contains("lay, 30° from x"), "the lay's legend");
    }
}

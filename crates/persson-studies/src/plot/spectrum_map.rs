//! The 2-D power spectrum of a height map as a colour map (`persson
//! anisotropy --plot`): log10 C(q_x, q_y) over the Fourier grid with a colour
//! bar, and the lay drawn as a line through q = 0.
//!
//! A surface with a lay varies slowly along it, so its power lies in a band
//! *across* the lay in the q-plane: the drawn line runs along the lay and
//! the bright band perpendicular to it. Like [`super::Figure`] a
//! [`SpectrumMapFigure`] is plain data, drawn by [`super::render`] into an
//! `.svg` or `.png` file (atomically) or by [`render_spectrum_map_svg_string`].
//!
//! Grids finer than [`super::map::MAP_CELLS`] per side are drawn in blocks,
//! each the mean of log10 C over its positive values (grey where none is).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{render_canvas_svg_string, Canvas, DrawResult};
use super::map::{colour_bar, font, tick, viridis, MAP_CELLS};
use crate::{Error, Result};

/// Default size in pixels, width × height.
pub const SPECTRUM_MAP_SIZE: (u32, u32) = (760, 620);

/// The fraction of the positive values below the colour scale's bottom
/// (drawn in its lowest colour): one map's spectrum spans many decades,
/// most of them in a few noisy modes near the Nyquist corners.
const LOW_QUANTILE: f64 = 0.02;

/// Colour of cells without a positive C.
const EMPTY: RGBColor = RGBColor(225, 225, 225);

/// A 2-D spectrum as plain data.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumMapFigure {
    /// Title over the figure.
    pub title: String,
    /// q_x of the columns, increasing, 1/m.
    pub qx: Vec<f64>,
    /// q_y of the rows, increasing, 1/m.
    pub qy: Vec<f64>,
    /// C(q_x, q_y) in m⁴, row-major `qy.len() × qx.len()`.
    pub c: Vec<f64>,
    /// The lay, degrees counterclockwise from x (drawn as a line).
    pub lay: Option<f64>,
    /// Size in pixels, width × height.
    pub size: (u32, u32),
}

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

/// Draws `fig` as an SVG document in memory.
///
/// # Errors
/// As [`super::Encode::encode`], except the file errors.
pub fn render_spectrum_map_svg_string(fig: &SpectrumMapFigure) -> Result<String> {
    render_canvas_svg_string(fig)
}

impl super::Encode for SpectrumMapFigure {
    fn encode(&self, path: &Path) -> Result<Vec<u8>> {
        super::canvas::encode_canvas(self, path)
    }
}

impl Canvas for SpectrumMapFigure {
    fn size(&self) -> (u32, u32) {
        self.size
    }
    fn check(&self) -> Result<()> {
        SpectrumMapFigure::check(self)
    }
    fn draw_on<DB: DrawingBackend>(&self, root: DrawingArea<DB, Shift>, k: u32) -> DrawResult<DB> {
        draw_figure(root, self, k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let svg = render_spectrum_map_svg_string(&f).unwrap();
        assert!(svg.contains("lay, 30° from x"), "the lay's legend");
    }
}

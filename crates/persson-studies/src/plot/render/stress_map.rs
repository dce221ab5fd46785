//! Drawing a stress field ([`FieldFigure`]) on a plotters backend.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::DrawResult;
use super::map::{colour_bar, font, viridis};
use crate::plot::map::{tick, MAP_CELLS};
use crate::plot::stress_map::FieldFigure;
use crate::{Error, Result};

super::canvas::canvas_figure!(FieldFigure, draw_field);

/// The field and its colour bar, at `k` times the figure's size.
fn draw_field<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    f: &FieldFigure,
    k: u32,
) -> DrawResult<DB> {
    let px = |v: u32| v * k;
    root.fill(&WHITE)?;
    let root = root
        .margin(px(8), 0, 0, 0)
        .titled(&f.title, font(16.0, k))?;
    let (w, _) = root.dim_in_pixel();
    let (map_area, bar_area) = root.split_horizontally(w.saturating_sub(px(130)));
    let top = f
        .values
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let (x0, x1) = f.x_range;
    // A depth axis grows downwards: plot −z and label |z|.
    let (y0, y1) = if f.depth_down {
        (-f.y_range.1, -f.y_range.0)
    } else {
        f.y_range
    };
    let mut chart = ChartBuilder::on(&map_area)
        .margin(px(10))
        .x_label_area_size(px(45))
        .y_label_area_size(px(70))
        .build_cartesian_2d(x0..x1, y0..y1)?;
    let flip = f.depth_down;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(f.x_label.as_str())
        .y_desc(f.y_label.as_str())
        .label_style(font(12.0, k))
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(if flip { -*v } else { *v }))
        .axis_desc_style(font(14.0, k))
        .x_labels(6)
        .y_labels(6)
        .draw()?;
    let (mx, my, kx, ky, mean) = f.cells();
    let dx = (x1 - x0) / f.nx as f64;
    let dy = (f.y_range.1 - f.y_range.0) / f.ny as f64;
    chart.draw_series((0..mx * my).map(|c| {
        let (i, j) = (c / mx, c % mx);
        let xa = x0 + (j * kx) as f64 * dx;
        let xb = x0 + (((j + 1) * kx).min(f.nx)) as f64 * dx;
        let ya = f.y_range.0 + (i * ky) as f64 * dy;
        let yb = f.y_range.0 + (((i + 1) * ky).min(f.ny)) as f64 * dy;
        let (ya, yb) = if flip { (-ya, -yb) } else { (ya, yb) };
        Rectangle::new([(xa, ya), (xb, yb)], viridis(mean[c] / top).filled())
    }))?;
    colour_bar(&bar_area, (0.0, top), &f.value_label, 85, k)?;
    Ok(())
}

impl FieldFigure {
    fn check(&self) -> Result<()> {
        if self.nx == 0 || self.ny == 0 || self.values.len() != self.nx * self.ny {
            return Err(Error::Inconsistent {
                name: "stress map".into(),
                requirement: format!(
                    "nx·ny = {} values, got {}",
                    self.nx * self.ny,
                    self.values.len()
                ),
            });
        }
        for (name, (a, b)) in [("x range", self.x_range), ("y range", self.y_range)] {
            if !(a.is_finite() && b.is_finite() && b > a) {
                return Err(Error::invalid(name, b - a, "finite and > 0"));
            }
        }
        Ok(())
    }

    /// The field in blocks of at most [`MAP_CELLS`] per side: (mx, my, means).
    fn cells(&self) -> (usize, usize, usize, usize, Vec<f64>) {
        let k = self.nx.max(self.ny).div_ceil(MAP_CELLS).max(1);
        let (mx, my) = (self.nx.div_ceil(k), self.ny.div_ceil(k));
        let mut sum = vec![0.0; mx * my];
        let mut count = vec![0usize; mx * my];
        for i in 0..self.ny {
            for j in 0..self.nx {
                let v = self.values[i * self.nx + j];
                let c = (i / k) * mx + j / k;
                sum[c] += if v.is_finite() { v } else { 0.0 };
                count[c] += 1;
            }
        }
        for (s, &c) in sum.iter_mut().zip(&count) {
            *s /= c.max(1) as f64;
        }
        // Edges of the blocks in cells (the last block may be narrower).
        (mx, my, k, k, sum)
    }
}

//! Colour maps of the stress below the surface: the von Mises stress of a
//! plane z = const (`bem rough --subsurface --stress-plot`, the scene's
//! `bem.subsurface.plot`) and of the vertical section through the axis of a
//! Hertz contact (`bem hertz --subsurface --stress-plot`).
//!
//! Like [`super::map::MapFigure`] a [`FieldFigure`] is plain data, drawn
//! into an `.svg` or `.png` file ([`super::Encode`]), with the same
//! viridis scale from 0 to the field's largest value and a colour bar. Fields
//! finer than [`super::map::MAP_CELLS`] per side are drawn in blocks (the
//! block's mean).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::canvas::{Canvas, DrawResult};
use super::map::{colour_bar, font, tick, viridis, MAP_CELLS};
use crate::{Error, Result};

/// The default size in pixels of a field figure, width × height.
pub const FIELD_SIZE: (u32, u32) = (720, 600);

/// A scalar field on a rectangle, as plain data.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldFigure {
    /// Title over the figure.
    pub title: String,
    /// Label of the horizontal axis (with its unit).
    pub x_label: String,
    /// Label of the vertical axis (with its unit).
    pub y_label: String,
    /// Range of the horizontal axis (cell edges).
    pub x_range: (f64, f64),
    /// Range of the vertical axis (cell edges).
    pub y_range: (f64, f64),
    /// Whether the vertical axis is a depth, drawn growing downwards.
    pub depth_down: bool,
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// Values, row-major `v[i·nx + j]` (i along y from `y_range.0`, j along x).
    pub values: Vec<f64>,
    /// Label of the colour bar (with its unit).
    pub value_label: String,
    /// Size in pixels, width × height.
    pub size: (u32, u32),
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

/// The figure of one plane's von Mises map: `n × n` values on the side
/// `size` (rows along x, columns along y as in [`persson::bem::subsurface`]),
/// at `depth` under the nominal pressure `nominal_pressure`.
pub fn von_mises_plane(
    von_mises: &[f64],
    n: usize,
    size: f64,
    depth: f64,
    nominal_pressure: f64,
    pressure_unit: &str,
) -> FieldFigure {
    // Rows run along x: draw x horizontally, so transpose to (y rows, x columns).
    let mut values = vec![0.0; von_mises.len()];
    for i in 0..n {
        for j in 0..n {
            if let (Some(v), Some(slot)) = (von_mises.get(i * n + j), values.get_mut(j * n + i)) {
                *slot = *v;
            }
        }
    }
    FieldFigure {
        title: format!(
            "Von Mises stress at z = {} m, σ0 = {}",
            tick(depth),
            tick(nominal_pressure)
        ),
        x_label: "x (m)".into(),
        y_label: "y (m)".into(),
        x_range: (0.0, size),
        y_range: (0.0, size),
        depth_down: false,
        nx: n,
        ny: n,
        values,
        value_label: format!("σ_vM ({pressure_unit})"),
        size: FIELD_SIZE,
    }
}

/// The figure of a vertical section: `values` on `nz` depths (rows, from
/// the top) × `nx` positions (columns), the cell edges spanning `x_range`
/// and `z_range` (depth, drawn downwards).
pub fn vertical_section(
    title: String,
    (x_label, z_label, value_label): (&str, &str, &str),
    values: Vec<f64>,
    (nx, nz): (usize, usize),
    x_range: (f64, f64),
    z_range: (f64, f64),
) -> FieldFigure {
    FieldFigure {
        title,
        x_label: x_label.into(),
        y_label: z_label.into(),
        x_range,
        y_range: z_range,
        depth_down: true,
        nx,
        ny: nz,
        values,
        value_label: value_label.into(),
        size: FIELD_SIZE,
    }
}

impl super::Encode for FieldFigure {
    fn encode(&self, path: &Path) -> Result<Vec<u8>> {
        super::canvas::encode_canvas(self, path)
    }
}

impl Canvas for FieldFigure {
    fn size(&self) -> (u32, u32) {
        self.size
    }
    fn check(&self) -> Result<()> {
        FieldFigure::check(self)
    }
    fn draw_on<DB: DrawingBackend>(&self, root: DrawingArea<DB, Shift>, k: u32) -> DrawResult<DB> {
        draw_field(root, self, k)
    }
}

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

/// The figure of every kept von Mises map (`maps`, from
/// [`crate::bem_detail::Details::maps`]), each with its file: `path` with
/// `_k_j` added before the extension (solve k, depth j, as the `.npy` of
/// `stress_field`); `depths` and `pressures` are the study's.
#[cfg(feature = "bem")]
pub fn planes(
    maps: &[crate::bem_detail::StressMap],
    (n, size): (usize, f64),
    depths: &[f64],
    pressures: &[f64],
    pressure_unit: &str,
    path: &Path,
) -> Vec<(std::path::PathBuf, FieldFigure)> {
    maps.iter()
        .map(|m| {
            let depth = depths.get(m.depth_index).copied().unwrap_or(f64::NAN);
            let sigma0 = pressures.get(m.index).copied().unwrap_or(f64::NAN);
            let fig = von_mises_plane(&m.von_mises_stress, n, size, depth, sigma0, pressure_unit);
            (
                crate::bem_detail::indexed(path, m.index, m.depth_index),
                fig,
            )
        })
        .collect()
}

/// The figure of the vertical section through a Hertz contact's axis.
#[cfg(feature = "bem")]
pub fn hertz_section_figure(
    r: &crate::bem_detail::HertzSubsurface,
    s: &crate::bem_detail::VerticalSection,
) -> FieldFigure {
    vertical_section(
        format!(
            "Von Mises stress below the Hertz contact (FFT-BEM, {} boundary, N = {}, ν = {})",
            r.boundary.name(),
            r.grid,
            tick(r.poisson)
        ),
        ("distance from the axis / a", "depth z / a", "σ_vM / p0"),
        s.von_mises_stress.clone(),
        (s.columns, s.depths),
        s.offset_range,
        s.depth_range,
    )
}

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

use super::map::tick;

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

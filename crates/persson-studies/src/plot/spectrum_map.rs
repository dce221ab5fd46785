//! The 2-D power spectrum of a height map as a colour map (`persson
//! anisotropy --plot`): log10 C(q_x, q_y) over the Fourier grid with a colour
//! bar, and the lay drawn as a line through q = 0.
//!
//! A surface with a lay varies slowly along it, so its power lies in a band
//! *across* the lay in the q-plane: the drawn line runs along the lay and
//! the bright band perpendicular to it. Like [`super::Figure`] a
//! [`SpectrumMapFigure`] is plain data, drawn by [`super::render`] into an
//! `.svg` or `.png` file (atomically) or by [`super::render_svg_string`].
//!
//! Grids finer than [`super::map::MAP_CELLS`] per side are drawn in blocks,
//! each the mean of log10 C over its positive values (grey where none is).

/// Default size in pixels, width × height.
pub const SPECTRUM_MAP_SIZE: (u32, u32) = (760, 620);

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

//! Windows against the leakage of a non-periodic map's edges.
//!
//! # Formula
//! Maps use a rotationally symmetric window, so that the leakage is isotropic
//! like the spectrum it distorts (SurfaceTopography's `get_window_2D`):
//! ```text
//! r = √((Lx (i_x − ⌊nx/2⌋)/nx)² + (Ly (i_y − ⌊ny/2⌋)/ny)²),   r_max = min(Lx, Ly)/2
//! Hann:      w(r) = ½ + ½ cos(π r/r_max)
//! Blackman:  w(r) = 0.42 + 0.5 cos(π r/r_max) + 0.08 cos(2π r/r_max)
//! w = 0 for r > r_max
//! ```
//! Line scans use the periodic 1D windows of `scipy.signal.get_window`,
//! `w_i = ½ − ½ cos(2πi/n)` (Hann) and `0.42 − 0.5 cos(2πi/n) + 0.08 cos(4πi/n)`
//! (Blackman). In both cases the window is scaled so that its mean square
//! over the grid is one, `⟨w²⟩ = 1`: the spectrum of a windowed white noise
//! keeps its variance.
//!
//! # References
//! Jacobs, Junge & Pastewka, Surf. Topogr.: Metrol. Prop. 5, 013001 (2017).

use super::Layout;

pub use crate::names::Window;

impl Window {
    /// The window as a function of `t ∈ [0, 1]`, `t = r/r_max` (radial) or
    /// `|2i/n − 1|` (1D), unnormalised.
    fn shape(self, t: f64) -> f64 {
        use std::f64::consts::PI;
        if t > 1.0 {
            return 0.0;
        }
        match self {
            Window::None => 1.0,
            Window::Hann => 0.5 + 0.5 * (PI * t).cos(),
            Window::Blackman => 0.42 + 0.5 * (PI * t).cos() + 0.08 * (2.0 * PI * t).cos(),
        }
    }
}

/// Multiply `h` (`ny × nx`, row-major) by the normalised window.
pub(crate) fn apply(
    h: &mut [f64],
    nx: usize,
    ny: usize,
    (lx, ly): (f64, f64),
    layout: Layout,
    window: Window,
) {
    if window == Window::None {
        return;
    }
    match layout {
        Layout::LineScans => {
            // Periodic 1D window: w_i = f(|2i/n − 1|) equals ½ − ½cos(2πi/n) for Hann.
            let w: Vec<f64> = (0..nx)
                .map(|i| window.shape((2.0 * i as f64 / nx as f64 - 1.0).abs()))
                .collect();
            let ms = w.iter().map(|v| v * v).sum::<f64>() / nx as f64;
            let s = 1.0 / ms.sqrt();
            for row in h.chunks_exact_mut(nx) {
                row.iter_mut().zip(&w).for_each(|(v, w)| *v *= w * s);
            }
        }
        Layout::Map => {
            let mut sum_w2 = 0.0;
            for_rows(nx, ny, (lx, ly), window, |iy, w| {
                if let Some(w) = w {
                    let row = &mut h[iy * nx..(iy + 1) * nx];
                    row.iter_mut().zip(w).for_each(|(v, w)| *v *= w);
                    sum_w2 += w.iter().map(|v| v * v).sum::<f64>();
                }
            });
            let s = 1.0 / (sum_w2 / (nx * ny) as f64).sqrt();
            h.iter_mut().for_each(|v| *v *= s);
        }
    }
}

/// Call `f(iy, Some(w_row))` for every row of an `ny × nx` map with the
/// unnormalised radial window (`f(iy, None)` without a window). Rows at the
/// same distance from the centre row share one evaluation, and each row is
/// mirrored about the centre column: a quarter of the cosines.
pub(crate) fn for_rows(
    nx: usize,
    ny: usize,
    (lx, ly): (f64, f64),
    window: Window,
    mut f: impl FnMut(usize, Option<&[f64]>),
) {
    if window == Window::None {
        (0..ny).for_each(|iy| f(iy, None));
        return;
    }
    let r_max = 0.5 * lx.min(ly);
    let (cx, cy) = (nx / 2, ny / 2);
    let (sx, sy) = (lx / nx as f64 / r_max, ly / ny as f64 / r_max);
    let xs: Vec<f64> = (0..nx)
        .map(|i| (sx * (i as f64 - cx as f64)).powi(2))
        .collect();
    let mut row = vec![0.0; nx];
    for d in 0..=cy.max(ny - 1 - cy) {
        let y2 = (sy * d as f64).powi(2);
        for ix in cx..nx {
            row[ix] = window.shape((xs[ix] + y2).sqrt());
        }
        for ix in 0..cx {
            let m = 2 * cx - ix;
            row[ix] = if m < nx {
                row[m]
            } else {
                window.shape((xs[ix] + y2).sqrt())
            };
        }
        if d <= cy {
            f(cy - d, Some(&row));
        }
        if d > 0 && cy + d < ny {
            f(cy + d, Some(&row));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ⟨w²⟩ = 1 after normalisation, to rounding.
    const ROUNDING: f64 = 1e-13;

    #[test]
    fn power_is_normalised() {
        for window in [Window::Hann, Window::Blackman] {
            for (layout, nx, ny, l) in [
                (Layout::Map, 24, 17, (2.0, 1.5)),
                (Layout::Map, 16, 16, (1.0, 1.0)),
                (Layout::LineScans, 33, 2, (1.0, 0.0)),
            ] {
                let mut h = vec![1.0; nx * ny];
                apply(&mut h, nx, ny, l, layout, window);
                let ms = h.iter().map(|v| v * v).sum::<f64>() / h.len() as f64;
                assert!((ms - 1.0).abs() < ROUNDING, "{window:?} {layout:?}: {ms}");
            }
        }
    }

    #[test]
    fn hann_line_is_scipy_periodic_hann() {
        // scipy.signal.get_window('hann', 8): 0.5 − 0.5 cos(2πi/8).
        let w: Vec<f64> = (0..8)
            .map(|i| Window::Hann.shape((2.0 * i as f64 / 8.0 - 1.0).abs()))
            .collect();
        for (i, v) in w.iter().enumerate() {
            let e = 0.5 - 0.5 * (std::f64::consts::TAU * i as f64 / 8.0).cos();
            assert!((v - e).abs() < 1e-15, "{i}: {v} vs {e}");
        }
    }
}

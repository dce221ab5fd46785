//! rms height, slope and curvature in real space.
//!
//! # Formula
//! On the detrended heights h (no window), with Δx, Δy the pixel sizes:
//! ```text
//! h_rms  = √⟨(h − h̄)²⟩
//! h'_rms = √⟨(D⁺_x h)² + (D⁺_y h)²⟩,   D⁺_x h = (h_{i+1,j} − h_{i,j})/Δx      (forward differences)
//! h''_rms = √⟨(∇²_5 h)²⟩,   ∇²_5 h = (h_{i+1,j} − 2h_{i,j} + h_{i−1,j})/Δx² + (h_{i,j+1} − 2h_{i,j} + h_{i,j−1})/Δy²
//! ```
//! The slope is averaged over the (nx−1)(ny−1) points where both forward
//! differences exist and the Laplacian over the (nx−2)(ny−2) interior points
//! (all points, wrapping around, for periodic maps): SurfaceTopography's
//! default stencils, so that `rms_gradient` and `rms_laplacian` agree to
//! rounding (its `rms_curvature_from_area` is half the rms Laplacian, the
//! mean curvature; ours is Persson's `⟨(∇²h)²⟩^{1/2}`, crate conventions).
//!
//! In Fourier space the stencils are the symbols `(2/Δ) sin(qΔ/2)` and
//! `−(2/Δ)² sin²(qΔ/2)` instead of `iq` and `−q²`: on a periodic map
//! `h'²_rms = Σ_q [(2/Δx)² sin²(q_xΔx/2) + (2/Δy)² sin²(q_yΔy/2)] C(q) Δq_x Δq_y`
//! exactly, below the spectral `Σ_q q² C Δq_x Δq_y` by the relative amount
//! `≈ ⟨q⁴⟩Δ²/(12⟨q²⟩)`.
//!
//! Line scans use the same 1D stencils along x and report the 2D values of
//! an isotropic surface, `h'_rms = √2 · rms(D⁺_x h)` and
//! `h''_rms = √(8/3) · rms(D²_x h)`.

use super::{condition, Detrend, Layout, Topography};
use crate::error::Result;

/// Real-space statistics of a topography.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct RealSpaceStats {
    /// rms height about the mean, m.
    pub rms_height: f64,
    /// rms slope (forward differences), dimensionless.
    pub rms_slope: f64,
    /// rms Laplacian (5-point), 1/m; `None` when no point has the stencil's
    /// neighbours (a non-periodic map of fewer than 3 points along x or y, a
    /// line scan of fewer than 3 points).
    pub rms_curvature: Option<f64>,
    /// Line scans: rms slope along the profiles, `rms(D⁺_x h)` (`None` for maps).
    pub rms_slope_profile: Option<f64>,
    /// Line scans: rms second derivative along the profiles, `rms(D²_x h)`,
    /// 1/m (`None` for maps, and for profiles of fewer than 3 points).
    pub rms_curvature_profile: Option<f64>,
}

/// rms height, slope and curvature of the topography after `detrend`
/// (module docs for the stencils).
///
/// # Errors
/// None for a valid topography; the `Result` is for future stencils.
///
/// # Examples
/// ```
/// use persson::topography::{real_space_stats, Detrend, Topography};
/// # fn main() -> persson::Result<()> {
/// // A tilted plane h = 0.01·x on a 1 µm grid: forward differences are exact,
/// // h'_rms = 0.01, and the Laplacian vanishes; detrending the plane leaves 0.
/// let (nx, ny, d) = (8, 5, 1e-6);
/// let h = (0..nx * ny).map(|k| 0.01 * d * (k % nx) as f64).collect();
/// let t = Topography::map(nx, ny, nx as f64 * d, ny as f64 * d, h, false)?;
/// let s = real_space_stats(&t, Detrend::Mean)?;
/// assert!((s.rms_slope - 0.01).abs() < 1e-15);
/// assert!(s.rms_curvature.unwrap().abs() < 1e-6);
/// assert!(real_space_stats(&t, Detrend::Plane)?.rms_height < 1e-20);
/// # Ok(()) }
/// ```
pub fn real_space_stats(t: &Topography, detrend: Detrend) -> Result<RealSpaceStats> {
    let h = condition::detrended(t, detrend);
    let (nx, ny) = (t.nx(), t.ny());
    let n = h.len() as f64;
    let mean = h.iter().sum::<f64>() / n;
    let rms_height = (h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
    let at = |i: usize, j: usize| h[j * nx + i];
    let dx = t.dx();
    let p = t.periodic();
    let (rms_slope, rms_curvature, profile) = match t.layout() {
        Layout::LineScans => {
            let (mut s1, mut n1, mut s2, mut n2) = (0.0, 0usize, 0.0, 0usize);
            for j in 0..ny {
                for i in 0..nx {
                    if p || i + 1 < nx {
                        s1 += ((at((i + 1) % nx, j) - at(i, j)) / dx).powi(2);
                        n1 += 1;
                    }
                    if p || (i >= 1 && i + 1 < nx) {
                        let (l, r) = ((i + nx - 1) % nx, (i + 1) % nx);
                        s2 += ((at(l, j) - 2.0 * at(i, j) + at(r, j)) / (dx * dx)).powi(2);
                        n2 += 1;
                    }
                }
            }
            let (slope, curvature) = (
                (s1 / n1 as f64).sqrt(),
                (n2 > 0).then(|| (s2 / n2 as f64).sqrt()),
            );
            (
                2f64.sqrt() * slope,
                curvature.map(|c| (8.0f64 / 3.0).sqrt() * c),
                Some((slope, curvature)),
            )
        }
        Layout::Map => {
            let dy = t.dy();
            let (mut s1, mut n1, mut s2, mut n2) = (0.0, 0usize, 0.0, 0usize);
            for j in 0..ny {
                for i in 0..nx {
                    if p || (i + 1 < nx && j + 1 < ny) {
                        let gx = (at((i + 1) % nx, j) - at(i, j)) / dx;
                        let gy = (at(i, (j + 1) % ny) - at(i, j)) / dy;
                        s1 += gx * gx + gy * gy;
                        n1 += 1;
                    }
                    if p || (i >= 1 && i + 1 < nx && j >= 1 && j + 1 < ny) {
                        let (l, r) = ((i + nx - 1) % nx, (i + 1) % nx);
                        let (d, u) = ((j + ny - 1) % ny, (j + 1) % ny);
                        let c = at(i, j);
                        let lap = (at(l, j) - 2.0 * c + at(r, j)) / (dx * dx)
                            + (at(i, d) - 2.0 * c + at(i, u)) / (dy * dy);
                        s2 += lap * lap;
                        n2 += 1;
                    }
                }
            }
            (
                (s1 / n1 as f64).sqrt(),
                (n2 > 0).then(|| (s2 / n2 as f64).sqrt()),
                None,
            )
        }
    };
    Ok(RealSpaceStats {
        rms_height,
        rms_slope,
        rms_curvature,
        rms_slope_profile: profile.map(|p| p.0),
        rms_curvature_profile: profile.and_then(|p| p.1),
    })
}

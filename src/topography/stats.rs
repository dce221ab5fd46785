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
    if t.layout() == Layout::Map {
        let trend = condition::map_trend(t, detrend);
        return Ok(map_stats(t, trend.as_ref()));
    }
    let h = condition::detrended(t, detrend);
    let (nx, ny) = (t.nx(), t.ny());
    let n = h.len() as f64;
    let mean = h.iter().sum::<f64>() / n;
    let rms_height = (h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
    let at = |i: usize, j: usize| h[j * nx + i];
    let dx = t.dx();
    let p = t.periodic();
    // Line scans: the 1D stencils along each profile.
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
    Ok(RealSpaceStats {
        rms_height,
        rms_slope: 2f64.sqrt() * slope,
        rms_curvature: curvature.map(|c| (8.0f64 / 3.0).sqrt() * c),
        rms_slope_profile: Some(slope),
        rms_curvature_profile: curvature,
    })
}

/// The statistics of a map from its detrended rows, handed over one at a
/// time in any order ([`MapRows::push`]): each stencil term is added as soon
/// as the rows it needs are in, and a row is let go once every term that
/// needs it is added. The spectrum's row pass hands the rows over from the
/// centre outwards ([`condition::for_detrended_rows`]), so that the
/// statistics need no pass and no detrended copy of their own, and a few
/// rows are held at a time (as for rows in order).
///
/// The rms height comes from `Σ(h − s)` and `Σ(h − s)²` about `s`, the mean
/// of the heights as they are when nothing is detrended and 0 otherwise
/// (the trend takes the mean out): `⟨(h − h̄)²⟩ = ⟨(h − s)²⟩ − (h̄ − s)²`.
pub(crate) struct MapRows {
    nx: usize,
    ny: usize,
    periodic: bool,
    shift: f64,
    /// 1/Δx, 1/Δy.
    inv: (f64, f64),
    /// Rows held: (iy, detrended heights).
    rows: Vec<(usize, Vec<f64>)>,
    /// Buffers let go, for the next rows.
    spare: Vec<Vec<f64>>,
    /// Whether the slope and Laplacian terms of each row are in (or have
    /// none: the last row and column of a non-periodic map have no forward
    /// difference, its edges no Laplacian).
    slope_done: Vec<bool>,
    laplacian_done: Vec<bool>,
    pushed: usize,
    /// Σ(h − s), Σ(h − s)², Σ|∇h|², number of slope points, Σ(∇²h)², number
    /// of Laplacian points.
    sums: (f64, f64, f64, usize, f64, usize),
}

impl MapRows {
    /// No row yet, for the map `t` detrended by `trend`.
    pub(crate) fn new(t: &Topography, trend: Option<&condition::MapTrend>) -> Self {
        let (nx, ny) = (t.nx(), t.ny());
        let periodic = t.periodic();
        let shift = match trend {
            None => t.heights().iter().sum::<f64>() / (nx * ny) as f64,
            Some(_) => 0.0,
        };
        MapRows {
            nx,
            ny,
            periodic,
            shift,
            inv: (1.0 / t.dx(), 1.0 / t.dy()),
            rows: Vec::new(),
            spare: Vec::new(),
            slope_done: (0..ny).map(|j| !(periodic || j + 1 < ny)).collect(),
            laplacian_done: (0..ny)
                .map(|j| !(periodic || (j >= 1 && j + 1 < ny)))
                .collect(),
            pushed: 0,
            sums: (0.0, 0.0, 0.0, 0, 0.0, 0),
        }
    }

    /// Take detrended row `iy` out of `h`, which gets a spare buffer of the
    /// same length in exchange.
    pub(crate) fn push(&mut self, iy: usize, h: &mut Vec<f64>) {
        let spare = self.spare.pop().unwrap_or_else(|| vec![0.0; self.nx]);
        let row = std::mem::replace(h, spare);
        let (a, b) = sums(&row, self.shift);
        self.sums.0 += a;
        self.sums.1 += b;
        self.rows.push((iy, row));
        self.pushed += 1;
        // The terms row iy takes part in: slopes of iy − 1 and iy,
        // Laplacians of iy − 1, iy and iy + 1.
        let ny = self.ny;
        let (below, above) = ((iy + ny - 1) % ny, (iy + 1) % ny);
        for j in [below, iy] {
            self.slope(j);
        }
        for j in [below, iy, above] {
            self.laplacian(j);
        }
        // Let go of the rows no term still needs.
        let mut k = 0;
        while k < self.rows.len() {
            let j = self.rows[k].0;
            let (b, a) = ((j + ny - 1) % ny, (j + 1) % ny);
            let needed = !self.slope_done[j]
                || !self.slope_done[b]
                || !self.laplacian_done[b]
                || !self.laplacian_done[j]
                || !self.laplacian_done[a];
            if needed {
                k += 1;
            } else {
                let (_, row) = self.rows.swap_remove(k);
                self.spare.push(row);
            }
        }
    }

    fn row(&self, j: usize) -> Option<&[f64]> {
        self.rows
            .iter()
            .find(|(i, _)| *i == j)
            .map(|(_, r)| r.as_slice())
    }

    /// The slope terms of row `j` if due and its rows are in.
    fn slope(&mut self, j: usize) {
        if self.slope_done[j] {
            return;
        }
        let (Some(cur), Some(next)) = (self.row(j), self.row((j + 1) % self.ny)) else {
            return;
        };
        let s = slope_sum(cur, next, self.inv.0, self.inv.1, self.periodic);
        self.sums.2 += s;
        self.sums.3 += if self.periodic { self.nx } else { self.nx - 1 };
        self.slope_done[j] = true;
    }

    /// The Laplacian terms of row `j` if due and its rows are in.
    fn laplacian(&mut self, j: usize) {
        if self.laplacian_done[j] {
            return;
        }
        let ny = self.ny;
        let (Some(prev), Some(cur), Some(next)) = (
            self.row((j + ny - 1) % ny),
            self.row(j),
            self.row((j + 1) % ny),
        ) else {
            return;
        };
        let (ix, iy) = self.inv;
        let s = laplacian_sum(prev, cur, next, ix * ix, iy * iy, self.periodic);
        self.sums.4 += s;
        self.sums.5 += if self.periodic {
            self.nx
        } else {
            self.nx.saturating_sub(2)
        };
        self.laplacian_done[j] = true;
    }

    /// The statistics, once every row is in.
    pub(crate) fn finish(self) -> RealSpaceStats {
        debug_assert_eq!(self.pushed, self.ny, "every row once");
        let n = (self.nx * self.ny) as f64;
        let (s0, s00, s1, n1, s2, n2) = self.sums;
        let mean = s0 / n;
        RealSpaceStats {
            rms_height: (s00 / n - mean * mean).max(0.0).sqrt(),
            rms_slope: (s1 / n1 as f64).sqrt(),
            rms_curvature: (n2 > 0).then(|| (s2 / n2 as f64).sqrt()),
            rms_slope_profile: None,
            rms_curvature_profile: None,
        }
    }
}

/// The statistics of a map, its rows detrended one at a time in order.
fn map_stats(t: &Topography, trend: Option<&condition::MapTrend>) -> RealSpaceStats {
    let mut rows = MapRows::new(t, trend);
    let mut h = vec![0.0; t.nx()];
    for iy in 0..t.ny() {
        condition::detrended_row(t, trend, iy, &mut h);
        rows.push(iy, &mut h);
    }
    rows.finish()
}

/// Lanes of the partial sums below (independent additions the compiler
/// can keep in vector registers).
const LANES: usize = 4;

/// `(Σ(h − s), Σ(h − s)²)` of a row.
fn sums(h: &[f64], s: f64) -> (f64, f64) {
    let (mut a, mut b) = ([0.0; LANES], [0.0; LANES]);
    let mut chunks = h.chunks_exact(LANES);
    for c in &mut chunks {
        for l in 0..LANES {
            let v = c[l] - s;
            a[l] += v;
            b[l] += v * v;
        }
    }
    for &v in chunks.remainder() {
        let v = v - s;
        a[0] += v;
        b[0] += v * v;
    }
    (a.iter().sum(), b.iter().sum())
}

/// `Σ_i (D⁺_x h)² + (D⁺_y h)²` along row `cur` (`next` the row above): over
/// `i < nx − 1`, and `i = nx − 1` wrapping around when periodic.
fn slope_sum(cur: &[f64], next: &[f64], ix: f64, iy: f64, periodic: bool) -> f64 {
    let nx = cur.len();
    let next = &next[..nx];
    let g2 = |i: usize, r: f64| {
        let gx = (r - cur[i]) * ix;
        let gy = (next[i] - cur[i]) * iy;
        gx * gx + gy * gy
    };
    let mut acc = [0.0; LANES];
    let m = nx - 1;
    let (c0, c1, n0) = (&cur[..m], &cur[1..], &next[..m]);
    let mut i = 0;
    while i + LANES <= m {
        for l in 0..LANES {
            let gx = (c1[i + l] - c0[i + l]) * ix;
            let gy = (n0[i + l] - c0[i + l]) * iy;
            acc[l] += gx * gx + gy * gy;
        }
        i += LANES;
    }
    for k in i..m {
        acc[0] += g2(k, cur[k + 1]);
    }
    if periodic {
        acc[0] += g2(m, cur[0]);
    }
    acc.iter().sum()
}

/// `Σ_i (∇²_5 h)²` along row `cur` (`prev`, `next` the rows below and
/// above): the interior `0 < i < nx − 1`, and both ends wrapping around
/// when periodic.
fn laplacian_sum(
    prev: &[f64],
    cur: &[f64],
    next: &[f64],
    ix2: f64,
    iy2: f64,
    periodic: bool,
) -> f64 {
    let nx = cur.len();
    let (prev, next) = (&prev[..nx], &next[..nx]);
    let lap = |i: usize, l: f64, r: f64| {
        let c = cur[i];
        let v = (l - 2.0 * c + r) * ix2 + (prev[i] - 2.0 * c + next[i]) * iy2;
        v * v
    };
    let mut acc = [0.0; LANES];
    if nx >= 3 {
        let m = nx - 2;
        let (l0, c0, r0) = (&cur[..m], &cur[1..m + 1], &cur[2..]);
        let (d0, u0) = (&prev[1..m + 1], &next[1..m + 1]);
        let mut i = 0;
        while i + LANES <= m {
            for l in 0..LANES {
                let c = c0[i + l];
                let v = (l0[i + l] - 2.0 * c + r0[i + l]) * ix2
                    + (d0[i + l] - 2.0 * c + u0[i + l]) * iy2;
                acc[l] += v * v;
            }
            i += LANES;
        }
        for k in i..m {
            acc[0] += lap(k + 1, cur[k], cur[k + 2]);
        }
    }
    if periodic {
        acc[0] += lap(0, cur[nx - 1], cur[1 % nx]);
        acc[0] += lap(nx - 1, cur[nx - 2], cur[0]);
    }
    acc.iter().sum()
}

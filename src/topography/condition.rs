//! Detrending: least-squares removal of the mean, a plane or a quadratic.
//!
//! # Formula
//! The trend is the least-squares fit of the heights by polynomials in the
//! grid coordinates: `1` (mean), `1, x, y` (plane), `1, x, y, x², xy, y²`
//! (curvature); line scans use `1`, `1, x`, `1, x, x²` per profile. The fit is
//! computed by projection on polynomials that are orthogonal on the grid,
//! ```text
//! u = 2i/(n−1) − 1,   P0 = 1,   P1 = u,   P2 = u² − ⟨u²⟩,   ⟨u²⟩ = (n+1)/(3(n−1))
//! h − Σ_b (Σ h φ_b / Σ φ_b²) φ_b,   φ_b ∈ {P_a(u)·P_c(v)}
//! ```
//! which is exact (the products are orthogonal on a full tensor grid because
//! odd sums over the symmetric grid vanish), so no linear system is solved
//! and the residual is the least-squares residual to rounding. It does not
//! depend on where the grid's origin is, so it equals SurfaceTopography's
//! `detrend('center' | 'height' | 'curvature')` residual.

use super::{Layout, Topography};

pub use crate::names::Detrend;

impl Detrend {
    /// Polynomial degree, `None` for no detrending.
    fn degree(self) -> Option<usize> {
        match self {
            Detrend::None => None,
            Detrend::Mean => Some(0),
            Detrend::Plane => Some(1),
            Detrend::Curvature => Some(2),
        }
    }
}

/// The orthogonal polynomials P0, P1, P2 of module docs on `n` points.
fn basis(n: usize) -> [Vec<f64>; 3] {
    let u: Vec<f64> = if n > 1 {
        (0..n)
            .map(|i| 2.0 * i as f64 / (n - 1) as f64 - 1.0)
            .collect()
    } else {
        vec![0.0]
    };
    // ⟨u²⟩ computed on the grid itself (not the closed form) so that P2 is
    // orthogonal to P0 to rounding.
    let mean_u2 = u.iter().map(|x| x * x).sum::<f64>() / n as f64;
    [
        vec![1.0; n],
        u.clone(),
        u.iter().map(|x| x * x - mean_u2).collect(),
    ]
}

/// The detrended heights of `t` (a new vector, row-major like `t.heights()`).
pub(crate) fn detrended(t: &Topography, mode: Detrend) -> Vec<f64> {
    let mut h = t.heights().to_vec();
    detrend_in_place(&mut h, t.nx(), t.ny(), t.layout(), mode);
    h
}

/// Remove the trend from `h` (`ny × nx`, row-major).
pub(crate) fn detrend_in_place(h: &mut [f64], nx: usize, ny: usize, layout: Layout, mode: Detrend) {
    let Some(degree) = mode.degree() else {
        return;
    };
    let bx = basis(nx);
    match layout {
        Layout::LineScans => {
            for row in h.chunks_exact_mut(nx) {
                for p in bx.iter().take(degree + 1) {
                    let norm: f64 = p.iter().map(|v| v * v).sum();
                    let a = row.iter().zip(p).map(|(h, v)| h * v).sum::<f64>() / norm;
                    row.iter_mut().zip(p).for_each(|(h, v)| *h -= a * v);
                }
            }
        }
        Layout::Map => {
            let trend = MapTrend::fit(h, nx, ny, degree);
            for (iy, row) in h.chunks_exact_mut(nx).enumerate() {
                let c = trend.row(iy);
                for (ix, v) in row.iter_mut().enumerate() {
                    *v -= c[0] + c[1] * trend.bx[1][ix] + c[2] * trend.bx[2][ix];
                }
            }
        }
    }
}

/// Lanes of the partial sums below (independent additions the compiler
/// can keep in vector registers).
const LANES: usize = 4;

/// `(Σ h, Σ h·p1, Σ h·p2)` of a row, in [`LANES`] partial sums.
fn row_moments(row: &[f64], p1: &[f64], p2: &[f64]) -> [f64; 3] {
    let mut s = [[0.0; LANES]; 3];
    let (rows, p1s, p2s) = (
        row.chunks_exact(LANES),
        p1.chunks_exact(LANES),
        p2.chunks_exact(LANES),
    );
    let tail = rows.remainder().len();
    for ((v, a), b) in rows.zip(p1s).zip(p2s) {
        for l in 0..LANES {
            s[0][l] += v[l];
            s[1][l] += v[l] * a[l];
            s[2][l] += v[l] * b[l];
        }
    }
    let k = row.len() - tail;
    for i in k..row.len() {
        s[0][0] += row[i];
        s[1][0] += row[i] * p1[i];
        s[2][0] += row[i] * p2[i];
    }
    s.map(|l| l.iter().sum())
}

/// Σ w² of a window row, in [`LANES`] partial sums.
pub(crate) fn sum_squares(w: &[f64]) -> f64 {
    let mut s = [0.0; LANES];
    let mut chunks = w.chunks_exact(LANES);
    for c in &mut chunks {
        for l in 0..LANES {
            s[l] += c[l] * c[l];
        }
    }
    for v in chunks.remainder() {
        s[0] += v * v;
    }
    s.iter().sum()
}

/// The least-squares trend of a map: `Σ_k coef_k P_a(u) P_b(v)`.
pub(crate) struct MapTrend {
    /// P0, P1, P2 along x.
    pub bx: [Vec<f64>; 3],
    by: [Vec<f64>; 3],
    terms: &'static [(usize, usize)],
    coef: Vec<f64>,
}

impl MapTrend {
    /// Fit the polynomial of `degree` (0, 1, 2) to `h` (`ny × nx`).
    pub(crate) fn fit(h: &[f64], nx: usize, ny: usize, degree: usize) -> Self {
        let bx = basis(nx);
        let by = basis(ny);
        // (index along x, index along y) of the tensor-product terms.
        let terms: &'static [(usize, usize)] = match degree {
            0 => &[(0, 0)],
            1 => &[(0, 0), (1, 0), (0, 1)],
            _ => &[(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)],
        };
        // One pass for all projections: Σ_iy P_b(v_iy) Σ_ix h P_a(u_ix).
        let mut num = vec![0.0; terms.len()];
        for (iy, row) in h.chunks_exact(nx).enumerate() {
            let s = row_moments(row, &bx[1], &bx[2]);
            for (k, &(a, b)) in terms.iter().enumerate() {
                num[k] += s[a] * by[b][iy];
            }
        }
        let norm = |p: &[f64]| p.iter().map(|v| v * v).sum::<f64>();
        let coef = terms
            .iter()
            .zip(&num)
            .map(|(&(a, b), n)| n / (norm(&bx[a]) * norm(&by[b])))
            .collect();
        MapTrend {
            bx,
            by,
            terms,
            coef,
        }
    }

    /// The trend along row `iy` as `c0 + c1 P1(u) + c2 P2(u)`.
    pub(crate) fn row(&self, iy: usize) -> [f64; 3] {
        let mut c = [0.0; 3];
        for (k, &(a, b)) in self.terms.iter().enumerate() {
            c[a] += self.coef[k] * self.by[b][iy];
        }
        c
    }
}

/// The trend `mode` of a map, fitted once for the spectrum and the
/// statistics (`None` without detrending).
pub(crate) fn map_trend(t: &Topography, mode: Detrend) -> Option<MapTrend> {
    mode.degree()
        .map(|d| MapTrend::fit(t.heights(), t.nx(), t.ny(), d))
}

/// Row `iy` of a map with the trend removed, into `out` (`nx` values): the
/// same numbers as row `iy` of [`detrended`].
pub(crate) fn detrended_row(t: &Topography, trend: Option<&MapTrend>, iy: usize, out: &mut [f64]) {
    let nx = t.nx();
    let src = &t.heights()[iy * nx..(iy + 1) * nx];
    match trend {
        Some(tr) => {
            let c = tr.row(iy);
            for (((d, s), p1), p2) in out.iter_mut().zip(src).zip(&tr.bx[1]).zip(&tr.bx[2]) {
                *d = s - (c[0] + c[1] * p1 + c[2] * p2);
            }
        }
        None => out.copy_from_slice(src),
    }
}

/// The detrended rows of a map one at a time, in the window's order
/// ([`super::window::for_rows`]: the centre row, then outwards a row below
/// and a row above at a time): `f(iy, h, w)` for every row, `h` the row
/// `iy` of [`detrended`] in a buffer of `nx` values that `f` may overwrite
/// or swap for another of the same length, `w` the unnormalised window along
/// it (`None` without a window). The conditioned row is `h·w`. Returns
/// the window's mean square `⟨w²⟩` (1 without a window), which the caller
/// divides the power by. No full-size copy.
pub(crate) fn for_detrended_rows(
    t: &Topography,
    trend: Option<&MapTrend>,
    window: super::Window,
    mut f: impl FnMut(usize, &mut Vec<f64>, Option<&[f64]>),
) -> f64 {
    let (nx, ny) = (t.nx(), t.ny());
    let mut buf = vec![0.0; nx];
    let mut sum_w2 = 0.0;
    super::window::for_rows(nx, ny, (t.lx(), t.ly()), window, |iy, w| {
        buf.resize(nx, 0.0);
        detrended_row(t, trend, iy, &mut buf);
        if let Some(w) = w {
            sum_w2 += sum_squares(w);
        }
        f(iy, &mut buf, w);
    });
    if window == super::Window::None {
        1.0
    } else {
        sum_w2 / (nx * ny) as f64
    }
}

/// `out = h·w` (`h` without a window).
pub(crate) fn windowed(h: &[f64], w: Option<&[f64]>, out: &mut [f64]) {
    match w {
        Some(w) => {
            for ((o, h), w) in out.iter_mut().zip(h).zip(w) {
                *o = h * w;
            }
        }
        None => out.copy_from_slice(h),
    }
}

/// The conditioned heights of a map in one pass: `(h − trend)·w`, with the
/// window's mean square `⟨w²⟩` returned instead of applied (the caller
/// divides the power by it).
pub(crate) fn conditioned_map(
    t: &Topography,
    mode: Detrend,
    window: super::Window,
) -> (Vec<f64>, f64) {
    let nx = t.nx();
    let trend = map_trend(t, mode);
    let mut out = vec![0.0; nx * t.ny()];
    let mean_w2 = for_detrended_rows(t, trend.as_ref(), window, |iy, h, w| {
        windowed(h, w, &mut out[iy * nx..(iy + 1) * nx])
    });
    (out, mean_w2)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Residual allowed after removing an exactly representable trend:
    /// rounding of sums over ~100 points of values of order 10.
    const EXACT: f64 = 1e-12;

    #[test]
    fn basis_is_orthogonal() {
        for n in [2, 3, 7, 10] {
            let b = basis(n);
            for i in 0..3 {
                for j in 0..i {
                    let d: f64 = b[i].iter().zip(&b[j]).map(|(x, y)| x * y).sum();
                    assert!(d.abs() < 1e-14, "n {n} ({i},{j}) {d}");
                }
            }
        }
    }

    #[test]
    fn removes_quadratic_exactly() {
        let (nx, ny) = (9, 6);
        let f = |x: f64, y: f64| 3.0 + 0.5 * x - 2.0 * y + 0.25 * x * x - 0.1 * x * y + 0.3 * y * y;
        let mut h: Vec<f64> = (0..nx * ny)
            .map(|k| f((k % nx) as f64, (k / nx) as f64))
            .collect();
        detrend_in_place(&mut h, nx, ny, Layout::Map, Detrend::Curvature);
        assert!(h.iter().all(|v| v.abs() < EXACT), "{h:?}");
    }
}

//! Elastic compliance operators of the half-space: periodic and free.
//!
//! Both map the nodal pressures `p` of an `N × N` grid of spacing `Δ = L/N`
//! to the normal surface displacements `u = 𝒢 p` (positive into the body).
//!
//! # Formula
//! ```text
//! periodic:  û(q) = 2 p̂(q) / (E* |q|),  q = (2π/L)(k_x, k_y) ≠ 0,  û(0) = 0
//! free:      u_i = Σ_j K(x_i − x_j) p_j,
//!            K(x) = 1/(π E*) ∫∫_{|x'|,|y'| ≤ Δ/2} dx' dy' / |x − x'|
//!                 = Δ/(π E*) Σ_corners ± I(·,·),   I(X, Y) = X asinh(Y/X) + Y asinh(X/Y)
//! ```
//! The periodic operator samples the half-space Green's function in Fourier
//! space (Westergaard / Johnson; Molinari's EPFL lecture, §"Discretization"); the mean
//! displacement is undetermined in a periodic system and set to zero.
//!
//! The free operator is the exact (Love 1929) displacement at a node due to a
//! uniform pressure on the square cell around another node (piecewise-constant
//! pressure, collocation at cell centres). It is applied as a circular
//! convolution on a `2N × 2N` grid whose padding is zero, so that an isolated
//! contact sees no periodic images. The corner sum cancels digits at large
//! distance r (relative error about 1e-16·(r/Δ)², below 1e-10 for N ≤ 4096).
//!
//! Units: `p` and `E*` in one pressure unit, lengths in the unit of `L`;
//! `u` comes out in the unit of `L`.
//!
//! # References
//! - K. L. Johnson, *Contact Mechanics* (CUP 1985), ch. 3 (Boussinesq's
//!   point load; Love's uniformly loaded rectangle).
//! - J. F. Molinari, EPFL lecture "From single asperity to multi asperity contact": u = FFT⁻¹(K FFT(p)), K = 2/(E*|q|).
//! - Liu, Wang & Liu, Wear 243, 101 (2000): DC-FFT, zero padding to 2N.

use rustfft::num_complex::Complex64;

use super::fft::Fft2;
use crate::error::{check, Error, Result};

mod padded;
pub(crate) use padded::Padded;

pub use crate::names::Boundary;

/// A planned compliance operator `u = 𝒢 p` on an `N × N` grid.
///
/// Owns every buffer it needs: [`Operator::apply`] never allocates.
#[derive(Debug)]
pub struct Operator {
    boundary: Boundary,
    n: usize,
    size: f64,
    e_star: f64,
    fft: Fft2,
    /// Multiplier of the half spectrum, including the `1/n_f²` normalisation
    /// of the inverse FFT (real: both kernels are even), stored per column
    /// `k_j` for `k_i ≤ n_f/2` only (`n_f/2 + 1` values; symmetric in k_i).
    multiplier: Vec<f64>,
    /// Real-space periodic kernel `k[(i − i')·N + (j − j')]` (periodic only;
    /// empty for the free operator), for sparse updates.
    spatial: Vec<f64>,
    /// Rows and columns of the padding kept on each side of the window in
    /// the transform ([`FREE_MARGIN`] free, 0 periodic): the window sits at
    /// offset `(margin, margin)` of the padded grid.
    margin: usize,
}

/// Nodes of the padding on each side of the window whose stiffness response
/// the free operator returns ([`Operator::apply_stiffness_rows_with_margin`]):
/// the reach of the preconditioner's edge correction
/// ([`super::preconditioned`]).
pub(crate) const FREE_MARGIN: usize = 3;

impl Operator {
    /// Plan the operator for an `n × n` grid of side `size` and modulus `e_star`.
    ///
    /// # Errors
    /// `n < 2`, `size` or `e_star` not finite and positive.
    pub fn new(boundary: Boundary, n: usize, size: f64, e_star: f64) -> Result<Self> {
        check::positive("size", size)?;
        check::positive("contact_modulus", e_star)?;
        if n < 2 {
            return Err(Error::invalid("grid", n as f64, ">= 2"));
        }
        let (nf, margin) = match boundary {
            Boundary::Periodic => (n, 0),
            Boundary::Free => (2 * n, FREE_MARGIN.min(n / 2)),
        };
        // Free: the window's N rows and `margin` rows of padding each side
        // (their response is returned; they are zero on input).
        let mut fft = Fft2::new(nf, n + 2 * margin)?;
        let multiplier = match boundary {
            Boundary::Periodic => periodic_multiplier(n, size, e_star),
            Boundary::Free => free_multiplier(&mut fft, size, e_star)?,
        };
        let mut op = Operator {
            boundary,
            n,
            size,
            e_star,
            fft,
            multiplier,
            spatial: Vec::new(),
            margin,
        };
        if boundary == Boundary::Periodic {
            // The kernel is the response to a unit pressure at node (0, 0).
            let mut spatial = vec![0.0; n * n];
            op.apply_rows(
                &mut |i, row| {
                    row.fill(0.0);
                    if i == 0 {
                        row[0] = 1.0;
                    }
                },
                &mut |i, row| spatial[i * n..(i + 1) * n].copy_from_slice(row),
            )?;
            op.spatial = spatial;
        }
        Ok(op)
    }

    /// Boundary condition.
    pub(crate) fn boundary(&self) -> Boundary {
        self.boundary
    }

    /// Grid side N.
    pub fn n(&self) -> usize {
        self.n
    }

    /// Physical side L.
    pub fn size(&self) -> f64 {
        self.size
    }

    /// Contact modulus E*.
    pub fn e_star(&self) -> f64 {
        self.e_star
    }

    /// Displacements `u = 𝒢 p` (`p`, `u`: `N × N` row-major).
    ///
    /// # Errors
    /// Wrong slice lengths.
    pub fn apply(&mut self, p: &[f64], u: &mut [f64]) -> Result<()> {
        let n = self.n;
        if p.len() != n * n || u.len() != n * n {
            return Err(Error::Inconsistent {
                name: "operator buffers".into(),
                requirement: format!("length N² = {}, got {} and {}", n * n, p.len(), u.len()),
            });
        }
        self.apply_rows(
            &mut |i, row| row.copy_from_slice(&p[i * n..(i + 1) * n]),
            &mut |i, row| u[i * n..(i + 1) * n].copy_from_slice(row),
        )
    }

    /// `u = 𝒢 p` row by row: `fill(i, row)` writes the N pressures of row
    /// `i`, then `emit(i, row)` receives the N displacements of row `i`
    /// (both in increasing `i`; every `fill` runs before the first `emit`).
    /// Lets a caller fuse its own passes over the fields with the transform's.
    ///
    /// # Errors
    /// None in practice: the FFT's sizes are computed here (a failure
    /// would be a bug and panics: `bem::fft`). The `Result` stays for the API.
    pub fn apply_rows(
        &mut self,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        self.apply_symbol_rows(Symbol::Compliance, fill, emit)
    }

    /// Pressures `p = 𝒦 u` of the displacements `u` (`N × N` row-major),
    /// with the half-space stiffness 𝒦 (see [`Operator::apply_stiffness_rows`]).
    ///
    /// # Errors
    /// Wrong slice lengths.
    pub fn apply_stiffness(&mut self, u: &[f64], p: &mut [f64]) -> Result<()> {
        let n = self.n;
        if p.len() != n * n || u.len() != n * n {
            return Err(Error::Inconsistent {
                name: "operator buffers".into(),
                requirement: format!("length N² = {}, got {} and {}", n * n, u.len(), p.len()),
            });
        }
        self.apply_stiffness_rows(
            &mut |i, row| row.copy_from_slice(&u[i * n..(i + 1) * n]),
            &mut |i, row| p[i * n..(i + 1) * n].copy_from_slice(row),
        )
    }

    /// `p = 𝒦 u` row by row (as [`Operator::apply_rows`]): the stiffness of
    /// the half-space, the inverse of the periodic compliance.
    ///
    /// # Formula
    /// ```text
    /// periodic:  p̂(q) = E* |q| û(q) / 2,  q = (2π/L)(k_x, k_y),  p̂(0) = 0   (𝒦 = 𝒢⁻¹ but for the mean)
    /// free:      p̂(k) = û(k) / K̂(k)   on the zero-padded 2N × 2N grid       (the inverse of 𝒢's circulant)
    /// ```
    /// K̂ is the free operator's multiplier (Love's cell kernel embedded in
    /// the 2N × 2N circulant, positive at every k). With the free boundary
    /// 𝒦 inverts 𝒢 for fields on the padded grid; restricted to the N × N
    /// window it is an approximate inverse (used as a preconditioner).
    ///
    /// # Errors
    /// None in practice: the FFT's sizes are computed here (a failure
    /// would be a bug and panics: `bem::fft`). The `Result` stays for the API.
    pub fn apply_stiffness_rows(
        &mut self,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        self.apply_symbol_rows(Symbol::Stiffness { mean: 0.0 }, fill, emit)
    }

    /// [`Operator::apply_stiffness_rows`] with `p̂(0) = mean · û(0)` (a
    /// stiffness for the mean mode, which 𝒦 leaves at 0).
    pub(crate) fn apply_stiffness_rows_with_mean(
        &mut self,
        mean: f64,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        self.apply_symbol_rows(Symbol::Stiffness { mean }, fill, emit)
    }

    /// The stiffness of the longest wave of the grid, `E* Δq / 2` (Δq the
    /// fundamental wavevector of the transform's grid).
    pub(crate) fn fundamental_stiffness(&self) -> f64 {
        let period = self.size * (self.fft.n() / self.n) as f64;
        self.e_star * std::f64::consts::PI / period
    }

    fn apply_symbol_rows(
        &mut self,
        symbol: Symbol,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        let (n, r) = (self.n, self.margin);
        self.apply_symbol_rows_with_margin(symbol, fill, &mut |i, row| {
            if let Ok(i) = usize::try_from(i) {
                if i < n {
                    emit(i, &row[r..r + n]);
                }
            }
        })
    }

    /// `p = 𝒦 u` (with `mean` for the q = 0 mode, as
    /// [`Operator::apply_stiffness_rows_with_mean`]), returning besides the
    /// window the response on the margin of the padding: `emit(i, row)`
    /// receives grid rows `i = −m … N + m − 1` (m = [`FREE_MARGIN`] free, 0
    /// periodic), each with the `N + 2m` columns `−m … N + m − 1`. Inputs
    /// are zero on the padding, as in every free application.
    pub(crate) fn apply_stiffness_rows_with_margin(
        &mut self,
        mean: f64,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(isize, &[f64]),
    ) -> Result<()> {
        self.apply_symbol_rows_with_margin(Symbol::Stiffness { mean }, fill, emit)
    }

    /// Rows of padding kept on each side of the window (0 periodic).
    pub(crate) fn margin(&self) -> usize {
        self.margin
    }

    fn apply_symbol_rows_with_margin(
        &mut self,
        symbol: Symbol,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(isize, &[f64]),
    ) -> Result<()> {
        let (n, r) = (self.n, self.margin);
        let nf = self.fft.n();
        let half = nf / 2 + 1;
        let multiplier = &self.multiplier;
        let norm = 1.0 / (nf as f64 * nf as f64);
        let dq = std::f64::consts::TAU / (self.size * (nf / n) as f64);
        let (e_star, boundary) = (self.e_star, self.boundary);
        self.fft.convolve(
            &mut |i, row| {
                if (r..r + n).contains(&i) {
                    row[..r].fill(0.0);
                    fill(i - r, &mut row[r..r + n]);
                    row[r + n..].fill(0.0);
                } else {
                    row.fill(0.0);
                }
            },
            &mut |kj, col| {
                let m = &multiplier[kj * half..(kj + 1) * half];
                match symbol {
                    Symbol::Compliance => scale_column(col, half, |ki| m[ki]),
                    Symbol::Stiffness { mean } => {
                        let k2 = (kj * kj) as f64;
                        match boundary {
                            // 𝒢's own multiplier times (E*q/2)²: no square root.
                            Boundary::Periodic => {
                                let c = (0.5 * e_star * dq).powi(2);
                                let zero = if kj == 0 { mean * norm } else { 0.0 };
                                scale_column(col, half, |ki| {
                                    if ki == 0 && kj == 0 {
                                        zero
                                    } else {
                                        m[ki] * c * ((ki * ki) as f64 + k2)
                                    }
                                })
                            }
                            // The inverse of the 2N circulant (its
                            // multiplier is positive: ≥ 1.82 c at the
                            // Nyquist corner, measured for N = 32 … 512).
                            Boundary::Free => {
                                let c = norm * norm;
                                scale_column(col, half, |ki| c / m[ki])
                            }
                        }
                    }
                }
            },
            Some(&mut |i, row| emit(i as isize - r as isize, &row[..n + 2 * r])),
        );
        Ok(())
    }

    /// Add `𝒢 c` for a sparse `c` (values `c[k]` at flat indices `idx[k]`)
    /// to `u` by direct summation: `m·N²` operations instead of two FFTs.
    /// Returns `false` (and leaves `u` alone) for the free operator, which
    /// keeps no real-space kernel.
    pub(crate) fn add_sparse(&self, idx: &[usize], c: &[f64], u: &mut [f64]) -> bool {
        if self.spatial.is_empty() {
            return false;
        }
        let n = self.n;
        for (i, urow) in u.chunks_exact_mut(n).enumerate() {
            for (&k, &ck) in idx.iter().zip(c) {
                let (ki, kj) = (k / n, k % n);
                let di = (i + n - ki) % n;
                let krow = &self.spatial[di * n..(di + 1) * n];
                // u[i, j] += c k[di, (j − kj) mod N]: two contiguous runs.
                let (head, tail) = urow.split_at_mut(kj);
                for (x, y) in tail.iter_mut().zip(&krow[..n - kj]) {
                    *x += ck * y;
                }
                for (x, y) in head.iter_mut().zip(&krow[n - kj..]) {
                    *x += ck * y;
                }
            }
        }
        true
    }

    /// The energy product `⟨a, 𝒢 b⟩ = Σ a_i (𝒢b)_i Δ²` (work units: force × length).
    ///
    /// `work` is an `N × N` buffer used for `𝒢 b`.
    ///
    /// # Errors
    /// Wrong slice lengths.
    pub fn energy_product(&mut self, a: &[f64], b: &[f64], work: &mut [f64]) -> Result<f64> {
        self.apply(b, work)?;
        let da = (self.size / self.n as f64).powi(2);
        Ok(a.iter().zip(work.iter()).map(|(x, y)| x * y).sum::<f64>() * da)
    }
}

/// Which symbol a convolution multiplies by.
#[derive(Debug, Clone, Copy)]
enum Symbol {
    /// The operator's own multiplier (𝒢).
    Compliance,
    /// The half-space stiffness E*|q|/2 (𝒦), with `mean` for the q = 0 mode.
    Stiffness { mean: f64 },
}

/// Multiply a column of the spectrum (`n_f` values over k_i) by `f(k)`,
/// `k = min(k_i, n_f − k_i)` the multiplier index (both kernels are even).
#[inline(always)]
fn scale_column(col: &mut [Complex64], half: usize, f: impl Fn(usize) -> f64) {
    let (low, high) = col.split_at_mut(half);
    for (ki, z) in low.iter_mut().enumerate() {
        *z *= f(ki);
    }
    // k_i = n_f − 1 … half  ↔  multiplier index 1 … n_f − half.
    for (z, ki) in high.iter_mut().rev().zip(1..) {
        *z *= f(ki);
    }
}

/// The periodic operator's multiplier `2/(E*|q|)/N²` (half rows, `k_i ≤ N/2`).
fn periodic_multiplier(n: usize, size: f64, e_star: f64) -> Vec<f64> {
    let (nc, half) = (n / 2 + 1, n / 2 + 1);
    let dq = std::f64::consts::TAU / size;
    let norm = 1.0 / (n as f64 * n as f64);
    let mut m = vec![0.0; nc * half];
    for kj in 0..nc {
        for ki in 0..half {
            let q = dq * ((ki * ki + kj * kj) as f64).sqrt();
            m[kj * half + ki] = if q > 0.0 {
                2.0 / (e_star * q) * norm
            } else {
                0.0
            };
        }
    }
    m
}

/// The free operator's multiplier (half rows, `k_i ≤ N`), from the 2N × 2N
/// circulant Love kernel: its top and bottom N rows are transformed
/// separately by the pruned FFT and combined, `K̂ = F(top) + (−1)^{k_i}
/// F(bottom)` (a shift by N rows).
fn free_multiplier(fft: &mut Fft2, size: f64, e_star: f64) -> Result<Vec<f64>> {
    let nf = fft.n();
    let n = nf / 2;
    let (nc, half) = (fft.nc(), nf / 2 + 1);
    let c = size / n as f64 / (std::f64::consts::PI * e_star);
    let norm = 1.0 / (nf as f64 * nf as f64);
    let mut m = vec![0.0; nc * half];
    for part in 0..2 {
        fft.convolve(
            &mut |i, row| {
                // Rows past N (the operator's margin) are zero.
                if i >= n {
                    row.fill(0.0);
                    return;
                }
                let si = signed(i + part * n, nf) as f64;
                for (j, v) in row.iter_mut().enumerate() {
                    *v = c * love_cell(si, signed(j, nf) as f64);
                }
            },
            &mut |kj, col| {
                for (ki, z) in col[..half].iter().enumerate() {
                    let sign = if part == 1 && ki % 2 == 1 { -1.0 } else { 1.0 };
                    m[kj * half + ki] += sign * z.re * norm;
                }
            },
            None,
        );
    }
    Ok(m)
}

/// FFT index `k ∈ 0 … n` to the signed frequency `k` or `k − n`
/// (the Nyquist index `n/2` stays positive).
pub(crate) fn signed(k: usize, n: usize) -> i64 {
    if k <= n / 2 {
        k as i64
    } else {
        k as i64 - n as i64
    }
}

/// `∫∫ dx' dy' / |x − x'|` over the unit cell centred at the origin, at the
/// point `(x, y)` in cell units (Love's rectangle formula).
///
/// # Formula
/// ```text
/// I(X, Y) = sgn X sgn Y (|X| asinh(|Y|/|X|) + |Y| asinh(|X|/|Y|)) = ∫₀^X∫₀^Y dx dy / r
/// ∫∫_cell = I(x+½, y+½) − I(x−½, y+½) − I(x+½, y−½) + I(x−½, y−½)
/// ```
/// At the centre of the cell the value is 4 asinh(1) = 3.5255.
pub(crate) fn love_cell(x: f64, y: f64) -> f64 {
    corner(x + 0.5, y + 0.5) - corner(x - 0.5, y + 0.5) - corner(x + 0.5, y - 0.5)
        + corner(x - 0.5, y - 0.5)
}

fn corner(x: f64, y: f64) -> f64 {
    let (ax, ay) = (x.abs(), y.abs());
    if ax == 0.0 || ay == 0.0 {
        return 0.0;
    }
    let v = ax * (ay / ax).asinh() + ay * (ax / ay).asinh();
    v * x.signum() * y.signum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding of a few FFT round trips.
    const FFT_TOL: f64 = 1e-12;

    #[test]
    fn love_cell_centre_and_far_field() {
        // Centre: 4 asinh(1) (closed form of ∫∫ 1/r over a unit square from its centre).
        assert!((love_cell(0.0, 0.0) - 4.0 * 1f64.asinh()).abs() < 1e-15);
        // Far field on an axis: Taylor expansion of the cell average,
        // 1/r + ∇²(1/r)/24 + [(∂⁴x + ∂⁴y)/1920 + ∂²x∂²y/576](1/r) + O(r⁻⁷)
        // = 1/r + 1/(24 r³) + (33/1920 − 12/576)/r⁵. The corner sum loses
        // ~r·ln r / (1/r) ≈ 6e3 ulps at r = 40: tolerance 1e-12 absolute.
        let r: f64 = 40.0;
        let v = love_cell(r, 0.0);
        let series =
            1.0 / r + 1.0 / (24.0 * r.powi(3)) + (33.0 / 1920.0 - 12.0 / 576.0) / r.powi(5);
        assert!((v - series).abs() < 1e-12, "{:e}", v - series);
    }

    #[test]
    fn periodic_operator_on_cosines() {
        // p = Σ cos(2π(k_x x + k_y y)/L): u = Σ 2p_k/(E*|q_k|), |q| = 2π|k|/L.
        // Odd and even grids; at 256² the column blocks of the transform are
        // 63, 63 and 3 columns wide, and the modes land in the first and last.
        let (l, e) = (2.0, 3.0);
        for (n, modes) in [
            (15, vec![(3.0, 4.0)]),
            (32, vec![(3.0, 4.0), (-5.0, 16.0)]),
            (256, vec![(3.0, 4.0), (-70.0, 127.0), (1.0, 128.0)]),
        ] {
            let mut op = Operator::new(Boundary::Periodic, n, l, e).unwrap();
            let wave = |k: usize, kx: f64, ky: f64| {
                let (i, j) = ((k / n) as f64, (k % n) as f64);
                (std::f64::consts::TAU * (kx * i + ky * j) / n as f64).cos()
            };
            let p: Vec<f64> = (0..n * n)
                .map(|k| modes.iter().map(|&(a, b)| wave(k, a, b)).sum())
                .collect();
            let mut u = vec![0.0; n * n];
            op.apply(&p, &mut u).unwrap();
            let err = (0..n * n)
                .map(|k| {
                    let exact: f64 = modes
                        .iter()
                        .map(|&(a, b)| {
                            let q = std::f64::consts::TAU * f64::hypot(a, b) / l;
                            2.0 / (e * q) * wave(k, a, b)
                        })
                        .sum();
                    (exact - u[k]).abs()
                })
                .fold(0.0, f64::max);
            assert!(err < FFT_TOL, "n = {n}: {err:e}");
        }
    }

    #[test]
    fn free_operator_equals_direct_sum() {
        // Free operator against the direct sum of Love's cell kernel: every
        // node at 12², and a diagonal of nodes at 100² (a 200-point padded
        // transform, processed in several column blocks).
        let (l, e) = (1.5, 2.0);
        for (n, stride) in [(12, 1), (100, 101)] {
            let mut op = Operator::new(Boundary::Free, n, l, e).unwrap();
            let p: Vec<f64> = (0..n * n).map(|k| ((k * 7 % 11) as f64) * 0.1).collect();
            let mut u = vec![0.0; n * n];
            op.apply(&p, &mut u).unwrap();
            let c = l / n as f64 / (std::f64::consts::PI * e);
            for node in (0..n * n).step_by(stride) {
                let (i, j) = ((node / n) as f64, (node % n) as f64);
                let s: f64 = (0..n * n)
                    .map(|k| {
                        let (a, b) = ((k / n) as f64, (k % n) as f64);
                        c * love_cell(i - a, j - b) * p[k]
                    })
                    .sum();
                assert!(
                    (s - u[node]).abs() < FFT_TOL * s.abs().max(1.0),
                    "n = {n}, node {node}: {s} vs {}",
                    u[node]
                );
            }
        }
    }

    #[test]
    fn periodic_stiffness_inverts_the_compliance() {
        // 𝒦𝒢p = p − mean(p): the two multipliers multiply to 1 on every
        // mode but the mean (odd and even grids).
        for n in [15, 64] {
            let mut op = Operator::new(Boundary::Periodic, n, 2.0, 3.0).unwrap();
            let p: Vec<f64> = (0..n * n).map(|k| ((k * 7 % 11) as f64) * 0.1).collect();
            let mean = p.iter().sum::<f64>() / (n * n) as f64;
            let (mut u, mut back) = (vec![0.0; n * n], vec![0.0; n * n]);
            op.apply(&p, &mut u).unwrap();
            op.apply_stiffness(&u, &mut back).unwrap();
            let err = p
                .iter()
                .zip(&back)
                .map(|(a, b)| (a - mean - b).abs())
                .fold(0.0, f64::max);
            assert!(err < FFT_TOL, "n = {n}: {err:e}");
        }
    }

    /// The free stiffness on the window and its margin against the inverse
    /// of the 2N circulant computed by direct DFTs (no pruned transform, no
    /// shift): every node of the window and margin, for unit pressures at
    /// corners and edges of the window, where the margin's values wrap.
    #[test]
    fn free_stiffness_margin_equals_the_circulant_inverse() {
        use std::f64::consts::TAU;
        let (n, l, e) = (8usize, 1.5, 2.0);
        let m2 = 2 * n;
        let c = l / n as f64 / (std::f64::consts::PI * e);
        // K̂(q) = Σ_d K(d) cos(2π q·d / 2N) (the kernel is even: real).
        let kernel = |a: usize, b: usize| c * love_cell(signed(a, m2) as f64, signed(b, m2) as f64);
        let mut symbol = vec![0.0; m2 * m2];
        for (q, v) in symbol.iter_mut().enumerate() {
            let (qa, qb) = (q / m2, q % m2);
            for d in 0..m2 * m2 {
                let (da, db) = (d / m2, d % m2);
                let phase = TAU * ((qa * da + qb * db) % m2) as f64 / m2 as f64;
                *v += kernel(da, db) * phase.cos();
            }
        }
        // s(d) = (1/(2N)²) Σ_q cos(2π q·d / 2N) / K̂(q).
        let stiffness = |da: usize, db: usize| {
            let mut acc = 0.0;
            for (q, v) in symbol.iter().enumerate() {
                let (qa, qb) = (q / m2, q % m2);
                let phase = TAU * ((qa * da + qb * db) % m2) as f64 / m2 as f64;
                acc += phase.cos() / v;
            }
            acc / (m2 * m2) as f64
        };
        let mut op = Operator::new(Boundary::Free, n, l, e).unwrap();
        let r = op.margin();
        assert_eq!(r, FREE_MARGIN);
        let w = n + 2 * r;
        let diagonal = stiffness(0, 0);
        for (i0, j0) in [(0, 0), (0, n - 1), (n - 1, 3), (4, 4)] {
            let mut x = vec![f64::NAN; w * w];
            op.apply_stiffness_rows_with_margin(
                0.0,
                &mut |i, row| {
                    row.fill(0.0);
                    if i == i0 {
                        row[j0] = 1.0;
                    }
                },
                &mut |i, row| {
                    let i = usize::try_from(i + r as isize).unwrap();
                    x[i * w..(i + 1) * w].copy_from_slice(row);
                },
            )
            .unwrap();
            for (k, &v) in x.iter().enumerate() {
                // Grid offsets from the unit pressure, on the 2N torus.
                let (a, b) = ((k / w) as isize - r as isize, (k % w) as isize - r as isize);
                let da = (a - i0 as isize).rem_euclid(m2 as isize) as usize;
                let db = (b - j0 as isize).rem_euclid(m2 as isize) as usize;
                let s = stiffness(da, db);
                assert!(
                    (v - s).abs() <= FFT_TOL * diagonal,
                    "unit at ({i0}, {j0}), node ({a}, {b}): {v} vs {s}"
                );
            }
        }
    }

    #[test]
    fn stiffness_is_symmetric_positive_definite() {
        // ⟨x, 𝒦y⟩ = ⟨𝒦x, y⟩ and ⟨x, 𝒦x⟩ > 0 for fields of the N × N window
        // (free: the inverse of the 2N circulant restricted to the window);
        // with a mean stiffness w, 𝒦1 = w (periodic).
        for boundary in [Boundary::Periodic, Boundary::Free] {
            let n = 24;
            let mut op = Operator::new(boundary, n, 1.5, 2.0).unwrap();
            let x: Vec<f64> = (0..n * n).map(|k| ((k * 7 % 11) as f64) - 5.0).collect();
            let y: Vec<f64> = (0..n * n).map(|k| ((k * 5 % 13) as f64) - 6.0).collect();
            let (mut kx, mut ky) = (vec![0.0; n * n], vec![0.0; n * n]);
            op.apply_stiffness(&x, &mut kx).unwrap();
            op.apply_stiffness(&y, &mut ky).unwrap();
            let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(u, v)| u * v).sum::<f64>();
            let (xky, kxy) = (dot(&x, &ky), dot(&kx, &y));
            assert!(
                (xky - kxy).abs() < FFT_TOL * xky.abs().max(1.0),
                "{boundary:?}"
            );
            assert!(dot(&x, &kx) > 0.0, "{boundary:?}");
        }
        let n = 16;
        let mut op = Operator::new(Boundary::Periodic, n, 1.0, 2.0).unwrap();
        let w = op.fundamental_stiffness();
        assert!((w - 2.0 * std::f64::consts::PI).abs() < 1e-15); // E* π / L
        let mut k1 = vec![0.0; n * n];
        op.apply_stiffness_rows_with_mean(w, &mut |_, row| row.fill(1.0), &mut |i, row| {
            k1[i * n..(i + 1) * n].copy_from_slice(row)
        })
        .unwrap();
        assert!(k1.iter().all(|v| (v - w).abs() < FFT_TOL * w));
    }
}

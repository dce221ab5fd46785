//! Two-dimensional real FFT on square grids, planned once and reused.
//!
//! # Conventions
//! A real field `x` of `n × n` values is stored row-major (`x[i·n + j]`,
//! `i` the row). The forward transform is unnormalised,
//! ```text
//! X(k_i, k_j) = Σ_{i,j} x[i, j] e^{−2πi (k_i i + k_j j)/n}
//! ```
//! and only the half spectrum `k_j = 0 … n/2` is kept (the rest follows from
//! Hermitian symmetry). In [`Fft2`] the half spectrum is stored
//! **transposed**, `spec[k_j·n + k_i]`, because the column FFTs then run over
//! contiguous memory in one batched call. The inverse applies no `1/n²`
//! factor: callers fold it into their multiplier (see [`super::kernel`]).
//!
//! Only the first `rows ≤ n` rows of the real field are used: the forward
//! transform treats rows `rows … n` as zero and the inverse returns only the
//! first `rows` rows. With `rows = n/2` this is the pruned transform of a
//! zero-padded field (free-boundary operator), saving the row transforms of
//! the padding.
//!
//! [`Fft2::convolve`] multiplies by a spectral multiplier without ever
//! holding the whole spectrum: the rows are transformed into the row spectra
//! (`rows × (n/2+1)`), then the columns are processed in blocks of a few
//! columns (forward FFT, multiplier, inverse FFT) in a buffer that stays in
//! the L2 cache, then the rows are transformed back. It needs no
//! `(n/2+1)·n` spectrum buffer and no transposes of it: a periodic 𝒢p
//! (`cargo bench --bench bem -- apply`, median) took 13.6 ms at 1024² and
//! 1.73 ms at 512² as two full transforms, 9.7 ms and 1.39 ms this way.
//!
//! No allocation happens after [`Fft2::new`]: all scratch space is owned.
//!
//! The plans come from the crate's one FFT module (`src/fft.rs`), which
//! plans each length once; a realfft failure on the lengths planned is a
//! bug and panics there (its module docs say why), so only the lengths of
//! buffers a caller passes are errors here.

use std::sync::Arc;

use realfft::{ComplexToReal, RealToComplex};
pub use rustfft::num_complex::Complex64;
use rustfft::Fft;

use crate::error::{Error, Result};
use crate::fft::{complex, forward_row, real_forward, real_inverse, LENGTHS};

/// Bytes of the column block of [`Fft2::convolve`]: a quarter of the 1 MiB
/// L2 cache of this machine's cores (the block and the rustfft scratch stay
/// in L2). Median periodic 𝒢p (`cargo bench --bench bem -- apply`) with
/// 2¹⁶ / 2¹⁸ / 2²⁰ bytes: 1.54 / 1.39 / 1.59 ms at 512², 9.57 / 9.70 /
/// 11.2 ms at 1024² (13.6 ms with the full transposed spectrum).
const BLOCK_BYTES: usize = 1 << 18;

/// A consumer of the rows of an inverse transform: `(row index, row)`.
type RowSink<'a> = &'a mut dyn FnMut(usize, &[f64]);

/// A planned 2-D real FFT of an `n × n` grid whose first `rows` rows are live.
pub struct Fft2 {
    n: usize,
    rows: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    fwd: Arc<dyn Fft<f64>>,
    inv: Arc<dyn Fft<f64>>,
    /// Row spectra, `rows × (n/2 + 1)`.
    rowspec: Vec<Complex64>,
    scratch: Vec<Complex64>,
    /// A block of whole columns of the spectrum, `width × n` (convolve).
    block: Vec<Complex64>,
    /// One real row (convolve).
    row: Vec<f64>,
}

impl std::fmt::Debug for Fft2 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Fft2")
            .field("n", &self.n)
            .field("rows", &self.rows)
            .finish()
    }
}

impl Fft2 {
    /// Plan the transforms of an `n × n` grid with `rows` live rows.
    ///
    /// # Errors
    /// `n < 2` or `rows` not in `1 ..= n`.
    pub fn new(n: usize, rows: usize) -> Result<Self> {
        if n < 2 || rows == 0 || rows > n {
            return Err(Error::Inconsistent {
                name: "fft size".into(),
                requirement: format!("n >= 2 and 1 <= rows <= n, got n = {n}, rows = {rows}"),
            });
        }
        let (r2c, c2r) = (real_forward(n), real_inverse(n));
        let (fwd, inv) = (complex(n, false), complex(n, true));
        let len = [
            r2c.get_scratch_len(),
            c2r.get_scratch_len(),
            fwd.get_inplace_scratch_len(),
            inv.get_inplace_scratch_len(),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        let nc = n / 2 + 1;
        Ok(Fft2 {
            n,
            rows,
            r2c,
            c2r,
            fwd,
            inv,
            rowspec: vec![Complex64::new(0.0, 0.0); rows * nc],
            scratch: vec![Complex64::new(0.0, 0.0); len],
            block: vec![Complex64::new(0.0, 0.0); column_block(n, nc)],
            row: vec![0.0; n],
        })
    }

    /// Grid side `n`.
    pub(crate) fn n(&self) -> usize {
        self.n
    }

    /// Number of half-spectrum columns, `n/2 + 1`.
    pub(crate) fn nc(&self) -> usize {
        self.n / 2 + 1
    }

    /// Length of the transposed half spectrum, `(n/2 + 1)·n`.
    pub fn spectrum_len(&self) -> usize {
        self.nc() * self.n
    }

    /// Forward transform of the first `rows` rows of `x` (`rows × n`,
    /// overwritten as scratch) into `spec` (`(n/2+1) × n`, transposed).
    ///
    /// # Errors
    /// [`Error::Inconsistent`] for buffers of the wrong lengths.
    pub fn forward(&mut self, x: &mut [f64], spec: &mut [Complex64]) -> Result<()> {
        let (n, nc, rows) = (self.n, self.nc(), self.rows);
        if x.len() != rows * n || spec.len() != nc * n {
            return Err(length_error("forward", x.len(), spec.len()));
        }
        for (xr, sr) in x.chunks_exact_mut(n).zip(self.rowspec.chunks_exact_mut(nc)) {
            forward_row(&*self.r2c, xr, sr, &mut self.scratch);
        }
        gather(&self.rowspec, nc, 0, nc, spec, n, n);
        self.fwd.process_with_scratch(spec, &mut self.scratch);
        Ok(())
    }

    /// Inverse transform of `spec` (overwritten) into the first `rows` rows of
    /// `x` (`rows × n`), without the `1/n²` factor.
    ///
    /// # Errors
    /// [`Error::Inconsistent`] for buffers of the wrong lengths.
    pub fn inverse(&mut self, spec: &mut [Complex64], x: &mut [f64]) -> Result<()> {
        let (n, nc, rows) = (self.n, self.nc(), self.rows);
        if x.len() != rows * n || spec.len() != nc * n {
            return Err(length_error("inverse", x.len(), spec.len()));
        }
        self.inv.process_with_scratch(spec, &mut self.scratch);
        scatter(spec, n, 0, nc, &mut self.rowspec, nc);
        let even = n.is_multiple_of(2);
        for (sr, xr) in self.rowspec.chunks_exact_mut(nc).zip(x.chunks_exact_mut(n)) {
            // The DC (and, for even n, Nyquist) bins of a real row are real;
            // rounding leaves ~1e-17 imaginary parts that c2r rejects.
            sr[0].im = 0.0;
            if even {
                sr[nc - 1].im = 0.0;
            }
            self.c2r
                .process_with_scratch(sr, xr, &mut self.scratch)
                .expect(LENGTHS);
        }
        Ok(())
    }

    /// Convolution through the spectrum, one block of columns at a time.
    ///
    /// `fill(i, row)` writes real row `i < rows` (all `n` values; rows
    /// `rows … n` are zero). `multiply(k_j, column)` is called once per
    /// half-spectrum column `k_j = 0 … n/2` with its `n` values over `k_i`
    /// (unnormalised forward transform) and may change them. If `emit` is
    /// given, the result is transformed back (without the `1/n²` factor)
    /// and `emit(i, row)` receives each of the first `rows` rows in order.
    pub fn convolve(
        &mut self,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        multiply: &mut dyn FnMut(usize, &mut [Complex64]),
        emit: Option<RowSink<'_>>,
    ) {
        let (n, nc) = (self.n, self.nc());
        for (i, sr) in self.rowspec.chunks_exact_mut(nc).enumerate() {
            fill(i, &mut self.row);
            forward_row(&*self.r2c, &mut self.row, sr, &mut self.scratch);
        }
        // Columns of the block are `ld = n + PAD` apart: a power-of-two
        // stride would map a gather's writes to one cache set.
        let ld = n + PAD;
        let width = (self.block.len() + PAD) / ld;
        for c0 in (0..nc).step_by(width) {
            let w = width.min(nc - c0);
            gather(&self.rowspec, nc, c0, w, &mut self.block, ld, n);
            for c in 0..w {
                let col = &mut self.block[c * ld..c * ld + n];
                self.fwd.process_with_scratch(col, &mut self.scratch);
                multiply(c0 + c, col);
                if emit.is_some() {
                    self.inv.process_with_scratch(col, &mut self.scratch);
                }
            }
            if emit.is_some() {
                scatter(&self.block, ld, c0, w, &mut self.rowspec, nc);
            }
        }
        let Some(emit) = emit else {
            return;
        };
        let even = n.is_multiple_of(2);
        for (i, sr) in self.rowspec.chunks_exact_mut(nc).enumerate() {
            // The DC (and, for even n, Nyquist) bins of a real row are real;
            // rounding leaves ~1e-17 imaginary parts that c2r rejects.
            sr[0].im = 0.0;
            if even {
                sr[nc - 1].im = 0.0;
            }
            self.c2r
                .process_with_scratch(sr, &mut self.row, &mut self.scratch)
                .expect(LENGTHS);
            emit(i, &self.row);
        }
    }
}

/// Padding between the columns of the block (4 complex values = 64 bytes).
const PAD: usize = 4;

/// Rows per tile of the gather and scatter: one 64-byte line of a column.
const LINE: usize = 4;

/// Length of the column block of [`Fft2::convolve`]: as many columns of
/// `n` complex values (`n + PAD` apart) as fit in [`BLOCK_BYTES`], at least
/// 1, at most `nc`.
fn column_block(n: usize, nc: usize) -> usize {
    let width = (BLOCK_BYTES / (16 * (n + PAD))).clamp(1, nc);
    width * (n + PAD) - PAD
}

/// Columns `c0 … c0+w` of the `rows × nc` row spectra `src` into columns of
/// length `n` (`ld` apart) of `block`: `block[c·ld + r] = src[r·nc + c0 + c]`
/// for `r < rows` and zero for `r ∈ rows … n` (the padding of a pruned
/// transform), a cache line of each column at a time.
fn gather(
    src: &[Complex64],
    nc: usize,
    c0: usize,
    w: usize,
    block: &mut [Complex64],
    ld: usize,
    n: usize,
) {
    let rows = src.len() / nc;
    for r0 in (0..rows).step_by(LINE) {
        let r1 = (r0 + LINE).min(rows);
        for c in 0..w {
            for r in r0..r1 {
                block[c * ld + r] = src[r * nc + c0 + c];
            }
        }
    }
    if rows < n {
        for c in 0..w {
            block[c * ld + rows..c * ld + n].fill(Complex64::new(0.0, 0.0));
        }
    }
}

/// The inverse of [`gather`] for the rows of `dst`.
fn scatter(block: &[Complex64], ld: usize, c0: usize, w: usize, dst: &mut [Complex64], nc: usize) {
    let rows = dst.len() / nc;
    for r0 in (0..rows).step_by(LINE) {
        let r1 = (r0 + LINE).min(rows);
        for c in 0..w {
            for r in r0..r1 {
                dst[r * nc + c0 + c] = block[c * ld + r];
            }
        }
    }
}

fn length_error(what: &str, real: usize, spec: usize) -> Error {
    Error::Inconsistent {
        name: format!("fft {what} buffers"),
        requirement: format!("lengths rows·n and (n/2+1)·n, got {real} and {spec}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Round trip of a pseudo-random field: rounding only (deps.md §4 saw 1e-14).
    const ROUND_TRIP_TOL: f64 = 1e-13;

    fn field(n: usize, rows: usize) -> Vec<f64> {
        (0..rows * n)
            .map(|k| ((k as f64 * 0.7548776662).fract() - 0.5) * 3.0)
            .collect()
    }

    #[test]
    fn round_trip_even_and_odd() {
        for (n, rows) in [(16, 16), (15, 15), (32, 16), (64, 40)] {
            let x0 = field(n, rows);
            let mut x = x0.clone();
            let mut f = Fft2::new(n, rows).unwrap();
            let mut s = vec![Complex64::new(0.0, 0.0); f.spectrum_len()];
            f.forward(&mut x, &mut s).unwrap();
            let mut y = vec![0.0; rows * n];
            f.inverse(&mut s, &mut y).unwrap();
            let scale = 1.0 / (n * n) as f64;
            let err = x0
                .iter()
                .zip(&y)
                .map(|(a, b)| (a - b * scale).abs())
                .fold(0.0, f64::max);
            assert!(err < ROUND_TRIP_TOL, "n = {n}, rows = {rows}: {err:e}");
        }
    }

    #[test]
    fn single_mode_lands_in_its_bin() {
        // x = cos(2π(2 i + 3 j)/n): X(2, 3) = n²/2 in the half spectrum.
        let n = 16;
        let mut x: Vec<f64> = (0..n * n)
            .map(|k| {
                let (i, j) = ((k / n) as f64, (k % n) as f64);
                (std::f64::consts::TAU * (2.0 * i + 3.0 * j) / n as f64).cos()
            })
            .collect();
        let mut f = Fft2::new(n, n).unwrap();
        let mut s = vec![Complex64::new(0.0, 0.0); f.spectrum_len()];
        f.forward(&mut x, &mut s).unwrap();
        let v = s[3 * n + 2];
        assert!((v.re - (n * n) as f64 / 2.0).abs() < 1e-10 && v.im.abs() < 1e-10);
        let total: f64 = s.iter().map(|c| c.norm()).sum();
        assert!((total - v.norm()).abs() < 1e-9);
    }
}

//! Rigid rough surfaces on periodic grids: Fourier synthesis from a spectrum,
//! and height maps read from `.npy` or text files (through [`crate::io`],
//! the readers the measured surfaces use too).
//!
//! Heights are those of the rigid rough surface, pointing towards the
//! elastic body (its peaks touch first), in the unit of the side `L`.
//!
//! # Formula (synthesis)
//! A periodic `L × L` surface is the Fourier series
//! `h(x) = Σ_q h_q e^{i q·x}`, `q = (2π/L)(k_x, k_y)`, `h_{−q} = h_q*`.
//! With Persson's normalisation (the crate docs, Conventions; docs/conventions.md)
//! ```text
//! C(q) = (2π)⁻² ∫ d²x ⟨h(x)h(0)⟩ e^{−iq·x}   ⇒   ⟨|h_q|²⟩ = (2π/L)² C(|q|)
//! ```
//! (each mode stands for the cell of area (2π/L)² around it). The synthesis
//! uses the cell average instead of the point value,
//! ```text
//! ⟨|h_q|²⟩ = ∫_cell(q) C(|q'|) d²q'      (4 × 4 Gauss–Legendre per cell)
//! ```
//! so that `⟨h²⟩ = Σ_q ⟨|h_q|²⟩ = ∫ C d²q = 2π ∫ q C dq` holds in expectation
//! over the band the grid resolves (all of it when `q_max ≤ (N−1)π/L` and
//! `q_min ≥ √2 π/L`; the cell of q = 0 is dropped, the surface has zero mean),
//! and `⟨|∇h|²⟩ = Σ |q|² ⟨|h_q|²⟩` equals `2π ∫ q³ C dq` up to
//! O((2π/L)²/q²) per cell. Modes are `h_q = √(v/2)(ξ₁ + iξ₂)` with
//! independent standard normals ξ (real `√v ξ₁` for the self-conjugate
//! Nyquist modes).
//!
//! # Reproducibility
//! The normals come from `rand_pcg::Pcg64Mcg::seed_from_u64(seed)` (a
//! value-stable generator) through an in-house Box–Muller transform: each
//! mode consumes two `next_u64` draws, `u = ((x >> 11) + ½)·2⁻⁵³`,
//! `ξ₁ + iξ₂ = √(−2 ln u₁) e^{2πi u₂}`, in the order of the half spectrum
//! (`k_y = 0 … N/2` outer, `k_x = 0 … N−1` inner, skipping the conjugate
//! half). A seed gives the same surface in every version of this crate.
//!
//! # References
//! Persson, Bucher & Chiaia, PRB 65, 184106 (2002) (normalisation);
//! the crate docs, Conventions (docs/conventions.md).

use std::path::Path;

use rand_core::{Rng, SeedableRng};
use rand_pcg::Pcg64Mcg;
use rustfft::num_complex::Complex64;

use super::fft::Fft2;
use super::kernel::signed;
use crate::error::{check, Error, Result};
use crate::spectrum::anisotropic::SlopeTensor;
use crate::spectrum::{Radial, Spectrum, Spectrum2d};

/// A periodic height map on the BEM's `N × N` grid of side `size`: the rigid
/// rough surface of a solve (a measured map of any shape is a
/// `persson::topography::Topography`).
#[derive(Debug, Clone, PartialEq)]
pub struct GridSurface {
    /// Grid side N.
    pub n: usize,
    /// Physical side L.
    pub size: f64,
    /// Heights, row-major `N × N` (unit of L).
    pub heights: Vec<f64>,
}

impl GridSurface {
    /// A surface from heights, checked: square, `N ≥ 8`, finite.
    ///
    /// # Errors
    /// Wrong length, non-finite height or size; [`Error::Inconsistent`]
    /// naming `heights` for a map of fewer than 8 × 8 points (or more than
    /// 32768 × 32768), saying how many it has: the map is the user's input
    /// here, not a grid option (3.21 of the issue-37 audit: "grid = 3" for a
    /// 3 × 3 map).
    pub fn new(n: usize, size: f64, heights: Vec<f64>) -> Result<Self> {
        check::positive("size", size)?;
        if !(super::MIN_GRID..=super::MAX_GRID).contains(&n) {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!(
                    "a square map of {0} × {0} to {1} × {1} points for the BEM; this one is \
                     {n} × {n}",
                    super::MIN_GRID,
                    super::MAX_GRID
                ),
            });
        }
        if heights.len() != n * n {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!("{n}×{n} = {} values, got {}", n * n, heights.len()),
            });
        }
        if let Some(k) = heights.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid(
                format!("height[{}, {}]", k / n, k % n),
                heights[k],
                "finite",
            ));
        }
        Ok(GridSurface { n, size, heights })
    }

    /// rms height about the mean, `sqrt(Σ(h − h̄)²/N²)`.
    pub fn rms_height(&self) -> f64 {
        let n2 = self.heights.len() as f64;
        let m = self.heights.iter().sum::<f64>() / n2;
        (self.heights.iter().map(|h| (h - m).powi(2)).sum::<f64>() / n2).sqrt()
    }

    /// rms slope of the trigonometric interpolant, `sqrt(Σ_q |q|² |h_q|²)`.
    ///
    /// # Errors
    /// None in practice: the FFT's sizes are computed here (a failure
    /// would be a bug and panics: `bem::fft`). The `Result` stays for the API.
    pub fn rms_slope(&self) -> Result<f64> {
        let n = self.n;
        let mut fft = Fft2::new(n, n)?;
        let mut x = self.heights.clone();
        let mut spec = vec![Complex64::new(0.0, 0.0); fft.spectrum_len()];
        fft.forward(&mut x, &mut spec)?;
        let dq = std::f64::consts::TAU / self.size;
        let nc = fft.nc();
        let mut s = 0.0;
        for kj in 0..nc {
            // Columns 1 … ceil(n/2)−1 stand for themselves and their conjugates.
            let w = if kj == 0 || (n.is_multiple_of(2) && kj == n / 2) {
                1.0
            } else {
                2.0
            };
            for ki in 0..n {
                let kx = signed(ki, n) as f64;
                let q2 = dq * dq * (kx * kx + (kj * kj) as f64);
                s += w * q2 * spec[kj * n + ki].norm_sqr();
            }
        }
        Ok((s / (n as f64).powi(4)).sqrt())
    }

    /// The slope tensor `⟨∇h ∇hᵀ⟩ = Σ_q q qᵀ |h_q|²` of the trigonometric
    /// interpolant (x along a row), whose trace is `rms_slope()²`; its
    /// [`SlopeTensor::principal`] is the surface's Peklenik number and lay.
    ///
    /// # Errors
    /// None in practice: the FFT's sizes are computed here (a failure
    /// would be a bug and panics: `bem::fft`). The `Result` stays for the API.
    pub fn slope_tensor(&self) -> Result<SlopeTensor> {
        let n = self.n;
        let mut fft = Fft2::new(n, n)?;
        let mut x = self.heights.clone();
        let mut spec = vec![Complex64::new(0.0, 0.0); fft.spectrum_len()];
        fft.forward(&mut x, &mut spec)?;
        let dq = std::f64::consts::TAU / self.size;
        let (mut xx, mut xy, mut yy) = (0.0, 0.0, 0.0);
        // The half spectrum: kj the column (x) wavenumber, ki the row (y) one.
        for kj in 0..fft.nc() {
            let w = if kj == 0 || (n.is_multiple_of(2) && kj == n / 2) {
                1.0
            } else {
                2.0
            };
            for ki in 0..n {
                let (qx, qy) = (dq * kj as f64, dq * signed(ki, n) as f64);
                let p = w * spec[kj * n + ki].norm_sqr();
                xx += qx * qx * p;
                xy += qx * qy * p;
                yy += qy * qy * p;
            }
        }
        let f = (n as f64).powi(-4);
        Ok(SlopeTensor {
            xx: f * xx,
            xy: f * xy,
            yy: f * yy,
        })
    }
}

/// Gauss–Legendre nodes and weights on [−1, 1], 4 points.
const GL4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// Expected `|h_q|²` of mode `(kx, ky)`: `∫_cell C(q) d²q` (4 × 4 Gauss).
fn mode_variance(spectrum: &dyn Spectrum2d, kx: f64, ky: f64, dq: f64) -> f64 {
    let hw = 0.5 * dq;
    let mut s = 0.0;
    for (a, wa) in GL4 {
        for (b, wb) in GL4 {
            let qx = (kx + 0.5 * a) * dq;
            let qy = (ky + 0.5 * b) * dq;
            s += wa * wb * spectrum.c2(qx, qy);
        }
    }
    s * hw * hw
}

/// Standard normal pair by Box–Muller from two 64-bit draws.
pub(crate) fn normal_pair(rng: &mut Pcg64Mcg) -> (f64, f64) {
    let unit = |x: u64| ((x >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64);
    let u1 = unit(rng.next_u64());
    let u2 = unit(rng.next_u64());
    let r = (-2.0 * u1.ln()).sqrt();
    let (s, c) = (std::f64::consts::TAU * u2).sin_cos();
    (r * c, r * s)
}

/// Synthesise a periodic Gaussian surface with spectrum `C(q)` (module docs);
/// an anisotropic spectrum ([`Spectrum::as_2d`]) through [`synthesize_2d`].
///
/// # Errors
/// Grid below 8, size not positive.
///
/// # Examples
/// ```
/// use persson::spectrum::{Amplitude, SelfAffine};
/// # fn main() -> persson::Result<()> {
/// let s = SelfAffine::new(20.0, 40.0, 320.0, 0.8, Amplitude::RmsSlope(0.1))?;
/// let a = persson::bem::surface::synthesize(&s, 64, 1.0, 7)?;
/// let b = persson::bem::surface::synthesize(&s, 64, 1.0, 7)?;
/// assert_eq!(a.heights, b.heights);
/// # Ok(()) }
/// ```
pub fn synthesize(spectrum: &dyn Spectrum, n: usize, size: f64, seed: u64) -> Result<GridSurface> {
    match spectrum.as_2d() {
        Some(s2) => synthesize_2d(s2, n, size, seed),
        None => synthesize_grid(&Radial(spectrum), n, size, seed),
    }
}

/// A 2-D spectrum in the FFT's frame: `c2(q_row, q_col) = C(q_x = q_col, q_y = q_row)`
/// (the half spectrum is indexed by the row wavenumber first, [`super::fft`];
/// x runs along a row of the height map).
struct RowColumn<'a>(&'a dyn Spectrum2d);

impl Spectrum2d for RowColumn<'_> {
    fn c2(&self, q_row: f64, q_col: f64) -> f64 {
        self.0.c2(q_col, q_row)
    }
    fn q_min(&self) -> f64 {
        self.0.q_min()
    }
    fn q_max(&self) -> f64 {
        self.0.q_max()
    }
}

/// Synthesise a periodic Gaussian surface with a 2-D spectrum `C(q_x, q_y)`
/// (module docs, with `C(q)` for `C(|q|)`; the same seed and draws as
/// [`synthesize`]: on [`Radial`] the two give the same surface). Heights are
/// row-major with x along a row (`heights[iy·N + ix]`, as
/// [`crate::topography::Topography::map`]). An anisotropic
/// self-affine surface is [`crate::spectrum::Stretched`] here.
///
/// # Errors
/// Grid below 8, size not positive.
///
/// # Examples
/// ```
/// use std::sync::Arc;
/// use persson::spectrum::{Amplitude, SelfAffine, Stretched};
/// # fn main() -> persson::Result<()> {
/// let iso = Arc::new(SelfAffine::new(20.0, 40.0, 320.0, 0.8, Amplitude::RmsSlope(0.1))?);
/// let s = Stretched::new(iso, 3.0, 0.0)?; // ridges along x
/// let a = persson::bem::surface::synthesize_2d(&s, 64, 1.0, 7)?;
/// assert_eq!(a.heights.len(), 64 * 64);
/// # Ok(()) }
/// ```
pub fn synthesize_2d(
    spectrum: &dyn Spectrum2d,
    n: usize,
    size: f64,
    seed: u64,
) -> Result<GridSurface> {
    synthesize_grid(&RowColumn(spectrum), n, size, seed)
}

/// The synthesis with the spectrum in the FFT's (row, column) frame.
fn synthesize_grid(
    spectrum: &dyn Spectrum2d,
    n: usize,
    size: f64,
    seed: u64,
) -> Result<GridSurface> {
    check::positive("size", size)?;
    super::check_grid(n)?;
    let dq = std::f64::consts::TAU / size;
    let mut fft = Fft2::new(n, n)?;
    let nc = fft.nc();
    let mut spec = vec![Complex64::new(0.0, 0.0); fft.spectrum_len()];
    let mut rng = Pcg64Mcg::seed_from_u64(seed);
    let even = n.is_multiple_of(2);
    for kj in 0..nc {
        // Columns k_y = 0 and (even n) N/2 are Hermitian in k_x themselves.
        let hermitian_column = kj == 0 || (even && kj == n / 2);
        for ki in 0..n {
            let kx = signed(ki, n);
            let conj_ki = (n - ki) % n;
            if hermitian_column && kx < 0 {
                continue; // filled as the conjugate of its partner
            }
            let self_conjugate = hermitian_column && conj_ki == ki;
            if hermitian_column && ki == 0 && kj == 0 {
                continue; // zero mean
            }
            let v = mode_variance(spectrum, kx as f64, kj as f64, dq);
            let (x1, x2) = normal_pair(&mut rng);
            let z = if self_conjugate {
                Complex64::new(v.sqrt() * x1, 0.0)
            } else {
                Complex64::new(x1, x2) * (0.5 * v).sqrt()
            };
            spec[kj * n + ki] = z;
            if hermitian_column && !self_conjugate {
                spec[kj * n + conj_ki] = z.conj();
            }
        }
    }
    let mut heights = vec![0.0; n * n];
    fft.inverse(&mut spec, &mut heights)?;
    GridSurface::new(n, size, heights)
}

/// The expected rms height and rms slope of [`synthesize`]'s surfaces:
/// `sqrt(Σ_q v_q)` and `sqrt(Σ_q |q|² v_q)` over the grid's modes.
pub fn expected_rms(spectrum: &dyn Spectrum, n: usize, size: f64) -> (f64, f64) {
    expected_rms_2d(&Radial(spectrum), n, size)
}

/// [`expected_rms`] of [`synthesize_2d`]'s surfaces (the sums run over the
/// whole plane, so the frame does not matter).
fn expected_rms_2d(spectrum: &dyn Spectrum2d, n: usize, size: f64) -> (f64, f64) {
    let dq = std::f64::consts::TAU / size;
    let (mut h2, mut s2) = (0.0, 0.0);
    for i in 0..n {
        for j in 0..n {
            let (kx, ky) = (signed(i, n) as f64, signed(j, n) as f64);
            if kx == 0.0 && ky == 0.0 {
                continue;
            }
            let v = mode_variance(spectrum, kx, ky, dq);
            h2 += v;
            s2 += v * dq * dq * (kx * kx + ky * ky);
        }
    }
    (h2.sqrt(), s2.sqrt())
}

/// Read a height map: `.npy` (float64/float32, either byte order, C or
/// Fortran order, 2-D square; [`crate::io::npy`]) by extension or magic
/// string, else a text matrix ([`crate::io::text`]). `size` is the physical
/// side L.
///
/// # Errors
/// Unreadable file, malformed header or text, wrong dtype or shape (not 2-D,
/// not square, side below 8), non-finite heights.
pub fn read_height_map(path: &Path, size: f64) -> Result<GridSurface> {
    check::positive("size", size)?;
    let bytes = crate::io::read(path)?;
    height_map_from_bytes(path, &bytes, size)
}

/// [`read_height_map`] from bytes in memory; `path` names the source in
/// errors and its extension `.npy` selects the binary format (as does the
/// `.npy` magic string).
///
/// # Errors
/// As [`read_height_map`], without the I/O errors.
pub fn height_map_from_bytes(path: &Path, bytes: &[u8], size: f64) -> Result<GridSurface> {
    check::positive("size", size)?;
    let is_npy = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("npy"))
        || bytes.starts_with(crate::io::npy::MAGIC);
    let m = if is_npy {
        crate::io::npy::parse(path, bytes)?
    } else {
        crate::io::text::matrix(path, bytes)?
    };
    if m.rows != m.cols {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("shape ({}, {}): need a square N×N grid", m.rows, m.cols),
        ));
    }
    GridSurface::new(m.rows, size, m.values).map_err(|e| match e {
        Error::InvalidParameter {
            name,
            value,
            requirement,
        } => Error::parse(
            path,
            0,
            0,
            format!(
                "{name} = {}: must be {requirement}",
                crate::error::num(value)
            ),
        ),
        Error::Inconsistent { name, requirement } => {
            Error::parse(path, 0, 0, format!("{name}: {requirement}"))
        }
        other => other,
    })
}

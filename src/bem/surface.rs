//! Rigid rough surfaces on periodic grids: Fourier synthesis from a spectrum,
//! and height maps read from `.npy` or text files.
//!
//! Heights are those of the rigid rough surface, pointing towards the
//! elastic body (its peaks touch first), in the unit of the side `L`.
//!
//! # Formula (synthesis)
//! A periodic `L × L` surface is the Fourier series
//! `h(x) = Σ_q h_q e^{i q·x}`, `q = (2π/L)(k_x, k_y)`, `h_{−q} = h_q*`.
//! With Persson's normalisation (`../shared/theory.md` §1)
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
//! `../shared/theory.md` §1.

use std::path::Path;

use rand_core::{Rng, SeedableRng};
use rand_pcg::Pcg64Mcg;
use rustfft::num_complex::Complex64;

use super::fft::Fft2;
use super::kernel::signed;
use crate::error::{check, Error, Result};
use crate::spectrum::Spectrum;

/// A periodic height map on the BEM's `N × N` grid of side `size`: the rigid
/// rough surface of a solve (called `Surface` in persson 0.3; a measured map
/// of any shape is a `persson::topography::Topography`).
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
    /// Wrong length, grid below 8, non-finite height or size.
    pub fn new(n: usize, size: f64, heights: Vec<f64>) -> Result<Self> {
        check::positive("size", size)?;
        super::check_grid(n)?;
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
    /// Internal FFT errors only.
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
}

/// Gauss–Legendre nodes and weights on [−1, 1], 4 points.
const GL4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

/// Expected `|h_q|²` of mode `(kx, ky)`: `∫_cell C(|q|) d²q` (4 × 4 Gauss).
fn mode_variance(spectrum: &dyn Spectrum, kx: f64, ky: f64, dq: f64) -> f64 {
    let hw = 0.5 * dq;
    let mut s = 0.0;
    for (a, wa) in GL4 {
        for (b, wb) in GL4 {
            let qx = (kx + 0.5 * a) * dq;
            let qy = (ky + 0.5 * b) * dq;
            s += wa * wb * spectrum.c(qx.hypot(qy));
        }
    }
    s * hw * hw
}

/// Standard normal pair by Box–Muller from two 64-bit draws.
fn normal_pair(rng: &mut Pcg64Mcg) -> (f64, f64) {
    let unit = |x: u64| ((x >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64);
    let u1 = unit(rng.next_u64());
    let u2 = unit(rng.next_u64());
    let r = (-2.0 * u1.ln()).sqrt();
    let (s, c) = (std::f64::consts::TAU * u2).sin_cos();
    (r * c, r * s)
}

/// Synthesise a periodic Gaussian surface with spectrum `C(q)` (module docs).
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
    let dq = std::f64::consts::TAU / size;
    let (mut h2, mut s2) = (0.0, 0.0);
    for i in 0..n {
        for j in 0..n {
            let (kx, ky) = (signed(i, n) as f64, signed(j, n) as f64);
            if kx == 0.0 && ky == 0.0 {
                continue;
            }
            let v = mode_variance(spectrum, kx, ky.abs(), dq);
            h2 += v;
            s2 += v * dq * dq * (kx * kx + ky * ky);
        }
    }
    (h2.sqrt(), s2.sqrt())
}

/// Read a height map: `.npy` (float64/float32, little-endian, C or Fortran
/// order, 2-D square) by extension, else a whitespace-separated text matrix
/// (`#` starts a comment). `size` is the physical side L.
///
/// # Errors
/// Unreadable file, malformed header or text, wrong dtype or shape (not 2-D,
/// not square, side below 8), non-finite heights.
pub fn read_height_map(path: &Path, size: f64) -> Result<GridSurface> {
    check::positive("size", size)?;
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
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
        || bytes.starts_with(NPY_MAGIC);
    let (n, heights) = if is_npy {
        parse_npy(path, bytes)?
    } else {
        parse_text(path, bytes)?
    };
    GridSurface::new(n, size, heights).map_err(|e| match e {
        Error::InvalidParameter {
            name,
            value,
            requirement,
        } => Error::parse(
            path,
            0,
            0,
            format!("{name} = {value:e}: must be {requirement}"),
        ),
        other => other,
    })
}

const NPY_MAGIC: &[u8] = b"\x93NUMPY";

/// Parse a 2-D square float `.npy` into `(n, row-major heights)`.
fn parse_npy(path: &Path, b: &[u8]) -> Result<(usize, Vec<f64>)> {
    let bad = |m: String| Error::parse(path, 0, 0, m);
    if !b.starts_with(NPY_MAGIC) || b.len() < 10 {
        return Err(bad(
            "not a .npy file (magic string \\x93NUMPY missing)".into()
        ));
    }
    let (hlen, start) = match b[6] {
        1 => (u16::from_le_bytes([b[8], b[9]]) as usize, 10),
        2 | 3 if b.len() >= 12 => (u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize, 12),
        v => {
            return Err(bad(format!(
                ".npy format version {v} not supported (1, 2 or 3)"
            )))
        }
    };
    let header = b
        .get(start..start + hlen)
        .ok_or_else(|| bad("truncated .npy header".into()))?;
    let header = std::str::from_utf8(header).map_err(|_| bad(".npy header is not text".into()))?;
    let descr = dict_value(header, "descr").ok_or_else(|| bad("header has no 'descr'".into()))?;
    let descr = descr.trim_matches(|c| c == '\'' || c == '"');
    let item = match descr {
        "<f8" | "=f8" => 8,
        "<f4" | "=f4" => 4,
        d => {
            return Err(bad(format!(
                "dtype {d:?} not supported: need little-endian float64 ('<f8') or float32 ('<f4')"
            )))
        }
    };
    let fortran = match dict_value(header, "fortran_order") {
        Some("True") => true,
        Some("False") => false,
        _ => return Err(bad("header has no valid 'fortran_order'".into())),
    };
    let shape = dict_value(header, "shape").ok_or_else(|| bad("header has no 'shape'".into()))?;
    let dims: Vec<usize> = shape
        .trim_matches(|c| c == '(' || c == ')')
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse::<usize>())
        .collect::<std::result::Result<_, _>>()
        .map_err(|_| bad(format!("unreadable shape {shape}")))?;
    let (rows, cols) = match dims[..] {
        [r, c] => (r, c),
        _ => return Err(bad(format!("shape {shape}: need a 2-D array"))),
    };
    if rows != cols {
        return Err(bad(format!(
            "shape ({rows}, {cols}): need a square N×N grid"
        )));
    }
    let data = &b[start + hlen..];
    let count = rows
        .checked_mul(cols)
        .and_then(|c| c.checked_mul(item).map(|_| c))
        .ok_or_else(|| bad(format!("shape ({rows}, {cols}) is too large")))?;
    if data.len() != count * item {
        return Err(bad(format!(
            "data holds {} bytes, shape ({rows}, {cols}) of {item}-byte floats needs {}",
            data.len(),
            count * item
        )));
    }
    let flat: Vec<f64> = if item == 8 {
        data.chunks_exact(8)
            .map(|c| f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]))
            .collect()
    } else {
        data.chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
            .collect()
    };
    let heights = if fortran {
        let mut t = vec![0.0; count];
        for i in 0..rows {
            for j in 0..cols {
                t[i * cols + j] = flat[j * rows + i];
            }
        }
        t
    } else {
        flat
    };
    Ok((rows, heights))
}

/// The raw text of `'key': value` in a Python dict literal (value up to the
/// next top-level comma).
fn dict_value<'a>(header: &'a str, key: &str) -> Option<&'a str> {
    let k = header
        .find(&format!("'{key}'"))
        .or_else(|| header.find(&format!("\"{key}\"")))?;
    let rest = &header[k + key.len() + 2..];
    let rest = rest.trim_start().strip_prefix(':')?.trim_start();
    let mut depth = 0i32;
    for (i, c) in rest.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' | '}' if depth == 0 => return Some(rest[..i].trim()),
            _ => {}
        }
    }
    None
}

/// Parse a whitespace-separated square text matrix.
fn parse_text(path: &Path, b: &[u8]) -> Result<(usize, Vec<f64>)> {
    let text = std::str::from_utf8(b).map_err(|_| Error::parse(path, 0, 0, "not UTF-8 text"))?;
    let mut rows = 0usize;
    let mut cols = None;
    let mut out = Vec::new();
    for (ln, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("");
        let mut count = 0usize;
        for (col, tok) in line
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|t| !t.is_empty())
            .enumerate()
        {
            let v: f64 = tok.parse().map_err(|_| {
                Error::parse(path, ln + 1, col + 1, format!("{tok:?} is not a number"))
            })?;
            out.push(v);
            count += 1;
        }
        if count == 0 {
            continue;
        }
        match cols {
            None => cols = Some(count),
            Some(c) if c != count => {
                return Err(Error::parse(
                    path,
                    ln + 1,
                    0,
                    format!("row has {count} values, the first row has {c}"),
                ))
            }
            _ => {}
        }
        rows += 1;
    }
    let cols = cols.unwrap_or(0);
    if rows != cols || rows == 0 {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("matrix is {rows}×{cols}: need a square N×N grid"),
        ));
    }
    Ok((rows, out))
}

/// Write a 2-D `rows × cols` row-major float64 array as `.npy` (version 1.0,
/// C order).
///
/// # Errors
/// Wrong length, I/O errors.
pub fn write_npy(path: &Path, rows: usize, cols: usize, data: &[f64]) -> Result<()> {
    if data.len() != rows * cols {
        return Err(Error::Inconsistent {
            name: "npy data".into(),
            requirement: format!("{rows}×{cols} values, got {}", data.len()),
        });
    }
    let mut header =
        format!("{{'descr': '<f8', 'fortran_order': False, 'shape': ({rows}, {cols}), }}");
    // Pad so that the data starts on a 64-byte boundary, ending with '\n'.
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut out = Vec::with_capacity(10 + header.len() + 8 * data.len());
    out.extend_from_slice(NPY_MAGIC);
    out.extend_from_slice(&[1, 0]);
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for v in data {
        out.extend_from_slice(&v.to_le_bytes());
    }
    std::fs::write(path, out).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })
}

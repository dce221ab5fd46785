//! Anisotropy of a height map: the 2-D spectrum C(q_x, q_y), the Peklenik
//! number, and ISO 25178-2's texture aspect ratio Str, autocorrelation length
//! Sal and texture direction Std.
//!
//! # 2-D spectrum
//! The conditioned heights (detrended, windowed with `⟨w²⟩ = 1`, as for the
//! radial average, [`super::isotropic_spectrum`]) and their unnormalised DFT
//! ĥ give, on the full Fourier grid `q = 2π(k_x/Lx, k_y/Ly)`,
//! ```text
//! C(q_x, q_y) = Lx·Ly / ((2π)² N²) · |ĥ(q)|²      [m⁴],   Σ_q C (2π/Lx)(2π/Ly) = ⟨h²⟩
//! ```
//! (Persson's normalisation, the crate docs' Conventions), stored with q = 0 at
//! index `(ny/2, nx/2)` (numpy's `fftshift`).
//!
//! # Peklenik number (moment form)
//! The slope tensor `M = Σ_q q qᵀ C(q) Δq_x Δq_y = ⟨∇h ∇hᵀ⟩` has eigenvalues
//! `λ₁ ≥ λ₂`; the Peklenik number is `γ = √(λ₁/λ₂) ≥ 1` and the principal
//! direction is the eigenvector of λ₂ (the direction of the slowest
//! variation, along the lay). Peklenik (Proc. Inst. Mech. Eng. 182, 108
//! (1967)) defined γ as the ratio of the correlation lengths along two
//! principal directions; for a stretched surface `h(u, v) = h_iso(u/γ, v)`
//! the autocorrelation is `R_iso(√((u/γ)² + v²))`, so every correlation
//! length along u is γ times the one along v, and `⟨h_v²⟩/⟨h_u²⟩ = γ²`: the
//! two forms agree exactly. The moment form (the second spectral moments
//! m₂₀, m₀₂, m₁₁ of Longuet-Higgins and Nayak, in principal axes) is the
//! one used here because it needs no threshold and no lag beyond a pixel.
//!
//! # Str, Sal (ISO 25178-2:2012, 4.5)
//! The autocorrelation of the detrended heights (no window), by
//! Wiener–Khinchin: circular for a periodic map, linear (zero-padded to
//! 2nx × 2ny) otherwise, normalised to 1 at zero lag:
//! ```text
//! f_ACF(t) = Σ_x z(x) z(x + t) / Σ_x z(x)²
//! ```
//! Along rays from the origin at 360 angles in [0°, 180°), sampled every
//! min(Δx, Δy)/4 with bilinear interpolation, the distance at which f_ACF
//! first falls to s = 0.2 (linear interpolation between samples).
//! `Sal` is the smallest such distance, `Str` = smallest/largest ∈ (0, 1].
//! A ray that reaches |t_x| = Lx/2 or |t_y| = Ly/2 before falling to s makes
//! Str undefined (the map is too small): an error naming `texture_aspect_ratio`.
//!
//! # Std
//! The angular power spectrum `f_APS(θ) = ∫_{q_1}^{q_2} C(q cos θ, q sin θ) q dq`
//! (bilinear interpolation on the grid, q from 2π/min(Lx, Ly) to the smaller
//! Nyquist wavevector) at 360 angles in [0°, 180°). Its maximum points across
//! the lay (the heights vary fastest there); `texture_direction` is the lay,
//! 90° from it, in [0°, 180°) counterclockwise from x (x along a row, y along
//! increasing row index). ISO 25178-2 states Std as the angle of the
//! maximum of the angular spectrum; instrument software reports the lay,
//! which is what users compare, so this is the choice here (stated in the
//! guide).

use crate::fft::fft2;
use rustfft::num_complex::Complex64;

use super::{condition, Conditioning, Detrend, Layout, Topography};
use crate::error::{Error, Result};

/// The threshold s of Str and Sal (ISO 25178-2's default).
pub const STR_THRESHOLD: f64 = 0.2;
/// Angles sampled over [0°, 180°) for Str, Sal and Std (0.5° apart).
const ANGLES: usize = 360;
/// Smallest side (points) of a map for the anisotropy statistics.
const MIN_SIDE: usize = 8;

/// The 2-D power spectrum of a map on its Fourier grid (module docs).
#[derive(Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Spectrum2dMap {
    /// q_x of the columns, increasing, 1/m (`(i − nx/2)·2π/Lx`).
    pub qx: Vec<f64>,
    /// q_y of the rows, increasing, 1/m.
    pub qy: Vec<f64>,
    /// C(q_x, q_y), m⁴, row-major `ny × nx` (row = q_y).
    pub c: Vec<f64>,
}

impl std::fmt::Debug for Spectrum2dMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Spectrum2dMap({} × {})", self.qy.len(), self.qx.len())
    }
}

impl Spectrum2dMap {
    /// C at the signed mode numbers `(kx, ky)` (taken modulo the grid).
    pub fn at(&self, kx: isize, ky: isize) -> f64 {
        let (nx, ny) = (self.qx.len() as isize, self.qy.len() as isize);
        let i = (kx + nx / 2).rem_euclid(nx) as usize;
        let j = (ky + ny / 2).rem_euclid(ny) as usize;
        self.c[j * nx as usize + i]
    }
}

/// The anisotropy statistics of a map (module docs).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Anisotropy {
    /// Peklenik number √(λ₁/λ₂) of the slope tensor, ≥ 1.
    pub peklenik_number: f64,
    /// Direction of the slowest variation (the long correlation axis), degrees in [0, 180).
    pub principal_direction: f64,
    /// ISO 25178-2 Str at s = 0.2, in (0, 1].
    pub texture_aspect_ratio: f64,
    /// ISO 25178-2 Sal at s = 0.2 (the shortest decay length), m.
    pub autocorrelation_length: f64,
    /// Std: the lay direction, degrees in [0, 180).
    pub texture_direction: f64,
    /// The 2-D spectrum (not serialised: N values).
    #[serde(skip)]
    pub spectrum: Spectrum2dMap,
}

fn check_map(t: &Topography) -> Result<()> {
    if t.layout() != Layout::Map {
        return Err(Error::Inconsistent {
            name: "surface".into(),
            requirement: "a height map for the anisotropy (line scans have one direction)".into(),
        });
    }
    if t.nx() < MIN_SIDE || t.ny() < MIN_SIDE {
        return Err(Error::Inconsistent {
            name: "texture_aspect_ratio".into(),
            requirement: format!(
                "a map of at least {MIN_SIDE} × {MIN_SIDE} points, got {} × {}",
                t.ny(),
                t.nx()
            ),
        });
    }
    Ok(())
}

/// The 2-D spectrum of a map with the given conditioning (module docs).
///
/// # Errors
/// Line scans, a side below 8 points.
pub fn spectrum_2d(t: &Topography, conditioning: Conditioning) -> Result<Spectrum2dMap> {
    use std::f64::consts::TAU;
    check_map(t)?;
    let (nx, ny, lx, ly) = (t.nx(), t.ny(), t.lx(), t.ly());
    let (h, mean_w2) = condition::conditioned_map(t, conditioning.detrend, conditioning.window);
    let mut buf: Vec<Complex64> = h.iter().map(|&v| Complex64::new(v, 0.0)).collect();
    fft2(&mut buf, nx, ny, false);
    let n2 = (nx * ny) as f64;
    let factor = lx * ly / (TAU * TAU * n2 * n2 * mean_w2);
    let mut c = vec![0.0; nx * ny];
    for j in 0..ny {
        let sy = (j + ny - ny / 2) % ny;
        for i in 0..nx {
            let sx = (i + nx - nx / 2) % nx;
            c[j * nx + i] = factor * buf[sy * nx + sx].norm_sqr();
        }
    }
    let axis = |n: usize, l: f64| -> Vec<f64> {
        (0..n)
            .map(|i| (i as f64 - (n / 2) as f64) * TAU / l)
            .collect()
    };
    Ok(Spectrum2dMap {
        qx: axis(nx, lx),
        qy: axis(ny, ly),
        c,
    })
}

/// The anisotropy statistics of a map (module docs); the 2-D spectrum is
/// that of `conditioning`, the autocorrelation uses its detrending only.
///
/// # Errors
/// Line scans or a side below 8 points; a surface that does not vary along
/// some direction (`peklenik_number`); an autocorrelation that stays above
/// 0.2 out to half the map in some direction (`texture_aspect_ratio`).
pub fn anisotropy(t: &Topography, conditioning: Conditioning) -> Result<Anisotropy> {
    let spectrum = spectrum_2d(t, conditioning)?;
    let (peklenik_number, principal_direction) = peklenik(&spectrum)?;
    let (texture_aspect_ratio, autocorrelation_length) =
        texture_aspect_ratio(t, conditioning.detrend)?;
    Ok(Anisotropy {
        peklenik_number,
        principal_direction,
        texture_aspect_ratio,
        autocorrelation_length,
        texture_direction: texture_direction(&spectrum),
        spectrum,
    })
}

/// An angle in degrees mapped into [0, 180).
fn half_turn_degrees(rad: f64) -> f64 {
    let d = rad.to_degrees().rem_euclid(180.0);
    if d >= 180.0 {
        0.0
    } else {
        d
    }
}

/// `(γ, direction°)` from the slope tensor of the spectrum
/// ([`crate::spectrum::anisotropic::SlopeTensor::principal`]).
fn peklenik(s: &Spectrum2dMap) -> Result<(f64, f64)> {
    let nx = s.qx.len();
    let cell = (s.qx[1] - s.qx[0]) * (s.qy[1] - s.qy[0]);
    let (mut a, mut b, mut d) = (0.0, 0.0, 0.0);
    for (j, &qy) in s.qy.iter().enumerate() {
        for (i, &qx) in s.qx.iter().enumerate() {
            let c = s.c[j * nx + i] * cell;
            a += qx * qx * c;
            b += qx * qy * c;
            d += qy * qy * c;
        }
    }
    crate::spectrum::anisotropic::SlopeTensor {
        xx: a,
        xy: b,
        yy: d,
    }
    .principal()
}

/// Bilinear interpolation of a periodic row-major `ny × nx` array at the
/// fractional indices (x, y).
fn bilinear(v: &[f64], nx: usize, ny: usize, x: f64, y: f64) -> f64 {
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    let wrap = |k: f64, n: usize| (k as isize).rem_euclid(n as isize) as usize;
    let (i0, i1) = (wrap(x0, nx), wrap(x0 + 1.0, nx));
    let (j0, j1) = (wrap(y0, ny), wrap(y0 + 1.0, ny));
    let at = |i: usize, j: usize| v[j * nx + i];
    (1.0 - fy) * ((1.0 - fx) * at(i0, j0) + fx * at(i1, j0))
        + fy * ((1.0 - fx) * at(i0, j1) + fx * at(i1, j1))
}

/// `(Str, Sal)` at s = 0.2 (module docs).
fn texture_aspect_ratio(t: &Topography, detrend: Detrend) -> Result<(f64, f64)> {
    let (nx, ny, lx, ly) = (t.nx(), t.ny(), t.lx(), t.ly());
    let (dx, dy) = (lx / nx as f64, ly / ny as f64);
    let mut h = t.detrended(detrend);
    let mean = h.iter().sum::<f64>() / h.len() as f64;
    h.iter_mut().for_each(|v| *v -= mean);
    let (px, py) = if t.periodic() {
        (nx, ny)
    } else {
        (2 * nx, 2 * ny)
    };
    let mut buf = vec![Complex64::new(0.0, 0.0); px * py];
    for iy in 0..ny {
        for ix in 0..nx {
            buf[iy * px + ix].re = h[iy * nx + ix];
        }
    }
    fft2(&mut buf, px, py, false);
    buf.iter_mut()
        .for_each(|z| *z = Complex64::new(z.norm_sqr(), 0.0));
    fft2(&mut buf, px, py, true);
    let r0 = buf[0].re;
    if r0.is_nan() || r0 <= 0.0 {
        // a map flat after detrending: no texture to measure
        return Err(Error::Inconsistent {
            name: "surface".into(),
            requirement:
                "heights that vary after detrending (the autocorrelation at zero lag is zero)"
                    .into(),
        });
    }
    let acf: Vec<f64> = buf.iter().map(|z| z.re / r0).collect();
    let step = 0.25 * dx.min(dy);
    let (mut r_min, mut r_max) = (f64::INFINITY, 0.0f64);
    for k in 0..ANGLES {
        let theta = std::f64::consts::PI * k as f64 / ANGLES as f64;
        let (s, c) = theta.sin_cos();
        let (mut r_prev, mut f_prev) = (0.0, 1.0);
        let mut crossing = None;
        let mut r = step;
        while (r * c).abs() <= 0.5 * lx && (r * s).abs() <= 0.5 * ly {
            let f = bilinear(&acf, px, py, r * c / dx, r * s / dy);
            if f <= STR_THRESHOLD {
                let w = (f_prev - STR_THRESHOLD) / (f_prev - f);
                crossing = Some(r_prev + w * (r - r_prev));
                break;
            }
            (r_prev, f_prev) = (r, f);
            r += step;
        }
        let Some(rc) = crossing else {
            return Err(Error::Inconsistent {
                name: "texture_aspect_ratio".into(),
                requirement: format!(
                    "an autocorrelation that falls to s = {STR_THRESHOLD} within half the map in every direction; at {:.1}° it is still {f_prev:.3} at {} m (map {} × {} m): measure a larger area",
                    theta.to_degrees(),
                    crate::error::num(r_prev),
                    crate::error::num(lx),
                    crate::error::num(ly)
                ),
            });
        };
        r_min = r_min.min(rc);
        r_max = r_max.max(rc);
    }
    Ok((r_min / r_max, r_min))
}

/// Std: the lay direction, 90° from the maximum of the angular spectrum.
fn texture_direction(s: &Spectrum2dMap) -> f64 {
    let (nx, ny) = (s.qx.len(), s.qy.len());
    let (dqx, dqy) = (s.qx[1] - s.qx[0], s.qy[1] - s.qy[0]);
    let q1 = dqx.max(dqy);
    let q2 = (dqx * (nx / 2) as f64).min(dqy * (ny / 2) as f64);
    let dq = 0.5 * dqx.min(dqy);
    let steps = ((q2 - q1) / dq).floor().max(1.0) as usize;
    let (mut best, mut best_theta) = (f64::NEG_INFINITY, 0.0);
    for k in 0..ANGLES {
        let theta = std::f64::consts::PI * k as f64 / ANGLES as f64;
        let (sn, cs) = theta.sin_cos();
        let mut f = 0.0;
        for m in 0..=steps {
            let q = q1 + m as f64 * dq;
            let x = q * cs / dqx + (nx / 2) as f64;
            let y = q * sn / dqy + (ny / 2) as f64;
            f += q * bilinear(&s.c, nx, ny, x, y);
        }
        if f > best {
            (best, best_theta) = (f, theta);
        }
    }
    half_turn_degrees(best_theta + std::f64::consts::FRAC_PI_2)
}

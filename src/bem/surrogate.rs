//! Surrogates of a height map: random surfaces with the map's periodic power
//! spectrum, to ask whether the map makes contact like a random surface of
//! the same spectrum (the only thing Persson's theory sees of it).
//!
//! # Phase-randomised surrogates
//! The map's discrete Fourier transform `H(k) = Σ_x h(x) e^{−2πi k·x/N}` keeps
//! its amplitudes and gets the phases of a Gaussian white-noise field `w`:
//! ```text
//! S(k) = |H(k)| · W(k)/|W(k)|,   W = DFT(w),   S(0) = H(0)
//! ```
//! `w` is real, so `W(−k) = W(k)*` and `S` is Hermitian: the surrogate is real.
//! The self-conjugate modes (`k_x, k_y ∈ {0, N/2}`) have a real `W`, so they
//! keep `|H|` with a random sign; the mean (`k = 0`) is the map's. Every
//! `|S(k)|² = |H(k)|²`: the periodic spectrum is the map's at every
//! wavevector (to rounding), and the phases are uniform and independent
//! between the pairs `±k`: a random-phase surface, Gaussian in the limit of
//! many modes (Theiler et al. 1992).
//!
//! # Amplitude-adjusted surrogates (IAAFT)
//! A phase surrogate's heights are Gaussian whatever the map's. The iterative
//! amplitude-adjusted Fourier transform (Schreiber & Schmitz 1996) keeps the
//! map's height distribution exactly and its spectrum nearly: from a random
//! shuffle `r` of the heights, repeat
//! ```text
//! s = IDFT(|H| · R/|R|),  R = DFT(r)      (impose the amplitudes)
//! r = the map's sorted heights in the rank order of s   (impose the values)
//! ```
//! until the ranks stop changing or `iterations` pass. It ends on the second
//! step, so the sorted heights equal the map's exactly; the spectrum is left
//! slightly off, and [`radial_mismatch`] says by how much in each radial bin.
//!
//! # Reproducibility
//! The white noise and the shuffle come from `rand_pcg::Pcg64Mcg` seeded with
//! the seed, as [`super::surface::synthesize`]'s normals: a seed gives the
//! same surrogate in every version of this crate.
//!
//! # References
//! J. Theiler, S. Eubank, A. Longtin, B. Galdrikian and J. D. Farmer,
//! Physica D 58, 77 (1992) (phase randomisation); T. Schreiber and
//! A. Schmitz, Phys. Rev. Lett. 77, 635 (1996) (IAAFT); C. Campañá and
//! M. H. Müser, "Contact mechanics of real versus randomly rough surfaces: a
//! Green's function molecular dynamics study" (2007), the project's seed
//! (real against random surfaces in contact).

use rand_core::{Rng, SeedableRng};
use rand_pcg::Pcg64Mcg;
use rustfft::num_complex::Complex64;

use super::surface::{normal_pair, GridSurface};
use crate::error::{Error, Result};
use crate::fft::fft2;

/// Iterations of [`amplitude_adjusted`] a user gets by default: enough for
/// the radial spectrum to be within 1 % of the map's in every bin on the
/// maps of the tests (it stops earlier when the ranks settle).
pub const DEFAULT_IAAFT_ITERATIONS: usize = 200;

/// An amplitude-adjusted surrogate and how close its spectrum came.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct AmplitudeAdjusted {
    /// The surrogate: the map's heights, rearranged.
    pub surface: GridSurface,
    /// Iterations done.
    pub iterations: usize,
    /// Whether the radial spectrum came within 1e-3 of the map's in every
    /// shell before the limit.
    pub converged: bool,
    /// The largest relative difference of the radial spectrum from the map's
    /// over the bins of [`radial_mismatch`].
    pub spectrum_mismatch: f64,
}

/// A phase-randomised surrogate of `map` (module docs), drawn with `seed`.
///
/// # Errors
/// A constant map ([`Error::Inconsistent`] naming `heights`: it has no
/// spectrum to keep).
pub fn phase_randomised(map: &GridSurface, seed: u64) -> Result<GridSurface> {
    check_map(map)?;
    let n = map.n;
    let target = transform(&map.heights, n);
    let mut rng = Pcg64Mcg::seed_from_u64(seed);
    let mut noise = Vec::with_capacity(n * n);
    while noise.len() < n * n {
        let (a, b) = normal_pair(&mut rng);
        noise.push(a);
        if noise.len() < n * n {
            noise.push(b);
        }
    }
    let mut s = transform(&noise, n);
    for (k, (sk, hk)) in s.iter_mut().zip(&target).enumerate() {
        *sk = if k == 0 {
            *hk
        } else {
            with_phase_of(hk.norm(), *sk)
        };
    }
    GridSurface::new(n, map.size, inverse_real(s, n))
}

/// An amplitude-adjusted (IAAFT) surrogate of `map` (module docs), drawn
/// with `seed`, after at most `iterations` rounds.
///
/// # Errors
/// A constant map; `iterations` = 0.
pub fn amplitude_adjusted(
    map: &GridSurface,
    seed: u64,
    iterations: usize,
) -> Result<AmplitudeAdjusted> {
    check_map(map)?;
    if iterations == 0 {
        return Err(Error::invalid("iterations", 0.0, ">= 1"));
    }
    let n = map.n;
    let target: Vec<f64> = transform(&map.heights, n)
        .iter()
        .map(|c| c.norm())
        .collect();
    let shells = Shells::new(n);
    let target_power = shells.power(&target);
    let mut amplitude = target.clone();
    let mut sorted = map.heights.clone();
    sorted.sort_by(f64::total_cmp);
    let mut r = shuffled(&map.heights, seed);
    let mut done = 0;
    let mut converged = false;
    // The largest shell mismatch of `r` as it stands (set by every round).
    let mut worst = f64::INFINITY;
    while done < iterations {
        // A round of IAAFT on the current amplitudes, until its ranks settle.
        let mut rank: Vec<usize> = Vec::new();
        let round = ROUND.min(iterations - done);
        for _ in 0..round {
            done += 1;
            let order = iaaft_step(&mut r, &amplitude, &sorted, n);
            if order == rank {
                break;
            }
            rank = order;
        }
        // The rank step adds power of its own: aim each shell's amplitudes
        // so that what comes out has the map's power.
        let got: Vec<f64> = transform(&r, n).iter().map(|c| c.norm()).collect();
        let power = shells.power(&got);
        worst = relative_differences(&target_power, &power).fold(0.0, f64::max);
        if worst <= CORRECTED {
            converged = true;
            break;
        }
        for (k, a) in amplitude.iter_mut().enumerate() {
            if let Some(s) = shells.of(k) {
                if power[s] > 0.0 {
                    *a *= (target_power[s] / power[s]).sqrt();
                }
            }
        }
    }
    // The corrections change the amplitudes, never `r`: the last round's
    // mismatch is the surrogate's ([`radial_mismatch`]'s largest bin).
    Ok(AmplitudeAdjusted {
        surface: GridSurface::new(n, map.size, r)?,
        iterations: done,
        converged,
        spectrum_mismatch: worst,
    })
}

/// Iterations of one IAAFT round between corrections of the amplitudes.
const ROUND: usize = 25;

/// The radial spectrum's relative difference at which the corrections stop.
const CORRECTED: f64 = 1e-3;

/// One IAAFT step on `r` (module docs): impose `amplitude`, then the sorted
/// heights in the rank order that gave; returns that order.
fn iaaft_step(r: &mut [f64], amplitude: &[f64], sorted: &[f64], n: usize) -> Vec<usize> {
    let mut spectrum = transform(r, n);
    for (c, &a) in spectrum.iter_mut().zip(amplitude) {
        *c = with_phase_of(a, *c);
    }
    let s = inverse_real(spectrum, n);
    let mut order: Vec<usize> = (0..n * n).collect();
    order.sort_by(|&i, &j| s[i].total_cmp(&s[j]));
    for (v, &i) in sorted.iter().zip(&order) {
        r[i] = *v;
    }
    order
}

/// The radial shells of an `n × n` transform: unit width in `|k|` from 1 to
/// n/2 (units of 2π/L), the isotropic band of the grid.
struct Shells {
    shell: Vec<Option<usize>>,
    count: usize,
}

impl Shells {
    fn new(n: usize) -> Self {
        let count = n / 2;
        let shell = (0..n * n)
            .map(|i| {
                let k = signed(i % n, n).hypot(signed(i / n, n));
                let s = (k + 0.5).floor() as usize;
                (1..=count).contains(&s).then_some(s - 1)
            })
            .collect();
        Shells { shell, count }
    }

    /// The shell of mode `i` (row-major), if in the band.
    fn of(&self, i: usize) -> Option<usize> {
        self.shell[i]
    }

    /// Σ |a|² per shell, and the modes of each.
    fn power(&self, a: &[f64]) -> Vec<f64> {
        let mut p = vec![0.0; self.count];
        for (i, v) in a.iter().enumerate() {
            if let Some(s) = self.shell[i] {
                p[s] += v * v;
            }
        }
        p
    }

    fn modes(&self) -> Vec<usize> {
        let mut m = vec![0; self.count];
        for s in self.shell.iter().flatten() {
            m[*s] += 1;
        }
        m
    }
}

/// `|b − a|/a` per shell (|b| where a = 0).
fn relative_differences<'a>(a: &'a [f64], b: &'a [f64]) -> impl Iterator<Item = f64> + 'a {
    a.iter()
        .zip(b)
        .map(|(&a, &b)| if a > 0.0 { (b - a).abs() / a } else { b.abs() })
}

/// One radial bin of [`radial_mismatch`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct RadialBin {
    /// The bin holds the modes with `|k|` in `[k − ½, k + ½)` (units of 2π/L).
    pub k: usize,
    /// Modes in the bin.
    pub modes: usize,
    /// `|Σ|S|² − Σ|H|²| / Σ|H|²` over the bin.
    pub relative_difference: f64,
}

/// The radial spectrum of `surrogate` against `map`'s: shells of unit width
/// in `|k|` from 1 to N/2 (the isotropic band of the grid), each the relative
/// difference of the summed power `|DFT|²` of its modes.
///
/// # Errors
/// Maps of different grids.
pub fn radial_mismatch(map: &GridSurface, surrogate: &GridSurface) -> Result<Vec<RadialBin>> {
    if map.n != surrogate.n {
        return Err(Error::Inconsistent {
            name: "surrogate".into(),
            requirement: format!("the map's grid {} × {}", map.n, map.n),
        });
    }
    let n = map.n;
    let shells = Shells::new(n);
    let norms = |h: &[f64]| -> Vec<f64> { transform(h, n).iter().map(|c| c.norm()).collect() };
    let (a, b) = (
        shells.power(&norms(&map.heights)),
        shells.power(&norms(&surrogate.heights)),
    );
    Ok(relative_differences(&a, &b)
        .zip(shells.modes())
        .enumerate()
        .map(|(s, (relative_difference, modes))| RadialBin {
            k: s + 1,
            modes,
            relative_difference,
        })
        .collect())
}

/// Skewness `⟨(h − h̄)³⟩/σ³` and kurtosis `⟨(h − h̄)⁴⟩/σ⁴` (3 for a
/// Gaussian) of the heights; `(0, 0)` for a constant map.
pub fn height_moments(heights: &[f64]) -> (f64, f64) {
    let n = heights.len().max(1) as f64;
    let mean = heights.iter().sum::<f64>() / n;
    let (mut m2, mut m3, mut m4) = (0.0, 0.0, 0.0);
    for h in heights {
        let d = h - mean;
        let d2 = d * d;
        m2 += d2;
        m3 += d2 * d;
        m4 += d2 * d2;
    }
    let (m2, m3, m4) = (m2 / n, m3 / n, m4 / n);
    if m2 <= 0.0 {
        return (0.0, 0.0);
    }
    (m3 / m2.powf(1.5), m4 / (m2 * m2))
}

/// Student's t quantiles t₀.₉₇₅(ν) for ν = 1 … 30 (the standard tables,
/// e.g. Abramowitz & Stegun 1964, Table 26.10).
const T_975: [f64; 30] = [
    12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
    2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
    2.052, 2.048, 2.045, 2.042,
];

/// The two-sided 95 % point of Student's t with `dof` degrees of freedom:
/// a value one more draw from K surrogates' distribution exceeds in
/// `|x − mean|/(s·√(1 + 1/K))` with probability 5 % (ν = K − 1, the
/// prediction interval of normal data).
///
/// # Formula
/// The table for ν ≤ 30 (3 decimals); above it the Cornish–Fisher series
/// `t ≈ z + (z³ + z)/(4ν) + (5z⁵ + 16z³ + 3z)/(96ν²)`, z = 1.959964
/// (Abramowitz & Stegun 26.7.5), within 1e-3 of the exact quantile there.
/// `dof` = 0 gives infinity (no spread can be estimated).
pub fn student_t_975(dof: usize) -> f64 {
    match dof {
        0 => f64::INFINITY,
        1..=30 => T_975[dof - 1],
        _ => {
            let (z, v) = (1.959_963_984_540_054_f64, dof as f64);
            z + (z.powi(3) + z) / (4.0 * v)
                + (5.0 * z.powi(5) + 16.0 * z.powi(3) + 3.0 * z) / (96.0 * v * v)
        }
    }
}

/// The index `i` of an `n`-point transform as a signed wavenumber.
fn signed(i: usize, n: usize) -> f64 {
    if i <= n / 2 {
        i as f64
    } else {
        i as f64 - n as f64
    }
}

/// `a · z/|z|`, or `a` (phase 0) where `z` = 0.
fn with_phase_of(a: f64, z: Complex64) -> Complex64 {
    let m = z.norm();
    if m > 0.0 {
        z * (a / m)
    } else {
        Complex64::new(a, 0.0)
    }
}

/// The 2-D DFT of the real `n × n` array `x`.
fn transform(x: &[f64], n: usize) -> Vec<Complex64> {
    let mut buf: Vec<Complex64> = x.iter().map(|&v| Complex64::new(v, 0.0)).collect();
    fft2(&mut buf, n, n, false);
    buf
}

/// The real part of the normalised inverse 2-D DFT (the imaginary part of a
/// Hermitian spectrum's is rounding).
fn inverse_real(mut spectrum: Vec<Complex64>, n: usize) -> Vec<f64> {
    fft2(&mut spectrum, n, n, true);
    let scale = 1.0 / (n * n) as f64;
    spectrum.iter().map(|c| c.re * scale).collect()
}

/// The heights in a random order (Fisher–Yates with `seed`).
fn shuffled(heights: &[f64], seed: u64) -> Vec<f64> {
    let mut rng = Pcg64Mcg::seed_from_u64(seed);
    let mut v = heights.to_vec();
    for i in (1..v.len()).rev() {
        // Lemire's multiply-shift: unbiased enough for 2⁶⁴ ≫ N².
        let j = ((rng.next_u64() as u128 * (i as u128 + 1)) >> 64) as usize;
        v.swap(i, j);
    }
    v
}

/// The check every surrogate of `map` makes: a map that is not constant.
///
/// # Errors
/// [`Error::Inconsistent`] naming `heights` for a constant map.
pub fn check_map(map: &GridSurface) -> Result<()> {
    let first = map.heights.first().copied().unwrap_or(0.0);
    if map.heights.iter().all(|&h| h == first) {
        return Err(Error::Inconsistent {
            name: "heights".into(),
            requirement: "a map that is not constant (a flat map has no spectrum to keep)".into(),
        });
    }
    Ok(())
}

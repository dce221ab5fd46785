//! One surface on several grids, for resolution studies: a synthesised
//! realisation subsampled, a periodic height map low-passed and subsampled,
//! or a height map block-averaged.
//!
//! # Formula
//! ```text
//! subsampled:   h_n(i, j) = h_N(r i, r j),  r = N/n
//! low-passed:   h̃(x) = Σ_{|q| ≤ q_s} ĥ_q e^{iq·x},   ĥ_q = N⁻² Σ_x h(x) e^{−iq·x},  q = 2πk/L
//! block mean:   h_n(i, j) = r⁻² Σ_{a,b < r} h_N(r i + a, r j + b)
//! ```
//! When every mode lies below the coarsest grid's Nyquist wavevector
//! (|k| < n/2 for every mode k of the surface), the subsampled copies are
//! the same band-limited surface exactly: their trigonometric interpolants
//! coincide, so A(N) of a resolution study converges for one realisation
//! as the discretisation refines. A block mean keeps a map's modes up to its
//! own Nyquist wavevector, attenuated by sinc(q_x Δ/2)·sinc(q_y Δ/2) (Δ its
//! pixel): each copy is a smoother surface.
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005
//! (the resolution study: A(N) = A∞ + c N^{−α}).

use super::fft::{Complex64, Fft2};
use super::surface::{self, GridSurface};
use crate::error::{check, Error, Result};
use crate::spectrum::Spectrum;

/// One realisation on every grid of `grids` (ascending, each dividing the
/// finest): synthesised on the finest grid ([`surface::synthesize`]),
/// subsampled on the others.
///
/// # Formula
/// ```text
/// h_n(i, j) = h_N(r i, r j),  r = N/n   (exact when all modes |k| < n/2)
/// ```
///
/// # Errors
/// Grids not ascending, each dividing the next; the spectrum has modes at or
/// above the coarsest grid's Nyquist wavevector (`q_max L/2π + 1 ≥ n/2`: the
/// cell-averaged synthesis touches the mode next to q_max); as
/// [`surface::synthesize`].
///
/// # Examples
/// ```
/// use persson::bem::resample::nested_surfaces;
/// use persson::spectrum::{Amplitude, SelfAffine};
/// # fn main() -> persson::Result<()> {
/// let tau = std::f64::consts::TAU;
/// let s = SelfAffine::new(tau, 2.0 * tau, 4.0 * tau, 0.8, Amplitude::RmsSlope(0.1))?;
/// let [coarse, fine] = <[_; 2]>::try_from(nested_surfaces(&s, &[16, 32], 1.0, 7)?).unwrap();
/// // the same band-limited surface on both grids: every other node, the same slope
/// assert_eq!(coarse.heights[1], fine.heights[2]);
/// assert!((coarse.rms_slope()? / fine.rms_slope()? - 1.0).abs() < 1e-12);
/// # Ok(()) }
/// ```
pub fn nested_surfaces(
    spectrum: &dyn Spectrum,
    grids: &[usize],
    size: f64,
    seed: u64,
) -> Result<Vec<GridSurface>> {
    check::positive("size", size)?;
    let (&coarsest, &finest) = match (grids.first(), grids.last()) {
        (Some(a), Some(b)) => (a, b),
        _ => return Err(Error::invalid("grids", 0.0, "at least one grid")),
    };
    for w in grids.windows(2) {
        if !(w[0] < w[1] && w[1].is_multiple_of(w[0])) {
            return Err(Error::Inconsistent {
                name: "grids".into(),
                requirement: format!("ascending, each dividing the next (got {grids:?})"),
            });
        }
    }
    let k_max = spectrum.q_max() * size / std::f64::consts::TAU;
    if k_max + 1.0 >= coarsest as f64 / 2.0 {
        return Err(Error::invalid(
            "q_s",
            spectrum.q_max(),
            format!(
                "below the coarsest grid's Nyquist wavevector: q_s L/2π + 1 < {coarsest}/2 (L = {size:e})"
            ),
        ));
    }
    let fine = surface::synthesize(spectrum, finest, size, seed)?;
    subsampled(&fine, grids)
}

/// Every `r`-th node of `fine` on each grid `n` of `grids` (`r = N/n`).
fn subsampled(fine: &GridSurface, grids: &[usize]) -> Result<Vec<GridSurface>> {
    let nf = fine.n;
    grids
        .iter()
        .map(|&n| {
            let r = nf / n;
            let heights = (0..n * n)
                .map(|k| fine.heights[(k / n) * r * nf + (k % n) * r])
                .collect();
            GridSurface::new(n, fine.size, heights)
        })
        .collect()
}

/// A periodic map low-passed in Fourier space: every mode with
/// `|q| > q_s` removed (a circular cut, `q = 2π k/L`), the mean kept.
///
/// # Formula
/// ```text
/// h̃(x) = Σ_{|q| ≤ q_s} ĥ_q e^{iq·x},   ĥ_q = N⁻² Σ_x h(x) e^{−iq·x}
/// ```
///
/// # Errors
/// `q_s` not finite and positive.
///
/// # Examples
/// ```
/// use persson::bem::{resample::band_limited_map, GridSurface};
/// # fn main() -> persson::Result<()> {
/// // cos(2πx/L) + cos(2π·5y/L) on 16²: a cut at q = 3·2π/L keeps the first
/// let n = 16;
/// let tau = std::f64::consts::TAU;
/// let h = (0..n * n)
///     .map(|k| (tau * (k % n) as f64 / n as f64).cos() + (tau * 5.0 * (k / n) as f64 / n as f64).cos())
///     .collect();
/// let cut = band_limited_map(&GridSurface::new(n, 1.0, h)?, 3.0 * tau)?;
/// assert!((cut.heights[0] - 1.0).abs() < 1e-14);
/// # Ok(()) }
/// ```
pub fn band_limited_map(map: &GridSurface, q_s: f64) -> Result<GridSurface> {
    check::positive("q_s", q_s)?;
    let n = map.n;
    let k_max = q_s * map.size / std::f64::consts::TAU;
    let k2_max = k_max * k_max * (1.0 + 1e-12);
    let mut fft = Fft2::new(n, n)?;
    let mut x = map.heights.clone();
    let mut spec = vec![Complex64::new(0.0, 0.0); fft.spectrum_len()];
    fft.forward(&mut x, &mut spec)?;
    let scale = 1.0 / (n * n) as f64;
    for kj in 0..fft.nc() {
        for ki in 0..n {
            let kx = if ki <= n / 2 {
                ki as f64
            } else {
                ki as f64 - n as f64
            };
            let k2 = kx * kx + (kj * kj) as f64;
            let z = &mut spec[kj * n + ki];
            *z = if k2 <= k2_max { *z * scale } else { 0.0.into() };
        }
    }
    let mut heights = vec![0.0; n * n];
    fft.inverse(&mut spec, &mut heights)?;
    GridSurface::new(n, map.size, heights)
}

/// A periodic map low-passed at `q_s` ([`band_limited_map`]) and sampled on
/// every grid of `grids` (ascending, each dividing the next, the finest the
/// map's): the band-limited map on its own grid, every `r`-th node of it on
/// the coarser ones. Every mode lies below the coarsest grid's Nyquist
/// wavevector (enforced), so each copy is the same continuous surface: its
/// trigonometric interpolant is the band-limited map's.
///
/// # Errors
/// Grids as for [`coarsened`]; modes at or above the coarsest grid's Nyquist
/// wavevector (`⌊q_s L/2π⌋ ≥ n/2`: fewer than 2 pixels per wavelength); as
/// [`band_limited_map`].
pub fn band_limited_copies(
    map: &GridSurface,
    q_s: f64,
    grids: &[usize],
) -> Result<Vec<GridSurface>> {
    check_map_grids(map, grids)?;
    let coarsest = grids[0];
    let k_max = q_s * map.size / std::f64::consts::TAU;
    if (k_max * (1.0 + 1e-12)).floor() >= (coarsest / 2) as f64 {
        return Err(Error::invalid(
            "q_s",
            q_s,
            format!(
                "below the coarsest grid's Nyquist wavevector: q_s L/2π < {coarsest}/2 (L = {:e}; more than 2 pixels per wavelength)",
                map.size
            ),
        ));
    }
    subsampled(&band_limited_map(map, q_s)?, grids)
}

/// The grids of a map: ascending, each dividing the next, the finest the map's.
fn check_map_grids(map: &GridSurface, grids: &[usize]) -> Result<()> {
    let nf = map.n;
    let ok = grids.last() == Some(&nf)
        && grids
            .windows(2)
            .all(|w| w[0] < w[1] && w[1].is_multiple_of(w[0]));
    if ok {
        Ok(())
    } else {
        Err(Error::Inconsistent {
            name: "grids".into(),
            requirement: format!(
                "ascending, each dividing the next, the finest the map's {nf} (got {grids:?})"
            ),
        })
    }
}

/// A height map on coarser grids by averaging `r × r` blocks (`r = N/n`):
/// the finest grid is the map itself; each copy keeps the map's modes up to
/// its own Nyquist wavevector (attenuated by the block average's
/// `sinc(q_x Δ/2)·sinc(q_y Δ/2)`, Δ its pixel).
///
/// # Formula
/// ```text
/// h_n(i, j) = r⁻² Σ_{a,b < r} h_N(r i + a, r j + b)
/// ```
///
/// # Errors
/// The finest grid is not the map's; grids not ascending, each dividing the
/// next; as [`GridSurface::new`].
///
/// # Examples
/// ```
/// use persson::bem::{resample::coarsened, GridSurface};
/// # fn main() -> persson::Result<()> {
/// let h: Vec<f64> = (0..256).map(|k| k as f64).collect();
/// let copies = coarsened(&GridSurface::new(16, 1.0, h)?, &[8, 16])?;
/// // the first 2×2 block: (0 + 1 + 16 + 17)/4
/// assert_eq!(copies[0].heights[0], 8.5);
/// # Ok(()) }
/// ```
pub fn coarsened(map: &GridSurface, grids: &[usize]) -> Result<Vec<GridSurface>> {
    let nf = map.n;
    check_map_grids(map, grids)?;
    grids
        .iter()
        .map(|&n| {
            let r = nf / n;
            let w = 1.0 / (r * r) as f64;
            let heights = (0..n * n)
                .map(|k| {
                    let (i, j) = (k / n, k % n);
                    if r == 1 {
                        return map.heights[k];
                    }
                    let mut sum = 0.0;
                    for a in 0..r {
                        let row = (i * r + a) * nf + j * r;
                        sum += map.heights[row..row + r].iter().sum::<f64>();
                    }
                    sum * w
                })
                .collect();
            GridSurface::new(n, map.size, heights)
        })
        .collect()
}

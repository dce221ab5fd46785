//! The crate's FFT set-up (features `bem` and `topography`): one planner
//! for the whole crate, so each length is planned once, for the BEM's 2-D
//! real transform (`bem::fft::Fft2`), the measured maps' spectra
//! (`topography::psd`) and their 2-D complex transforms
//! (`topography::anisotropy`). Transforms are unnormalised.
//!
//! # Panics
//! realfft's and rustfft's only failures are buffer lengths that do not
//! match the plan, and (inverse real transform) a DC or Nyquist bin with an
//! imaginary part. Every length passed here is one this crate computed from
//! the grid, and those bins are zeroed first, so such a failure is a bug in
//! the crate, never a property of the input: it panics (as RustFFT itself
//! does, see its `# Panics`) instead of being threaded through `Result` as
//! if a caller could cause or handle it. Lengths of buffers a caller passes
//! (`Fft2::forward`, `Fft2::inverse`) are checked there and are errors.
//!
//! # References
//! The rustfft 6.4 crate (mixed-radix, Rader and Bluestein plans chosen per
//! length) and the realfft 3.5 crate (a real transform of length n through
//! a complex one of length n/2), both on docs.rs.

use std::sync::{Arc, Mutex, OnceLock};

use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};

/// The reason a transform on lengths we computed cannot fail (module docs,
/// Panics).
pub(crate) const LENGTHS: &str = "FFT buffers of the lengths planned (a bug in persson if not)";

/// The crate's planners: realfft's and rustfft's, which keep every plan they
/// made, so a length is planned once per process.
struct Planners {
    real: RealFftPlanner<f64>,
    complex: FftPlanner<f64>,
}

fn planners() -> std::sync::MutexGuard<'static, Planners> {
    static PLANNERS: OnceLock<Mutex<Planners>> = OnceLock::new();
    PLANNERS
        .get_or_init(|| {
            Mutex::new(Planners {
                real: RealFftPlanner::new(),
                complex: FftPlanner::new(),
            })
        })
        .lock()
        // a panic while planning leaves the caches as valid as before
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// The forward real transform of length `n`.
pub(crate) fn real_forward(n: usize) -> Arc<dyn RealToComplex<f64>> {
    planners().real.plan_fft_forward(n)
}

/// The inverse real transform of length `n` (unnormalised).
#[cfg_attr(not(feature = "bem"), allow(dead_code))]
pub(crate) fn real_inverse(n: usize) -> Arc<dyn ComplexToReal<f64>> {
    planners().real.plan_fft_inverse(n)
}

/// The complex transform of length `n`, forward or inverse (unnormalised).
pub(crate) fn complex(n: usize, inverse: bool) -> Arc<dyn Fft<f64>> {
    let mut p = planners();
    if inverse {
        p.complex.plan_fft_inverse(n)
    } else {
        p.complex.plan_fft_forward(n)
    }
}

/// `out` = the half spectrum (`n/2 + 1` values) of the real row `x` (`n`,
/// overwritten as scratch).
///
/// # Panics
/// Buffers not of the plan's lengths (module docs).
pub(crate) fn forward_row(
    plan: &dyn RealToComplex<f64>,
    x: &mut [f64],
    out: &mut [Complex64],
    scratch: &mut [Complex64],
) {
    plan.process_with_scratch(x, out, scratch).expect(LENGTHS);
}

/// In-place 2-D complex FFT of a row-major `ny × nx` array (unnormalised).
#[cfg_attr(not(feature = "topography"), allow(dead_code))]
pub(crate) fn fft2(buf: &mut [Complex64], nx: usize, ny: usize, inverse: bool) {
    let (rows, cols) = (complex(nx, inverse), complex(ny, inverse));
    for row in buf.chunks_exact_mut(nx) {
        rows.process(row);
    }
    let mut col = vec![Complex64::new(0.0, 0.0); ny];
    for ix in 0..nx {
        for (iy, c) in col.iter_mut().enumerate() {
            *c = buf[iy * nx + ix];
        }
        cols.process(&mut col);
        for (iy, c) in col.iter().enumerate() {
            buf[iy * nx + ix] = *c;
        }
    }
}

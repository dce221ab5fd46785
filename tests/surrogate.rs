//! Surrogates of a height map (issue 39): the phase surrogates keep the
//! periodic spectrum at every wavevector, checked with a direct O(N⁴) DFT
//! (not the crate's FFT); the IAAFT surrogates keep the sorted heights
//! exactly and the radial spectrum to 1 %; the moments on closed forms.
#![cfg(feature = "bem")]

use persson::bem::surface::{synthesize, GridSurface};
use persson::bem::surrogate::{
    amplitude_adjusted, height_moments, phase_randomised, radial_mismatch, student_t_975,
    DEFAULT_IAAFT_ITERATIONS,
};
use persson::spectrum::{Amplitude, SelfAffine};
use persson::Error;

/// A Gaussian self-affine map, H = 0.8, on an `n`-grid of side 1.
fn gaussian(n: usize, seed: u64) -> GridSurface {
    let q0 = std::f64::consts::TAU;
    let s = SelfAffine::new(
        q0,
        2.0 * q0,
        n as f64 / 2.0 * q0,
        0.8,
        Amplitude::RmsHeight(1e-2),
    )
    .unwrap();
    synthesize(&s, n, 1.0, seed).unwrap()
}

/// The Gaussian map with its heights above the 60th percentile cut flat.
fn plateau(n: usize, seed: u64) -> GridSurface {
    let mut g = gaussian(n, seed);
    let mut sorted = g.heights.clone();
    sorted.sort_by(f64::total_cmp);
    let cut = sorted[sorted.len() * 6 / 10];
    for h in &mut g.heights {
        *h = h.min(cut);
    }
    g
}

/// Sparse tall bumps on a faint Gaussian background.
fn bumps(n: usize) -> GridSurface {
    let mut bumps = vec![0.0; n * n];
    // Sparse tall bumps on a faint Gaussian background.
    let background = gaussian(n, 21);
    for (b, g) in bumps.iter_mut().zip(&background.heights) {
        *b = 0.1 * g;
    }
    for k in 0..12 {
        let (ci, cj) = ((k * 37 + 5) % n, (k * 53 + 17) % n);
        for di in 0..n {
            for dj in 0..n {
                let d = |a: usize, c: usize| {
                    let t = (a as f64 - c as f64).abs();
                    t.min(n as f64 - t)
                };
                let r2 = d(di, ci).powi(2) + d(dj, cj).powi(2);
                bumps[di * n + dj] += 0.05 * (-r2 / 4.0).exp();
            }
        }
    }
    GridSurface::new(n, 1.0, bumps).unwrap()
}

/// |DFT|² of a real n × n map by the direct double sum.
fn power_direct(h: &[f64], n: usize) -> Vec<f64> {
    let w = std::f64::consts::TAU / n as f64;
    let mut out = vec![0.0; n * n];
    for ky in 0..n {
        for kx in 0..n {
            let (mut re, mut im) = (0.0, 0.0);
            for y in 0..n {
                for x in 0..n {
                    let phase = -w * ((kx * x + ky * y) % n) as f64;
                    let (s, c) = phase.sin_cos();
                    re += h[y * n + x] * c;
                    im += h[y * n + x] * s;
                }
            }
            out[ky * n + kx] = re * re + im * im;
        }
    }
    out
}

#[test]
fn phase_surrogates_keep_the_spectrum_at_every_wavevector() {
    let n = 32;
    for map in [gaussian(n, 3), plateau(n, 5)] {
        let target = power_direct(&map.heights, n);
        let top = target.iter().copied().fold(0.0, f64::max);
        for seed in [1, 2, 3] {
            let s = phase_randomised(&map, seed).unwrap();
            let got = power_direct(&s.heights, n);
            for (k, (a, b)) in target.iter().zip(&got).enumerate() {
                // Relative to each mode; the floor is the direct sum's own
                // rounding (N² terms of size ~√top·ε), far below any mode here.
                let tol = 1e-12 * a + 1e-24 * top;
                assert!(
                    (a - b).abs() <= tol,
                    "seed {seed}, mode {k}: {a:e} against {b:e}"
                );
            }
            // The mean is the map's; the surface is new.
            let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
            assert!((mean(&s.heights) - mean(&map.heights)).abs() < 1e-15);
            assert!(s.heights != map.heights);
        }
    }
}

#[test]
fn phase_surrogates_are_reproducible_and_gaussian() {
    let map = plateau(64, 11);
    let a = phase_randomised(&map, 7).unwrap();
    assert_eq!(a, phase_randomised(&map, 7).unwrap());
    assert_ne!(a, phase_randomised(&map, 8).unwrap());
    // The plateau is skewed (peaks cut); its surrogate is not: the skewness
    // of 64² random-phase heights has a spread of order 0.1 here.
    let (skew_map, _) = height_moments(&map.heights);
    assert!(skew_map < -0.5, "{skew_map}");
    let skews: Vec<f64> = (0..8)
        .map(|s| height_moments(&phase_randomised(&map, s).unwrap().heights).0)
        .collect();
    let mean = skews.iter().sum::<f64>() / 8.0;
    assert!(mean.abs() < 0.15, "{skews:?}");
}

/// A real AFM map (tests/data/di-3.di, 256², Nanoscope), its plane removed
/// as the spectrum's conditioning does.
#[cfg(feature = "topography")]
fn afm() -> GridSurface {
    use persson::topography::{read, Detrend, ReadOptions};
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/di-3.di");
    let t = read(&path, &ReadOptions::default()).unwrap();
    let [ny, nx] = t.shape();
    assert_eq!(ny, nx);
    GridSurface::new(nx, t.lx(), t.detrended(Detrend::Plane)).unwrap()
}

#[test]
fn amplitude_adjusted_surrogates_keep_the_heights_exactly_and_the_spectrum_to_one_percent() {
    let maps = [
        vec![plateau(64, 5)],
        #[cfg(feature = "topography")]
        vec![afm()],
    ];
    for map in maps.into_iter().flatten() {
        let mut sorted = map.heights.clone();
        sorted.sort_by(f64::total_cmp);
        for seed in [1, 2] {
            let s = amplitude_adjusted(&map, seed, DEFAULT_IAAFT_ITERATIONS).unwrap();
            let mut got = s.surface.heights.clone();
            got.sort_by(f64::total_cmp);
            assert_eq!(got, sorted, "the heights, exactly");
            let bins = radial_mismatch(&map, &s.surface).unwrap();
            assert_eq!(bins.len(), map.n / 2);
            let worst = bins
                .iter()
                .map(|b| b.relative_difference)
                .fold(0.0, f64::max);
            assert!(
                worst < 0.01,
                "worst bin {worst} after {} iterations",
                s.iterations
            );
            assert_eq!(worst, s.spectrum_mismatch);
        }
    }
}

/// Where the map's spectrum falls below what rearranging its heights adds
/// (sparse smooth bumps: a steep fall beyond their width), no rearrangement
/// reaches it, and the mismatch says so.
#[test]
fn an_unreachable_spectrum_is_reported() {
    let map = bumps(64);
    let s = amplitude_adjusted(&map, 1, DEFAULT_IAAFT_ITERATIONS).unwrap();
    let bins = radial_mismatch(&map, &s.surface).unwrap();
    // The band up to k = 16 is matched; the steep tail is not.
    assert!(bins[..16].iter().all(|b| b.relative_difference < 0.01));
    assert!(s.spectrum_mismatch > 1.0, "{}", s.spectrum_mismatch);
    assert!(!s.converged);
}

#[test]
fn height_moments_of_known_distributions() {
    // ±1 with equal weight: skewness 0, kurtosis 1.
    let (s, k) = height_moments(&[1.0, -1.0, 1.0, -1.0]);
    assert!(s.abs() < 1e-15 && (k - 1.0).abs() < 1e-15);
    // One spike among m zeros (Bernoulli p = 1/(m+1)): skewness (1−2p)/√(p(1−p)),
    // kurtosis (1 − 3p(1−p))/(p(1−p)).
    let m = 9;
    let mut v = vec![0.0; m];
    v.push(1.0);
    let p = 1.0 / (m as f64 + 1.0);
    let (s, k) = height_moments(&v);
    let q = p * (1.0 - p);
    assert!((s - (1.0 - 2.0 * p) / q.sqrt()).abs() < 1e-14, "{s}");
    assert!((k - (1.0 - 3.0 * q) / q).abs() < 1e-13, "{k}");
    assert_eq!(height_moments(&[2.0; 5]), (0.0, 0.0));
}

#[test]
fn bad_input_is_named() {
    let flat = GridSurface::new(8, 1.0, vec![1.5; 64]).unwrap();
    for e in [
        phase_randomised(&flat, 1).unwrap_err(),
        amplitude_adjusted(&flat, 1, 10).unwrap_err(),
    ] {
        assert!(
            matches!(&e, Error::Inconsistent { name, .. } if name == "heights"),
            "{e}"
        );
    }
    let map = gaussian(16, 1);
    assert!(matches!(
        amplitude_adjusted(&map, 1, 0),
        Err(Error::InvalidParameter { ref name, .. }) if name == "iterations"
    ));
    let other = gaussian(32, 1);
    assert!(radial_mismatch(&map, &other).is_err());
}

/// P(|T| ≤ t) of Student's t with ν degrees of freedom, by adaptive
/// Gauss–Kronrod (bilby) of its density, an oracle independent of the table.
fn t_coverage(t: f64, nu: f64) -> f64 {
    let ln_c = libm::lgamma((nu + 1.0) / 2.0)
        - libm::lgamma(nu / 2.0)
        - 0.5 * (nu * std::f64::consts::PI).ln();
    let pdf = |x: f64| (ln_c - (nu + 1.0) / 2.0 * (1.0 + x * x / nu).ln()).exp();
    let r = bilby::AdaptiveIntegrator::default()
        .with_abs_tol(1e-13)
        .with_rel_tol(1e-13)
        .integrate(0.0, t, pdf)
        .unwrap();
    2.0 * r.value
}

#[test]
fn student_t_quantiles_cover_95_percent() {
    for nu in [1, 2, 3, 5, 7, 10, 20, 30] {
        let c = t_coverage(student_t_975(nu), nu as f64);
        // 3 decimals of t: the coverage to about 1e-4.
        assert!((c - 0.95).abs() < 2e-4, "ν = {nu}: {c}");
    }
    for nu in [31, 50, 100, 1000] {
        let c = t_coverage(student_t_975(nu), nu as f64);
        assert!((c - 0.95).abs() < 1e-4, "ν = {nu}: {c}");
    }
    assert_eq!(student_t_975(0), f64::INFINITY);
}

//! One surface on several grids (`persson::bem::resample`) and the spectrum
//! a grid resolves (`persson::spectrum::BandLimited`): the numerics under the
//! resolution studies of `persson compare`.
#![cfg(feature = "bem")]

use persson::bem::resample::{band_limited_copies, band_limited_map, coarsened, nested_surfaces};
use persson::bem::GridSurface;
use persson::spectrum::{Amplitude, BandLimited, SelfAffine, Spectrum};

/// Rounding of sums over ≤ 256² values and of a few FFTs.
const ROUNDING: f64 = 1e-12;

/// H = 0.8 surface with a roll-off at 2 q_l, q_s = `q_s` q_l, rms slope 0.1, q_l = 1.
fn surface_spectrum(q_s: f64) -> SelfAffine {
    SelfAffine::new(1.0, 2.0, q_s, 0.8, Amplitude::RmsSlope(0.1)).unwrap()
}

#[test]
fn band_limit_clips_the_spectrum() {
    let s = surface_spectrum(64.0);
    let b = BandLimited::new(&s, 16.0).unwrap();
    assert!(b.clipped());
    assert_eq!(b.q_max(), 16.0);
    assert_eq!(b.c(20.0), 0.0);
    assert_eq!(b.c(10.0), s.c(10.0));
    let m = b.moment(3, 0.0, 100.0).unwrap().value;
    let r = s.moment(3, 0.0, 16.0).unwrap().value;
    assert!((m - r).abs() <= ROUNDING * r);
    assert!(!BandLimited::new(&s, 100.0).unwrap().clipped());
    assert!(BandLimited::new(&s, 0.5).is_err());
}

#[test]
fn nested_surfaces_are_one_band_limited_surface() {
    // The coarse grids subsample the finest: the trigonometric interpolants
    // coincide, so rms height and rms slope (computed by FFT on each grid)
    // agree to rounding. Aliasing of any mode would break this.
    let s = surface_spectrum(16.0);
    let surfaces = nested_surfaces(&s, &[64, 128, 256], std::f64::consts::TAU, 7).unwrap();
    let fine: &GridSurface = &surfaces[2];
    let (h, g) = (fine.rms_height(), fine.rms_slope().unwrap());
    for c in &surfaces[..2] {
        assert!(
            (c.rms_height() - h).abs() <= 1e-10 * h,
            "{} vs {h}",
            c.rms_height()
        );
        let gc = c.rms_slope().unwrap();
        assert!((gc - g).abs() <= 1e-10 * g, "{gc} vs {g}");
    }
    // q_s beyond the coarsest Nyquist (16²: k < 8 − 1) is refused
    assert!(nested_surfaces(&s, &[16, 32], std::f64::consts::TAU, 7).is_err());
    assert!(nested_surfaces(&s, &[64, 96], std::f64::consts::TAU, 7).is_err());
}

/// A periodic map low-passed at q_s and sampled on coarser grids: every copy
/// is the low-passed map (the same trigonometric interpolant, so the same rms
/// height and slope to rounding), its modes beyond q_s are gone, and a cut
/// above the coarsest Nyquist wavevector is refused. The block-averaged copies
/// of a map keep its mean exactly.
#[test]
fn low_passed_copies_are_one_surface_and_block_means_keep_the_mean() {
    let s = surface_spectrum(16.0);
    let tau = std::f64::consts::TAU;
    // a map with modes up to q = 16 on 128² (side 2π: q = k)
    let map = persson::bem::surface::synthesize(&s, 128, tau, 3).unwrap();
    let cut = band_limited_map(&map, 6.0).unwrap();
    // the cut removes the band 6 < q ≤ 16: the rms slope falls
    assert!(cut.rms_slope().unwrap() < 0.9 * map.rms_slope().unwrap());
    // cutting again at the same q_s changes nothing (a projection)
    let again = band_limited_map(&cut, 6.0).unwrap();
    for (a, b) in again.heights.iter().zip(&cut.heights) {
        assert!((a - b).abs() <= ROUNDING * cut.rms_height(), "{a} vs {b}");
    }
    let copies = band_limited_copies(&map, 6.0, &[32, 64, 128]).unwrap();
    let (h, g) = (cut.rms_height(), cut.rms_slope().unwrap());
    for c in &copies {
        assert!((c.rms_height() - h).abs() <= 1e-10 * h);
        assert!((c.rms_slope().unwrap() - g).abs() <= 1e-10 * g);
    }
    // 16² resolves |k| < 8: a cut at 8 is refused
    assert!(band_limited_copies(&map, 8.0, &[16, 128]).is_err());
    let blocks = coarsened(&map, &[32, 64, 128]).unwrap();
    let mean = |m: &GridSurface| m.heights.iter().sum::<f64>() / m.heights.len() as f64;
    for b in &blocks {
        assert!((mean(b) - mean(&map)).abs() <= ROUNDING * map.rms_height());
    }
    assert_eq!(blocks[2].heights, map.heights);
    assert!(coarsened(&map, &[32, 64]).is_err()); // the finest must be the map's
}

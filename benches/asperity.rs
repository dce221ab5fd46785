//! Benchmarks of issue 27: 100-point curves of the asperity theories, the
//! contact-patch statistics of a 1024² mask, and one plane of subsurface
//! stress on a 1024² grid (periodic and free).
//!
//! `cargo bench --bench asperity`

use persson::asperity::{
    AsperityTheory, Bush, EllipticHertz, GreenwoodWilliamson, SpectralMoments,
};

fn main() {
    divan::main();
}

/// A self-affine surface: H = 0.8, q_l = 1e4, q_r = 4e4, q_s = 4e6 1/m, h'_rms = 0.5.
fn moments() -> SpectralMoments {
    use persson::spectrum::{Amplitude, SelfAffine};
    let s = SelfAffine::new(1e4, 4e4, 4e6, 0.8, Amplitude::RmsSlope(0.5)).unwrap();
    SpectralMoments::from_spectrum(&s).unwrap()
}

/// 100 separations from −1 to 4 rms heights.
fn separations(m: &SpectralMoments) -> Vec<f64> {
    (0..100)
        .map(|i| m.rms_height() * (-1.0 + 5.0 * i as f64 / 99.0))
        .collect()
}

/// 100 nominal pressures from 1e-5 to 1e-2 E*.
fn pressures() -> Vec<f64> {
    (0..100)
        .map(|i| 1e-5 * 10f64.powf(3.0 * i as f64 / 99.0))
        .collect()
}

#[divan::bench]
fn gw_separation_curve(bencher: divan::Bencher) {
    let m = moments();
    let gw = GreenwoodWilliamson::from_moments(&m, 1.0).unwrap();
    let d = separations(&m);
    bencher.bench_local(|| gw.separation_curve(divan::black_box(&d)).unwrap());
}

#[divan::bench]
fn gw_pressure_curve(bencher: divan::Bencher) {
    let gw = GreenwoodWilliamson::from_moments(&moments(), 1.0).unwrap();
    let p = pressures();
    bencher.bench_local(|| gw.pressure_curve(divan::black_box(&p)).unwrap());
}

/// The model built once (its summit table included), then 100 points.
#[divan::bench]
fn bush_separation_curve(bencher: divan::Bencher) {
    let m = moments();
    let b = Bush::new(&m, 1.0, EllipticHertz::Exact).unwrap();
    let d = separations(&m);
    b.at_separation(0.0).unwrap();
    bencher.bench_local(|| b.separation_curve(divan::black_box(&d)).unwrap());
}

/// A fresh model each time: the summit table is built inside the timing.
#[divan::bench(sample_count = 20)]
fn bush_separation_curve_with_setup(bencher: divan::Bencher) {
    let m = moments();
    let d = separations(&m);
    bencher.bench_local(|| {
        let b = Bush::new(&m, 1.0, EllipticHertz::Exact).unwrap();
        b.separation_curve(divan::black_box(&d)).unwrap()
    });
}

#[divan::bench(sample_count = 20)]
fn bush_pressure_curve(bencher: divan::Bencher) {
    let b = Bush::new(&moments(), 1.0, EllipticHertz::Exact).unwrap();
    let p = pressures();
    b.at_separation(0.0).unwrap();
    bencher.bench_local(|| b.pressure_curve(divan::black_box(&p)).unwrap());
}

/// The pressure curve of `bush_pressure_curve` without the table of ln J/φ
/// in δ: every Newton step integrates the summit table (the path before it).
#[divan::bench(sample_count = 20)]
fn bush_pressure_curve_summit_table(bencher: divan::Bencher) {
    let b = Bush::new(&moments(), 1.0, EllipticHertz::Exact)
        .unwrap()
        .with_separation_table(false);
    let p = pressures();
    b.at_separation(0.0).unwrap();
    bencher.bench_local(|| b.pressure_curve(divan::black_box(&p)).unwrap());
}

/// `bush_separation_curve` without the table of ln J/φ in δ.
#[divan::bench]
fn bush_separation_curve_summit_table(bencher: divan::Bencher) {
    let m = moments();
    let b = Bush::new(&m, 1.0, EllipticHertz::Exact)
        .unwrap()
        .with_separation_table(false);
    let d = separations(&m);
    b.at_separation(0.0).unwrap();
    bencher.bench_local(|| b.separation_curve(divan::black_box(&d)).unwrap());
}

#[cfg(feature = "bem")]
mod bem {
    use persson::bem::patches::{patch_statistics, PatchOptions};
    use persson::bem::subsurface::Subsurface;
    use persson::bem::surface::synthesize;
    use persson::bem::Boundary;
    use persson::spectrum::{Amplitude, SelfAffine};

    /// Heights of a 1024² self-affine surface (H = 0.8, q_s = 256 q_l) and
    /// the cut leaving ~10 % above it.
    fn field(n: usize) -> (Vec<f64>, f64) {
        let ql = std::f64::consts::TAU;
        let s = SelfAffine::new(
            ql,
            4.0 * ql,
            ql * n as f64 / 4.0,
            0.8,
            Amplitude::RmsSlope(0.1),
        )
        .unwrap();
        let h = synthesize(&s, n, 1.0, 7).unwrap().heights;
        let mut sorted = h.clone();
        sorted.sort_by(f64::total_cmp);
        let cut = sorted[sorted.len() * 9 / 10];
        (h, cut)
    }

    #[divan::bench(args = [1024], sample_count = 20)]
    fn patches(bencher: divan::Bencher, n: usize) {
        let (h, cut) = field(n);
        let mask: Vec<bool> = h.iter().map(|&v| v > cut).collect();
        let o = PatchOptions::default();
        bencher.bench_local(|| {
            patch_statistics(divan::black_box(&mask), n, 1.0, &o)
                .unwrap()
                .patch_count
        });
    }

    fn pressure(n: usize) -> Vec<f64> {
        let (h, cut) = field(n);
        h.iter().map(|&v| (v - cut).max(0.0)).collect()
    }

    #[divan::bench(args = [1024], sample_count = 5)]
    fn subsurface_plane_periodic(bencher: divan::Bencher, n: usize) {
        let p = pressure(n);
        let mut s = Subsurface::new(&p, n, 1.0, Boundary::Periodic, 0.3).unwrap();
        bencher.bench_local(|| {
            s.plane(divan::black_box(0.01))
                .unwrap()
                .summary
                .von_mises_stress
                .value
        });
    }

    #[divan::bench(args = [1024], sample_count = 5)]
    fn subsurface_plane_free(bencher: divan::Bencher, n: usize) {
        let p = pressure(n);
        let mut s = Subsurface::new(&p, n, 1.0, Boundary::Free, 0.3).unwrap();
        bencher.bench_local(|| {
            s.plane(divan::black_box(0.01))
                .unwrap()
                .summary
                .von_mises_stress
                .value
        });
    }
}

//! Corrected-theory load curves and the mean separation.
//!
//! `cargo bench --bench theories`. Target: a 100-point load curve
//! for any theory under 1 ms on a self-affine or a 10,000-point tabulated
//! spectrum.

use persson::corrected::{self, Theory};
use persson::separation::Separation;
use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Tabulated};
use persson::theory::Persson;

fn main() {
    divan::main();
}

fn self_affine() -> SelfAffine {
    SelfAffine::new(1e3, 1e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

/// The self-affine spectrum sampled at 10,000 log-spaced wavevectors.
fn tabulated() -> Tabulated {
    let s = self_affine();
    let n = 10_000;
    let (a, b) = (s.q_min().ln(), s.q_max().ln());
    let pts: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let q = (a + (b - a) * i as f64 / (n - 1) as f64)
                .exp()
                .clamp(s.q_min(), s.q_max());
            (q, s.c(q))
        })
        .collect();
    Tabulated::new(&pts).unwrap()
}

/// 100 pressures from 1e-5 E* to 1 E* (A/A0 from ~1e-5 to ~0.9).
fn pressures() -> Vec<f64> {
    (0..100)
        .map(|i| 10f64.powf(-5.0 + 5.0 * i as f64 / 99.0))
        .collect()
}

const THEORIES: [&str; 4] = corrected::THEORY_NAMES;

#[divan::bench(args = THEORIES)]
fn area_curve_self_affine(bencher: divan::Bencher, name: &str) {
    let s = self_affine();
    let model = Persson::new(&s, 1.0).unwrap();
    let theory = Theory::from_name(name, None).unwrap();
    let p = pressures();
    bencher.bench_local(|| {
        corrected::load_curve(
            &model,
            theory,
            model.zeta_max(),
            divan::black_box(&p),
            1e-12,
        )
        .unwrap()
    });
}

#[divan::bench(args = THEORIES)]
fn area_curve_tabulated_10k(bencher: divan::Bencher, name: &str) {
    let s = tabulated();
    let model = Persson::new(&s, 1.0).unwrap();
    let theory = Theory::from_name(name, None).unwrap();
    let p = pressures();
    bencher.bench_local(|| {
        corrected::load_curve(
            &model,
            theory,
            model.zeta_max(),
            divan::black_box(&p),
            1e-12,
        )
        .unwrap()
    });
}

#[divan::bench(sample_count = 10)]
fn separation_curve_self_affine(bencher: divan::Bencher) {
    let s = self_affine();
    let sep = Separation::new(&s, 1.0).unwrap().with_breaks(&[s.q_r()]);
    let p = pressures();
    bencher.bench_local(|| sep.load_curve(divan::black_box(&p)).unwrap());
}

#[divan::bench(sample_count = 10)]
fn separation_point_self_affine(bencher: divan::Bencher) {
    let s = self_affine();
    let sep = Separation::new(&s, 1.0).unwrap().with_breaks(&[s.q_r()]);
    bencher.bench_local(|| sep.point(divan::black_box(1e-3)).unwrap());
}

#[divan::bench(sample_count = 3)]
fn separation_point_tabulated_10k(bencher: divan::Bencher) {
    let s = tabulated();
    let sep = Separation::new(&s, 1.0).unwrap();
    bencher.bench_local(|| sep.point(divan::black_box(1e-3)).unwrap());
}

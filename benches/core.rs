//! Speed of the core: `cargo bench --bench core`.
//!
//! Targets: A/A0 at one pressure on the self-affine spectrum under 1 µs; a
//! 10,000-point tabulated spectrum set up in under 1 ms, then G(ζ) in under 1 µs.

use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Tabulated};
use persson::theory::Persson;

fn main() {
    divan::main();
}

fn self_affine() -> SelfAffine {
    SelfAffine::new(1e4, 1e5, 1e9, 0.8, Amplitude::RmsHeight(1e-6)).unwrap()
}

fn table(n: usize) -> Vec<(f64, f64)> {
    let s = self_affine();
    (0..n)
        .map(|i| {
            let q = 1e4 * 1e5f64.powf(i as f64 / (n - 1) as f64);
            (q, s.c(q) * (1.0 + 0.1 * (i as f64).sin()))
        })
        .collect()
}

#[divan::bench]
fn area_self_affine(b: divan::Bencher) {
    let s = self_affine();
    let m = Persson::new(&s, 1e9).unwrap();
    b.bench(|| {
        m.contact_fraction(divan::black_box(1e4), divan::black_box(1e6))
            .unwrap()
            .fraction
    });
}

#[divan::bench]
fn tabulated_setup_10k(b: divan::Bencher) {
    let pts = table(10_000);
    b.bench(|| Tabulated::new(divan::black_box(&pts)).unwrap());
}

#[divan::bench]
fn g_tabulated_10k(b: divan::Bencher) {
    let t = Tabulated::new(&table(10_000)).unwrap();
    let m = Persson::new(&t, 1e9).unwrap();
    let mut z = 1.0;
    b.bench_local(|| {
        z = if z > 9e4 { 1.0 } else { z * 1.37 };
        m.g(divan::black_box(z), 1e6).unwrap().value
    });
}

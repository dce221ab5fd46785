//! Benchmarks of the boundary-element solver (feature `bem`): one operator
//! application (two 2-D real FFTs; 𝒢 and the stiffness 𝒦), and whole
//! solves (Hertz, rough: preconditioned and plain, saturated).
//!
//! `cargo bench --bench bem` (the iteration table of issue 22 is
//! `cargo run --release --example bem_iterations`).

use persson::bem::surface::synthesize;
use persson::bem::{hertz, Boundary, Control, Method, Operator, Options, Solver};
use persson::spectrum::{Amplitude, SelfAffine};

fn main() {
    divan::main();
}

#[divan::bench(args = [256, 512, 1024])]
fn apply_periodic(bencher: divan::Bencher, n: usize) {
    let mut op = Operator::new(Boundary::Periodic, n, 1.0, 1.0).unwrap();
    let p: Vec<f64> = (0..n * n).map(|k| (k % 7) as f64).collect();
    let mut u = vec![0.0; n * n];
    bencher.bench_local(|| op.apply(divan::black_box(&p), &mut u).unwrap());
}

#[divan::bench(args = [256, 512, 1024])]
fn apply_stiffness_periodic(bencher: divan::Bencher, n: usize) {
    let mut op = Operator::new(Boundary::Periodic, n, 1.0, 1.0).unwrap();
    let u: Vec<f64> = (0..n * n).map(|k| (k % 7) as f64).collect();
    let mut p = vec![0.0; n * n];
    bencher.bench_local(|| op.apply_stiffness(divan::black_box(&u), &mut p).unwrap());
}

#[divan::bench(args = [256, 512])]
fn apply_free(bencher: divan::Bencher, n: usize) {
    let mut op = Operator::new(Boundary::Free, n, 1.0, 1.0).unwrap();
    let p: Vec<f64> = (0..n * n).map(|k| (k % 7) as f64).collect();
    let mut u = vec![0.0; n * n];
    bencher.bench_local(|| op.apply(divan::black_box(&p), &mut u).unwrap());
}

#[divan::bench(args = [256, 512], sample_count = 5)]
fn hertz_periodic(n: usize) -> f64 {
    let opts = Options {
        tolerance: 1e-10,
        ..Options::default()
    };
    hertz::validate(&hertz::HertzCase::new(n, Boundary::Periodic), &opts)
        .unwrap()
        .energy_error
}

fn rough_surface(n: usize) -> Vec<f64> {
    // H = 0.8, rms slope 0.1, q_l = 2π, q_r = 4 q_l, q_s = (N/4) q_l.
    let ql = std::f64::consts::TAU;
    let s = SelfAffine::new(
        ql,
        4.0 * ql,
        ql * n as f64 / 4.0,
        0.8,
        Amplitude::RmsSlope(0.1),
    )
    .unwrap();
    synthesize(&s, n, 1.0, 1).unwrap().heights
}

/// The rough case at p = 0.005 E*, preconditioned (default) and plain.
#[divan::bench(args = [256, 512], consts = [true, false], sample_count = 5)]
fn rough_periodic<const PRECONDITIONED: bool>(bencher: divan::Bencher, n: usize) {
    let heights = rough_surface(n);
    let opts = Options {
        tolerance: 1e-10,
        ..Options::default()
    };
    let method = if PRECONDITIONED {
        Method::default()
    } else {
        Method::Plain
    };
    bencher.bench_local(|| {
        let op = Operator::new(Boundary::Periodic, n, 1.0, 1.0).unwrap();
        Solver::with_method(op, method)
            .solve(&heights, Control::MeanPressure(0.005), &opts)
            .unwrap()
            .contact_fraction
    });
}

#[divan::bench(args = [256, 512], sample_count = 3)]
fn rough_saturated(bencher: divan::Bencher, n: usize) {
    // The surface of rough_periodic at p = 0.006 E* with σY = 0.02 E*
    // (the Tamaas KatoSaturated comparison of examples/tamaas_compare.py).
    let heights = rough_surface(n);
    let opts = Options {
        tolerance: 1e-10,
        yield_stress: Some(0.02),
        ..Options::default()
    };
    bencher.bench_local(|| {
        let mut solver = Solver::new(Operator::new(Boundary::Periodic, n, 1.0, 1.0).unwrap());
        solver
            .solve(&heights, Control::MeanPressure(0.006), &opts)
            .unwrap()
            .plastic_fraction
    });
}

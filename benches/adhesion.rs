//! Adhesion theory timings: the stickiness scan, one adhesive point (the
//! moving-boundary Volterra solve on two meshes) in the bulk and near
//! pull-off, and a rubber case in physical units; with the `bem` feature, one
//! adhesive FFT-BEM solve at 128² with each iteration.
//!
//! Run: `cargo bench --bench adhesion`

use persson::adhesion::{AdhesionModel, AdhesiveContact};
use persson::spectrum::{Amplitude, SelfAffine};

fn main() {
    divan::main();
}

/// q_l = 1, q_r = 2, q_s = 100, H = 0.8, h'_rms = 0.5, E* = 1 (tests/adhesion.rs).
fn test_spectrum() -> SelfAffine {
    SelfAffine::new(1.0, 2.0, 100.0, 0.8, Amplitude::RmsSlope(0.5)).unwrap()
}

/// Δγ_eff(ζ) scan with sign changes, rubber (E* = 1 MPa) on q_l = 1e4 … q_s = 1e8.
#[divan::bench]
fn stickiness_rubber() -> bool {
    let s = SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
    let m = AdhesionModel::new(&s, 1e6, divan::black_box(0.05)).unwrap();
    m.stickiness(&[10.0, 1e3, 1e4]).unwrap().sticky
}

/// A/A0 at σ0 = 0.05 E*, ζ = 100, default tolerance 1e-5.
#[divan::bench]
fn point_compressive() -> f64 {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(0.05), 100.0)
        .unwrap()
        .contact_fraction
}

/// A/A0 at σ0 = 0 (the adhesive contact under no load), tolerance 1e-5.
#[divan::bench]
fn point_zero_load() -> f64 {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(0.0), 100.0)
        .unwrap()
        .contact_fraction
}

/// A/A0 at σ0 = −0.99 σ_p (close to pull-off), tolerance 1e-5.
#[divan::bench]
fn point_near_pull_off() -> f64 {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let sp = m.pull_off_stress().unwrap().value;
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(-0.99 * sp), 100.0)
        .unwrap()
        .contact_fraction
}

/// Rubber, sticky (Δγ = 0.2 J/m², E* = 1 MPa, ζ_max = 1e4): A/A0 at σ0 = 0.
#[divan::bench]
fn point_rubber_zero_load() -> f64 {
    let s = SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
    let m = AdhesionModel::new(&s, 1e6, 0.2).unwrap();
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(0.0), 1e4)
        .unwrap()
        .contact_fraction
}

/// The adhesive FFT-BEM: one cold solve of the exponential law on a 128²
/// self-affine surface (the set-up of examples/adhesive_tamaas.rs, tolerance
/// 1e-10), with each iteration.
#[cfg(feature = "bem")]
mod bem {
    use persson::bem::adhesive::{AdhesiveOptions, AdhesiveSolver, CohesiveLaw};
    use persson::bem::surface::synthesize;
    use persson::bem::{Boundary, Method, Operator};
    use persson::spectrum::{Amplitude, SelfAffine};

    fn case(n: usize) -> (Vec<f64>, CohesiveLaw, f64) {
        let tau = std::f64::consts::TAU;
        let s = SelfAffine::new(tau, tau, 32.0 * tau, 0.8, Amplitude::RmsSlope(0.1)).unwrap();
        let h = synthesize(&s, n, 1.0, 1).unwrap().heights;
        let n2 = (n * n) as f64;
        let mean = h.iter().sum::<f64>() / n2;
        let rms = (h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n2).sqrt();
        let h_max = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let rho = rms / 20.0;
        let law = CohesiveLaw::exponential(0.02 * rho, rho).unwrap();
        (h, law, 0.6 * (h_max - mean))
    }

    fn solve(method: Method) -> f64 {
        let n = 128;
        let (h, law, mean_gap) = case(n);
        let opts = AdhesiveOptions {
            tolerance: 1e-10,
            max_iterations: 20_000,
        };
        let mut s = AdhesiveSolver::new(Operator::new(Boundary::Periodic, n, 1.0, 1.0).unwrap())
            .unwrap()
            .with_method(method);
        s.solve(&h, &law, divan::black_box(mean_gap), &opts)
            .unwrap()
            .mean_pressure
    }

    /// Preconditioned (the exponential law's default).
    #[divan::bench]
    fn adhesive_bem_preconditioned_128() -> f64 {
        solve(Method::PRECONDITIONED)
    }

    /// Plain conjugate gradient.
    #[divan::bench]
    fn adhesive_bem_plain_128() -> f64 {
        solve(Method::Plain)
    }
}

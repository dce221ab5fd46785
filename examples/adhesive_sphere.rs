//! Pull-off of a sphere from the adhesive FFT-BEM (Maugis–Dugdale law) on a
//! periodic cell, against N and the Maugis parameter λ: the measured figures
//! of docs/adhesion.md. Run: cargo run --release --example adhesive_sphere [N…]
//!
//! R = 1, E* = 1, L = 1, Δγ = 1e-4; λ = (Δγ/ρ)(9R/(2πΔγE*²))^{1/3} (Maugis 1992).

use persson::bem::adhesive::{AdhesiveOptions, AdhesiveSolver, CohesiveLaw};
use persson::bem::{Boundary, Operator};

fn sphere(n: usize) -> Vec<f64> {
    let dx = 1.0 / n as f64;
    let mut h = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            let x = (i as f64 + 0.5) * dx - 0.5;
            let y = (j as f64 + 0.5) * dx - 0.5;
            h[i * n + j] = -(x * x + y * y) / 2.0;
        }
    }
    h
}

fn main() {
    let grids: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let grids = if grids.is_empty() {
        vec![64, 128, 256]
    } else {
        grids
    };
    let dg = 1e-4;
    let scale = (9.0 / (2.0 * std::f64::consts::PI * dg)).cbrt();
    let exponential = std::env::var_os("EXPONENTIAL").is_some();
    for lambda in [0.3, 1.0, 3.0] {
        let rho = dg / lambda * scale;
        for &n in &grids {
            let h = sphere(n);
            let h_max = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let rigid_mean = h.iter().map(|v| h_max - v).sum::<f64>() / (n * n) as f64;
            let op = Operator::new(Boundary::Periodic, n, 1.0, 1.0).unwrap();
            let mut s = AdhesiveSolver::new(op).unwrap();
            let law = if exponential {
                CohesiveLaw::exponential(dg, rho).unwrap()
            } else {
                CohesiveLaw::maugis(dg, rho).unwrap()
            };
            let mut gaps: Vec<f64> = (0..=10)
                .map(|k| rigid_mean + 2.0 * rho - 0.006 * k as f64 / 10.0)
                .collect();
            let back: Vec<f64> = (0..=50)
                .map(|k| rigid_mean - 0.006 + 0.026 * k as f64 / 50.0)
                .collect();
            gaps.extend(back);
            let t = std::time::Instant::now();
            let seq = s
                .sequence(
                    &h,
                    &law,
                    &gaps,
                    &AdhesiveOptions {
                        tolerance: 1e-8,
                        max_iterations: 20_000,
                    },
                )
                .unwrap();
            let it: usize = seq.points.iter().map(|p| p.iterations).sum();
            let bad = seq.points.iter().filter(|p| !p.converged).count();
            println!(
                "λ = {lambda}, N = {n}: F/(πRΔγ) = {:.4}, {} solves, {it} iterations, {bad} not converged, {:.2} s",
                seq.pull_off_pressure / (std::f64::consts::PI * dg),
                seq.points.len(),
                t.elapsed().as_secs_f64()
            );
        }
    }
}

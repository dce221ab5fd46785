//! One adhesive solve on a synthesised self-affine surface, for the side-by-side
//! with Tamaas 2.9 (`examples/adhesive_tamaas.py` runs this and Tamaas on the same
//! heights, mean gap and tolerance). Run:
//! `cargo run --release --example adhesive_tamaas N OUT_DIR [maugis|exponential] [auto|plain|preconditioned]`
//! (the iteration: `auto` is the solver's choice by the law, `AdhesiveSolver::method_for`).
//!
//! Surface: L = 1, self-affine H = 0.8, q_l = q_r = 2π, q_s = 2π·32, rms slope 0.1,
//! seed 1, E* = 1. Law: ρ = h_rms/20, Δγ = 0.02 ρ (cohesive stress Δγ/ρ = 0.02 E*);
//! mean gap 0.6 × the rigid mean gap (h_max − mean h); tolerance 1e-10. Writes
//! OUT_DIR/surface_N.npy and gap_N.npy and prints one JSON line with the answer and the time.

use persson::bem::adhesive::{AdhesiveOptions, AdhesiveSolver, CohesiveLaw};
use persson::bem::surface::synthesize;
use persson::bem::{Boundary, Method, Operator};
use persson::spectrum::{Amplitude, SelfAffine};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().ok_or("N")?.parse()?;
    let dir = std::path::PathBuf::from(args.next().ok_or("OUT_DIR")?);
    let law_name = args.next().unwrap_or_else(|| "maugis".into());
    let method_name = args.next().unwrap_or_else(|| "auto".into());
    let method = match method_name.as_str() {
        "auto" => None,
        "plain" => Some(Method::Plain),
        "preconditioned" => Some(Method::PRECONDITIONED),
        other => {
            return Err(format!("method {other:?}: one of auto, plain, preconditioned").into())
        }
    };
    let tau = std::f64::consts::TAU;
    let spectrum = SelfAffine::new(tau, tau, 32.0 * tau, 0.8, Amplitude::RmsSlope(0.1))?;
    let s = synthesize(&spectrum, n, 1.0, 1)?;
    let h = &s.heights;
    let n2 = (n * n) as f64;
    let mean = h.iter().sum::<f64>() / n2;
    let rms = (h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n2).sqrt();
    let h_max = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (rho, mean_gap) = (rms / 20.0, 0.6 * (h_max - mean));
    let dg = 0.02 * rho;
    let law = match law_name.as_str() {
        "exponential" => CohesiveLaw::exponential(dg, rho)?,
        _ => CohesiveLaw::maugis(dg, rho)?,
    };
    persson::io::npy::write(&dir.join(format!("surface_{n}.npy")), n, n, h)?;
    let opts = AdhesiveOptions {
        tolerance: 1e-10,
        max_iterations: 20_000,
    };
    let t = std::time::Instant::now();
    let mut solver = AdhesiveSolver::new(Operator::new(Boundary::Periodic, n, 1.0, 1.0)?)?;
    solver.set_method(method);
    let used = solver.method_for(&law);
    let p = solver.solve(h, &law, mean_gap, &opts)?;
    let seconds = t.elapsed().as_secs_f64();
    persson::io::npy::write(&dir.join(format!("gap_{n}.npy")), n, n, solver.gap())?;
    println!(
        "{{\"n\": {n}, \"law\": \"{law_name}\", \"method\": \"{}\", \"work_of_adhesion\": {dg:e}, \"adhesion_range\": {rho:e}, \
         \"mean_gap\": {mean_gap:e}, \"mean_pressure\": {:e}, \"contact_fraction\": {:e}, \
         \"cohesive_fraction\": {:e}, \"iterations\": {}, \"residual\": {:e}, \"converged\": {}, \"fallback\": {}, \"seconds\": {seconds}}}",
        match used { Method::Plain => "plain", _ => "preconditioned" },
        p.mean_pressure, p.contact_fraction, p.cohesive_fraction, p.iterations, p.residual, p.converged,
        p.fallback.is_some()
    );
    Ok(())
}

//! One adhesive solve on a synthesised self-affine surface, for the side-by-side
//! with Tamaas 2.9 (`examples/adhesive_tamaas.py` runs this and Tamaas on the same
//! heights, mean gap and tolerance). Run:
//! `cargo run --release --example adhesive_tamaas N OUT_DIR [maugis|exponential] [auto|plain|preconditioned|starts|sensitivity] [S] [D]`
//! (the iteration: `auto` is the solver's choice by the law, `AdhesiveSolver::method_for`).
//! `starts` (Maugis–Dugdale, issue 24) solves the same mean gap from several starts with
//! both iterations — cold (the rigid gap), from the exponential law's solution, from the
//! Δγ = 0 solution, a ramp of Δγ (¼, ½, ¾, 1) and an approach from 1.3 ḡ — and prints per
//! start p̄, A/A0, the iterations, the energy Π/A and the time (text, not JSON).
//!
//! `sensitivity` (Maugis–Dugdale) solves cold at ḡ(1 + k·1e-9), k = −2…2, and at ḡ with
//! the tolerances 1e-8 and 1e-12, both iterations, and prints the cohesive length
//! E*ρ²/Δγ in grid spacings: whether the answer moves under perturbations far below any
//! accuracy asked of it, and how far the two iterations' answers lie apart.
//!
//! Surface: L = 1, self-affine H = 0.8, q_l = q_r = 2π, q_s = 2π·32, rms slope 0.1,
//! seed 1, E* = 1. Law: ρ = h_rms/D (D = 20 unless given), Δγ = S ρ (cohesive stress
//! Δγ/ρ = S E*, S = 0.02 unless given);
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
    let cohesive_stress: f64 = args.next().map_or(Ok(0.02), |a| a.parse())?;
    let range_divisor: f64 = args.next().map_or(Ok(20.0), |a| a.parse())?;
    let method = match method_name.as_str() {
        "auto" => None,
        "plain" => Some(Method::Plain),
        "preconditioned" | "starts" | "sensitivity" => Some(Method::PRECONDITIONED),
        other => {
            return Err(
                format!("method {other:?}: one of auto, plain, preconditioned, starts").into(),
            )
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
    let (rho, mean_gap) = (rms / range_divisor, 0.6 * (h_max - mean));
    let dg = cohesive_stress * rho;
    let law = match law_name.as_str() {
        "exponential" => CohesiveLaw::exponential(dg, rho)?,
        _ => CohesiveLaw::maugis(dg, rho)?,
    };
    // the cohesive length E*ρ²/Δγ (E* = 1) over the grid spacing L/N
    let zone_nodes = law.cohesive_length(1.0) * n as f64;
    persson::io::npy::write(&dir.join(format!("surface_{n}.npy")), n, n, h)?;
    let opts = AdhesiveOptions {
        tolerance: 1e-10,
        max_iterations: 20_000,
    };
    if method_name == "starts" {
        return starts(n, h, dg, rho, mean_gap, &opts);
    }
    if method_name == "sensitivity" {
        eprintln!("cohesive length: {zone_nodes:.2} grid spacings");
        return sensitivity(n, h, dg, rho, mean_gap);
    }
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
         \"cohesive_fraction\": {:e}, \"zone_nodes\": {zone_nodes}, \"iterations\": {}, \"residual\": {:e}, \"converged\": {}, \"fallback\": {}, \"seconds\": {seconds}}}",
        match used { Method::Plain => "plain", _ => "preconditioned" },
        p.mean_pressure, p.contact_fraction, p.cohesive_fraction, p.iterations, p.residual, p.converged,
        p.fallback.is_some()
    );
    Ok(())
}

/// Π/A = ½ mean((g + h) 𝒦(g + h)) + mean W(g) of the Maugis–Dugdale law.
fn energy(
    h: &[f64],
    g: &[f64],
    op: &mut Operator,
    dg: f64,
    rho: f64,
) -> Result<f64, Box<dyn std::error::Error>> {
    let u: Vec<f64> = g.iter().zip(h).map(|(a, b)| a + b).collect();
    let mut p = vec![0.0; u.len()];
    op.apply_stiffness(&u, &mut p)?;
    let n2 = u.len() as f64;
    let elastic = 0.5 * u.iter().zip(&p).map(|(a, b)| a * b).sum::<f64>() / n2;
    let adhesion = g
        .iter()
        .map(|&x| if x < rho { -dg * (1.0 - x / rho) } else { 0.0 })
        .sum::<f64>()
        / n2;
    Ok(elastic + adhesion)
}

/// The Maugis–Dugdale solve at ḡ from several starts, both iterations (see the header).
fn starts(
    n: usize,
    h: &[f64],
    dg: f64,
    rho: f64,
    mean_gap: f64,
    opts: &AdhesiveOptions,
) -> Result<(), Box<dyn std::error::Error>> {
    let md = CohesiveLaw::maugis(dg, rho)?;
    let mut op = Operator::new(Boundary::Periodic, n, 1.0, 1.0)?;
    for method in [Method::Plain, Method::PRECONDITIONED] {
        let name = match method {
            Method::Plain => "plain",
            _ => "preconditioned",
        };
        // (start, the laws and mean gaps solved in order, the last is the answer)
        let plans: Vec<(&str, Vec<(CohesiveLaw, f64)>)> = vec![
            ("cold", vec![(md, mean_gap)]),
            (
                "from the exponential law",
                vec![
                    (CohesiveLaw::exponential(dg, rho)?, mean_gap),
                    (md, mean_gap),
                ],
            ),
            (
                "from dg = 0",
                vec![(CohesiveLaw::maugis(0.0, rho)?, mean_gap), (md, mean_gap)],
            ),
            (
                "dg ramp 1/4 .. 1",
                [0.25, 0.5, 0.75, 1.0]
                    .iter()
                    .map(|f| Ok((CohesiveLaw::maugis(f * dg, rho)?, mean_gap)))
                    .collect::<Result<_, persson::Error>>()?,
            ),
            (
                "approach from 1.3 mean gap",
                [1.3, 1.2, 1.1, 1.0]
                    .iter()
                    .map(|f| (md, f * mean_gap))
                    .collect(),
            ),
        ];
        for (start, plan) in plans {
            let t = std::time::Instant::now();
            let mut solver = AdhesiveSolver::new(Operator::new(Boundary::Periodic, n, 1.0, 1.0)?)?
                .with_method(method);
            let mut iterations = 0;
            let mut last = None;
            for (law, g) in plan {
                let p = solver.solve(h, &law, g, opts)?;
                iterations += p.iterations;
                last = Some(p);
            }
            let seconds = t.elapsed().as_secs_f64();
            let p = last.ok_or("empty plan")?;
            println!(
                "N = {n} {name:14} {start:28} mean pressure {:.8e} contact fraction {:.8e} iterations {iterations:4} energy/A {:.10e} converged {} {seconds:.3} s",
                p.mean_pressure,
                p.contact_fraction,
                energy(h, solver.gap(), &mut op, dg, rho)?,
                p.converged
            );
        }
    }
    Ok(())
}

/// The Maugis–Dugdale solve at ḡ(1 + k·10⁻⁹), k = −2…2, and at ḡ with the
/// tolerance 1e-8, 1e-10, 1e-12, both iterations, cold: how far the answer moves
/// under perturbations far below any accuracy asked of it (see the header).
fn sensitivity(
    n: usize,
    h: &[f64],
    dg: f64,
    rho: f64,
    mean_gap: f64,
) -> Result<(), Box<dyn std::error::Error>> {
    let md = CohesiveLaw::maugis(dg, rho)?;
    let mut op = Operator::new(Boundary::Periodic, n, 1.0, 1.0)?;
    let cases: Vec<(f64, f64)> = [-2.0, -1.0, 0.0, 1.0, 2.0]
        .iter()
        .map(|k| (1.0 + k * 1e-9, 1e-10))
        .chain([(1.0, 1e-8), (1.0, 1e-12)])
        .collect();
    for method in [Method::Plain, Method::PRECONDITIONED] {
        let name = match method {
            Method::Plain => "plain",
            _ => "preconditioned",
        };
        for &(factor, tolerance) in &cases {
            let opts = AdhesiveOptions {
                tolerance,
                max_iterations: 20_000,
            };
            let mut solver = AdhesiveSolver::new(Operator::new(Boundary::Periodic, n, 1.0, 1.0)?)?
                .with_method(method);
            let p = solver.solve(h, &md, factor * mean_gap, &opts)?;
            println!(
                "N = {n} {name:14} mean gap x {factor:.9} tol {tolerance:.0e} mean pressure {:.8e} contact fraction {:.8e} iterations {:4} energy/A {:.10e} converged {}",
                p.mean_pressure,
                p.contact_fraction,
                p.iterations,
                energy(h, solver.gap(), &mut op, dg, rho)?,
                p.converged
            );
        }
    }
    Ok(())
}

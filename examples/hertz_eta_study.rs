//! Hertz η study (free boundary, L = R = E* = 1, a = 0.1 L): the
//! energy-norm error η = ‖p − p_ex‖_𝒢 / ‖p_ex‖_𝒢 next to the η_L² =
//! |Σ(u − u_ex)(p − p_ex)| / Σ u_ex p_ex of J. F. Molinari's EPFL lecture
//! "From single asperity to multi asperity contact" (Table 1; u_ex the exact
//! Hertz displacement, Johnson 1985 eqs. 3.41a/3.42a, `persson::reference`),
//! for honest variants of the same problem.
//!
//! `cargo run --release --example hertz_eta_study -- [N ...] [--tol T] [--scan M]`
//! (default grids 64 128 256 512 1024, tol 1e-12).
//!
//! Variants: `node` (the sphere on the node (L/2, L/2) under load control:
//! `persson bem hertz`), `corner` (on the cell corner (L/2 + Δ/2, L/2 + Δ/2)),
//! `pen` (penetration control at the exact approach δ = a²/R), `pen-corner`.
//! `--scan M` moves the centre over (s_x, s_y)Δ, s ∈ {0, 1/(2M), …, ½},
//! s_x ≥ s_y (every distinct position by symmetry), and prints the
//! min / mean / max of η: the luck of the contact edge's alignment.

use persson::bem::{hertz, Boundary, Control, Operator, Options, Solver};
use persson::reference;

type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;

/// η, η_L and the sign of η_L's sum for the sphere centred at
/// `(L/2 + s_x Δ, L/2 + s_y Δ)`, under load or penetration control.
fn etas(n: usize, tol: f64, shift: (f64, f64), penetration: bool) -> Result<(f64, f64, f64)> {
    let case = hertz::HertzCase::new(n, Boundary::Free);
    let (a, p0) = (case.contact_radius, case.peak_pressure());
    let dx = case.size / n as f64;
    let (cx, cy) = (0.5 + shift.0 * dx, 0.5 + shift.1 * dx);
    let radii: Vec<f64> = (0..n * n)
        .map(|k| ((k / n) as f64 * dx - cx).hypot((k % n) as f64 * dx - cy))
        .collect();
    let h: Vec<f64> = radii.iter().map(|r| -r * r / (2.0 * case.radius)).collect();
    let control = if penetration {
        // The solver's δ is measured from first touch: a²/R + max h.
        let h_max = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Control::Penetration(a * a / case.radius + h_max)
    } else {
        Control::MeanPressure(case.mean_pressure())
    };
    let opts = Options {
        tolerance: tol,
        ..Options::default()
    };
    let mut solver = Solver::new(Operator::new(Boundary::Free, n, case.size, case.e_star)?);
    let sol = solver.solve(&h, control, &opts)?;
    let p_ex: Vec<f64> = radii
        .iter()
        .map(|&r| reference::pressure_profile(r, a, p0))
        .collect();
    let u_ex: Vec<f64> = radii
        .iter()
        .map(|&r| reference::ball_displacement(r, a, p0, case.e_star))
        .collect();
    let e: Vec<f64> = sol.pressure.iter().zip(&p_ex).map(|(p, q)| p - q).collect();
    let mut work = vec![0.0; n * n];
    let op = solver.operator();
    let eta = (op.energy_product(&e, &e, &mut work)?.max(0.0)
        / op.energy_product(&p_ex, &p_ex, &mut work)?)
    .sqrt();
    let (mut num, mut den) = (0.0, 0.0);
    for (((u, ue), ei), pe) in sol.displacement.iter().zip(&u_ex).zip(&e).zip(&p_ex) {
        num += (u - ue) * ei;
        den += ue * pe;
    }
    Ok((eta, (num.abs() / den).sqrt(), num.signum()))
}

fn lecture(n: usize) -> String {
    hertz::lecture_eta(n).map_or("-".into(), |v| format!("{v:.2e}"))
}

fn main() -> Result<()> {
    let mut grids = Vec::new();
    let (mut tol, mut scan) = (1e-12, 0usize);
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--tol" => tol = args.next().ok_or("--tol needs a value")?.parse()?,
            "--scan" => scan = args.next().ok_or("--scan needs a value")?.parse()?,
            _ => grids.push(a.parse()?),
        }
    }
    if grids.is_empty() {
        grids = vec![64, 128, 256, 512, 1024];
    }
    if scan > 0 {
        println!("grid  eta min / mean / max (sphere centre over the cell)  Molinari");
        for &n in &grids {
            let mut all = Vec::new();
            for ix in 0..=scan {
                for iy in 0..=ix {
                    let s = (ix as f64 / (2 * scan) as f64, iy as f64 / (2 * scan) as f64);
                    all.push(etas(n, tol, s, false)?.0);
                }
            }
            let min = all.iter().copied().fold(f64::INFINITY, f64::min);
            let max = all.iter().copied().fold(0.0, f64::max);
            let mean = all.iter().sum::<f64>() / all.len() as f64;
            println!("{n:>5} {min:.3e} / {mean:.3e} / {max:.3e}  {}", lecture(n));
        }
        return Ok(());
    }
    println!("variant     grid  eta        eta_L (sign)    Molinari");
    for (name, shift, pen) in [
        ("node", (0.0, 0.0), false),
        ("corner", (0.5, 0.5), false),
        ("pen", (0.0, 0.0), true),
        ("pen-corner", (0.5, 0.5), true),
    ] {
        for &n in &grids {
            let (eta, eta_l, sign) = etas(n, tol, shift, pen)?;
            let sign = if sign > 0.0 { '+' } else { '-' };
            println!(
                "{name:<10} {n:>5}  {eta:.3e}  {eta_l:.3e} ({sign})  {}",
                lecture(n)
            );
        }
    }
    Ok(())
}

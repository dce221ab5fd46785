//! Hertz η study (issue 4): the energy-norm error η = ‖p − p_ex‖_𝒢 /
//! ‖p_ex‖_𝒢 next to the lecture's η_L² = Σ(u − u_ex)(p − p_ex) / Σ u_ex p_ex
//! (u_ex the exact Hertz displacement), for variants of the same problem.
//!
//! `cargo run --release --example hertz_eta_study -- [N ...] [--tol T] [--variants a,b,...] [--scan M]`
//! (default grids 64 128 256 512 1024, tol 1e-12, all variants).
//! `--scan M` moves the sphere centre over (s_x, s_y)Δ, s ∈ {0, 1/(2M), …, ½}
//! for the first variant and prints min / mean / max η; `--variants lib`
//! prints the library's `HertzReport` (η, η_L, η_u) with timings; the
//! environment variable `ETA_PROJ` adds η_u computed independently (two CG
//! solves to 1e-12) to each row.
//!
//! Variants (free boundary, L = R = E* = 1, a = 0.1):
//! - `base`: sphere on the node (L/2, L/2), load control (the library's `validate`);
//! - `corner`: sphere on the cell corner (L/2 + Δ/2, L/2 + Δ/2);
//! - `pen`: penetration control at the exact approach δ = a²/R;
//! - `pen-corner`: both;
//! - `corr`: Love operator with the O(Δ²) midpoint correction
//!   𝒢' = 𝒢 (I − Δ²∇ₕ²/24) (5-point Laplacian), own Polonsky–Keer loop;
//! - `corr-corner`: corrected operator, sphere on the corner;
//! - `anti`, `anti-corner`: the opposite correction 𝒢 (I + Δ²∇ₕ²/24), to
//!   first order the Galerkin (cell-averaged displacement) operator.

use persson::bem::{hertz, Boundary, Control, Operator, Options, Solver};

/// Lecture 000, Table 1: free-boundary η per grid.
const LECTURE: [(usize, f64); 6] = [
    (64, 1.40e-2),
    (128, 4.08e-3),
    (256, 7.78e-4),
    (512, 3.66e-4),
    (1024, 1.20e-4),
    (2048, 1.66e-5),
];

const A: f64 = 0.1;
const R: f64 = 1.0;

fn p0() -> f64 {
    hertz::peak_pressure(A, R, 1.0)
}

/// Exact Hertz displacement (Johnson 1985, eqs. 3.41a / 3.42a), E* = 1.
fn u_exact(r: f64) -> f64 {
    let p0 = p0();
    if r <= A {
        std::f64::consts::PI * p0 * (2.0 * A * A - r * r) / (4.0 * A)
    } else {
        p0 / (2.0 * A) * ((2.0 * A * A - r * r) * (A / r).asin() + A * (r * r - A * A).sqrt())
    }
}

/// Node radii from the centre `(L/2 + s_x Δ, L/2 + s_y Δ)`.
fn radii(n: usize, shift: (f64, f64)) -> Vec<f64> {
    let dx = 1.0 / n as f64;
    let (cx, cy) = (0.5 + shift.0 * dx, 0.5 + shift.1 * dx);
    (0..n * n)
        .map(|k| ((k / n) as f64 * dx - cx).hypot((k % n) as f64 * dx - cy))
        .collect()
}

/// 𝒢' p = 𝒢 (p − ∇ₕ²p/24) with the 5-point Laplacian in cell units
/// (p vanishes outside the grid).
fn smooth(n: usize, c: f64, p: &[f64], out: &mut [f64]) {
    for i in 0..n {
        for j in 0..n {
            let at = |a: isize, b: isize| -> f64 {
                if a < 0 || b < 0 || a >= n as isize || b >= n as isize {
                    0.0
                } else {
                    p[a as usize * n + b as usize]
                }
            };
            let (a, b) = (i as isize, j as isize);
            let lap = at(a + 1, b) + at(a - 1, b) + at(a, b + 1) + at(a, b - 1) - 4.0 * at(a, b);
            out[i * n + j] = p[i * n + j] + c * lap;
        }
    }
}

/// Plain Polonsky–Keer CG under load control (mean pressure `pm`) for any
/// symmetric operator; stops at the library's ε ≤ tol with no overlap.
fn pk_solve(
    apply: &mut dyn FnMut(&[f64], &mut [f64]),
    h: &[f64],
    pm: f64,
    tol: f64,
) -> (Vec<f64>, Vec<f64>, usize) {
    let n2 = h.len();
    let hm = h.iter().sum::<f64>() / n2 as f64;
    let sigma = (h.iter().map(|x| (x - hm).powi(2)).sum::<f64>() / (n2 as f64 - 1.0)).sqrt();
    let mut p = vec![pm; n2];
    let (mut u, mut g, mut t, mut r) = (vec![0.0; n2], vec![0.0; n2], vec![0.0; n2], vec![0.0; n2]);
    let mut g_old = 1.0;
    let mut conj = false;
    for k in 0..100_000 {
        apply(&p, &mut u);
        let mut gmin = f64::INFINITY;
        let (mut sp, mut spg, mut sg, mut cnt) = (0.0, 0.0, 0.0, 0.0);
        for i in 0..n2 {
            g[i] = u[i] - h[i];
            if p[i] > 0.0 {
                gmin = gmin.min(g[i]);
                sp += p[i];
                spg += p[i] * g[i];
                sg += g[i];
                cnt += 1.0;
            }
        }
        let eps = (spg - gmin * sp) / (sp * sigma);
        let overlap = (0..n2).any(|i| p[i] == 0.0 && g[i] < gmin - tol * sigma);
        if eps <= tol && !overlap {
            return (p, u, k);
        }
        let gbar = sg / cnt;
        let mut gn = 0.0;
        for i in 0..n2 {
            g[i] -= gbar;
            if p[i] > 0.0 {
                gn += g[i] * g[i];
            }
        }
        let beta = if conj { gn / g_old } else { 0.0 };
        g_old = gn;
        for i in 0..n2 {
            t[i] = if p[i] > 0.0 { g[i] + beta * t[i] } else { 0.0 };
        }
        apply(&t, &mut r);
        let (mut sr, mut st, mut sgt, mut srt) = (0.0, 0.0, 0.0, 0.0);
        for i in 0..n2 {
            if p[i] > 0.0 {
                sr += r[i];
                st += t[i];
                sgt += g[i] * t[i];
                srt += r[i] * t[i];
            }
        }
        let tau = sgt / (srt - sr / cnt * st);
        let mut any = false;
        let mut sum = 0.0;
        for i in 0..n2 {
            let v = (p[i] - tau * t[i]).max(0.0);
            p[i] = if v == 0.0 && g[i] < 0.0 {
                any = true;
                -tau * g[i]
            } else {
                v
            };
            sum += p[i];
        }
        conj = !any;
        let s = pm * n2 as f64 / sum;
        p.iter_mut().for_each(|v| *v *= s);
    }
    panic!("PK did not converge");
}

/// Conjugate gradients for `𝒢 x = b` on the whole grid (𝒢 SPD), from 0,
/// to a relative residual `tol`.
fn cg(apply: &mut dyn FnMut(&[f64], &mut [f64]), b: &[f64], tol: f64) -> (Vec<f64>, usize) {
    let n2 = b.len();
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let mut x = vec![0.0; n2];
    let mut r = b.to_vec();
    let mut d = r.clone();
    let mut q = vec![0.0; n2];
    let b2 = dot(b, b);
    let mut rr = b2;
    for k in 0..100_000 {
        if rr <= tol * tol * b2 {
            return (x, k);
        }
        apply(&d, &mut q);
        let alpha = rr / dot(&d, &q);
        for i in 0..n2 {
            x[i] += alpha * d[i];
            r[i] -= alpha * q[i];
        }
        let rr_new = dot(&r, &r);
        let beta = rr_new / rr;
        rr = rr_new;
        for i in 0..n2 {
            d[i] = r[i] + beta * d[i];
        }
    }
    panic!("CG did not converge");
}

struct Row {
    eta: f64,
    eta_love: f64,
    eta_l: f64,
    sign: f64,
    approach: f64,
    iters: usize,
}

fn measures(
    n: usize,
    shift: (f64, f64),
    p: &[f64],
    u: &[f64],
    apply: &mut dyn FnMut(&[f64], &mut [f64]),
    love: &mut Operator,
) -> (f64, f64, f64, f64) {
    let rr = radii(n, shift);
    let pe: Vec<f64> = rr.iter().map(|&r| hertz::pressure(r, A, p0())).collect();
    let ue: Vec<f64> = rr.iter().map(|&r| u_exact(r)).collect();
    let e: Vec<f64> = p.iter().zip(&pe).map(|(a, b)| a - b).collect();
    let mut w = vec![0.0; n * n];
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    apply(&e, &mut w);
    let num = dot(&e, &w);
    apply(&pe, &mut w);
    let den = dot(&pe, &w);
    let eta = (num.max(0.0) / den).sqrt();
    love.apply(&e, &mut w).unwrap();
    let num_l = dot(&e, &w);
    love.apply(&pe, &mut w).unwrap();
    let den_l = dot(&pe, &w);
    let eta_love = (num_l.max(0.0) / den_l).sqrt();
    let du: Vec<f64> = u.iter().zip(&ue).map(|(a, b)| a - b).collect();
    let lnum = dot(&du, &e);
    let lden = dot(&ue, &pe);
    if std::env::var("ETA_PROJ").is_ok() {
        // p_ex represented by P = 𝒢⁻¹u_ex (the nodal pressures that
        // reproduce the exact displacement at every node):
        // ‖p − P‖²_𝒢 = ⟨𝒢p − u_ex, 𝒢⁻¹(𝒢p − u_ex)⟩.
        let (pp, it) = cg(apply, &ue, 1e-12);
        let (x, it2) = cg(apply, &du, 1e-12);
        let num = dot(&du, &x);
        let den = dot(&ue, &pp);
        let pmax = pp.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let pmin = pp.iter().copied().fold(f64::INFINITY, f64::min);
        let dp = pp
            .iter()
            .zip(&pe)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        println!(
            "    proj: eta_P = {:.3e}, ‖P − p_ex‖∞/p₀ = {:.2e}, P ∈ [{:.2e}, {:.3e}] p₀, CG {it}+{it2}",
            (num / den).sqrt(),
            dp / p0(),
            pmin / p0(),
            pmax / p0()
        );
    }
    (eta, eta_love, (lnum.abs() / lden).sqrt(), lnum.signum())
}

fn run(variant: &str, n: usize, tol: f64) -> Result<Row, Box<dyn std::error::Error>> {
    let corner = variant.ends_with("corner");
    let shift = if corner { (0.5, 0.5) } else { (0.0, 0.0) };
    run_at(variant, n, tol, shift)
}

fn run_at(
    variant: &str,
    n: usize,
    tol: f64,
    shift: (f64, f64),
) -> Result<Row, Box<dyn std::error::Error>> {
    let opts = Options {
        tol,
        ..Options::default()
    };
    let rr = radii(n, shift);
    let h: Vec<f64> = rr.iter().map(|r| -r * r / (2.0 * R)).collect();
    let hmax = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let case = hertz::HertzCase::new(n, Boundary::Free);
    let mut love = Operator::new(Boundary::Free, n, 1.0, 1.0)?;
    if variant.starts_with("corr") || variant.starts_with("anti") {
        let c = if variant.starts_with("corr") {
            -1.0 / 24.0
        } else {
            1.0 / 24.0
        };
        let mut op = Operator::new(Boundary::Free, n, 1.0, 1.0)?;
        let mut tmp = vec![0.0; n * n];
        let mut apply = |p: &[f64], u: &mut [f64]| {
            smooth(n, c, p, &mut tmp);
            op.apply(&tmp, u).unwrap();
        };
        let (p, u, iters) = pk_solve(&mut apply, &h, case.mean_pressure(), tol);
        let approach = rr
            .iter()
            .zip(&u)
            .zip(&p)
            .find(|((_, _), p)| **p > 0.0)
            .map_or(f64::NAN, |((r, u), _)| u + r * r / (2.0 * R));
        let (eta, eta_love, eta_l, sign) = measures(n, shift, &p, &u, &mut apply, &mut love);
        return Ok(Row {
            eta,
            eta_love,
            eta_l,
            sign,
            approach,
            iters,
        });
    }
    let control = if variant.starts_with("pen") {
        // Solver's δ is measured from first touch: δ_s = a²/R + max h.
        Control::Penetration(A * A / R + hmax)
    } else {
        Control::MeanPressure(case.mean_pressure())
    };
    let mut solver = Solver::new(Operator::new(Boundary::Free, n, 1.0, 1.0)?);
    let sol = solver.solve(&h, control, &opts)?;
    let mut op = Operator::new(Boundary::Free, n, 1.0, 1.0)?;
    let mut apply = |p: &[f64], u: &mut [f64]| op.apply(p, u).unwrap();
    let (eta, eta_love, eta_l, sign) = measures(
        n,
        shift,
        &sol.pressure,
        &sol.displacement,
        &mut apply,
        &mut love,
    );
    Ok(Row {
        eta,
        eta_love,
        eta_l,
        sign,
        approach: sol.approach - hmax,
        iters: sol.iterations,
    })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut grids = Vec::new();
    let mut tol = 1e-12;
    let mut variants: Vec<String> = ["base", "corner", "pen", "pen-corner", "corr", "corr-corner"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let mut scan = 0usize;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--scan" => scan = args.next().ok_or("--scan needs a count")?.parse()?,
            "--tol" => tol = args.next().ok_or("--tol needs a value")?.parse()?,
            "--variants" => {
                variants = args
                    .next()
                    .ok_or("--variants needs a list")?
                    .split(',')
                    .map(str::to_string)
                    .collect()
            }
            _ => grids.push(a.parse::<usize>()?),
        }
    }
    if grids.is_empty() {
        grids = vec![64, 128, 256, 512, 1024];
    }
    if variants.len() == 1 && variants[0] == "lib" {
        // The library's report: η, η_L and η_u, and the cost of η_u.
        println!("grid  eta        eta_L      eta_u      lecture    solve s  total s  eta_u s");
        for &n in &grids {
            let opts = Options {
                tol,
                ..Options::default()
            };
            let t = std::time::Instant::now();
            let r = hertz::validate(&hertz::HertzCase::new(n, Boundary::Free), &opts)?;
            let total = t.elapsed().as_secs_f64();
            // The η_u conjugate gradients alone.
            let case = hertz::HertzCase::new(n, Boundary::Free);
            let mut op = Operator::new(Boundary::Free, n, 1.0, 1.0)?;
            let pe = case.exact_pressure();
            let t = std::time::Instant::now();
            hertz::displacement_energy_error(
                &mut op,
                &pe,
                &case.exact_displacement(),
                &pe,
                opts.max_iter,
            )?;
            let cg = t.elapsed().as_secs_f64();
            let lecture = LECTURE
                .iter()
                .find(|(g, _)| *g == n)
                .map_or("-".to_string(), |(_, v)| format!("{v:.2e}"));
            println!(
                "{n:>5} {:.3e}  {:.3e}  {:.3e}  {lecture:<9}  {:.2}     {total:.2}    {cg:.2}",
                r.energy_error,
                r.energy_error_lecture.unwrap_or(f64::NAN),
                r.displacement_energy_error.unwrap_or(f64::NAN),
                r.seconds
            );
        }
        return Ok(());
    }
    if scan > 0 {
        return scan_shifts(&grids, tol, scan, &variants[0]);
    }
    println!("variant      grid  eta(issue)  eta(Love)   lecture    eta_L      sign  delta/(a²/R)-1  iters");
    for v in &variants {
        for &n in &grids {
            let row = run(v, n, tol)?;
            let lecture = LECTURE
                .iter()
                .find(|(g, _)| *g == n)
                .map_or("-".to_string(), |(_, v)| format!("{v:.2e}"));
            println!(
                "{:<11} {:>5}  {:.3e}   {:.3e}   {:<9}  {:.3e}  {:>4}  {:+.2e}       {}",
                v,
                n,
                row.eta,
                row.eta_love,
                lecture,
                row.eta_l,
                if row.sign > 0.0 { "+" } else { "-" },
                row.approach / (A * A / R) - 1.0,
                row.iters
            );
        }
    }
    Ok(())
}

/// η of `variant` over the sphere centres `(L/2 + s_x Δ, L/2 + s_y Δ)`,
/// `s_x ≥ s_y` in `{0, 1/(2m), …, 1/2}` (all distinct positions by symmetry):
/// the spread is the luck of the contact edge's alignment with the grid.
fn scan_shifts(
    grids: &[usize],
    tol: f64,
    m: usize,
    variant: &str,
) -> Result<(), Box<dyn std::error::Error>> {
    println!("scan of the sphere centre, variant {variant}: grid, eta min / mean / max (issue), eta_L min / max, argmin (sx, sy)");
    for &n in grids {
        let mut etas = Vec::new();
        let mut els = Vec::new();
        let mut best = (f64::INFINITY, (0.0, 0.0));
        for ix in 0..=m {
            for iy in 0..=ix {
                let sh = (ix as f64 / (2 * m) as f64, iy as f64 / (2 * m) as f64);
                let row = run_at(variant, n, tol, sh)?;
                if row.eta < best.0 {
                    best = (row.eta, sh);
                }
                etas.push(row.eta);
                els.push(row.eta_l);
            }
        }
        let mean = etas.iter().sum::<f64>() / etas.len() as f64;
        let min = etas.iter().copied().fold(f64::INFINITY, f64::min);
        let max = etas.iter().copied().fold(0.0, f64::max);
        let lmin = els.iter().copied().fold(f64::INFINITY, f64::min);
        let lmax = els.iter().copied().fold(0.0, f64::max);
        println!(
            "{n:>5}  {min:.3e} / {mean:.3e} / {max:.3e}   {lmin:.3e} / {lmax:.3e}   ({:.3}, {:.3})",
            best.1 .0, best.1 .1
        );
    }
    Ok(())
}

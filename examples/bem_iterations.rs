//! Iterations and times of the BEM solver, plain against
//! preconditioned, on the rough case of docs/bem.md: self-affine H = 0.8, rms
//! slope 0.1, q_l = 2π/L, q_r = 4 q_l, q_s = (N/4) q_l, seed 1, L = E* = 1,
//! ε ≤ 1e-10; periodic and free boundary, and saturated (σY = 4 σ0,
//! periodic). One line per case, grid and load: iterations, solve times,
//! A/A0 of both and the largest pressure difference relative to the peak.
//!
//! `cargo run --release --example bem_iterations -- [--grids 256 512 1024 2048]
//!  [--loads 0.005 0.05] [--cases periodic free saturated] [--tolerance 1e-10]
//!  [--methods plain preconditioned] [--repeat 1]`
//!
//! `--repeat k` solves each case k times (each cold) and reports the
//! shortest time: on a shared machine the least disturbed run. `--cpu`
//! reports the process's CPU time of each solve (user + system, from
//! /proc/self/stat, Linux; 10 ms ticks) instead of the solve's wall time:
//! it does not count the time the process waits for a core. `--trace`
//! prints ε and A/A0 of every iteration to stderr.
//!
//! Run it on one thread (the solver is single-threaded; nothing else should
//! run on the core). The surface is synthesised once per grid.

#[cfg(not(feature = "bem"))]
fn main() {
    eprintln!("bem_iterations needs the feature bem");
}

#[cfg(feature = "bem")]
fn main() -> persson::Result<()> {
    use persson::bem::surface::synthesize;
    use persson::bem::{Boundary, Control, Method, Operator, Options, Solver};
    use persson::spectrum::{Amplitude, SelfAffine};

    let args: Vec<String> = std::env::args().skip(1).collect();
    let list = |flag: &str, default: &[&str]| -> Vec<String> {
        match args.iter().position(|a| a == flag) {
            Some(i) => args[i + 1..]
                .iter()
                .take_while(|a| !a.starts_with("--"))
                .cloned()
                .collect(),
            None => default.iter().map(|s| s.to_string()).collect(),
        }
    };
    let num = |s: &String| s.parse::<f64>().expect("a number");
    let grids: Vec<usize> = list("--grids", &["256", "512", "1024", "2048"])
        .iter()
        .map(|s| s.parse().expect("a grid"))
        .collect();
    let loads: Vec<f64> = list("--loads", &["0.005", "0.05"])
        .iter()
        .map(num)
        .collect();
    let cases = list("--cases", &["periodic", "free", "saturated"]);
    let tolerance = list("--tolerance", &["1e-10"])
        .iter()
        .map(num)
        .next()
        .unwrap_or(1e-10);
    let methods = list("--methods", &["plain", "preconditioned"]);
    let cpu = args.iter().any(|a| a == "--cpu");
    let trace = args.iter().any(|a| a == "--trace");
    // Process CPU seconds (utime + stime of /proc/self/stat, in ticks of 10 ms).
    let cpu_seconds = || -> f64 {
        let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
        let after = stat.rsplit(')').next().unwrap_or("");
        let fields: Vec<&str> = after.split_whitespace().collect();
        let tick = |i: usize| {
            fields
                .get(i)
                .and_then(|v| v.parse::<f64>().ok())
                .unwrap_or(0.0)
        };
        (tick(11) + tick(12)) / 100.0
    };
    let repeat: usize = list("--repeat", &["1"])
        .first()
        .map_or(1, |s| s.parse().expect("a count"));

    println!(
        "| case | N | σ0/E* | iterations plain | iterations precond. | s plain | s precond. | A/A0 plain | A/A0 precond. | max|Δp|/p_max | fallback |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    let ql = std::f64::consts::TAU;
    for &n in &grids {
        let s = SelfAffine::new(
            ql,
            4.0 * ql,
            ql * n as f64 / 4.0,
            0.8,
            Amplitude::RmsSlope(0.1),
        )?;
        let surf = synthesize(&s, n, 1.0, 1)?;
        for case in &cases {
            let (boundary, saturated) = match case.as_str() {
                "periodic" => (Boundary::Periodic, false),
                "free" => (Boundary::Free, false),
                "saturated" => (Boundary::Periodic, true),
                other => panic!("unknown case {other}"),
            };
            for &load in &loads {
                let opts = Options {
                    tolerance,
                    yield_stress: saturated.then_some(4.0 * load),
                    ..Options::default()
                };
                let mut sols = Vec::new();
                for m in &methods {
                    let method = match m.as_str() {
                        "plain" => Method::Plain,
                        _ => Method::default(),
                    };
                    let mut best: Option<persson::bem::Solution> = None;
                    for _ in 0..repeat.max(1) {
                        let op = Operator::new(boundary, n, 1.0, 1.0)?;
                        let mut solver = Solver::with_method(op, method);
                        let before = cpu_seconds();
                        let mut s = solver.solve_observed(
                            &surf.heights,
                            Control::MeanPressure(load),
                            &opts,
                            &mut |it| {
                                if trace {
                                    eprintln!(
                                        "{case} {n} {load} {m}: iteration {} ε {:.3e} A/A0 {:.6}",
                                        it.iteration, it.residual, it.contact_fraction
                                    );
                                }
                            },
                        )?;
                        if cpu {
                            s.seconds = cpu_seconds() - before;
                        }
                        if best.as_ref().is_none_or(|b| s.seconds < b.seconds) {
                            best = Some(s);
                        }
                    }
                    sols.extend(best);
                }
                let (a, b) = (&sols[0], &sols[sols.len() - 1]);
                let p_max = a.pressure.iter().copied().fold(0.0, f64::max);
                let dp = a
                    .pressure
                    .iter()
                    .zip(&b.pressure)
                    .map(|(x, y)| (x - y).abs())
                    .fold(0.0, f64::max);
                println!(
                    "| {case} | {n} | {load} | {} | {} | {:.3} | {:.3} | {:.6} | {:.6} | {:.1e} | {} |",
                    a.iterations,
                    b.iterations,
                    a.seconds,
                    b.seconds,
                    a.contact_fraction,
                    b.contact_fraction,
                    dp / p_max,
                    b.fallback.map_or("-".to_string(), |f| format!("after {}", f.iterations)),
                );
            }
        }
    }
    Ok(())
}

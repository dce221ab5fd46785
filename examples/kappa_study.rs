//! κ(H) from the low-load regime of the FFT-BEM at three resolutions of one
//! surface per seed, extrapolated to the continuum limit (issue 7, seed 002).
//!
//! ```text
//! cargo run --release --example kappa_study [FINEST_GRID] [SEEDS]
//! ```
//! Defaults: finest grid 512 (grids 128, 256, 512), 4 seeds, H = 0.2, 0.5,
//! 0.8, q_l = 1, q_r = 2, q_s = finest/16 (4 pixels per shortest wavelength
//! on the coarsest grid), rms slope 0.1, E* = 1, 8 pressures with linear-law
//! A/A0 ≈ 0.005 … 0.09, solver tolerance 1e-8, α = 0.7.

use std::time::Instant;

use persson::compare_bem::{default_pressures, resolution_grids, sweep, SweepConfig};
use persson::kappa::Kappa;
use persson::spectrum::{Amplitude, SelfAffine};

fn main() -> persson::Result<()> {
    let mut args = std::env::args().skip(1);
    let finest: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(512);
    let seeds: u64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(4);
    let grids = resolution_grids(finest, 3)?;
    let q_s = finest as f64 / 16.0;
    let slope = 0.1;
    let pressures = default_pressures(1.0, slope, 8, 0.005, 0.09);
    let config = SweepConfig {
        grids: grids.clone(),
        seeds: (1..=seeds).collect(),
        options: persson::bem::Options {
            tol: 1e-8,
            max_iter: 10_000,
            warm_start: true,
        },
        size: std::f64::consts::TAU,
    };
    println!(
        "grids {grids:?}, {seeds} seeds, q_s/q_l = {q_s}, q_r/q_l = 2, rms slope {slope}; \
         Persson √(8/π) = {:.4}, Bush √(2π) = {:.4}",
        Kappa::Persson.value(),
        Kappa::Bush.value()
    );
    print!("{:>5}", "H");
    for g in &grids {
        print!("  {:>15}", format!("κ({g}²)"));
    }
    println!("  {:>15}  {:>8}", "κ(N→∞)", "seconds");
    for h in [0.2, 0.5, 0.8] {
        let start = Instant::now();
        let s = SelfAffine::new(1.0, 2.0, q_s, h, Amplitude::RmsSlope(slope))?;
        let sw = sweep(&s, 1.0, &pressures, &config, &mut |_| {})?;
        let k = sw.kappa(1.0, slope, 0.1, Some(0.7))?;
        print!("{h:>5}");
        for (_, e) in &k.per_grid {
            print!(
                "  {:>15}",
                format!("{:.3} ± {:.3}", e.kappa, e.standard_error)
            );
        }
        println!(
            "  {:>15}  {:>8.1}",
            format!(
                "{:.3} ± {:.3}",
                k.extrapolated.kappa, k.extrapolated.standard_error
            ),
            start.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

//! κ(H) from the low-load regime of the FFT-BEM at three resolutions of one
//! surface per seed, extrapolated to the continuum limit (Campañá & Müser,
//! EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005).
//!
//! ```text
//! cargo run --release --example kappa_study [FINEST_GRID] [SEEDS]
//! ```
//! Defaults: finest grid 512 (grids 128, 256, 512), 4 seeds, H = 0.2, 0.5,
//! 0.8, q_l = 1, q_r = 2, q_s = finest/16 (4 pixels per shortest wavelength
//! on the coarsest grid), rms slope 0.1, E* = 1, 8 pressures with linear-law
//! A/A0 ≈ 0.005 … 0.09, solver tolerance 1e-8, α = 0.7. The same study as
//! `persson compare kappa`, through the library.

use persson_studies::table::Tabulate;
use persson_studies::validation::{kappa_study, KappaStudyConfig, SweepSettings};

fn main() -> persson::Result<()> {
    let mut args = std::env::args().skip(1);
    let finest: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(512);
    let seeds: u64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(4);
    let config = KappaStudyConfig {
        hurst: vec![0.2, 0.5, 0.8],
        q_r: Some(2.0),
        q_s: Some(finest as f64 / 16.0),
        sweep: SweepSettings {
            grid: finest,
            seeds: (1..=seeds).collect(),
            options: persson::bem::Options {
                tolerance: 1e-8,
                max_iterations: 10_000,
                warm_start: true,
                yield_stress: None,
            },
            ..SweepSettings::default()
        },
        ..KappaStudyConfig::default()
    };
    let start = std::time::Instant::now();
    let study = kappa_study(&config, &mut |_| {})?;
    for t in study.tables() {
        print!("{}", t.to_text());
    }
    println!("{:.1} s", start.elapsed().as_secs_f64());
    Ok(())
}

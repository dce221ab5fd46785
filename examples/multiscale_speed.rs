//! Speed of the multi-scale spectrum: three 2048² maps (a coarse large scan,
//! a medium and a fine one cut from one synthesised surface) combined into
//! one spectrum with [`persson::topography::multi_scale`].
//!
//! Run: `cargo run --release --example multiscale_speed`. Prints the best of
//! five wall times of the combination (analysis of the three maps on the
//! common bins and the mode-weighted average); the synthesis is not timed.

use std::time::Instant;

use persson::spectrum::{Amplitude, SelfAffine};
use persson::topography::{multi_scale, AnalysisOptions, Measurement, Topography};

fn main() -> persson::Result<()> {
    let (n, l) = (2048usize, 1e-3);
    let q_l = std::f64::consts::TAU / l;
    let model = SelfAffine::new(q_l, q_l, 1e3 * q_l, 0.8, Amplitude::RmsHeight(1e-6))?;
    let maps: Vec<Topography> = (0..3u64)
        .map(|i| {
            let side = l / 4f64.powi(i as i32);
            let s = persson::bem::surface::synthesize(&model, n, side, 11 + i)?;
            Topography::map(n, n, side, side, s.heights, false)
        })
        .collect::<persson::Result<_>>()?;
    let measurements: Vec<Measurement<'_>> = maps
        .iter()
        .map(|t| Measurement {
            topography: t,
            options: AnalysisOptions::default(),
            tip_radius: None,
        })
        .collect();
    let mut best = f64::INFINITY;
    let mut bins = 0;
    for _ in 0..5 {
        let t0 = Instant::now();
        let m = multi_scale(&measurements, 10)?;
        best = best.min(t0.elapsed().as_secs_f64());
        bins = m.q.len();
    }
    println!("three {n}² maps combined into {bins} bins: best of 5 = {best:.3} s");
    Ok(())
}

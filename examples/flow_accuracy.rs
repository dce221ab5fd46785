//! Time and accuracy of the two P(u) load curves of `benches/flow.rs`
//! (effective-medium leak rate, gas gap conductance; 100 loads each), for
//! the error-vs-time rows of docs/speed.md (issue 23).
//!
//! `cargo run --release --example flow_accuracy -- write FILE` stores the
//! curves (17 digits); `… -- compare FILE` prints the largest relative
//! difference of each curve to the stored one. Either prints the fastest and
//! median wall time of 7 repeats; state the load average beside any figure.

use persson::conductance::{Conductance, ConductanceOptions, GapLaw};
use persson::gap::DensityOptions;
use persson::leakage::{Drive, EffectiveMedium, Seal};
use persson::spectrum::{Amplitude, SelfAffine};
use std::time::{Duration, Instant};

fn time<T>(mut f: impl FnMut() -> T) -> (T, Duration, Duration) {
    let mut times = Vec::new();
    let mut out = f();
    for _ in 0..7 {
        let t = Instant::now();
        out = f();
        times.push(t.elapsed());
    }
    times.sort();
    (out, times[0], times[3])
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let s = SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0))?;
    let loads: Vec<f64> = (0..100)
        .map(|i| 1e9 * 10f64.powf(-4.0 + 3.5 * f64::from(i) / 99.0))
        .collect();
    let density = DensityOptions {
        breaks: vec![4e4],
        ..Default::default()
    };
    let seal = Seal {
        seal_width: 1e-3,
        seal_length: 1e-2,
        viscosity: 1e-3,
        drive: Drive::Liquid { pressure_drop: 1e5 },
    };
    let em = EffectiveMedium::new(&s, 1e9, seal, density.clone())?;
    let gap = Conductance::new(
        &s,
        1e9,
        ConductanceOptions {
            gap_law: Some(GapLaw::Gas {
                gas_conductivity: 0.026,
                mean_free_path: 7e-8,
            }),
            density,
            ..Default::default()
        },
    )?;
    let (em_curve, em_fast, em_median) = time(|| em.load_curve(&loads));
    let (gap_curve, gap_fast, gap_median) = time(|| gap.load_curve(&loads));
    println!("effective-medium curve: fastest {em_fast:?}, median {em_median:?}");
    println!("gap-conductance curve: fastest {gap_fast:?}, median {gap_median:?}");
    let values: Vec<(f64, f64)> = em_curve?
        .iter()
        .zip(gap_curve?.iter())
        .map(|(a, b)| (a.leak_rate, b.gap_conductance.unwrap_or(f64::NAN)))
        .collect();
    match (args.first().map(String::as_str), args.get(1)) {
        (Some("write"), Some(path)) => {
            let text: String = values
                .iter()
                .map(|(a, b)| format!("{a:.17e} {b:.17e}\n"))
                .collect();
            std::fs::write(path, text)?;
        }
        (Some("compare"), Some(path)) => {
            let text = std::fs::read_to_string(path)?;
            let (mut worst_em, mut worst_gap) = (0.0f64, 0.0f64);
            for (line, (a, b)) in text.lines().zip(&values) {
                let mut it = line.split_whitespace().map(str::parse::<f64>);
                let (ra, rb) = (
                    it.next().ok_or("short line")??,
                    it.next().ok_or("short line")??,
                );
                if ra > 0.0 {
                    worst_em = worst_em.max(((a - ra) / ra).abs());
                } else if *a != 0.0 {
                    worst_em = f64::INFINITY;
                }
                worst_gap = worst_gap.max(((b - rb) / rb).abs());
            }
            println!("largest relative difference: leak rate {worst_em:.2e}, gap conductance {worst_gap:.2e}");
        }
        _ => println!("(pass `write FILE` or `compare FILE` for the accuracy)"),
    }
    Ok(())
}

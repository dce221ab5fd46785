//! Time and accuracy of the two P(u) load curves of `benches/flow.rs`
//! (effective-medium leak rate, gas gap conductance; 100 loads each), for
//! the error-vs-time rows of docs/speed.md (issue 23).
//!
//! `cargo run --release --example flow_accuracy -- knobs` times both curves
//! at several values of their accuracy knob
//! (`DensityOptions::table_panels_per_unit`) and prints the largest relative
//! difference of each to the adaptive point route (`EffectiveMedium::point`,
//! `Conductance::point`: adaptive P(u), tolerance 1e-9) over the loads where
//! A/A0 ≤ 0.4 (nearer the 2-D threshold ½, σ_eff → 0 and relative errors
//! grow without bound).
//! `… -- write FILE` stores the default curves (17 digits); `… -- compare
//! FILE` prints the largest relative difference of each curve to the stored
//! one (a code change's effect). Every mode prints the fastest and median
//! wall time of 7 repeats; state the load average beside any figure.

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

/// The two models with the knob at `per_unit` ζ-panels per unit of ln m3.
fn models(
    s: &SelfAffine,
    per_unit: f64,
) -> persson::Result<(EffectiveMedium<'_>, Conductance<'_>)> {
    let density = DensityOptions {
        breaks: vec![4e4],
        table_panels_per_unit: per_unit,
        ..Default::default()
    };
    let seal = Seal {
        seal_width: 1e-3,
        seal_length: 1e-2,
        viscosity: 1e-3,
        drive: Drive::Liquid { pressure_drop: 1e5 },
    };
    let em = EffectiveMedium::new(s, 1e9, seal, density.clone())?;
    let gap = Conductance::new(
        s,
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
    Ok((em, gap))
}

/// Largest relative difference over the pairs whose reference is non-zero.
fn worst(pairs: impl Iterator<Item = (f64, f64)>) -> f64 {
    pairs
        .filter(|(_, r)| *r != 0.0)
        .map(|(a, r)| ((a - r) / r).abs())
        .fold(0.0, f64::max)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let s = SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0))?;
    let loads: Vec<f64> = (0..100)
        .map(|i| 1e9 * 10f64.powf(-4.0 + 3.5 * f64::from(i) / 99.0))
        .collect();
    if args.first().map(String::as_str) == Some("knobs") {
        let (em, gap) = models(&s, persson::gap::table::DEFAULT_CURVE_PANELS_PER_UNIT)?;
        // the reference: the adaptive route at each load
        let mut reference = Vec::new();
        for &p in &loads {
            let e = em.point(p)?;
            if e.contact_fraction <= 0.4 {
                reference.push((
                    p,
                    e.leak_rate,
                    gap.point(p)?.gap_conductance.unwrap_or(f64::NAN),
                ));
            }
        }
        println!("| table_panels_per_unit | effective medium: fastest / median | error | gap conductance: fastest / median | error |");
        println!("|---|---|---|---|---|");
        for per_unit in [0.25, 0.35, 0.5, 1.0] {
            let (em, gap) = models(&s, per_unit)?;
            let (em_curve, em_fast, em_median) = time(|| em.load_curve(&loads));
            let (gap_curve, gap_fast, gap_median) = time(|| gap.load_curve(&loads));
            let (em_curve, gap_curve) = (em_curve?, gap_curve?);
            let at = |p: f64| loads.iter().position(|&l| l == p).unwrap_or(0);
            let em_err = worst(reference.iter().map(|r| (em_curve[at(r.0)].leak_rate, r.1)));
            let gap_err = worst(
                reference
                    .iter()
                    .map(|r| (gap_curve[at(r.0)].gap_conductance.unwrap_or(f64::NAN), r.2)),
            );
            println!(
                "| {per_unit} | {:.1} / {:.1} ms | {em_err:.1e} | {:.1} / {:.1} ms | {gap_err:.1e} |",
                em_fast.as_secs_f64() * 1e3,
                em_median.as_secs_f64() * 1e3,
                gap_fast.as_secs_f64() * 1e3,
                gap_median.as_secs_f64() * 1e3,
            );
        }
        println!("({} of the 100 loads have A/A0 ≤ 0.4)", reference.len());
        return Ok(());
    }
    let (em, gap) = models(&s, persson::gap::table::DEFAULT_CURVE_PANELS_PER_UNIT)?;
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
            let mut stored = Vec::new();
            for line in text.lines() {
                let mut it = line.split_whitespace().map(str::parse::<f64>);
                let a = it.next().ok_or("short line")??;
                let b = it.next().ok_or("short line")??;
                stored.push((a, b));
            }
            let pairs = values.iter().zip(&stored);
            let worst_em = worst(pairs.clone().map(|(v, r)| (v.0, r.0)));
            let worst_gap = worst(pairs.map(|(v, r)| (v.1, r.1)));
            println!("largest relative difference: leak rate {worst_em:.2e}, gap conductance {worst_gap:.2e}");
        }
        _ => println!("(pass `knobs`, `write FILE` or `compare FILE` for the accuracy)"),
    }
    Ok(())
}

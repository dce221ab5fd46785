//! Bias of the multi-scale spectrum (issue 40, item 4): three measurements
//! cut from one large synthesised surface (a coarse large scan, a medium
//! one, a fine small one, each point-sampled with white noise of 3 % of its
//! rms height) combined with the defaults, against the model spectrum the
//! surface was drawn from.
//!
//! Run: `cargo run --release --example multiscale_bias --features bem,topography [seeds]`.
//! Prints, per measurement and octave of q/q_Nyquist, the mean over seeds of
//! C_measured/C_model, then per seed the band variance and A/A0 at σ0 = 1 MPa
//! (E* = 1 GPa) from the combined spectrum against the model's over the same
//! band.

use persson::bem::surface::synthesize;
use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Tabulated};
use persson::theory::Persson;
use persson::topography::{multi_scale, AnalysisOptions, Measurement, Topography};

const L: f64 = 1e-3;
const N: usize = 2048;

fn model() -> persson::Result<SelfAffine> {
    let q_l = std::f64::consts::TAU / L;
    SelfAffine::new(
        q_l,
        q_l,
        std::f64::consts::PI * N as f64 / L,
        0.8,
        Amplitude::RmsHeight(1e-6),
    )
}

/// Gaussian noise (Box–Muller on a 64-bit LCG), seed-stable.
fn noise(n: usize, sigma: f64, seed: u64) -> Vec<f64> {
    let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut u = || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((x >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    (0..n)
        .map(|_| (-2.0 * u().ln()).sqrt() * (std::f64::consts::TAU * u()).cos() * sigma)
        .collect()
}

/// `n × n` points every `step` pixels from (x0, y0), noise of `NOISE` × rms.
fn cut(
    h: &[f64],
    x0: usize,
    y0: usize,
    n: usize,
    step: usize,
    noise_rms: f64,
    seed: u64,
) -> Topography {
    let v: Vec<f64> = (0..n * n)
        .map(|k| h[((y0 + (k / n) * step) % N) * N + (x0 + (k % n) * step) % N])
        .collect();
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let rms = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / v.len() as f64).sqrt();
    let e = noise(n * n, noise_rms * rms, seed);
    let v = v.iter().zip(&e).map(|(a, b)| a + b).collect();
    let side = n as f64 * step as f64 * L / N as f64;
    Topography::map(n, n, side, side, v, false).unwrap()
}

fn main() -> persson::Result<()> {
    let seeds: u64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(6);
    let noise_rms: f64 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0.03);
    let m = model()?;
    // ratio sums per measurement and octave band of q/q_Nyquist (8 octaves).
    let mut sums = [[(0.0f64, 0usize); 8]; 3];
    let mut per_bin: Vec<(f64, f64, usize)> = Vec::new();
    for seed in 0..seeds {
        let s = synthesize(&m, N, L, 100 + seed)?;
        let maps = [
            cut(&s.heights, 0, 0, 512, 4, noise_rms, 3 * seed + 1),
            cut(&s.heights, 300, 700, 512, 2, noise_rms, 3 * seed + 2),
            cut(&s.heights, 1100, 200, 512, 1, noise_rms, 3 * seed + 3),
        ];
        let ms: Vec<Measurement<'_>> = maps
            .iter()
            .map(|t| Measurement {
                topography: t,
                options: AnalysisOptions::default(),
                tip_radius: None,
            })
            .collect();
        let c = multi_scale(&ms, 10)?;
        for (i, contribution) in c.measurements.iter().enumerate() {
            let nyquist = contribution.q_max.max(maps[i].band().1);
            for (&q, &cq) in contribution
                .analysis
                .psd
                .q
                .iter()
                .zip(&contribution.analysis.psd.c)
            {
                let octave = (nyquist / q).log2().floor() as usize;
                if octave < 8 {
                    sums[i][octave].0 += cq / m.c(q);
                    sums[i][octave].1 += 1;
                }
            }
        }
        for (i, contribution) in c.measurements.iter().enumerate() {
            eprintln!(
                "  seed {seed} measurement {i}: band {:.3e}..{:.3e}, reliable {:.3e}..{:.3e}, floor {:?}",
                contribution.q_min, contribution.q_max, contribution.reliable.0, contribution.reliable.1, contribution.floor
            );
        }
        let combined = c.to_tabulated()?;
        let band = |s: &dyn Spectrum| {
            // ∫ 2π q C dq on 4000 log-spaced points (trapezoid in ln q).
            let (lo, hi) = (combined.q_min().ln(), combined.q_max().ln());
            let k = 4000;
            (0..=k)
                .map(|j| {
                    let q = (lo + (hi - lo) * j as f64 / k as f64).exp();
                    let w = if j == 0 || j == k { 0.5 } else { 1.0 };
                    w * std::f64::consts::TAU * q * q * s.c(q)
                })
                .sum::<f64>()
                * (hi - lo)
                / k as f64
        };
        // The truth: the whole periodic surface's spectrum on the same bins
        // (a bin's mean C is above C at its mean q for a convex C: the model
        // evaluated at the bins' q would be 4 % low).
        let edges = persson::topography::Bins::Log { per_decade: 10 }.edges(c.q_min, c.q_max)?;
        let top = c.q_max;
        let own: Vec<f64> = edges.iter().copied().take_while(|e| *e <= top).collect();
        let full = Topography::map(N, N, L, L, s.heights.clone(), true)?;
        let truth = persson::topography::analyse(
            &full,
            &AnalysisOptions {
                q_max: own.last().copied(),
                bins: Some(persson::topography::Bins::Edges(own)),
                ..Default::default()
            },
        )?
        .psd;
        let model_band = Tabulated::new(
            &truth
                .q
                .iter()
                .zip(&truth.c)
                .filter(|(q, _)| **q >= c.q[0] * 0.9 && **q <= *c.q.last().unwrap() * 1.1)
                .map(|(q, c)| (*q, *c))
                .collect::<Vec<_>>(),
        )?;
        for (k, (&q, &cq)) in c.q.iter().zip(&c.c).enumerate() {
            let t = model_band.c(q);
            if per_bin.len() <= k {
                per_bin.push((q, 0.0, 0));
            }
            per_bin[k].1 += cq / t;
            per_bin[k].2 += 1;
        }
        let area = |s: &dyn Spectrum| {
            let p = Persson::new(s, 1e9).unwrap();
            p.contact_fraction(s.q_max() / s.q_min(), 1e6)
                .unwrap()
                .fraction
        };
        println!(
            "seed {seed}: variance combined/truth {:.4}, A/A0 at 1 MPa combined/truth {:.4}",
            band(&combined) / band(&model_band),
            area(&combined) / area(&model_band)
        );
    }
    println!("combined C/C_truth by bin (mean over seeds):");
    for (q, r, n) in &per_bin {
        println!("  q = {q:.4e}: {:.4}", r / *n as f64);
    }
    println!("mean C/C_model by octave below each measurement's Nyquist wavevector:");
    for (i, row) in sums.iter().enumerate() {
        let cells: Vec<String> = row
            .iter()
            .map(|(s, n)| {
                if *n > 0 {
                    format!("{:.3}", s / *n as f64)
                } else {
                    "–".into()
                }
            })
            .collect();
        println!("  measurement {i}: {}", cells.join("  "));
    }
    Ok(())
}

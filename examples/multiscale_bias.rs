//! Bias of the multi-scale spectrum: three measurements cut from one large
//! periodic synthesised surface (a coarse large scan of the whole surface,
//! every 4th point; a medium one, every 2nd point; a fine small one at full
//! resolution; each 512², with white noise of NOISE × its rms height)
//! combined with the defaults, against two references computed from the
//! whole surface on the same bins and compared over the same band:
//! - **periodogram**: the whole periodic surface as it is (no window), the
//!   realisation's own spectrum;
//! - **conditioned**: the whole surface conditioned as the measurements are
//!   (taken as non-periodic: plane removed, Hann window). The coarse scan is
//!   that surface point-sampled, so in the lowest bins, which only it
//!   measures, both carry the same main-lobe smoothing of the window (a
//!   single measurement's bias, not the combination's); the difference to
//!   this reference is the combination's own bias.
//!
//! Run: `cargo run --release --example multiscale_bias --features
//! bem,topography -- [SEEDS] [NOISE]` (default 6 seeds, noise 0.03).
//!
//! Prints per seed A/A0 at σ0 = 1 MPa (E* = 1 GPa) from the combined spectrum
//! over that from each reference, A/A0 = erf(1/(2√G)) with
//! G = (E*/σ0)² ⟨|∇h|²⟩/8 and ⟨|∇h|²⟩ = 2π ∫ q³ C dq over the band both
//! cover (log-log interpolation between the bins), and the excess slope
//! variance (combined − reference) over the periodogram's total, split at
//! `LOW_MODES · 2π/L` (below it the coarse scan's window main lobe); then
//! the mean, standard error and standard deviation over seeds, and per bin
//! the mean C ratio to each reference.

use persson::bem::surface::synthesize;
use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Tabulated};
use persson::topography::{
    analyse, multi_scale, AnalysisOptions, Bins, Detrend, Measurement, MultiScale, Topography,
    Window,
};

const L: f64 = 1e-3;
const N: usize = 2048;
const PRESSURE: f64 = 1e6;
const MODULUS: f64 = 1e9;
/// Modes of the largest scan below which its window's main lobe biases C
/// (the multi-scale module's `LOW_MODES`).
const LOW_MODES: f64 = 8.0;

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

/// `n × n` points every `step` pixels from (x0, y0), noise of `noise_rms` ×
/// their rms height, not periodic.
fn cut(
    h: &[f64],
    (x0, y0): (usize, usize),
    n: usize,
    step: usize,
    noise_rms: f64,
    seed: u64,
) -> persson::Result<Topography> {
    let v: Vec<f64> = (0..n * n)
        .map(|k| h[((y0 + (k / n) * step) % N) * N + (x0 + (k % n) * step) % N])
        .collect();
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let rms = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / v.len() as f64).sqrt();
    let e = noise(n * n, noise_rms * rms, seed);
    let v = v.iter().zip(&e).map(|(a, b)| a + b).collect();
    let side = n as f64 * step as f64 * L / N as f64;
    Topography::map(n, n, side, side, v, false)
}

/// The whole surface's spectrum on the combined spectrum's bins (`periodic`:
/// as it is; else plane-detrended and Hann-windowed as the measurements),
/// the bins of the combined band only, as `(bin index, q, C)`.
fn reference(
    heights: &[f64],
    c: &MultiScale,
    edges: &[f64],
    periodic: bool,
) -> persson::Result<Vec<(usize, f64, f64)>> {
    let own: Vec<f64> = edges
        .iter()
        .copied()
        .take_while(|e| *e <= c.q_max)
        .collect();
    let full = Topography::map(N, N, L, L, heights.to_vec(), periodic)?;
    let options = AnalysisOptions {
        q_max: own.last().copied(),
        bins: Some(Bins::Edges(own)),
        detrend: Some(if periodic {
            Detrend::None
        } else {
            Detrend::Plane
        }),
        window: Some(if periodic { Window::None } else { Window::Hann }),
    };
    let psd = analyse(&full, &options)?.psd;
    let (first, last) = (bin(edges, c.q[0]), bin(edges, c.q[c.q.len() - 1]));
    Ok(psd
        .q
        .iter()
        .zip(&psd.c)
        .map(|(&q, &cq)| (bin(edges, q), q, cq))
        .filter(|(b, _, _)| (first..=last).contains(b))
        .collect())
}

/// The index of the bin of `q`.
fn bin(edges: &[f64], q: f64) -> usize {
    edges.partition_point(|e| *e < q).saturating_sub(1)
}

/// `2π ∫ q³ C dq` over `[lo, hi]`.
fn slope_variance(s: &Tabulated, lo: f64, hi: f64) -> persson::Result<f64> {
    Ok(std::f64::consts::TAU * s.moment(3, lo, hi)?.value)
}

/// A/A0 at [`PRESSURE`] for a slope variance (Persson's original theory).
fn area(slope_variance: f64) -> persson::Result<f64> {
    let g = (MODULUS / PRESSURE).powi(2) * slope_variance / 8.0;
    Ok(persson::theory::contact_fraction(g, 0.0)?.fraction)
}

/// Mean, standard error and standard deviation.
fn stats(x: &[f64]) -> (f64, f64, f64) {
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0)).sqrt();
    (mean, sd / n.sqrt(), sd)
}

/// One seed's comparison: A/A0 ratios − 1 to (periodogram, conditioned) and
/// the excess slope variance below and above the main-lobe split, each over
/// the periodogram's total.
struct Seed {
    area: [f64; 2],
    excess: [[f64; 2]; 2],
}

fn compare(
    c: &MultiScale,
    references: &[Vec<(usize, f64, f64)>; 2],
    split: f64,
) -> persson::Result<Seed> {
    let combined = c.to_tabulated()?;
    let tables = references
        .iter()
        .map(|r| Tabulated::new(&r.iter().map(|p| (p.1, p.2)).collect::<Vec<_>>()))
        .collect::<persson::Result<Vec<_>>>()?;
    let lo = tables
        .iter()
        .map(|t| t.q_min())
        .fold(combined.q_min(), f64::max);
    let hi = tables
        .iter()
        .map(|t| t.q_max())
        .fold(combined.q_max(), f64::min);
    let total = slope_variance(&tables[0], lo, hi)?;
    let a = area(slope_variance(&combined, lo, hi)?)?;
    let mut seed = Seed {
        area: [0.0; 2],
        excess: [[0.0; 2]; 2],
    };
    for (k, t) in tables.iter().enumerate() {
        seed.area[k] = a / area(slope_variance(t, lo, hi)?)? - 1.0;
        for (j, (a0, b0)) in [(lo, split), (split, hi)].into_iter().enumerate() {
            let (a0, b0) = (a0.clamp(lo, hi), b0.clamp(lo, hi));
            seed.excess[k][j] =
                (slope_variance(&combined, a0, b0)? - slope_variance(t, a0, b0)?) / total;
        }
    }
    Ok(seed)
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
    let split = LOW_MODES * std::f64::consts::TAU / L;
    // per bin index: q, Σ C/C_ref for both references, seeds.
    let mut per_bin: std::collections::BTreeMap<usize, (f64, [f64; 2], usize)> = Default::default();
    let mut results = Vec::new();
    for seed in 0..seeds {
        let s = synthesize(&m, N, L, 100 + seed)?;
        let maps = [
            cut(&s.heights, (0, 0), 512, 4, noise_rms, 3 * seed + 1)?,
            cut(&s.heights, (300, 700), 512, 2, noise_rms, 3 * seed + 2)?,
            cut(&s.heights, (1100, 200), 512, 1, noise_rms, 3 * seed + 3)?,
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
        for (i, m) in c.measurements.iter().enumerate() {
            eprintln!(
                "  seed {seed} measurement {i}: reliable {:.3e}..{:.3e}, floor {:.3e}",
                m.reliable.0,
                m.reliable.1,
                m.floor.unwrap_or(0.0)
            );
        }
        let edges = Bins::Log { per_decade: 10 }.edges(c.q_min, c.q_max)?;
        let references = [
            reference(&s.heights, &c, &edges, true)?,
            reference(&s.heights, &c, &edges, false)?,
        ];
        for (&q, &cq) in c.q.iter().zip(&c.c) {
            let b = bin(&edges, q);
            let entry = per_bin.entry(b).or_insert((q, [0.0; 2], 0));
            for (k, r) in references.iter().enumerate() {
                if let Some(p) = r.iter().find(|p| p.0 == b) {
                    entry.1[k] += cq / p.2;
                }
            }
            entry.2 += 1;
        }
        let r = compare(&c, &references, split)?;
        println!(
            "seed {seed}: A/A0 combined/periodogram − 1 = {:+.4}, combined/conditioned − 1 = \
             {:+.4}; excess slope variance below/above {split:.3e} 1/m: periodogram {:+.4} \
             {:+.4}, conditioned {:+.4} {:+.4}; top of the band {:.3e} 1/m",
            r.area[0],
            r.area[1],
            r.excess[0][0],
            r.excess[0][1],
            r.excess[1][0],
            r.excess[1][1],
            c.q[c.q.len() - 1]
        );
        results.push(r);
    }
    println!("{seeds} seeds, noise {noise_rms}: mean ± standard error (standard deviation)");
    for (k, name) in ["periodogram", "conditioned"].iter().enumerate() {
        let show = |x: Vec<f64>| {
            let (m, se, sd) = stats(&x);
            format!(
                "{:+.2} ± {:.2} % ({:.2} %)",
                100.0 * m,
                100.0 * se,
                100.0 * sd
            )
        };
        println!(
            "  {name}: A/A0 {}; excess slope variance below the split {}, above it {}",
            show(results.iter().map(|r| r.area[k]).collect()),
            show(results.iter().map(|r| r.excess[k][0]).collect()),
            show(results.iter().map(|r| r.excess[k][1]).collect())
        );
    }
    println!("combined C / reference C by bin (mean over the seeds with the bin):");
    for (q, sums, n) in per_bin.values() {
        println!(
            "  q = {q:.4e} ({n} seeds): periodogram {:.4}, conditioned {:.4}",
            sums[0] / *n as f64,
            sums[1] / *n as f64
        );
    }
    Ok(())
}

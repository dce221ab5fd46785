//! Time detrending plus the radially averaged spectrum of a 4096² map (the
//! issue's speed goal: under 1 s on one thread, at most 4 N² doubles of extra
//! memory).
//!
//! ```text
//! cargo run --release --example topography_speed [-- N]
//! ```
//!
//! The map is a deterministic non-periodic rough field (a 2D random walk of
//! LCG numbers plus a plane), conditioned with the non-periodic defaults:
//! least-squares plane removed and a radial Hann window, then binned on the
//! log grid. The extra memory is the rise of the peak resident set size
//! (`VmHWM` of /proc/self/status, Linux) during the spectrum, in units of
//! N² doubles. The side-by-side SurfaceTopography run is
//! `detrend('height').power_spectrum_from_area(window='hann')` on the same
//! map (see tests/reference/surface_topography.py for the environment).

use std::time::Instant;

use persson::topography::{isotropic_spectrum, Bins, Conditioning, Detrend, Topography, Window};

fn peak_rss_bytes() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024.0)
}

/// CPU time of this thread so far (first field of /proc/thread-self/schedstat,
/// ns): the wall time is inflated when other processes share the cores.
fn cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(s.split_whitespace().next()?.parse::<f64>().ok()? * 1e-9)
}

fn main() -> persson::Result<()> {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(4096);
    let mut x: u64 = 12345;
    let mut h = vec![0.0; n * n];
    for v in h.iter_mut() {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        *v = (x >> 11) as f64 * 2f64.powi(-53) - 0.5;
    }
    for row in h.chunks_exact_mut(n) {
        for i in 1..n {
            row[i] += row[i - 1];
        }
    }
    for j in 1..n {
        for i in 0..n {
            h[j * n + i] += h[(j - 1) * n + i] + 1e-3 * i as f64;
        }
    }
    let t = Topography::map(n, n, 1e-3, 1e-3, h, false)?;
    let before = peak_rss_bytes();
    let cond = Conditioning {
        detrend: Detrend::Plane,
        window: Window::Hann,
    };
    let cpu0 = cpu_seconds();
    let start = Instant::now();
    let psd = isotropic_spectrum(&t, cond, &Bins::default(), None)?;
    let seconds = start.elapsed().as_secs_f64();
    let cpu = cpu0.zip(cpu_seconds()).map(|(a, b)| b - a);
    let after = peak_rss_bytes();
    println!(
        "{n}² map: detrend (plane) + Hann window + spectrum ({} bins) in {seconds:.3} s",
        psd.q.len()
    );
    if let Some(cpu) = cpu {
        println!("cpu time {cpu:.3} s (one thread)");
    }
    if let (Some(b), Some(a)) = (before, after) {
        println!(
            "peak extra memory {:.0} MB = {:.2} N² doubles",
            (a - b) / 1e6,
            (a - b) / (8.0 * (n * n) as f64)
        );
    }
    // The whole analysis the CLI will call (spectrum, real-space statistics
    // with their own detrended copy, Hurst fit).
    let start = Instant::now();
    let r = persson::topography::analyse(&t, &Default::default())?;
    println!(
        "analyse (spectrum + real-space statistics + Hurst fit) in {:.3} s: H = {:?} ± {:?}",
        start.elapsed().as_secs_f64(),
        r.hurst,
        r.hurst_error
    );
    Ok(())
}

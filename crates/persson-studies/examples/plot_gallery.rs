//! Renders every standard figure of `persson_studies::plot` as SVG and PNG.
//!
//! ```text
//! cargo run --release --example plot_gallery [--features plot] [OUT_DIR]
//! ```
//! OUT_DIR defaults to `target/plot-gallery`. The data are computed here with
//! the library (a self-affine spectrum, Persson's G and A/A0), the Hertz-ball
//! stress distribution of Persson, Bucher & Chiaia (2002) Fig. 3 by the method
//! of images, and a measured accuracy–cost comparison of three quadratures.

use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::theory::{log_zetas, Persson};
use persson_studies::plot::{self, Figure, LinearLaw, PowerLaw, Series};
use std::path::{Path, PathBuf};
use std::time::Instant;

type BoxResult<T> = Result<T, Box<dyn std::error::Error>>;

fn main() -> BoxResult<()> {
    let out = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("target/plot-gallery"));
    std::fs::create_dir_all(&out)?;

    // A self-affine surface: H = 0.8, roll-off at q_r, rms height 1 µm.
    let (q_l, q_r, q_s, hurst) = (1e4, 1e5, 1e9, 0.8);
    let surface = SelfAffine::new(q_l, q_r, q_s, hurst, Amplitude::RmsHeight(1e-6))?;
    let contact_modulus = 1e7; // Pa
    let theory = Persson::new(&surface, contact_modulus)?;

    save(
        &out,
        "spectrum",
        &spectrum_figure(&surface, q_l, q_r, q_s, hurst)?,
    )?;
    save(&out, "g_vs_zeta", &g_figure(&theory)?)?;
    save(&out, "area_vs_zeta", &area_zeta_figure(&theory)?)?;
    save(&out, "area_vs_load", &area_load_figure(&theory, &surface)?)?;
    save(&out, "stress_family", &stress_figure()?)?;
    save(&out, "error_vs_time", &error_time_figure()?)?;
    println!("wrote the gallery to {}", out.display());
    Ok(())
}

fn save(dir: &Path, name: &str, fig: &Figure) -> BoxResult<()> {
    for ext in ["svg", "png"] {
        let path = dir.join(format!("{name}.{ext}"));
        let start = Instant::now();
        plot::render(fig, &path)?;
        let ms = 1e3 * start.elapsed().as_secs_f64();
        let kb = std::fs::metadata(&path)?.len() as f64 / 1024.0;
        println!("{:<40} {ms:7.1} ms {kb:7.1} KiB", path.display());
    }
    Ok(())
}

/// `n` values from `a` to `b` evenly spaced in log.
fn geomspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a * (b / a).powf(i as f64 / (n - 1) as f64))
        .collect()
}

fn spectrum_figure(s: &SelfAffine, q_l: f64, q_r: f64, q_s: f64, h: f64) -> BoxResult<Figure> {
    let q = geomspace(q_l, q_s, 200);
    let c: Vec<f64> = q.iter().map(|&q| s.c(q)).collect();
    let exponent = -2.0 * (h + 1.0);
    let fit = PowerLaw {
        prefactor: s.c_r() * q_r.powf(-exponent),
        exponent,
        q_range: Some((q_r, q_s)),
    };
    Ok(plot::spectrum(&q, &c, Some(fit))?)
}

const PRESSURES: [(f64, &str); 3] = [
    (1e4, "σ0 = 10 kPa"),
    (1e5, "σ0 = 100 kPa"),
    (1e6, "σ0 = 1 MPa"),
];

fn g_figure(t: &Persson) -> BoxResult<Figure> {
    let zeta = log_zetas(t.zeta_max(), 120);
    let mut ys = Vec::new();
    for (p, _) in PRESSURES {
        ys.push(
            zeta.iter()
                .map(|&z| t.g(z, p).map(|g| g.value))
                .collect::<persson::Result<Vec<f64>>>()?,
        );
    }
    let curves: Vec<(&str, &[f64])> = PRESSURES
        .iter()
        .zip(&ys)
        .map(|((_, l), y)| (*l, &y[..]))
        .collect();
    Ok(plot::g_vs_zeta(&zeta, &curves)?)
}

fn area_zeta_figure(t: &Persson) -> BoxResult<Figure> {
    let zeta = log_zetas(t.zeta_max(), 120);
    let mut ys = Vec::new();
    for (p, _) in PRESSURES {
        let pts = t.magnification_curve(&zeta, p)?;
        ys.push(pts.iter().map(|a| a.contact_fraction).collect::<Vec<f64>>());
    }
    let curves: Vec<(&str, &[f64])> = PRESSURES
        .iter()
        .zip(&ys)
        .map(|((_, l), y)| (*l, &y[..]))
        .collect();
    Ok(plot::area_vs_zeta(&zeta, &curves)?)
}

fn area_load_figure(t: &Persson, s: &SelfAffine) -> BoxResult<Figure> {
    let pressures = geomspace(1e3, 3e7, 80);
    let pts = t.load_curve(&pressures, t.zeta_max())?;
    let area: Vec<f64> = pts.iter().map(|a| a.contact_fraction).collect();
    let rms_slope = s.rms_slope(s.q_l(), s.q_s())?.value;
    let mut fig = plot::area_vs_load(
        &pressures,
        &[("Persson theory, ζ = ζmax", &area)],
        "Pa",
        Some(LinearLaw {
            contact_modulus: t.contact_modulus(),
            rms_slope,
        }),
    )?;
    // The κ ≈ 2 that boundary-element and GFMD results give (Campañá & Müser, EPL 77, 38005 (2007)), as markers.
    let kappa_num = 2.0;
    let gfmd: Vec<(f64, f64)> = geomspace(1e3, 3e6, 8)
        .into_iter()
        .map(|p| (p, kappa_num * p / (t.contact_modulus() * rms_slope)))
        .collect();
    fig.push(Series::markers("κ = 2 (Campañá & Müser 2007)", gfmd));
    Ok(fig)
}

/// P(σ, ζ) for the Hertz ball (P0 = 2σ/σH² below σH, σ0 = 2σH/3) by the
/// method of images: P = ∫ P0(s) [φ(σ − s) − φ(σ + s)] ds, φ Gaussian of
/// variance 2σ0²G. Units: σ in σH, P in 1/σH.
fn hertz_ball(sigma: f64, g: f64) -> f64 {
    if g == 0.0 {
        return if sigma < 1.0 { 2.0 * sigma } else { 0.0 };
    }
    let s0 = 2.0 / 3.0;
    let var = 2.0 * s0 * s0 * g;
    let phi = |x: f64| (-x * x / (2.0 * var)).exp() / (2.0 * std::f64::consts::PI * var).sqrt();
    let n = 2000;
    let h = 1.0 / n as f64;
    // Midpoint rule over s in (0, 1): ample for a figure.
    (0..n)
        .map(|i| {
            let s = (i as f64 + 0.5) * h;
            2.0 * s * (phi(sigma - s) - phi(sigma + s)) * h
        })
        .sum()
}

fn stress_figure() -> BoxResult<Figure> {
    let sigma: Vec<f64> = (0..=400).map(|i| 3.0 * i as f64 / 400.0).collect();
    let gs = [(0.0, "G = 0"), (0.6, "G = 0.6"), (2.0, "G = 2")];
    let ys: Vec<Vec<f64>> = gs
        .iter()
        .map(|&(g, _)| sigma.iter().map(|&s| hertz_ball(s, g)).collect())
        .collect();
    let curves: Vec<(&str, &[f64])> = gs.iter().zip(&ys).map(|((_, l), y)| (*l, &y[..])).collect();
    let mut fig = plot::stress_family(&sigma, &curves)?;
    fig.title = "Hertz ball: stress distribution P(σ, ζ) (PRB 65, 184106, Fig. 3)".into();
    Ok(fig)
}

/// Seconds per call of `f`: the best of 5 batches of at least 2 ms each
/// (the minimum filters out interference from other processes).
fn time<T>(mut f: impl FnMut() -> T) -> (f64, T) {
    let mut out = f();
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let start = Instant::now();
        let mut reps = 0u32;
        while start.elapsed().as_secs_f64() < 2e-3 {
            out = f();
            reps += 1;
        }
        best = best.min(start.elapsed().as_secs_f64() / reps as f64);
    }
    (best, out)
}

/// Error against time of three quadratures of ∫₀¹ √x dx = 2/3 (an endpoint
/// singularity in the derivative: the composite rules converge as h^1.5).
fn error_time_figure() -> BoxResult<Figure> {
    let exact = 2.0 / 3.0;
    let f = |x: f64| x.sqrt();
    let rel = |v: f64| ((v - exact) / exact).abs().max(1e-17);

    let mut adaptive = Vec::new();
    for k in 2..=13 {
        let tol = 10f64.powi(-k);
        // bilby's adaptive G10K21 rule, as the crate's own quadrature uses it
        let (t, r) = time(|| {
            bilby::AdaptiveIntegrator::default()
                .with_pair(bilby::GKPair::G10K21)
                .with_rel_tol(tol)
                .with_abs_tol(0.0)
                .with_max_evals(1_000_000)
                .integrate(0.0, 1.0, f)
        });
        adaptive.push((t, rel(r?.value)));
    }
    let mut trapezoid = Vec::new();
    let mut simpson = Vec::new();
    for k in 2..=18 {
        let n = 1usize << k;
        let h = 1.0 / n as f64;
        let (t, v) = time(|| {
            let inner: f64 = (1..n).map(|i| f(i as f64 * h)).sum();
            h * (inner + 0.5 * (f(0.0) + f(1.0)))
        });
        trapezoid.push((t, rel(v)));
        let (t, v) = time(|| {
            let s: f64 = (1..n)
                .map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * h))
                .sum();
            h / 3.0 * (s + f(0.0) + f(1.0))
        });
        simpson.push((t, rel(v)));
    }
    let mut fig = plot::error_vs_time(&[
        ("adaptive G10K21, tol = 10⁻² … 10⁻¹³", &adaptive),
        ("trapezoid, n = 4 … 2¹⁸", &trapezoid),
        ("Simpson, n = 4 … 2¹⁸", &simpson),
    ]);
    fig.title = "Quadrature of ∫₀¹ √x dx = 2/3: accuracy against cost".into();
    Ok(fig)
}

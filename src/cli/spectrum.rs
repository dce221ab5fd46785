//! `persson spectrum`: moments of the spectrum and C(q).

use serde_json::json;

use super::args::SpectrumArgs;
use super::output::{Format, Report};

/// Arguments of `persson spectrum`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    /// Lower end of the q range for the moments (default q_l), 1/m.
    #[arg(long, allow_negative_numbers = true)]
    q_min: Option<f64>,
    /// Upper end of the q range for the moments (default q_s), 1/m.
    #[arg(long, allow_negative_numbers = true)]
    q_max: Option<f64>,
    /// Number of log-spaced q values in the C(q) table.
    #[arg(long, default_value_t = 11)]
    points: usize,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson spectrum`.
pub fn run(a: Args) -> anyhow::Result<()> {
    use persson::error::check;
    a.plot.check()?;
    let s = a.spectrum.build()?;
    let lo = check::positive("q_min", a.q_min.unwrap_or(s.q_min()))?;
    let hi = check::positive("q_max", a.q_max.unwrap_or(s.q_max()))?;
    if hi <= lo {
        anyhow::bail!("invalid q_max = {hi:e}: must be > q_min = {lo:e}");
    }
    let (h, m, k) = (
        s.rms_height(lo, hi)?,
        s.rms_slope(lo, hi)?,
        s.rms_curvature(lo, hi)?,
    );
    // The power-law fit over the self-affine part: the upper half (in log q) of the band.
    let mid = (s.q_min() * s.q_max()).sqrt();
    let fine: Vec<(f64, f64)> = (0..=200)
        .map(|i| (s.q_min() * (s.q_max() / s.q_min()).powf(f64::from(i) / 200.0)).min(s.q_max()))
        .map(|q| (q, s.c(q)))
        .collect();
    let upper: Vec<(f64, f64)> = fine.iter().copied().filter(|p| p.0 >= mid).collect();
    let fit = persson::spectrum::fit_power_law(&upper)?;
    #[cfg(feature = "plot")]
    a.plot.draw(|| {
        let (q, c): (Vec<f64>, Vec<f64>) = fine.iter().copied().unzip();
        let law = persson::plot::PowerLaw {
            prefactor: fit.0,
            exponent: fit.1,
            q_range: Some((mid, s.q_max())),
        };
        persson::plot::spectrum(&q, &c, Some(law))
    })?;
    let n = a.points.max(2);
    let table: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let q = if i + 1 == n {
                s.q_max()
            } else {
                s.q_min() * (s.q_max() / s.q_min()).powf(i as f64 / (n - 1) as f64)
            };
            (q, s.c(q))
        })
        .collect();
    Report {
        title: format!(
            "Spectrum (Persson's normalisation), moments over q in [{lo:e}, {hi:e}] 1/m"
        ),
        scalars: vec![
            ("q_l".into(), s.q_min()),
            ("q_s".into(), s.q_max()),
            ("rms_height".into(), h.value),
            ("rms_slope".into(), m.value),
            ("rms_curvature".into(), k.value),
            ("fit_exponent".into(), fit.1),
            ("fit_hurst".into(), -fit.1 / 2.0 - 1.0),
        ],
        columns: vec!["q".into(), "c".into()],
        rows: table.iter().map(|&(q, c)| vec![q, c]).collect(),
        json: json!({
            "q_l": s.q_min(), "q_s": s.q_max(), "q_min": lo, "q_max": hi,
            "rms_height": h.value, "rms_height_error": h.error,
            "rms_slope": m.value, "rms_slope_error": m.error,
            "rms_curvature": k.value, "rms_curvature_error": k.error,
            "power_law_fit": { "prefactor": fit.0, "exponent": fit.1, "hurst": -fit.1 / 2.0 - 1.0, "q_min": mid, "q_max": s.q_max() },
            "table": table.iter().map(|&(q, c)| json!({"q": q, "c": c})).collect::<Vec<_>>(),
        }),
    }
    .print(&a.format)
}

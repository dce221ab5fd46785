//! `persson g`: G(ζ) and A/A0 against magnification.

use persson::theory::{log_zetas, Persson};
use serde_json::json;

use super::args::{MaterialArgs, SpectrumArgs};
use super::output::{Format, Report};

/// Arguments of `persson g`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, same unit as the modulus.
    #[arg(long, allow_negative_numbers = true)]
    pressure: Option<f64>,
    /// Magnifications ζ ≥ 1 (comma-separated; default: --points values from 1 to q_s/q_l).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    zeta: Vec<f64>,
    /// Number of log-spaced magnifications when --zeta is not given.
    #[arg(long, default_value_t = 21)]
    points: usize,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
    /// Also draw G(ζ) into this file (.svg or .png).
    #[arg(long, value_name = "FILE.svg|png")]
    plot_g: Option<std::path::PathBuf>,
}

/// Run `persson g`.
pub fn run(a: Args) -> anyhow::Result<()> {
    a.plot.check()?;
    let plot_g = super::plot::PlotArg {
        plot: a.plot_g.clone(),
    };
    plot_g.check()?;
    let spectrum = a.spectrum.build()?;
    let material = a.material.build(a.spectrum.example)?;
    let pressure = match (a.pressure, a.spectrum.example) {
        (Some(p), _) => p,
        (None, true) => super::args::example::PRESSURES[3],
        (None, false) => anyhow::bail!("no nominal pressure: give --pressure P"),
    };
    let model = Persson::new(spectrum.as_ref(), material.contact_modulus())?;
    let zetas = if a.zeta.is_empty() {
        log_zetas(model.zeta_max(), a.points)
    } else {
        a.zeta.clone()
    };
    let points = model.magnification_curve(&zetas, pressure)?;
    let z: Vec<f64> = points.iter().map(|p| p.zeta).collect();
    let label = format!("σ0 = {pressure:e}");
    #[cfg(feature = "plot")]
    {
        let a_: Vec<f64> = points.iter().map(|p| p.contact_fraction).collect();
        let g_: Vec<f64> = points.iter().map(|p| p.g).collect();
        a.plot
            .draw(|| persson::plot::area_vs_zeta(&z, &[(label.as_str(), &a_)]))?;
        plot_g.draw(|| persson::plot::g_vs_zeta(&z, &[(label.as_str(), &g_)]))?;
    }
    #[cfg(not(feature = "plot"))]
    let _ = (&z, &label);
    Report {
        title: format!(
            "G(zeta) and A/A0 at pressure {pressure:e}, E* = {:e}",
            material.contact_modulus()
        ),
        scalars: vec![("zeta_max".into(), model.zeta_max())],
        columns: ["zeta", "g", "g_error", "contact_fraction", "rms_slope"]
            .map(String::from)
            .to_vec(),
        rows: points
            .iter()
            .map(|p| vec![p.zeta, p.g, p.g_error, p.contact_fraction, p.rms_slope])
            .collect(),
        json: json!({
            "pressure": pressure,
            "contact_modulus": material.contact_modulus(),
            "zeta_max": model.zeta_max(),
            "points": points,
        }),
    }
    .print(&a.format)
}

//! `persson kappa`: κ of the linear low-load law.

use persson::kappa::Kappa;
use serde_json::json;

use super::args::{MaterialArgs, SpectrumArgs};
use super::output::{Format, Report};

/// Arguments of `persson kappa`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal pressures: with a spectrum and material, print the linear contact fractions.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pressure: Vec<f64>,
    #[command(flatten)]
    format: Format,
}

/// Run `persson kappa`.
pub fn run(a: Args) -> anyhow::Result<()> {
    let (kb, kp) = (Kappa::Bush.value(), Kappa::Persson.value());
    let mut json = json!({ "kappa_bush": kb, "kappa_persson": kp });
    let mut rows = Vec::new();
    let mut scalars = vec![
        ("kappa_bush".to_string(), kb),
        ("kappa_persson".to_string(), kp),
    ];
    let has_surface = a.spectrum.example || a.spectrum.psd.is_some() || a.spectrum.hurst.is_some();
    if has_surface {
        let spectrum = a.spectrum.build()?;
        let e = a.material.build(a.spectrum.example)?.contact_modulus();
        let slope = spectrum
            .rms_slope(spectrum.q_min(), spectrum.q_max())?
            .value;
        let pressures = super::args::pressures(&a.pressure, a.spectrum.example)?;
        let mut pts = Vec::new();
        for &p in &pressures {
            persson::error::check::positive("pressure", p)?;
            let (b, q) = (
                Kappa::Bush.linear_fraction(p, e, slope),
                Kappa::Persson.linear_fraction(p, e, slope),
            );
            rows.push(vec![p, b, q]);
            pts.push(json!({ "pressure": p, "contact_fraction_bush_linear": b, "contact_fraction_persson_linear": q }));
        }
        scalars.push(("rms_slope".into(), slope));
        json["rms_slope"] = json!(slope);
        json["points"] = json!(pts);
    }
    Report {
        title: "kappa: A/A0 = kappa * pressure / (E* * rms_slope) at low load".into(),
        scalars,
        columns: ["pressure", "bush_linear", "persson_linear"]
            .map(String::from)
            .to_vec(),
        rows,
        json,
    }
    .print(&a.format)
}

//! `persson area`: A/A0 against nominal pressure.

use persson::corrected::{self, Theory};
use persson::kappa::Kappa;
use persson::theory::Persson;
use serde_json::json;

use super::args::{pressures, MaterialArgs, SpectrumArgs};
use super::output::{Format, Report};

/// Arguments of `persson area`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure σ0, same unit as the modulus; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pressure: Vec<f64>,
    /// Magnification ζ (default q_s/q_l, full magnification).
    #[arg(long, allow_negative_numbers = true)]
    zeta: Option<f64>,
    #[command(flatten)]
    theory: super::separation::TheoryArgs,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson area`.
pub fn run(a: Args) -> anyhow::Result<()> {
    report(&a)?.print(&a.format)
}

fn report(a: &Args) -> anyhow::Result<Report> {
    a.plot.check()?;
    let spectrum = a.spectrum.build()?;
    let material = a.material.build(a.spectrum.example)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let model = Persson::new(spectrum.as_ref(), material.contact_modulus())?;
    let zeta = a.zeta.unwrap_or_else(|| model.zeta_max());
    let theory = a.theory.build()?;
    let points = model.load_curve(&pressures, zeta)?;
    let corrected = corrected::load_curve(&model, theory, zeta, &pressures, a.theory.tolerance)?;
    // The core's points, with A/A0, 1 − A/A0 and the error bound from the theory.
    let json_points: Vec<serde_json::Value> = points
        .iter()
        .zip(&corrected)
        .map(|(p, c)| {
            let mut v = json!(p);
            if theory != Theory::Original {
                v["contact_fraction"] = json!(c.contact_fraction);
                v["complement"] = json!(c.complement);
                v["error"] = json!(c.error);
            }
            v["effective_g"] = json!(c.effective_g);
            v
        })
        .collect();
    let (q_l, q_s) = (spectrum.q_min(), spectrum.q_max());
    let rms_height = spectrum.rms_height(q_l, q_s)?.value;
    let rms_slope = spectrum.rms_slope(q_l, q_s)?.value;
    #[cfg(feature = "plot")]
    a.plot.draw(|| {
        let area: Vec<f64> = points.iter().map(|p| p.contact_fraction).collect();
        let chosen: Vec<f64> = corrected.iter().map(|p| p.contact_fraction).collect();
        let law = persson::plot::LinearLaw {
            contact_modulus: material.contact_modulus(),
            rms_slope,
        };
        let label = format!("Persson theory, ζ = {zeta:.3e}");
        let other = format!(
            "{} theory, γ = {:.3}",
            theory.name(),
            theory.gamma().unwrap_or(1.0)
        );
        let mut curves = vec![(label.as_str(), area.as_slice())];
        if theory != Theory::Original {
            curves.push((other.as_str(), chosen.as_slice()));
        }
        persson::plot::area_vs_load(&pressures, &curves, "unit of E*", Some(law))
    })?;
    #[cfg(not(feature = "plot"))]
    a.plot.unavailable()?;
    Ok(Report {
        title: format!(
            "Contact area ({} theory{}), E* = {:e}, zeta = {zeta:e}",
            theory.name(),
            theory
                .gamma()
                .map(|g| format!(", gamma = {g}"))
                .unwrap_or_default(),
            material.contact_modulus()
        ),
        scalars: vec![
            ("rms_height".into(), rms_height),
            ("rms_slope".into(), rms_slope),
            ("kappa_bush".into(), Kappa::Bush.value()),
            ("kappa_persson".into(), Kappa::Persson.value()),
        ],
        columns: [
            "pressure",
            "zeta",
            "g",
            "contact_fraction",
            "bush_linear",
            "error_bound",
        ]
        .map(String::from)
        .to_vec(),
        rows: points
            .iter()
            .zip(&json_points)
            .map(|(p, v)| {
                vec![
                    p.pressure,
                    p.zeta,
                    p.g,
                    v["contact_fraction"].as_f64().unwrap_or(f64::NAN),
                    p.contact_fraction_bush_linear,
                    v["error"].as_f64().unwrap_or(f64::NAN),
                ]
            })
            .collect(),
        json: json!({
            "contact_modulus": material.contact_modulus(),
            "rms_height": rms_height,
            "rms_slope": rms_slope,
            "kappa_bush": Kappa::Bush.value(),
            "kappa_persson": Kappa::Persson.value(),
            "theory": theory.name(),
            "gamma": theory.gamma(),
            "kappa_theory": theory.low_load_kappa(),
            "points": json_points,
        }),
    })
}

//! `persson separation`: mean interfacial separation ū, contact stiffness
//! K = −dp/dū and elastic energy against nominal pressure; and the
//! `--theory`/`--gamma` flags shared with `persson area`.

use persson::corrected::{self, Theory, THEORY_NAMES};
use persson::separation::{Separation, DEFAULT_TOLERANCE};
use serde_json::json;

use super::args::{example, pressures, MaterialArgs, SpectrumArgs};
use super::output::{Format, Report};

/// Choice of contact-area theory (`--theory`, `--gamma`).
#[derive(clap::Args, Debug, Clone)]
pub struct TheoryArgs {
    /// Contact-area theory: original (Persson 2001), yang-persson (Yang & Persson
    /// 2008, γ = 0.45), wang-muser (Wang & Müser 2017, γ = 5/9), xu (Xu et al. 2024, γ = 0.42).
    #[arg(long, default_value = "original",
          value_parser = clap::builder::PossibleValuesParser::new(THEORY_NAMES))]
    pub theory: String,
    /// γ of the corrected theory (yang-persson and xu: [0.001, 1]; wang-muser: [0.02, 11/9]).
    #[arg(long, allow_negative_numbers = true)]
    pub gamma: Option<f64>,
    /// Absolute tolerance on A/A0 of the corrected theories' solver.
    #[arg(long = "theory-tolerance", default_value_t = corrected::DEFAULT_TOLERANCE,
          allow_negative_numbers = true)]
    pub tolerance: f64,
}

impl TheoryArgs {
    /// The validated theory.
    pub fn build(&self) -> anyhow::Result<Theory> {
        Ok(Theory::from_name(&self.theory, self.gamma)?)
    }
}

/// Arguments of `persson separation`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure p, same unit as the modulus; repeatable or comma-separated.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pressure: Vec<f64>,
    /// Relative tolerance of the wavevector integrals.
    #[arg(long, default_value_t = DEFAULT_TOLERANCE, allow_negative_numbers = true)]
    tolerance: f64,
    #[command(flatten)]
    format: Format,
}

/// Run `persson separation`.
pub fn run(a: Args) -> anyhow::Result<()> {
    report(&a)?.print(&a.format)
}

fn report(a: &Args) -> anyhow::Result<Report> {
    let spectrum = a.spectrum.build()?;
    let material = a.material.build(a.spectrum.example)?;
    let pressures = pressures(&a.pressure, a.spectrum.example)?;
    let e_star = material.contact_modulus();
    let breaks = roll_off(&a.spectrum);
    let model = Separation::new(spectrum.as_ref(), e_star)?
        .with_tolerance(a.tolerance)?
        .with_breaks(&breaks);
    let points = model.load_curve(&pressures)?;
    let law = model.low_load_law()?;
    let full = model.full_contact_energy()?;
    let (q_l, q_s) = (spectrum.q_min(), spectrum.q_max());
    let rms_height = spectrum.rms_height(q_l, q_s)?.value;
    let rms_slope = spectrum.rms_slope(q_l, q_s)?.value;
    Ok(Report {
        title: format!("Mean interfacial separation (Persson 2007), E* = {e_star:e}"),
        scalars: vec![
            ("rms_height".into(), rms_height),
            ("rms_slope".into(), rms_slope),
            ("low_load_length_u0".into(), law.length.value),
            ("reference_pressure".into(), law.reference_pressure.value),
            ("full_contact_energy".into(), full.value),
        ],
        columns: [
            "pressure",
            "mean_separation",
            "stiffness",
            "elastic_energy",
            "rel_error",
        ]
        .map(String::from)
        .to_vec(),
        rows: points
            .iter()
            .map(|p| {
                vec![
                    p.pressure,
                    p.mean_separation,
                    p.stiffness,
                    p.elastic_energy,
                    relative(p.mean_separation_error, p.mean_separation)
                        .max(relative(p.stiffness_error, p.stiffness))
                        .max(relative(p.elastic_energy_error, p.elastic_energy)),
                ]
            })
            .collect(),
        json: json!({
            "contact_modulus": e_star,
            "rms_height": rms_height,
            "rms_slope": rms_slope,
            "tolerance": a.tolerance,
            "low_load_length": law.length,
            "reference_pressure": law.reference_pressure,
            "full_contact_energy": full,
            "points": points,
        }),
    })
}

/// The roll-off of a self-affine spectrum, where C(q) has a kink.
fn roll_off(s: &SpectrumArgs) -> Vec<f64> {
    match (s.psd.is_some(), s.q_r, s.example && s.hurst.is_none()) {
        (true, _, _) => vec![],
        (false, Some(q_r), _) => vec![q_r],
        (false, None, true) => vec![example::Q_R],
        _ => vec![],
    }
}

/// |err/value| (0 when both vanish; 0 for an infinite value).
fn relative(err: f64, value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        0.0
    } else {
        (err / value).abs()
    }
}

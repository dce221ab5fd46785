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
    /// Also draw ū against load (with the small-load law) into this file (.svg or .png).
    #[command(flatten)]
    plot: super::plot::PlotArg,
    /// Also draw A/A0 against load for all four theories (default γ) into this file.
    #[arg(long, value_name = "FILE.svg|png")]
    plot_area: Option<std::path::PathBuf>,
    /// Number of log-spaced pressures in the plots, spanning the given pressures
    /// (a single pressure p: p/100 to 100 p).
    #[arg(long, default_value_t = 60)]
    plot_points: usize,
}

/// Run `persson separation`.
pub fn run(a: Args) -> anyhow::Result<()> {
    report(&a)?.print(&a.format)
}

fn report(a: &Args) -> anyhow::Result<Report> {
    a.plot.check()?;
    let plot_area = super::plot::PlotArg {
        plot: a.plot_area.clone(),
    };
    plot_area.check()?;
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
    #[cfg(feature = "plot")]
    {
        let grid = plot_pressures(&pressures, a.plot_points)?;
        if a.plot.plot.is_some() {
            let curve = model.load_curve(&grid)?;
            a.plot.draw(|| separation_figure(&curve, &law, e_star))?;
        }
        if plot_area.plot.is_some() {
            let persson = persson::theory::Persson::new(spectrum.as_ref(), e_star)?;
            let zeta = persson.zeta_max();
            let mut curves = Vec::new();
            for t in Theory::all_defaults() {
                let pts =
                    corrected::load_curve(&persson, t, zeta, &grid, corrected::DEFAULT_TOLERANCE)?;
                let label = match t.gamma() {
                    None => format!("{} (κ = {:.3})", t.name(), t.low_load_kappa()),
                    Some(g) => format!("{}, γ = {g:.3} (κ = {:.3})", t.name(), t.low_load_kappa()),
                };
                curves.push((
                    label,
                    pts.iter().map(|p| p.contact_fraction).collect::<Vec<f64>>(),
                ));
            }
            let refs: Vec<(&str, &[f64])> = curves
                .iter()
                .map(|(l, c)| (l.as_str(), c.as_slice()))
                .collect();
            let law = persson::plot::LinearLaw {
                contact_modulus: e_star,
                rms_slope,
            };
            plot_area
                .draw(|| persson::plot::area_vs_load(&grid, &refs, "unit of E*", Some(law)))?;
        }
    }
    #[cfg(not(feature = "plot"))]
    {
        a.plot.unavailable()?;
        plot_area.unavailable()?;
    }
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

/// `n` log-spaced pressures spanning the given ones (p/100 to 100 p for one).
#[cfg(feature = "plot")]
fn plot_pressures(given: &[f64], n: usize) -> anyhow::Result<Vec<f64>> {
    let lo = given.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = given.iter().copied().fold(0.0, f64::max);
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        (lo / 100.0, hi * 100.0)
    };
    if n < 2 {
        anyhow::bail!("--plot-points {n}: need at least 2");
    }
    let (a, b) = (lo.ln(), hi.ln());
    Ok((0..n)
        .map(|i| (a + (b - a) * i as f64 / (n - 1) as f64).exp())
        .collect())
}

/// ū against load, log pressure axis, with the small-load law u0 ln(p_ref/p).
#[cfg(feature = "plot")]
fn separation_figure(
    curve: &[persson::separation::SeparationPoint],
    law: &persson::separation::LowLoadLaw,
    e_star: f64,
) -> persson::Result<persson::plot::Figure> {
    use persson::plot::{Axis, Figure, Series};
    let u: Vec<(f64, f64)> = curve
        .iter()
        .map(|p| (p.pressure, p.mean_separation))
        .collect();
    let (u0, p_ref) = (law.length.value, law.reference_pressure.value);
    let asymptote: Vec<(f64, f64)> = curve
        .iter()
        .map(|p| (p.pressure, u0 * (p_ref / p.pressure).ln()))
        .filter(|&(_, v)| v > 0.0)
        .collect();
    Ok(Figure::new(
        format!("Mean interfacial separation (Persson 2007), E* = {e_star:e}"),
        Axis::log("nominal pressure p (unit of E*)"),
        Axis::log("mean separation ū (m)"),
    )
    .with_series(Series::line("ū(p)", u))
    .with_series(Series::dashed(
        format!("u0 ln(p_ref/p), u0 = {u0:.3e} m, p_ref = {p_ref:.3e}"),
        asymptote,
    )))
}

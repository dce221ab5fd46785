//! The stress distributions' entries (sine series, image quadrature) and
//! their extreme cases.
//!
//! Every error is measured against the mpmath values of
//! `tests/reference/stress.json` (40 digits, `tests/reference/stress_reference.py`),
//! compiled in with `include_str!` and read with serde_json (the numbers
//! `tests/stress.rs` reads from the same file), so the report needs no files
//! at run time. Densities are compared as in the accuracy policy of
//! [`persson::stress`]: absolute in 1/σH, relative where the density exceeds
//! 1/σH; fractions absolutely.

use std::sync::LazyLock;

use super::accuracy::{time_it, AccuracyRow, Extent, Knob, MethodAccuracy};
use super::stability::{case, num, Family, StabilityCase};
use persson::error::{Error, Result};
use persson::stress::{series_fractions, Method, Solver, Start, TabulatedStart};

/// Where the references come from, for the methods' `reference`.
const REFERENCE_NAME: &str = "mpmath at 40 digits (tests/reference/stress_reference.py)";
/// Wall-time budget per row, s (the median of repeated runs is reported).
const TIME_BUDGET: f64 = 0.04;

/// The reference file: three starts × G × σY/σH, densities on a σ grid and
/// both fractions (`python3 tests/reference/stress_reference.py` writes it).
const REFERENCE_JSON: &str = include_str!("../../../../tests/reference/stress.json");

/// One reference case: a start, G and σY/σH, the density on a σ grid and
/// both fractions.
#[derive(Debug, serde::Deserialize)]
pub(super) struct Reference {
    /// `flat`, `hertz` or `cylinder`.
    pub(super) start: String,
    /// G.
    pub(super) g: f64,
    /// σY/σH, `None` when elastic.
    pub(super) yield_ratio: Option<f64>,
    /// s = σ/σH.
    pub(super) sigma: Vec<f64>,
    /// P(s) in 1/σH.
    pub(super) density: Vec<f64>,
    /// A_el/A0.
    pub(super) contact_fraction: f64,
    /// A_pl/A0.
    pub(super) plastic_fraction: f64,
}

impl Reference {
    /// τ/y² = (σ0/σH)² G/y², the series' decay scale (0 when elastic).
    fn tau_over_y2(&self, start: &Start) -> f64 {
        let m = start.mean_ratio();
        self.yield_ratio.map_or(0.0, |y| m * m * self.g / (y * y))
    }
}

/// The cases of [`REFERENCE_JSON`], read once (or why they cannot be: a
/// defect of the file, reported as the error of the report).
static CASES: LazyLock<std::result::Result<Vec<Reference>, String>> =
    LazyLock::new(|| serde_json::from_str(REFERENCE_JSON).map_err(|e| e.to_string()));

/// The references with their starts.
///
/// # Errors
/// The reference file does not parse, or names a start the solver does not
/// know (a defect of the file).
fn references() -> Result<Vec<(Start, &'static Reference)>> {
    let cases = CASES
        .as_ref()
        .map_err(|e| Error::parse("tests/reference/stress.json", 0, 0, e.as_str()))?;
    cases
        .iter()
        .map(|c| Ok((Start::from_name(&c.start)?, c)))
        .collect()
}

/// Accuracy-knob settings: tolerances 1e-4 … 1e-14 (Full: also 1e-5, 1e-15).
fn tolerances(extent: Extent) -> Vec<f64> {
    let mut tols = vec![1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    if extent == Extent::Full {
        tols.insert(1, 1e-5);
        tols.push(1e-15);
    }
    tols
}

/// Error against time of the stress-distribution methods: the sine series
/// (density by tolerance, fractions by number of terms) and the image
/// quadrature (cylinder: Gauss rules; flat and Hertz: closed forms whose only
/// knob is the window cut).
///
/// # Errors
/// A reference the solver rejects or a quadrature failure (none expected).
pub(super) fn accuracy(extent: Extent) -> Result<Vec<MethodAccuracy>> {
    let refs = references()?;
    // τ/y² below which the series needs too many terms to be of interest
    let min_ratio = if extent == Extent::Full { 1e-4 } else { 1e-2 };
    let series: Vec<_> = refs
        .iter()
        .filter(|(st, c)| c.yield_ratio.is_some() && c.tau_over_y2(st) >= min_ratio)
        .map(|(st, c)| (st, *c))
        .collect();
    // the images' own domain: elastic, or τ/y² below the series' switch
    let images = |cylinder: bool| -> Vec<(&Start, &Reference)> {
        refs.iter()
            .filter(|(st, c)| {
                matches!(st, Start::Cylinder) == cylinder && c.g > 0.0 && c.tau_over_y2(st) < 0.25
            })
            .map(|(st, c)| (st, *c))
            .collect()
    };
    // the Hertz start P0 = 2s as a two-point table: every Hertz reference
    let table = Start::Tabulated(TabulatedStart::new(&[0.0, 1.0], &[0.0, 2.0], 1e-15)?);
    let tabulated: Vec<_> = refs
        .iter()
        .filter(|(st, _)| matches!(st, Start::Hertz))
        .map(|(_, c)| (&table, *c))
        .collect();
    let density = |method: &'static str,
                   title: &str,
                   cases: &[(&Start, &Reference)],
                   how: Method|
     -> Result<MethodAccuracy> {
        let points: usize = cases.iter().map(|(_, c)| c.sigma.len()).sum();
        Ok(MethodAccuracy {
            method,
            title: title.into(),
            knob: Knob::Tolerance,
            reference: format!(
                "{REFERENCE_NAME}: {} cases, {points} values of σ; error absolute in 1/σH, \
                 relative above 1/σH; time per density value, setup included",
                cases.len()
            ),
            rows: tolerances(extent)
                .into_iter()
                .map(|tol| density_row(cases, tol, how))
                .collect::<Result<_>>()?,
        })
    };
    let mut methods = vec![
        density(
            "stress-series",
            "Stress distribution P(σ), sine series, every start with a yield stress",
            &series,
            Method::Series,
        )?,
        density(
            "stress-images-cylinder",
            "Stress distribution P(σ), image sum by Gauss rules, cylinder start",
            &images(true),
            Method::Images,
        )?,
        density(
            "stress-images-closed-form",
            "Stress distribution P(σ), image sum in closed form, flat and Hertz starts",
            &images(false),
            Method::Images,
        )?,
        density(
            "stress-tabulated",
            "Stress distribution P(σ), tabulated start (adaptive Gauss–Kronrod), Hertz's P0 as a table",
            &tabulated,
            Method::Auto,
        )?,
    ];
    let mut terms = vec![1, 2, 3, 4, 6, 8, 12, 16, 24, 32];
    if extent == Extent::Full {
        terms.extend([48, 64, 96, 128, 192, 256]);
    }
    methods.push(MethodAccuracy {
        method: "stress-series-fractions",
        title: "Elastic and plastic fractions A_el/A0, A_pl/A0, sine series".into(),
        knob: Knob::Terms,
        reference: format!(
            "{REFERENCE_NAME}: {} cases; error absolute; time per (A_el, A_pl) pair",
            series.len()
        ),
        rows: terms
            .into_iter()
            .map(|n| fractions_row(&series, n))
            .collect::<Result<_>>()?,
    });
    Ok(methods)
}

/// Largest scaled density error |P − P_ref|/max(1, |P_ref|) over every σ of
/// `cases`, with the solver's bound on the same quantity, and the time per
/// density value (the solver's setup included, shared by one case's σ).
fn density_row(cases: &[(&Start, &Reference)], tol: f64, how: Method) -> Result<AccuracyRow> {
    let points: usize = cases.iter().map(|(_, c)| c.sigma.len()).sum();
    let run = || -> Result<(f64, f64)> {
        let (mut err, mut est): (f64, f64) = (0.0, 0.0);
        for (st, c) in cases {
            let solver = Solver::with_method(st, c.g, c.yield_ratio, tol, how)?;
            for (&s, &want) in c.sigma.iter().zip(&c.density) {
                let got = solver.density(s)?;
                let scale = want.abs().max(1.0);
                err = err.max((got.value - want).abs() / scale);
                est = est.max(got.error / scale);
            }
        }
        Ok((err, est))
    };
    let (r, seconds) = time_it(TIME_BUDGET, run);
    let (error, estimate) = r?;
    Ok(AccuracyRow {
        setting: tol,
        error,
        error_bound: Some(estimate),
        residual: None,
        seconds: seconds / points.max(1) as f64,
    })
}

/// Largest absolute error of A_el and A_pl from `terms` sine terms, with the
/// largest of their bounds, and the time per (A_el, A_pl) pair.
fn fractions_row(cases: &[(&Start, &Reference)], terms: usize) -> Result<AccuracyRow> {
    let run = || -> Result<(f64, f64)> {
        let (mut err, mut est): (f64, f64) = (0.0, 0.0);
        for (st, c) in cases {
            let y = c.yield_ratio.unwrap_or(f64::INFINITY);
            let (el, pl) = series_fractions(st, c.g, y, terms)?;
            err = err
                .max((el.value - c.contact_fraction).abs())
                .max((pl.value - c.plastic_fraction).abs());
            est = est.max(el.error).max(pl.error);
        }
        Ok((err, est))
    };
    let (r, seconds) = time_it(TIME_BUDGET, run);
    let (error, estimate) = r?;
    Ok(AccuracyRow {
        setting: terms as f64,
        error,
        error_bound: Some(estimate),
        residual: None,
        seconds: seconds / cases.len().max(1) as f64,
    })
}

/// G of the stability sweep: 0, 1e-12 … 1e12 and 1e30.
const STABILITY_G: [f64; 14] = [
    0.0, 1e-12, 1e-9, 1e-6, 1e-3, 0.02, 0.1, 1.0, 10.0, 1e3, 1e6, 1e9, 1e12, 1e30,
];
/// σY/σH of the stability sweep (`None`: elastic), from barely above the
/// peak pressure to 1e6.
const STABILITY_Y: [Option<f64>; 8] = [
    None,
    Some(1.000_001),
    Some(1.01),
    Some(1.1),
    Some(2.0),
    Some(10.0),
    Some(1e3),
    Some(1e6),
];
/// Points of each curve.
const STABILITY_POINTS: usize = 101;
/// Tolerance asked of the solver (the CLI's default).
const STABILITY_TOL: f64 = 1e-12;

/// A_el/A0 at σY barely above σH, mpmath at 40 digits with the f64 inputs:
/// A_pl = F(y) = ∫₀¹ P0(1 − v) [erfc((y − 1 + v)/w) − erfc((y + 1 − v)/w)] dv
/// integrated in units of its decay length, A_el = A∞ − F(y), A∞ from the
/// closed forms (cylinder: 1 − ∫ cos θ erfc(cos θ/w) dθ). Hertz's values hold
/// for its table too. (start, G, σY/σH, A_el/A0).
#[allow(clippy::excessive_precision)] // the references keep 17 digits
const EDGE_REFERENCES: [(&str, f64, Option<f64>, f64); 3] = [
    ("cylinder", 1e-12, Some(1.000_001), 0.999_632_593_106_101_3),
    ("hertz", 1e-9, Some(1.000_001), 0.999_954_396_550_963_7),
    ("hertz", 1e-9, None, 0.999_999_999_111_111_1),
];

/// The reference A_el/A0 of a sweep case, where one exists: G = 0 (no
/// roughness, no yield: exactly 1), the mpmath cases of `refs` and
/// [`EDGE_REFERENCES`]. A tabulated start is Hertz's P0 as a table.
fn sweep_reference(
    refs: &[(Start, &Reference)],
    st: &Start,
    g: f64,
    y: Option<f64>,
) -> Option<f64> {
    if g == 0.0 {
        return Some(1.0);
    }
    let name = match st {
        Start::Tabulated(_) => "hertz",
        _ => st.name(),
    };
    refs.iter()
        .find(|(s, c)| s.name() == name && c.g == g && c.yield_ratio == y)
        .map(|(_, c)| c.contact_fraction)
        .or_else(|| {
            EDGE_REFERENCES
                .iter()
                .find(|r| r.0 == name && r.1 == g && r.2 == y)
                .map(|r| r.3)
        })
}

/// Extreme cases of the stress distributions: every start (and a table) × G
/// from 0 to 1e30 × σY/σH from 1 + 1e-6 to 1e6 and elastic, each a 101-point curve with both
/// fractions; `value` is A_el/A0, `error_bound` the curve's bound, and
/// `finite` covers every density, both fractions, A_nc and every bound.
/// References: [`sweep_reference`].
///
/// # Errors
/// An input the library rejects (none of these should be).
pub(super) fn stability() -> Result<Vec<StabilityCase>> {
    let refs = references()?;
    let mut out = Vec::new();
    // a tabulated start too: Hertz's P0 = 2s as a two-point table
    let table = Start::Tabulated(TabulatedStart::new(&[0.0, 1.0], &[0.0, 2.0], 1e-15)?);
    for st in [Start::Flat, Start::Hertz, Start::Cylinder, table] {
        let family = match st {
            Start::Flat => Family::StressFlat,
            Start::Hertz => Family::StressHertz,
            Start::Cylinder => Family::StressCylinder,
            _ => Family::StressTabulated,
        };
        for g in STABILITY_G {
            for y in STABILITY_Y {
                let solver = Solver::new(&st, g, y, STABILITY_TOL)?;
                let c = solver.curve(&solver.grid(STABILITY_POINTS))?;
                let mut others = c.scaled_density.clone();
                others.extend([
                    c.plastic_fraction,
                    c.non_contact_fraction,
                    c.scaled_density_error_bound,
                    c.elastic_fraction_error_bound,
                    c.plastic_fraction_error_bound,
                    c.tau,
                ]);
                let y_name = y.map_or("elastic".to_string(), |v| format!("σY/σH = {}", num(v)));
                out.push(case(
                    family,
                    format!("A_el/A0, {} start, G = {}, {y_name}", st.name(), num(g)),
                    (c.elastic_fraction, c.error_bound),
                    &others,
                    sweep_reference(&refs, &st, g, y),
                ));
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The compiled-in file parses into its 129 cases, each with as many
    /// densities as σ values and a start the solver knows.
    #[test]
    fn reference_file_parses() {
        let refs = references().unwrap();
        assert_eq!(refs.len(), 129);
        for (_, c) in &refs {
            assert_eq!(c.sigma.len(), c.density.len(), "{c:?}");
        }
        assert_eq!(refs[0].1.density[9], 282094.79177387815);
    }
}

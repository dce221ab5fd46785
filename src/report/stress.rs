//! The stress distributions' entries (sine series, image quadrature) and
//! their extreme cases.
//!
//! Every error is measured against the mpmath values of
//! `tests/reference/stress.json` (40 digits, `tests/reference/stress_reference.py`),
//! compiled in so the report needs no files at run time. Densities are
//! compared as in the accuracy policy of [`crate::stress`]: absolute in 1/σH,
//! relative where the density exceeds 1/σH; fractions absolutely.

use serde::Deserialize;

use super::{case, time_it, AccuracyRow, Extent, StabilityCase};
use crate::error::{Error, Result};
use crate::stress::{series_fractions, Method, Solver, Start, TabulatedStart};

/// The mpmath references: three starts × G × σY/σH, densities on a σ grid
/// and both fractions.
const REFERENCES: &str = include_str!("../../tests/reference/stress.json");
/// Where they come from, for the rows' `reference`.
const REFERENCE_NAME: &str = "mpmath, 40 digits (tests/reference/stress.json)";
/// Wall-time budget per row, s (the median of repeated runs is reported).
const TIME_BUDGET: f64 = 0.04;

/// One reference case.
#[derive(Debug, Deserialize)]
struct Reference {
    start: String,
    g: f64,
    yield_ratio: Option<f64>,
    sigma: Vec<f64>,
    density: Vec<f64>,
    contact_fraction: f64,
    plastic_fraction: f64,
}

impl Reference {
    /// τ/y² = (σ0/σH)² G/y², the series' decay scale (0 when elastic).
    fn tau_over_y2(&self, start: &Start) -> f64 {
        let m = start.mean_ratio();
        self.yield_ratio.map_or(0.0, |y| m * m * self.g / (y * y))
    }
}

/// The references with their starts.
///
/// # Errors
/// [`Error::Parse`] if the compiled-in file is malformed (a build defect).
fn references() -> Result<Vec<(Start, Reference)>> {
    let parse = |message: String| Error::Parse {
        path: "tests/reference/stress.json".into(),
        line: 0,
        column: 0,
        message,
    };
    let cases: Vec<Reference> =
        serde_json::from_str(REFERENCES).map_err(|e| parse(e.to_string()))?;
    cases
        .into_iter()
        .map(|c| {
            let st = Start::from_name(&c.start).map_err(|e| parse(e.to_string()))?;
            Ok((st, c))
        })
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
pub(super) fn accuracy(extent: Extent) -> Result<Vec<AccuracyRow>> {
    let refs = references()?;
    // τ/y² below which the series needs too many terms to be of interest
    let min_ratio = if extent == Extent::Full { 1e-4 } else { 1e-2 };
    let series: Vec<_> = refs
        .iter()
        .filter(|(st, c)| c.yield_ratio.is_some() && c.tau_over_y2(st) >= min_ratio)
        .map(|(st, c)| (st, c))
        .collect();
    // the images' own domain: elastic, or τ/y² below the series' switch
    let images = |cylinder: bool| -> Vec<(&Start, &Reference)> {
        refs.iter()
            .filter(|(st, c)| {
                matches!(st, Start::Cylinder) == cylinder && c.g > 0.0 && c.tau_over_y2(st) < 0.25
            })
            .map(|(st, c)| (st, c))
            .collect()
    };
    // the Hertz start P0 = 2s as a two-point table: every Hertz reference
    let table = Start::Tabulated(TabulatedStart::new(&[0.0, 1.0], &[0.0, 2.0], 1e-15)?);
    let tabulated: Vec<_> = refs
        .iter()
        .filter(|(st, _)| matches!(st, Start::Hertz))
        .map(|(_, c)| (&table, c))
        .collect();
    let mut rows = Vec::new();
    for tol in tolerances(extent) {
        rows.push(density_row(
            "stress P(s), sine series (Method::Series), all starts",
            &series,
            tol,
            Method::Series,
        )?);
    }
    for tol in tolerances(extent) {
        rows.push(density_row(
            "stress P(s), image quadrature (Gauss rules), cylinder",
            &images(true),
            tol,
            Method::Images,
        )?);
    }
    for tol in tolerances(extent) {
        rows.push(density_row(
            "stress P(s), closed-form images, flat and Hertz",
            &images(false),
            tol,
            Method::Images,
        )?);
    }
    for tol in tolerances(extent) {
        rows.push(density_row(
            "stress P(s), tabulated start (adaptive Gauss-Kronrod), Hertz as a table",
            &tabulated,
            tol,
            Method::Auto,
        )?);
    }
    let mut terms = vec![1, 2, 3, 4, 6, 8, 12, 16, 24, 32];
    if extent == Extent::Full {
        terms.extend([48, 64, 96, 128, 192, 256]);
    }
    for n in terms {
        rows.push(fractions_row(&series, n)?);
    }
    Ok(rows)
}

/// Largest scaled density error |P − P_ref|/max(1, |P_ref|) over every σ of
/// `cases`, with the solver's bound on the same quantity, and the time per
/// density value (the solver's setup included, shared by one case's σ).
fn density_row(
    method: &str,
    cases: &[(&Start, &Reference)],
    tol: f64,
    how: Method,
) -> Result<AccuracyRow> {
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
        method: method.into(),
        knob: "tolerance (absolute, 1/σH)".into(),
        setting: tol,
        error,
        estimate: Some(estimate),
        seconds: seconds / points.max(1) as f64,
        reference: format!(
            "{REFERENCE_NAME}: {} cases, {points} σ; error absolute in 1/σH, \
             relative above 1/σH; seconds per density value incl. setup",
            cases.len()
        ),
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
        method: "stress A_el/A0 and A_pl/A0, sine series, all starts (absolute error)".into(),
        knob: "terms".into(),
        setting: terms as f64,
        error,
        estimate: Some(estimate),
        seconds: seconds / cases.len().max(1) as f64,
        reference: format!(
            "{REFERENCE_NAME}: {} cases; error absolute; seconds per (A_el, A_pl) pair",
            cases.len()
        ),
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

/// Extreme cases of the stress distributions: every start (and a table) × G
/// from 0 to 1e30 × σY/σH from 1 + 1e-6 to 1e6 and elastic, each a 101-point curve with both
/// fractions; `value` is A_el/A0, `error_bound` the curve's bound, and
/// `finite` covers every density, both fractions, A_nc and every bound.
///
/// # Errors
/// An input the library rejects (none of these should be).
pub(super) fn stability() -> Result<Vec<StabilityCase>> {
    let mut out = Vec::new();
    // a tabulated start too: Hertz's P0 = 2s as a two-point table
    let table = Start::Tabulated(TabulatedStart::new(&[0.0, 1.0], &[0.0, 2.0], 1e-15)?);
    for st in [Start::Flat, Start::Hertz, Start::Cylinder, table] {
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
                let y_name = y.map_or("elastic".to_string(), |v| format!("σY/σH = {v:e}"));
                out.push(case(
                    format!("stress {}, G = {g:e}, {y_name}: A_el/A0", st.name()),
                    c.elastic_fraction,
                    c.error_bound,
                    &others,
                ));
            }
        }
    }
    Ok(out)
}

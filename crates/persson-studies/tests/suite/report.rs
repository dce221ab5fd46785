//! The report's own numbers are checked against references: every method
//! of the accuracy report meets its tolerance and its own error bound at
//! every setting and a stated bound at its default, the BEM rows reproduce
//! the reference solutions, and every case of the stability sweep with a
//! reference value lies within its error bound.

use persson_studies::report::{accuracy, stability, AccuracyReport, Family, Knob, MethodAccuracy};

/// Rounding floor of the stress errors: the densities' relative rounding is a
/// few 1e-15 (`persson::stress`, # Accuracy; 7.4e-15 measured for the
/// cylinder's Gauss rules at tolerance 1e-14), so below it the error may
/// wander as the knob moves.
const FLOOR: f64 = 1e-14;
/// The references' own error: 40 digits rounded to f64, at most half an ulp of
/// a value ≤ 1 or, for the scaled density error, half an ulp relative; the
/// G reference is the f64 closed form, a few ulps.
const REF_ROUNDING: f64 = 1.2e-16;
/// The closed form G is itself evaluated in f64: a few ulps relative.
const G_REF_ROUNDING: f64 = 1e-15;
/// The loosest setting must be this much worse than the tightest: the knob
/// has to matter (else the monotonicity check could not fail).
const KNOB_EFFECT: f64 = 1e3;
/// The CLI's default tolerance (`--tolerance`) of G and the stress solver.
const DEFAULT_TOLERANCE: f64 = 1e-12;
/// G(ζ): the crate's accuracy claim, 1e-13 relative (README, Accuracy).
const G_CLAIM: f64 = 1e-13;
/// Both fractions from 32 sine terms: the issue-3 goal, 1e-13 absolute.
const FRACTIONS_CLAIM: f64 = 1e-13;
/// Periodic Hertz η of the reference discrete solution (Tamaas 2.9
/// PolonskyKeerRey, same grid, load and kernel; tests/bem.rs), and the
/// agreement required: both solves stop at ε ≤ 1e-12.
#[cfg(feature = "bem")]
const PERIODIC_REFERENCE: [(usize, f64); 2] = [(128, 3.099e-3), (256, 1.443e-3)];
#[cfg(feature = "bem")]
const PERIODIC_REL_TOL: f64 = 1e-3;
/// Free Hertz η at 256² (tests/bem.rs): 1.035e-3 measured with the Love cell
/// kernel; a regression of the discretisation exceeds it.
#[cfg(feature = "bem")]
const FREE_256_BOUND: f64 = 1.05e-3;
/// Rough A/A0 at 128² against 256²: the discretisation error falls about as
/// 1/N (0.203, 0.062, 0.022 measured at 32², 64², 128²); 0.03 at 128².
#[cfg(feature = "bem")]
const ROUGH_128_BOUND: f64 = 0.03;
/// Stability cases that must have a reference (9 + 36 core, 137 stress).
const MIN_REFERENCED_CASES: usize = 150;

fn method<'a>(r: &'a AccuracyReport, name: &str) -> &'a MethodAccuracy {
    r.methods
        .iter()
        .find(|m| m.method == name)
        .unwrap_or_else(|| panic!("no method {name}"))
}

/// The row of `m` at `setting`.
fn at(m: &MethodAccuracy, setting: f64) -> f64 {
    m.rows
        .iter()
        .find(|r| r.setting == setting)
        .unwrap_or_else(|| panic!("{}: no row at {setting}", m.method))
        .error
}

#[test]
fn accuracy_report_meets_its_tolerances_bounds_and_references() {
    let report = accuracy(persson_studies::report::Extent::Default).unwrap();
    // Every tolerance knob: the tolerance is met (down to the rounding
    // floor), the error stays within the method's own bound, the error does
    // not grow as the knob tightens, and the knob matters.
    for m in &report.methods {
        assert!(m.rows.len() >= 3, "{}: {} rows", m.method, m.rows.len());
        let reference_rounding = if m.method == "g-quadrature" {
            G_REF_ROUNDING
        } else {
            REF_ROUNDING
        };
        let floor = FLOOR;
        for r in &m.rows {
            if let Some(bound) = r.error_bound {
                assert!(
                    r.error <= bound + reference_rounding,
                    "{} at {}: error {:e} above its bound {bound:e}",
                    m.method,
                    r.setting,
                    r.error
                );
            }
            if m.knob == Knob::Tolerance {
                assert!(
                    r.error <= r.setting.max(floor),
                    "{} at {:e}: error {:e} misses the tolerance",
                    m.method,
                    r.setting,
                    r.error
                );
            }
        }
        if m.method.starts_with("stress") {
            for w in m.rows.windows(2) {
                assert!(
                    w[1].error <= w[0].error.max(floor),
                    "{}: error {:e} at {} above {:e} at {}",
                    m.method,
                    w[1].error,
                    w[1].setting,
                    w[0].error,
                    w[0].setting
                );
            }
            let (first, last) = (&m.rows[0], &m.rows[m.rows.len() - 1]);
            assert!(
                first.error >= KNOB_EFFECT * last.error.max(f64::MIN_POSITIVE),
                "{}: the knob barely matters ({:e} … {:e})",
                m.method,
                first.error,
                last.error
            );
        }
    }
    // Each method at its default setting, against its stated claim.
    assert!(at(method(&report, "g-quadrature"), DEFAULT_TOLERANCE) < G_CLAIM);
    for name in [
        "stress-series",
        "stress-images-cylinder",
        "stress-images-closed-form",
        "stress-tabulated",
    ] {
        let e = at(method(&report, name), DEFAULT_TOLERANCE);
        assert!(e <= DEFAULT_TOLERANCE, "{name}: {e:e}");
    }
    let e = at(method(&report, "stress-series-fractions"), 32.0);
    assert!(e <= FRACTIONS_CLAIM, "fractions at 32 terms: {e:e}");
    #[cfg(feature = "bem")]
    {
        let periodic = method(&report, "bem-hertz-periodic");
        for (n, want) in PERIODIC_REFERENCE {
            let got = at(periodic, n as f64);
            assert!(
                (got / want - 1.0).abs() < PERIODIC_REL_TOL,
                "periodic η at {n}²: {got:e} vs Tamaas {want:e}"
            );
        }
        let free = at(method(&report, "bem-hertz-free"), 256.0);
        assert!(free < FREE_256_BOUND, "free η at 256²: {free:e}");
        let rough = method(&report, "bem-rough-grid");
        assert!(at(rough, 128.0) < ROUGH_128_BOUND);
        for w in rough.rows.windows(2) {
            assert!(w[1].error < w[0].error, "rough A/A0 error grows with N");
        }
        // The surrogates: K = 2 … 16, the standard error of their mean
        // falls with K (as 1/√K, up to the scatter of sd), the time grows.
        for name in ["surrogates-64", "surrogates-128"] {
            let m = method(&report, name);
            let k: Vec<f64> = m.rows.iter().map(|r| r.setting).collect();
            assert_eq!(k, [2.0, 4.0, 8.0, 16.0], "{name}");
            let (first, last) = (&m.rows[0], &m.rows[3]);
            assert!(last.error < first.error && last.error > 0.0, "{name}");
            assert!(last.seconds > first.seconds, "{name}");
        }
        // The solver's tolerance: the pressure's energy-norm error is below
        // the tolerance asked (the residual ε it stops at bounds it here).
        for r in &method(&report, "bem-tolerance").rows {
            assert!(
                r.error <= r.setting,
                "BEM at {:e}: {:e}",
                r.setting,
                r.error
            );
        }
    }
}

/// The stress references of the sweep come from the mpmath file the stress
/// tests read, `tests/reference/stress.json`, read here on its own.
fn stress_json_fractions() -> Vec<f64> {
    let text = include_str!("../../../../tests/reference/stress.json");
    let cases: serde_json::Value = serde_json::from_str(text).unwrap();
    cases
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["contact_fraction"].as_f64().unwrap())
        .collect()
}

/// A_el/A0 at σY barely above σH (mpmath at 40 digits; `tests/stress_edge.rs`,
/// EDGE_CASES): cylinder at G = 1e-12, Hertz (and its table) at G = 1e-9, and
/// Hertz elastic at G = 1e-9, the three edge references of the sweep.
#[allow(clippy::excessive_precision)]
const EDGE_FRACTIONS: [f64; 3] = [
    0.999_632_593_106_101_3,
    0.999_954_396_550_963_7,
    0.999_999_999_111_111_1,
];

/// The rounding allowed between a value and its reference beyond the value's
/// error bound: half an ulp of the reference (it is rounded to f64).
const REFERENCE_ULP: f64 = 0.5 * f64::EPSILON;

/// erf from libm as the independent A/A0 = erf(1/(2√G)) of the contact-fraction
/// family: 2e-16 relative (docs/design-notes.md, special), rounding of 1/(2√G) included.
const ERF_ORACLE_REL: f64 = 1e-15;

/// The sweep graded by this test, not by the report: every value and bound
/// finite; every reference checked against a source this test reads on its
/// own (libm's erf for A/A0 = erf(1/(2√G)), the mpmath file of the stress
/// tests, the mpmath edge values, exactly 1 at G = 0); and every value within
/// its bound of its reference, the error computed here.
#[test]
fn stability_sweep_is_finite_and_within_its_bounds() {
    let report = stability().unwrap();
    let stress = stress_json_fractions();
    let mut referenced = 0;
    for c in &report.cases {
        assert!(c.finite, "{}: a non-finite output", c.case);
        assert!(
            c.value.is_finite() && c.error_bound.is_finite() && c.error_bound >= 0.0,
            "{}: value {} ± {}",
            c.case,
            c.value,
            c.error_bound
        );
        let Some(r) = c.reference else { continue };
        referenced += 1;
        match c.family {
            Family::ContactFraction => {
                let g: f64 = c.case.rsplit("G = ").next().unwrap().parse().unwrap();
                let want = libm::erf(1.0 / (2.0 * g.sqrt()));
                assert!(
                    (r - want).abs() <= ERF_ORACLE_REL * want,
                    "{}: reference {r} against erf {want}",
                    c.case
                );
            }
            Family::StressFlat
            | Family::StressHertz
            | Family::StressCylinder
            | Family::StressTabulated => assert!(
                r == 1.0 || stress.contains(&r) || EDGE_FRACTIONS.contains(&r),
                "{}: reference {r} is in no mpmath file",
                c.case
            ),
            // the self-affine spectra: mpmath in the report's own table
            // (tests/reference/stability.py), graded below like the others
            _ => {}
        }
        let error = (c.value - r).abs();
        assert!(
            error <= c.error_bound + REFERENCE_ULP * r.abs(),
            "{}: |{} − {r}| = {error:e} above its bound {:e}",
            c.case,
            c.value,
            c.error_bound
        );
        // the report's own verdict agrees
        assert_eq!(c.bound_held, Some(true), "{}", c.case);
    }
    assert!(
        referenced >= MIN_REFERENCED_CASES,
        "only {referenced} cases with a reference"
    );
    // every family is there, with references, and the summary adds up
    for family in Family::ALL {
        let s = report
            .families
            .iter()
            .find(|s| s.family == family)
            .unwrap_or_else(|| panic!("no family {family:?}"));
        let of = report.cases.iter().filter(|c| c.family == family).count();
        assert_eq!(s.cases, of, "{family:?}");
        assert!(s.cases_with_reference > 0 && s.bounds_held, "{family:?}");
    }
    // the extremes are covered
    for want in [
        "G = 1e30",
        "G = 1e-12",
        "σY/σH = 1.000001",
        "σY/σH = 1e6",
        "ζ = 1.000000000001",
    ] {
        assert!(
            report.cases.iter().any(|c| c.case.contains(want)),
            "no case with {want}"
        );
    }
}

/// The accuracy report measures what it says: its error of the sine-series
/// fractions at 32 terms is the largest error this test finds itself, with
/// the library against the mpmath file read here on its own.
#[test]
fn accuracy_report_errors_are_measured_against_the_mpmath_file() {
    use persson::stress::{series_fractions, Start};
    let report = accuracy(persson_studies::report::Extent::Default).unwrap();
    let text = include_str!("../../../../tests/reference/stress.json");
    let cases: serde_json::Value = serde_json::from_str(text).unwrap();
    let mut worst: f64 = 0.0;
    for c in cases.as_array().unwrap() {
        let Some(y) = c["yield_ratio"].as_f64() else {
            continue;
        };
        let start = Start::from_name(c["start"].as_str().unwrap()).unwrap();
        let g = c["g"].as_f64().unwrap();
        // the series' domain in the report: τ/y² ≥ 1e-2
        let m = start.mean_ratio();
        if m * m * g / (y * y) < 1e-2 {
            continue;
        }
        let (el, pl) = series_fractions(&start, g, y, 32).unwrap();
        worst = worst
            .max((el.value - c["contact_fraction"].as_f64().unwrap()).abs())
            .max((pl.value - c["plastic_fraction"].as_f64().unwrap()).abs());
    }
    let reported = at(method(&report, "stress-series-fractions"), 32.0);
    assert_eq!(reported, worst);
    assert!(worst <= FRACTIONS_CLAIM, "{worst:e}");
}

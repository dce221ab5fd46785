//! `persson compare --work-of-adhesion` (issue 24): Persson's adhesive theory
//! against the adhesive BEM along a mean-gap path, on the sweep's surfaces.
//! Checked: Δγ → 0 gives the non-adhesive theory (`persson area`) at the
//! BEM's loads; the theory's pull-off is `persson adhesion`'s; the default
//! range is h'_rms L/N; the BEM path reaches tension and lets go; bad flags.
#![cfg(feature = "bem")]

use crate::common;

use common::{json, persson};
use serde_json::Value;

/// A self-affine surface, L = 1, E* = 1, on 32² and 64² (q_s clipped to 8 q_l).
const SWEEP: &[&str] = &[
    "compare",
    "--hurst",
    "0.8",
    "--q-l",
    "6.283",
    "--q-s",
    "201",
    "--rms-slope",
    "0.1",
    "--contact-modulus",
    "1",
    "--size",
    "1",
    "--grid",
    "64",
    "--levels",
    "2",
];

fn run(extra: &[&str]) -> Value {
    let args: Vec<&str> = SWEEP.iter().chain(extra).copied().collect();
    json(&args)
}

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number `{key}` in {v}"))
}

/// The compared (clipped) spectrum's flags for `persson area` / `persson
/// adhesion`: the same C(q) over the band the sweep resolves.
fn theory_flags(r: &Value) -> Vec<String> {
    let s = &r["spectrum"];
    ["--hurst", "0.8", "--q-l", "6.283", "--contact-modulus", "1"]
        .iter()
        .map(|s| s.to_string())
        .chain([
            "--q-s".into(),
            format!("{:e}", f(s, "q_s")),
            "--rms-slope".into(),
            format!("{:e}", f(s, "rms_slope")),
        ])
        .collect()
}

/// Δγ → 0: at every compressive point of the path the theory's A/A0 is
/// Persson's non-adhesive A/A0 (`persson area`, an independent route:
/// erf(1/(2√G)) against the diffusion with the detachment boundary), and
/// the default range is h'_rms L/N of the compared band.
#[test]
fn vanishing_adhesion_is_the_non_adhesive_theory() {
    let r = run(&["--work-of-adhesion", "1e-12", "--json"]);
    let a = &r["adhesion"];
    assert_eq!(a["grids"], serde_json::json!([32, 64]));
    let w = &a["per_work"][0];
    let slope = f(&r["spectrum"], "rms_slope");
    let spacing = f(&r, "size") / 64.0;
    assert!((f(w, "adhesion_range") / (slope * spacing) - 1.0).abs() < 1e-12);
    assert_eq!(f(w, "theory_pull_off_stress"), 0.0);
    let points: Vec<&Value> = w["points"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| f(p, "nominal_pressure") > 1e-4)
        .collect();
    assert!(points.len() >= 5, "{}", points.len());
    let pressures: Vec<String> = points
        .iter()
        .map(|p| format!("{:e}", f(p, "nominal_pressure")))
        .collect();
    let mut args = vec!["area".to_string()];
    args.extend(theory_flags(&r));
    args.extend(["--pressure".into(), pressures.join(","), "--json".into()]);
    let area = json(&args.iter().map(String::as_str).collect::<Vec<_>>());
    for (p, q) in points.iter().zip(area["points"].as_array().unwrap()) {
        let (adhesive, plain) = (f(p, "theory_contact_fraction"), f(q, "contact_fraction"));
        assert!(
            (adhesive - plain).abs() < 1e-5,
            "{adhesive} against {plain}"
        );
    }
}

/// A sticky Δγ: the theory's pull-off is `persson adhesion`'s, the BEM pulls
/// (tension on the way out, then it lets go: the last point is detached),
/// and the ratio is theory/BEM.
#[test]
fn sticky_comparison_reports_both_pull_offs() {
    let r = run(&["--work-of-adhesion", "3e-4", "--json"]);
    let w = &r["adhesion"]["per_work"][0];
    let mut args = vec!["adhesion".to_string()];
    args.extend(theory_flags(&r));
    args.extend(
        ["--work-of-adhesion", "3e-4", "--pressure", "0", "--json"]
            .iter()
            .map(|s| s.to_string()),
    );
    let theory = json(&args.iter().map(String::as_str).collect::<Vec<_>>());
    let sigma_p = f(&theory, "pull_off_stress");
    assert!(sigma_p > 0.0);
    assert!((f(w, "theory_pull_off_stress") / sigma_p - 1.0).abs() < 1e-12);
    let pull = f(w, "bem_pull_off_stress");
    assert!(pull > 0.0);
    assert!((f(w, "pull_off_ratio") - sigma_p / pull).abs() < 1e-12 * sigma_p / pull);
    let points = w["points"].as_array().unwrap();
    let min = points
        .iter()
        .map(|p| f(p, "nominal_pressure"))
        .fold(f64::INFINITY, f64::min);
    assert!(
        (min + pull).abs() < 1e-15 + 1e-12 * pull,
        "{min} against {pull}"
    );
    let last = points.last().unwrap();
    assert_eq!(f(last, "bem_contact_fraction"), 0.0);
    for p in points {
        let a = f(p, "bem_contact_fraction");
        assert!((0.0..=1.0).contains(&a));
    }
}

/// Bad input names the flag and never panics.
#[test]
fn bad_adhesion_comparison_names_the_flag() {
    let cases: &[(&[&str], &str)] = &[
        (&["--work-of-adhesion", "-1e-4"], "--work-of-adhesion"),
        (
            &["--work-of-adhesion", "1e-4", "--adhesion-range", "0"],
            "--adhesion-range",
        ),
        (&["--adhesion-range", "1e-3"], "--adhesion-range"),
        (
            &["--work-of-adhesion", "1e-4", "--yield-stress", "1"],
            "--work-of-adhesion",
        ),
    ];
    for (extra, flag) in cases {
        let args: Vec<&str> = SWEEP.iter().chain(extra.iter()).copied().collect();
        let (code, _, err) = persson(&args);
        assert_ne!(code, 0, "{extra:?}: {err}");
        assert!(err.contains(flag), "{extra:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

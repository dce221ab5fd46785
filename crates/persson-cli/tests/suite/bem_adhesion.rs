//! `bem rough --work-of-adhesion`: the adhesive BEM along a mean-gap path
//! (issue 24), checked against the non-adhesive `bem rough` (Δγ → 0), the
//! path's own identities (pull-off = −min p̄, the fractions in [0, 1]) and its
//! bad input.
#![cfg(feature = "bem")]

use crate::common;

use common::{json, persson};
use serde_json::Value;

/// A 64² self-affine surface, L = 1, E* = 1 (heights of order 1e-2).
const SURFACE: &[&str] = &[
    "bem",
    "rough",
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
];

fn run(extra: &[&str]) -> Value {
    let args: Vec<&str> = SURFACE.iter().chain(extra).copied().collect();
    json(&args)
}

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number `{key}` in {v}"))
}

/// Δγ → 0 is the non-adhesive contact: at the adhesive solve's mean gap and
/// the pressure it carries, `bem rough` finds the same contact nodes and the
/// same mean separation.
#[test]
fn vanishing_adhesion_is_the_non_adhesive_contact() {
    let a = run(&[
        "--work-of-adhesion",
        "1e-14",
        "--adhesion-range",
        "0.02",
        "--mean-gap",
        "4e-3",
        "--json",
    ]);
    let p = &a["points"][0];
    let (pressure, fraction) = (f(p, "nominal_pressure"), f(p, "contact_fraction"));
    assert!(pressure > 0.0, "{p}");
    let b = run(&["--pressure", &format!("{pressure:e}"), "--json"]);
    let q = &b["points"][0];
    assert_eq!(f(q, "contact_fraction"), fraction, "{q}");
    assert!(
        (f(q, "mean_separation") - 4e-3).abs() < 1e-9,
        "ū = {} against ḡ = 4e-3",
        f(q, "mean_separation")
    );
}

/// A sticky path in and out: tension on the way out, the pull-off is the
/// largest tension, the fractions add up to at most 1, every solve converged
/// and the Maugis–Dugdale cohesive stress Δγ/ρ bounds the tension.
#[test]
fn sticky_path_reaches_tension_and_reports_pull_off() {
    let a = run(&[
        "--work-of-adhesion",
        "2e-4",
        "--adhesion-range",
        "0.02",
        "--mean-gap",
        "4e-3,2e-3,4e-3,8e-3,1.6e-2",
        "--json",
    ]);
    let points = a["points"].as_array().expect("points");
    assert_eq!(points.len(), 5);
    let min_p = points
        .iter()
        .map(|p| f(p, "nominal_pressure"))
        .fold(f64::INFINITY, f64::min);
    assert!(min_p < 0.0, "no tension on the path: {a}");
    assert_eq!(f(&a, "pull_off_stress"), -min_p);
    for p in points {
        let (c, z) = (f(p, "contact_fraction"), f(p, "cohesive_fraction"));
        assert!((0.0..=1.0).contains(&c) && (0.0..=1.0).contains(&z) && c + z <= 1.0);
        assert_eq!(p["converged"], Value::Bool(true), "{p}");
    }
    // The cohesive stress Δγ/ρ bounds every tension (Maugis–Dugdale).
    assert!(-min_p <= f(&a, "cohesive_stress") * (1.0 + 1e-12));
    assert_eq!(a["warnings"].as_array().map(Vec::len), Some(0), "{a}");
}

/// `--boundary free --approach`: with Δγ → 0 the free adhesive solve at the
/// approach δ that `bem rough --boundary free --pressure σ0` reports carries
/// that σ0 on the same contact nodes with the same mean separation (two
/// solvers, load against approach control, the same tolerance).
#[test]
fn free_boundary_under_approach_control_is_the_non_adhesive_contact() {
    let free = ["--boundary", "free"];
    let b = run(&[&free[..], &["--pressure", "0.01", "--json"]].concat());
    let q = &b["points"][0];
    let delta = f(q, "approach");
    let a = run(&[
        &free[..],
        &[
            "--work-of-adhesion",
            "1e-14",
            "--adhesion-range",
            "0.02",
            "--approach",
            &format!("{delta:e}"),
            "--json",
        ],
    ]
    .concat());
    assert_eq!(a["boundary"], "free");
    let p = &a["points"][0];
    assert!(
        (f(p, "nominal_pressure") / 0.01 - 1.0).abs() < 1e-8,
        "p̄ = {} against σ0 = 0.01",
        f(p, "nominal_pressure")
    );
    assert_eq!(f(p, "contact_fraction"), f(q, "contact_fraction"));
    assert!((f(p, "mean_separation") / f(q, "mean_separation") - 1.0).abs() < 1e-8);
    assert_eq!(f(p, "approach"), delta);
}

/// Periodic, `--approach δ` is `--mean-gap ḡ` with ḡ = max h − mean h − δ:
/// the same solve.
#[test]
fn periodic_approach_is_the_mean_gap_path() {
    let law = ["--work-of-adhesion", "2e-4", "--adhesion-range", "0.02"];
    let g = run(&[&law[..], &["--mean-gap", "4e-3,2e-3", "--json"]].concat());
    let deltas: Vec<String> = (0..2)
        .map(|k| format!("{:e}", f(&g["points"][k], "approach")))
        .collect();
    let d = run(&[&law[..], &["--approach", &deltas.join(","), "--json"]].concat());
    for k in 0..2 {
        let (a, b) = (&g["points"][k], &d["points"][k]);
        assert!((f(b, "mean_separation") - f(a, "mean_separation")).abs() < 1e-15);
        assert!((f(b, "nominal_pressure") / f(a, "nominal_pressure") - 1.0).abs() < 1e-9);
        assert_eq!(f(b, "contact_fraction"), f(a, "contact_fraction"));
    }
    assert_eq!(d["pull_off_stress"], g["pull_off_stress"]);
}

/// A range below the grid spacing L/N is warned of, by kind.
#[test]
fn unresolved_cohesive_zone_is_warned_of() {
    let a = run(&[
        "--work-of-adhesion",
        "2e-5",
        "--adhesion-range",
        "1e-3",
        "--adhesion",
        "exponential",
        "--mean-gap",
        "4e-3",
        "--json",
    ]);
    let kinds: Vec<&str> = a["warnings"]
        .as_array()
        .expect("warnings")
        .iter()
        .filter_map(|w| w["kind"].as_str())
        .collect();
    assert!(kinds.contains(&"cohesive_zone_unresolved"), "{kinds:?}");
    assert_eq!(a["adhesion"], "exponential");
}

/// A range above the grid spacing (1/64) is not enough: the cohesive length
/// E*ρ²/Δγ must span 8 spacings (0.125 here). ρ = 0.02 with Δγ = 1e-4 gives
/// ℓ = 4 (resolved, no warning); with Δγ = 4e-3, ℓ = 0.1 (warned, the length
/// reported).
#[test]
fn short_cohesive_length_is_warned_of() {
    let warnings = |dg: &str| -> Vec<Value> {
        let a = run(&[
            "--work-of-adhesion",
            dg,
            "--adhesion-range",
            "0.02",
            "--mean-gap",
            "4e-3",
            "--json",
        ]);
        a["warnings"].as_array().expect("warnings").clone()
    };
    let unresolved = |w: &Vec<Value>| -> Vec<Value> {
        w.iter()
            .filter(|w| w["kind"] == "cohesive_zone_unresolved")
            .cloned()
            .collect()
    };
    assert!(unresolved(&warnings("1e-4")).is_empty());
    let w = unresolved(&warnings("4e-3"));
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        (f(&w[0], "cohesive_length") / 0.1 - 1.0).abs() < 1e-12,
        "{w:?}"
    );
    assert!(
        (f(&w[0], "grid_spacing") - 1.0 / 64.0).abs() < 1e-15,
        "{w:?}"
    );
    let message = w[0]["message"].as_str().expect("message");
    assert!(message.contains("cohesive length"), "{message}");
}

/// `--adhesive-iteration preconditioned` on a Maugis–Dugdale path whose
/// cohesive zone the grid resolves (ℓ = E*ρ²/Δγ = 2 = 128 spacings): the
/// default (plain) iteration's answer (measured: p̄ within 2e-11 relative,
/// the same contact nodes) in fewer iterations (measured 66 against 251).
#[test]
fn preconditioned_iteration_is_the_plain_answer_where_the_zone_is_resolved() {
    let path = |iteration: &str| {
        run(&[
            "--work-of-adhesion",
            "2e-4",
            "--adhesion-range",
            "0.02",
            "--mean-gap",
            "4e-3,2e-3,8e-3",
            "--adhesive-iteration",
            iteration,
            "--json",
        ])
    };
    let (plain, pre) = (path("auto"), path("preconditioned"));
    let points = |r: &Value| r["points"].as_array().expect("points").clone();
    let iterations = |r: &Value| -> f64 { points(r).iter().map(|p| f(p, "iterations")).sum() };
    for (a, b) in points(&plain).iter().zip(&points(&pre)) {
        let (pa, pb) = (f(a, "nominal_pressure"), f(b, "nominal_pressure"));
        assert!((pa - pb).abs() <= 1e-8 * pa.abs(), "{a} {b}");
        assert_eq!(a["contact_fraction"], b["contact_fraction"]);
    }
    assert!(2.0 * iterations(&pre) < iterations(&plain));
}

/// Bad input names its flag and never panics.
#[test]
fn bad_adhesion_input_names_the_flag() {
    let cases: &[(&[&str], &str)] = &[
        (
            &[
                "--work-of-adhesion",
                "-1",
                "--adhesion-range",
                "0.02",
                "--mean-gap",
                "1e-3",
            ],
            "--work-of-adhesion",
        ),
        (
            &[
                "--work-of-adhesion",
                "1e-4",
                "--adhesion-range",
                "0",
                "--mean-gap",
                "1e-3",
            ],
            "--adhesion-range",
        ),
        (
            &[
                "--work-of-adhesion",
                "1e-4",
                "--adhesion-range",
                "0.02",
                "--mean-gap",
                "-1e-3",
            ],
            "--mean-gap",
        ),
        (
            &["--work-of-adhesion", "1e-4", "--mean-gap", "1e-3"],
            "--adhesion-range",
        ),
        (
            &["--work-of-adhesion", "1e-4", "--adhesion-range", "0.02"],
            "--mean-gap",
        ),
        (
            &[
                "--work-of-adhesion",
                "1e-4",
                "--adhesion-range",
                "0.02",
                "--mean-gap",
                "1e-3",
                "--patches",
            ],
            "--patches",
        ),
        (
            &[
                "--work-of-adhesion",
                "1e-4",
                "--adhesion-range",
                "0.02",
                "--mean-gap",
                "1e-3",
                "--boundary",
                "free",
            ],
            "--boundary",
        ),
        (
            &[
                "--work-of-adhesion",
                "1e-4",
                "--adhesion-range",
                "0.02",
                "--approach",
                "1",
            ],
            "--approach",
        ),
        (
            &[
                "--work-of-adhesion",
                "1e-4",
                "--adhesion-range",
                "0.02",
                "--approach",
                "1e-3",
                "--mean-gap",
                "1e-3",
            ],
            "--approach",
        ),
    ];
    for (extra, flag) in cases {
        let args: Vec<&str> = SURFACE.iter().chain(extra.iter()).copied().collect();
        let (code, _, err) = persson(&args);
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert!(err.contains(flag), "{extra:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

/// `bem hertz --work-of-adhesion` against Maugis's (1992) exact pull-off at
/// λ = 1 (Δγ = 1e-3, ρ = 0.01127, R = L = E* = 1): the oracle is Maugis's
/// 1.600735 πRΔγ (40-digit reference, `tests/reference/maugis_dugdale_mpmath.py`),
/// and the BEM approaches it from above as the grid refines (measured
/// F/F_MD − 1 = +0.054 at 64², +0.030 at 128², +0.013 at 256²).
#[test]
fn adhesive_sphere_approaches_maugis_dugdale() {
    let r = json(&[
        "bem",
        "hertz",
        "--grid",
        "64,128",
        "--boundary",
        "periodic",
        "--work-of-adhesion",
        "1e-3",
        "--adhesion-range",
        "0.01127",
        "--json",
    ]);
    let lambda = f(&r, "maugis_parameter");
    assert!((lambda - 1.0).abs() < 1e-3, "λ = {lambda}");
    let exact = f(&r, "maugis_dugdale_pull_off_force") / (std::f64::consts::PI * 1e-3);
    // Maugis's pull-off at this λ (1.00022): 1.600735 at λ = 1, dF/dλ ≈ −0.1.
    assert!((exact - 1.6007).abs() < 2e-4, "F_MD/(πRΔγ) = {exact}");
    let d: Vec<f64> = (0..2)
        .map(|k| f(&r["per_grid"][k], "maugis_dugdale_difference"))
        .collect();
    assert!(d[0] > d[1] && d[1] > 0.0, "{d:?}");
    assert!(d[1] < 0.04, "{d:?}");
}

/// `bem hertz --work-of-adhesion`: at a small Maugis parameter (λ ≈ 0.05,
/// ρ = 0.05 L resolved by 3 grid spacings at 64²) the sphere's pull-off
/// approaches DMT's 2πRΔγ from below as the grid is refined (measured
/// 1.9646 at 32², 1.9770 at 64²); JKR's and DMT's forces and λ are the
/// closed forms.
#[test]
fn adhesive_sphere_tends_to_dmt_at_small_maugis_parameter() {
    let r = json(&[
        "bem",
        "hertz",
        "--grid",
        "32,64",
        "--boundary",
        "periodic",
        "--work-of-adhesion",
        "1e-4",
        "--adhesion-range",
        "0.05",
        "--json",
    ]);
    let pi = std::f64::consts::PI;
    assert!((f(&r, "jkr_pull_off_force") - 1.5 * pi * 1e-4).abs() < 1e-18);
    assert!((f(&r, "dmt_pull_off_force") - 2.0 * pi * 1e-4).abs() < 1e-18);
    let lambda = 1e-4 / 0.05 * (9.0 / (2.0 * pi * 1e-4)).cbrt();
    assert!((f(&r, "maugis_parameter") - lambda).abs() < 1e-14 * lambda);
    let grids = r["per_grid"].as_array().expect("per_grid");
    let ratio: Vec<f64> = grids
        .iter()
        .map(|g| f(g, "reduced_pull_off_force"))
        .collect();
    assert!(ratio[0] < ratio[1] && ratio[1] < 2.0, "{ratio:?}");
    assert!(2.0 - ratio[1] < 0.03, "{ratio:?}");
    assert_eq!(r["warnings"].as_array().map(Vec::len), Some(0), "{r}");
}

#[test]
fn adhesive_sphere_bad_input_names_the_flag() {
    for (extra, flag) in [
        (&["--adhesion-range", "0.05"][..], "--boundary"),
        (
            &["--adhesion-range", "-1", "--boundary", "periodic"][..],
            "--adhesion-range",
        ),
        (&["--boundary", "periodic"][..], "--adhesion-range"),
    ] {
        let mut args = vec!["bem", "hertz", "--grid", "16", "--work-of-adhesion", "1e-4"];
        args.extend_from_slice(extra);
        let (code, _, err) = persson(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
    }
}

/// The scene output `bem_adhesion` is `bem rough --work-of-adhesion --json`
/// to the last digit (the surface synthesised at the scene's side 2π/q_l);
/// a mean-gap path on the free boundary is an error naming the field.
#[test]
fn scene_output_equals_the_command_line() {
    let dir = std::env::temp_dir().join(format!("persson-bem-adhesion-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = |output: &str| {
        format!(
            r#"{{"schema": 1, "material": {{"contact_modulus": 1}},
                "spectrum": {{"kind": "self_affine", "hurst": 0.8, "q_l": 6.283, "q_r": 6.283,
                              "q_s": 201, "rms_slope": 0.1}},
                "outputs": {{"bem_adhesion": {output}}}}}"#
        )
    };
    let path = dir.join("s.json");
    std::fs::write(
        &path,
        scene(
            r#"{"grid": 64, "work_of_adhesion": 2e-4, "adhesion_range": 0.02,
                "adhesion": "exponential", "mean_gap": [4e-3, 2e-3, 8e-3]}"#,
        ),
    )
    .unwrap();
    let s = json(&["run", path.to_str().unwrap(), "--json"]);
    let mut cli = json(&[
        "bem",
        "rough",
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
        "--grid",
        "64",
        "--work-of-adhesion",
        "2e-4",
        "--adhesion-range",
        "0.02",
        "--adhesion",
        "exponential",
        "--mean-gap",
        "4e-3,2e-3,8e-3",
        "--json",
    ]);
    assert_eq!(cli["warnings"], s["warnings"]);
    cli.as_object_mut().unwrap().remove("warnings");
    assert_eq!(cli, s["bem_adhesion"]);
    std::fs::write(
        &path,
        scene(
            r#"{"grid": 32, "boundary": "free", "work_of_adhesion": 2e-4,
                "adhesion_range": 0.02, "mean_gap": [4e-3]}"#,
        ),
    )
    .unwrap();
    let (code, _, err) = persson(&["run", path.to_str().unwrap()]);
    assert_ne!(code, 0);
    assert!(err.contains("outputs.bem_adhesion.mean_gap"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

//! The command-line interface: outputs parse, fields are named, bad input
//! exits 2 with a one-line message and never panics.

use crate::common;
use common::{json, persson};

#[test]
fn area_json_interface() {
    let v = json(&[
        "area",
        "--hurst",
        "0.8",
        "--q-l",
        "1e4",
        "--q-r",
        "1e5",
        "--q-s",
        "1e9",
        "--rms-slope",
        "1",
        "--contact-modulus",
        "1",
        "--pressure",
        "1e-3",
        "--pressure",
        "1e-2",
        "--json",
    ]);
    for key in [
        "rms_height",
        "rms_slope",
        "kappa_bush",
        "kappa_persson",
        "points",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert!((v["rms_slope"].as_f64().unwrap() - 1.0).abs() < 1e-14);
    let pts = v["points"].as_array().unwrap();
    assert_eq!(pts.len(), 2);
    assert_eq!(pts[0]["nominal_pressure"].as_f64().unwrap(), 1e-3);
    assert!((pts[0]["zeta"].as_f64().unwrap() - 1e5).abs() < 1e-9);
    // G = (E*/σ0)² ⟨|∇h|²⟩ / 8 with rms slope 1 at full magnification.
    let g = pts[0]["g"].as_f64().unwrap();
    assert!((g - 1e6 / 8.0).abs() / g < 1e-14, "{g}");
    let a = pts[0]["contact_fraction"].as_f64().unwrap();
    let exact = libm::erf(0.5 / g.sqrt());
    assert!((a - exact).abs() / exact < 1e-15);
    let bush = pts[1]["contact_fraction_bush_linear"].as_f64().unwrap();
    assert!((bush - (2.0 * std::f64::consts::PI).sqrt() * 1e-2).abs() < 1e-15);
}

#[test]
fn example_runs_in_every_format() {
    let (code, out, _) = persson(&["area", "--example"]);
    assert_eq!(code, 0);
    assert!(out.contains("A/A0"));
    // The title says what the example is.
    let example = "self-affine surface, H = 0.8, q_l = 1e4, q_r = 1e5, q_s = 1e8 1/m, rms height 1 µm; E* = 1 GPa";
    assert!(out.contains(example), "{out}");
    let (_, help, _) = persson(&["area", "--help"]);
    let help = help.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        help.contains("H = 0.8, q_l = 1e4, q_r = 1e5, q_s = 1e8 1/m, rms height 1 µm; E* = 1 GPa"),
        "{help}"
    );
    let (code, out, _) = persson(&["area", "--example", "--csv"]);
    assert_eq!(code, 0);
    assert!(out.lines().next().unwrap().starts_with(
        "nominal_pressure,g,effective_g,contact_fraction,error_bound,contact_fraction_bush_linear"
    ));
    assert_eq!(out.lines().count(), 7);
    for cmd in ["spectrum", "magnification", "kappa", "separation", "area"] {
        let v = json(&[cmd, "--example", "--json"]);
        assert!(v.is_object(), "{cmd}");
    }
    // The BEM commands say it on stderr, their stdout being the report alone.
    for args in [
        &[
            "bem",
            "rough",
            "--example",
            "--grid",
            "16",
            "--pressure",
            "1e6",
        ][..],
        &[
            "compare",
            "--example",
            "--grid",
            "16",
            "--levels",
            "2",
            "--pressure",
            "1e6",
        ][..],
    ] {
        let (code, _, err) = persson(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert!(err.contains(example), "{args:?}: {err}");
    }
    // `g` is the hidden old name of `magnification`, `--modulus` of `--contact-modulus`.
    assert_eq!(
        json(&["g", "--example", "--json"]),
        json(&["magnification", "--example", "--json"])
    );
    assert_eq!(
        json(&["area", "--example", "--modulus", "2e9", "--json"])["points"],
        json(&["area", "--example", "--contact-modulus", "2e9", "--json"])["points"]
    );
}

#[test]
fn psd_file_matches_model() {
    let dir = std::env::temp_dir().join(format!("persson-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("psd.csv");
    // C = q^-3.6 (H = 0.8) sampled on a power law: log-log interpolation is exact.
    let rows: String = (0..=40)
        .map(|i| {
            let q = 1e4 * 10f64.powf(i as f64 / 10.0);
            format!("{q:e},{:e}\n", q.powf(-3.6))
        })
        .collect();
    std::fs::write(&path, format!("q,C\n{rows}")).unwrap();
    let p = path.to_str().unwrap();
    let tab = json(&[
        "area",
        "--psd",
        p,
        "--contact-modulus",
        "1",
        "--pressure",
        "1e-3",
        "--json",
    ]);
    let c_r = 1e4f64.powf(-3.6);
    let model = json(&[
        "area",
        "--hurst",
        "0.8",
        "--q-l",
        "1e4",
        "--q-s",
        "1e8",
        "--c-r",
        &format!("{c_r:e}"),
        "--contact-modulus",
        "1",
        "--pressure",
        "1e-3",
        "--json",
    ]);
    let (a, b) = (
        tab["points"][0]["g"].as_f64().unwrap(),
        model["points"][0]["g"].as_f64().unwrap(),
    );
    assert!(((a - b) / b).abs() < 1e-12, "{a} vs {b}");
}

#[test]
fn bad_input_exits_2_naming_the_field() {
    let sa = [
        "--q-l",
        "1e4",
        "--q-s",
        "1e8",
        "--rms-slope",
        "0.1",
        "--contact-modulus",
        "1",
    ];
    let with = |extra: &[&str]| -> Vec<String> {
        let mut v: Vec<String> = vec!["area".into()];
        v.extend(sa.iter().map(|s| s.to_string()));
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    let cases: Vec<(Vec<String>, &str)> = vec![
        (with(&["--hurst", "1", "--pressure", "1"]), "hurst"),
        (with(&["--hurst", "0", "--pressure", "1"]), "hurst"),
        (with(&["--hurst", "nan", "--pressure", "1"]), "hurst"),
        (with(&["--hurst", "0.5", "--pressure", "-1"]), "pressure"),
        (with(&["--hurst", "0.5", "--pressure", "inf"]), "pressure"),
        (
            with(&["--hurst", "0.5", "--pressure", "1", "--zeta", "0.5"]),
            "zeta",
        ),
        (with(&["--hurst", "0.5"]), "pressure"),
        (
            [
                "area",
                "--hurst",
                "0.5",
                "--q-l",
                "1e8",
                "--q-s",
                "1e4",
                "--rms-slope",
                "0.1",
                "--contact-modulus",
                "1",
                "--pressure",
                "1",
            ]
            .map(String::from)
            .to_vec(),
            "q_l <= q_r < q_s",
        ),
        (
            [
                "area",
                "--hurst",
                "0.5",
                "--q-l",
                "1e4",
                "--q-s",
                "1e8",
                "--rms-slope",
                "0.1",
                "--contact-modulus",
                "-1",
                "--pressure",
                "1",
            ]
            .map(String::from)
            .to_vec(),
            "contact_modulus",
        ),
        (
            [
                "area",
                "--psd",
                "/nonexistent/psd.csv",
                "--contact-modulus",
                "1",
                "--pressure",
                "1",
            ]
            .map(String::from)
            .to_vec(),
            "psd.csv",
        ),
        (
            ["spectrum", "--example", "--q-min", "-3"]
                .map(String::from)
                .to_vec(),
            "q_min",
        ),
    ];
    for (args, needle) in cases {
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, out, err) = persson(&refs);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?} printed {out}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(
            !err.contains("panicked") && !err.contains("backtrace"),
            "{err}"
        );
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    }
}

#[test]
fn help_and_version_exit_0_on_stdout() {
    for args in [
        &["--help"][..],
        &["--version"],
        &["stress", "--help"],
        &["area", "-h"],
    ] {
        let (code, out, err) = persson(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert!(!out.is_empty() && err.is_empty(), "{args:?}: {err}");
        assert!(!out.contains("persson: error"), "{args:?}");
    }
    let (_, out, _) = persson(&["stress", "--help"]);
    for flag in [
        "--ball-radius",
        "--cylinder-radius",
        "--flat",
        "--yield-stress",
        "--zeta",
    ] {
        assert!(out.contains(flag), "stress --help lacks {flag}");
    }
}

/// `--example` with self-affine flags: the flags replace those parts of the
/// example's spectrum (the same numbers as the full flags).
#[test]
fn example_flags_replace_parts_of_the_example() {
    let over = json(&[
        "area",
        "--example",
        "--hurst",
        "0.5",
        "--pressure",
        "1e6",
        "--json",
    ]);
    let full = json(&[
        "area",
        "--hurst",
        "0.5",
        "--q-l",
        "1e4",
        "--q-r",
        "1e5",
        "--q-s",
        "1e8",
        "--rms-height",
        "1e-6",
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6",
        "--json",
    ]);
    assert_eq!(over["points"], full["points"]);
    assert_eq!(over["rms_slope"], full["rms_slope"]);
    // No flag: the example itself.
    let plain = json(&["area", "--example", "--pressure", "1e6", "--json"]);
    assert_ne!(plain["rms_slope"], over["rms_slope"]);
}

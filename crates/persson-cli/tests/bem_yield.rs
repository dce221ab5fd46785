//! The saturated contact (yield stress, 0 ≤ p ≤ σY) of the boundary-element
//! solver (issue 14): the elastic limit, the KKT conditions, the Hertz
//! plastic disc, bad input.
#![cfg(feature = "bem")]

/// `persson bem rough --yield-stress`: the JSON point carries the elastic
/// and plastic fractions, which add up to the total; σY ≤ σ0 is refused.
#[test]
fn cli_rough_yield_stress() {
    let run = |y: &str| {
        std::process::Command::new(env!("CARGO_BIN_EXE_persson"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args([
                "bem",
                "rough",
                "--hurst",
                "0.8",
                "--q-l",
                "6.283",
                "--q-r",
                "25.13",
                "--q-s",
                "100",
                "--rms-slope",
                "0.1",
                "--size",
                "1",
                "--grid",
                "32",
                "--modulus",
                "1",
                "--pressure",
                "0.006",
                "--yield-stress",
                y,
                "--json",
            ])
            .env("RUST_BACKTRACE", "0")
            .output()
            .unwrap()
    };
    let out = run("0.02");
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["yield_stress"], 0.02);
    let p = &v["points"][0];
    let (total, el, pl) = (
        p["contact_fraction"].as_f64().unwrap(),
        p["elastic_fraction"].as_f64().unwrap(),
        p["plastic_fraction"].as_f64().unwrap(),
    );
    assert!(pl > 0.0);
    // Node counts over 32²: the sum is exact.
    assert_eq!(el + pl, total);
    assert!(p["plastic_displacement_max"].as_f64().unwrap() > 0.0);
    let bad = run("0.006");
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("no solution"));
}

/// `persson bem hertz --yield-stress --grid 32,64 --json`: one row per grid,
/// the change of c between them; a list of grids without a yield stress is
/// refused.
#[test]
fn cli_hertz_yield_stress() {
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_persson"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(["bem", "hertz"])
            .args(args)
            .env("RUST_BACKTRACE", "0")
            .output()
            .unwrap()
    };
    let out = run(&["--yield-stress", "0.05", "--grid", "32,64", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["yield_stress"], 0.05);
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    let c = |k: usize| rows[k]["plastic_radius"].as_f64().unwrap();
    assert_eq!(
        rows[1]["plastic_radius_change"].as_f64().unwrap(),
        c(1) - c(0)
    );
    assert!(c(1) > 0.0 && c(1) < 0.1);
    let bad = run(&["--grid", "32,64"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--yield-stress"));
}

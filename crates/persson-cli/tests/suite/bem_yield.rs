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

/// The Hertz ball (R = 1, E* = 1, a_H = 0.1) with the pressure capped at
/// σY = (π/4) p₀_H, solved as a 1-D axisymmetric problem
/// (examples/hertz_plastic_rings.py 0.7853981633974483 3200, RMAX = 1.11 …
/// 1.15): (c/a_H, δ/δ_H), c the mean over the five ring meshes (they spread
/// by ±1.2e-4, the ring width 3.5e-4), δ/δ_H = 1.0125887 on every mesh.
const RINGS_PI_4: (f64, f64) = (0.764608, 1.012_588_7);

/// |c_BEM − c_rings| in cells Δ = L/N: the plastic radius is a node count,
/// which moves in whole shells of nodes (measured: 0.14 cell at 32², 0.21
/// at 64²).
const PLASTIC_RADIUS_CELLS: f64 = 0.3;

/// |δ_BEM/δ_rings − 1| at 64² (measured: 1.3e-3; 2e-4 at 128², tests/bem_yield.rs).
const APPROACH_64: f64 = 2e-3;

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
    // η of the elastic ball on each grid beside the plastic disc, as a
    // scene's `bem_hertz` with a yield stress reports.
    assert_eq!(v["rows"].as_array().unwrap().len(), 2);
    let v = &v["plastic"];
    assert_eq!(v["yield_stress"], 0.05);
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    let c = |k: usize| rows[k]["plastic_radius"].as_f64().unwrap();
    assert_eq!(
        rows[1]["plastic_radius_change"].as_f64().unwrap(),
        c(1) - c(0)
    );
    // σY = 0.05 = (π/4) p₀_H (p₀_H = 0.2/π): against the axisymmetric
    // solution of the same ball, c/a_H = RINGS_PI_4 (a_H = 0.1), within
    // PLASTIC_RADIUS_CELLS cells of each grid; δ/δ_H within APPROACH_64.
    let a_h = rows[1]["plastic_radius"].as_f64().unwrap()
        / rows[1]["plastic_radius_ratio"].as_f64().unwrap();
    assert!((a_h - 0.1).abs() < 1e-15);
    for (k, n) in [(0, 32.0), (1, 64.0)] {
        let cells = (c(k) - RINGS_PI_4.0 * a_h).abs() * n;
        assert!(
            cells <= PLASTIC_RADIUS_CELLS,
            "{n}²: c = {}, {cells} cells",
            c(k)
        );
    }
    let approach = rows[1]["approach"].as_f64().unwrap() / (a_h * a_h);
    assert!(
        (approach / RINGS_PI_4.1 - 1.0).abs() <= APPROACH_64,
        "δ/δ_H = {approach}"
    );
    // Several grids without a yield stress: η per grid alone, as a scene's
    // `bem_hertz` (the command line used to refuse the list).
    let elastic = run(&["--grid", "32,64", "--json"]);
    assert!(elastic.status.success());
    let v: serde_json::Value = serde_json::from_slice(&elastic.stdout).unwrap();
    assert_eq!(v["rows"].as_array().unwrap().len(), 2);
    assert!(v.get("plastic").is_none());
}

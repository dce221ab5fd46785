//! `persson conductance`, `persson leakage` and `bem rough --leakage`
//! (issue 23): the wiring of the numerics, checked against the closed forms
//! that tie the printed numbers together.
#![cfg(feature = "flow")]

use crate::common;

use common::json;

/// Rounding of a product of a few factors printed by serde_json (shortest
/// round-trip form, so exact to the last bit; a few ulps of the products).
const PRODUCT_TOLERANCE: f64 = 1e-14;

const SPECTRUM: &[&str] = &[
    "--hurst",
    "0.8",
    "--q-l",
    "6283.185307179586",
    "--q-r",
    "25132.741228718345",
    "--q-s",
    "100530.96491487338",
    "--rms-slope",
    "0.1",
    "--contact-modulus",
    "1e7",
];

fn args<'a>(head: &[&'a str], tail: &[&'a str]) -> Vec<&'a str> {
    head.iter().chain(SPECTRUM).chain(tail).copied().collect()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs()
}

#[test]
fn conductance_is_barbers_identity_on_the_printed_stiffness() {
    let v = json(&args(
        &["conductance"],
        &[
            "--pressure",
            "1e4,1e5",
            "--conductivity",
            "0.2,50",
            "--resistivity",
            "0.1,1.7e-8",
            "--json",
        ],
    ));
    let e_star = 1e7;
    let kappa_s = 0.2 * 50.0 / 50.2;
    for p in v["points"].as_array().unwrap() {
        let k = p["stiffness"].as_f64().unwrap();
        let h = p["thermal_conductance"].as_f64().unwrap();
        let he = p["electrical_conductance"].as_f64().unwrap();
        assert!(
            close(h, 2.0 * kappa_s * k / e_star, PRODUCT_TOLERANCE),
            "{p}"
        );
        assert!(
            close(he, 2.0 * k / ((0.1 + 1.7e-8) * e_star), PRODUCT_TOLERANCE),
            "{p}"
        );
        assert!(p["thermal_conductance_error_bound"].as_f64().unwrap() > 0.0);
    }
}

#[test]
fn leakage_is_the_cube_law_and_a_sealed_load_leaks_nothing_with_a_warning() {
    let v = json(&args(
        &["leakage"],
        &[
            "--pressure",
            "3e4,5e5",
            "--viscosity",
            "1e-3",
            "--pressure-drop",
            "1e5",
            "--seal-width",
            "2e-3",
            "--seal-length",
            "1e-2",
            "--json",
        ],
    ));
    let pts = v["points"].as_array().unwrap();
    let cj = &pts[0]["critical_junction"];
    assert_eq!(cj["status"], "leaking");
    let u1 = cj["critical_separation"].as_f64().unwrap();
    let q = 5.0 * u1.powi(3) * 1e5 / 12e-3;
    assert!(
        close(cj["leak_rate"].as_f64().unwrap(), q, PRODUCT_TOLERANCE),
        "{cj}"
    );
    // 5e5 Pa = 0.05 E*: A/A0 above both thresholds.
    for method in ["critical_junction", "effective_medium"] {
        assert_eq!(pts[1][method]["status"], "sealed", "{}", pts[1]);
        assert_eq!(pts[1][method]["leak_rate"].as_f64(), Some(0.0));
    }
    let kinds: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["kind"] == "sealed")
        .map(|w| w["method"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["critical-junction", "effective-medium"]);
}

#[test]
fn a_gas_leaks_by_the_difference_of_the_squares() {
    let run = |extra: &[&str]| {
        let mut tail = vec!["--pressure", "3e4", "--viscosity", "1.8e-5", "--json"];
        tail.extend_from_slice(extra);
        json(&args(&["leakage"], &tail))["points"][0]["critical_junction"]["leak_rate"]
            .as_f64()
            .unwrap()
    };
    let liquid = run(&["--pressure-drop", "1e5"]);
    let gas = run(&["--inlet-pressure", "3e5", "--outlet-pressure", "1e5"]);
    // (P_a² − P_b²)/(2 P_b) = 4e5 Pa: four times the liquid's 1e5 Pa.
    assert!(
        close(gas, 4.0 * liquid, PRODUCT_TOLERANCE),
        "{gas} {liquid}"
    );
}

#[test]
fn bem_rough_leakage_reports_both_directions_and_writes_the_gap() {
    let dir = std::env::temp_dir().join(format!("persson-transport-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let gap = dir.join("gap.npy");
    let gap_arg = gap.to_string_lossy().into_owned();
    let v = json(&args(
        &["bem", "rough", "--grid", "64"],
        &[
            "--pressure",
            "3e4",
            "--leakage",
            "--viscosity",
            "1e-3",
            "--pressure-drop",
            "1e5",
            "--conductivity",
            "50",
            "--gap-field",
            &gap_arg,
            "--json",
        ],
    ));
    let t = &v["transport"][0];
    let flows = t["flows"].as_array().unwrap();
    assert_eq!(flows.len(), 2);
    assert_eq!(flows[0]["direction"], "x");
    assert_eq!(flows[1]["direction"], "y");
    let mean = (flows[0]["effective_flow_conductivity"].as_f64().unwrap()
        + flows[1]["effective_flow_conductivity"].as_f64().unwrap())
        / 2.0;
    let sigma = t["effective_flow_conductivity"].as_f64().unwrap();
    assert!(sigma > 0.0 && close(sigma, mean, PRODUCT_TOLERANCE), "{t}");
    // A square seal (default 1 mm × 1 mm): Q = σ_eff ΔP.
    assert!(
        close(
            t["leak_rate"].as_f64().unwrap(),
            sigma * 1e5,
            PRODUCT_TOLERANCE
        ),
        "{t}"
    );
    let k = t["stiffness"].as_f64().unwrap();
    assert!(close(
        t["thermal_conductance"].as_f64().unwrap(),
        50.0 * k / 1e7,
        PRODUCT_TOLERANCE
    ));
    let bytes = std::fs::read(&gap).unwrap();
    // 64² float64 values after the header.
    assert!(bytes.len() > 64 * 64 * 8 && bytes.starts_with(b"\x93NUMPY"));
    let _ = std::fs::remove_dir_all(&dir);
}

//! Every command that computes something runs on `--example` (issue 38),
//! and what it computes there is what the example says it is.

use crate::common::{json, persson};

/// The tread compound's μ(v) rises from 1 µm/s, peaks inside the sampled
/// velocities and falls by 100 m/s: the rubber-friction curve of the
/// guide, on 50 velocities.
#[test]
fn friction_example_rises_and_falls_over_fifty_velocities() {
    let r = json(&["friction", "--example", "--json"]);
    let mu: Vec<f64> = r["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["friction_coefficient"].as_f64().unwrap())
        .collect();
    assert_eq!(mu.len(), 50);
    let (peak, &max) = mu
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .unwrap();
    assert!(
        peak > 5 && peak < 45,
        "the peak of μ(v) at point {peak} of 50"
    );
    assert!(max > 10.0 * mu[0] && max > 10.0 * mu[49], "{mu:?}");
}

/// The water seal leaks less as it is pressed harder (both theories), and
/// the example's heat path reports the gap's conductance beside the spots'.
#[test]
fn leakage_and_conductance_examples_are_a_water_seal_and_an_air_gap() {
    let l = json(&["leakage", "--example", "--json"]);
    assert_eq!(l["viscosity"].as_f64(), Some(1e-3));
    assert_eq!(l["pressure_drop"].as_f64(), Some(1e5));
    let q: Vec<f64> = l["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["effective_medium"]["leak_rate"].as_f64().unwrap())
        .collect();
    assert!(q.windows(2).all(|w| w[1] < w[0]), "{q:?}");
    let c = json(&["conductance", "--example", "--json"]);
    assert_eq!(c["gas_conductivity"].as_f64(), Some(0.026));
    for p in c["points"].as_array().unwrap() {
        assert!(p["gap_conductance"].as_f64().unwrap() > 0.0, "{p}");
        assert!(p["thermal_conductance"].as_f64().unwrap() > 0.0, "{p}");
    }
}

/// Adhesion, stress, the BEM and anisotropy compute on `--example` too.
#[test]
fn every_computing_command_runs_on_the_example() {
    for args in [
        &["adhesion", "--example"][..],
        &["stress", "--example"],
        &["bem", "rough", "--example"],
        &["anisotropy", "--example"],
        &["spectrum", "--example"],
        &["magnification", "--example"],
        &["area", "--example"],
        &["kappa", "--example"],
        &["separation", "--example"],
        &["compare", "--example", "--grid", "32", "--levels", "2"],
        &[
            "compare",
            "ensemble",
            "--example",
            "--grid",
            "32",
            "--seeds",
            "2",
        ],
    ] {
        let (code, out, err) = persson(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert!(!out.is_empty(), "{args:?}");
    }
}

/// The anisotropy example is the guide's map (`docs/data/stretched.npy`,
/// written by `examples/anisotropic_map.rs`): the same numbers.
#[test]
fn anisotropy_example_is_the_guides_stretched_map() {
    let example = json(&["anisotropy", "--example", "--json"]);
    let file = json(&[
        "anisotropy",
        "--surface",
        "docs/data/stretched.npy",
        "--size",
        "1e-3",
        "--periodic",
        "--json",
    ]);
    for key in [
        "peklenik_number",
        "principal_direction",
        "texture_aspect_ratio",
        "texture_direction",
    ] {
        assert_eq!(example[key], file[key], "{key}");
    }
}

/// `compare kappa --example` is κ(H) at H = 0.2, 0.5 and 0.8; a given
/// --hurst replaces them.
#[test]
fn kappa_study_example_is_three_hurst_exponents() {
    let hurst = |r: &serde_json::Value| -> Vec<f64> {
        r["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|row| row["hurst"].as_f64().unwrap())
            .collect()
    };
    let base = [
        "compare",
        "kappa",
        "--example",
        "--grid",
        "32",
        "--levels",
        "2",
        "--json",
    ];
    assert_eq!(hurst(&json(&base)), [0.2, 0.5, 0.8]);
    let mut given = base.to_vec();
    given.extend(["--hurst", "0.6"]);
    assert_eq!(hurst(&json(&given)), [0.6]);
    let (code, _, err) = persson(&["compare", "kappa"]);
    assert_ne!(code, 0);
    assert!(err.contains("--hurst"), "{err}");
}

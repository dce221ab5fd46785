//! Stress distributions P(σ, ζ): accuracy against mpmath, invariants,
//! method cross-checks and input validation.

// The one oracle of the workspace's tests (the root crate's tests/common).
#[path = "../../../../tests/common/oracle.rs"]
mod oracle;
use persson::stress::{distribution, Start};

/// `persson stress … --json` prints the documented keys; bad input exits with 2.
#[test]
fn cli_stress_json_and_exit_codes() {
    use std::process::Command;
    let bin = env!("CARGO_BIN_EXE_persson");
    let out = Command::new(bin)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .args([
            "stress",
            "--start",
            "hertz",
            "--g",
            "0.6",
            "--yield-ratio",
            "1.5",
        ])
        .args([
            "--sigma-ratio",
            "0.25,0.5,1",
            "--tolerance",
            "1e-12",
            "--json",
        ])
        .env("RUST_BACKTRACE", "0")
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let want = distribution(&Start::Hertz, 0.6, Some(1.5), &[0.25, 0.5, 1.0], 1e-12).unwrap();
    assert_eq!(v["yield_ratio"].as_f64().unwrap(), 1.5);
    let v = &v["curves"][0];
    // contact_fraction is the total A/A0 = A_el/A0 + A_pl/A0
    assert_eq!(
        v["contact_fraction"].as_f64().unwrap(),
        want.elastic_fraction + want.plastic_fraction
    );
    assert_eq!(
        v["elastic_fraction"].as_f64().unwrap(),
        want.elastic_fraction
    );
    assert_eq!(
        v["plastic_fraction"].as_f64().unwrap(),
        want.plastic_fraction
    );
    assert_eq!(v["scaled_density"].as_array().unwrap().len(), 3);
    assert_eq!(v["sigma_ratio"][2].as_f64().unwrap(), 1.0);
    // one bound per quantity, the solver's own (no aggregate `error_bound`);
    // read back to an ulp (serde_json's default float parser, without its
    // `float_roundtrip` feature, may miss the nearest double by one)
    assert!(v.get("error_bound").is_none());
    let ulp = |a: f64, b: f64| (a - b).abs() <= f64::EPSILON * b.abs();
    for (key, want) in [
        (
            "scaled_density_error_bound",
            want.scaled_density_error_bound,
        ),
        (
            "elastic_fraction_error_bound",
            want.elastic_fraction_error_bound,
        ),
        (
            "plastic_fraction_error_bound",
            want.plastic_fraction_error_bound,
        ),
    ] {
        let got = v[key].as_f64().unwrap();
        assert!(ulp(got, want), "{key}: {got:e} vs {want:e}");
    }
    // the method as data: the density from the sine series and its terms
    assert_eq!(v["method"]["density"]["kind"], "sine_series");
    assert!(v["method"]["density"]["terms"].as_u64().unwrap() >= 1);
    for bad in [
        &["--start", "flat", "--g", "-1"][..],
        &["--start", "flat", "--g", "nan"],
        &["--start", "cylinder", "--g", "0.6", "--yield-ratio", "1"],
        &["--start", "hertz", "--g", "0.6", "--yield-ratio", "0.5"],
        &["--start", "disk", "--g", "0.6"],
    ] {
        let out = Command::new(bin)
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .arg("stress")
            .args(bad)
            .arg("--json")
            .env("RUST_BACKTRACE", "0")
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
        assert!(!out.stderr.is_empty() && out.stdout.is_empty(), "{bad:?}");
    }
    // tabulated starts: a triangle is accepted; negative or unnormalised tables are not
    let dir = std::env::temp_dir().join(format!("persson-stress-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text, code) in [
        ("ok.csv", "# sigma, P0\n0, 0\n1, 1\n2, 0\n", 0),
        ("negative.csv", "0 0\n1 -1\n2 3\n", 2),
        ("unnormalised.csv", "0 0\n1 1\n2 0.5\n", 2),
        ("garbage.csv", "0 0\n1 x\n", 2),
    ] {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        let out = Command::new(bin)
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(["stress", "--g", "0.1", "--json", "--table"])
            .arg(&path)
            .env("RUST_BACKTRACE", "0")
            .output()
            .unwrap();
        assert_eq!(
            out.status.code(),
            Some(code),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

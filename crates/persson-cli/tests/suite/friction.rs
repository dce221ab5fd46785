//! `persson friction`: its JSON, the scene output of the same name, and bad
//! input (every case exits 2 naming the flag's field or the file's line).

use crate::common;

use common::{json, persson};

const SPECTRUM: &str = "--hurst 0.8 --q-l 1e3 --q-r 1e4 --q-s 1e7 --rms-slope 0.8";
const SLS: &str = "--standard-linear-solid 3e8,3e6,1e-4";
const CURVE: &str =
    "--master-curve tests/reference/data/rubber_master_curve.csv --frequency-unit rad/s";

fn args(extra: &str) -> Vec<String> {
    format!("friction {SPECTRUM} {extra}")
        .split_whitespace()
        .map(String::from)
        .collect()
}

fn run_json(extra: &str) -> serde_json::Value {
    let mut a = args(extra);
    a.push("--json".into());
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    json(&a)
}

#[test]
fn json_has_a_point_per_temperature_pressure_and_velocity() {
    let r = run_json(&format!(
        "{CURVE} --wlf 8.86,101.6,293.15 --temperature 293.15,313.15 --pressure 1e5,2e5 \
         --velocity-range 1e-3,1,4 --flash-temperature --thermal-conductivity 0.25 \
         --density 1200 --heat-capacity 1500"
    ));
    let points = r["points"].as_array().unwrap();
    assert_eq!(points.len(), 2 * 2 * 4);
    // Temperature outermost, velocity innermost.
    assert_eq!(points[0]["temperature"], 293.15);
    assert_eq!(points[8]["temperature"], 313.15);
    assert_eq!(points[4]["nominal_pressure"], 2e5);
    assert_eq!(points[3]["velocity"], 1.0);
    for p in points {
        for key in [
            "friction_coefficient",
            "friction_coefficient_error_bound",
            "contact_fraction",
            "contact_fraction_error_bound",
        ] {
            let v = p[key].as_f64().unwrap();
            assert!(v.is_finite() && v >= 0.0, "{key} = {v}");
            let f = p["flash"][key].as_f64().unwrap();
            assert!(f.is_finite() && f >= 0.0, "flash {key} = {f}");
        }
        // The decades add up to μ (to the error bound).
        let sum: f64 = p["decades"]
            .as_array()
            .unwrap()
            .iter()
            .map(|d| d["friction_coefficient"].as_f64().unwrap())
            .sum();
        let mu = p["friction_coefficient"].as_f64().unwrap();
        let bound = p["friction_coefficient_error_bound"].as_f64().unwrap();
        assert!((sum - mu).abs() <= bound + 1e-14 * mu, "{sum} vs {mu}");
        assert!(p["flash"]["flash_temperature"].as_f64().unwrap() >= 0.0);
    }
}

#[test]
fn the_scene_output_prints_the_same_numbers() {
    let r = run_json(&format!(
        "{CURVE} --wlf 8.86,101.6,293.15 --temperature 293.15,313.15 --pressure 2e5 \
         --velocity-range 1e-4,1,9 --flash-temperature --thermal-conductivity 0.25 \
         --density 1200 --heat-capacity 1500"
    ));
    let out = std::env::temp_dir().join(format!("persson-friction-{}", std::process::id()));
    let out = out.to_string_lossy().into_owned();
    let scene = json(&["run", "scenes/friction.json", "--out", &out, "--json"]);
    assert_eq!(scene["friction"]["points"], r["points"]);
    assert!(std::path::Path::new(&out).join("friction.svg").exists());
}

#[test]
fn frequency_independent_loss_gives_velocity_independent_friction() {
    // E = 2e6 + 5e5 i at every frequency, γ = 1: μ is the same at every v
    // (the closed form is checked in tests/friction.rs and the Python tests).
    let dir = std::env::temp_dir().join(format!("persson-friction-c-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("constant.csv");
    std::fs::write(&f, "1,2e6,5e5\n10,2e6,5e5\n100,2e6,5e5\n").unwrap();
    let r = run_json(&format!(
        "--master-curve {} --frequency-unit Hz --pressure 1e5 --velocity 1e-6,1e-2,1 \
         --gamma 1 --tolerance 1e-12",
        f.display()
    ));
    let mu: Vec<f64> = r["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["friction_coefficient"].as_f64().unwrap())
        .collect();
    for m in &mu {
        assert!(((m - mu[0]) / mu[0]).abs() < 1e-10, "{mu:?}");
    }
    assert_eq!(r["warnings"][0]["kind"], "master_curve_range");
}

#[test]
fn bad_input_names_the_flag_or_the_line() {
    let dir = std::env::temp_dir().join(format!("persson-friction-b-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.display().to_string()
    };
    let unsorted = file("unsorted.txt", "1 1e6 1e5\n10 2e6 2e5\n5 3e6 3e5\n");
    let repeated = file(
        "repeated.txt",
        "# w E1 E2\n1 1e6 1e5\n10 2e6 2e5\n10 3e6 3e5\n",
    );
    let nan = file("nan.txt", "1 1e6 1e5\n10 2e6 nan\n100 3e6 3e5\n");
    let short = file("short.txt", "1 1e6 1e5\n10 2e6 2e5\n");
    let negative = file("negative.txt", "1 1e6 1e5\n10 -2e6 2e5\n100 3e6 3e5\n");
    let lossless = file("lossless.txt", "1 1e6 1e5\n10 2e6 2e5\n100 3e6 0\n");
    let cases: Vec<(String, &str)> = vec![
        (format!("{SLS} --pressure 2e5 --velocity 0"), "--velocity"),
        (format!("{SLS} --pressure 2e5 --velocity -1"), "--velocity"),
        (format!("{SLS} --pressure 2e5 --velocity nan"), "--velocity"),
        (
            format!("{SLS} --pressure 2e5 --velocity-range 0,1,3"),
            "--velocity-range",
        ),
        (
            format!("{SLS} --pressure 2e5 --velocity-range 1,2"),
            "--velocity-range",
        ),
        (
            format!("{SLS} --wlf 8.86,101.6,293.15 --temperature 191 --pressure 2e5 --velocity 1"),
            "WLF singularity",
        ),
        (
            format!(
                "{SLS} --wlf 8.86,101.6,293.15 --temperature 191.55 --pressure 2e5 --velocity 1"
            ),
            "--temperature",
        ),
        (
            format!("{SLS} --pressure 2e5 --velocity 1 --q1 1e8"),
            "--q1",
        ),
        (
            format!("{SLS} --pressure 2e5 --velocity 1 --q1 1e3"),
            "--q1",
        ),
        (
            format!("{SLS} --pressure 2e5 --velocity 1 --q1-rms-slope 50"),
            "--q1-rms-slope",
        ),
        (format!("{SLS} --pressure 0 --velocity 1"), "--pressure"),
        (format!("{SLS} --velocity 1"), "--pressure"),
        (format!("{SLS} --pressure 2e5"), "--velocity"),
        (
            "--standard-linear-solid 3e8,3e6 --pressure 2e5 --velocity 1".into(),
            "--standard-linear-solid",
        ),
        (
            format!("{SLS} --pressure 2e5 --velocity 1 --flash-temperature"),
            "--thermal-conductivity",
        ),
        (
            format!("--master-curve {unsorted} --frequency-unit Hz --pressure 2e5 --velocity 1"),
            "unsorted.txt:3",
        ),
        (
            format!("--master-curve {repeated} --frequency-unit Hz --pressure 2e5 --velocity 1"),
            "repeated.txt:4",
        ),
        (
            format!("--master-curve {nan} --frequency-unit Hz --pressure 2e5 --velocity 1"),
            "nan.txt:2",
        ),
        (
            format!("--master-curve {short} --frequency-unit Hz --pressure 2e5 --velocity 1"),
            "at least 3",
        ),
        (
            format!("--master-curve {negative} --frequency-unit Hz --pressure 2e5 --velocity 1"),
            "negative.txt:2",
        ),
        (
            format!("--master-curve {lossless} --frequency-unit Hz --pressure 2e5 --velocity 1"),
            "lossless.txt:3",
        ),
        (
            format!("--master-curve {short} --pressure 2e5 --velocity 1"),
            "--frequency-unit",
        ),
    ];
    for (extra, word) in cases {
        let a = args(&extra);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        let (code, out, err) = persson(&a);
        assert_eq!(code, 2, "{extra}: {err}");
        assert!(out.is_empty(), "{extra}: {out}");
        assert_eq!(err.lines().count(), 1, "{extra}: {err}");
        assert!(err.contains(word), "{extra}: {err} lacks {word}");
        assert!(
            !err.contains("NaN") || extra.contains("nan"),
            "{extra}: {err}"
        );
    }
}

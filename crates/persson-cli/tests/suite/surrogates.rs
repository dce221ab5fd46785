//! `persson surrogates` and the scene output `surrogates` (issue 39): the
//! example, a real map, the files it writes, the scene equal to the flags,
//! and bad input named.
#![cfg(feature = "bem")]

use crate::common::{json, persson, root};

#[test]
fn the_example_compares_a_random_map_with_its_surrogates() {
    let r = json(&["surrogates", "--example", "--json"]);
    assert_eq!(r["count"], 8);
    assert_eq!(r["kind"], "phase");
    assert_eq!(r["grid"], 64);
    let points = r["points"].as_array().unwrap();
    assert_eq!(points.len(), 4, "the example's loads from 1e6 Pa");
    assert!(
        r["warnings"].as_array().unwrap().is_empty(),
        "{}",
        r["warnings"]
    );
    for p in points {
        // The example's map is itself random: no load flagged.
        assert_eq!(p["significant"], false, "{p}");
        let (a, m) = (
            p["map_contact_fraction"].as_f64().unwrap(),
            p["surrogate_contact_fraction"].as_f64().unwrap(),
        );
        assert!(a > 0.0 && m > 0.0 && a <= 1.0 && m <= 1.0);
        let ratio = p["ratio"].as_f64().unwrap();
        assert!(
            (ratio - a / m).abs() <= 1e-15 * ratio,
            "ratio = map / mean: {ratio} {}",
            a / m
        );
    }
}

/// The real AFM map of the scene `scenes/surrogates.json`: the command line
/// prints the scene's numbers, and its map differs from random surfaces.
#[test]
fn a_measured_map_on_the_command_line_equals_the_scene() {
    let flags = json(&[
        "surrogates",
        "--surface",
        "tests/data/di-3.di",
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6,1e7,3e7",
        "--json",
    ]);
    let scene = json(&["run", "scenes/surrogates.json", "--json"]);
    let s = &scene["surrogates"];
    for key in [
        "map_contact_fraction",
        "surrogate_contact_fraction",
        "z",
        "theory_contact_fraction",
    ] {
        for i in 0..3 {
            assert_eq!(flags["points"][i][key], s["points"][i][key], "{key} at {i}");
        }
    }
    // Its kurtosis is far from a Gaussian's and its tail exponential.
    assert!(s["map_heights"]["kurtosis"].as_f64().unwrap() > 4.0);
    assert_eq!(s["points"][1]["significant"], true);
    assert!(
        s["points"][1]["map_tail"]["log_likelihood_advantage"]
            .as_f64()
            .unwrap()
            > 0.0
    );
}

#[test]
fn the_surrogates_and_figures_are_written_on_request() {
    let dir = std::env::temp_dir().join(format!("persson-surrogates-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("s.npy");
    let (code, _, err) = persson(&[
        "surrogates",
        "--example",
        "--count",
        "2",
        "--surfaces",
        file.to_str().unwrap(),
        "--plot",
        dir.join("a.svg").to_str().unwrap(),
        "--plot-distribution",
        dir.join("p.png").to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    for name in ["s_1.npy", "s_2.npy", "a.svg", "p.png"] {
        let len = std::fs::metadata(dir.join(name))
            .map(|m| m.len())
            .unwrap_or(0);
        assert!(len > 1000, "{name}: {len} bytes");
    }
    // 64² float64 and the npy header.
    assert_eq!(
        std::fs::metadata(dir.join("s_1.npy")).unwrap().len(),
        128 + 64 * 64 * 8
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_input_names_the_flag_or_the_file() {
    let cases: [(&[&str], &str); 4] = [
        (&["surrogates", "--example", "--count", "1"], "count"),
        (
            &[
                "surrogates",
                "--surface",
                "tests/data/sur-2.sur",
                "--contact-modulus",
                "1e9",
                "--pressure",
                "1e6",
            ],
            "undefined",
        ),
        (
            &[
                "surrogates",
                "--surface",
                "tests/data/metropro-1.dat",
                "--contact-modulus",
                "1e9",
                "--pressure",
                "1e6",
            ],
            "square",
        ),
        (&["surrogates", "--example", "--kind", "shuffle"], "kind"),
    ];
    for (args, what) in cases {
        let (code, _, err) = persson(args);
        assert_ne!(code, 0, "{args:?}");
        assert!(!err.contains("panicked"), "{err}");
        assert!(err.contains(what), "{args:?}: {err}");
    }
    // A scene cannot overwrite its own map.
    let scene = root().join("target/surrogates-overwrite.json");
    std::fs::write(
        &scene,
        r#"{"schema": 1, "material": {"contact_modulus": 1e9},
            "spectrum": {"kind": "height_map", "file": "../tests/data/di-3.di"},
            "nominal_pressure": [1e7],
            "outputs": {"surrogates": {"count": 2, "surfaces": "../tests/data/di-3.di"}}}"#,
    )
    .unwrap();
    let before = std::fs::read(root().join("tests/data/di-3.di")).unwrap();
    let (code, _, err) = persson(&["run", scene.to_str().unwrap()]);
    assert_ne!(code, 0);
    assert!(err.contains("surfaces"), "{err}");
    assert_eq!(
        std::fs::read(root().join("tests/data/di-3.di")).unwrap(),
        before
    );
}

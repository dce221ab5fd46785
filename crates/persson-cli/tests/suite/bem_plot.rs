//! `persson bem rough --plot` (issue 15): the pressure map with its colour
//! bar and the histogram with the plastic δ-peak at σY.
#![cfg(all(feature = "bem", feature = "plot"))]

/// The CLI writes the file; a bad extension is refused before any solve.
#[test]
fn cli_rough_plot() {
    let dir = std::env::temp_dir().join(format!("persson-bem-plot-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let run = |file: &str| {
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
                "0.02",
                "--plot",
            ])
            .arg(dir.join(file))
            .env("RUST_BACKTRACE", "0")
            .output()
            .unwrap()
    };
    let out = run("map.svg");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.join("map.svg")).unwrap();
    assert!(svg.contains("δ-peak at σY = 0.02"));
    let bad = run("map.txt");
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains(".svg or .png"));
    std::fs::remove_dir_all(&dir).unwrap();
}

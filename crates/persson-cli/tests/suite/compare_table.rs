//! The text tables of `persson compare` (issue 15, item 4): they fit 100
//! characters unless `--wide`, κ rows follow the grids numerically, no
//! standard error stands where none was estimated, and the scores of
//! `--data` are in the text.
#![cfg(feature = "bem")]

use crate::common;

use common::{json, persson};

/// The default width of the text tables.
const WIDTH: usize = 100;

/// H = 0.8, q_l = 1, q_r = 2, q_s = 8, rms slope 0.1, E* = 1.
const SURFACE: [&str; 13] = [
    "compare",
    "--hurst",
    "0.8",
    "--q-l",
    "1",
    "--q-r",
    "2",
    "--q-s",
    "8",
    "--rms-slope",
    "0.1",
    "--modulus",
    "1",
];

fn run(extra: &[&str]) -> String {
    let mut args = SURFACE.to_vec();
    args.extend_from_slice(extra);
    let (code, out, err) = persson(&args);
    assert_eq!(code, 0, "{err}");
    out
}

fn widest(text: &str) -> usize {
    text.lines().map(|l| l.chars().count()).max().unwrap_or(0)
}

/// The column headings and rows of the text table whose title starts with
/// `title` (the lines after its title and scalars up to the blank line),
/// split at runs of two or more spaces.
fn rows<'a>(text: &'a str, title: &str) -> Vec<Vec<&'a str>> {
    let block = text
        .split("\n\n")
        .skip_while(|b| !b.starts_with(title))
        .nth(1)
        .unwrap_or_else(|| panic!("no table {title}: {text}"));
    block
        .lines()
        .map(|l| {
            l.split("  ")
                .map(str::trim)
                .filter(|c| !c.is_empty())
                .collect()
        })
        .collect()
}

fn temp(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("persson-table-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn every_line_fits_100_characters_unless_wide() {
    let data = temp(
        "data.csv",
        "nominal_pressure,contact_fraction\n0.001,0.02\n0.002,0.035\n0.004,0.07\n",
    );
    for extra in [
        &["--grid", "64"][..],
        &["--grid", "64", "--data", data.to_str().unwrap()],
        &["--grid", "64", "--levels", "2", "--yield-stress", "0.05"],
        &["--grid", "64", "--levels", "2", "--pressure", "0.002,0.005"],
    ] {
        let out = run(extra);
        assert!(widest(&out) <= WIDTH, "{extra:?}:\n{out}");
    }
    // Seven grids 8² … 512²: the BEM table is wider than 100 with every
    // column; by default the coarsest grids' columns are left out and named.
    let many = ["--grid", "512", "--levels", "7", "--pressure", "0.002"];
    let out = run(&many);
    assert!(widest(&out) <= WIDTH, "{out}");
    assert!(
        out.contains("not shown (--wide shows them)  N = 8, N = 16"),
        "{out}"
    );
    let bem = rows(&out, "Contact area A/A0 of the FFT-BEM");
    assert_eq!(
        bem[0],
        [
            "σ0",
            "N = 32",
            "N = 64",
            "N = 128",
            "N = 256",
            "N = 512",
            "N → ∞",
            "standard error",
            "α"
        ]
    );
    let mut wide = many.to_vec();
    wide.push("--wide");
    let all = run(&wide);
    assert!(widest(&all) > WIDTH, "{all}");
    assert!(!all.contains("not shown"));
    assert_eq!(rows(&all, "Contact area A/A0 of the FFT-BEM")[0].len(), 11);
    // the JSON has every grid either way
    let mut j = many.to_vec();
    j.push("--json");
    let mut args = SURFACE.to_vec();
    args.extend(j);
    assert_eq!(json(&args)["bem"].as_array().unwrap().len(), 7);
}

#[test]
fn kappa_rows_follow_the_grids_numerically() {
    // 16, 32, 64, 128: as strings 128 would sort before 16
    let out = run(&["--grid", "128", "--levels", "4"]);
    let kappa = rows(&out, "κ of A/A0");
    let grids: Vec<usize> = kappa
        .iter()
        .filter(|r| r[0] == "BEM")
        .map(|r| r[1].parse().unwrap())
        .collect();
    assert_eq!(grids, [16, 32, 64, 128]);
    let solves = rows(&out, "FFT-BEM solves");
    let grids: Vec<&str> = solves.iter().skip(1).map(|r| r[0]).collect();
    assert_eq!(grids, ["16", "32", "64", "128"]);
    let bem = rows(&out, "Contact area A/A0 of the FFT-BEM");
    assert_eq!(&bem[0][1..5], ["N = 16", "N = 32", "N = 64", "N = 128"]);
}

#[test]
fn no_standard_error_where_none_was_estimated_and_the_scores_in_the_text() {
    let data = temp(
        "scores.csv",
        "nominal_pressure,contact_fraction\n0.001,0.02\n0.002,0.035\n0.004,0.07\n",
    );
    let extra = ["--grid", "64", "--data", data.to_str().unwrap()];
    let out = run(&extra);
    let kappa = rows(&out, "κ of A/A0");
    assert_eq!(kappa[0][3], "standard error");
    for r in kappa.iter().skip(1) {
        let estimated = r[0].starts_with("BEM");
        // exact theory curves and your data: their fit's error measures
        // only the curve's bend, not shown; the BEM's is shown
        assert_eq!(r[3] == "–", !estimated, "{r:?}\n{out}");
        if estimated {
            assert!(r[3].parse::<f64>().unwrap() > 0.0, "{r:?}");
        }
    }
    assert!(kappa.iter().any(|r| r[0] == "your data"), "{out}");
    // the JSON keeps every fit's standard error, and the scores
    let mut args = SURFACE.to_vec();
    args.extend(extra);
    args.push("--json");
    let v = json(&args);
    assert!(v["kappa"]["data"]["standard_error"].is_number());
    let scores = rows(&out, "Your data: relative deviation");
    assert_eq!(scores[0], ["reference", "rms", "max", "points"]);
    let want = v["data"]["scores"].as_array().unwrap();
    assert_eq!(scores.len() - 1, want.len());
    for (row, s) in scores.iter().skip(1).zip(want) {
        assert_eq!(row[0], s["reference"].as_str().unwrap());
        for (cell, key) in [
            (row[1], "rms_relative_deviation"),
            (row[2], "max_relative_deviation"),
        ] {
            let (shown, exact) = (cell.parse::<f64>().unwrap(), s[key].as_f64().unwrap());
            // three significant digits
            assert!(
                (shown - exact).abs() <= 5e-3 * exact,
                "{key}: {cell} vs {exact}"
            );
        }
        assert_eq!(row[3], s["points"].to_string());
    }
}

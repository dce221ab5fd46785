//! One name per quantity: the names table `src/names.md` is published
//! verbatim in the user guide (`docs/conventions.md`), and every JSON key the
//! `persson` binary prints is a name of that table (or one of the few
//! container keys allowed below).
#![cfg(feature = "bem")]

use crate::common;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The one source of names.
const NAMES: &str = include_str!("../../../../src/names.md");

/// Keys that hold other values rather than name a quantity. Keep this list
/// short: a quantity belongs in `src/names.md`, not here.
const CONTAINERS: &[&str] = &[
    "points",   // the rows of a curve (area, magnification, separation, BEM)
    "tables",   // the tables of a report
    "spectrum", // the spectrum echoed by a report or a scene
    "material", // the material echoed by a report or a scene
    "outputs",  // a scene's outputs, keyed by the output names below
    // The output names of a scene file (the keys of its "outputs").
    "area",
    "magnification",
    "kappa",
    "theories",
    "separation",
    "adhesion",
    "stress",
    "bem",
    "bem_hertz",
    "friction",
    "conductance",
    "leakage",
    // Keys whose value is a label from a closed set, spelled as on the command
    // line (CONTRACT: theory, boundary, start, convention).
    "theory",
    "boundary",
    "start",
    "convention",
    "method",
    // Text for people: a scene's name and description, a surface's origin.
    "name",
    "description",
    "surface",
    // Lists and groups of rows.
    "curves",
    "rows",
    "table",
    "cases",
    "families",
    "per_grid",
    "extrapolated",
    "pressure_distribution",
    "theory_curve",
    "fit",
    "power_law_fit",
    "solves", // an ensemble's jobs, one row per (seed, grid)
];

/// Prefixes of a quantity set beside the same quantity from elsewhere.
const PREFIXES: &[&str] = &["bem_", "theory_", "map_", "surrogate_"];

/// Suffixes of an error of the quantity they follow (`g_error_bound`).
const ERROR_SUFFIXES: &[&str] = &["_error_bound", "_standard_error", "_error"];

/// The names of `src/names.md`: every `backticked` word of its name column
/// (the fourth), without the pattern `<quantity>_error_bound`.
fn names() -> BTreeSet<String> {
    let mut header = None;
    let mut names = BTreeSet::new();
    for line in NAMES.lines().filter(|l| l.trim_start().starts_with('|')) {
        let cells: Vec<&str> = line.trim().trim_matches('|').split('|').collect();
        let Some(column) = header else {
            header = cells.iter().position(|c| c.trim().starts_with("name"));
            assert!(header.is_some(), "src/names.md: no `name` column in {line}");
            continue;
        };
        let cell = cells.get(column).copied().unwrap_or_default();
        for (i, word) in cell.split('`').enumerate() {
            if i % 2 == 1 && !word.contains('<') {
                names.insert(word.to_string());
            }
        }
    }
    names
}

/// Is `key` a published name, an error bound of one, or an allowed container?
fn allowed(key: &str, names: &BTreeSet<String>) -> bool {
    let named = |k: &str| {
        names.contains(k)
            || PREFIXES
                .iter()
                .any(|p| k.strip_prefix(p).is_some_and(|q| names.contains(q)))
    };
    named(key)
        || CONTAINERS.contains(&key)
        || ERROR_SUFFIXES
            .iter()
            .any(|s| key.strip_suffix(s).is_some_and(named))
}

/// Every key of every object in `v` that is not allowed, once each, with the
/// path of its first occurrence.
fn offending(
    v: &serde_json::Value,
    path: &str,
    names: &BTreeSet<String>,
    out: &mut Vec<(String, String)>,
) {
    match v {
        serde_json::Value::Object(map) => {
            for (k, child) in map {
                let here = format!("{path}.{k}");
                if !allowed(k, names) && !out.iter().any(|(key, _)| key == k) {
                    out.push((k.clone(), here.clone()));
                }
                offending(child, &here, names, out);
            }
        }
        serde_json::Value::Array(items) => {
            for (i, child) in items.iter().enumerate() {
                offending(child, &format!("{path}[{i}]"), names, out);
            }
        }
        _ => {}
    }
}

/// One command to run with `--json`: its spellings, newest first (a renamed
/// subcommand is tried under its old name when the new one does not exist).
fn commands(out_dir: &Path) -> Vec<Vec<Vec<String>>> {
    let words = |s: &str| s.split_whitespace().map(String::from).collect::<Vec<_>>();
    let mut list: Vec<Vec<Vec<String>>> = [
        "spectrum --example",
        "magnification --example --pressure 1e6|g --example --pressure 1e6",
        "area --example",
        "area --example --theory bush --pressure 1e5,1e8",
        "area --example --theory greenwood-williamson --pressure 1e6",
        "area --example --theory overlap --yield-stress 1e9 --pressure 1e6",
        "area --surface tests/reference/data/map_a.npy --pixel-size 1e-6 --contact-modulus 1e9 --theory greenwood-williamson --pressure 1e6",
        "kappa --example",
        "stress --start hertz --g 0.6 --points 11",
        "stress --example --ball-radius 0.01 --load 10 --zeta 10 --yield-stress 1e8 --points 5",
        "separation --example",
        "separation --example --pressure 1e6 --separation-density --density-points 3",
        "adhesion --hurst 0.8 --q-l 1e4 --q-s 1e6 --c-r 1e-19 --contact-modulus 1e6 --work-of-adhesion 1 --pressure -1e5,-4e4,1e3 --adhesion-range 1e-9 --points 3",
        "friction --example --standard-linear-solid 3e8,3e6,1e-4 --pressure 2e5 --velocity 1e-2,1 --flash-temperature --thermal-conductivity 0.25 --density 1200 --heat-capacity 1500",
        "conductance --example --conductivity 50,20 --resistivity 1e-7 --gas-conductivity 0.026 --mean-free-path 7e-8",
        "leakage --example --viscosity 1e-3 --pressure-drop 1e5",
        "leakage --example --viscosity 1e-5 --inlet-pressure 2e5 --outlet-pressure 1e5",
        "bem rough --example --grid 32 --conductivity 50 --resistivity 1e-7 --gas-conductivity 0.026 --mean-free-path 7e-8 --leakage --viscosity 1e-3 --pressure-drop 1e5",
        "bem hertz --grid 32",
        "bem hertz --grid 16 --boundary periodic --work-of-adhesion 1e-4 --adhesion-range 0.01",
        "bem rough --example --grid 32 --work-of-adhesion 1e-3 --adhesion-range 1e-7 --mean-gap 1e-6,2e-6",
        "bem hertz --grid 16,32 --yield-stress 0.05",
        "bem rough --example --grid 32",
        "bem rough --example --grid 32 --pressure 1e7 --patches --subsurface --depth 1e-5,1e-4 --tensile-yield-stress 1e8",
        "bem hertz --grid 32 --subsurface",
        "compare --example --grid 32 --levels 2",
        "compare --example --grid 32 --levels 2 --anisotropy 3",
        "compare --example --grid 32 --levels 2 --yield-stress 6e6",
        "compare --example --grid 32 --levels 2 --pressure 1e5,3e6 --leakage --viscosity 1e-3 --pressure-drop 1e5 --conductance --conductivity 50 --resistivity 1e-7 --gas-conductivity 0.026 --mean-free-path 6.8e-8",
        "compare ensemble --example --grid 32 --levels 2 --seeds 2 --pressure 1e6 --threads 1",
        "spectrum --surface tests/reference/data/map_a.npy --pixel-size 1e-6",
        "spectrum --surface docs/data/scan_coarse.npy --surface docs/data/scan_fine.npy --pixel-size 7.8125e-6,3.90625e-6",
        "spectrum --surface docs/data/scan_coarse.npy --surface docs/data/scan_fine.npy --pixel-size 7.8125e-6,3.90625e-7",
        "area --example --psd2 tests/reference/data/psd_second_body.csv",
        "compare --surface tests/reference/data/map_b.npy --pixel-size 2e-6 --periodic --contact-modulus 1e9",
        "report stability",
    ]
    .iter()
    .map(|c| c.split('|').map(words).collect())
    .collect();
    for scene in scenes() {
        // --out keeps the plots and tables a scene writes out of the source tree.
        let mut args = vec!["run".to_string(), scene.display().to_string()];
        args.extend(["--out".to_string(), out_dir.display().to_string()]);
        list.push(vec![args]);
    }
    for spellings in &mut list {
        for args in spellings.iter_mut() {
            args.push("--json".into());
        }
    }
    list
}

/// Every shipped scene, `scenes/*.json` (but the scene file's JSON Schema).
fn scenes() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("read scenes/").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no scenes in {}", dir.display());
    files
}

#[test]
fn every_json_key_is_a_name() {
    let names = names();
    let out_dir = std::env::temp_dir().join(format!("persson-names-{}", std::process::id()));
    std::fs::create_dir_all(&out_dir).expect("create the scene output directory");
    let mut problems = Vec::new();
    for spellings in commands(&out_dir) {
        let mut result = None;
        for args in &spellings {
            let argv: Vec<&str> = args.iter().map(String::as_str).collect();
            let (code, stdout, stderr) = common::persson(&argv);
            result = Some((args.join(" "), code, stdout, stderr));
            if code == 0 {
                break;
            }
        }
        let (command, code, stdout, stderr) = result.expect("at least one spelling");
        if code != 0 {
            let first = stderr.lines().next().unwrap_or_default();
            problems.push(format!("persson {command}: exit code {code}: {first}"));
            continue;
        }
        match serde_json::from_str::<serde_json::Value>(&stdout) {
            Ok(v) => {
                let mut keys = Vec::new();
                offending(&v, "", &names, &mut keys);
                for (key, path) in keys {
                    problems.push(format!("persson {command}: key `{key}` (at {path})"));
                }
            }
            Err(e) => problems.push(format!("persson {command}: stdout is not JSON: {e}")),
        }
    }
    let _ = std::fs::remove_dir_all(&out_dir);
    for p in &problems {
        println!("{p}");
    }
    assert!(
        problems.is_empty(),
        "{} JSON keys or commands outside src/names.md (listed above, one per line)",
        problems.len()
    );
}

//! Scene files: parsing, errors with line and column, computing only what a
//! scene asks for, and every number against an oracle (closed forms,
//! identities, the subcommand of the same name to the last digit).

use std::path::{Path, PathBuf};

use persson::Error;
use persson_studies::scene::{ConventionName, StartName};
use persson_studies::scene::{Scene, TheoryName};
use persson_studies::table::number;

fn parse(text: &str) -> Result<Scene, Error> {
    Scene::parse(Path::new("test.json"), text)
}

/// E* = 1, rms slope 1 over [1, 100]: G = (E*/σ0)² h'²/8 at full magnification.
const BASE: &str = r#"{
  "schema": 1,
  "material": { "contact_modulus": 1.0 },
  "spectrum": { "kind": "self_affine", "hurst": 0.8, "q_l": 1.0, "q_s": 100.0, "rms_slope": 1.0 },
  "nominal_pressure": [0.01, 0.1],
  "outputs": OUTPUTS
}"#;

fn scene(outputs: &str) -> String {
    BASE.replace("OUTPUTS", outputs)
}

/// G from a quadrature of q³C: relative error of a few ulps times the integral's.
const G_REL_TOL: f64 = 1e-13;
/// erf and the propagated error of G.
const AREA_ABS_TOL: f64 = 1e-13;
/// Closed forms of the stress distribution's areas (tests/stress.rs uses the same).
const CLOSED_FORM_TOL: f64 = 1e-14;
/// Simpson's rule on 2001 points of a smooth density (its error is below 1e-11 here).
const SIMPSON_TOL: f64 = 1e-11;

fn scratch(name: &str) -> PathBuf {
    let d =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("scene-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// ∫ y dx by Simpson's rule on an even number of equal intervals.
fn simpson(x: &[f64], y: &[f64]) -> f64 {
    assert!(x.len() % 2 == 1 && x.len() >= 3);
    let h = (x[x.len() - 1] - x[0]) / (x.len() - 1) as f64;
    let inner: f64 = y[1..y.len() - 1]
        .iter()
        .enumerate()
        .map(|(i, v)| if i % 2 == 0 { 4.0 * v } else { 2.0 * v })
        .sum();
    h / 3.0 * (y[0] + inner + y[y.len() - 1])
}

#[test]
fn errors_name_field_line_and_column() {
    let cases: [(String, usize, &str); 8] = [
        (scene(r#"{ "area": { "zetta": 3 } }"#), 6, "unknown field `zetta`"),
        (
            BASE.replace("\"hurst\"", "\"hurts\"").replace("OUTPUTS", "{}"),
            4,
            "unknown field `hurts`",
        ),
        (BASE.replace("0.8", "\"0.8\"").replace("OUTPUTS", "{}"), 4, "invalid type"),
        (
            BASE.replace("\"schema\": 1", "\"schema\": 2").replace("OUTPUTS", "{}"),
            0,
            "schema",
        ),
        (scene(r#"{ "area": {} "#), 7, "EOF"),
        (
            BASE.replace("\"nominal_pressure\": [0.01, 0.1],", "")
                .replace("OUTPUTS", "{}")
                .replace("\"outputs\"", "\"output\""),
            6,
            "unknown field `output`",
        ),
        (
            scene(r#"{ "stress": { "start": "wedge", "g": [1] } }"#),
            6,
            "unknown variant `wedge`, expected one of `flat`, `hertz`, `cylinder`",
        ),
        (
            scene(r#"{ "area": { "theory": "persson" } }"#),
            6,
            "unknown variant `persson`, expected one of `original`, `yang-persson`, `wang-muser`, `xu`",
        ),
    ];
    for (text, line, needle) in cases {
        match parse(&text) {
            Err(Error::Parse {
                line: l, message, ..
            }) => {
                assert_eq!(l, line, "{message}");
                assert!(message.contains(needle), "{message}");
            }
            other => panic!("expected a parse error containing {needle}, got {other:?}"),
        }
    }
}

#[test]
fn the_pressures_key_of_persson_0_1_is_still_read() {
    let old = scene(r#"{ "area": {} }"#).replace("\"nominal_pressure\"", "\"pressures\"");
    let a = parse(&old).unwrap().run().unwrap().area.unwrap();
    let b = parse(&scene(r#"{ "area": {} }"#))
        .unwrap()
        .run()
        .unwrap()
        .area
        .unwrap();
    assert_eq!(a, b);
}

#[test]
fn invalid_values_are_named_with_their_section() {
    for (from, to, needle) in [
        ("\"hurst\": 0.8", "\"hurst\": 1.2", "spectrum.hurst"),
        (
            "\"contact_modulus\": 1.0",
            "\"contact_modulus\": -1",
            "material.contact_modulus",
        ),
        ("[0.01, 0.1]", "[]", "nominal_pressure"),
    ] {
        let s = BASE
            .replace(from, to)
            .replace("OUTPUTS", r#"{ "area": {} }"#);
        let e = parse(&s).unwrap().run().unwrap_err().to_string();
        assert!(e.contains(needle), "{e}");
    }
}

/// Every closed set is spelled the same in scenes (serde) and on the command
/// line (clap), and `name()` says so.
#[test]
fn closed_sets_are_spelled_as_on_the_command_line() {
    use clap::ValueEnum;
    fn check<
        T: ValueEnum
            + serde::Serialize
            + serde::de::DeserializeOwned
            + PartialEq
            + std::fmt::Debug
            + Copy,
    >(
        all: &[T],
        name: impl Fn(T) -> &'static str,
    ) {
        for &v in all {
            let clap = v.to_possible_value().unwrap();
            assert_eq!(clap.get_name(), name(v));
            assert_eq!(
                serde_json::to_string(&v).unwrap(),
                format!("\"{}\"", name(v))
            );
            let back: T = serde_json::from_str(&format!("\"{}\"", name(v))).unwrap();
            assert_eq!(back, v);
        }
    }
    /// The numerics' closed sets, through the studies' value parser.
    fn check_named<T: persson::names::Named + Send + Sync + serde::Serialize + std::fmt::Debug>() {
        use clap::builder::TypedValueParser;
        let parser = persson_studies::scene::by_name::<T>();
        let clap: Vec<_> = parser
            .possible_values()
            .unwrap()
            .map(|v| v.get_name().to_string())
            .collect();
        assert_eq!(clap, T::names().collect::<Vec<_>>());
        for &(v, name, _) in T::VALUES {
            assert_eq!(serde_json::to_string(&v).unwrap(), format!("\"{name}\""));
        }
    }
    check(ConventionName::ALL, ConventionName::name);
    check_named::<persson::bem::Boundary>();
    check(StartName::ALL, StartName::name);
    check(TheoryName::ALL, TheoryName::name);
    assert_eq!(ConventionName::Profile1d.name(), "profile1d");
    assert_eq!(
        ConventionName::SurfaceTopography.name(),
        "surface-topography"
    );
}

/// A tabulated spectrum in the SurfaceTopography convention (C·(2π)²) gives
/// the same G as the same spectrum in Persson's.
#[test]
fn tabulated_conventions_are_read_by_name() {
    let dir = scratch("psd");
    let rows = |scale: f64| -> String {
        (0..=20)
            .map(|i| {
                let q = 10f64.powf(i as f64 / 10.0);
                format!("{q:e},{:e}\n", scale * q.powf(-3.6))
            })
            .collect()
    };
    let tau2 = std::f64::consts::TAU * std::f64::consts::TAU;
    std::fs::write(dir.join("p.csv"), rows(1.0)).unwrap();
    std::fs::write(dir.join("st.csv"), rows(tau2)).unwrap();
    let run = |file: &str, convention: &str| {
        let text = format!(
            r#"{{"schema": 1, "material": {{"contact_modulus": 1}},
               "spectrum": {{"kind": "tabulated", "file": "{file}", "convention": "{convention}"}},
               "nominal_pressure": [0.01], "outputs": {{"area": {{}}}}}}"#
        );
        Scene::parse(&dir.join("s.json"), &text)
            .unwrap()
            .run()
            .unwrap()
            .area
            .unwrap()
            .points[0]
            .g
    };
    let (a, b) = (run("p.csv", "persson"), run("st.csv", "surface-topography"));
    assert!((a - b).abs() <= G_REL_TOL * a, "{a} vs {b}");
    // The 1D convention parses under its CLI name (it was `profile1_d`).
    let text = r#"{"schema": 1, "spectrum": {"kind": "tabulated", "file": "x.csv", "convention": "profile1d"}, "outputs": {}}"#;
    assert!(parse(text).is_ok());
    let grid = r#"{"schema": 1, "material": {"contact_modulus": 1}, "spectrum": {"kind": "tabulated", "file": "p.csv", "convention": "grid"}, "nominal_pressure": [0.1], "outputs": {"area": {}}}"#;
    let e = Scene::parse(&dir.join("s.json"), grid)
        .unwrap()
        .run()
        .unwrap_err()
        .to_string();
    assert!(e.contains("spectrum.size"), "{e}");
}

#[test]
fn stress_output_matches_closed_forms_and_integrates_to_the_area() {
    let s = parse(
        r#"{"schema": 1, "outputs": {"stress": {"start": "hertz", "g": [0.6, 2], "points": 2001}}}"#,
    )
    .unwrap();
    let r = s.run().unwrap();
    assert!(
        r.area.is_none() && r.theories.is_none(),
        "only the stress output"
    );
    let st = r.stress.unwrap();
    assert_eq!(st.curves.len(), 2);
    for (c, g) in st.curves.iter().zip([0.6f64, 2.0]) {
        // Hertz start: A/A0 = erf(c)(1 − 1/(2c²)) + e^{−c²}/(c√π), c = 3/(4√G)
        // (Persson, Bucher & Chiaia 2002, Fig. 3: 0.615097, 0.377787).
        let x = 0.75 / g.sqrt();
        let want = libm::erf(x) * (1.0 - 0.5 / (x * x))
            + (-x * x).exp() / (x * std::f64::consts::PI.sqrt());
        assert!(
            (c.contact_fraction - want).abs() < CLOSED_FORM_TOL,
            "{}",
            c.contact_fraction
        );
        assert_eq!(c.contact_fraction, c.elastic_fraction + c.plastic_fraction);
        assert_eq!(c.sigma_ratio.len(), 2001);
        // ∫ P dσ = A/A0.
        let integral = simpson(&c.sigma_ratio, &c.scaled_density);
        assert!(
            (integral - c.contact_fraction).abs() < SIMPSON_TOL,
            "{integral} vs {}",
            c.contact_fraction
        );
    }
    assert!((st.curves[0].contact_fraction - 0.615_097).abs() < 5e-7);
    assert!((st.curves[1].contact_fraction - 0.377_787).abs() < 5e-7);
}

#[test]
fn stress_output_in_the_pressure_unit() {
    // Flat start at σ0 = 0.1 E*: G(ζ) from the core, A/A0 = erf(1/(2√G)).
    let s = parse(&scene(
        r#"{"stress": {"start": "flat", "peak_pressure": 0.1, "zeta": [10, 100], "points": 5}}"#,
    ))
    .unwrap();
    let st = s.run().unwrap().stress.unwrap();
    assert_eq!(st.peak_pressure, Some(0.1));
    for c in &st.curves {
        let exact = libm::erf(0.5 / c.g.sqrt());
        assert!(
            (c.contact_fraction - exact).abs() < AREA_ABS_TOL,
            "{} vs {exact}",
            c.contact_fraction
        );
        assert!(c.zeta.is_some() && c.sigma.len() == 5 && c.sigma_ratio.is_empty());
    }
    // With a yield stress the σ grid ends at σY: ∫₀^σY P dσ = A_el/A0, and
    // contact_fraction is the total A_el/A0 + A_pl/A0.
    let s = parse(&scene(
        r#"{"stress": {"start": "hertz", "peak_pressure": 0.1, "yield_stress": 0.15, "zeta": [100], "points": 2001}}"#,
    ))
    .unwrap();
    let c = &s.run().unwrap().stress.unwrap().curves[0];
    let integral = simpson(&c.sigma, &c.density);
    assert!(
        (integral - c.elastic_fraction).abs() < SIMPSON_TOL,
        "{integral} vs {}",
        c.elastic_fraction
    );
    assert!(c.plastic_fraction > 0.0);
    assert_eq!(c.contact_fraction, c.elastic_fraction + c.plastic_fraction);
    let bad = parse(&scene(r#"{"stress": {"start": "hertz", "zeta": [10]}}"#))
        .unwrap()
        .run()
        .unwrap_err();
    assert!(bad.to_string().contains("outputs.stress"), "{bad}");
}

#[test]
fn theories_and_separation_outputs() {
    let s = parse(&scene(r#"{"theories": {"theories": [{"theory": "original"}, {"theory": "xu", "gamma": 1.0}]}, "separation": {}}"#)).unwrap();
    let r = s.run().unwrap();
    let t = r.theories.unwrap();
    assert_eq!(t.curves[1].theory, TheoryName::Xu);
    // Xu with γ = 1 is the original theory.
    for (a, b) in t.curves[0].points.iter().zip(&t.curves[1].points) {
        assert!(
            (a.contact_fraction - b.contact_fraction).abs()
                < 1e-12 * a.contact_fraction.max(1e-300) + 1e-15
        );
        let exact = libm::erf(0.5 / a.g.sqrt());
        assert!((a.contact_fraction - exact).abs() < AREA_ABS_TOL);
    }
    let sep = r.separation.unwrap();
    assert_eq!(sep.points.len(), 2);
    assert!(sep.points[0].mean_separation > sep.points[1].mean_separation);
    assert!(sep.points[1].mean_separation > 0.0 && sep.low_load_length > 0.0);
    let e = parse(&scene(
        r#"{"theories": {"theories": [{"theory": "yang-persson", "gamma": 7}]}}"#,
    ))
    .unwrap()
    .run()
    .unwrap_err();
    assert!(e.to_string().contains("gamma"), "{e}");
}

/// Every shipped scene runs, and its name states the numbers it computes.
#[test]
fn shipped_scenes_run_and_their_titles_match() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("scenes");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let s = Scene::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let name = s.name.clone().unwrap();
        for label in ["seed 0", "Seed 0", "lecture 000", "closure"] {
            assert!(!name.contains(label), "{}: {name}", path.display());
        }
        if cfg!(not(feature = "bem")) && (s.outputs.bem.is_some() || s.outputs.bem_hertz.is_some())
        {
            let e = s.run().unwrap_err().to_string();
            assert!(e.contains("`bem` feature"), "{}: {e}", path.display());
            continue;
        }
        let r = s
            .run()
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        // Stress scenes print A/A0 of each curve in their name, to 3 digits.
        for c in r.stress.iter().flat_map(|st| &st.curves) {
            let a = number(c.contact_fraction, 3);
            assert!(
                name.contains(&a),
                "{}: {name} lacks A/A0 = {a}",
                path.display()
            );
        }
        n += 1;
    }
    assert!(n >= 6, "{n} scenes");
}

/// Every JSON key of a scene report is snake_case.
#[test]
fn report_keys_are_snake_case() {
    fn walk(v: &serde_json::Value, bad: &mut Vec<String>) {
        match v {
            serde_json::Value::Object(m) => {
                for (k, x) in m {
                    if !k
                        .chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
                    {
                        bad.push(k.clone());
                    }
                    walk(x, bad);
                }
            }
            serde_json::Value::Array(a) => a.iter().for_each(|x| walk(x, bad)),
            _ => {}
        }
    }
    let r = parse(&scene(
        r#"{"spectrum": {}, "area": {"theory": "xu"}, "magnification": {"nominal_pressure": 0.1, "points": 3},
            "kappa": {}, "theories": {}, "separation": {},
            "stress": {"start": "cylinder", "peak_pressure": 0.1, "zeta": [10], "points": 3}}"#,
    ))
    .unwrap()
    .run()
    .unwrap();
    let v = serde_json::to_value(&r).unwrap();
    let mut bad = Vec::new();
    walk(&v, &mut bad);
    assert!(bad.is_empty(), "{bad:?}");
    for key in [
        "spectrum",
        "area",
        "magnification",
        "kappa",
        "theories",
        "separation",
        "stress",
    ] {
        assert!(v.get(key).is_some(), "{key}");
    }
}

/// The JSON Schemas of `compare`'s specs in crates/persson-studies/schema/
/// (sweep, compare and ensemble.schema.json) are the ones their types
/// generate (regenerate with PERSSON_WRITE_SCHEMA=1): Python's tests check
/// `compare`'s and `ensemble`'s keywords against them.
#[cfg(feature = "bem")]
#[test]
fn compare_schema_files_are_generated_from_the_types() {
    use persson_studies::validation::{spec_schema, CompareSpec, EnsembleSpec, SweepSpec};
    generated("sweep.schema.json", &spec_schema::<SweepSpec>());
    generated("compare.schema.json", &spec_schema::<CompareSpec>());
    generated("ensemble.schema.json", &spec_schema::<EnsembleSpec>());
}

/// `crates/persson-studies/schema/<name>` holds `want` (written there with
/// PERSSON_WRITE_SCHEMA=1).
fn generated(name: &str, want: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../persson-studies/schema")
        .join(name);
    if std::env::var_os("PERSSON_WRITE_SCHEMA").is_some() {
        std::fs::write(&path, want).unwrap();
    }
    let got = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        got == want,
        "crates/persson-studies/schema/{name} is stale: run \
         PERSSON_WRITE_SCHEMA=1 cargo test -p persson-cli --features full --test suite"
    );
}

/// The JSON Schema in crates/persson-studies/schema/scene.schema.json (apart
/// from the scenes, so that `persson run scenes/*.json` runs every file) is
/// the one the types generate (regenerate with PERSSON_WRITE_SCHEMA=1).
#[test]
fn schema_file_is_generated_from_the_types() {
    let want = persson_studies::scene::json_schema();
    generated("scene.schema.json", &want);
    // Every field of the scene file is documented in the guide's page on scenes.
    let section = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join("docs/scenes.md"),
    )
    .unwrap();
    let schema: serde_json::Value = serde_json::from_str(&want).unwrap();
    let mut keys = Vec::new();
    collect_properties(&schema, &mut keys);
    for k in keys {
        assert!(
            section.contains(&format!("`{k}`")),
            "docs/scenes.md lacks `{k}`"
        );
    }
}

fn collect_properties(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Object(m) => {
            if let Some(serde_json::Value::Object(p)) = m.get("properties") {
                out.extend(p.keys().cloned());
            }
            m.values().for_each(|x| collect_properties(x, out));
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| collect_properties(x, out)),
        _ => {}
    }
}

use crate::common;

/// The subcommands print the very numbers of the scene outputs of the same name.
mod cli {
    use super::*;
    use common::{json, persson};

    const FLAGS: [&str; 10] = [
        "--hurst",
        "0.8",
        "--q-l",
        "1",
        "--q-s",
        "100",
        "--rms-slope",
        "1",
        "--contact-modulus",
        "1",
    ];

    fn with(cmd: &str, extra: &[&str]) -> serde_json::Value {
        let mut a = vec![cmd];
        a.extend_from_slice(&FLAGS);
        a.extend_from_slice(extra);
        a.push("--json");
        body(json(&a))
    }

    /// A subcommand's JSON without its top-level `warnings` (which a scene
    /// gathers at its own top level).
    fn body(mut v: serde_json::Value) -> serde_json::Value {
        let w = v.as_object_mut().unwrap().remove("warnings");
        assert!(w.is_some_and(|w| w.is_array()), "no warnings array");
        v
    }

    fn run_scene(outputs: &str) -> serde_json::Value {
        let dir = scratch("same");
        let p = dir.join("s.json");
        std::fs::write(&p, scene(outputs)).unwrap();
        json(&["run", p.to_str().unwrap(), "--json"])
    }

    #[test]
    fn subcommands_equal_scene_outputs_to_the_last_digit() {
        let r = run_scene(
            r#"{"area": {"theory": "yang-persson"}, "separation": {}, "kappa": {},
                "magnification": {"nominal_pressure": 0.1, "zeta": [1, 10, 100]},
                "separation_density": {"density_points": 21}}"#,
        );
        assert_eq!(
            with(
                "separation",
                &[
                    "--pressure",
                    "0.01,0.1",
                    "--separation-density",
                    "--density-points",
                    "21"
                ]
            ),
            r["separation_density"]
        );
        let area = with(
            "area",
            &["--pressure", "0.01,0.1", "--theory", "yang-persson"],
        );
        assert_eq!(area, r["area"]);
        assert_eq!(
            with("separation", &["--pressure", "0.01,0.1"]),
            r["separation"]
        );
        assert_eq!(with("kappa", &["--pressure", "0.01,0.1"]), r["kappa"]);
        let sp = run_scene(r#"{"spectrum": {"q_min": 2, "points": 5}}"#);
        let cli = json(&[
            "spectrum",
            "--hurst",
            "0.8",
            "--q-l",
            "1",
            "--q-s",
            "100",
            "--rms-slope",
            "1",
            "--q-min",
            "2",
            "--points",
            "5",
            "--json",
        ]);
        let cli = body(cli);
        assert_eq!(cli, sp["spectrum"]);
        assert_eq!(
            with(
                "magnification",
                &["--pressure", "0.1", "--zeta", "1,10,100"]
            ),
            r["magnification"]
        );
        let st = run_scene(r#"{"stress": {"start": "cylinder", "g": [0.6], "points": 11}}"#);
        let cli = json(&[
            "stress", "--start", "cylinder", "--g", "0.6", "--points", "11", "--json",
        ]);
        let cli = body(cli);
        assert_eq!(cli, st["stress"]);
    }

    /// `persson stress` in physical units prints the scene's physical stress
    /// output to the last digit (and the same warnings), for each contact.
    #[test]
    fn physical_stress_equals_the_scene_to_the_last_digit() {
        // The rail–wheel scene as shipped (σH = 542 MPa, cylinder start).
        let dir = scratch("rail");
        let rail = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join("scenes/rail_wheel.json");
        let r = json(&[
            "run",
            rail.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
            "--json",
        ]);
        let words = "stress --young 1e11 --poisson 0.3 --hurst 0.5 --q-l 628.3185307179587 \
                     --q-r 2e4 --q-s 1e9 --rms-height 6.717514421272201e-7 --start cylinder \
                     --peak-pressure 542e6 --zeta 100,400 --points 201 --json";
        let args: Vec<&str> = words.split_whitespace().collect();
        let mut cli = json(&args);
        assert_eq!(cli["warnings"], r["warnings"], "rail–wheel warnings");
        let cli = body(cli.take());
        assert_eq!(cli, r["stress"]);
        assert_eq!(cli["curves"].as_array().unwrap().len(), 2);

        // A ball, a cylinder and a flat punch on the example surface, with a yield stress.
        let example = r#""material": {"contact_modulus": 1e9},
            "spectrum": {"kind": "self_affine", "hurst": 0.8, "q_l": 1e4, "q_r": 1e5, "q_s": 1e8, "rms_height": 1e-6}"#;
        for (stress, flags) in [
            (
                r#"{"start": "hertz", "ball": {"radius": 0.01, "load": 10}, "zeta": [10, 100], "yield_stress": 3e8, "points": 51}"#,
                "--ball-radius 0.01 --load 10 --zeta 10,100 --yield-stress 3e8 --points 51",
            ),
            (
                r#"{"start": "cylinder", "cylinder": {"radius": 0.5, "load_per_length": 1e5}, "zeta": [1, 1000], "points": 31}"#,
                "--cylinder-radius 0.5 --load-per-length 1e5 --zeta 1,1000 --points 31",
            ),
            (
                r#"{"start": "flat", "peak_pressure": 1e7, "zeta": [10000], "yield_stress": 5e7, "tolerance": 1e-10, "points": 11}"#,
                "--flat --pressure 1e7 --yield-stress 5e7 --tolerance 1e-10 --points 11",
            ),
        ] {
            let d = scratch("phys");
            let p = d.join("s.json");
            std::fs::write(
                &p,
                format!(r#"{{"schema": 1, {example}, "outputs": {{"stress": {stress}}}}}"#),
            )
            .unwrap();
            let sc = json(&["run", p.to_str().unwrap(), "--json"]);
            let mut args = vec!["stress", "--example"];
            args.extend(flags.split_whitespace());
            args.push("--json");
            let mut cli = json(&args);
            assert_eq!(cli["warnings"], sc["warnings"], "{flags}");
            assert_eq!(body(cli.take()), sc["stress"], "{flags}");
        }
        // The ball's smooth start: a = (3FR/(4E*))^(1/3), σH = 3F/(2πa²) (Johnson, Eqs. 4.22–4.24).
        let v = json(&[
            "stress",
            "--example",
            "--ball-radius",
            "0.01",
            "--load",
            "10",
            "--json",
        ]);
        let a = (3.0 * 10.0 * 0.01 / (4.0 * 1e9f64)).cbrt();
        let sh = 3.0 * 10.0 / (2.0 * std::f64::consts::PI * a * a);
        let rel = |x: &serde_json::Value, y: f64| (x.as_f64().unwrap() / y - 1.0).abs();
        assert!(
            rel(&v["contact_radius"], a) < 1e-14,
            "{}",
            v["contact_radius"]
        );
        assert!(
            rel(&v["peak_pressure"], sh) < 1e-14,
            "{}",
            v["peak_pressure"]
        );
        assert!(rel(&v["nominal_pressure"], 2.0 * sh / 3.0) < 1e-14);
        // Default ζ: full magnification q_s/q_l = 1e4.
        assert_eq!(v["curves"][0]["zeta"], serde_json::json!(1e4));
    }

    #[test]
    fn run_out_creates_the_directory_and_writes_one_csv_per_table() {
        let dir = scratch("out").join("a/b");
        let scene = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join("scenes/fig3_hertz.json");
        let (code, out, err) = persson(&[
            "run",
            scene.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(
            out.contains("G = 0.6") && !out.contains("None") && !out.contains("Some("),
            "{out}"
        );
        assert!(dir.join("report.json").exists());
        // serde_json's float parsing may be 1 ulp off: compare with the report itself.
        let report = Scene::read(&scene).unwrap().run().unwrap().stress.unwrap();
        for (name, k) in [("stress_G0", 0), ("stress_G0.6", 1), ("stress_G2", 2)] {
            let text = std::fs::read_to_string(dir.join(format!("{name}.csv"))).unwrap();
            assert!(err.contains(&format!("{name}.csv")), "{err}");
            let mut lines = text.lines();
            assert_eq!(lines.next(), Some("sigma_ratio,scaled_density"));
            let curve = &report.curves[k];
            let mut rows = 0;
            for (i, line) in lines.enumerate() {
                let cells: Vec<&str> = line.split(',').collect();
                assert_eq!(cells.len(), 2, "{name}: {line}");
                let s: f64 = cells[0].parse().unwrap();
                let p: f64 = cells[1].parse().unwrap();
                assert_eq!((s, p), (curve.sigma_ratio[i], curve.scaled_density[i]));
                rows += 1;
            }
            assert_eq!(rows, 201);
        }
        assert!(dir.join("fig3_hertz.svg").exists());
    }

    #[test]
    fn run_csv_writes_files_into_the_current_directory() {
        let dir = scratch("csv");
        let scene = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join("scenes/theories.json");
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_persson"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(["run", scene.to_str().unwrap(), "--csv"])
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(out.status.success());
        assert!(out.stdout.is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        for name in [
            "theories_original",
            "theories_yang-persson",
            "theories_wang-muser",
            "theories_xu",
            "separation",
        ] {
            let text = std::fs::read_to_string(dir.join(format!("{name}.csv"))).unwrap();
            assert!(err.contains(&format!("{name}.csv")), "{err}");
            let width = text.lines().next().unwrap().split(',').count();
            assert_eq!(text.lines().count(), 9, "{name}: header and 8 pressures");
            assert!(
                text.lines().all(|l| l.split(',').count() == width),
                "{name}"
            );
        }
        // γ is printed as a number, never as Rust's Option.
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_persson"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(["run", scene.to_str().unwrap()])
            .current_dir(&dir)
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            text.contains("γ = 0.45") && !text.contains("None") && !text.contains("Some("),
            "{text}"
        );
    }
}

//! Scene files: parsing, errors with line and column, and computing only what
//! a scene asks for.

use std::path::Path;

use persson::scene::Scene;
use persson::Error;

fn parse(text: &str) -> Result<Scene, Error> {
    Scene::parse(Path::new("test.json"), text)
}

const BASE: &str = r#"{
  "schema": 1,
  "material": { "contact_modulus": 1.0 },
  "spectrum": { "kind": "self_affine", "hurst": 0.8, "q_l": 1.0, "q_s": 100.0, "rms_slope": 1.0 },
  "pressures": [0.01, 0.1],
  "outputs": OUTPUTS
}"#;

fn scene(outputs: &str) -> String {
    BASE.replace("OUTPUTS", outputs)
}

#[test]
fn computes_only_what_is_asked() {
    let r = parse(&scene(r#"{ "kappa": {} }"#)).unwrap().run().unwrap();
    assert!(r.kappa.is_some() && r.area.is_none() && r.magnification.is_none());
    let r = parse(&scene(r#"{ "area": {} }"#)).unwrap().run().unwrap();
    assert!(r.kappa.is_none() && r.magnification.is_none());
    let area = r.area.unwrap();
    assert_eq!(area.len(), 2);
    // G = (E*/σ0)² s²/8 with s = 1 at full magnification.
    assert!((area[0].g - 1e4 / 8.0).abs() < 1e-10);
    let json =
        serde_json::to_value(parse(&scene(r#"{ "kappa": {} }"#)).unwrap().run().unwrap()).unwrap();
    assert!(
        json.get("area").is_none(),
        "absent outputs are not written: {json}"
    );
}

#[test]
fn kappa_alone_needs_no_material_or_spectrum() {
    let r = parse(r#"{"schema": 1, "outputs": {"kappa": {}}}"#)
        .unwrap()
        .run()
        .unwrap();
    assert!((r.kappa.unwrap().kappa_bush - (2.0 * std::f64::consts::PI).sqrt()).abs() < 1e-15);
}

#[test]
fn errors_name_field_line_and_column() {
    let cases: [(String, usize, &str); 6] = [
        (
            scene(r#"{ "area": { "zetta": 3 } }"#),
            6,
            "unknown field `zetta`",
        ),
        (
            BASE.replace("\"hurst\"", "\"hurts\"")
                .replace("OUTPUTS", "{}"),
            4,
            "unknown field `hurts`",
        ),
        (
            BASE.replace("0.8", "\"0.8\"").replace("OUTPUTS", "{}"),
            4,
            "invalid type",
        ),
        (
            BASE.replace("\"schema\": 1", "\"schema\": 2")
                .replace("OUTPUTS", "{}"),
            0,
            "schema",
        ),
        (scene(r#"{ "area": {} "#), 7, "EOF"),
        (
            BASE.replace("\"pressures\": [0.01, 0.1],", "")
                .replace("OUTPUTS", "{}")
                .replace("\"outputs\"", "\"output\""),
            6,
            "unknown field `output`",
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
fn invalid_values_are_named_with_their_section() {
    let s = BASE
        .replace("\"hurst\": 0.8", "\"hurst\": 1.2")
        .replace("OUTPUTS", r#"{ "area": {} }"#);
    let e = parse(&s).unwrap().run().unwrap_err().to_string();
    assert!(e.contains("spectrum.hurst"), "{e}");
    let s = BASE
        .replace("\"contact_modulus\": 1.0", "\"contact_modulus\": -1")
        .replace("OUTPUTS", r#"{ "area": {} }"#);
    let e = parse(&s).unwrap().run().unwrap_err().to_string();
    assert!(e.contains("material.contact_modulus"), "{e}");
    let s = BASE
        .replace("[0.01, 0.1]", "[]")
        .replace("OUTPUTS", r#"{ "area": {} }"#);
    let e = parse(&s).unwrap().run().unwrap_err().to_string();
    assert!(e.contains("pressures"), "{e}");
}

#[test]
fn shipped_scenes_parse_and_run() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "json") {
            let s = Scene::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            // Without the BEM, a scene naming a BEM output must say so.
            if cfg!(not(feature = "bem"))
                && (s.outputs.bem.is_some() || s.outputs.bem_hertz.is_some())
            {
                let e = s.run().unwrap_err().to_string();
                assert!(e.contains("`bem` feature"), "{}: {e}", path.display());
                continue;
            }
            s.run()
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            n += 1;
        }
    }
    assert!(n >= 1);
}

#[test]
fn stress_output_dimensionless_matches_seed_areas() {
    // ../shared/theory.md §3: Hertz start, A/A0 = 0.615097 and 0.377787 at G = 0.6, 2.
    let s = parse(
        r#"{"schema": 1, "outputs": {"stress": {"start": "hertz", "g": [0.6, 2], "points": 11}}}"#,
    )
    .unwrap();
    let r = s.run().unwrap();
    let st = r.stress.unwrap();
    assert_eq!(st.len(), 2);
    assert!((st[0].contact_fraction - 0.615_097).abs() < 5e-7);
    assert!((st[1].contact_fraction - 0.377_787).abs() < 5e-7);
    assert_eq!(st[0].sigma.len(), 11);
    assert!(
        r.area.is_none() && r.theories.is_none(),
        "only the stress output is computed"
    );
}

#[test]
fn stress_output_physical_uses_g_of_the_scene() {
    // Flat start at σ0 = 0.1 E*: G(ζ) from the core, A/A0 = erf(1/(2√G)).
    let s = parse(&scene(
        r#"{"stress": {"start": "flat", "peak_pressure": 0.1, "zetas": [10, 100], "points": 5}}"#,
    ))
    .unwrap();
    let st = s.run().unwrap().stress.unwrap();
    for c in &st {
        let exact = libm::erf(0.5 / c.g.sqrt());
        assert!(
            (c.contact_fraction - exact).abs() < 1e-13,
            "{} vs {exact}",
            c.contact_fraction
        );
        assert!(c.zeta.is_some());
    }
    let bad = parse(&scene(r#"{"stress": {"start": "hertz", "zetas": [10]}}"#))
        .unwrap()
        .run()
        .unwrap_err();
    assert!(bad.to_string().contains("outputs.stress"), "{bad}");
    let bad = parse(&scene(r#"{"stress": {"start": "wedge", "g": [1]}}"#))
        .unwrap()
        .run()
        .unwrap_err();
    assert!(bad.to_string().contains("start"), "{bad}");
}

#[test]
fn theories_and_separation_outputs() {
    let s = parse(&scene(r#"{"theories": {"theories": [{"theory": "original"}, {"theory": "xu", "gamma": 1.0}]}, "separation": {}}"#)).unwrap();
    let r = s.run().unwrap();
    let t = r.theories.unwrap();
    // Xu with γ = 1 is the original theory.
    for (a, b) in t[0].points.iter().zip(&t[1].points) {
        assert!(
            (a.contact_fraction - b.contact_fraction).abs()
                < 1e-12 * a.contact_fraction.max(1e-300) + 1e-15
        );
    }
    let sep = r.separation.unwrap();
    assert_eq!(sep.len(), 2);
    assert!(sep[0].mean_separation > sep[1].mean_separation && sep[1].mean_separation > 0.0);
    let e = parse(&scene(
        r#"{"theories": {"theories": [{"theory": "yang-persson", "gamma": 7}]}}"#,
    ))
    .unwrap()
    .run()
    .unwrap_err();
    assert!(e.to_string().contains("gamma"), "{e}");
}

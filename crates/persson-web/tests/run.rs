//! The module's entry point, natively: the same report as `Scene::run`, the
//! text `persson run` prints, files from memory, errors as messages.

use std::path::Path;

use persson_studies::scene::Scene;
use persson_web::run::{run, Outcome};
use serde_json::Value;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

fn done(text: &str) -> persson_web::run::Done {
    match run(text) {
        Outcome::Ok(d) => *d,
        Outcome::Error { error } => panic!("scene failed: {error}"),
    }
}

fn error(text: &str) -> String {
    match run(text) {
        Outcome::Error { error } => error,
        Outcome::Ok(_) => panic!("scene ran"),
    }
}

#[test]
fn the_report_is_the_scenes() {
    let text = std::fs::read_to_string(root().join("scenes/example.json")).unwrap();
    let d = done(&text);
    let scene = Scene::parse(Path::new("scene.json"), &text).unwrap();
    let report = scene.run().unwrap();
    let direct = serde_json::to_value(persson_studies::warning::Warned::new(
        &report,
        &report.warnings,
    ))
    .unwrap();
    assert_eq!(d.report, direct);
    // The text begins with the name and description, then the tables.
    assert!(d.text.starts_with("Built-in example"), "{}", d.text);
    let area = d.tables.iter().find(|t| t.name == "area").unwrap();
    assert!(d.text.contains(&area.text));
    // The values behind the plot are the report's, to the last bit.
    let col = area
        .keys
        .iter()
        .position(|k| k == "contact_fraction")
        .unwrap();
    let first = report.area.as_ref().unwrap().points[0].contact_fraction;
    assert_eq!(area.rows[0][col].as_f64(), Some(first));
    assert_eq!(area.rows.len(), 6);
}

#[test]
fn a_mounted_file_reads_as_the_same_file_on_disk() {
    let bytes = std::fs::read(root().join("docs/data/stretched.npy")).unwrap();
    persson::io::mount("web-test-stretched.npy", bytes);
    let scene = |file: &str| {
        format!(
            r#"{{"schema": 1, "material": {{"contact_modulus": 1e9}},
            "spectrum": {{"kind": "height_map", "file": "{file}", "size": 1e-4, "periodic": true}},
            "nominal_pressure": [1e6], "outputs": {{"spectrum": {{}}, "area": {{}}}}}}"#
        )
    };
    let memory = done(&scene("web-test-stretched.npy"));
    let disk_path = root().join("docs/data/stretched.npy");
    let disk = done(&scene(&disk_path.to_string_lossy()));
    // Equal but for the file's name in the texts.
    let disk_text = disk
        .report
        .to_string()
        .replace(&*disk_path.to_string_lossy(), "web-test-stretched.npy");
    assert_eq!(memory.report.to_string(), disk_text);
    assert!(memory.report["spectrum"].is_object(), "{}", memory.report);
}

#[test]
fn bad_input_is_a_message_naming_the_field() {
    let e = error(
        r#"{"schema": 1, "material": {"contact_modulus": -1}, "spectrum": {"kind": "self_affine", "hurst": 0.8, "q_l": 1e4, "q_r": 1e5, "q_s": 1e8, "rms_height": 1e-6}, "nominal_pressure": [1e6], "outputs": {"area": {}}}"#,
    );
    assert!(e.contains("material.contact_modulus"), "{e}");
    let e = error(r#"{"schema": 1, "outputs": {"area": {}}, "typo": 1}"#);
    assert!(e.starts_with("scene.json:1:"), "{e}");
    assert!(e.contains("typo"), "{e}");
    let e = error(
        r#"{"schema": 1, "material": {"contact_modulus": 1e9}, "spectrum": {"kind": "height_map", "file": "not-mounted.npy", "size": 1e-4}, "nominal_pressure": [1e6], "outputs": {"area": {}}}"#,
    );
    assert!(e.contains("not-mounted.npy"), "{e}");
}

#[test]
fn the_envelope_is_json_with_a_status() {
    let text = std::fs::read_to_string(root().join("scenes/example.json")).unwrap();
    let v: Value = serde_json::to_value(run(&text)).unwrap();
    assert_eq!(v["status"], "ok");
    assert!(v["report"]["area"].is_object());
    let v: Value = serde_json::to_value(run("{")).unwrap();
    assert_eq!(v["status"], "error");
    assert!(v["error"].as_str().unwrap().starts_with("scene.json:"));
}

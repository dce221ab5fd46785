//! Warnings (issue 15): each slip a user makes gives one line on stderr,
//! `persson: warning: …`, and an entry of the top-level `"warnings"` array of
//! `--json` (always present): an object with its `kind`, its typed fields and
//! its `message`, which names the input, never a flag (stderr adds the flag
//! in parentheses). A warning never changes a number.

use crate::common;

use common::persson;
use serde_json::Value;

/// Run with `--json`: (exit code, JSON, the `persson: warning:` lines of stderr).
fn run(args: &str) -> (Value, Vec<String>) {
    let mut argv: Vec<&str> = args.split_whitespace().collect();
    argv.push("--json");
    let (code, out, err) = persson(&argv);
    assert_eq!(code, 0, "persson {args}: {err}");
    let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args}: {e}\n{out}"));
    let lines: Vec<String> = err
        .lines()
        .filter(|l| l.starts_with("persson: warning: "))
        .map(String::from)
        .collect();
    (v, lines)
}

/// The messages of the `"warnings"` array, which every `--json` output has;
/// each warning is an object with a `kind` from the closed set and a `message`
/// that names no flag.
fn warnings(v: &Value) -> Vec<String> {
    const KINDS: [&str; 8] = [
        "high_pressure",
        "steep_slope",
        "zeta_beyond_band",
        "band_limited",
        "psd_convention",
        "rising_spectrum",
        "clipped_band",
        "map_not_periodic",
    ];
    v["warnings"]
        .as_array()
        .unwrap_or_else(|| panic!("no \"warnings\" array in {v}"))
        .iter()
        .map(|w| {
            let kind = w["kind"].as_str().expect("a warning has a kind");
            assert!(KINDS.contains(&kind), "{w}");
            let message = w["message"].as_str().expect("a warning has a message");
            assert!(!message.contains("--"), "a flag in {message}");
            message.to_string()
        })
        .collect()
}

/// Stderr and JSON carry the same warnings, one line each (stderr with the
/// flag that sets the input, if any, in parentheses after the message).
fn same(v: &Value, lines: &[String]) -> Vec<String> {
    let w = warnings(v);
    assert_eq!(
        w.len(),
        lines.len(),
        "stderr and --json disagree: {lines:?}"
    );
    for (x, l) in w.iter().zip(lines) {
        let printed = l.trim_start_matches("persson: warning: ");
        let hint = printed.strip_prefix(x.as_str());
        assert!(
            hint.is_some_and(|h| h.is_empty() || (h.starts_with(" (--") && h.ends_with(')'))),
            "stderr and --json disagree: {printed} against {x}"
        );
        assert!(!x.contains('\n'), "{x}");
    }
    w
}

/// Every number of the report but the `warnings`, for comparing two runs.
fn numbers(v: &Value) -> Value {
    let mut v = v.clone();
    v.as_object_mut().unwrap().remove("warnings");
    v
}

const SA: &str = "--hurst 0.8 --q-l 1e4 --q-r 1e5 --q-s 1e8";

#[test]
fn no_warning_gives_an_empty_array() {
    let (v, lines) = run(&format!(
        "area {SA} --rms-height 1e-6 --contact-modulus 1e9 --pressure 1e6"
    ));
    assert!(warnings(&v).is_empty() && lines.is_empty(), "{lines:?}");
    for args in ["stress --start hertz --g 0.6 --points 11", "kappa"] {
        let (v, _) = run(args);
        assert!(warnings(&v).is_empty(), "{args}");
    }
}

#[test]
fn modulus_in_mpa_is_named_with_both_values() {
    // E = 10 (MPa meant) with ν = 0.5: E* = 13.333…, σ0 = 1e6 Pa.
    let (v, lines) = run(&format!(
        "area {SA} --rms-height 1e-6 --young 10 --poisson 0.5 --pressure 1e6"
    ));
    let w = same(&v, &lines);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("σ0 = 1e6") && w[0].contains("13.3333") && w[0].contains("MPa"),
        "{w:?}"
    );
    // Between 0.1 E* and E*: strains of order one, not a unit slip.
    let (v, lines) = run(&format!(
        "area {SA} --rms-height 1e-6 --contact-modulus 1e9 --pressure 1e6,2e8,3e8"
    ));
    let w = same(&v, &lines);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("2 nominal pressures") && w[0].contains("3e8") && w[0].contains("1e8"),
        "{w:?}"
    );
    // Exactly 0.1 E* is not warned of.
    let (v, _) = run(&format!(
        "area {SA} --rms-height 1e-6 --contact-modulus 1e9 --pressure 1e8"
    ));
    assert!(warnings(&v).is_empty());
}

#[test]
fn steep_slope_is_outside_the_theory() {
    // rms height 1 (µm typed as m): rms slope ~1.2e5.
    let (v, lines) = run(&format!(
        "area {SA} --rms-height 1 --contact-modulus 1e9 --pressure 1e6"
    ));
    let w = same(&v, &lines);
    let slope = v["rms_slope"].as_f64().unwrap();
    assert!(slope > 1e5, "{slope}");
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("rms slope") && w[0].contains("small-slope"),
        "{w:?}"
    );
    // The spectrum summary warns too; a slope of exactly 1 does not.
    let (v, _) = run(&format!("spectrum {SA} --rms-height 1"));
    assert_eq!(warnings(&v).len(), 1);
    let (v, _) = run(&format!("spectrum {SA} --rms-slope 1"));
    assert!(warnings(&v).is_empty(), "{:?}", warnings(&v));
}

#[test]
fn zeta_beyond_the_band_says_what_was_computed() {
    let (beyond, lines) = run("area --example --pressure 1e6 --zeta 1e6");
    let w = same(&beyond, &lines);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("ζ = 1e6") && w[0].contains("full magnification ζ = 10000"),
        "{w:?}"
    );
    // What was computed: the numbers of full magnification ζ = q_s/q_l = 1e4.
    let (full, _) = run("area --example --pressure 1e6 --zeta 1e4");
    assert!(warnings(&full).is_empty());
    for key in ["g", "contact_fraction", "rms_slope"] {
        assert_eq!(beyond["points"][0][key], full["points"][0][key], "{key}");
    }
    // magnification: the largest ζ of the list is named.
    let (v, _) = run("magnification --example --zeta 10,1e5,1e7");
    let w = warnings(&v);
    assert!(w.len() == 1 && w[0].contains("ζ = 1e7"), "{w:?}");
}

/// A spectrum file written from the example's own C(q).
fn psd_file(name: &str, rising: bool) -> String {
    let dir = std::env::temp_dir().join(format!("persson-warn-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    let mut text = String::from("q,C\n");
    for i in 0..=40 {
        let q = 1e4 * 10f64.powf(f64::from(i) / 10.0);
        let c = if rising {
            1e-30 * q
        } else {
            1e-20 * (q / 1e4).powf(-3.6)
        };
        text.push_str(&format!("{q:e},{c:e}\n"));
    }
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn spectrum_file_names_its_convention() {
    let file = psd_file("falling.csv", false);
    let (v, lines) = run(&format!(
        "area --psd {file} --contact-modulus 1e9 --pressure 1e6"
    ));
    let w = same(&v, &lines);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("falling.csv")
            && w[0].contains("`persson` convention")
            && w[0].contains("the `surface-topography` convention"),
        "{w:?}"
    );
    assert_eq!(v["warnings"][0]["kind"], "psd_convention");
    assert_eq!(v["warnings"][0]["convention"], "persson");
    assert!(
        lines[0].ends_with("(--psd-convention surface-topography)"),
        "{lines:?}"
    );
    let (st, _) = run(&format!(
        "area --psd {file} --psd-convention surface-topography --contact-modulus 1e9 --pressure 1e6"
    ));
    let w = warnings(&st);
    assert!(
        w.len() == 1 && w[0].contains("`surface-topography` convention"),
        "{w:?}"
    );
    // The summary and a scene name it too.
    let (v, _) = run(&format!("spectrum --psd {file}"));
    assert!(warnings(&v)[0].contains("`persson` convention"));
    let dir = std::env::temp_dir().join(format!("persson-warn-{}", std::process::id()));
    let scene = dir.join("psd_scene.json");
    std::fs::write(
        &scene,
        format!(
            r#"{{"schema":1,"material":{{"contact_modulus":1e9}},"spectrum":{{"kind":"tabulated","file":"{file}"}},"nominal_pressure":[1e6],"outputs":{{"area":{{}}}}}}"#
        ),
    )
    .unwrap();
    // The BEM on a synthesised surface from the file names it too.
    let (b, lines) = run(&format!(
        "bem rough --psd {file} --grid 32 --contact-modulus 1e9 --pressure 1e6"
    ));
    let w = same(&b, &lines);
    assert!(w[0].contains("`persson` convention"), "{w:?}");
    let (sc, lines) = run(&format!("run {}", scene.display()));
    let w = warnings(&sc);
    assert!(
        w.len() == 1 && w[0].contains("`persson` convention"),
        "{w:?}"
    );
    // a scene's warning names the scene's key, not a flag
    assert_eq!(
        lines,
        [format!(
            "persson: warning: {} (spectrum.convention: \"surface-topography\")",
            w[0]
        )]
    );
    assert_eq!(sc["area"]["points"], v_area(&file)["points"]);
}

fn v_area(file: &str) -> Value {
    run(&format!(
        "area --psd {file} --contact-modulus 1e9 --pressure 1e6"
    ))
    .0
}

#[test]
fn rising_spectrum_file_suggests_a_surface() {
    let file = psd_file("rising.csv", true);
    let (v, lines) = run(&format!(
        "area --psd {file} --contact-modulus 1e9 --pressure 1e6"
    ));
    let w = same(&v, &lines);
    assert!(
        w.iter()
            .any(|x| x.contains("does not fall with q") && x.contains("height map")),
        "{w:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.contains("does not fall with q") && l.ends_with("(--surface FILE)")),
        "{lines:?}"
    );
}

#[test]
fn bem_surface_band_limited_by_its_grid() {
    let (v, lines) = run("bem rough --example --grid 32 --pressure 1e6");
    let w = same(&v, &lines);
    let surface = v["surface_rms_slope"].as_f64().unwrap();
    assert!(surface < 0.1, "{surface}");
    assert!(
        w.iter().any(|x| x.contains("32² surface is band-limited")
            && x.contains(&persson_studies::table::number(surface, 6))
            && x.contains("0.577654")),
        "{w:?}"
    );
}

#[test]
fn numbers_do_not_change_with_a_warning() {
    // The same run with and without the ζ beyond the band prints the same
    // report apart from ζ itself and the warnings.
    let (a, _) = run("magnification --example --zeta 1e4,2e4");
    let (b, _) = run("magnification --example --zeta 1e4,1e4");
    assert_eq!(a["points"][1]["g"], b["points"][1]["g"]);
    assert_eq!(
        a["points"][1]["contact_fraction"],
        b["points"][1]["contact_fraction"]
    );
    assert_eq!(warnings(&a).len(), 1);
    assert!(warnings(&b).is_empty());
    let mut a = numbers(&a);
    a["points"][1]["zeta"] = b["points"][1]["zeta"].clone();
    assert_eq!(a, numbers(&b));
}

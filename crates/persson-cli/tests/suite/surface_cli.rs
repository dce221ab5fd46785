//! Measured surfaces through the command line (issue 13): `spectrum
//! --surface`, the `--psd-out` round trip into `--psd`, bad maps, scenes with
//! a `height_map` spectrum, `compare --surface`.
#![cfg(feature = "topography")]

use crate::common;
use common::{json, persson};

use std::path::{Path, PathBuf};

use persson::topography::{analyse, read, AnalysisOptions, ReadOptions, SizeSpec};

/// The `--psd-out` CSV holds shortest round-trip numbers, so its spectrum is
/// the map's to the last bit; A/A0 then differs only by the solver's
/// floating-point path, far below this.
const ROUND_TRIP: f64 = 1e-12;

/// serde_json (without `float_roundtrip`, as a dev-dependency here) parses
/// decimals to within one ulp, not always to the nearest double.
const JSON_PARSE: f64 = 3e-16;

fn assert_same(what: &str, got: f64, expected: f64) {
    assert!(
        (got - expected).abs() <= JSON_PARSE * expected.abs(),
        "{what}: {got:e} printed, {expected:e} computed"
    );
}

/// A scratch directory for this test process.
fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("persson-surface-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn reference(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("tests/reference/data")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

/// The committed reference maps: (file, pixel size, periodic).
const MAPS: [(&str, &str, bool); 2] = [("map_a.npy", "1e-6", false), ("map_b.npy", "2e-6", true)];

fn map_flags(name: &str, pixel: &str, periodic: bool) -> Vec<String> {
    let mut v = vec![
        "--surface".to_string(),
        reference(name),
        "--pixel-size".into(),
        pixel.into(),
    ];
    if periodic {
        v.push("--periodic".into());
    }
    v
}

fn run_json(args: &[String]) -> serde_json::Value {
    let a: Vec<&str> = args.iter().map(String::as_str).collect();
    json(&a)
}

#[test]
fn area_from_the_map_equals_area_from_its_psd_csv() {
    for (name, pixel, periodic) in MAPS {
        let csv = dir().join(format!("{name}.csv"));
        let mut spectrum = vec!["spectrum".to_string()];
        spectrum.extend(map_flags(name, pixel, periodic));
        spectrum.extend(["--psd-out".into(), csv.to_string_lossy().into_owned()]);
        let a: Vec<&str> = spectrum.iter().map(String::as_str).collect();
        let (code, _, err) = persson(&a);
        assert_eq!(code, 0, "{err}");
        let tail = [
            "--contact-modulus",
            "1e9",
            "--pressure",
            "1e4,1e5,1e6",
            "--json",
        ];
        let mut from_map = vec!["area".to_string()];
        from_map.extend(map_flags(name, pixel, periodic));
        from_map.extend(tail.iter().map(|s| s.to_string()));
        let mut from_csv = vec!["area".to_string(), "--psd".into()];
        from_csv.push(csv.to_string_lossy().into_owned());
        from_csv.extend(tail.iter().map(|s| s.to_string()));
        let (m, c) = (run_json(&from_map), run_json(&from_csv));
        let (pm, pc) = (
            m["points"].as_array().unwrap(),
            c["points"].as_array().unwrap(),
        );
        assert_eq!(pm.len(), 3);
        for (x, y) in pm.iter().zip(pc) {
            let (x, y) = (
                x["contact_fraction"].as_f64().unwrap(),
                y["contact_fraction"].as_f64().unwrap(),
            );
            assert!(x > 0.0 && x < 1.0, "{name}: A/A0 = {x}");
            assert!(
                (x / y - 1.0).abs() < ROUND_TRIP,
                "{name}: A/A0 {x} from the map, {y} from its CSV"
            );
        }
    }
}

#[test]
fn spectrum_of_the_reference_maps_is_the_library_analysis() {
    for (name, pixel, periodic) in MAPS {
        let mut args = vec!["spectrum".to_string()];
        args.extend(map_flags(name, pixel, periodic));
        args.push("--json".into());
        let v = run_json(&args);
        let o = ReadOptions {
            size: Some(SizeSpec::PixelSize(pixel.parse().unwrap())),
            periodic,
            ..Default::default()
        };
        let t = read(Path::new(&reference(name)), &o).unwrap();
        let a = analyse(&t, &AnalysisOptions::default()).unwrap();
        // JSON numbers are shortest round-trip: equal up to the parser's ulp.
        let scalars = [
            ("rms_height", a.rms_height),
            ("rms_slope", a.rms_slope),
            ("rms_curvature", a.rms_curvature.unwrap()),
            ("mean_curvature_rms", a.mean_curvature_rms.unwrap()),
            ("hurst", a.hurst.unwrap()),
            ("hurst_error", a.hurst_error.unwrap()),
            ("q_min", a.q_min),
            ("q_max", a.q_max),
        ];
        for (key, value) in scalars {
            assert_same(&format!("{name} {key}"), v[key].as_f64().unwrap(), value);
        }
        let shape: Vec<u64> = a.shape.iter().map(|n| *n as u64).collect();
        let got: Vec<u64> = v["shape"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap())
            .collect();
        assert_eq!(got, shape);
        assert_eq!(
            v["pixel_size"][0].as_f64().unwrap(),
            pixel.parse::<f64>().unwrap()
        );
        let expected = if periodic {
            ("none", "none")
        } else {
            ("plane", "hann")
        };
        assert_eq!(v["detrend"], expected.0);
        assert_eq!(v["window"], expected.1);
        for (key, values) in [("q", &a.psd.q), ("c", &a.psd.c)] {
            let got: Vec<f64> = v["psd"][key]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            assert_eq!(got.len(), values.len(), "{name} psd.{key}");
            for (b, (g, e)) in got.iter().zip(values.iter()).enumerate() {
                assert_same(&format!("{name} psd.{key}[{b}]"), *g, *e);
            }
        }
        let counts: Vec<usize> = v["psd"]["count"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as usize)
            .collect();
        assert_eq!(counts, a.psd.count);
    }
    // SurfaceTopography 1.27 on map A, plane removed (tests/topography.rs,
    // tests/reference/surface_topography.py): the rms height to 1e-10.
    let svg = dir().join("psd_a.svg");
    let mut args = vec!["spectrum".to_string()];
    args.extend(map_flags("map_a.npy", "1e-6", false));
    args.extend([
        "--json".into(),
        "--plot".into(),
        svg.to_string_lossy().into_owned(),
    ]);
    let h = run_json(&args)["rms_height"].as_f64().unwrap();
    // The plot is drawn from the same report: C(q) and the Hurst fit.
    let drawing = std::fs::read_to_string(&svg).unwrap();
    assert!(
        drawing.starts_with("<svg") && drawing.contains("measured surface"),
        "{svg:?}"
    );
    assert!((h / 5.3093491068746826e-09 - 1.0).abs() < 1e-10, "{h}");
}

/// A `.npy` file with the given dtype descriptor, shape and raw data.
fn npy(descr: &str, shape: &str, data: &[u8]) -> Vec<u8> {
    let mut header = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}");
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut b = b"\x93NUMPY\x01\x00".to_vec();
    b.extend((header.len() as u16).to_le_bytes());
    b.extend(header.as_bytes());
    b.extend(data);
    b
}

#[test]
fn bad_maps_exit_2_with_one_line_naming_the_file_and_write_nothing() {
    let f8 = |v: &[f64]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let cases: Vec<(&str, Vec<u8>, &str, &str)> = vec![
        ("one_row.txt", b"1 2 3 4\n".to_vec(), "1e-6", "1 row(s)"),
        ("one_column.txt", b"1\n2\n3\n".to_vec(), "1e-6", "1 column(s)"),
        ("flat.txt", b"1 1 1\n1 1 1\n".to_vec(), "1e-6", "not all equal"),
        ("holes.txt", b"1 2 3\nnan 4 5\n".to_vec(), "1e-6", "1 of 6 points are undefined"),
        ("irregular.xyz", b"0 0 1\n1 0 2\n0 1 3\n1.5 1 4\n".to_vec(), "", "not a regular grid"),
        (
            "truncated.gsf",
            b"Gwyddion Simple Field 1.0\nXRes = 4\nYRes = 4\nXReal = 1e-6\nYReal = 1e-6\n\0\0\0\0abcd".to_vec(),
            "",
            "truncated",
        ),
        ("broken.x3p", b"PK\x03\x04garbage".to_vec(), "", ".x3p"),
        ("zero.txt", b"1 2 3\n3 4 5\n".to_vec(), "0", "pixel_size = 0"),
        ("negative.txt", b"1 2 3\n3 4 5\n".to_vec(), "-1e-6", "pixel_size = -0.000001"),
        ("integers.npy", npy("<i8", "(2, 2)", &[1u8; 32]), "1e-6", "dtype"),
        ("rank3.npy", npy("<f8", "(2, 2, 2)", &f8(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0])), "1e-6", "rank"),
    ];
    for (name, bytes, pixel, problem) in cases {
        let path = dir().join(name);
        std::fs::write(&path, bytes).unwrap();
        let out = dir().join(format!("{name}.psd.csv"));
        let (p, o) = (
            path.to_string_lossy().into_owned(),
            out.to_string_lossy().into_owned(),
        );
        let mut args = vec!["spectrum", "--surface", &p, "--psd-out", &o];
        if !pixel.is_empty() {
            args.extend(["--pixel-size", pixel]);
        }
        let (code, stdout, stderr) = persson(&args);
        assert_eq!(code, 2, "{name}: {stderr}");
        assert!(stdout.is_empty(), "{name}: {stdout}");
        assert_eq!(stderr.lines().count(), 1, "{name}: {stderr}");
        assert!(stderr.starts_with("persson: error: "), "{name}: {stderr}");
        assert!(stderr.contains(name), "{name} not named: {stderr}");
        assert!(
            stderr.contains(problem),
            "{name}: `{problem}` not in {stderr}"
        );
        assert!(!out.exists(), "{name}: {} written", out.display());
    }
}

/// A 64 × 64 periodic map synthesised by `persson bem rough --example`, side
/// 2π/q_l = 2π·1e-4 m.
fn synthesised_map(name: &str) -> (PathBuf, f64) {
    let p = dir().join(name);
    let s = p.to_string_lossy().into_owned();
    let (code, _, err) = persson(&[
        "bem",
        "rough",
        "--example",
        "--grid",
        "64",
        "--pressure",
        "1e6",
        "--surface-out",
        &s,
    ]);
    assert_eq!(code, 0, "{err}");
    (p, std::f64::consts::TAU / 1e4)
}

#[test]
fn a_scene_with_a_height_map_runs_area_and_bem() {
    let (map, size) = synthesised_map("scene_map.npy");
    let scene = dir().join("height_map_scene.json");
    let text = format!(
        r#"{{"schema": 1, "material": {{"contact_modulus": 1e9}},
            "spectrum": {{"kind": "height_map", "file": "scene_map.npy", "size": {size:?}, "periodic": true}},
            "nominal_pressure": [1e6, 1e7], "outputs": {{"area": {{}}, "bem": {{}}}}}}"#
    );
    std::fs::write(&scene, text).unwrap();
    let v = json(&["run", scene.to_str().unwrap(), "--json"]);
    // The scene's area is `area --surface` with the same conditioning.
    let (m, s) = (map.to_string_lossy().into_owned(), format!("{size:?}"));
    let cli = json(&[
        "area",
        "--surface",
        &m,
        "--size",
        &s,
        "--periodic",
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6,1e7",
        "--json",
    ]);
    assert_eq!(v["area"]["points"], cli["points"]);
    let title = v["area"]["surface"].as_str().unwrap();
    assert!(
        title.contains("periodic; detrend none, window none"),
        "{title}"
    );
    // The scene's BEM solves on the map itself: `bem rough --surface`.
    let bem = json(&[
        "bem",
        "rough",
        "--surface",
        &m,
        "--size",
        &s,
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6,1e7",
        "--json",
    ]);
    for k in 0..2 {
        for key in ["contact_fraction", "mean_separation"] {
            assert_eq!(v["bem"]["points"][k][key], bem["points"][k][key], "{key}");
        }
    }
    assert_eq!(v["bem"]["grid"], 64);
}

/// A∞ of a band-limited map and of the synthesised surface of the same
/// spectrum and seed differ by the map's tabulated (binned) spectrum and the
/// synthesis' cell averages near q_s; the test asks for agreement within the
/// synthesised compare's stated standard error.
#[cfg(feature = "bem")]
#[test]
fn compare_on_a_periodic_map_converges_on_its_band_limited_copies() {
    let (map, size) = synthesised_map("compare_map.npy");
    let (m, s) = (map.to_string_lossy().into_owned(), format!("{size:?}"));
    let flags = [
        "--surface",
        &m,
        "--size",
        &s,
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6,1e7",
    ];
    let mut args = vec!["compare", "--periodic", "--json"];
    args.extend(flags);
    let (code, out, err) = common::persson(&args);
    assert_eq!(code, 0, "{err}");
    let c: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(c["grids"], serde_json::json!([16, 32, 64]));
    assert_eq!(c["size"].as_f64().unwrap(), size);
    // q_s is clipped to what the coarsest grid resolves, 16 q_l / 4, with a
    // warning naming both values; the theories use the clipped spectrum.
    let q_l = c["spectrum"]["q_l"].as_f64().unwrap();
    assert!((q_l / 1e4 - 1.0).abs() < 1e-12, "q_l = 2π/L: {q_l}");
    assert_eq!(c["spectrum"]["clipped"], true);
    let q_s = c["spectrum"]["q_s"].as_f64().unwrap();
    assert!((q_s / (4.0 * q_l) - 1.0).abs() < 1e-12, "q_s = {q_s}");
    assert!(
        err.contains("warning: q_s = 306145") && err.contains("use q_s = 40000"),
        "{err}"
    );
    // The map as measured: `bem rough --surface` to the last digit.
    let mut rough = vec!["bem", "rough", "--json"];
    rough.extend(flags);
    let r = json(&rough);
    let measured = &c["measured"];
    assert_eq!(measured["grid"], 64);
    for k in 0..2 {
        for key in ["contact_fraction", "mean_separation"] {
            assert_eq!(measured[key][k], r["points"][k][key], "{key}");
        }
    }
    // A(N) converges: it falls with N by less at each step, and A∞ is
    // positive, at most the finest grid's value and at least the lowest
    // theory (Persson's), within its standard error.
    let bem = c["bem"].as_array().unwrap();
    let theories = c["theories"].as_array().unwrap();
    let mut synthesised = vec![
        "compare",
        "--example",
        "--grid",
        "64",
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6,1e7",
        "--json",
    ];
    let y = json(&synthesised);
    synthesised.clear();
    let at = |g: usize, k: usize| bem[g]["contact_fraction"][k].as_f64().unwrap();
    let k = 0; // σ0 = 1e6, A/A0 ≈ 0.2: the other is in full contact
    let (a16, a32, a64) = (at(0, k), at(1, k), at(2, k));
    assert!(a16 > a32 && a32 > a64, "A(N) = {a16}, {a32}, {a64}");
    assert!(a16 - a32 > a32 - a64, "A(N) = {a16}, {a32}, {a64}");
    let e = &c["extrapolated"][k];
    let (a_inf, se) = (
        e["contact_fraction"].as_f64().unwrap(),
        e["standard_error"].as_f64().unwrap(),
    );
    let original = theories[0]["contact_fraction"][k].as_f64().unwrap();
    assert_eq!(theories[0]["theory"], "original");
    assert!(a_inf > 0.0 && a_inf <= a64 + se, "A∞ = {a_inf} ± {se}");
    assert!(
        a_inf >= original - se,
        "A∞ = {a_inf} ± {se}, Persson {original}"
    );
    // The synthesised compare on the same spectrum and seed.
    let ye = &y["extrapolated"][k];
    let (b_inf, b_se) = (
        ye["contact_fraction"].as_f64().unwrap(),
        ye["standard_error"].as_f64().unwrap(),
    );
    assert!(
        (a_inf - b_inf).abs() <= b_se,
        "map A∞ = {a_inf} ± {se}, synthesised {b_inf} ± {b_se}"
    );
    // --grid, --seed and --seeds: the map sets the grid.
    for flag in [["--grid", "64"], ["--seed", "2"], ["--seeds", "2"]] {
        let mut args = vec!["compare", "--periodic"];
        args.extend(flags);
        args.extend(flag);
        let (code, out, err) = common::persson(&args);
        assert_eq!(code, 2, "{flag:?}: {err}");
        assert!(out.is_empty());
        assert!(
            err.contains(&format!(
                "{} is not used with --surface: the map sets the grid",
                flag[0]
            )),
            "{err}"
        );
    }
    // The BEM needs a square map.
    let oblong = dir().join("oblong.txt");
    std::fs::write(
        &oblong,
        "0 1 2 3 4 5 6 7 8 9\n".repeat(8).replace("0 1", "1 0"),
    )
    .unwrap();
    let o = oblong.to_string_lossy().into_owned();
    let (code, out, err) = persson(&[
        "compare",
        "--surface",
        &o,
        "--pixel-size",
        "1e-6",
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6",
        "--levels",
        "2",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("oblong.txt") && err.contains("8 × 10 points") && err.contains("square"),
        "{err}"
    );
}

/// The finest grid of `compare --surface` on a periodic map is the
/// band-limited map itself, solved directly to the last bit; the coarser
/// copies sample the same continuous surface (equal rms slope of their
/// trigonometric interpolants).
#[cfg(feature = "bem")]
#[test]
fn the_finest_grid_of_a_periodic_map_is_its_band_limited_map() {
    use persson::bem::resample::{band_limited_copies, band_limited_map};
    use persson::bem::rough::{self, RoughOptions};
    use persson::bem::Boundary;
    use persson_studies::validation::{compare_surface, ComparisonConfig};
    let (map, size) = synthesised_map("library_map.npy");
    let surface = rough::read_surface(&map, size, Boundary::Periodic).unwrap();
    let o = ReadOptions {
        size: Some(SizeSpec::Size(size, None)),
        periodic: true,
        ..Default::default()
    };
    let a = analyse(&read(&map, &o).unwrap(), &AnalysisOptions::default()).unwrap();
    let spectrum = a.psd.to_tabulated().unwrap();
    let mut config = ComparisonConfig::new(1e9);
    config.nominal_pressure = vec![1e6, 3e6];
    let c = compare_surface(
        &spectrum,
        &surface,
        Boundary::Periodic,
        &config,
        &mut |_| {},
    )
    .unwrap();
    let q_s = c.spectrum.q_s;
    let band = band_limited_map(&surface, q_s).unwrap();
    let options = RoughOptions {
        boundary: Boundary::Periodic,
        solver: config.sweep.options,
        bins: None,
        ..RoughOptions::default()
    };
    let direct = rough::solve(&band, 1e9, &config.nominal_pressure, &options, &mut ()).unwrap();
    let finest = c.bem.last().unwrap();
    assert_eq!(finest.grid, 64);
    for (k, p) in direct.iter().enumerate() {
        assert_eq!(finest.contact_fraction[k], p.contact_fraction);
        assert_eq!(finest.mean_separation[k], p.mean_separation);
    }
    let measured = c.measured.as_ref().unwrap();
    let raw = rough::solve(&surface, 1e9, &config.nominal_pressure, &options, &mut ()).unwrap();
    assert_eq!(measured.contact_fraction[0], raw[0].contact_fraction);
    // One continuous surface on every grid: the interpolants' rms slopes
    // agree to rounding, and no mode above q_s is left.
    let copies = band_limited_copies(&surface, q_s, &[16, 32, 64]).unwrap();
    let slope = copies[2].rms_slope().unwrap();
    for s in &copies {
        assert!((s.rms_slope().unwrap() / slope - 1.0).abs() < 1e-12);
    }
    assert_eq!(band_limited_map(&band, q_s).unwrap().heights.len(), 64 * 64);
    let again = band_limited_map(&band, q_s).unwrap();
    let diff = again
        .heights
        .iter()
        .zip(&band.heights)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(
        diff <= 1e-12 * band.rms_height(),
        "low-pass not idempotent: {diff:e}"
    );
    // Fewer than 2 pixels per wavelength on the coarsest grid: modes on its
    // Nyquist wavevector would alias.
    assert!(band_limited_copies(&surface, 8.0 * 1e4, &[16, 32, 64]).is_err());
}

fn instrument_file(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("tests/data")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

/// Issue 20 through the binary: a failed Hurst fit is `null` plus a warning
/// (exit 0, statistics printed); a real line scan gives its 1D spectrum and
/// statistics with the warnings of the 2D conversion; the new flags reach
/// the reader; an unsupported binary format is one line, exit 2.
#[test]
fn instrument_files_through_the_command_line() {
    let gwy = instrument_file("gwyddion-export-english.txt");
    let v = json(&["spectrum", "--surface", &gwy, "--json"]);
    assert!(v["hurst"].is_null() && v["hurst_error"].is_null(), "{v}");
    let w = v["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{v}");
    assert_eq!(w[0]["kind"], "hurst_not_fitted", "{w:?}");
    assert!(
        w[0]["message"]
            .as_str()
            .unwrap()
            .contains("no Hurst exponent"),
        "{w:?}"
    );
    assert!(v["rms_height"].as_f64().unwrap() > 3.76);
    // The header's size, checked against a given one.
    let (code, _, err) = persson(&["spectrum", "--surface", &gwy, "--size", "1e-5,5.6789e-6"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("disagrees"), "{err}");

    let dektak = instrument_file("dektak-1.csv");
    let v = json(&["spectrum", "--surface", &dektak, "--json"]);
    let p = &v["psd_profile"];
    let bins = p["q"].as_array().unwrap().len();
    assert_eq!(p["c_1d"].as_array().unwrap().len(), bins);
    let kept = v["psd"]["q"].as_array().unwrap().len();
    assert!(kept < bins, "{kept} of {bins}");
    for key in ["rms_slope_profile", "rms_curvature_profile"] {
        assert!(v[key].as_f64().unwrap() > 0.0, "{key}");
    }
    let w: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| w["kind"] == "bins_left_out")
        .map(|w| w["message"].as_str().unwrap())
        .collect();
    assert!(
        w.iter()
            .any(|w| w.contains(&format!("{} of {bins} bins", bins - kept))),
        "{w:?}"
    );
    // area on the same scan: its 2D spectrum (the bins that convert), with the warning.
    let (code, _, err) = persson(&[
        "area",
        "--surface",
        &dektak,
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e5",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("left out of C(q)"), "{err}");

    // --height-unit and --transpose reach the reader.
    let npy = dir().join("um.npy");
    persson::io::npy::write(&npy, 2, 3, &[1.0, 2.0, 4.0, 3.0, 5.0, 9.0]).unwrap();
    let npy = npy.to_string_lossy().into_owned();
    let base = [
        "spectrum",
        "--surface",
        &npy,
        "--size",
        "3e-6,2e-6",
        "--json",
    ];
    let m = json(&base);
    let mut um = base.to_vec();
    um.extend(["--height-unit", "um"]);
    let u = json(&um);
    let ratio = u["rms_height"].as_f64().unwrap() / m["rms_height"].as_f64().unwrap();
    assert!((ratio - 1e-6).abs() < 1e-20, "{ratio}");
    let mut t = base.to_vec();
    t.push("--transpose");
    assert_eq!(json(&t)["shape"], serde_json::json!([3, 2]));

    let sur = dir().join("scan.vk4");
    std::fs::write(&sur, b"anything\0\0\0").unwrap();
    let (code, out, err) = persson(&["spectrum", "--surface", &sur.to_string_lossy()]);
    assert_eq!((code, out.as_str()), (2, ""), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("unsupported format (.vk4): persson reads")
            && err.contains("export to GSF or x3p with Gwyddion or SurfaceTopography"),
        "{err}"
    );
    // An Igor wave without units: the user says them, never metres by default.
    let ibw = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/10x10-one_channel_without_name.ibw"
    );
    let (code, _, err) = persson(&["spectrum", "--surface", ibw]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("no unit of the heights") && err.contains("height_unit"),
        "{err}"
    );
}

/// One reader for every command: each instrument format the readers know
/// (one example file each, with the flags it needs) is read by `spectrum`
/// and by the BEM alike: the BEM solves on exactly the heights the reader
/// gives (its `--surface-out`), or refuses a map that is not square, naming
/// the file. Every other command that takes `--surface` reads through the
/// same entry (`HeightMapSpec::read`): each runs on the small files of
/// three container families (NetCDF, X3P, Igor), printing only finite
/// numbers.
#[test]
fn every_format_is_read_alike_by_every_command_that_takes_a_surface() {
    // (file, extra reading flags)
    let files: &[(&str, &[&str])] = &[
        ("di-3.di", &[]),
        ("spot_1-1000nm.ibw", &[]),
        (
            "10x10-one_channel_without_name.ibw",
            &["--height-unit", "nm", "--size", "1e-6"],
        ),
        ("sur-3.sur", &["--fill-undefined"]),
        ("sur-2.sur", &["--fill-undefined"]),
        ("al3d-1.al3d", &[]),
        ("metropro-1.dat", &[]),
        ("nc-1.nc", &[]),
        ("st-mask.nc", &["--fill-undefined"]),
        ("plu-1.plu", &[]),
        (
            "gwyfile-test.gwy",
            &["--height-unit", "m", "--lateral-unit", "m"],
        ),
        ("ISO5436-sample1_bin.x3p", &["--fill-undefined"]),
        ("gwyddion-export-english.txt", &[]),
        ("matrix-4.txt", &[]),
        ("xyz-2.txt", &["--fill-undefined"]),
    ];
    let d = dir();
    for (name, flags) in files {
        let file = instrument_file(name);
        let with = |cmd: &[&str], more: &[&str]| -> Vec<String> {
            let mut v: Vec<String> = cmd.iter().map(|s| s.to_string()).collect();
            v.extend(["--surface".into(), file.clone()]);
            v.extend(flags.iter().map(|s| s.to_string()));
            v.extend(more.iter().map(|s| s.to_string()));
            v
        };
        let spectrum = run_json(&with(&["spectrum"], &["--json"]));
        // The theory commands: the map's spectrum, whatever the command.
        let material = ["--contact-modulus", "1e9"];
        let theory: [&[&str]; 8] = [
            &["area", "--pressure", "1e5"],
            &["magnification", "--pressure", "1e5"],
            &["separation", "--pressure", "1e5"],
            &["conductance", "--pressure", "1e5", "--conductivity", "50"],
            &[
                "leakage",
                "--pressure",
                "1e5",
                "--viscosity",
                "1e-3",
                "--pressure-drop",
                "1e5",
            ],
            &[
                "adhesion",
                "--pressure",
                "1e5",
                "--work-of-adhesion",
                "0.01",
            ],
            &["stress", "--flat", "--pressure", "1e5"],
            &["spectrum"],
        ];
        let small = [
            "nc-1.nc",
            "ISO5436-sample1_bin.x3p",
            "10x10-one_channel_without_name.ibw",
        ];
        for cmd in theory.iter().filter(|_| small.contains(name)) {
            let more = if cmd[0] == "spectrum" {
                vec![]
            } else {
                material.to_vec()
            };
            let (code, out, err) = persson(&str_refs(&with(cmd, &more)));
            assert_eq!(code, 0, "{name} {}: {err}", cmd[0]);
            assert!(
                !out.contains("NaN") && !out.contains('∞'),
                "{name} {}: {out}",
                cmd[0]
            );
        }
        if !small.contains(name) {
            // (the theory commands above and friction: the small files)
        } else {
            let (code, _, err) = persson(&str_refs(&with(
                &["friction"],
                &[
                    "--master-curve",
                    &reference("rubber_master_curve.csv"),
                    "--frequency-unit",
                    "rad/s",
                    "--pressure",
                    "1e5",
                    "--velocity",
                    "1e-2",
                ],
            )));
            assert_eq!(code, 0, "{name} friction: {err}");
        }
        if spectrum["shape"][0] == spectrum["shape"][1] {
            // Square: the anisotropy and the BEM on exactly the reader's heights.
            // (a map too small for the texture parameters is refused, naming it)
            let (code, _, err) = persson(&str_refs(&with(&["anisotropy"], &[])));
            assert!(
                code == 0 || (code == 2 && err.contains(name) && err.contains("texture")),
                "{name} anisotropy: {err}"
            );
            let out = d.join(format!("{name}.bem.npy"));
            let args = with(
                &["bem", "rough"],
                &[
                    "--contact-modulus",
                    "1e9",
                    "--pressure",
                    "1e5",
                    "--boundary",
                    "free",
                    "--surface-out",
                    &out.to_string_lossy(),
                ],
            );
            let (code, _, err) = persson(&str_refs(&args));
            let n = spectrum["shape"][0].as_u64().unwrap();
            if n < persson::bem::MIN_GRID as u64 {
                assert_eq!(code, 2, "{name}");
                assert!(err.contains("grid"), "{name}: {err}");
                continue;
            }
            assert_eq!(code, 0, "{name} bem: {err}");
            let solved = persson::io::npy::parse(&out, &std::fs::read(&out).unwrap()).unwrap();
            let read = read_as_the_flags_say(&file, flags);
            assert_eq!(
                solved.values, read,
                "{name}: the BEM's heights are the reader's"
            );
        } else {
            let (code, _, err) = persson(&str_refs(&with(
                &["bem", "rough"],
                &["--contact-modulus", "1e9", "--pressure", "1e5"],
            )));
            assert_eq!(code, 2, "{name}");
            assert!(
                err.contains(name) && err.contains("square"),
                "{name}: {err}"
            );
        }
    }
}

fn str_refs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// The heights `persson::topography::read` gives for `file` with the
/// reading flags of the test above.
fn read_as_the_flags_say(file: &str, flags: &[&str]) -> Vec<f64> {
    use persson::topography::{read, LengthUnit, ReadOptions, SizeSpec};
    let mut o = ReadOptions::default();
    let mut it = flags.iter();
    while let Some(f) = it.next() {
        match *f {
            "--fill-undefined" => o.fill_undefined = true,
            "--height-unit" => {
                o.height_unit = Some(match *it.next().unwrap() {
                    "nm" => LengthUnit::Nanometre,
                    _ => LengthUnit::Metre,
                })
            }
            "--size" => o.size = Some(SizeSpec::Size(it.next().unwrap().parse().unwrap(), None)),
            "--lateral-unit" => {
                it.next();
                o.lateral_unit = Some(LengthUnit::Metre)
            }
            other => panic!("flag {other}"),
        }
    }
    read(Path::new(file), &o).unwrap().heights().to_vec()
}

/// A contact.engineering dataset as `--surface`: `spectrum` shows each
/// measurement's reliable band (named `dataset.zip#measurement`) and the
/// combined spectrum; every other command takes the combined spectrum;
/// `--channel` reads one measurement; a measurement it does not hold is an
/// error naming the archive and listing the measurements.
#[test]
fn a_dataset_export_is_a_multi_scale_surface() {
    let zip = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/container-2.zip"
    );
    let s = json(&["spectrum", "--surface", zip, "--json"]);
    let bands = s["measurements"].as_array().unwrap();
    assert_eq!(bands.len(), 3);
    assert!(bands[1]["file"]
        .as_str()
        .unwrap()
        .ends_with("container-2.zip#gain_control_uncd_35.001"));
    let q = s["q"].as_array().unwrap();
    assert!(q.len() > 12, "{} bins", q.len());
    let a = json(&[
        "area",
        "--surface",
        zip,
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e6",
        "--json",
    ]);
    let f = a["points"][0]["contact_fraction"].as_f64().unwrap();
    assert!(f > 0.0 && f < 1.0, "{a}");
    // One measurement, by name: the AFM map's own analysis.
    let one = json(&[
        "spectrum",
        "--surface",
        zip,
        "--channel",
        "gain_control_uncd_35.001",
        "--json",
    ]);
    assert_eq!(one["shape"], serde_json::json!([512, 512]));
    let (code, _, err) = persson(&["spectrum", "--surface", zip, "--channel", "AFM"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("container-2.zip")
            && err.contains("no measurement \"AFM\"")
            && err.contains("2: \"uncd_stylus_300um_5mar_3.txt\""),
        "{err}"
    );
}

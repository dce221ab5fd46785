//! Table-driven bad input across subcommands and file formats: every case
//! exits 2 with a one-line message naming the offending field, prints nothing
//! on stdout, and never panics.

use std::path::PathBuf;
use std::process::Command;

/// A scratch directory for this test process.
fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("persson-bad-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Write a file into the scratch directory and return its path as a string.
fn file(name: &str, bytes: &[u8]) -> String {
    let p = dir().join(name);
    std::fs::write(&p, bytes).unwrap();
    p.to_string_lossy().into_owned()
}

const SA: &str = "--hurst 0.8 --q-l 1e4 --q-s 1e8 --rms-slope 0.1";

/// (command line, text the message must contain). `{SA}` is a valid spectrum.
fn cases() -> Vec<(String, String)> {
    let good_psd = file("good.csv", b"q,C\n1e4,1e-20\n1e5,1e-24\n1e6,1e-28\n");
    let scene_ok = r#"{"schema":1,"material":{"contact_modulus":1},"spectrum":{"kind":"self_affine","hurst":0.8,"q_l":1,"q_s":100,"rms_slope":1},"nominal_pressure":[0.1],"outputs":{"area":{}}}"#;
    let mut big = Vec::with_capacity(4 << 20);
    for i in 0..(4u32 << 20) {
        big.push((i.wrapping_mul(2_654_435_761) >> 24) as u8);
    }
    let v: Vec<(String, &str)> = vec![
        // area: numbers
        (format!("area {SA} --contact-modulus 1 --pressure nan"), "pressure"),
        (format!("area {SA} --contact-modulus 1 --pressure -1"), "pressure"),
        (format!("area {SA} --contact-modulus 1 --pressure 0"), "pressure"),
        (format!("area {SA} --contact-modulus 1 --pressure 1e999"), "pressure"),
        (format!("area {SA} --contact-modulus inf --pressure 1"), "contact_modulus"),
        (format!("area {SA} --contact-modulus 0 --pressure 1"), "contact_modulus"),
        (format!("area {SA} --contact-modulus 1 --pressure 1 --zeta 0"), "zeta"),
        (format!("area {SA} --contact-modulus 1 --pressure 1 --zeta nan"), "zeta"),
        (format!("area {SA} --young 1 --poisson 0.7 --pressure 1"), "poisson"),
        (format!("area {SA} --young -1 --poisson 0.3 --pressure 1"), "young"),
        (format!("area {SA} --contact-modulus 1"), "pressure"),
        ("area --contact-modulus 1 --pressure 1".into(), "spectrum"),
        (format!("area {SA} --pressure 1"), "material"),
        // spectrum parameters
        ("area --hurst 0 --q-l 1 --q-s 10 --c-r 1 --contact-modulus 1 --pressure 1".into(), "hurst"),
        ("area --hurst 1 --q-l 1 --q-s 10 --c-r 1 --contact-modulus 1 --pressure 1".into(), "hurst"),
        ("area --hurst -0.5 --q-l 1 --q-s 10 --c-r 1 --contact-modulus 1 --pressure 1".into(), "hurst"),
        ("area --hurst 0.5 --q-l 10 --q-s 1 --c-r 1 --contact-modulus 1 --pressure 1".into(), "q_l <= q_r < q_s"),
        ("area --hurst 0.5 --q-l 1 --q-r 20 --q-s 10 --c-r 1 --contact-modulus 1 --pressure 1".into(), "q_l <= q_r < q_s"),
        ("area --hurst 0.5 --q-l -1 --q-s 10 --c-r 1 --contact-modulus 1 --pressure 1".into(), "q_l"),
        ("area --hurst 0.5 --q-l 1 --q-s inf --c-r 1 --contact-modulus 1 --pressure 1".into(), "q_s"),
        ("area --hurst 0.5 --q-l 1 --q-s 10 --c-r 0 --contact-modulus 1 --pressure 1".into(), "c_r"),
        ("area --hurst 0.5 --q-l 1 --q-s 10 --rms-height nan --contact-modulus 1 --pressure 1".into(), "rms_height"),
        ("area --hurst 0.5 --q-l 1 --q-s 10 --rms-slope -1 --contact-modulus 1 --pressure 1".into(), "rms_slope"),
        ("area --hurst 0.5 --q-l 1 --q-s 10 --contact-modulus 1 --pressure 1".into(), "amplitude"),
        // PSD files
        ("area --psd /no/such/file.csv --contact-modulus 1 --pressure 1".into(), "file.csv"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("empty.csv", b"")), "no data"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("comments.csv", b"# a\n# b\n")), "no data"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("one.csv", b"1e4,1e-20\n")), "at least 2"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("trunc.csv", b"q,C\n1e4,1e-20\n1e5,")), "2 columns"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("extra.csv", b"1e4,1e-20,3\n1e5,1e-24,3\n")), "2 columns"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("missing.csv", b"1e4\n1e5\n")), "2 columns"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("text.csv", b"1e4,abc\n1e5,1e-24\n")), "not a number"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("order.csv", b"1e5,1e-20\n1e4,1e-24\n")), "q[1]"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("dup.csv", b"1e4,1e-20\n1e4,1e-24\n")), "q[1]"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("negc.csv", b"1e4,1e-20\n1e5,-1e-24\n")), "C[1]"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("zeroc.csv", b"1e4,0\n1e5,1e-24\n")), "C[0]"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("nanq.csv", b"nan,1e-20\n1e5,1e-24\n")), "q[0]"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("hugeq.csv", b"1e4,1e-20\n1e999,1e-24\n")), "q[1]"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("binary.csv", &big)), "UTF-8"),
        (format!("area --psd {good_psd} --psd-convention grid --contact-modulus 1 --pressure 1"), "psd-size"),
        (format!("area --psd {good_psd} --psd-convention grid --psd-size -1 --contact-modulus 1 --pressure 1"), "size"),
        (format!("area --psd {} --psd-convention profile1d --contact-modulus 1 --pressure 1", file("rising.csv", b"1e4,1e-24\n1e5,1e-20\n")), "C[0]"),
        // other subcommands
        ("spectrum --example --q-min nan".into(), "q_min"),
        ("spectrum --example --q-min 1e9 --q-max 1e5".into(), "q_max"),
        (format!("magnification {SA} --contact-modulus 1 --pressure 1 --zeta 0.5"), "zeta"),
        (format!("magnification {SA} --contact-modulus 1"), "pressure"),
        (format!("kappa {SA} --contact-modulus 1 --pressure -3"), "pressure"),
        // scenes
        ("run /no/such/scene.json".into(), "scene.json"),
        (format!("run {}", file("typo.json", scene_ok.replace("hurst", "hurts").as_bytes())), "hurts"),
        (format!("run {}", file("type.json", scene_ok.replace("0.8", "\"0.8\"").as_bytes())), "invalid type"),
        (format!("run {}", file("schema.json", scene_ok.replace("\"schema\":1", "\"schema\":7").as_bytes())), "schema"),
        (format!("run {}", file("trunc.json", &scene_ok.as_bytes()[..60])), "EOF"),
        (format!("run {}", file("bin.json", &big[..4096])), "UTF-8"),
        (format!("run {}", file("neg.json", scene_ok.replace("[0.1]", "[-0.1]").as_bytes())), "pressure"),
        (format!("run {}", file("nomat.json", scene_ok.replace(r#""material":{"contact_modulus":1},"#, "").as_bytes())), "material"),
        // --out DIR is created, unless a file stands in the way
        (format!("run {} --out {}/sub", file("ok.json", scene_ok.as_bytes()), file("plain.txt", b"x")), "plain.txt/sub"),
        // outputs that would overwrite an input, or cannot be written
        (format!("area {SA} --contact-modulus 1 --pressure 1 --plot {}/a.svg", file("plain2.txt", b"x")), "plain2.txt/a.svg"),
        (format!("area {SA} --contact-modulus 1 --pressure 1 --plot {}", dir().join("a.jpg").display()), "a.jpg"),
        (
            format!(
                "run {}",
                file("clobber.json", scene_ok.replace(r#""area":{}"#, &format!(r#""area":{{"plot":"{}"}}"#, dir().join("clobber.json").display())).as_bytes())
            ),
            "overwrite",
        ),
        // stress
        ("stress --start flat --g -1".into(), "g"),
        ("stress --start hertz --g nan".into(), "g"),
        ("stress --start hertz --g 1 --yield-ratio 1".into(), "yield"),
        ("stress --start cylinder --g 1 --yield-ratio 0.5".into(), "yield"),
        ("stress --start hertz --g 1 --tolerance 0".into(), "tol"),
        (format!("stress --table {} --g 1", file("p0neg.csv", b"0,0\n0.5,-1\n1,2\n")), "table"),
        (format!("stress --table {} --g 1", file("p0norm.csv", b"0,0\n1,5\n")), "table"),
        // A ball's --load with a cylinder (and the cylinder's load with a ball)
        // names the conflict, not a list of "required" flags of the other body.
        ("stress --example --cylinder-radius 0.01 --load 10".into(), "'--load <LOAD>'"),
        ("stress --example --ball-radius 0.01 --load-per-length 10".into(), "'--load-per-length"),
        // --points below 2 (issue 15), wherever a number of points exists
        ("stress --start hertz --g 0.6 --points 0".into(), "invalid points = 0: must be an integer >= 2"),
        ("stress --start hertz --g 0.6 --points 1".into(), "invalid points = 1"),
        ("stress --example --flat --pressure 1e6 --points 1".into(), "invalid points = 1"),
        ("magnification --example --points 1".into(), "invalid points = 1"),
        ("spectrum --example --points 0".into(), "invalid points = 0"),
        (format!("run {}", file("points.json", br#"{"schema":1,"outputs":{"stress":{"start":"hertz","g":[0.6],"points":1}}}"#)), "outputs.stress.points = 1"),
        // the physical stress distribution
        ("stress --start hertz".into(), "no G: give --g G"),
        ("stress --example --ball-radius -1 --load 10".into(), "radius"),
        ("stress --example --cylinder-radius 0.5 --load-per-length 0".into(), "load"),
        ("stress --example --flat --pressure 1e6 --yield-stress 1e5".into(), "yield_stress = 100000: must be finite and > the peak pressure 1e6"),
        ("stress --example --start hertz --peak-pressure 1e6 --zeta 0.5".into(), "zeta"),
        ("stress --example --zeta 10 --g 1".into(), "--zeta needs a physical contact"),
        ("stress --example --peak-pressure 5e8".into(), "no start: give --start X"),
        ("stress --example --start hertz --g 1".into(), "needs a physical contact"),
        ("stress --example --ball-radius 0.01".into(), "--load"),
        // usage errors: one line with the prefix, the usage hint after it
        ("area --exmple".into(), "persson: error: unexpected argument '--exmple' found; tip: a similar argument exists: '--example'"),
        ("bogus".into(), "persson: error: unrecognized subcommand 'bogus'"),
        ("area --example --pressure".into(), "a value is required for '--pressure"),
        // units typed after a number: the plain SI number named
        ("area --example --pressure 1MPa".into(), "`1MPa` is not a plain number: give SI numbers without units (1e6 for 1MPa, in Pa)"),
        ("area --example --rms-height 2.5um".into(), "2.5e-6 for 2.5um, in m"),
        ("area --example --contact-modulus 1.5GPa".into(), "1.5e9 for 1.5GPa"),
        ("area --example --pressure abc".into(), "`abc` is not a number"),
        // a partial spectrum names what is missing, and --example only when not given
        ("area --hurst 0.5 --contact-modulus 1 --pressure 1".into(), "incomplete self-affine spectrum: missing --q-l, --q-s (or add --example"),
        // a height map where a spectrum file is expected
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("map.npy", b"\x93NUMPY\x01\x00v\x00{'descr': '<f8'}")), "give it as --surface"),
        (format!("area --psd {} --contact-modulus 1 --pressure 1", file("map.txt", b"1 2 3\n4 5 6\n7 8 9\n")), "looks like a height map, not a spectrum: give it as --surface"),
        // corrected theories and separation
        (format!("area {SA} --contact-modulus 1 --pressure 1 --theory yang-persson --gamma 5"), "gamma"),
        (format!("area {SA} --contact-modulus 1 --pressure 1 --theory wang-muser --gamma 0"), "gamma"),
        // adhesion: pressures ≤ 0 are tensions, but the rest is checked and names its flag
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion -1"), "--work-of-adhesion"),
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion nan"), "--work-of-adhesion"),
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion 1 --adhesion-range 0"), "--adhesion-range"),
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion 1 --pressure inf"), "--pressure"),
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion 1 --zeta 0.5"), "--zeta"),
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion 1 --points 1"), "--points"),
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion 1 --tolerance 2"), "--tolerance"),
        (format!("adhesion {SA} --contact-modulus 1 --work-of-adhesion 1 --area-enhancement x"), "area-enhancement"),
        (format!("separation {SA} --contact-modulus 1 --pressure -1"), "pressure"),
        (format!("separation {SA} --contact-modulus 1 --pressure 0"), "pressure"),
        // BEM
        ("bem hertz --grid 4".into(), "grid"),
        ("bem hertz --grid 20000".into(), "GiB"),
        (format!("bem rough {SA} --grid 32 --contact-modulus 1 --pressure -1"), "pressure"),
        (format!("bem rough {SA} --grid 32 --contact-modulus 1 --pressure 0"), "pressure"),
        (format!("bem rough --surface {} --size 1 --contact-modulus 1 --pressure 0.1", file("ragged.txt", b"1 2 3\n4 5\n")), "ragged.txt"),
        (format!("bem rough --surface {} --size 1 --contact-modulus 1 --pressure 0.1", file("nanmap.txt", b"1 2\nnan 4\n")), "nanmap.txt"),
        (format!("bem rough --surface {} --size 1 --contact-modulus 1 --pressure 0.1", file("bad.npy", b"\x93NUMPY\x01\x00garbage")), "bad.npy"),
        (format!("bem rough --surface {} --size 1 --contact-modulus 1 --pressure 0.1", file("empty.npy", b"")), "empty.npy"),
        (format!("bem rough --surface {} --size -1 --contact-modulus 1 --pressure 0.1", file("ok.txt", b"0 1\n1 0\n")), "size"),
        // conductance and leakage (issue 23)
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --conductivity 0"), "conductivity"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --conductivity 50,-1"), "conductivity"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --conductivity 1,2,3"), "conductivity"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --resistivity nan"), "resistivity"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --resistivity -1e-8"), "resistivity"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --gas-conductivity 0.02 --mean-free-path 0"), "mean_free_path"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --gas-conductivity -1 --mean-free-path 1e-7"), "gas_conductivity"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e6 --gap-table {}", file("gap.txt", b"0 1\n0 2\n")), "gap.txt:2: --gap-table"),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure -1 --conductivity 1"), "pressure"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 0 --pressure-drop 1e5"), "viscosity"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity -1e-3 --pressure-drop 1e5"), "viscosity"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3 --pressure-drop 0"), "pressure_drop"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3 --pressure-drop nan"), "pressure_drop"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3 --pressure-drop 1e5 --seal-width 0"), "seal_width"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3 --pressure-drop 1e5 --seal-length -1"), "seal_length"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3 --pressure-drop 1e5 --percolation-threshold 0"), "percolation_threshold"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3 --pressure-drop 1e5 --percolation-threshold 1.2"), "percolation_threshold"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3 --inlet-pressure 1e5 --outlet-pressure 2e5"), "outlet_pressure"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --pressure-drop 1e5"), "--viscosity"),
        (format!("leakage {SA} --contact-modulus 1e9 --pressure 1e6 --viscosity 1e-3"), "--pressure-drop"),
        (format!("bem rough {SA} --grid 32 --contact-modulus 1 --pressure 0.01 --viscosity 1e-3"), "--leakage"),
        (format!("bem rough {SA} --grid 32 --contact-modulus 1 --pressure 0.01 --leakage --viscosity 1e-3 --pressure-drop -1"), "pressure_drop"),
        (format!("bem rough {SA} --grid 32 --contact-modulus 1 --pressure 0.01 --boundary free --conductivity 1"), "--boundary periodic"),
        (format!("bem rough --surface {} --size 1 --contact-modulus 1 --pressure 0.1 --conductivity 1 --gap-field {}", file("in.txt", b"0 1 0\n1 0 1\n0 1 0\n"), file("in.txt", b"0 1 0\n1 0 1\n0 1 0\n")), "would overwrite the input"),
    ];
    v.into_iter().map(|(a, n)| (a, n.to_string())).collect()
}

#[test]
fn every_bad_input_exits_2_with_a_named_one_line_error() {
    let cases = cases();
    assert!(cases.len() >= 40, "{} cases", cases.len());
    let mut failures = Vec::new();
    for (line, needle) in &cases {
        let args: Vec<&str> = line.split_whitespace().collect();
        let out = Command::new(env!("CARGO_BIN_EXE_persson"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(&args)
            .env("RUST_BACKTRACE", "full")
            .output()
            .unwrap();
        let (code, stdout, stderr) = (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr),
        );
        let ok = code == Some(2)
            && stdout.is_empty()
            && stderr.starts_with("persson: error: ")
            && !stderr.contains(":0:0")
            && stderr.contains(needle.as_str())
            && !stderr.contains("panicked")
            && stderr.trim_end().lines().count()
                <= 1 + usize::from(stderr.contains("\nUsage: persson "));
        if !ok {
            failures.push(format!("{line}\n  -> code {code:?}, stdout {stdout:?}, stderr {stderr:?} (wanted '{needle}')"));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// The usage hint after a parse error names the subcommand that was run,
/// two words deep (`bem rough`, `compare kappa`), not only its first word.
#[test]
fn usage_hint_names_the_subcommand() {
    for (args, hint) in [
        (
            &["bem", "rough", "--grid", "x"][..],
            "Usage: persson bem rough --help",
        ),
        (
            &["compare", "kappa", "--levels", "x"][..],
            "Usage: persson compare kappa --help",
        ),
        (
            &["area", "--pressure", "x"][..],
            "Usage: persson area --help",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_persson"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(args)
            .env("RUST_BACKTRACE", "0")
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("persson: error: "), "{args:?}: {err}");
        assert_eq!(err.lines().nth(1), Some(hint), "{args:?}: {err}");
    }
}

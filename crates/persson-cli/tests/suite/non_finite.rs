//! No NaN or ∞ reaches a table, JSON or CSV: the inputs that printed them
//! (a 2 × 2 map's curvature, an overflowing work of adhesion, an adhesive
//! mean gap beyond the solver, full contact's infinite stiffness, …) give
//! either finite numbers with `–`/`null` for what cannot be computed and a
//! warning that says why, or exit 2 naming the input.

use crate::common;

use common::persson;

const SA: &str = "--hurst 0.8 --q-l 6283.185307179586 --q-r 12566.370614359172 \
                  --q-s 50265.48245743669 --rms-slope 0.1";

/// Whether a printed output holds a non-finite number (the word `inf`, `NaN`
/// or `∞` as a value, not inside a sentence such as "N → ∞").
fn has_non_finite(out: &str) -> bool {
    out.split(|c: char| c.is_whitespace() || c == ',' || c == ':' || c == '[' || c == ']')
        .any(|w| matches!(w, "NaN" | "nan" | "inf" | "-inf" | "∞" | "−∞" | "Infinity"))
}

#[test]
fn no_output_holds_a_non_finite_number() {
    let dir = std::env::temp_dir().join(format!("persson-non-finite-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let map2 = dir.join("m2.npy");
    persson::io::npy::write(&map2, 2, 2, &[0.0, 1e-6, 3e-7, -2e-7]).unwrap();
    let map2 = map2.to_string_lossy().into_owned();
    let cases: Vec<(String, bool)> = vec![
        // (command line, whether it must succeed)
        (format!("spectrum --surface {map2} --size 1e-5"), true),
        (format!("adhesion {SA} --contact-modulus 1e9 --pressure 1e7 --work-of-adhesion 1e300"), false),
        (
            format!("bem rough {SA} --contact-modulus 1e9 --grid 32 --work-of-adhesion 0.05 --adhesion-range 1e-5 --mean-gap 1e300"),
            false,
        ),
        (format!("conductance {SA} --contact-modulus 1e9 --pressure 1e300 --conductivity 1"), false),
        (format!("separation {SA} --contact-modulus 1e9 --pressure 1e12"), true),
        // full contact: K and h_c are +∞, printed as – with a warning
        (format!("conductance {SA} --contact-modulus 1e7 --pressure 2e7 --conductivity 0.2"), true),
        (format!("area {SA} --contact-modulus 1e-300 --pressure 1e7"), false),
    ];
    for (cmd, succeeds) in cases {
        for format in ["", "--json", "--csv"] {
            let line = format!("{cmd} {format}");
            let args: Vec<&str> = line.split_whitespace().collect();
            let (code, out, err) = persson(&args);
            match format {
                // serde_json reads no NaN or ∞: a non-finite value fails to parse.
                "--json" if code == 0 => {
                    serde_json::from_str::<serde_json::Value>(&out)
                        .unwrap_or_else(|e| panic!("{line}: {e}: {out}"));
                }
                _ => assert!(!has_non_finite(&out), "{line}: {out}"),
            }
            match succeeds {
                true => assert_eq!(code, 0, "{line}: {err}"),
                false => {
                    assert_eq!((code, out.as_str()), (2, ""), "{line}: {err}");
                    assert!(
                        err.starts_with("persson: error: --"),
                        "{line}: names no flag: {err}"
                    );
                }
            }
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

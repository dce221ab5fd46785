//! Corrected contact-area theories and the mean interfacial separation, each
//! against an independent reference (E1 is unit-tested in src/special.rs).

// Reference values keep the digits mpmath printed; f64 rounds them.
#![allow(clippy::excessive_precision)]

use persson::corrected::{self, Theory};
use persson::separation::Separation;
use persson::spectrum::{Amplitude, SelfAffine};

fn surface() -> SelfAffine {
    // 4 decades, roll-off at 10 q_l, unit rms slope.
    SelfAffine::new(1e3, 1e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

// ------------------------------------------------------- separation

// ------------------------------------------------------------- CLI

mod cli {
    use super::*;
    use crate::common::{json, persson};

    const SPECTRUM: [&str; 12] = [
        "--hurst",
        "0.8",
        "--q-l",
        "1e3",
        "--q-r",
        "1e4",
        "--q-s",
        "1e7",
        "--rms-slope",
        "1",
        "--contact-modulus",
        "1",
    ];

    fn args<'a>(cmd: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
        let mut v = vec![cmd];
        v.extend_from_slice(&SPECTRUM);
        v.extend_from_slice(&["--pressure", "1e-4,1e-2,0.5", "--json"]);
        v.extend_from_slice(extra);
        v
    }

    #[test]
    fn area_theory_flag() {
        let core = json(&args("area", &[]));
        assert_eq!(core["theory"], "original");
        for (name, theory) in [
            ("yang-persson", Theory::yang_persson()),
            ("wang-muser", Theory::wang_muser()),
            ("xu", Theory::Xu { gamma: 0.3 }),
        ] {
            let extra: Vec<&str> = match theory {
                Theory::Xu { .. } => vec!["--theory", name, "--gamma", "0.3"],
                _ => vec!["--theory", name],
            };
            let v = json(&args("area", &extra));
            assert_eq!(v["theory"], name);
            assert_eq!(v["gamma"].as_f64(), theory.gamma());
            for (p, c) in v["points"]
                .as_array()
                .unwrap()
                .iter()
                .zip(core["points"].as_array().unwrap())
            {
                // Same G as the core's area; A/A0 from the chosen theory.
                assert_eq!(p["g"], c["g"]);
                let g = p["g"].as_f64().unwrap();
                let want = theory
                    .contact_fraction(g, 0.0, 1e-12)
                    .unwrap()
                    .contact_fraction;
                let got = p["contact_fraction"].as_f64().unwrap();
                assert!((got - want).abs() < 1e-15, "{name}: {got} vs {want}");
                assert!(got > c["contact_fraction"].as_f64().unwrap());
            }
        }
    }

    #[test]
    fn separation_json_interface() {
        let v = json(&args("separation", &[]));
        let s = surface();
        let sep = Separation::new(&s, 1.0).unwrap().with_breaks(&[s.q_r()]);
        let pts = v["points"].as_array().unwrap();
        assert_eq!(pts.len(), 3);
        for p in pts {
            let pressure = p["nominal_pressure"].as_f64().unwrap();
            let want = sep.point(pressure).unwrap();
            // serde_json's default float parsing may be 1 ulp off the printed value.
            for (key, w) in [
                ("mean_separation", want.mean_separation),
                ("stiffness", want.stiffness),
            ] {
                let got = p[key].as_f64().unwrap();
                assert!(
                    (got - w).abs() <= 2.0 * f64::EPSILON * w,
                    "{key}: {got} vs {w}"
                );
            }
        }
        let law = sep.low_load_law().unwrap();
        let u0 = v["low_load_length"].as_f64().unwrap();
        assert!((u0 - law.length.value).abs() <= 2.0 * f64::EPSILON * law.length.value);
        let bound = v["low_load_length_error_bound"].as_f64().unwrap();
        assert!((bound - law.length.error).abs() <= 2.0 * f64::EPSILON * law.length.error);
    }

    #[cfg(feature = "plot")]
    #[test]
    fn separation_plots_all_theories() {
        let dir = std::env::temp_dir().join(format!("persson-theories-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (u, a) = (dir.join("u.svg"), dir.join("a.svg"));
        let (us, as_) = (u.to_str().unwrap(), a.to_str().unwrap());
        let v = json(&args(
            "separation",
            &["--plot", us, "--plot-area", as_, "--plot-points", "12"],
        ));
        assert_eq!(v["points"].as_array().unwrap().len(), 3);
        let area = std::fs::read_to_string(&a).unwrap();
        for name in corrected::THEORY_NAMES {
            assert!(area.contains(name), "{name} missing from the area plot");
        }
        assert!(std::fs::read_to_string(&u)
            .unwrap()
            .contains("u0 ln(σ_ref/σ0)"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn bad_theory_input_exits_2() {
        for (extra, field) in [
            (vec!["--theory", "yang-persson", "--gamma", "0"], "gamma"),
            (vec!["--theory", "yang-persson", "--gamma", "1.5"], "gamma"),
            (vec!["--theory", "wang-muser", "--gamma", "-1"], "gamma"),
            (vec!["--theory", "xu", "--gamma", "nan"], "gamma"),
            (vec!["--theory", "original", "--gamma", "0.5"], "gamma"),
            (
                vec!["--theory", "yang-persson", "--pressure", "0"],
                "pressure",
            ),
            (vec!["--theory", "xu", "--pressure", "-1"], "pressure"),
            (vec!["--theory", "hertz"], "theory"),
        ] {
            let (code, out, err) = persson(&args("area", &extra));
            assert_eq!(code, 2, "{extra:?}: {out}{err}");
            assert!(
                err.contains(field) && !err.contains("panicked"),
                "{extra:?}: {err}"
            );
        }
        for bad in ["0", "-1e3", "nan"] {
            let (code, _, err) = persson(&args("separation", &["--pressure", bad]));
            assert_eq!(code, 2, "{bad}: {err}");
            assert!(
                err.contains("pressure") && err.lines().count() == 1,
                "{err}"
            );
        }
    }
}

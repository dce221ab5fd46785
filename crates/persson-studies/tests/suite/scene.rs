//! Scene files: parsing, errors with line and column, computing only what a
//! scene asks for, and every number against an oracle (closed forms,
//! identities, the subcommand of the same name to the last digit).

use std::path::Path;

use persson::Error;
use persson_studies::scene::Scene;

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

#[test]
fn area_matches_the_closed_form_and_only_it_is_computed() {
    let r = parse(&scene(r#"{ "area": {} }"#)).unwrap().run().unwrap();
    assert!(r.kappa.is_none() && r.magnification.is_none() && r.stress.is_none());
    let area = r.area.unwrap();
    assert_eq!(area.points.len(), 2);
    for (p, sigma0) in area.points.iter().zip([0.01, 0.1]) {
        let g = 1.0 / (8.0 * sigma0 * sigma0);
        assert!((p.g - g).abs() <= G_REL_TOL * g, "G = {} vs {g}", p.g);
        // Persson (2001): A/A0 = erf(1/(2√G)), 1 − A/A0 = erfc(1/(2√G)).
        let exact = libm::erf(0.5 / g.sqrt());
        assert!(
            (p.contact_fraction - exact).abs() < AREA_ABS_TOL,
            "{}",
            p.contact_fraction
        );
        assert!((p.non_contact_fraction - libm::erfc(0.5 / g.sqrt())).abs() < AREA_ABS_TOL);
        assert!(p.error_bound > 0.0 && p.error_bound < AREA_ABS_TOL);
        assert_eq!(p.effective_g, Some(p.g), "original theory: G_e = G");
        let bush = (2.0 * std::f64::consts::PI).sqrt() * sigma0;
        assert!((p.contact_fraction_bush_linear - bush).abs() <= 4.0 * f64::EPSILON * bush);
    }
    assert!((area.rms_slope - 1.0).abs() < 1e-14);
    let json =
        serde_json::to_value(parse(&scene(r#"{ "kappa": {} }"#)).unwrap().run().unwrap()).unwrap();
    assert!(
        json.get("area").is_none(),
        "absent outputs are not written: {json}"
    );
}

#[test]
fn kappa_values_are_the_papers() {
    let r = parse(r#"{"schema": 1, "outputs": {"kappa": {}}}"#)
        .unwrap()
        .run()
        .unwrap();
    let k = r.kappa.unwrap();
    // Bush, Gibson & Thomas (1975): √(2π); Persson (2001): √(8/π).
    assert_eq!(k.kappa_bush, (2.0 * std::f64::consts::PI).sqrt());
    assert_eq!(k.kappa_persson, (8.0 / std::f64::consts::PI).sqrt());
    assert!(k.points.is_empty() && k.rms_slope.is_none());
    // With a surface: A/A0 = κ σ0/(E* h'_rms), h'_rms = 1.
    let k = parse(&scene(r#"{ "kappa": {} }"#))
        .unwrap()
        .run()
        .unwrap()
        .kappa
        .unwrap();
    for (p, sigma0) in k.points.iter().zip([0.01, 0.1]) {
        let want = (8.0 / std::f64::consts::PI).sqrt() * sigma0;
        assert!((p.contact_fraction_persson_linear - want).abs() <= 4.0 * f64::EPSILON * want);
    }
}

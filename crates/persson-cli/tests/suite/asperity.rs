//! `persson area --theory overlap|greenwood-williamson|bush` (issue 27): each
//! against values computed here independently of the crate (Simpson sums of
//! the Gaussian integrals, the summit closed forms written out, the hardness
//! law), plus warnings and bad input naming the flag.

use crate::common;

use common::{json, persson};
use serde_json::Value;

/// A self-affine spectrum with no roll-off, two decades: α = m0 m4/m2² ≈ 30.
const SPECTRUM: [&str; 12] = [
    "--hurst",
    "0.8",
    "--q-l",
    "1e4",
    "--q-r",
    "1e4",
    "--q-s",
    "1e6",
    "--rms-height",
    "1e-6",
    "--contact-modulus",
    "1e9",
];

/// Simpson sums here against the crate's F_n (trapezoid, continued fraction,
/// tested to 1e-13 against mpmath): 2e-4 steps on a smooth integrand give
/// ~1e-14; the separation is solved to 1e-14 of σ_s.
const GW_TOL: f64 = 1e-10;

/// Summit closed forms against the crate's, same formulas in another order.
const CLOSED_FORM_TOL: f64 = 1e-12;

/// The standard normal density.
fn phi(x: f64) -> f64 {
    (-0.5 * x * x).exp() / std::f64::consts::TAU.sqrt()
}

/// F_n(t) = ∫_t^∞ (s − t)^n φ(s) ds with s = t + w², ds = 2w dw (smooth in
/// w), composite Simpson on w ∈ [0, 7] (the integrand is below 1e-20 beyond).
fn f_n(n: f64, t: f64) -> f64 {
    let m = 35_000;
    let h = 7.0 / m as f64;
    let g = |w: f64| 2.0 * w.powf(2.0 * n + 1.0) * phi(t + w * w);
    let mut s = g(0.0) + g(7.0);
    for k in 1..m {
        s += g(k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * h / 3.0
}

fn area(theory: &str, extra: &[&str]) -> Value {
    let mut args = vec!["area", "--theory", theory, "--json"];
    args.extend(SPECTRUM);
    args.extend(extra);
    json(&args)
}

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number `{key}` in {v}"))
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn greenwood_williamson_against_its_closed_forms() {
    let r = area("greenwood-williamson", &["--pressure", "1e5,1e6,1e7"]);
    let (m0, m2, m4) = (f(&r, "m0"), f(&r, "m2"), f(&r, "m4"));
    let pi = std::f64::consts::PI;
    let alpha = m0 * m4 / (m2 * m2);
    assert!(rel(f(&r, "bandwidth_parameter"), alpha) < CLOSED_FORM_TOL);
    // Nayak (1971) / McCool (1986): η, κ̄, y_s, σ_s of the summits.
    let eta = m4 / (6.0 * pi * 3f64.sqrt() * m2);
    let kappa = 8.0 / 3.0 * (m4 / pi).sqrt();
    let y_s = 4.0 * (m0 / (pi * alpha)).sqrt();
    // McCool's 0.8968 is 1 + 16/π − 3√3 to its digits.
    let s_s = ((1.0 - (1.0 + 16.0 / pi - 3.0 * 3f64.sqrt()) / alpha) * m0).sqrt();
    assert!(rel(f(&r, "summit_density"), eta) < CLOSED_FORM_TOL);
    assert!(rel(f(&r, "summit_curvature"), kappa) < CLOSED_FORM_TOL);
    assert!(rel(f(&r, "summit_mean_height"), y_s) < CLOSED_FORM_TOL);
    assert!(rel(f(&r, "summit_rms_height"), s_s) < CLOSED_FORM_TOL);
    let e_star = 1e9;
    let beta = 1.0 / kappa;
    for p in r["points"].as_array().unwrap() {
        let t = (f(p, "separation") - y_s) / s_s;
        let area = pi * eta * beta * s_s * f_n(1.0, t);
        let load = 4.0 / 3.0 * eta * e_star * beta.sqrt() * s_s.powf(1.5) * f_n(1.5, t);
        let n = eta * f_n(0.0, t);
        assert!(rel(f(p, "contact_fraction"), area) < GW_TOL, "{p}");
        assert!(rel(f(p, "nominal_pressure"), load) < GW_TOL, "{p}");
        assert!(rel(f(p, "contact_number_density"), n) < GW_TOL, "{p}");
        assert!(f(p, "error_bound") < 1e-12 * area);
    }
}

#[test]
fn overlap_follows_the_hardness_law() {
    // σ0 = σY A/A0 exactly; the cut of Gaussian heights at A/A0 = 1/2 is the mean plane.
    let r = area(
        "overlap",
        &["--yield-stress", "2e7", "--pressure", "1e6,1e7"],
    );
    let points = r["points"].as_array().unwrap();
    assert!(rel(f(&points[0], "contact_fraction"), 0.05) < 1e-14);
    assert!(f(&points[1], "separation").abs() < 1e-12 * f(&r, "rms_height"));
    assert_eq!(f(&r, "yield_stress"), 2e7);
}

#[test]
fn bush_reports_its_low_load_slope_and_warns_at_high_load() {
    // κ = √(2π) (Bush, Gibson & Thomas 1975); the approach to it needs
    // δ ≫ √α (tests/asperity.rs checks it at δ = 10⁸ rms heights).
    let r = area("bush", &["--pressure", "1e-3,3e7"]);
    assert!(rel(f(&r, "kappa"), (2.0 * std::f64::consts::PI).sqrt()) < 1e-12);
    let (low, high) = (&r["points"][0], &r["points"][1]);
    assert!(f(low, "separation") > f(high, "separation"));
    // The summit count is bounded by the summit density.
    assert!(f(high, "contact_number_density") < f(&r, "summit_density"));
    let kinds: Vec<&str> = r["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|w| w["kind"].as_str())
        .collect();
    assert!(kinds.contains(&"coalescence"), "{kinds:?}");
}

#[test]
fn a_narrow_band_warns_of_small_bandwidth() {
    // Half a decade: α ≈ 4, below Nayak's threshold 10.
    let r = json(&[
        "area",
        "--theory",
        "greenwood-williamson",
        "--json",
        "--hurst",
        "0.8",
        "--q-l",
        "1e4",
        "--q-r",
        "1e4",
        "--q-s",
        "3e4",
        "--rms-height",
        "1e-6",
        "--contact-modulus",
        "1e9",
        "--pressure",
        "1e5",
    ]);
    assert!(f(&r, "bandwidth_parameter") < 10.0);
    assert!(r["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w["kind"] == "small_bandwidth"));
}

#[test]
fn bad_input_names_the_flag() {
    let run = |theory: &str, extra: &[&str]| {
        let mut args = vec!["area", "--theory", theory];
        args.extend(SPECTRUM);
        args.extend(extra);
        let (code, _, err) = persson(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
        err
    };
    let e = run("overlap", &["--pressure", "1e6"]);
    assert!(e.contains("yield_stress"), "{e}");
    let e = run("bush", &["--pressure", "1e6", "--yield-stress", "1e9"]);
    assert!(e.contains("yield_stress"), "{e}");
    let e = run("bush", &["--pressure", "1e6", "--gamma", "0.5"]);
    assert!(e.contains("gamma"), "{e}");
    let e = run("overlap", &["--pressure", "1e6", "--yield-stress", "-1"]);
    assert!(e.contains("yield_stress"), "{e}");
}

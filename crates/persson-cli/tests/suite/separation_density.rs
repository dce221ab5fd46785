//! `separation --separation-density`: P(u) as its own output (issue 23),
//! checked by its identities: the contact's weight plus the continuous part
//! is 1, the first moment is ū plus the fold's shift, and the trapezoidal
//! integral of the printed P_nc(u) recovers the non-contact fraction.

use crate::common;

use common::{json, persson};
use serde_json::Value;

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number `{key}` in {v}"))
}

#[test]
fn density_is_normalised_and_its_moment_is_the_mean_separation() {
    let r = json(&[
        "separation",
        "--example",
        "--pressure",
        "1e5,1e6,1e7,1e8",
        "--separation-density",
        "--density-points",
        "2001",
        "--json",
    ]);
    let curves = r["curves"].as_array().expect("curves");
    assert_eq!(curves.len(), 4);
    for c in curves {
        let norm = f(c, "contact_fraction") + f(c, "non_contact_fraction");
        assert!((norm - 1.0).abs() < 1e-9, "A/A0 + ∫P_nc = {norm}");
        let moment = f(c, "separation_first_moment");
        let ubar = f(c, "mean_separation");
        let shift = f(c, "fold_shift");
        assert!(shift >= 0.0);
        assert!(
            (moment - ubar - shift).abs() <= 1e-6 * moment,
            "∫uP = {moment}, ū + s_fold = {}",
            ubar + shift
        );
        // The printed curve integrates (trapezoids on 2001 points) to ∫P_nc:
        // a P(u) off by a few per cent fails here.
        let pts = c["points"].as_array().expect("points");
        let (u, p): (Vec<f64>, Vec<f64>) = pts
            .iter()
            .map(|q| (f(q, "separation"), f(q, "separation_density")))
            .unzip();
        let trapezoid: f64 = (1..u.len())
            .map(|i| 0.5 * (p[i] + p[i - 1]) * (u[i] - u[i - 1]))
            .sum();
        let nc = f(c, "non_contact_fraction");
        // At σ0 = 1e8 Pa most of P_nc sits within ū ≈ 4e-8 m of u = 0, a
        // dozen grid steps: the trapezoids are good to 1 % there (measured
        // 0.72 %), to 0.2 % at the lower loads.
        let tolerance = if f(c, "nominal_pressure") > 1e7 {
            1e-2
        } else {
            2e-3
        };
        assert!(
            (trapezoid - nc).abs() <= tolerance * nc,
            "σ0 = {}: trapezoids {trapezoid} against ∫P_nc = {nc}",
            f(c, "nominal_pressure")
        );
    }
}

#[test]
fn bad_density_input_names_the_flag() {
    for (args, flag) in [
        (
            &[
                "separation",
                "--example",
                "--pressure",
                "-1",
                "--separation-density",
            ][..],
            "--pressure",
        ),
        (
            &[
                "separation",
                "--example",
                "--separation-density",
                "--density-points",
                "1",
            ][..],
            "--density-points",
        ),
    ] {
        let (code, _, err) = persson(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
    }
}

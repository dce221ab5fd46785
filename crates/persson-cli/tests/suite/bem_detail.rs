//! `bem rough --patches`, `bem rough --subsurface --depth …` and `bem hertz
//! --subsurface` (issue 27), against closed forms and identities computed
//! here: Johnson's Hertz axis stresses, the uniform stress deep below a
//! periodic load, the patch areas adding up to the contact area.
#![cfg(feature = "bem")]

use crate::common;

use common::{json, persson};
use serde_json::Value;

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number `{key}` in {v}"))
}

/// Johnson (1985) §3.4: the largest (σ_z − σ_r)/2 on the Hertz axis and its
/// depth ratio (golden section on the closed form).
fn johnson_max_shear(nu: f64) -> (f64, f64) {
    let tau = |z: f64| {
        let sz = -1.0 / (1.0 + z * z);
        let sr = -(1.0 + nu) * (1.0 - z * (1.0 / z).atan()) + 0.5 / (1.0 + z * z);
        0.5 * (sr - sz)
    };
    let (mut a, mut b) = (0.1, 1.5);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if tau(c) > tau(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let z = 0.5 * (a + b);
    (tau(z), z)
}

#[test]
fn hertz_axis_stresses_converge_to_johnson() {
    let (tau, at) = johnson_max_shear(0.3);
    // Johnson's rounded figures: 0.31 p0 at 0.48 a.
    assert!((tau - 0.31).abs() < 0.005 && (at - 0.48).abs() < 0.005);
    let mut last = f64::INFINITY;
    for n in ["32", "64"] {
        let r = json(&["bem", "hertz", "--subsurface", "--grid", n, "--json"]);
        let err = f(&r, "stress_error");
        assert!(err < last, "N = {n}: {err} not below {last}");
        last = err;
        // The profile is sampled every 0.05 a: τ_max within the sampling
        // (|τ''| ≈ 0.5 p0/a², (0.025)² · 0.25 ≈ 2e-4) and the error.
        assert!((f(&r, "max_shear_stress") - tau).abs() < err + 1e-3, "{r}");
        assert!((f(&r, "depth_ratio") - at).abs() <= 0.025 + 1e-12);
    }
    // The claim of the guide: 64² puts the axis stresses within 1% of p0.
    assert!(last < 1e-2, "{last}");
}

#[test]
fn patches_add_up_to_the_contact_area_and_deep_stress_is_uniform() {
    let r = json(&[
        "bem",
        "rough",
        "--example",
        "--grid",
        "64",
        "--pressure",
        "1e7",
        "--patches",
        "--subsurface",
        "--depth",
        "1e-5,6.283185307179586e-4",
        "--json",
    ]);
    let size = f(&r, "size");
    let p = &r["patches"]["points"][0];
    // Σ patch areas = A/A0 · L² (mean × count), and ∫ n dA = 1 over the bins.
    let total = f(p, "mean_patch_area") * f(p, "patch_count");
    let a = f(&r["points"][0], "contact_fraction");
    assert!((total / (a * size * size) - 1.0).abs() < 1e-12);
    let integral: f64 = p["area_distribution"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| f(b, "density") * (f(b, "area_high") - f(b, "area_low")))
        .sum();
    assert!((integral - 1.0).abs() < 1e-12, "{integral}");
    assert!(f(p, "largest_patch_area") <= total);
    // At depth L the modes have decayed to (1 + qL) e^{−qL} ≤ 7.3 e^{−2π}
    // ≈ 1.4% of their surface amplitude: the stress is the mean load's,
    // σ_zz = −σ0, σ_xx = σ_yy = −ν σ0/(1 − ν), von Mises σ0 (1 − 2ν)/(1 − ν).
    const DEEP_TOL: f64 = 0.05;
    let deep = &r["subsurface"]["points"][0]["planes"][1];
    let nu = 0.3;
    let expected = 1e7 * (1.0 - 2.0 * nu) / (1.0 - nu);
    let vm = f(&deep["von_mises_stress"], "value");
    assert!(
        (vm / expected - 1.0).abs() < DEEP_TOL,
        "{vm} against {expected}"
    );
}

/// Bad settings of the studies beside the solves name their own flag,
/// before any solve (a table would show one): depths out of (0, L],
/// patches' bins per decade 0, a tensile yield stress not > 0.
#[test]
fn bad_study_settings_name_their_flag_before_any_solve() {
    let base = [
        "bem",
        "rough",
        "--example",
        "--grid",
        "32",
        "--pressure",
        "1e7",
    ];
    let depths =
        ["0", "-1e-5", "1", "nan"].map(|d| (vec!["--subsurface", "--depth", d], "--depth"));
    let others = [
        (
            vec!["--patches", "--bins-per-decade", "0"],
            "--bins-per-decade",
        ),
        (
            vec![
                "--subsurface",
                "--depth",
                "1e-5",
                "--tensile-yield-stress",
                "-1",
            ],
            "--tensile-yield-stress",
        ),
    ];
    for (extra, flag) in depths.into_iter().chain(others) {
        let args: Vec<&str> = base.iter().chain(&extra).copied().collect();
        let (code, out, err) = persson(&args);
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert!(err.contains(flag), "{extra:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
        assert!(out.is_empty(), "{extra:?}: {out}");
    }
}

#[test]
#[cfg(feature = "plot")]
fn stress_plots_are_drawn_beside_the_npy() {
    let dir = std::env::temp_dir().join(format!("persson-stress-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let s = |name: &str| dir.join(name).to_string_lossy().into_owned();
    let (code, _, err) = persson(&[
        "bem",
        "rough",
        "--example",
        "--grid",
        "32",
        "--pressure",
        "1e6,1e7",
        "--subsurface",
        "--depth",
        "1e-6,1e-5",
        "--stress-field",
        &s("vm.npy"),
        "--stress-plot",
        &s("vm.svg"),
    ]);
    assert_eq!(code, 0, "{err}");
    for k in 0..2 {
        for j in 0..2 {
            let svg = std::fs::read_to_string(dir.join(format!("vm_{k}_{j}.svg"))).unwrap();
            assert!(svg.contains("Von Mises stress at z"), "{k} {j}");
            assert!(dir.join(format!("vm_{k}_{j}.npy")).exists());
        }
    }
    let (code, _, err) = persson(&[
        "bem",
        "hertz",
        "--grid",
        "32",
        "--subsurface",
        "--stress-plot",
        &s("section.png"),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(std::fs::metadata(dir.join("section.png")).unwrap().len() > 1000);
    // The flag needs --subsurface.
    let (code, _, err) = persson(&["bem", "hertz", "--stress-plot", &s("x.svg")]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--subsurface"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

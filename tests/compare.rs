//! Validation helpers (issue 7): continuum extrapolation, κ fit, user-data scoring.

use persson::compare::{extrapolate, fit_kappa, score, UserData, DEFAULT_ALPHA};

/// Exact arithmetic on a synthetic law: rounding only.
const EXACT: f64 = 1e-12;

#[test]
fn extrapolation_recovers_a_synthetic_law() {
    let law = |n: f64| 0.3 + 0.5 * n.powf(-0.7);
    let n = [64.0, 128.0, 256.0];
    let a: Vec<f64> = n.iter().map(|&x| law(x)).collect();
    // α fitted (Richardson) and α fixed at the seed's 0.7
    let fitted = extrapolate(&n, &a, None).unwrap();
    assert!((fitted.alpha - 0.7).abs() < EXACT, "{fitted:?}");
    assert!((fitted.value - 0.3).abs() < EXACT, "{fitted:?}");
    let fixed = extrapolate(&n, &a, Some(DEFAULT_ALPHA)).unwrap();
    assert!((fixed.value - 0.3).abs() < EXACT && (fixed.c - 0.5).abs() < EXACT);
    assert!(fixed.uncertainty < EXACT);
    // another α: the fit finds it
    let b: Vec<f64> = n.iter().map(|&x| 0.1 - 2.0 * x.powf(-1.3)).collect();
    let f = extrapolate(&n, &b, None).unwrap();
    assert!((f.alpha - 1.3).abs() < 1e-10 && (f.value - 0.1).abs() < EXACT);
}

#[test]
fn extrapolation_uncertainty_covers_noise() {
    // four grids, alternating ±1e-4 noise on top of the law: the true A∞ within 3 se
    let n = [32.0f64, 64.0, 128.0, 256.0];
    let a: Vec<f64> = n
        .iter()
        .enumerate()
        .map(|(i, &x)| 0.2 + 0.3 * x.powf(-0.7) + if i % 2 == 0 { 1e-4 } else { -1e-4 })
        .collect();
    let f = extrapolate(&n, &a, Some(0.7)).unwrap();
    assert!(f.uncertainty > 0.0);
    assert!((f.value - 0.2).abs() < 3.0 * f.uncertainty, "{f:?}");
}

#[test]
fn extrapolation_rejects_bad_input() {
    assert!(extrapolate(&[64.0], &[0.1], None).is_err());
    assert!(extrapolate(&[64.0, 128.0], &[0.1], None).is_err());
    assert!(extrapolate(&[64.0, -1.0], &[0.1, 0.2], None).is_err());
    assert!(extrapolate(&[64.0, 128.0], &[0.1, f64::NAN], None).is_err());
}

#[test]
fn kappa_fit_on_a_linear_law() {
    let (e, s) = (2.0, 0.5);
    let p: Vec<f64> = (1..=10).map(|i| 1e-3 * i as f64).collect();
    let a: Vec<f64> = p.iter().map(|&x| 2.0 * x / (e * s)).collect();
    let k = fit_kappa(&p, &a, e, s, 0.1).unwrap();
    assert!((k.kappa - 2.0).abs() < EXACT && k.standard_error < EXACT);
    // only points with A < 0.1 are used: 0.002·i/1 < 0.1 for all 10
    assert_eq!(k.points, 10);
    assert!(fit_kappa(&p, &a, e, s, 1e-9).is_err());
}

#[test]
fn user_file_equal_to_the_theory_scores_zero() {
    let theory = [0.01, 0.05, 0.2];
    let sc = score(&theory, &theory);
    assert_eq!(sc.rms, 0.0);
    assert_eq!(sc.max_abs, 0.0);
    let sc = score(&[0.011, 0.05, 0.2], &theory);
    assert!((sc.max_abs - 0.1).abs() < EXACT);
}

#[test]
fn user_data_csv_errors_name_the_line() {
    let dir = std::env::temp_dir().join(format!("persson-compare-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let ok = UserData::from_csv(&write(
        "ok.csv",
        "pressure,contact_fraction\n0.01,0.02\n0.1,0.2\n",
    ))
    .unwrap();
    assert_eq!(ok.pressures, vec![0.01, 0.1]);
    for (text, line, needle) in [
        ("p,a\n0.01,0.02\n0.1\n", 3, "2 columns"),
        ("0.01,0.02\n0.1,x\n", 2, "contact_fraction"),
        ("0.01,0.02\n-0.1,0.2\n", 2, "pressure"),
        ("0.01,1.5\n", 1, "[0, 1]"),
    ] {
        match UserData::from_csv(&write("bad.csv", text)) {
            Err(persson::Error::Parse {
                line: l, message, ..
            }) => {
                assert_eq!(l, line, "{message}");
                assert!(message.contains(needle), "{message}");
            }
            other => panic!("{text:?}: {other:?}"),
        }
    }
}

#[test]
fn density_distance_is_zero_for_equal_densities() {
    use persson::compare::density_distance;
    let x = [0.0, 1.0, 2.0, 3.0];
    let b = [0.0, 1.0, 1.0, 0.0];
    assert_eq!(density_distance(&x, &b, &b).unwrap(), 0.0);
    // a = 2b: ∫|a − b| / ∫|b| = 1
    let a: Vec<f64> = b.iter().map(|v| 2.0 * v).collect();
    assert!((density_distance(&x, &a, &b).unwrap() - 1.0).abs() < EXACT);
    assert!(density_distance(&x, &a[..3], &b).is_err());
    assert!(density_distance(&x, &b, &[0.0; 4]).is_err());
}

//! Validation helpers: continuum extrapolation, κ fit, user-data scoring.

use persson_studies::validation::{
    extrapolate, fit_kappa, score, UserData, UserHistogram, DEFAULT_ALPHA,
};

/// Exact arithmetic on a synthetic law: rounding only.
const EXACT: f64 = 1e-12;

#[test]
fn extrapolation_recovers_a_synthetic_law() {
    let law = |n: f64| 0.3 + 0.5 * n.powf(-0.7);
    let n = [64.0, 128.0, 256.0];
    let a: Vec<f64> = n.iter().map(|&x| law(x)).collect();
    // α fitted (Richardson) and α fixed at Campañá & Müser's 0.7
    let fitted = extrapolate(&n, &a, None).unwrap();
    assert!((fitted.alpha - 0.7).abs() < EXACT, "{fitted:?}");
    assert!((fitted.value - 0.3).abs() < EXACT, "{fitted:?}");
    let fixed = extrapolate(&n, &a, Some(DEFAULT_ALPHA)).unwrap();
    assert!((fixed.value - 0.3).abs() < EXACT && (fixed.coefficient - 0.5).abs() < EXACT);
    // three grids, two parameters: a standard error is estimated, and the
    // exact law leaves none; the step from the finest grid is c N^−α
    assert!(fixed.standard_error.unwrap() < EXACT);
    assert!((fixed.extrapolation_step - 0.5 * 256f64.powf(-0.7)).abs() < EXACT);
    // α fitted too: three parameters, no standard error, the step instead
    assert_eq!(fitted.standard_error, None);
    assert!((fitted.uncertainty() - 0.5 * 256f64.powf(-0.7)).abs() < 1e-10);
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
    let se = f.standard_error.unwrap();
    assert!(se > 0.0);
    assert!((f.value - 0.2).abs() < 3.0 * se, "{f:?}");
    // the residuals are ±1e-4 (less what the line absorbs): se(A∞) is of
    // that order, not zero and not the size of the correction
    assert!(se > 1e-5 && se < 1e-3, "{f:?}");
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
    assert!((k.kappa - 2.0).abs() < EXACT && k.standard_error.unwrap() < EXACT);
    assert_eq!(k.nominal_pressure_range, [1e-3, 1e-2]);
    // one point: κ exact, no standard error to estimate
    let one = fit_kappa(&p[..1], &a[..1], e, s, 0.1).unwrap();
    assert!((one.kappa - 2.0).abs() < EXACT);
    assert_eq!(one.standard_error, None);
    // a bent curve: A = 2x + 50x² on x = σ0/(E* s); the fit through the
    // origin is κ = Σx A/Σx² = 2 + 50 Σx³/Σx²
    let bent: Vec<f64> = p.iter().map(|&x| 2.0 * x + 50.0 * x * x).collect();
    let xs: Vec<f64> = p.clone();
    let want = 2.0
        + 50.0 * xs.iter().map(|x| x.powi(3)).sum::<f64>() / xs.iter().map(|x| x * x).sum::<f64>();
    let k = fit_kappa(&p, &bent, 1.0, 1.0, 0.1).unwrap();
    assert!((k.kappa - want).abs() < EXACT, "{k:?} vs {want}");
    // only points with A < 0.1 are used: 0.002·i/1 < 0.1 for all 10
    assert_eq!(k.points, 10);
    assert!(fit_kappa(&p, &a, e, s, 1e-9).is_err());
}

#[test]
fn user_file_equal_to_the_theory_scores_zero() {
    let theory = [0.01, 0.05, 0.2];
    let sc = score(&theory, &theory);
    assert_eq!(sc.rms_relative_deviation, 0.0);
    assert_eq!(sc.max_relative_deviation, 0.0);
    let sc = score(&[0.011, 0.05, 0.2], &theory);
    assert!((sc.max_relative_deviation - 0.1).abs() < EXACT);
    // rms of (0.1, 0, 0) = 0.1/√3
    assert!((sc.rms_relative_deviation - 0.1 / 3f64.sqrt()).abs() < EXACT);
    assert_eq!(sc.points, 3);
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
        "nominal_pressure,contact_fraction\n0.01,0.02\n0.1,0.2\n",
    ))
    .unwrap();
    assert_eq!(ok.nominal_pressure, vec![0.01, 0.1]);
    assert_eq!(ok.contact_fraction, vec![0.02, 0.2]);
    let h = UserHistogram::from_csv(&write("h.csv", "sigma,density\n0.001,5\n0.003,8\n")).unwrap();
    assert_eq!((h.sigma, h.density), (vec![0.001, 0.003], vec![5.0, 8.0]));
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
    use persson_studies::validation::density_distance;
    let x = [0.0, 1.0, 2.0, 3.0];
    let b = [0.0, 1.0, 1.0, 0.0];
    assert_eq!(density_distance(&x, &b, &b).unwrap(), 0.0);
    // a = 2b: ∫|a − b| / ∫|b| = 1
    let a: Vec<f64> = b.iter().map(|v| 2.0 * v).collect();
    assert!((density_distance(&x, &a, &b).unwrap() - 1.0).abs() < EXACT);
    assert!(density_distance(&x, &a[..3], &b).is_err());
    assert!(density_distance(&x, &b, &[0.0; 4]).is_err());
}

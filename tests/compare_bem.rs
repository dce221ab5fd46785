//! Theory against the BEM (issue 7): nested surfaces, the resolution sweep,
//! its continuum limit, κ between Persson and Bush, histograms, and the
//! `persson compare` CLI (JSON keys, user data, bad data files).
#![cfg(feature = "bem")]

use persson::bem::Surface;
use persson::compare_bem::{
    default_pressures, interpolate_log, mean_and_error, nested_surfaces, resolution_grids,
    resolvable_q_max, sweep, BandLimited, GridResult, Histogram, Sweep, SweepConfig,
};
use persson::kappa::Kappa;
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};

/// Rounding of sums over ≤ 256² values and of a few FFTs.
const ROUNDING: f64 = 1e-12;

/// H = 0.8 surface with a roll-off at 2 q_l, q_s = `q_s` q_l, rms slope 0.1, q_l = 1.
fn surface_spectrum(q_s: f64) -> SelfAffine {
    SelfAffine::new(1.0, 2.0, q_s, 0.8, Amplitude::RmsSlope(0.1)).unwrap()
}

fn config(finest: usize, seeds: u64) -> SweepConfig {
    SweepConfig {
        grids: resolution_grids(finest, 3).unwrap(),
        seeds: (1..=seeds).collect(),
        options: persson::bem::Options {
            tol: 1e-8,
            max_iter: 10_000,
            warm_start: true,
        },
        size: std::f64::consts::TAU,
    }
}

#[test]
fn grids_halve_the_finest() {
    assert_eq!(resolution_grids(256, 3).unwrap(), vec![64, 128, 256]);
    assert_eq!(resolution_grids(64, 2).unwrap(), vec![32, 64]);
    assert!(resolution_grids(20, 3).is_err()); // coarsest 5 < 8
    assert!(resolution_grids(130, 3).is_err()); // not a multiple of 4
    assert!(resolution_grids(256, 1).is_err());
    // 4 pixels per shortest wavelength on 64²: q_s ≤ 16 q_l
    assert_eq!(resolvable_q_max(1.0, 64, 4.0), 16.0);
}

#[test]
fn band_limit_clips_the_spectrum() {
    let s = surface_spectrum(64.0);
    let b = BandLimited::new(&s, 16.0).unwrap();
    assert!(b.clipped());
    assert_eq!(b.q_max(), 16.0);
    assert_eq!(b.c(20.0), 0.0);
    assert_eq!(b.c(10.0), s.c(10.0));
    let m = b.moment(3, 0.0, 100.0).unwrap().value;
    let r = s.moment(3, 0.0, 16.0).unwrap().value;
    assert!((m - r).abs() <= ROUNDING * r);
    assert!(!BandLimited::new(&s, 100.0).unwrap().clipped());
    assert!(BandLimited::new(&s, 0.5).is_err());
}

#[test]
fn nested_surfaces_are_one_band_limited_surface() {
    // The coarse grids subsample the finest: the trigonometric interpolants
    // coincide, so rms height and rms slope (computed by FFT on each grid)
    // agree to rounding. Aliasing of any mode would break this.
    let s = surface_spectrum(16.0);
    let surfaces = nested_surfaces(&s, &[64, 128, 256], std::f64::consts::TAU, 7).unwrap();
    let fine: &Surface = &surfaces[2];
    let (h, g) = (fine.rms_height(), fine.rms_slope().unwrap());
    for c in &surfaces[..2] {
        assert!(
            (c.rms_height() - h).abs() <= 1e-10 * h,
            "{} vs {h}",
            c.rms_height()
        );
        let gc = c.rms_slope().unwrap();
        assert!((gc - g).abs() <= 1e-10 * g, "{gc} vs {g}");
    }
    // q_s beyond the coarsest Nyquist (16²: k < 8 − 1) is refused
    assert!(nested_surfaces(&s, &[16, 32], std::f64::consts::TAU, 7).is_err());
    assert!(nested_surfaces(&s, &[64, 96], std::f64::consts::TAU, 7).is_err());
}

#[test]
fn histogram_integrates_to_the_contact_fraction() {
    let mut h = Histogram::new(1.0);
    let field = [0.0, 0.5, 1.2, 3.7, 0.0, 0.0, 2.2, 0.01];
    h.add(&field);
    h.add(&[0.0; 8]);
    let (lo, hi, d) = h.density(5);
    let total: f64 = d
        .iter()
        .zip(lo.iter().zip(&hi))
        .map(|(p, (l, u))| p * (u - l))
        .sum();
    // 5 contact nodes of 16
    assert!((total - 5.0 / 16.0).abs() < ROUNDING);
    assert!(*hi.last().unwrap() >= 3.7);
}

#[test]
fn helpers() {
    let (m, se) = mean_and_error(&[1.0, 2.0, 3.0]);
    assert!((m - 2.0).abs() < ROUNDING && (se - (1.0f64 / 3.0).sqrt()).abs() < ROUNDING);
    assert_eq!(mean_and_error(&[4.0]), (4.0, 0.0));
    // exact on a power law
    let x = [1.0, 2.0, 4.0];
    let y: Vec<f64> = x.iter().map(|v: &f64| 3.0 * v.powf(1.5)).collect();
    let v = interpolate_log(&x, &y, 3.0).unwrap();
    assert!((v - 3.0 * 3f64.powf(1.5)).abs() < ROUNDING * v);
    assert!(interpolate_log(&x, &y, 5.0).is_none());
    let p = default_pressures(2.0, 0.1, 8, 0.01, 0.3);
    assert_eq!(p.len(), 8);
    assert!((p[0] - 0.001).abs() < ROUNDING && (p[7] - 0.03).abs() < ROUNDING);
}

/// A sweep following A_s(N) = A∞,s + c N^−0.7 exactly, two seeds.
fn synthetic_sweep() -> Sweep {
    let grids = [64usize, 128, 256];
    let a_inf = [[0.30, 0.10], [0.32, 0.12]]; // [seed][pressure]
    Sweep {
        pressures: vec![1e-2, 1e-3],
        grids: grids
            .iter()
            .map(|&g| GridResult {
                grid: g,
                contact_fraction: a_inf
                    .iter()
                    .map(|s| s.iter().map(|a| a + 0.5 * (g as f64).powf(-0.7)).collect())
                    .collect(),
                mean_gap: vec![vec![0.0; 2]; 2],
                surface_rms_slope: vec![0.1; 2],
                iterations: 0,
                residual: 0.0,
                seconds: 0.0,
            })
            .collect(),
        histograms: Vec::new(),
    }
}

#[test]
fn sweep_extrapolation_recovers_the_law_and_the_seed_scatter() {
    let sw = synthetic_sweep();
    for alpha in [Some(0.7), None] {
        let c = sw.extrapolate(alpha).unwrap();
        for (k, want) in [0.31, 0.11].into_iter().enumerate() {
            assert!((c[k].fit.value - want).abs() < ROUNDING, "{:?}", c[k]);
            assert!((c[k].fit.alpha - 0.7).abs() < 1e-9);
            // two seeds 0.02 apart: standard error of the mean 0.01
            assert!((c[k].seed_scatter - 0.01).abs() < ROUNDING);
            // α fixed: the exact law leaves no residual; α fitted from three
            // grids: the fit's uncertainty is the extrapolation step c N^−α
            let fit = if alpha.is_some() {
                0.0
            } else {
                0.5 * 256f64.powf(-0.7)
            };
            assert!((c[k].fit.uncertainty - fit).abs() < 1e-9, "{:?}", c[k]);
            assert!((c[k].uncertainty - fit.hypot(0.01)).abs() < 1e-9);
        }
    }
}

#[test]
fn bem_sweep_is_seed_reproducible_and_consistent() {
    let s = surface_spectrum(4.0);
    let cfg = config(64, 1);
    let p = [2e-3, 5e-3];
    let a = sweep(&s, 1.0, &p, &cfg, &mut |_| {}).unwrap();
    let b = sweep(&s, 1.0, &[5e-3, 2e-3], &cfg, &mut |_| {}).unwrap();
    for (ga, gb) in a.grids.iter().zip(&b.grids) {
        // the same solves in another order: warm start changes only the path
        let (x, y) = (ga.contact_fraction[0][0], gb.contact_fraction[0][1]);
        assert!(
            (x - y).abs() <= 2.0 / (ga.grid * ga.grid) as f64,
            "{x} vs {y}"
        );
        assert!(ga.contact_fraction[0][0] < ga.contact_fraction[0][1]);
        assert!(ga.mean_gap[0][0] > ga.mean_gap[0][1] && ga.mean_gap[0][1] > 0.0);
    }
    // the finest histogram integrates to the finest contact fraction
    for (k, h) in a.histograms.iter().enumerate() {
        let (lo, hi, d) = h.density(30);
        let total: f64 = d
            .iter()
            .zip(lo.iter().zip(&hi))
            .map(|(p, (l, u))| p * (u - l))
            .sum();
        let want = a.grids[2].contact_fraction[0][k];
        assert!((total - want).abs() < ROUNDING, "{total} vs {want}");
    }
}

/// H = 0.8, q_r = 2 q_l, q_s = 16 q_l (4 pixels per wavelength on 64²), two
/// seeds: κ of the 256² grid and of the continuum limit lie between
/// Persson's √(8/π) and Bush's √(2π) (seed 002: numerical κ ≈ 2). Measured
/// (release, 2 cores): ~2 s; κ_256 = 2.30, κ_∞ = 2.15 with 4 seeds.
#[test]
fn bem_kappa_at_256_lies_between_persson_and_bush() {
    let s = surface_spectrum(16.0);
    let slope = s.rms_slope(1.0, 16.0).unwrap().value;
    let p = default_pressures(1.0, slope, 6, 0.01, 0.09);
    let sw = sweep(&s, 1.0, &p, &config(256, 2), &mut |_| {}).unwrap();
    let k = sw.kappa(1.0, slope, 0.1, Some(0.7)).unwrap();
    let (persson, bush) = (Kappa::Persson.value(), Kappa::Bush.value());
    let k256 = k.per_grid[2].1.kappa;
    assert!(persson < k256 && k256 < bush, "{k:?}");
    let ki = k.extrapolated.kappa;
    assert!(persson < ki && ki < bush, "{k:?}");
    // convergence from above: coarse grids overestimate the area
    assert!(k.per_grid[0].1.kappa > k256 && k256 > ki, "{k:?}");
}

mod common;

mod cli {
    use crate::common::persson;

    const SURFACE: [&str; 12] = [
        "compare",
        "--hurst",
        "0.8",
        "--q-l",
        "1",
        "--q-r",
        "2",
        "--q-s",
        "8",
        "--rms-slope",
        "0.1",
        "--json",
    ];

    fn run_json(extra: &[&str]) -> serde_json::Value {
        let mut args: Vec<&str> = SURFACE.to_vec();
        args.extend_from_slice(extra);
        let (code, out, err) = persson(&args);
        assert_eq!(code, 0, "{err}");
        serde_json::from_str(&out).unwrap()
    }

    fn temp(name: &str, text: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("persson-compare-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    #[test]
    fn json_has_the_documented_keys() {
        let v = run_json(&[
            "--modulus",
            "1",
            "--pressure",
            "0.001,0.003",
            "--grid",
            "128",
        ]);
        let np = 2;
        assert_eq!(v["pressures"].as_array().unwrap().len(), np);
        for t in [
            "original",
            "bush_linear",
            "persson_linear",
            "yang-persson",
            "wang-muser",
            "xu",
        ] {
            assert_eq!(v["theories"][t].as_array().unwrap().len(), np, "{t}");
        }
        let bem = v["bem"].as_array().unwrap();
        let grids: Vec<u64> = bem.iter().map(|b| b["grid"].as_u64().unwrap()).collect();
        assert_eq!(grids, vec![32, 64, 128]);
        for b in bem {
            assert_eq!(b["contact_fraction"].as_array().unwrap().len(), np);
        }
        assert_eq!(
            v["extrapolated"]["contact_fraction"]
                .as_array()
                .unwrap()
                .len(),
            np
        );
        assert_eq!(
            v["extrapolated"]["uncertainty"].as_array().unwrap().len(),
            np
        );
        assert!(v["kappa"]["bem_extrapolated"].as_f64().unwrap() > 0.0);
        assert!(v["kappa"]["original"].as_f64().unwrap() > 0.0);
        assert_eq!(v["mean_separation"]["bem"].as_array().unwrap().len(), np);
        assert_eq!(v["mean_separation"]["theory"].as_array().unwrap().len(), np);
        let d = &v["pressure_distribution"][0];
        let bins = d["bins"].as_array().unwrap().len();
        assert_eq!(d["bem_density"].as_array().unwrap().len(), bins);
        assert_eq!(d["theory_density"].as_array().unwrap().len(), bins);
    }

    #[test]
    fn user_data_equal_to_the_theory_scores_zero() {
        // q_s = 8 is resolved on 32² (--grid 128): no clipping, same spectrum.
        let v = run_json(&[
            "--modulus",
            "1",
            "--pressure",
            "0.0005,0.001,0.004",
            "--grid",
            "128",
        ]);
        let p = v["pressures"].as_array().unwrap();
        let a = v["theories"]["original"].as_array().unwrap();
        let mut csv = String::from("pressure,contact_fraction\n");
        for (p, a) in p.iter().zip(a) {
            csv.push_str(&format!(
                "{:e},{:e}\n",
                p.as_f64().unwrap(),
                a.as_f64().unwrap()
            ));
        }
        let file = temp("theory.csv", &csv);
        let w = run_json(&[
            "--modulus",
            "1",
            "--grid",
            "128",
            "--data",
            file.to_str().unwrap(),
        ]);
        // the data's pressures became the command's
        assert_eq!(w["pressures"], v["pressures"]);
        let s = &w["data"]["scores"];
        assert_eq!(s["original"]["max_abs"].as_f64().unwrap(), 0.0, "{s}");
        assert!(s["bush_linear"]["max_abs"].as_f64().unwrap() > 0.3);
        assert!(s["bem_extrapolated"]["rms"].as_f64().unwrap() > 0.0);
    }

    #[test]
    fn bad_data_files_exit_2_naming_the_line() {
        for (name, text, line) in [
            (
                "missing.csv",
                "pressure,contact_fraction\n0.001,0.1\n0.002\n",
                ":3:",
            ),
            (
                "text.csv",
                "pressure,contact_fraction\n0.001,0.1\n0.002,abc\n",
                ":3:",
            ),
            (
                "negative.csv",
                "pressure,contact_fraction\n-0.001,0.1\n",
                ":2:",
            ),
            (
                "above.csv",
                "pressure,contact_fraction\n0.001,0.1\n0.002,1.5\n",
                ":3:",
            ),
        ] {
            let file = temp(name, text);
            let mut args: Vec<&str> = super::cli::SURFACE.to_vec();
            args.extend([
                "--modulus",
                "1",
                "--grid",
                "32",
                "--data",
                file.to_str().unwrap(),
            ]);
            let (code, out, err) = persson(&args);
            assert_eq!(code, 2, "{name}: {err}");
            assert!(out.is_empty() && err.contains(line), "{name}: {err}");
            assert!(!err.contains("panicked"), "{err}");
        }
    }

    #[cfg(feature = "plot")]
    #[test]
    fn plots_and_user_histogram() {
        let dir = temp("dummy", "").with_file_name("");
        let hist = temp("hist.csv", "pressure,density\n0.001,5\n0.003,8\n");
        let files = ["area.svg", "hist.svg", "hist_log.svg"].map(|f| dir.join(f));
        let v = run_json(&[
            "--modulus",
            "1",
            "--grid",
            "64",
            "--pressure",
            "0.001,0.004",
            "--data-histogram",
            hist.to_str().unwrap(),
            "--plot",
            files[0].to_str().unwrap(),
            "--plot-histogram",
            files[1].to_str().unwrap(),
            "--plot-histogram-log",
            files[2].to_str().unwrap(),
        ]);
        assert_eq!(v["data_histogram"]["densities"][1].as_f64(), Some(8.0));
        for f in &files {
            let svg = std::fs::read_to_string(f).unwrap();
            assert!(
                svg.starts_with("<svg") && svg.contains("BEM"),
                "{}",
                f.display()
            );
        }
        let bad = temp("bad_hist.csv", "pressure,density\n0.001,-5\n");
        let mut args: Vec<&str> = SURFACE.to_vec();
        args.extend([
            "--modulus",
            "1",
            "--grid",
            "32",
            "--data-histogram",
            bad.to_str().unwrap(),
        ]);
        let (code, _, err) = persson(&args);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(":2:"), "{err}");
    }

    #[test]
    fn kappa_study_reports_each_hurst_exponent() {
        let (code, out, err) = persson(&[
            "compare", "kappa", "--hurst", "0.5,0.8", "--grid", "64", "--seeds", "2", "--json",
        ]);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let rows = v["hurst"].as_array().unwrap();
        assert_eq!(rows.len(), 2);
        for r in rows {
            let k = &r["bem_extrapolated"];
            assert!(k["kappa"].as_f64().unwrap() > 0.0);
            assert!(k["standard_error"].as_f64().unwrap() > 0.0);
        }
        assert!(
            (v["kappa_bush"].as_f64().unwrap() - (2.0 * std::f64::consts::PI).sqrt()).abs() < 1e-15
        );
    }
}

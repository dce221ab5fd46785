//! The ensemble study: each job is the sweep's own solve of that seed and
//! grid (number for number), the statistics are the textbook mean and
//! standard error of those numbers, and the report does not depend on the
//! number of threads or the order the jobs came back in.
#![cfg(feature = "bem")]

use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson_studies::validation::ensemble::{gather, jobs, solve};
use persson_studies::validation::{ensemble, sweep, EnsembleConfig, EnsembleJob, SweepSettings};

/// Relative rounding of a mean or a standard error of ≤ 4 values computed
/// in another order (two-pass sum of squares against a compensated one).
const STATISTICS_ROUNDING: f64 = 1e-14;

fn spectrum() -> SelfAffine {
    SelfAffine::new(1.0, 2.0, 8.0, 0.8, Amplitude::RmsSlope(0.1)).unwrap()
}

fn config(seeds: usize) -> EnsembleConfig {
    let mut sweep = SweepSettings {
        grid: 32,
        levels: 2,
        seeds: (3..3 + seeds as u64).collect(),
        alpha: None,
        ..SweepSettings::default()
    };
    sweep.options.tolerance = 1e-10;
    EnsembleConfig {
        contact_modulus: 1.0,
        nominal_pressure: vec![0.02, 0.005, 0.01],
        sweep,
    }
}

#[test]
fn every_job_is_the_sweeps_own_solve() {
    let s = spectrum();
    let c = config(3);
    let report = ensemble(&s, &c, 1).unwrap();
    // The sweep of `compare` on the same settings, all seeds at once.
    let q_s = c.sweep.band(s.q_min(), Some(s.q_max())).unwrap().q_s;
    let band = persson::spectrum::BandLimited::new(&s, q_s).unwrap();
    let sw = sweep(
        &band,
        1.0,
        &c.nominal_pressure,
        &c.sweep.config(1.0).unwrap(),
        &mut |_| {},
    )
    .unwrap();
    assert_eq!(report.solves.len(), 6);
    for solve in &report.solves {
        let g = sw.grids.iter().find(|g| g.grid == solve.grid).unwrap();
        let k = c.sweep.seeds.iter().position(|&x| x == solve.seed).unwrap();
        assert_eq!(solve.contact_fraction, g.contact_fraction[k]);
        assert_eq!(solve.mean_separation, g.mean_separation[k]);
        assert_eq!(solve.surface_rms_slope, g.surface_rms_slope[k]);
    }
    // The grids' statistics are the sweep's seed means, to the last digit.
    for (e, m) in report.grids.iter().zip(sw.mean_contact_fraction()) {
        assert_eq!(e.contact_fraction, m.mean);
        assert_eq!(e.contact_fraction_standard_error, m.standard_error);
    }
}

#[test]
fn statistics_are_the_sample_mean_and_standard_error() {
    let report = ensemble(&spectrum(), &config(4), 1).unwrap();
    for g in &report.grids {
        let runs: Vec<_> = report.solves.iter().filter(|s| s.grid == g.grid).collect();
        assert_eq!(runs.len(), 4);
        for k in 0..3 {
            let x: Vec<f64> = runs.iter().map(|s| s.contact_fraction[k]).collect();
            // Compensated sums, the other way round from the crate's.
            let n = x.len() as f64;
            let mean = x.iter().rev().fold((0.0, 0.0), |(s, c): (f64, f64), &v| {
                let y = v - c;
                let t = s + y;
                (t, (t - s) - y)
            });
            let mean = mean.0 / n;
            let var = x.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0);
            let se = (var / n).sqrt();
            assert!((g.contact_fraction[k] / mean - 1.0).abs() < STATISTICS_ROUNDING);
            let got = g.contact_fraction_standard_error[k].unwrap();
            assert!(
                (got / se - 1.0).abs() < STATISTICS_ROUNDING,
                "{got} vs {se}"
            );
            assert!(
                got > 0.0,
                "four different surfaces give four different A/A0"
            );
        }
    }
}

#[test]
fn threads_and_order_do_not_change_the_report() {
    let s = spectrum();
    let c = config(3);
    let one = ensemble(&s, &c, 1).unwrap();
    let two = ensemble(&s, &c, 2).unwrap();
    let strip = |r: &persson_studies::validation::EnsembleReport| {
        let mut v = serde_json::to_value(r).unwrap();
        for s in v["solves"].as_array_mut().unwrap() {
            s.as_object_mut().unwrap().remove("seconds");
        }
        for g in v["grids"].as_array_mut().unwrap() {
            g.as_object_mut().unwrap().remove("seconds");
        }
        v
    };
    assert_eq!(strip(&one), strip(&two));
    // Jobs solved one by one and handed back in reverse order.
    let mut solves: Vec<_> = jobs(&s, &c)
        .unwrap()
        .into_iter()
        .map(|j| solve(&s, &c, j).unwrap())
        .collect();
    solves.reverse();
    assert_eq!(strip(&gather(&s, &c, solves).unwrap()), strip(&one));
}

#[test]
fn a_missing_or_repeated_job_is_an_error() {
    let s = spectrum();
    let c = config(2);
    let all: Vec<_> = jobs(&s, &c).unwrap();
    assert_eq!(
        all,
        vec![
            EnsembleJob { seed: 3, grid: 32 },
            EnsembleJob { seed: 4, grid: 32 },
            EnsembleJob { seed: 3, grid: 16 },
            EnsembleJob { seed: 4, grid: 16 },
        ]
    );
    let first = solve(&s, &c, all[0]).unwrap();
    let e = gather(&s, &c, vec![first.clone(), first.clone()]).unwrap_err();
    assert!(e.to_string().contains("exactly once"), "{e}");
    let e = solve(&s, &c, EnsembleJob { seed: 3, grid: 64 }).unwrap_err();
    assert!(e.to_string().contains("grid"), "{e}");
    let mut bad = c.clone();
    bad.nominal_pressure = vec![];
    assert!(jobs(&s, &bad).is_err());
    bad.nominal_pressure = vec![-1.0];
    assert!(jobs(&s, &bad)
        .unwrap_err()
        .to_string()
        .contains("nominal_pressure"));
}

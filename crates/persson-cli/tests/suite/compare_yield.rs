//! `persson compare --yield-stress`: the saturated BEM sweep against
//! Persson's finite-σY P(σ) (issue 14, item 3).
#![cfg(feature = "bem")]

use persson::bem::histogram::integral;
use persson::spectrum::{Amplitude, SelfAffine};
use persson_studies::validation::{compare, Comparison, ComparisonConfig, SweepSettings};

/// Rounding of sums over ≤ 64² values and of a few FFTs.
const ROUNDING: f64 = 1e-12;

/// Relative tolerance of the theory's P(σ) and fractions in compare
/// (its STRESS_TOLERANCE, 1e-9) and of a scene's (1e-12), with room for the
/// series' truncation at either.
const THEORY: f64 = 1e-8;

/// H = 0.8, q_l = 1, q_r = 2, q_s = 8, rms slope 0.1: on 32² and 64² (two
/// levels) q_s is resolved with 4 pixels per wavelength, not clipped.
fn spectrum() -> SelfAffine {
    SelfAffine::new(1.0, 2.0, 8.0, 0.8, Amplitude::RmsSlope(0.1)).unwrap()
}

const PRESSURES: [f64; 2] = [0.002, 0.005];

/// Above the largest BEM pressure of the elastic solves (0.14 on 64² at
/// σ0 = 0.005, measured: the last non-empty bin of its histogram ends
/// there), and far in the tail of Persson's elastic P(σ), whose mass beyond
/// it is 4e-23 (measured; beyond 0.2 it is still 5e-5).
const ABOVE_ELASTIC_MAX: f64 = 0.5;

fn run(yield_stress: Option<f64>) -> Comparison {
    let mut cfg = ComparisonConfig::new(1.0);
    cfg.nominal_pressure = PRESSURES.to_vec();
    cfg.sweep = SweepSettings {
        grid: 64,
        levels: 2,
        ..SweepSettings::default()
    };
    cfg.sweep.options.yield_stress = yield_stress;
    compare(&spectrum(), &cfg, &mut |_| {}).unwrap()
}

#[test]
fn yield_above_the_elastic_maximum_reproduces_the_elastic_comparison() {
    let e = run(None);
    let y = run(Some(ABOVE_ELASTIC_MAX));
    assert_eq!(e.yield_stress, None);
    assert_eq!(y.yield_stress, Some(ABOVE_ELASTIC_MAX));
    // the BEM: bit for bit (the saturated solver returns the elastic solution)
    for (a, b) in e.bem.iter().zip(&y.bem) {
        assert_eq!(a.contact_fraction, b.contact_fraction);
        assert_eq!(a.mean_separation, b.mean_separation);
        assert_eq!(b.plastic_fraction.as_deref(), Some(&[0.0, 0.0][..]));
        assert_eq!(b.elastic_fraction.as_ref(), Some(&a.contact_fraction));
        assert!(a.elastic_fraction.is_none() && a.plastic_fraction.is_none());
    }
    for (a, b) in e.extrapolated.iter().zip(&y.extrapolated) {
        assert_eq!(a.contact_fraction, b.contact_fraction);
        assert_eq!(a.standard_error, b.standard_error);
        assert_eq!(b.plastic_fraction, Some(0.0));
    }
    assert_eq!(e.kappa, y.kappa);
    assert_eq!(e.theories, y.theories);
    for (a, b) in e.pressure_distribution.iter().zip(&y.pressure_distribution) {
        assert_eq!(a.bem, b.bem);
        assert_eq!(b.bem_plastic_fraction, Some(0.0));
        // the theory: the finite-σY series with P(σY) = 0 far above the
        // pressures is the elastic P(σ) up to its tail beyond σY
        let rel = (a.theory_contact_fraction - b.theory_contact_fraction).abs()
            / a.theory_contact_fraction;
        assert!(rel < THEORY, "A/A0: {rel:e}");
        assert!(b.theory_plastic_fraction.unwrap() < THEORY * a.theory_contact_fraction);
        for (p, q) in a.theory_density.iter().zip(&b.theory_density) {
            assert!((p - q).abs() <= THEORY * p.abs().max(1.0), "{p} vs {q}");
        }
    }
}

#[test]
fn elastic_and_plastic_parts_add_up_and_the_histogram_leaves_the_peak_out() {
    let r = run(Some(0.05));
    for g in &r.bem {
        let (el, pl) = (
            g.elastic_fraction.as_ref().unwrap(),
            g.plastic_fraction.as_ref().unwrap(),
        );
        for k in 0..PRESSURES.len() {
            assert!((el[k] + pl[k] - g.contact_fraction[k]).abs() < ROUNDING);
            assert!(pl[k] > 0.0, "σY = 0.05 is below the elastic maximum");
            assert!(g.plastic_displacement_mean.as_ref().unwrap()[k] > 0.0);
        }
    }
    // the extrapolation is linear in the data: A_el∞ + A_pl∞ = A∞
    for c in &r.extrapolated {
        let sum = c.elastic_fraction.unwrap() + c.plastic_fraction.unwrap();
        assert!((sum - c.contact_fraction).abs() < ROUNDING, "{c:?}");
    }
    let finest = r.bem.last().unwrap();
    for (k, d) in r.pressure_distribution.iter().enumerate() {
        // the bins hold only the nodes below σY: they integrate to A_el
        assert!((integral(&d.bem) - d.bem_elastic_fraction.unwrap()).abs() < ROUNDING);
        assert_eq!(
            d.bem_plastic_fraction,
            Some(finest.plastic_fraction.as_ref().unwrap()[k])
        );
        // the theory: A = A_el + A_pl, P(σ) = 0 at σY, its curve ends at σY
        let (a, el, pl) = (
            d.theory_contact_fraction,
            d.theory_elastic_fraction.unwrap(),
            d.theory_plastic_fraction.unwrap(),
        );
        assert!((el + pl - a).abs() < THEORY, "{el} + {pl} vs {a}");
        assert_eq!(d.theory_curve.sigma.last(), Some(&0.05));
        assert!(d.theory_curve.density.last().unwrap().abs() < THEORY);
    }
}

/// (σ0, σY, G, A_el/A0, A_pl/A0) of Persson's finite-σY theory for this
/// spectrum at ζ = q_s/q_l, a flat start: the sums over the images of the
/// walls σ = 0 and σ = σY in mpmath at 40 digits, checked against the sine
/// series (`tests/reference/compare_yield.py`); G = h'_rms²/(8σ0²).
#[allow(clippy::excessive_precision)]
const YIELD_REFERENCE: [(f64, f64, f64, f64, f64); 6] = [
    (
        0.002,
        0.04,
        3.1249999999999998699e2,
        8.9239921011842997576e-5,
        4.9955380039498042185e-2,
    ),
    (
        0.002,
        0.05,
        3.1249999999999998699e2,
        1.1476752027326514105e-3,
        3.94261626104106733e-2,
    ),
    (
        0.002,
        0.08,
        3.1249999999999998699e2,
        1.4533916401138286773e-2,
        1.7755351779685799205e-2,
    ),
    (
        0.005,
        0.04,
        4.9999999999999997918e1,
        2.1830636406126308938e-4,
        1.2489084681797843834e-1,
    ),
    (
        0.005,
        0.05,
        4.9999999999999997918e1,
        2.8296656168624491238e-3,
        9.8585167692109421308e-2,
    ),
    (
        0.005,
        0.08,
        4.9999999999999997918e1,
        3.6138912644065811489e-2,
        4.4485120268986944968e-2,
    ),
];

/// The fractions' claim, 1e-13 absolute (issue 3). Compare asks the solver
/// for 1e-9 (its STRESS_TOLERANCE), but the series and image sums converge
/// far below that at these τ/y²: measured at most 7e-18 against mpmath.
const THEORY_ABSOLUTE: f64 = 1e-13;

/// G of the theory: the closed form to rounding (the spectrum's moments are
/// exact, G a product of them).
const G_RELATIVE: f64 = 1e-13;

/// The theory's A_el/A0 and A_pl/A0 are Persson's finite-σY fractions
/// (mpmath); the BEM's plastic fraction rises as σY falls, per grid and in
/// the continuum limit, and its elastic fraction falls.
#[test]
fn fractions_are_the_theory_s_and_the_bem_plastic_part_rises_as_the_yield_stress_falls() {
    let runs: Vec<(f64, Comparison)> = [0.04, 0.05, 0.08]
        .into_iter()
        .map(|y| (y, run(Some(y))))
        .collect();
    for &(s0, sy, g, el, pl) in &YIELD_REFERENCE {
        let r = &runs.iter().find(|(y, _)| *y == sy).unwrap().1;
        let k = PRESSURES.iter().position(|&p| p == s0).unwrap();
        let d = &r.pressure_distribution[k];
        assert!(
            ((d.g - g) / g).abs() < G_RELATIVE,
            "σ0 = {s0}: G = {} vs {g}",
            d.g
        );
        let (got_el, got_pl) = (
            d.theory_elastic_fraction.unwrap(),
            d.theory_plastic_fraction.unwrap(),
        );
        assert!(
            (got_el - el).abs() < THEORY_ABSOLUTE,
            "σ0 = {s0}, σY = {sy}: A_el = {got_el:e} vs {el:e}"
        );
        assert!(
            (got_pl - pl).abs() < THEORY_ABSOLUTE,
            "σ0 = {s0}, σY = {sy}: A_pl = {got_pl:e} vs {pl:e}"
        );
    }
    let (lo, hi) = (&runs[0].1, &runs[2].1);
    for k in 0..PRESSURES.len() {
        let b = |r: &Comparison| r.bem.last().unwrap().plastic_fraction.as_ref().unwrap()[k];
        let x = |r: &Comparison| r.extrapolated[k].plastic_fraction.unwrap();
        assert!(b(lo) > b(hi), "BEM {} vs {}", b(lo), b(hi));
        assert!(x(lo) > x(hi), "BEM N → ∞ {} vs {}", x(lo), x(hi));
        let e = |r: &Comparison| r.bem.last().unwrap().elastic_fraction.as_ref().unwrap()[k];
        assert!(e(lo) < e(hi));
    }
}

mod cli {
    use crate::common::{json, persson};

    const SURFACE: [&str; 19] = [
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
        "--modulus",
        "1",
        "--grid",
        "64",
        "--levels",
        "2",
        "--pressure",
        "0.002,0.005",
    ];

    fn compare(extra: &[&str]) -> serde_json::Value {
        let mut args = SURFACE.to_vec();
        args.extend_from_slice(extra);
        args.push("--json");
        json(&args)
    }

    /// The theory side is Persson's finite-σY P(σ) of a flat start at σ0 and
    /// ζ = q_s/q_l, as a scene's physical stress output computes it.
    #[test]
    fn theory_equals_the_scene_stress_output() {
        let v = compare(&["--yield-stress", "0.05"]);
        let zeta = v["spectrum"]["zeta"].as_f64().unwrap();
        assert_eq!(zeta, 8.0);
        let dir = std::env::temp_dir().join(format!("persson-yield-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for (k, p) in ["0.002", "0.005"].iter().enumerate() {
            let scene = format!(
                r#"{{ "schema": 1, "name": "yield",
  "material": {{ "contact_modulus": 1 }},
  "spectrum": {{ "kind": "self_affine", "hurst": 0.8, "q_l": 1, "q_r": 2, "q_s": 8, "rms_slope": 0.1 }},
  "outputs": {{ "stress": {{ "start": "flat", "peak_pressure": {p}, "yield_stress": 0.05, "zeta": [{zeta}], "points": 11 }} }} }}"#
            );
            let file = dir.join(format!("scene{k}.json"));
            std::fs::write(&file, scene).unwrap();
            let s = json(&["run", file.to_str().unwrap(), "--json"]);
            let c = &s["stress"]["curves"][0];
            let d = &v["pressure_distribution"][k];
            for (ours, theirs) in [
                ("theory_contact_fraction", "contact_fraction"),
                ("theory_elastic_fraction", "elastic_fraction"),
                ("theory_plastic_fraction", "plastic_fraction"),
            ] {
                let (a, b) = (d[ours].as_f64().unwrap(), c[theirs].as_f64().unwrap());
                assert!(
                    (a - b).abs() < super::THEORY * b.max(1e-3),
                    "{ours}: {a} vs {b}"
                );
            }
            assert_eq!(d["g"].as_f64(), c["g"].as_f64());
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// The finest grid of the sweep is the surface `bem rough` synthesises
    /// with the same spectrum, grid and seed: its plastic fraction is the
    /// direct solve's (pressures in the same ascending order, warm-started).
    #[test]
    fn bem_side_equals_a_direct_saturated_solve() {
        let v = compare(&["--yield-stress", "0.05"]);
        let r = json(&[
            "bem",
            "rough",
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
            "--modulus",
            "1",
            "--grid",
            "64",
            "--pressure",
            "0.002,0.005",
            "--yield-stress",
            "0.05",
            "--json",
        ]);
        let finest = &v["bem"][1];
        assert_eq!(finest["grid"].as_u64(), Some(64));
        for k in 0..2 {
            let point = &r["points"][k];
            for key in ["contact_fraction", "elastic_fraction", "plastic_fraction"] {
                assert_eq!(
                    finest[key][k].as_f64(),
                    point[key].as_f64(),
                    "{key} at pressure {k}"
                );
            }
            assert!(point["plastic_fraction"].as_f64().unwrap() > 0.0);
        }
    }

    #[test]
    fn text_shows_the_fractions_and_the_peak() {
        let mut args = SURFACE.to_vec();
        args.extend(["--yield-stress", "0.05"]);
        let (code, out, err) = persson(&args);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("Elastic–plastic contact, σY = 0.05"), "{out}");
        assert!(out.contains("A_el/A0") && out.contains("A_pl/A0"), "{out}");
        assert!(out.contains("δ-peak at σY: A_pl/A0 BEM"), "{out}");
        assert!(out.lines().all(|l| l.chars().count() <= 100), "{out}");
        // without a yield stress: no such table
        let (_, out, _) = persson(&SURFACE);
        assert!(!out.contains("Elastic–plastic") && !out.contains("δ-peak"));
    }

    /// A periodic measured map: the map as measured is solved with σY too.
    #[test]
    fn measured_map_as_measured_has_its_fractions() {
        let args = [
            "compare",
            "--surface",
            concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../tests/reference/data/map_b.npy"
            ),
            "--pixel-size",
            "2e-6",
            "--periodic",
            "--contact-modulus",
            "1e9",
            "--yield-stress",
            "8e5",
        ];
        let mut j = args.to_vec();
        j.push("--json");
        let v = json(&j);
        let m = &v["measured"];
        let n = v["nominal_pressure"].as_array().unwrap().len();
        for k in 0..n {
            let f = |key: &str| m[key][k].as_f64().unwrap();
            let sum = f("elastic_fraction") + f("plastic_fraction");
            assert!((sum - f("contact_fraction")).abs() < super::ROUNDING);
        }
        assert!(m["plastic_fraction"][n - 1].as_f64().unwrap() > 0.0);
        let (code, out, err) = persson(&args);
        assert_eq!(code, 0, "{err}");
        assert_eq!(out.matches("BEM, map as measured").count(), n, "{out}");
        assert!(out.lines().all(|l| l.chars().count() <= 100), "{out}");
    }

    #[test]
    fn bad_yield_stress_is_an_error_naming_it() {
        for (y, says) in [
            ("0", "finite and > 0"),
            ("-0.1", "finite and > 0"),
            ("nan", "finite and > 0"),
            ("inf", "finite and > 0"),
            ("0.005", "no solution exists"),
            ("0.003", "no solution exists"),
        ] {
            let mut args = SURFACE.to_vec();
            args.extend(["--yield-stress", y]);
            let (code, out, err) = persson(&args);
            assert_eq!(code, 2, "{y}: {err}");
            assert!(out.is_empty(), "{y}: {out}");
            assert!(
                err.contains("yield_stress") && err.contains(says),
                "{y}: {err}"
            );
            assert!(!err.contains("panicked"), "{err}");
        }
    }

    #[cfg(feature = "plot")]
    #[test]
    fn histogram_plot_marks_both_peaks() {
        let dir = std::env::temp_dir().join(format!("persson-yield-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (h, a) = (dir.join("h.svg"), dir.join("a.svg"));
        let v = compare(&[
            "--yield-stress",
            "0.05",
            "--plot-histogram",
            h.to_str().unwrap(),
            "--plot",
            a.to_str().unwrap(),
        ]);
        let d = &v["pressure_distribution"][v["histogram_index"].as_u64().unwrap() as usize];
        let svg = std::fs::read_to_string(&h).unwrap();
        for who in ["BEM", "Persson"] {
            let key = format!(
                "{}_plastic_fraction",
                if who == "BEM" { "bem" } else { "theory" }
            );
            let a_pl = persson_studies::table::number(d[key].as_f64().unwrap(), 3);
            let label = format!("{who} δ-peak at σY = 0.05: A_pl/A0 = {a_pl}");
            assert!(svg.contains(&label), "{label}");
        }
        let svg = std::fs::read_to_string(&a).unwrap();
        assert!(svg.contains("BEM A_pl/A0, N → ∞") && svg.contains("Persson A_pl/A0"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}

//! Scene outputs of the FFT-BEM: `bem` (rough contact from the scene's
//! spectrum or a height map) and `bem_hertz` (the lecture's convergence
//! table); the spectrum kind `height_map`.

use std::path::Path;

use persson_studies::scene::Scene;

fn parse(text: &str) -> persson::Result<Scene> {
    Scene::parse(Path::new("test.json"), text)
}

/// A spectrum resolved on 32² (q_s = 8 q_l, Nyquist 16 q_l), E* = 1.
const ROUGH: &str = r#"{
  "schema": 1,
  "material": { "contact_modulus": 1.0 },
  "spectrum": { "kind": "self_affine", "hurst": 0.8, "q_l": 6.283185307179586, "q_r": 12.566370614359172, "q_s": 50.26548245743669, "rms_slope": 0.1 },
  "nominal_pressure": [0.001, 0.003, 0.01],
  "outputs": OUTPUTS
}"#;

fn rough(outputs: &str) -> String {
    ROUGH.replace("OUTPUTS", outputs)
}

#[cfg(not(feature = "bem"))]
#[test]
fn bem_outputs_need_the_feature() {
    for out in [r#"{"bem": {"grid": 32}}"#, r#"{"bem_hertz": {}}"#] {
        let e = parse(&rough(out)).unwrap().run().unwrap_err().to_string();
        assert!(e.contains("`bem` feature"), "{e}");
    }
}

#[cfg(feature = "bem")]
mod bem {
    use super::*;
    use persson::bem::surface::synthesize;
    use persson::bem::{hertz, Boundary, Control, Operator, Options, Solver};
    use persson::io::npy;
    use persson::spectrum::{Amplitude, SelfAffine};
    use persson_studies::scene::BemHertzReport;

    /// Two runs of the same deterministic solve agree bit for bit; this
    /// allows for the summation order of a different code path only.
    const SAME_SOLVE_TOL: f64 = 1e-12;

    fn tmp(name: &str) -> std::path::PathBuf {
        let d = std::env::temp_dir().join(format!("persson-scene-bem-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        d.join(name)
    }

    #[test]
    fn bem_hertz_reproduces_validate_and_the_lecture() {
        let r = parse(r#"{"schema": 1, "outputs": {"bem_hertz": {"grids": [32, 64]}}}"#)
            .unwrap()
            .run()
            .unwrap();
        assert!(r.area.is_none() && r.bem.is_none(), "only bem_hertz");
        let BemHertzReport::Convergence(h) = r.bem_hertz.unwrap() else {
            panic!("several grids: η per grid")
        };
        assert_eq!(h.boundary.name(), "free");
        let rows = h.rows;
        assert_eq!(rows.len(), 2);
        // The scene's default tolerance, the command line's and Python's.
        let opts = Options {
            tolerance: 1e-10,
            ..Options::default()
        };
        for row in &rows {
            let direct =
                hertz::validate(&hertz::HertzCase::new(row.grid, Boundary::Free), &opts).unwrap();
            assert!((row.energy_error - direct.energy_error).abs() <= SAME_SOLVE_TOL);
        }
        // Molinari's lecture, Table 1, 64²: η = 1.40e-2 (ours must not be worse).
        assert_eq!(rows[1].energy_error_published, Some(1.40e-2));
        assert!(rows[1].energy_error < 1.40e-2, "{}", rows[1].energy_error);
        assert_eq!(rows[0].energy_error_published, None);
        let p = parse(
            r#"{"schema": 1, "outputs": {"bem_hertz": {"grids": [32], "boundary": "periodic"}}}"#,
        )
        .unwrap()
        .run()
        .unwrap()
        .bem_hertz
        .unwrap();
        let BemHertzReport::Validation(p) = p else {
            panic!("one grid: the validation")
        };
        assert_eq!(p.boundary.name(), "periodic");
        assert_eq!(
            p.energy_error_published, None,
            "the lecture lists the free boundary only"
        );
    }

    /// A scene's `bem_hertz` takes every input of `persson bem hertz` (one
    /// spec for both): the ball, the subsurface with its figure, the
    /// adhesive sphere; fields of one result beside another are refused,
    /// both named.
    #[test]
    fn bem_hertz_takes_the_ball_the_subsurface_and_adhesion() {
        let run = |spec: &str| {
            parse(&format!(
                r#"{{"schema": 1, "outputs": {{"bem_hertz": {spec}}}}}"#
            ))
            .unwrap()
            .run()
            .map(|r| r.bem_hertz.unwrap())
        };
        let ball = r#"{"grids": [32], "boundary": "periodic", "size": 2, "radius": 3,
            "contact_modulus": 5, "contact_radius": 0.3}"#;
        let BemHertzReport::Validation(v) = run(ball).unwrap() else {
            panic!("one grid: the validation")
        };
        // Hertz's p₀ = 2E*a/(πR) (Johnson, Contact Mechanics, Eq. 4.24).
        let p0 = 2.0 * 5.0 * 0.3 / (std::f64::consts::PI * 3.0);
        assert!((v.hertz_peak_pressure - p0).abs() <= 1e-15 * p0);
        assert_eq!((v.size, v.radius, v.contact_modulus), (2.0, 3.0, 5.0));
        let BemHertzReport::Subsurface(a) = run(r#"{"grids": [32], "subsurface": true}"#).unwrap()
        else {
            panic!("the axis")
        };
        // Johnson's σ_z on the axis, within the 32² grid's 1 % of p₀.
        assert!(a.stress_error < 0.01, "{}", a.stress_error);
        let sphere = r#"{"grids": [16], "boundary": "periodic", "work_of_adhesion": 1e-4,
            "adhesion_range": 0.05}"#;
        assert!(matches!(run(sphere).unwrap(), BemHertzReport::Adhesive(_)));
        for (spec, names) in [
            (r#"{"stress_plot": "x.svg"}"#, ["stress_plot", "subsurface"]),
            (r#"{"poisson": 0.3}"#, ["poisson", "subsurface"]),
            (
                r#"{"subsurface": true, "yield_stress": 0.05}"#,
                ["yield_stress", "subsurface"],
            ),
            (
                r#"{"adhesion_range": 0.05}"#,
                ["adhesion_range", "work_of_adhesion"],
            ),
            (
                r#"{"work_of_adhesion": 1e-4, "adhesion_range": 0.05, "subsurface": true}"#,
                ["subsurface", "work_of_adhesion"],
            ),
            (
                r#"{"grids": [16, 32], "subsurface": true}"#,
                ["grids", "grids"],
            ),
        ] {
            let e = run(spec).unwrap_err().to_string();
            for n in names {
                assert!(e.contains(&format!("outputs.bem_hertz.{n}")), "{spec}: {e}");
            }
        }
        let e = run(r#"{"work_of_adhesion": 1e-4, "adhesion_range": 0.05}"#)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("outputs.bem_hertz.boundary") && e.contains("periodic"),
            "{e}"
        );
    }

    #[test]
    fn bem_rough_equals_a_direct_solve() {
        let s = parse(&rough(r#"{"bem": {"grid": 32, "seed": 9}}"#)).unwrap();
        let r = s.run().unwrap();
        assert!(r.area.is_none() && r.bem_hertz.is_none(), "only bem");
        let b = r.bem.unwrap().rough;
        assert_eq!(
            (b.grid, b.surface.seed(), b.boundary.name()),
            (32, Some(9), "periodic")
        );
        assert!((b.size - 1.0).abs() < 1e-15, "L = 2π/q_l = 1");
        let q = std::f64::consts::TAU;
        let spec = SelfAffine::new(q, 2.0 * q, 8.0 * q, 0.8, Amplitude::RmsSlope(0.1)).unwrap();
        let surf = synthesize(&spec, 32, 1.0, 9).unwrap();
        let mut solver = Solver::new(Operator::new(Boundary::Periodic, 32, 1.0, 1.0).unwrap());
        let mut last = 0.0;
        for pt in &b.points {
            let sol = solver
                .solve(
                    &surf.heights,
                    Control::MeanPressure(pt.nominal_pressure),
                    &Options::default(),
                )
                .unwrap();
            // Warm starts may change the last digits of the pressure but
            // the contact set is the same.
            assert_eq!(pt.contact_fraction, sol.contact_fraction);
            assert!(pt.residual <= 1e-10 && pt.iterations > 0);
            assert!(pt.contact_fraction > last && pt.contact_fraction < 1.0);
            last = pt.contact_fraction;
            assert!(pt.histogram.is_none());
        }
        assert!((b.surface_rms_slope - surf.rms_slope().unwrap()).abs() <= SAME_SOLVE_TOL);
    }

    #[test]
    fn histograms_integrate_to_the_contact_fraction_and_are_written() {
        let dir = tmp("hist");
        std::fs::create_dir_all(&dir).unwrap();
        let s = parse(&rough(
            r#"{"bem": {"grid": 32, "histogram": "h.csv", "bins": 20, "boundary": "free"}}"#,
        ))
        .unwrap();
        assert!(s
            .output_files(&dir)
            .iter()
            .any(|(field, p, _)| *field == "outputs.bem.histogram" && *p == dir.join("h.csv")));
        let r = s.run().unwrap();
        let b = &r.bem.as_ref().unwrap().rough;
        assert_eq!(b.boundary.name(), "free");
        for pt in &b.points {
            let h = pt.histogram.as_ref().unwrap();
            assert_eq!(h.len(), 20);
            // Σ P Δσ = A/A0 exactly up to rounding of 20 terms.
            let total: f64 = h
                .iter()
                .map(|b| b.density * (b.sigma_high - b.sigma_low))
                .sum();
            assert!((total - pt.contact_fraction).abs() < 1e-14, "{total}");
        }
        let mut files = persson_studies::output::Files::new();
        let again = s.run_and_write(&dir, &mut files).unwrap();
        assert_eq!(again.warnings, r.warnings);
        let written = files.commit().unwrap();
        assert_eq!(written, vec![dir.join("h.csv")]);
        let text = std::fs::read_to_string(dir.join("h.csv")).unwrap();
        assert_eq!(text.lines().count(), 1 + 3 * 20);
        assert!(text.starts_with("nominal_pressure,sigma_low,sigma_high,density\n"));
    }

    #[test]
    fn height_map_scene_reads_relative_files() {
        let q = std::f64::consts::TAU;
        let spec = SelfAffine::new(q, 2.0 * q, 8.0 * q, 0.8, Amplitude::RmsSlope(0.1)).unwrap();
        let surf = synthesize(&spec, 32, 1.0, 9).unwrap();
        let map = tmp("map.npy");
        npy::write(&map, 32, 32, &surf.heights).unwrap();
        let scene_path = tmp("scene.json");
        let text = r#"{
          "schema": 1,
          "material": { "contact_modulus": 1.0 },
          "spectrum": { "kind": "height_map", "file": "map.npy", "size": 1.0 },
          "nominal_pressure": [0.001, 0.003, 0.01],
          "outputs": { "bem": {} } }"#;
        std::fs::write(&scene_path, text).unwrap();
        let from_map = Scene::read(&scene_path)
            .unwrap()
            .run()
            .unwrap()
            .bem
            .unwrap()
            .rough;
        assert_eq!(from_map.surface.seed(), None);
        let synthesised = parse(&rough(r#"{"bem": {"grid": 32, "seed": 9}}"#))
            .unwrap()
            .run()
            .unwrap()
            .bem
            .unwrap()
            .rough;
        for (a, b) in from_map.points.iter().zip(&synthesised.points) {
            assert_eq!(a.contact_fraction, b.contact_fraction);
        }
        // A height map's spectrum serves the other outputs too (issue 13):
        // its title says how the map was conditioned.
        let area = text.replace(r#""bem": {}"#, r#""area": {}"#);
        std::fs::write(&scene_path, &area).unwrap();
        let r = Scene::read(&scene_path)
            .unwrap()
            .run()
            .unwrap()
            .area
            .unwrap();
        let title = r.surface.unwrap();
        assert!(title.contains("detrend plane, window hann"), "{title}");
        // grid/seed make no sense with a height map.
        let bad = text.replace(r#""bem": {}"#, r#""bem": {"grid": 64}"#);
        std::fs::write(&scene_path, &bad).unwrap();
        let e = Scene::read(&scene_path)
            .unwrap()
            .run()
            .unwrap_err()
            .to_string();
        assert!(e.contains("outputs.bem.grid"), "{e}");
    }

    /// A scene's conductance and leakage solve the BEM on the scene's height
    /// map, as `outputs.bem` and `bem rough --surface` do: the same values as
    /// the synthesised surface the map was written from, and a grid or seed
    /// beside the map is refused.
    #[cfg(feature = "flow")]
    #[test]
    fn transport_bem_solves_on_the_height_map() {
        let q = std::f64::consts::TAU;
        let spec = SelfAffine::new(q, 2.0 * q, 8.0 * q, 0.8, Amplitude::RmsSlope(0.1)).unwrap();
        let surf = synthesize(&spec, 32, 1.0, 9).unwrap();
        let map = tmp("transport_map.npy");
        npy::write(&map, 32, 32, &surf.heights).unwrap();
        let scene_path = tmp("transport_scene.json");
        let outputs = r#"{ "conductance": { "conductivity": [1, 1], "bem": BEM },
            "leakage": { "viscosity": 1e-3, "pressure_drop": 1, "bem": BEM } }"#;
        let text = r#"{
          "schema": 1,
          "material": { "contact_modulus": 1.0 },
          "spectrum": { "kind": "height_map", "file": "transport_map.npy", "size": 1.0 },
          "nominal_pressure": [0.001, 0.003, 0.01],
          "outputs": OUTPUTS }"#
            .replace("OUTPUTS", outputs);
        std::fs::write(&scene_path, text.replace("BEM", "{}")).unwrap();
        let on_map = Scene::read(&scene_path).unwrap().run().unwrap();
        let synthesised = parse(&rough(
            &outputs.replace("BEM", r#"{"grid": 32, "seed": 9}"#),
        ))
        .unwrap()
        .run()
        .unwrap();
        let bem = |r: &persson_studies::scene::SceneReport| {
            let c = r.conductance.as_ref().unwrap().bem.clone().unwrap();
            let l = r.leakage.as_ref().unwrap().bem.clone().unwrap();
            (c, l)
        };
        let (map_c, map_l) = bem(&on_map);
        let (syn_c, syn_l) = bem(&synthesised);
        assert_eq!((map_c.grid, map_c.seed), (32, None));
        assert_eq!((syn_c.grid, syn_c.seed), (32, Some(9)));
        let close = |a: f64, b: f64| (a - b).abs() <= SAME_SOLVE_TOL * b.abs();
        for (a, b) in map_c.points.iter().zip(&syn_c.points) {
            assert!(close(a.stiffness, b.stiffness), "{a:?} {b:?}");
        }
        for (a, b) in map_l.points.iter().zip(&syn_l.points) {
            let (qa, qb) = (a.leak_rate.unwrap(), b.leak_rate.unwrap());
            assert!(close(qa, qb), "{qa} {qb}");
        }
        assert_eq!(map_l.points.len(), 3);
        for (given, name) in [(r#"{"grid": 32}"#, "grid"), (r#"{"seed": 9}"#, "seed")] {
            std::fs::write(&scene_path, text.replace("BEM", given)).unwrap();
            let e = Scene::read(&scene_path)
                .unwrap()
                .run()
                .unwrap_err()
                .to_string();
            assert!(
                e.contains(&format!("outputs.conductance.bem.{name}")),
                "{e}"
            );
            assert!(e.contains("height map"), "{e}");
        }
        // A spectrum without a grid names the missing field.
        let e = parse(&rough(&outputs.replace("BEM", "{}")))
            .unwrap()
            .run()
            .unwrap_err()
            .to_string();
        assert!(e.contains("outputs.conductance.bem.grid"), "{e}");
    }

    /// Σ patch areas = A/A0 L²: a sum of ≤ 32² cell areas (rounding).
    const AREA_SUM: f64 = 1e-12;

    /// At z = L every mode but the mean has decayed by e^{−2π} or more: the
    /// uniform stress of the mean load, σ_vM = σ0 (1 − 2ν)/(1 − ν), within 5 %
    /// (docs/asperity.md, Accuracy).
    const DEEP_PLANE: f64 = 0.05;

    #[test]
    fn patches_and_subsurface_as_scene_outputs() {
        let out = r#"{"bem": {"grid": 32, "patches": {"connectivity": "eight", "plot": "patches.svg"},
            "subsurface": {"depth": [0.05, 1.0], "stress_field": "vm.npy", "plot": "depth.svg"}}}"#;
        let text = rough(out).replace(
            r#""contact_modulus": 1.0"#,
            r#""contact_modulus": 1.0, "poisson": 0.25"#,
        );
        // E* given with the body's ν: the stress uses that ν
        let scene = parse(&text).unwrap();
        let nu = 0.25;
        let r = scene.run().unwrap();
        let bem = &r.bem.as_ref().unwrap().rough;
        let patches = r.bem.as_ref().unwrap().patches.as_ref().unwrap();
        let size = 1.0; // L = 2π/q_l
        for (p, b) in patches.points.iter().zip(&bem.points) {
            let areas: f64 = p.area_distribution.iter().map(|x| x.count).sum::<usize>() as f64;
            assert_eq!(areas as usize, p.patch_count);
            assert!(
                (p.mean_patch_area * p.patch_count as f64 - b.contact_fraction * size * size).abs()
                    < AREA_SUM
            );
        }
        let sub = r.bem.as_ref().unwrap().subsurface.as_ref().unwrap();
        for (p, &sigma0) in sub.points.iter().zip(&[0.001, 0.003, 0.01]) {
            let deep = p.report.planes[1].von_mises_stress.value;
            let uniform = sigma0 * (1.0 - 2.0 * nu) / (1.0 - nu);
            assert!(
                (deep / uniform - 1.0).abs() < DEEP_PLANE,
                "{deep} {uniform}"
            );
        }
        let dir = tmp("details");
        std::fs::create_dir_all(&dir).unwrap();
        let mut files = persson_studies::output::Files::new();
        let again = scene.run_and_write(&dir, &mut files).unwrap();
        assert_eq!(again.warnings, r.warnings);
        let written = files.commit().unwrap();
        let npy: Vec<_> = written
            .iter()
            .filter(|p| p.extension().is_some_and(|e| e == "npy"))
            .collect();
        assert_eq!(npy.len(), 3 * 2);
        // the .npy map of pressure 2, depth 0 holds the plane's maximum
        let path = dir.join("vm_2_0.npy");
        let map = npy::parse(&path, &std::fs::read(&path).unwrap()).unwrap();
        assert_eq!((map.rows, map.cols), (32, 32));
        let max = map.values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert_eq!(max, sub.points[2].report.planes[0].von_mises_stress.value);
        #[cfg(feature = "plot")]
        {
            let plots: Vec<_> = written
                .iter()
                .filter(|p| p.extension().is_some_and(|e| e == "svg"))
                .cloned()
                .collect();
            assert!(plots.contains(&dir.join("patches.svg")), "{plots:?}");
            assert!(plots.contains(&dir.join("depth.svg")), "{plots:?}");
            // each plane's von Mises map beside it: 3 pressures × 2 depths
            for k in 0..3 {
                for j in 0..2 {
                    let p = dir.join(format!("depth_{k}_{j}.svg"));
                    assert!(plots.contains(&p), "{plots:?}");
                    let svg = std::fs::read_to_string(&p).unwrap();
                    assert!(svg.contains("Von Mises stress at z"), "{k} {j}");
                }
            }
            assert_eq!(plots.len(), 2 + 3 * 2, "{plots:?}");
        }
        // bad input is named: a depth beyond the side, no bins
        for (bad, needle) in [
            (r#""depth": [0.05, 1.0]"#, r#""depth": [2.0]"#),
            (r#""depth": [0.05, 1.0]"#, r#""depth": [0.0]"#),
        ] {
            let e = parse(&rough(&out.replace(bad, needle)))
                .unwrap()
                .run()
                .unwrap_err()
                .to_string();
            assert!(e.contains("outputs.bem.subsurface.depth"), "{e}");
        }
        let e = parse(&rough(
            &out.replace(r#""connectivity": "eight""#, r#""bins_per_decade": 0"#),
        ))
        .unwrap()
        .run()
        .unwrap_err()
        .to_string();
        assert!(e.contains("outputs.bem.patches.bins_per_decade"), "{e}");
    }

    #[test]
    fn bad_bem_outputs_are_named() {
        let cases = [
            (r#"{"bem": {}}"#, "outputs.bem.grid"),
            (
                r#"{"bem": {"grid": 32, "tolerance": 0}}"#,
                "outputs.bem.tolerance",
            ),
            (r#"{"bem": {"grid": 4}}"#, "outputs.bem.grid"),
            (r#"{"bem": {"grid": 32, "bins": 0}}"#, "outputs.bem.bins"),
            (r#"{"bem_hertz": {"grids": [4]}}"#, "outputs.bem_hertz.grid"),
            (
                r#"{"bem": {"grid": 32, "patches": {"bins_per_decade": 0}}}"#,
                "outputs.bem.patches.bins_per_decade",
            ),
            (
                r#"{"bem": {"grid": 32, "subsurface": {"depth": [0.1], "tensile_yield_stress": -1}}}"#,
                "outputs.bem.subsurface.tensile_yield_stress",
            ),
            // The iteration limit is the scene's too: 2 iterations do not
            // reach 1e-10, and the solve says so.
            (
                r#"{"bem": {"grid": 32, "max_iterations": 2}}"#,
                "2 iterations",
            ),
        ];
        for (out, needle) in cases {
            let e = parse(&rough(out)).unwrap().run().unwrap_err().to_string();
            assert!(e.contains(needle), "{out}: {e}");
        }
        let e = parse(&rough(r#"{"bem": {"grid": 32}}"#).replace("[0.001, 0.003, 0.01]", "[]"))
            .unwrap()
            .run()
            .unwrap_err()
            .to_string();
        assert!(e.contains("nominal_pressure"), "{e}");
        let e = parse(&rough(r#"{"bem": {"grid": 32, "sead": 1}}"#))
            .unwrap_err()
            .to_string();
        assert!(e.contains("unknown field `sead`"), "{e}");
        // A boundary is one of the CLI's names, checked where the file is read.
        for out in [
            r#"{"bem": {"grid": 32, "boundary": "open"}}"#,
            r#"{"bem_hertz": {"boundary": "open"}}"#,
        ] {
            let e = parse(&rough(out)).unwrap_err().to_string();
            assert!(
                e.contains("unknown variant `open`, expected `periodic` or `free`"),
                "{out}: {e}"
            );
        }
    }
}

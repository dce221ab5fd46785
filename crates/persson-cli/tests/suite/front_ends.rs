//! The command line and scene files refuse the same inputs: for each value
//! the command line refuses, the scene with that value is refused too,
//! naming its field (`outputs.area.zeta`, `material.young2`), and a scene
//! section no output reads is checked all the same.

use crate::common;

use common::persson;

/// The self-affine surface and material of the cases (the CLI's flags).
const SA: &str = "--hurst 0.8 --q-l 6283.185307179586 --q-r 12566.370614359172 \
                  --q-s 50265.48245743669 --rms-slope 0.1";

/// A scene of the cases' surface, E* = 1 GPa and σ0 = 1e7 with `patch`
/// merged into it (objects merged, anything else replaced).
fn scene(patch: serde_json::Value) -> serde_json::Value {
    let mut base = serde_json::json!({
        "schema": 1,
        "material": {"contact_modulus": 1e9},
        "spectrum": {"kind": "self_affine", "hurst": 0.8, "q_l": 6283.185307179586,
                     "q_r": 12566.370614359172, "q_s": 50265.48245743669, "rms_slope": 0.1},
        "nominal_pressure": [1e7],
        "outputs": {}
    });
    merge(&mut base, patch);
    base
}

fn merge(a: &mut serde_json::Value, b: serde_json::Value) {
    match (a, b) {
        (serde_json::Value::Object(a), serde_json::Value::Object(b)) => {
            for (k, v) in b {
                match a.get_mut(&k) {
                    Some(x) if x.is_object() && v.is_object() => merge(x, v),
                    _ => {
                        a.insert(k, v);
                    }
                }
            }
        }
        (a, b) => *a = b,
    }
}

/// Each case: the command line (exit 2 expected; "" when the command line
/// cannot express the input at all), the scene patch, and the field the
/// scene's error must name.
fn cases() -> Vec<(String, serde_json::Value, &'static str)> {
    use serde_json::json;
    let sep = format!("separation {SA} --contact-modulus 1e9 --pressure 1e7 --separation-density");
    let bem = format!("bem rough {SA} --contact-modulus 1e9 --pressure 1e7 --grid 32");
    let adhesive = format!(
        "bem rough {SA} --contact-modulus 1e9 --grid 32 --adhesion-range 1e-5 --mean-gap 2e-5"
    );
    vec![
        (
            format!("{sep} --tolerance -1"),
            json!({"outputs": {"separation_density": {"tolerance": -1}}}),
            "outputs.separation_density.tolerance",
        ),
        (
            format!("{sep} --density-points 0"),
            json!({"outputs": {"separation_density": {"density_points": 0}}}),
            "outputs.separation_density.density_points",
        ),
        (
            "stress --start hertz --g 0.6 --yield-stress 1e8".to_string(),
            json!({"outputs": {"stress": {"start": "hertz", "g": [0.6], "yield_stress": 1e8}}}),
            "outputs.stress.yield_stress",
        ),
        (
            format!("stress {SA} --contact-modulus 1e9 --start cylinder --zeta 10 --peak-pressure 1e8 --yield-ratio 2"),
            json!({"outputs": {"stress": {"start": "cylinder", "zeta": [10], "peak_pressure": 1e8, "yield_ratio": 2}}}),
            "outputs.stress.yield_ratio",
        ),
        (
            format!("area {SA} --pressure 1e7 --contact-modulus 1e9 --young 1e9 --poisson 0.3"),
            json!({"material": {"young": 1e9, "poisson": 0.3}, "outputs": {"area": {}}}),
            "material.contact_modulus and material.young",
        ),
        (
            format!("area {SA} --pressure 1e7 --contact-modulus 1e9 --poisson 0.9"),
            json!({"material": {"poisson": 0.9}, "outputs": {"area": {}}}),
            "material.poisson",
        ),
        (
            format!("area {SA} --pressure 1e7 --young 1e9 --poisson 0.3 --young2 0 --poisson2 0.3"),
            json!({"material": {"contact_modulus": null, "young": 1e9, "poisson": 0.3, "young2": 0, "poisson2": 0.3}, "outputs": {"area": {}}}),
            "material.young2",
        ),
        (
            // an unused section: the only output reads neither spectrum nor material
            String::new(),
            json!({"spectrum": {"q_l": -1}, "outputs": {"stress": {"start": "hertz", "g": [0.6]}}}),
            "spectrum.q_l",
        ),
        (
            String::new(),
            json!({"material": {"contact_modulus": -5}, "outputs": {"bem_hertz": {"grids": [32]}}}),
            "material.contact_modulus",
        ),
        (
            format!("{adhesive} --work-of-adhesion 0"),
            json!({"outputs": {"bem_adhesion": {"grid": 32, "work_of_adhesion": 0, "adhesion_range": 1e-5, "mean_gap": [2e-5]}}}),
            "outputs.bem_adhesion.work_of_adhesion",
        ),
        (
            format!("{bem} --bins 0"),
            json!({"outputs": {"bem": {"grid": 32, "bins": 0}}}),
            "outputs.bem.bins",
        ),
        (
            String::new(),
            json!({"outputs": {"conductance": {"conductivity": [50], "gap_table": []}}}),
            "outputs.conductance",
        ),
        (
            format!("area {SA} --contact-modulus 1e9 --pressure 1e7 --zeta 0"),
            json!({"outputs": {"area": {"zeta": 0}}}),
            "outputs.area.zeta",
        ),
        (
            format!("magnification {SA} --contact-modulus 1e9 --pressure 1e7 --points 0"),
            json!({"outputs": {"magnification": {"nominal_pressure": 1e7, "points": 0}}}),
            "outputs.magnification.points",
        ),
        (
            format!("stress {SA} --contact-modulus 1e9 --zeta 10 --ball-radius 0 --load 10"),
            json!({"outputs": {"stress": {"start": "hertz", "zeta": [10], "ball": {"radius": 0, "load": 10}}}}),
            "outputs.stress.ball.radius",
        ),
        (
            format!("{bem} --subsurface --depth 1e-5 --tensile-yield-stress 0"),
            json!({"outputs": {"bem": {"grid": 32, "subsurface": {"depth": [1e-5], "tensile_yield_stress": 0}}}}),
            "outputs.bem.subsurface.tensile_yield_stress",
        ),
        (
            String::new(),
            json!({"outputs": {}}),
            "outputs",
        ),
    ]
}

#[test]
fn a_scene_is_refused_where_the_command_line_is_naming_its_field() {
    let dir = std::env::temp_dir().join(format!("persson-front-ends-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (i, (cli, patch, field)) in cases().into_iter().enumerate() {
        if !cli.is_empty() {
            let args: Vec<&str> = cli.split_whitespace().collect();
            let (code, _, err) = persson(&args);
            assert_eq!(code, 2, "{cli}: {err}");
        }
        let path = dir.join(format!("case{i}.json"));
        std::fs::write(&path, scene(patch).to_string()).unwrap();
        let (code, out, err) = persson(&["run", &path.to_string_lossy()]);
        assert_eq!((code, out.as_str()), (2, ""), "case {i} ({field}): {err}");
        assert!(err.contains(field), "case {i}: wanted {field}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The figures of the rough BEM are both front-ends': a scene's
/// `outputs.bem.plot` is `bem rough --area-plot`, its `pressure_plot` is
/// `bem rough --plot`, `patches.plot` is `--patches-plot` and
/// `subsurface.plot` is `--stress-plot` (the depth profiles and each
/// plane's map), byte for byte (the same surface, loads and solver).
#[test]
#[cfg(feature = "plot")]
fn the_rough_bem_draws_the_same_figures_from_a_scene_and_flags() {
    let dir = std::env::temp_dir().join(format!("persson-bem-figures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let s = scene(serde_json::json!({
        "nominal_pressure": [1e6, 3e6],
        "outputs": {"bem": {"grid": 32, "plot": "area.svg", "pressure_plot": "map.svg",
                            "patches": {"plot": "patches.svg"},
                            "subsurface": {"depth": [1e-5], "plot": "stress.svg"}}}
    }));
    let path = dir.join("s.json");
    std::fs::write(&path, s.to_string()).unwrap();
    let (code, _, err) = persson(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let (area, map) = (dir.join("cli-area.svg"), dir.join("cli-map.svg"));
    let mut args: Vec<&str> = vec!["bem", "rough"];
    args.extend(SA.split_whitespace());
    let (patches, stress) = (dir.join("cli-patches.svg"), dir.join("cli-stress.svg"));
    let (area_s, map_s) = (area.to_str().unwrap(), map.to_str().unwrap());
    let (patches_s, stress_s) = (patches.to_str().unwrap(), stress.to_str().unwrap());
    args.extend([
        "--contact-modulus",
        "1e9",
        "--grid",
        "32",
        "--pressure",
        "1e6,3e6",
        "--area-plot",
        area_s,
        "--plot",
        map_s,
        "--patches",
        "--patches-plot",
        patches_s,
        "--subsurface",
        "--depth",
        "1e-5",
        "--stress-plot",
        stress_s,
    ]);
    let (code, _, err) = persson(&args);
    assert_eq!(code, 0, "{err}");
    let read = |p: std::path::PathBuf| std::fs::read(p).unwrap();
    assert_eq!(read(dir.join("area.svg")), read(area));
    assert_eq!(read(dir.join("map.svg")), read(map));
    assert_eq!(read(dir.join("patches.svg")), read(patches.clone()));
    assert_eq!(read(dir.join("stress.svg")), read(stress.clone()));
    for k in 0..2 {
        let plane = |name: &str| dir.join(format!("{name}_{k}_0.svg"));
        assert_eq!(read(plane("stress")), read(plane("cli-stress")), "{k}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// A scene's `bem_adhesion` takes the iteration `bem rough
/// --adhesive-iteration` takes: the same path, point for point, from both
/// front-ends (the exponential law, whose default is the preconditioned
/// iteration, asked for the plain one).
#[test]
#[cfg(feature = "bem")]
fn the_adhesive_iteration_is_a_scene_field_too() {
    let dir = std::env::temp_dir().join(format!("persson-adhesive-it-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("scene.json");
    let s = scene(serde_json::json!({"outputs": {"bem_adhesion": {
        "grid": 32, "work_of_adhesion": 1e-4, "adhesion_range": 1e-5,
        "adhesion": "exponential", "mean_gap": [3e-5, 2e-5],
        "adhesive_iteration": "plain"}}}));
    std::fs::write(&path, s.to_string()).unwrap();
    let scene = common::json(&["run", &path.to_string_lossy(), "--json"]);
    let flags = format!(
        "bem rough {SA} --contact-modulus 1e9 --grid 32 --work-of-adhesion 1e-4 \
         --adhesion-range 1e-5 --adhesion exponential --mean-gap 3e-5,2e-5 \
         --adhesive-iteration plain --json"
    );
    let args: Vec<&str> = flags.split_whitespace().collect();
    let cli = common::json(&args);
    let points = |v: &serde_json::Value| {
        v["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                let f = |k: &str| p[k].as_f64().unwrap_or_else(|| panic!("{k}: {p}"));
                (
                    f("nominal_pressure"),
                    f("contact_fraction"),
                    f("iterations"),
                )
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(points(&scene["bem_adhesion"]), points(&cli));
    assert_eq!(points(&cli).len(), 2);
    std::fs::remove_dir_all(&dir).ok();
}

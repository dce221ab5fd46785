//! `persson run SCENE.json`: compute what a scene asks for.

use std::path::PathBuf;

use persson::scene::{Scene, SceneReport};
use persson::theory::AreaPoint;

use super::output::{Format, Report};

/// Arguments of `persson run`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The scene file (JSON, "schema": 1).
    scene: PathBuf,
    /// Also write report.json and one CSV per output into this existing directory.
    #[arg(long)]
    out: Option<PathBuf>,
    #[command(flatten)]
    format: Format,
}

/// Run `persson run`.
pub fn run(a: Args) -> anyhow::Result<()> {
    let scene = Scene::read(&a.scene)?;
    // Plots go to --out DIR, else the current directory. Fail before computing
    // anything if a file cannot be written there, or would overwrite an input.
    let dir = a.out.clone().unwrap_or_else(|| PathBuf::from("."));
    let mut outputs = scene.plot_paths(&dir);
    if a.out.is_some() {
        outputs.push(dir.join("report.json"));
    }
    for p in &outputs {
        if same_file(p, &a.scene) || scene_inputs(&scene).iter().any(|i| same_file(p, i)) {
            anyhow::bail!("{}: output would overwrite an input file", p.display());
        }
        #[cfg(not(feature = "plot"))]
        if !p.ends_with("report.json")
            && !scene
                .outputs
                .bem
                .as_ref()
                .and_then(|b| b.histogram.as_ref())
                .is_some_and(|h| p.ends_with(h))
        {
            anyhow::bail!(
                "{}: this persson was built without the `plot` feature",
                p.display()
            );
        }
        persson::io::check_writable(p)?;
    }
    let report = scene.run()?;
    #[cfg(feature = "plot")]
    for p in persson::scene::render_plots(&scene, &report, &dir)? {
        eprintln!("wrote {}", p.display());
    }
    for p in persson::scene::write_data(&scene, &report, &dir)? {
        eprintln!("wrote {}", p.display());
    }
    let sections = sections(&report);
    if let Some(dir) = &a.out {
        persson::io::write_atomic(
            &dir.join("report.json"),
            serde_json::to_string_pretty(&report)?.as_bytes(),
        )?;
        for (name, r) in sections.iter().filter(|(_, r)| !r.rows.is_empty()) {
            persson::io::write_atomic(&dir.join(format!("{name}.csv")), r.csv().as_bytes())?;
        }
    }
    if a.format.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
        return Ok(());
    }
    for (_, r) in &sections {
        r.print(&a.format)?;
        println!();
    }
    Ok(())
}

/// The input files a scene reads.
fn scene_inputs(scene: &Scene) -> Vec<PathBuf> {
    match &scene.spectrum {
        Some(
            persson::scene::SpectrumSpec::Tabulated { file, .. }
            | persson::scene::SpectrumSpec::HeightMap { file, .. },
        ) => vec![file.clone()],
        _ => vec![],
    }
}

/// Whether two paths name the same existing file.
fn same_file(a: &std::path::Path, b: &std::path::Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

/// One printable table per computed output.
fn sections(r: &SceneReport) -> Vec<(String, Report)> {
    let mut out = Vec::new();
    if let Some(k) = &r.kappa {
        out.push((
            "kappa".to_string(),
            Report {
                title: "kappa".into(),
                scalars: vec![
                    ("kappa_bush".into(), k.kappa_bush),
                    ("kappa_persson".into(), k.kappa_persson),
                ],
                columns: vec![],
                rows: vec![],
                json: serde_json::json!(k),
            },
        ));
    }
    let table = |title: &str, pts: &[AreaPoint]| Report {
        title: title.into(),
        scalars: vec![],
        columns: [
            "pressure",
            "zeta",
            "g",
            "contact_fraction",
            "bush_linear",
            "error_bound",
        ]
        .map(String::from)
        .to_vec(),
        rows: pts
            .iter()
            .map(|p| {
                vec![
                    p.pressure,
                    p.zeta,
                    p.g,
                    p.contact_fraction,
                    p.contact_fraction_bush_linear,
                    p.error,
                ]
            })
            .collect(),
        json: serde_json::json!(pts),
    };
    if let Some(p) = &r.area {
        out.push((
            "area".into(),
            table("Contact area against nominal pressure", p),
        ));
    }
    if let Some(p) = &r.magnification {
        out.push((
            "magnification".into(),
            table("Contact area against magnification", p),
        ));
    }
    for c in r.theories.iter().flatten() {
        let name = c.theory.name();
        out.push((
            name.to_string(),
            Report {
                title: format!(
                    "Contact area, {name} theory (gamma = {:?}, kappa = {:.4})",
                    c.theory.gamma(),
                    c.kappa
                ),
                scalars: vec![],
                columns: [
                    "pressure",
                    "zeta",
                    "g",
                    "effective_g",
                    "contact_fraction",
                    "error_bound",
                ]
                .map(String::from)
                .to_vec(),
                rows: c
                    .points
                    .iter()
                    .map(|p| {
                        vec![
                            p.pressure,
                            p.zeta,
                            p.g,
                            p.effective_g,
                            p.contact_fraction,
                            p.error,
                        ]
                    })
                    .collect(),
                json: serde_json::json!(c),
            },
        ));
    }
    if let Some(pts) = &r.separation {
        out.push((
            "separation".into(),
            Report {
                title: "Mean interfacial separation against load".into(),
                scalars: vec![],
                columns: ["pressure", "mean_separation", "stiffness", "elastic_energy"]
                    .map(String::from)
                    .to_vec(),
                rows: pts
                    .iter()
                    .map(|p| vec![p.pressure, p.mean_separation, p.stiffness, p.elastic_energy])
                    .collect(),
                json: serde_json::json!(pts),
            },
        ));
    }
    for (i, c) in r.stress.iter().flatten().enumerate() {
        out.push((
            format!("stress_{}", i + 1),
            Report {
                title: format!(
                    "Stress distribution, G = {:e}{}, method: {}",
                    c.g,
                    c.zeta.map_or(String::new(), |z| format!(", zeta = {z:e}")),
                    c.method
                ),
                scalars: vec![
                    ("contact_fraction".into(), c.contact_fraction),
                    ("plastic_fraction".into(), c.plastic_fraction),
                    ("error_bound".into(), c.error_bound),
                ],
                columns: ["sigma", "density"].map(String::from).to_vec(),
                rows: c
                    .sigma
                    .iter()
                    .zip(&c.density)
                    .map(|(s, p)| vec![*s, *p])
                    .collect(),
                json: serde_json::json!(c),
            },
        ));
    }
    if let Some(b) = &r.bem {
        out.push((
            "bem".into(),
            Report {
                title: format!(
                    "Rough contact (FFT-BEM), {0}x{0} grid, L = {1:e}, {2} boundary, tol = {3:e}",
                    b.grid, b.size, b.boundary, b.tolerance
                ),
                scalars: vec![
                    ("rms_height".into(), b.rms_height),
                    ("rms_slope".into(), b.rms_slope),
                ],
                columns: [
                    "pressure",
                    "contact_fraction",
                    "iterations",
                    "residual",
                    "approach",
                    "seconds",
                ]
                .map(String::from)
                .to_vec(),
                rows: b
                    .points
                    .iter()
                    .map(|p| {
                        vec![
                            p.pressure,
                            p.contact_fraction,
                            p.iterations as f64,
                            p.residual,
                            p.approach,
                            p.seconds,
                        ]
                    })
                    .collect(),
                json: serde_json::json!(b),
            },
        ));
    }
    if let Some(rows) = &r.bem_hertz {
        out.push((
            "bem_hertz".into(),
            Report {
                title: format!(
                    "Hertz convergence (FFT-BEM, {} boundary; a = 0.1 L, R = L; lecture: 000 Table 1, free boundary, NaN = not listed)",
                    rows.first().map_or("", |h| h.boundary.as_str())
                ),
                scalars: vec![],
                columns: [
                    "grid",
                    "energy_error",
                    "lecture",
                    "contact_radius_error",
                    "peak_pressure_error",
                    "contact_fraction",
                    "iterations",
                    "seconds",
                ]
                .map(String::from)
                .to_vec(),
                rows: rows
                    .iter()
                    .map(|h| {
                        vec![
                            h.grid as f64,
                            h.energy_error,
                            h.lecture.unwrap_or(f64::NAN),
                            h.contact_radius_error,
                            h.peak_pressure_error,
                            h.contact_fraction,
                            h.iterations as f64,
                            h.seconds,
                        ]
                    })
                    .collect(),
                json: serde_json::json!(rows),
            },
        ));
    }
    out
}

//! `persson run SCENE.json`: compute what a scene asks for.

use std::path::{Path, PathBuf};

use anyhow::Context;
use persson_studies::scene::Scene;
use persson_studies::table::Tabulate;

use super::output::{print_from, print_warning, Format, Source};
use persson_studies::warning::Warned;

/// Arguments of `persson run`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The scene file (JSON, "schema": 1; its JSON Schema is
    /// crates/persson-studies/schema/scene.schema.json).
    scene: PathBuf,
    /// Write report.json, one CSV per table and the plots into this directory
    /// (created if missing).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print one JSON object on stdout.
    #[arg(long, conflicts_with = "csv")]
    json: bool,
    /// Write one CSV per table, named by what it holds (`area.csv`,
    /// `stress_G0.6.csv`), into --out DIR or the current directory; the files
    /// are listed on stderr.
    #[arg(long)]
    csv: bool,
}

/// Run `persson run`.
pub fn run(a: Args) -> anyhow::Result<()> {
    let scene = Scene::read(&a.scene)?;
    // Plots go to --out DIR, else the current directory. Fail before computing
    // anything if a file cannot be written there, or would overwrite an input.
    let dir = a.out.clone().unwrap_or_else(|| PathBuf::from("."));
    if let Some(d) = &a.out {
        std::fs::create_dir_all(d).with_context(|| format!("creating {}", d.display()))?;
    }
    let mut outputs = scene.output_paths(&dir);
    if a.out.is_some() {
        outputs.push(dir.join("report.json"));
    }
    #[cfg(not(feature = "plot"))]
    if let Some(p) = scene.plot_paths(&dir).first() {
        anyhow::bail!(
            "{}: this persson was built without the `plot` feature",
            p.display()
        );
    }
    for p in &outputs {
        check_output(p, &a.scene, &scene)?;
    }
    let report = scene.run()?;
    #[cfg(feature = "plot")]
    for p in persson_studies::scene::render_plots(&scene, &report, &dir)? {
        eprintln!("wrote {}", p.display());
    }
    for p in persson_studies::scene::write_data(&scene, &report, &dir)? {
        eprintln!("wrote {}", p.display());
    }
    if a.out.is_some() || a.csv {
        for t in report.tables().iter().filter(|t| !t.rows.is_empty()) {
            let p = dir.join(format!("{}.csv", t.name));
            check_output(&p, &a.scene, &scene)?;
            persson::io::write_atomic(&p, t.to_csv().as_bytes())?;
            eprintln!("wrote {}", p.display());
        }
    }
    if a.out.is_some() {
        let p = dir.join("report.json");
        persson::io::write_atomic(
            &p,
            serde_json::to_string_pretty(&Warned::new(&report, &report.warnings))?.as_bytes(),
        )?;
        eprintln!("wrote {}", p.display());
    }
    if a.csv {
        for w in &report.warnings {
            print_warning(w, Source::Scene);
        }
        return Ok(());
    }
    if !a.json {
        for text in [&report.name, &report.description].into_iter().flatten() {
            println!("{text}\n");
        }
    }
    print_from(
        &report,
        &report.warnings,
        &Format {
            json: a.json,
            csv: false,
        },
        Source::Scene,
    )
}

/// An output file may not overwrite the scene or its inputs, and its
/// directory must accept it.
fn check_output(p: &Path, scene_file: &Path, scene: &Scene) -> anyhow::Result<()> {
    if same_file(p, scene_file) || scene.input_paths().iter().any(|i| same_file(p, i)) {
        anyhow::bail!("{}: output would overwrite an input file", p.display());
    }
    persson::io::check_writable(p)?;
    Ok(())
}

/// Whether two paths name the same existing file.
fn same_file(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

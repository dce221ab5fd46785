//! `persson run SCENE.json`: compute what a scene asks for.

use std::path::Path;

use persson_studies::output::Files;
use persson_studies::scene::Scene;
use persson_studies::table::Tabulate;

use super::files::{in_file, out_dir, InFile, OutDir};
use super::output::{print_from, print_warning, Format, Source};
use persson_studies::warning::Warned;

/// Arguments of `persson run`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The scene file (JSON, "schema": 1; its JSON Schema is
    /// crates/persson-studies/schema/scene.schema.json).
    #[arg(value_parser = in_file)]
    scene: InFile,
    /// Write report.json, one CSV per table and the plots into this directory
    /// (created if missing).
    #[arg(long, value_parser = out_dir)]
    out: Option<OutDir>,
    /// Print one JSON object on stdout.
    #[arg(long, conflicts_with = "csv")]
    json: bool,
    /// Write one CSV per table, named by what it holds (`area.csv`,
    /// `stress_G0.6.csv`), into --out DIR or the current directory; the files
    /// are listed on stderr.
    #[arg(long)]
    csv: bool,
}

/// Run `persson run`: every file the scene names is checked before the
/// scene is computed, and all are written, then listed, once it has run.
pub fn run(a: Args, files: &mut Files) -> anyhow::Result<()> {
    let scene = Scene::read(&a.scene)?;
    // Plots go to --out DIR, else the current directory.
    let dir = a.out.as_deref().unwrap_or(Path::new(".")).to_path_buf();
    scene.plan(&a.scene, &dir, files)?;
    let report_json = dir.join("report.json");
    if a.out.is_some() {
        files.reserve("--out", &report_json, &[])?;
    }
    let report = scene.run_and_write(&dir, files)?;
    if a.out.is_some() || a.csv {
        for t in report.tables().iter().filter(|t| !t.rows.is_empty()) {
            files.write(&dir.join(format!("{}.csv", t.name)), t.to_csv().as_bytes())?;
        }
    }
    if a.out.is_some() {
        let json = serde_json::to_string_pretty(&Warned::new(&report, &report.warnings))?;
        files.write(&report_json, json.as_bytes())?;
    }
    for p in files.commit()? {
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

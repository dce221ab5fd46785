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
    if let Some(dir) = &a.out {
        // Fail before computing anything if the directory cannot take the files.
        persson::io::check_writable(&dir.join("report.json"))?;
    }
    let report = scene.run()?;
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

/// One printable table per computed output.
fn sections(r: &SceneReport) -> Vec<(&'static str, Report)> {
    let mut out = Vec::new();
    if let Some(k) = &r.kappa {
        out.push((
            "kappa",
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
        out.push(("area", table("Contact area against nominal pressure", p)));
    }
    if let Some(p) = &r.magnification {
        out.push((
            "magnification",
            table("Contact area against magnification", p),
        ));
    }
    out
}

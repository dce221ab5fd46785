//! One scene in, one JSON document out: the report and everything
//! `persson run` prints of it.

use std::path::Path;

use persson_studies::scene::Scene;
use persson_studies::table::{Cell, Table, Tabulate};
use persson_studies::warning::{not_computed, Warned};
use serde::Serialize;
use serde_json::Value;

/// The name a scene has in the messages: the page's scene is the file a
/// user downloads and runs as `persson run scene.json`, so the errors
/// name the same file.
pub const SCENE: &str = "scene.json";

/// What [`run`] returns.
#[derive(Debug, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum Outcome {
    /// The scene ran.
    Ok(Box<Done>),
    /// It did not: the message `persson run` prints after `persson: error: `.
    Error {
        /// The message.
        error: String,
    },
}

/// A scene that ran.
#[derive(Debug, Serialize)]
pub struct Done {
    /// `persson run scene.json --json`, as a value.
    pub report: Value,
    /// What `persson run scene.json` prints on stdout.
    pub text: String,
    /// Its warnings, each as printed after `persson: warning: `.
    pub warnings: Vec<String>,
    /// The tables, with their values for the page's plots.
    pub tables: Vec<TableData>,
}

/// A table: its text and CSV as the command line writes them, and its
/// values.
#[derive(Debug, Serialize)]
pub struct TableData {
    /// File stem (`area`).
    pub name: String,
    /// Title line.
    pub title: String,
    /// Aligned text, as printed.
    pub text: String,
    /// CSV, as `--csv` writes it.
    pub csv: String,
    /// Column keys (`nominal_pressure`).
    pub keys: Vec<String>,
    /// Column headings (`σ0`).
    pub headings: Vec<String>,
    /// Rows of values: numbers (full precision), text, or `null`.
    pub rows: Vec<Vec<Value>>,
    /// Scalars above the table: key, heading, value.
    pub scalars: Vec<(String, String, Value)>,
}

/// Run the scene in `text` (its input files mounted with
/// [`persson::io::mount`] under the names it gives them).
pub fn run(text: &str) -> Outcome {
    match compute(text) {
        Ok(done) => Outcome::Ok(Box::new(done)),
        Err(e) => Outcome::Error {
            error: e.to_string(),
        },
    }
}

fn compute(text: &str) -> persson::Result<Done> {
    let scene = Scene::parse(Path::new(SCENE), text)?;
    let report = persson_studies::progress::observe(crate::host::progress, || scene.run())?;
    let tables = report.tables();
    let mut warnings = report.warnings.clone();
    warnings.extend(not_computed(&tables));
    let json = serde_json::to_value(Warned::new(&report, &warnings)).map_err(|e| {
        persson::Error::Inconsistent {
            name: "report".into(),
            requirement: format!("serialisable as JSON ({e})"),
        }
    })?;
    let mut out = String::new();
    for line in [&report.name, &report.description].into_iter().flatten() {
        out.push_str(line);
        out.push_str("\n\n");
    }
    let texts: Vec<String> = tables.iter().map(Table::to_text).collect();
    out.push_str(&texts.join("\n"));
    Ok(Done {
        report: json,
        text: out,
        warnings: warnings.iter().map(warning_text).collect(),
        tables: tables.iter().map(table_data).collect(),
    })
}

fn warning_text(w: &persson_studies::Warning) -> String {
    match w.scene_hint() {
        Some(h) => format!("{w} ({h})"),
        None => w.to_string(),
    }
}

fn table_data(t: &Table) -> TableData {
    TableData {
        name: t.name.clone(),
        title: t.title.clone(),
        text: t.to_text(),
        csv: t.to_csv(),
        keys: t.columns.iter().map(|c| c.key.clone()).collect(),
        headings: t.columns.iter().map(|c| c.heading.clone()).collect(),
        rows: t
            .rows
            .iter()
            .map(|r| r.iter().map(value).collect())
            .collect(),
        scalars: t
            .scalars
            .iter()
            .map(|(k, h, c)| (k.clone(), h.clone(), value(c)))
            .collect(),
    }
}

fn value(c: &Cell) -> Value {
    let number = |v: f64| serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number);
    match c {
        Cell::Int(i) => Value::from(*i),
        Cell::Num(v) | Cell::Measured { value: v, .. } => number(*v),
        Cell::Text(s) => Value::String(s.clone()),
        Cell::Empty => Value::Null,
    }
}

//! Mitutoyo SurfTest `.xlsx` (the spreadsheet the SurfTest roughness
//! testers export): a line scan.
//!
//! An Office Open XML workbook (a zip archive holding `xl/workbook.xml`).
//! Read from it:
//!
//! ```text
//! sheet "DATA"          column E: x (from Δ to n·Δ), column F: heights, one
//!                       point a row; column A from row 1: roughness
//!                       parameters "Ra     0.018  µm" (up to the first
//!                       empty cell)
//! sheet "Certificate"   cell E48: the cut-off, "0.08mm"
//! ```
//!
//! The sheets are found by name through `xl/workbook.xml` and
//! `xl/_rels/workbook.xml.rels`; text cells through `xl/sharedStrings.xml`.
//! The unit of x is the cut-off's; the unit of the heights is that of the
//! first roughness parameter (none there: the unit of x), as
//! SurfaceTopography takes them. A row with x but no height (or a height
//! but no x) is an error; the file has no undefined points. The
//! positions are taken as a text line scan's ([`super`] module docs, "Line
//! scans"), a cell's number as exact (it is a double, written out in full,
//! not a rounded decimal): equally spaced within 0.01 Δ, else resampled onto n
//! equally spaced points with a [`crate::topography::Note::Resampled`]; the
//! length is `n·Δ` (SurfaceTopography: the largest x, the same for the
//! positions Δ … n·Δ the instrument writes). The file has one channel.
//!
//! # References
//! ECMA-376 (Office Open XML), part 1, §18.3 (worksheets) and §18.4
//! (shared strings); the layout as SurfaceTopography's `IO/Mitutoyo.py`
//! reads it.

use std::collections::HashMap;
use std::io::Cursor;
use std::path::Path;

use super::archive::{self, Archive};
use super::units::{LengthUnit, Unit};
use super::{channel, line, Raw, ReadOptions};
use crate::error::{Error, Result};
use crate::io::text::{Row, Rows};

const FORMAT: &str = "Mitutoyo SurfTest .xlsx";
/// The workbook's part, which an .xlsx has and an .x3p has not.
const WORKBOOK: &str = "xl/workbook.xml";
/// The largest part read (an instrument's line scan sheet is a few MB; a
/// part's tree takes ~14× its text).
const MAX_PART: u64 = 1 << 25;
/// The most XML nodes parsed from one part (~20 per measured point).
const MAX_NODES: u32 = 1 << 24;

/// Whether `bytes` are a zip archive holding `xl/workbook.xml`.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PK\x03\x04")
        && zip::ZipArchive::new(Cursor::new(bytes))
            .is_ok_and(|z| z.index_for_name(WORKBOOK).is_some())
}

fn bad(path: &Path, message: impl std::fmt::Display) -> Error {
    Error::parse(path, 0, 0, format!("{FORMAT}: {message}"))
}

pub(crate) fn parse(path: &Path, bytes: &[u8], options: &ReadOptions) -> Result<Raw> {
    let mut zip = zip::ZipArchive::new(Cursor::new(bytes))
        .map_err(|e| bad(path, format!("not a readable zip archive: {e}")))?;
    if zip.index_for_name(WORKBOOK).is_none() {
        return Err(bad(path, format!("the archive has no {WORKBOOK}")));
    }
    channel::choose(&[("Default", true)], options.channel.as_deref()).map_err(|m| bad(path, m))?;
    let strings = match zip.index_for_name("xl/sharedStrings.xml") {
        Some(_) => shared_strings(path, &part(&mut zip, path, "xl/sharedStrings.xml")?)?,
        None => Vec::new(),
    };
    let sheets = sheet_parts(path, &mut zip)?;
    let sheet = |zip: &mut Archive, name: &str| -> Result<Cells> {
        let part_name = sheets
            .get(name)
            .ok_or_else(|| bad(path, format!("the workbook has no sheet {name:?}")))?;
        cells(path, name, &part(zip, path, part_name)?, &strings)
    };
    let data = sheet(&mut zip, "DATA")?;
    let certificate = sheet(&mut zip, "Certificate")?;
    let x_unit = cut_off_unit(path, &certificate)?;
    let h_unit = height_unit(path, &data)?.unwrap_or_else(|| x_unit.clone());
    let rows = points(path, &data)?;
    let mut raw = line::parse(path, &rows).map_err(|e| match e {
        Error::Parse { message, line, .. } => {
            bad(path, format!("sheet DATA, row {line}: {message}"))
        }
        e => e,
    })?;
    raw.height_unit = h_unit;
    if let Some(s) = raw.size.as_mut() {
        s.unit = x_unit;
    }
    Ok(raw)
}

/// A part of the archive, whole (at most [`MAX_PART`] bytes), as text.
fn part(zip: &mut Archive, path: &Path, name: &str) -> Result<String> {
    let bytes = archive::member(zip, path, FORMAT, name, MAX_PART)?;
    String::from_utf8(bytes).map_err(|_| bad(path, format!("part {name:?} is not UTF-8")))
}

fn xml<'t>(path: &Path, name: &str, text: &'t str) -> Result<roxmltree::Document<'t>> {
    let options = roxmltree::ParsingOptions {
        nodes_limit: MAX_NODES,
        ..Default::default()
    };
    roxmltree::Document::parse_with_options(text, options)
        .map_err(|e| bad(path, format!("{name}: {e}")))
}

/// The texts of `xl/sharedStrings.xml`, in order (a rich-text item is the
/// concatenation of its runs; phonetic hints are left out).
fn shared_strings(path: &Path, text: &str) -> Result<Vec<String>> {
    let doc = xml(path, "xl/sharedStrings.xml", text)?;
    Ok(doc
        .root_element()
        .children()
        .filter(|n| n.has_tag_name((MAIN, "si")))
        .map(|si| {
            si.descendants()
                .filter(|n| {
                    n.has_tag_name((MAIN, "t"))
                        && !n.ancestors().any(|a| a.has_tag_name((MAIN, "rPh")))
                })
                .filter_map(|t| t.text())
                .collect()
        })
        .collect())
}

const MAIN: &str = "http://schemas.openxmlformats.org/spreadsheetml/2006/main";
const REL: &str = "http://schemas.openxmlformats.org/officeDocument/2006/relationships";

/// The part of each sheet, by the sheet's name.
fn sheet_parts(path: &Path, zip: &mut Archive) -> Result<HashMap<String, String>> {
    let rels_text = part(zip, path, "xl/_rels/workbook.xml.rels")?;
    let rels = xml(path, "xl/_rels/workbook.xml.rels", &rels_text)?;
    let targets: HashMap<&str, &str> = rels
        .descendants()
        .filter(|n| n.tag_name().name() == "Relationship")
        .filter_map(|n| Some((n.attribute("Id")?, n.attribute("Target")?)))
        .collect();
    let book_text = part(zip, path, WORKBOOK)?;
    let book = xml(path, WORKBOOK, &book_text)?;
    let mut parts = HashMap::new();
    for s in book
        .descendants()
        .filter(|n| n.has_tag_name((MAIN, "sheet")))
    {
        let (Some(name), Some(id)) = (s.attribute("name"), s.attribute((REL, "id"))) else {
            continue;
        };
        if let Some(target) = targets.get(id) {
            let target = match target.strip_prefix('/') {
                Some(absolute) => absolute.to_string(),
                None => format!("xl/{target}"),
            };
            parts.insert(name.to_string(), target);
        }
    }
    Ok(parts)
}

/// A cell's content: a number (with its text, for the precision written)
/// or text.
#[derive(Debug, Clone)]
enum Cell {
    Number(f64, String),
    Text(String),
}

/// The cells of a sheet that hold a value, by reference (`"E12"`).
struct Cells {
    sheet: String,
    cells: HashMap<String, Cell>,
    /// The rows that hold a value, in order.
    rows: Vec<usize>,
}

fn cells(path: &Path, sheet: &str, text: &str, strings: &[String]) -> Result<Cells> {
    let doc = xml(path, &format!("sheet {sheet}"), text)?;
    let mut out = Cells {
        sheet: sheet.to_string(),
        cells: HashMap::new(),
        rows: Vec::new(),
    };
    for c in doc.descendants().filter(|n| n.has_tag_name((MAIN, "c"))) {
        let Some(reference) = c.attribute("r") else {
            continue;
        };
        let child = |name: &str| c.children().find(|n| n.has_tag_name((MAIN, name)));
        let value = child("v").and_then(|v| v.text());
        let cell = match (c.attribute("t").unwrap_or("n"), value) {
            ("inlineStr", _) => child("is").map(|is| {
                Cell::Text(
                    is.descendants()
                        .filter(|n| n.has_tag_name((MAIN, "t")))
                        .filter_map(|t| t.text())
                        .collect(),
                )
            }),
            (_, None) => None,
            ("s", Some(v)) => {
                let s = v
                    .trim()
                    .parse::<usize>()
                    .ok()
                    .and_then(|i| strings.get(i))
                    .ok_or_else(|| {
                        bad(
                            path,
                            format!("sheet {sheet}, cell {reference}: no shared string {v:?}"),
                        )
                    })?;
                Some(Cell::Text(s.clone()))
            }
            ("n", Some(v)) => {
                let x = v.trim().parse::<f64>().map_err(|_| {
                    bad(
                        path,
                        format!("sheet {sheet}, cell {reference}: {v:?} is not a number"),
                    )
                })?;
                Some(Cell::Number(x, v.trim().to_string()))
            }
            (_, Some(v)) => Some(Cell::Text(v.to_string())),
        };
        if let Some(cell) = cell {
            let row = reference
                .trim_start_matches(|ch: char| ch.is_ascii_alphabetic())
                .parse::<usize>()
                .map_err(|_| bad(path, format!("sheet {sheet}: cell reference {reference:?}")))?;
            if out.rows.last() != Some(&row) {
                out.rows.push(row);
            }
            out.cells.insert(reference.to_string(), cell);
        }
    }
    out.rows.sort_unstable();
    out.rows.dedup();
    Ok(out)
}

impl Cells {
    fn get(&self, column: &str, row: usize) -> Option<&Cell> {
        self.cells.get(&format!("{column}{row}"))
    }

    fn text(&self, column: &str, row: usize) -> Option<&str> {
        match self.get(column, row)? {
            Cell::Text(t) => Some(t),
            Cell::Number(_, t) => Some(t),
        }
    }
}

/// The unit of x: that of the cut-off in Certificate!E48 (`0.08mm`).
fn cut_off_unit(path: &Path, c: &Cells) -> Result<Unit> {
    let text = c.text("E", 48).ok_or_else(|| {
        bad(
            path,
            "sheet Certificate has no cut-off in E48 (it gives the unit of x)",
        )
    })?;
    let unit = text
        .trim()
        .trim_start_matches(|ch: char| ch.is_ascii_digit() || "+-.".contains(ch))
        .trim();
    match LengthUnit::parse(unit) {
        Some(u) => Ok(Unit::Stated(unit.to_string(), u)),
        None => Err(bad(
            path,
            format!(
                "the cut-off {text:?} in {}!E48 has no unit of length (it gives the unit of x)",
                c.sheet
            ),
        )),
    }
}

/// The unit of the first roughness parameter of column A (`Ra 0.018 µm`),
/// or `None` when the column holds none.
fn height_unit(path: &Path, data: &Cells) -> Result<Option<Unit>> {
    let mut row = 1;
    while let Some(text) = data.text("A", row) {
        let mut words = text.split_whitespace();
        let (Some(_key), Some(value)) = (words.next(), words.next()) else {
            row += 1;
            continue;
        };
        if value.parse::<f64>().is_ok() {
            let unit = words.next().unwrap_or("");
            return Unit::declared(
                &format!("the heights (unit of {text:?} in DATA!A{row})"),
                unit,
            )
            .map(Some)
            .map_err(|m| bad(path, m));
        }
        row += 1;
    }
    Ok(None)
}

/// The points (x in E, height in F) as the rows of a text line scan.
fn points(path: &Path, data: &Cells) -> Result<Rows> {
    let number = |column: &str, row: usize| -> Result<Option<f64>> {
        match data.get(column, row) {
            None => Ok(None),
            Some(Cell::Number(x, _)) => Ok(Some(*x)),
            Some(Cell::Text(t)) => Err(bad(
                path,
                format!("sheet DATA, cell {column}{row} holds the text {t:?}, not a number"),
            )),
        }
    };
    let mut rows = Vec::new();
    for &r in &data.rows {
        match (number("E", r)?, number("F", r)?) {
            (Some(x), Some(h)) => rows.push(Row {
                line: r,
                values: vec![x, h],
                // A cell stores a double; its text is that double written out
                // in full, not rounded: exact.
                resolution: [0.0, 0.0],
            }),
            (None, None) => {}
            (Some(_), None) => {
                return Err(bad(
                    path,
                    format!("sheet DATA, row {r}: x in E{r} but no height in F{r}"),
                ))
            }
            (None, Some(_)) => {
                return Err(bad(
                    path,
                    format!("sheet DATA, row {r}: a height in F{r} but no x in E{r}"),
                ))
            }
        }
    }
    if rows.is_empty() {
        return Err(bad(
            path,
            "sheet DATA holds no points (x in column E, heights in F)",
        ));
    }
    Ok(Rows {
        header: Vec::new(),
        comments: Vec::new(),
        rows,
    })
}

//! One table type for every report: aligned text for people, CSV for programs.
//!
//! Every typed report of the crate (a load curve, a stress distribution, a
//! comparison against the BEM, …) implements [`Tabulate`]; the command-line
//! tool and `persson run` print its tables with [`Table::to_text`] or write
//! them with [`Table::to_csv`], one file per table named [`Table::name`].
//!
//! # Number style
//! - Integers ([`Cell::Int`]) print as integers, in text and CSV alike.
//! - A column of reals prints in one style: fixed-point when every non-zero
//!   value lies in [1e-3, 1e6) and the column spans at most four decades,
//!   scientific (`1.234e-5`) otherwise, each with the column's significant
//!   digits.
//! - A measured value with its error ([`Cell::Measured`]) prints only the
//!   digits the error supports: `0.91 ± 0.03`.
//! - CSV writes reals in the shortest form that reads back to the same `f64`
//!   (`64`, `0.6`, `1e-12`, `1.333256300747068e7`): nothing is lost, nothing
//!   is padded.
//! - No non-finite number is printed: a NaN or ∞ is a quantity that could
//!   not be computed, `–` in text and empty in CSV (serde_json writes it as
//!   `null`), and [`crate::warning::not_computed`] says where.

use std::fmt::Write;

pub use persson::io::csv_number;

/// One cell of a table.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// An integer: a grid side, a count of iterations or points.
    Int(i64),
    /// A real number.
    Num(f64),
    /// A value with its (absolute) error; text shows only the digits the
    /// error supports, CSV the value alone.
    Measured {
        /// The value.
        value: f64,
        /// Its absolute error or standard error (non-negative).
        error: f64,
    },
    /// Text (a theory's name, a method).
    Text(String),
    /// No value here (printed as `–` in text, empty in CSV).
    Empty,
}

impl Cell {
    /// Whether the cell holds a number that is not finite: a quantity that
    /// could not be computed, printed as `–` in text and empty in CSV (and
    /// `null` in JSON), with a warning ([`crate::warning::not_computed`]).
    pub fn is_not_finite(&self) -> bool {
        matches!(self, Cell::Num(v) | Cell::Measured { value: v, .. } if !v.is_finite())
    }
}

impl From<f64> for Cell {
    fn from(v: f64) -> Self {
        Cell::Num(v)
    }
}

impl From<usize> for Cell {
    fn from(v: usize) -> Self {
        Cell::Int(v as i64)
    }
}

impl From<u64> for Cell {
    fn from(v: u64) -> Self {
        Cell::Int(v as i64)
    }
}

impl From<&str> for Cell {
    fn from(v: &str) -> Self {
        Cell::Text(v.to_string())
    }
}

impl From<String> for Cell {
    fn from(v: String) -> Self {
        Cell::Text(v)
    }
}

impl From<Option<f64>> for Cell {
    fn from(v: Option<f64>) -> Self {
        v.map_or(Cell::Empty, Cell::Num)
    }
}

/// A column: its machine key (CSV header, equal to the JSON key of the same
/// quantity) and its human heading.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// The key from the crate's names table (`nominal_pressure`).
    pub key: String,
    /// The heading a person reads (`σ0`, `A/A0`), with its unit if any.
    pub heading: String,
    /// Significant digits of real numbers in text.
    pub digits: usize,
    /// Whether a narrow text table may leave the column out, and in which
    /// order: lower ranks first, the leftmost first among equal ranks
    /// ([`narrow`]); `None`: always shown.
    pub omit_rank: Option<u8>,
}

/// Default significant digits of a real column in text.
pub const DEFAULT_DIGITS: usize = 6;

/// A titled table: scalars above, then one row per point.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table {
    /// File stem of its CSV, named by what it holds (`area`, `stress_G0.6`).
    pub name: String,
    /// The title line of the text output.
    pub title: String,
    /// Named scalars printed under the title: (key, heading, value).
    pub scalars: Vec<(String, String, Cell)>,
    /// The columns.
    pub columns: Vec<Column>,
    /// The rows, each as long as `columns`.
    pub rows: Vec<Vec<Cell>>,
}

/// A report that prints as one or more tables.
pub trait Tabulate {
    /// The tables, in reading order; their names are distinct.
    fn tables(&self) -> Vec<Table>;
}

impl Table {
    /// An empty table.
    pub fn new(name: impl Into<String>, title: impl Into<String>) -> Self {
        Table {
            name: name.into(),
            title: title.into(),
            ..Default::default()
        }
    }

    /// Add a column with [`DEFAULT_DIGITS`] significant digits.
    pub fn column(self, key: &str, heading: &str) -> Self {
        self.column_digits(key, heading, DEFAULT_DIGITS)
    }

    /// Add a column with `digits` significant digits.
    pub fn column_digits(mut self, key: &str, heading: &str, digits: usize) -> Self {
        self.columns.push(Column {
            key: key.into(),
            heading: heading.into(),
            digits: digits.clamp(1, 17),
            omit_rank: None,
        });
        self
    }

    /// Let a narrow text table leave out the last column added, in the order
    /// of `rank` ([`Column::omit_rank`], [`narrow`]). CSV and JSON keep it.
    pub fn omittable(mut self, rank: u8) -> Self {
        if let Some(c) = self.columns.last_mut() {
            c.omit_rank = Some(rank);
        }
        self
    }

    /// Add a scalar shown under the title.
    pub fn scalar(mut self, key: &str, heading: &str, value: impl Into<Cell>) -> Self {
        self.scalars
            .push((key.into(), heading.into(), value.into()));
        self
    }

    /// Add a row (as many cells as columns).
    pub fn push(&mut self, row: Vec<Cell>) {
        debug_assert_eq!(row.len(), self.columns.len(), "row length in {}", self.name);
        self.rows.push(row);
    }

    /// The table for a person: title, scalars, then aligned columns.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "{}", self.title);
        let width = self
            .scalars
            .iter()
            .map(|s| s.1.chars().count())
            .max()
            .unwrap_or(0);
        for (_, heading, value) in &self.scalars {
            let pad = width - heading.chars().count();
            let _ = writeln!(
                out,
                "  {heading}{}  {}",
                " ".repeat(pad),
                text_cell(value, None)
            );
        }
        if self.columns.is_empty() || self.rows.is_empty() {
            return out;
        }
        let styles: Vec<Style> = (0..self.columns.len())
            .map(|j| column_style(self.rows.iter().map(|r| &r[j]), self.columns[j].digits))
            .collect();
        let cells: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|r| {
                r.iter()
                    .zip(&styles)
                    .map(|(c, s)| text_cell(c, Some(*s)))
                    .collect()
            })
            .collect();
        let widths: Vec<usize> = (0..self.columns.len())
            .map(|j| {
                cells
                    .iter()
                    .map(|r| r[j].chars().count())
                    .chain([self.columns[j].heading.chars().count()])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        out.push('\n');
        let line = |cells: Vec<&str>| -> String {
            let parts: Vec<String> = cells
                .iter()
                .zip(&widths)
                .map(|(c, &w)| format!("{}{c}", " ".repeat(w - c.chars().count())))
                .collect();
            parts.join("  ").trim_end().to_string()
        };
        let head: Vec<&str> = self.columns.iter().map(|c| c.heading.as_str()).collect();
        let _ = writeln!(out, "{}", line(head));
        for r in &cells {
            let _ = writeln!(out, "{}", line(r.iter().map(String::as_str).collect()));
        }
        out
    }

    /// The table as CSV: one header line of keys, then one line per row;
    /// each column of reals in one form, plain digits or, where any of its
    /// values needs an exponent, all in exponent form (both the shortest that
    /// reads back to the same `f64`). Scalars are not written (they are in
    /// the JSON report) unless the table has no columns: then it is the
    /// scalars, as `key,value` lines.
    pub fn to_csv(&self) -> String {
        if self.columns.is_empty() {
            let mut s = String::from("key,value\n");
            for (key, _, value) in &self.scalars {
                s.push_str(&format!("{},{}\n", csv_escape(key), csv_cell(value, false)));
            }
            return s;
        }
        let mut s = self
            .columns
            .iter()
            .map(|c| csv_escape(&c.key))
            .collect::<Vec<_>>()
            .join(",");
        s.push('\n');
        let exponent: Vec<bool> = (0..self.columns.len())
            .map(|j| {
                self.rows.iter().any(|r| match &r[j] {
                    Cell::Num(v) | Cell::Measured { value: v, .. } => needs_exponent(*v),
                    _ => false,
                })
            })
            .collect();
        for r in &self.rows {
            let cells: Vec<String> = r
                .iter()
                .zip(&exponent)
                .map(|(c, &e)| csv_cell(c, e))
                .collect();
            s.push_str(&cells.join(","));
            s.push('\n');
        }
        s
    }
}

/// How a column of reals prints in text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Style {
    /// Fixed-point with this many decimals.
    Fixed(usize),
    /// Scientific with this many significant digits.
    Scientific(usize),
}

/// One style for a whole column: fixed-point when every non-zero value is in
/// [1e-3, 1e6) and they span at most four decades, scientific otherwise.
fn column_style<'a>(cells: impl Iterator<Item = &'a Cell>, digits: usize) -> Style {
    let mut lo = f64::INFINITY;
    let mut hi = 0.0f64;
    for c in cells {
        if let Cell::Num(v) = c {
            let a = v.abs();
            if a > 0.0 && a.is_finite() {
                lo = lo.min(a);
                hi = hi.max(a);
            }
        }
    }
    if hi == 0.0 {
        return Style::Fixed(0);
    }
    if lo >= 1e-3 && hi < 1e6 && hi / lo <= 1e4 {
        // Enough decimals for `digits` significant digits of the largest value,
        // and at least two of the smallest.
        let e_hi = hi.log10().floor() as i32;
        let e_lo = lo.log10().floor() as i32;
        let d = (digits as i32 - 1 - e_hi).max(1 - e_lo).max(0);
        Style::Fixed(d as usize)
    } else {
        Style::Scientific(digits)
    }
}

/// A cell for a person.
fn text_cell(c: &Cell, style: Option<Style>) -> String {
    match c {
        Cell::Int(i) => i.to_string(),
        Cell::Text(t) => t.clone(),
        Cell::Empty => "–".into(),
        c if c.is_not_finite() => "–".into(),
        Cell::Measured { value, error } => measured(*value, *error),
        Cell::Num(v) => match style {
            Some(Style::Fixed(d)) => format!("{v:.d$}"),
            Some(Style::Scientific(d)) => scientific(*v, d),
            None => number(*v, DEFAULT_DIGITS),
        },
    }
}

fn non_finite(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else if v > 0.0 {
        "∞".into()
    } else {
        "−∞".into()
    }
}

/// `v` with `digits` significant digits in scientific notation, mantissa
/// trailing zeros kept so a column lines up: `1.23400e-5`.
fn scientific(v: f64, digits: usize) -> String {
    let d = digits.saturating_sub(1);
    format!("{v:.d$e}")
}

/// A number for a person, in titles and scalars: at most `digits` significant
/// digits, trailing zeros dropped, fixed-point in [1e-3, 1e6), else
/// scientific: `0.6`, `12.5`, `1.333e7`, `1e-12`.
pub fn number(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return non_finite(v);
    }
    if v == 0.0 {
        return "0".into();
    }
    let digits = digits.clamp(1, 17);
    let a = v.abs();
    if (1e-3..1e6).contains(&a) {
        let e = a.log10().floor() as i32;
        let d = (digits as i32 - 1 - e).max(0) as usize;
        let s = format!("{v:.d$}");
        // Rounding may carry into a new leading digit (999.96 → 1000.0): fine.
        trim_fraction(&s)
    } else {
        let s = format!("{v:.prec$e}", prec = digits - 1);
        match s.split_once('e') {
            Some((m, e)) => format!("{}e{e}", trim_fraction(m)),
            None => s,
        }
    }
}

fn trim_fraction(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A measured value with the digits its error supports: the error to two
/// significant digits, the value to the same decimal place.
pub fn measured(value: f64, error: f64) -> String {
    if !value.is_finite() {
        return non_finite(value);
    }
    if !(error.is_finite() && error > 0.0) {
        return number(value, DEFAULT_DIGITS);
    }
    let place = error.log10().floor() as i32 - 1; // last digit kept
    if value != 0.0 && value.abs() < 1e-3 || value.abs() >= 1e6 {
        let e = value.abs().log10().floor() as i32;
        let digits = (e - place + 1).clamp(1, 17) as usize;
        return format!(
            "{} ± {}",
            number(value, digits),
            number(error, 2.min(digits).max(1))
        );
    }
    let d = (-place).max(0) as usize;
    format!("{value:.d$} ± {error:.d$}")
}

/// A cell for CSV: shortest round-trip reals (in exponent form if
/// `exponent`), integers as integers.
fn csv_cell(c: &Cell, exponent: bool) -> String {
    match c {
        Cell::Int(i) => i.to_string(),
        c if c.is_not_finite() => String::new(),
        Cell::Num(v) | Cell::Measured { value: v, .. } if exponent && v.is_finite() => {
            format!("{v:e}")
        }
        Cell::Num(v) | Cell::Measured { value: v, .. } => csv_number(*v),
        Cell::Text(t) => csv_escape(t),
        Cell::Empty => String::new(),
    }
}

/// Whether plain digits would be long for `v`: outside [1e-4, 1e16).
fn needs_exponent(v: f64) -> bool {
    let a = v.abs();
    a != 0.0 && a.is_finite() && !(1e-4..1e16).contains(&a)
}

fn csv_escape(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_for_people() {
        let cases: [(f64, usize, &str); 9] = [
            (0.6, 6, "0.6"),
            (1.333256300747068e7, 4, "1.333e7"),
            (1e-12, 6, "1e-12"),
            (2.0, 6, "2"),
            (12.5, 6, "12.5"),
            (1e4, 6, "10000"),
            (-0.00123456, 3, "-0.00123"),
            (3e8, 6, "3e8"),
            (0.0, 6, "0"),
        ];
        for (v, d, want) in cases {
            assert_eq!(number(v, d), want, "number({v}, {d})");
        }
    }

    #[test]
    fn csv_round_trips_shortest() {
        for v in [
            64.0,
            0.6,
            1e-12,
            1.333256300747068e7,
            1.0000000000000002e1,
            3e8,
            -2.5e-5,
        ] {
            let s = csv_number(v);
            assert_eq!(s.parse::<f64>().unwrap(), v, "{s}");
        }
        assert_eq!(csv_number(64.0), "64");
        assert_eq!(csv_number(1e-12), "1e-12");
        assert_eq!(csv_number(1e6), "1000000");
    }

    #[test]
    fn measured_keeps_supported_digits() {
        assert_eq!(measured(0.912345, 0.0345), "0.912 ± 0.035");
        assert_eq!(measured(1.5957691216, 0.1), "1.60 ± 0.10");
        assert_eq!(measured(2.0, 0.0), "2");
    }

    #[test]
    fn one_style_per_column() {
        let mut t = Table::new("t", "T")
            .column("nominal_pressure", "σ0")
            .column("grid", "N");
        for (p, n) in [(1e4, 32usize), (1e5, 64), (1e6, 128)] {
            t.push(vec![Cell::Num(p), Cell::from(n)]);
        }
        let text = t.to_text();
        assert!(text.contains("1.00000e4"), "{text}");
        assert!(text.contains("1.00000e6"), "{text}");
        assert!(text.contains("128"), "{text}");
        let csv = t.to_csv();
        assert_eq!(
            csv,
            "nominal_pressure,grid\n10000,32\n100000,64\n1000000,128\n"
        );
        let mut f = Table::new("f", "F").column("g", "G");
        for g in [0.5, 0.25, 0.125] {
            f.push(vec![Cell::Num(g)]);
        }
        let text = f.to_text();
        assert!(
            text.contains("0.500000") && text.contains("0.125000"),
            "{text}"
        );
    }

    #[test]
    fn csv_column_in_one_form_and_scalar_tables() {
        let mut t = Table::new("t", "T").column("stiffness", "K");
        for k in [8.085e9, 5.96e16, 0.0] {
            t.push(vec![Cell::Num(k)]);
        }
        assert_eq!(t.to_csv(), "stiffness\n8.085e9\n5.96e16\n0e0\n");
        let s = Table::new("s", "S")
            .scalar("energy_error", "η", 0.0113)
            .scalar("iterations", "iterations", 27usize);
        assert_eq!(
            s.to_csv(),
            "key,value\nenergy_error,0.0113\niterations,27\n"
        );
    }
}

#[cfg(feature = "bem")]
mod bem;
mod narrow;
#[cfg(feature = "topography")]
mod topography;

pub use narrow::{narrow, TEXT_WIDTH};

/// Significant digits that print every input as given (its shortest
/// round-trip form): `1e4`, `3e8`, `4.26e8`.
pub fn input_digits(values: impl IntoIterator<Item = f64>) -> usize {
    values
        .into_iter()
        .filter(|v| v.is_finite() && *v != 0.0)
        .map(|v| {
            let s = format!("{:e}", v.abs());
            s.split('e')
                .next()
                .unwrap_or("")
                .chars()
                .filter(char::is_ascii_digit)
                .count()
        })
        .max()
        .unwrap_or(1)
        .max(1)
}

/// The surface's description on a line of its own above a table's title (empty without one).
pub fn surface_prefix(surface: &Option<String>) -> String {
    surface.as_ref().map_or(String::new(), |s| format!("{s}\n"))
}

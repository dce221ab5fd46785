//! Header lines of text height maps: sizes, shape and units.
//!
//! Read from the header and comment lines ([`crate::io::text::Rows`]):
//! - Gwyddion's ASCII export: `# Width: 12.34 µm`, `# Height: 5678.9 nm`
//!   (the sizes along x and y), `# Value units: m`, with the labels of its
//!   translations (`Breite`/`Höhe`, `Largeur`/`Hauteur`, …);
//! - `h=305 w=75` (rows and columns), `pixel size=3.7e-7 m`,
//!   `data unit=rad` and `height conversion factor (-> m)=2.9e-8` (a map
//!   stored in another unit with its factor to metres), `x-unit`, `z-unit`.
//!
//! # References
//! Gwyddion user guide, "Export to text" (gwyddion.net/documentation).

use super::units::{LengthUnit, Unit};
use crate::io::text::{resolution, Line};

/// A length written in a header: value, unit, and one unit in its last
/// written digit (relative).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Written {
    pub value: f64,
    pub unit: Unit,
    pub relative_resolution: f64,
}

/// What a header says.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Header {
    /// Size along x (Gwyddion's width).
    pub width: Option<Written>,
    /// Size along y (Gwyddion's height).
    pub height: Option<Written>,
    /// Pixel size (square pixels).
    pub pixel_size: Option<Written>,
    /// Rows (`h=`).
    pub rows: Option<usize>,
    /// Columns (`w=`).
    pub cols: Option<usize>,
    /// The unit of the values (`Value units`, `data unit`, `z-unit`), as written.
    pub value_unit: Option<String>,
    /// Factor from the stored values to metres (`height conversion factor (-> m)`).
    pub to_metres: Option<f64>,
}

const WIDTH: &[&str] = &[
    "width",
    "breite",
    "largeur",
    "anchura",
    "larghezza",
    "largura",
    "šířka",
    "ширина",
];
const HEIGHT: &[&str] = &[
    "height",
    "höhe",
    "hauteur",
    "altura",
    "altezza",
    "výška",
    "высота",
];
const VALUE_UNITS: &[&str] = &["value units", "data unit", "z-unit", "z unit"];

/// A number and the unit written after it (`12.34 µm`).
fn written(text: &str) -> Option<Written> {
    let mut it = text.split_whitespace();
    let tok = it.next()?;
    let value = tok.parse::<f64>().ok()?;
    let unit = match it.next() {
        Some(u) => Unit::Stated(u.to_string(), LengthUnit::parse(u)?),
        None => Unit::Unstated,
    };
    let r = resolution(tok);
    Some(Written {
        value,
        unit,
        relative_resolution: if r.is_finite() && value != 0.0 {
            (r / value).abs()
        } else {
            0.0
        },
    })
}

/// `key` and `value` of `key: value` or `key = value`.
fn key_value(line: &str) -> Option<(String, &str)> {
    let k = line.find([':', '='])?;
    Some((line[..k].trim().to_lowercase(), line[k + 1..].trim()))
}

/// `name=<count>` anywhere in the line (`h=305 w=75`).
fn count(line: &str, name: &str) -> Option<usize> {
    line.split_whitespace()
        .filter_map(|w| w.split_once('='))
        .find(|(k, _)| k.eq_ignore_ascii_case(name))
        .and_then(|(_, v)| v.parse().ok())
}

/// Read every recognised field of the header and comment lines.
pub(crate) fn parse<'a>(lines: impl Iterator<Item = &'a Line>) -> Header {
    let mut h = Header::default();
    for l in lines {
        let text = l.text.trim();
        h.rows = h.rows.or_else(|| count(text, "h"));
        h.cols = h.cols.or_else(|| count(text, "w"));
        let Some((key, value)) = key_value(text) else {
            continue;
        };
        if WIDTH.contains(&key.as_str()) {
            h.width = h.width.take().or_else(|| written(value));
        } else if HEIGHT.contains(&key.as_str()) {
            h.height = h.height.take().or_else(|| written(value));
        } else if key == "pixel size" {
            h.pixel_size = written(value);
        } else if VALUE_UNITS.contains(&key.as_str()) {
            h.value_unit = value.split_whitespace().next().map(str::to_string);
        } else if let Some(unit) = key
            .strip_prefix("height conversion factor (->")
            .and_then(|r| r.strip_suffix(')'))
        {
            if let (Some(u), Ok(f)) = (LengthUnit::parse(unit), value.parse::<f64>()) {
                h.to_metres = Some(f * u.metres());
            }
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(t: &[&str]) -> Vec<Line> {
        t.iter()
            .enumerate()
            .map(|(k, s)| Line {
                line: k + 1,
                text: s.to_string(),
            })
            .collect()
    }

    #[test]
    fn gwyddion_and_h_w_headers() {
        let h = parse(
            lines(&[
                "Kanal: My Channel Name",
                "Breite: 12.34 µm",
                "Höhe: 5678.9 nm",
                "Value units: m",
            ])
            .iter(),
        );
        let w = h.width.unwrap();
        assert_eq!(w.value, 12.34);
        assert_eq!(w.unit, Unit::of(LengthUnit::Micrometre));
        assert!((w.relative_resolution - 0.01 / 12.34).abs() < 1e-15);
        assert_eq!(h.height.unwrap().value, 5678.9);
        assert_eq!(h.value_unit.as_deref(), Some("m"));
        let h = parse(
            lines(&[
                "h=305 w=75",
                "pixel size=3.69862e-007 m",
                "data unit=rad",
                "height conversion factor (-> m)=2.91818e-008",
            ])
            .iter(),
        );
        assert_eq!((h.rows, h.cols), (Some(305), Some(75)));
        assert_eq!(h.pixel_size.unwrap().value, 3.69862e-7);
        assert_eq!(h.value_unit.as_deref(), Some("rad"));
        assert_eq!(h.to_metres, Some(2.91818e-8));
    }
}

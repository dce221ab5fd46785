//! The text tables the friction inputs come in (a DMA master curve, a Prony
//! series, a shift-factor table): rows of numbers, `#` comments.
//!
//! Cells are separated by commas, semicolons, tabs or spaces; blank lines and
//! lines starting with `#` are skipped; the first non-comment line may be a
//! header (skipped when it starts with a letter and a cell is not a number).
//! Every error names the file, its 1-based line and the column's field.

use std::path::Path;

use crate::error::{Error, Result};

/// One data row and its 1-based line in the file.
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// The numbers, one per column.
    pub values: Vec<f64>,
    /// 1-based line.
    pub line: usize,
}

/// Parse rows with between `names.len() - optional` and `names.len()` columns;
/// `names` name the columns in messages.
pub(crate) fn parse_rows(
    path: &Path,
    bytes: &[u8],
    names: &[&str],
    optional: usize,
) -> Result<Vec<Row>> {
    let text = std::str::from_utf8(bytes)
        .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
    let (min, max) = (names.len() - optional, names.len());
    let mut rows = Vec::new();
    let mut first = true;
    for (n, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let cells: Vec<&str> = line
            .split(|ch: char| ch == ',' || ch == ';' || ch.is_whitespace())
            .filter(|s| !s.is_empty())
            .collect();
        let header = first
            && cells.iter().any(|c| c.parse::<f64>().is_err())
            && line.starts_with(|ch: char| ch.is_alphabetic());
        first = false;
        if header {
            continue;
        }
        if cells.len() < min || cells.len() > max {
            let want = if min == max {
                format!("{max}")
            } else {
                format!("{min} to {max}")
            };
            return Err(Error::parse(
                path,
                n + 1,
                0,
                format!(
                    "expected {want} columns ({}), found {}",
                    names.join(", "),
                    cells.len()
                ),
            ));
        }
        let mut values = Vec::with_capacity(cells.len());
        for (j, cell) in cells.iter().enumerate() {
            let v = cell.parse::<f64>().map_err(|_| {
                let col = raw.find(cell).map_or(0, |c| c + 1);
                Error::parse(
                    path,
                    n + 1,
                    col,
                    format!("{}: '{cell}' is not a number", names[j]),
                )
            })?;
            values.push(v);
        }
        rows.push(Row {
            values,
            line: n + 1,
        });
    }
    if rows.is_empty() {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("no data rows (expected columns {})", names.join(", ")),
        ));
    }
    Ok(rows)
}

/// An [`Error::Parse`] at `row`'s line about the value of column `col`.
pub(crate) fn cell_error(
    path: &Path,
    row: &Row,
    name: &str,
    value: f64,
    requirement: &str,
) -> Error {
    Error::parse(
        path,
        row.line,
        0,
        format!(
            "{name} = {}: must be {requirement}",
            crate::error::num(value)
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_comments_and_separators() {
        let text = "# DMA export\nomega, E', E''\n1 2 3\n\n# mid comment\n4;5\t6\n";
        let rows = parse_rows(Path::new("x"), text.as_bytes(), &["a", "b", "c"], 0).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[1].values, vec![4.0, 5.0, 6.0]);
        assert_eq!(rows[1].line, 6);
    }

    #[test]
    fn errors_name_line_and_field() {
        let e = parse_rows(Path::new("f.txt"), b"1 2 3\n1 x 3\n", &["a", "b", "c"], 0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("f.txt:2:3") && e.contains("b: 'x'"), "{e}");
        let e = parse_rows(Path::new("f.txt"), b"1 2\n", &["a", "b", "c"], 0)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("f.txt:1") && e.contains("expected 3 columns"),
            "{e}"
        );
        assert!(parse_rows(Path::new("f"), b"# only\n", &["a"], 0).is_err());
    }
}

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
pub(crate) use crate::io::text::Row;

/// Parse rows with between `names.len() - optional` and `names.len()` columns
/// ([`crate::io::text::columns`]); `names` name the columns in messages.
pub(crate) fn parse_rows(
    path: &Path,
    bytes: &[u8],
    names: &[&str],
    optional: usize,
) -> Result<Vec<Row>> {
    let text = std::str::from_utf8(bytes)
        .map_err(|e| Error::parse(path, 0, 0, format!("not UTF-8 text ({e})")))?;
    crate::io::text::columns(path, text, names, optional)
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

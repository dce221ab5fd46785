//! Text tables that fit a width: a long title wrapped at spaces, then the
//! columns a table marks as omittable ([`super::Table::omittable`]) left out
//! until it fits, with a line naming them. Only the text changes: CSV and
//! JSON keep every column.

use super::{Cell, Table};

/// Width in characters that the default text tables of the wide reports
/// (`persson compare`, `persson bem` with a yield stress) fit.
pub const TEXT_WIDTH: usize = 100;

/// Widest line of a table's text.
fn text_width(t: &Table) -> usize {
    t.to_text()
        .lines()
        .map(|l| l.chars().count())
        .max()
        .unwrap_or(0)
}

/// A title longer than `width` wrapped at spaces, its continuation lines
/// indented by two.
fn wrap_title(title: &str, width: usize) -> String {
    if title.chars().count() <= width {
        return title.to_string();
    }
    let mut lines = vec![String::new()];
    for word in title.split(' ') {
        let last = lines.last_mut().expect("one line");
        if !last.is_empty() && last.chars().count() + 1 + word.chars().count() > width {
            lines.push(format!("  {word}"));
        } else {
            if !last.is_empty() {
                last.push(' ');
            }
            last.push_str(word);
        }
    }
    lines.join("\n")
}

/// The next column to leave out: the lowest [`super::Column::omit_rank`],
/// the leftmost among equal ranks; `None` when none is left.
fn next_omitted(t: &Table) -> Option<usize> {
    let rank = t.columns.iter().filter_map(|c| c.omit_rank).min()?;
    t.columns.iter().position(|c| c.omit_rank == Some(rank))
}

/// Fit a table's text into `width` characters: a long title wrapped at
/// spaces, then its omittable columns left out, lowest rank first and the
/// leftmost first within a rank, until it fits; the headings left out are
/// named in a scalar `omitted` headed `note` (e.g. how to show them).
///
/// # Examples
/// ```
/// use persson_studies::table::{narrow, Table};
/// let mut t = Table::new("t", "A table")
///     .column("a", "a")
///     .column("b", "a long heading b")
///     .omittable(0);
/// t.push(vec![1.0.into(), 2.0.into()]);
/// narrow(&mut t, 10, "not shown");
/// assert_eq!(t.columns.len(), 1);
/// assert!(t.to_text().contains("not shown  a long heading b"));
/// ```
pub fn narrow(t: &mut Table, width: usize, note: &str) {
    t.title = wrap_title(&t.title, width);
    let mut dropped = Vec::new();
    while text_width(t) > width {
        let Some(j) = next_omitted(t) else { break };
        dropped.push(t.columns.remove(j).heading);
        for r in &mut t.rows {
            r.remove(j);
        }
    }
    if !dropped.is_empty() {
        t.scalars.push((
            "omitted".into(),
            note.into(),
            Cell::Text(dropped.join(", ")),
        ));
    }
}

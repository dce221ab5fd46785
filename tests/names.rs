//! One name per quantity: the names table `src/names.md` is published
//! verbatim in the user guide (`docs/conventions.md`); every JSON key the
//! `persson` binary prints is a name of that table (or one of the few
//! container keys allowed below), which `crates/persson-cli/tests/names.rs`
//! checks.
#![cfg(feature = "bem")]

use std::collections::BTreeSet;

/// The one source of names.
const NAMES: &str = include_str!("../src/names.md");
const GUIDE: &str = include_str!("../docs/conventions.md");

/// Keys that hold other values rather than name a quantity. Keep this list
/// short: a quantity belongs in `src/names.md`, not here.
const CONTAINERS: &[&str] = &[
    "points",   // the rows of a curve (area, magnification, separation, BEM)
    "tables",   // the tables of a report
    "spectrum", // the spectrum echoed by a report or a scene
    "material", // the material echoed by a report or a scene
    "outputs",  // a scene's outputs, keyed by the output names below
    // The output names of a scene file (the keys of its "outputs").
    "area",
    "magnification",
    "kappa",
    "theories",
    "separation",
    "stress",
    "bem",
    "bem_hertz",
    // Keys whose value is a label from a closed set, spelled as on the command
    // line (CONTRACT: theory, boundary, start, convention).
    "theory",
    "boundary",
    "start",
    "convention",
    "method",
    // Text for people: a scene's name and description, a surface's origin.
    "name",
    "description",
    "surface",
    // Lists and groups of rows.
    "curves",
    "rows",
    "table",
    "cases",
    "families",
    "per_grid",
    "extrapolated",
    "pressure_distribution",
    "theory_curve",
    "fit",
    "power_law_fit",
];

/// Prefixes of a quantity set beside the same quantity from elsewhere.
const PREFIXES: &[&str] = &["bem_", "theory_"];

/// Suffixes of an error of the quantity they follow (`g_error_bound`).
const ERROR_SUFFIXES: &[&str] = &["_error_bound", "_standard_error", "_error"];

/// The names of `src/names.md`: every `backticked` word of its name column
/// (the fourth), without the pattern `<quantity>_error_bound`.
fn names() -> BTreeSet<String> {
    let mut header = None;
    let mut names = BTreeSet::new();
    for line in NAMES.lines().filter(|l| l.trim_start().starts_with('|')) {
        let cells: Vec<&str> = line.trim().trim_matches('|').split('|').collect();
        let Some(column) = header else {
            header = cells.iter().position(|c| c.trim().starts_with("name"));
            assert!(header.is_some(), "src/names.md: no `name` column in {line}");
            continue;
        };
        let cell = cells.get(column).copied().unwrap_or_default();
        for (i, word) in cell.split('`').enumerate() {
            if i % 2 == 1 && !word.contains('<') {
                names.insert(word.to_string());
            }
        }
    }
    names
}

/// Is `key` a published name, an error bound of one, or an allowed container?
fn allowed(key: &str, names: &BTreeSet<String>) -> bool {
    let named = |k: &str| {
        names.contains(k)
            || PREFIXES
                .iter()
                .any(|p| k.strip_prefix(p).is_some_and(|q| names.contains(q)))
    };
    named(key)
        || CONTAINERS.contains(&key)
        || ERROR_SUFFIXES
            .iter()
            .any(|s| key.strip_suffix(s).is_some_and(named))
}

#[test]
fn names_table_parses() {
    let names = names();
    for name in [
        "contact_modulus",
        "nominal_pressure",
        "contact_fraction",
        "zeta",
        "tolerance",
    ] {
        assert!(names.contains(name), "src/names.md lost `{name}`");
    }
    assert!(
        !names.contains("--contact-modulus"),
        "the flag column was read as names"
    );
    assert!(allowed("g_error_bound", &names));
    assert!(!allowed("complement", &names));
    assert!(!allowed("nonsense_error_bound", &names));
}

#[test]
fn guide_has_the_names_table() {
    let table = NAMES.trim();
    assert!(
        GUIDE.contains(table),
        "docs/conventions.md must contain src/names.md verbatim (in its \"## Names\" section)"
    );
}

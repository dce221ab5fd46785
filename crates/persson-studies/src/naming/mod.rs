//! How an error names its input: the scene's field under its section
//! (`outputs.area.zeta`, `spectrum.hurst`), the names the command line maps
//! to its flags; and the studies' closed sets of names ([`names`]: the
//! convention of a spectrum file, a length unit, the stress start, the area
//! theory, the kind of surrogate), which `input` re-exports.

use persson::error::Error;

pub mod names;

/// A missing input.
pub fn required(what: &str) -> Error {
    Error::Inconsistent {
        name: what.to_string(),
        requirement: "missing (required for this calculation)".into(),
    }
}

/// An invalid parameter named `from` renamed `to` (the field a library
/// function's argument is in the spec); any other error unchanged.
pub(crate) fn rename(e: Error, from: &str, to: &str) -> Error {
    match e {
        Error::InvalidParameter {
            name,
            value,
            requirement,
        } if name == from => Error::InvalidParameter {
            name: to.into(),
            value,
            requirement,
        },
        e => e,
    }
}

/// Prefix the parameter name of an error with its section.
pub fn prefix(section: &str, e: Error) -> Error {
    match e {
        Error::InvalidParameter {
            name,
            value,
            requirement,
        } => Error::InvalidParameter {
            name: placed(section, &name),
            value,
            requirement,
        },
        Error::Inconsistent { name, requirement } => Error::Inconsistent {
            name: placed(section, &name),
            requirement,
        },
        other => other,
    }
}

/// `name` as the scene's field under `section`: each field of a list
/// (`a, b and c`) prefixed, unless already placed (under `section`, another
/// output, or a top-level field); a name in words (`number of spectrum
/// points`) keeps its words with the section after it.
fn placed(section: &str, name: &str) -> String {
    let field = |f: &str| {
        !f.is_empty()
            && f.chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || "_.[]".contains(c))
    };
    let is_placed = |f: &str| {
        f.starts_with(section)
            || f.starts_with("outputs.")
            || TOP_LEVEL.iter().any(|t| {
                f == *t || f.starts_with(&format!("{t}.")) || f.starts_with(&format!("{t}["))
            })
    };
    // `fields (a remark)`: the fields before the remark.
    let (head, remark) = match name.find(" (") {
        Some(i) => name.split_at(i),
        None => (name, ""),
    };
    // A name in words already placed under a section (`… (rubber)`) stays.
    let tag = remark.trim_start_matches(" (").trim_end_matches(')');
    if !head.split([',', '/']).all(|p| field(p.trim())) && is_placed(&format!("{tag}.")) {
        return name.to_string();
    }
    let parts: Vec<&str> = head
        .split([',', '/'])
        .flat_map(|p| p.split(" and "))
        .flat_map(|p| p.split(" or "))
        .map(str::trim)
        .collect();
    if parts.iter().all(|p| field(p)) {
        let mut out = head.to_string();
        for p in parts.iter().filter(|p| !is_placed(p)) {
            out = replace_word(&out, p, &format!("{section}{p}"));
        }
        out + remark
    } else {
        format!("{name} ({})", section.trim_end_matches('.'))
    }
}

/// `text` with the whole word `word` replaced by `with`.
fn replace_word(text: &str, word: &str, with: &str) -> String {
    let mut out = String::with_capacity(text.len() + with.len());
    let mut rest = text;
    while let Some(i) = rest.find(word) {
        let before = rest[..i].chars().next_back();
        let after = rest[i + word.len()..].chars().next();
        let boundary =
            |c: Option<char>| c.is_none_or(|c| !(c.is_alphanumeric() || c == '_' || c == '.'));
        out.push_str(&rest[..i]);
        if boundary(before) && boundary(after) {
            out.push_str(with);
        } else {
            out.push_str(word);
        }
        rest = &rest[i + word.len()..];
    }
    out.push_str(rest);
    out
}

/// A scene's fields outside `outputs`, named as they are wherever an error
/// arises (`nominal_pressure`, not `outputs.bem.nominal_pressure`).
const TOP_LEVEL: [&str; 4] = ["nominal_pressure", "material", "spectrum", "rubber"];

//! Which flag an error of the library is about. The library names the
//! field it refuses by its snake_case name (`tolerance`, `work_of_adhesion`,
//! `gap_table[3]`, `standard_linear_solid.relaxation_time`); the command
//! line spells the same field as the flag whose argument id is that name
//! (`--tolerance`). [`name_flag`] prefixes the error with that flag when the
//! user gave it, so every command names its flags without a table of its own.

use clap::parser::ValueSource;
use clap::{ArgMatches, Command};

/// `e` prefixed with the flags of the fields it names (`--tolerance:
/// invalid tolerance = 0: …`): for an invalid value, the flag the user gave
/// with that id; for fields that are missing or contradict each other
/// (`mean_gap or approach`), every flag of the innermost subcommand of `m`
/// with one of their ids. `e` unchanged when none matches.
pub fn name_flag(cmd: &Command, m: &ArgMatches, e: anyhow::Error) -> anyhow::Error {
    let Some(pe) = e.downcast_ref::<persson::Error>() else {
        return e;
    };
    let (cmd, m) = innermost(cmd, m);
    let (names, only_given) = match pe {
        persson::Error::InvalidParameter { name, .. } => (vec![field(name)], true),
        persson::Error::Inconsistent { name, .. } => (fields(name), false),
        _ => return e,
    };
    let flags: Vec<String> = names
        .iter()
        .map(|f| {
            ALIASES
                .iter()
                .find(|(k, _)| k == f)
                .map_or(*f, |(_, id)| *id)
        })
        .filter_map(|f| {
            cmd.get_arguments().find(|a| {
                a.get_id().as_str() == f
                    && (!only_given
                        || m.value_source(a.get_id().as_str()) == Some(ValueSource::CommandLine))
            })
        })
        .filter_map(|a| a.get_long().map(|l| format!("--{l}")))
        .collect();
    match flags.is_empty() {
        true => e,
        false => anyhow::anyhow!("{}: {e}", flags.join(", ")),
    }
}

/// Fields whose flag has another name (the names table of the numerics:
/// the JSON key `nominal_pressure` is the flag `--pressure`).
const ALIASES: [(&str, &str); 1] = [("nominal_pressure", "pressure")];

/// The argument id of a field's name, without an index or a sub-field
/// (`gap_table[3]` → `gap_table`, `standard_linear_solid.tau` →
/// `standard_linear_solid`).
fn field(name: &str) -> &str {
    let end = name.find(['[', '.', ' ']).unwrap_or(name.len());
    &name[..end]
}

/// The fields of a list of names (`mean_gap or approach`, `a, b and c`).
fn fields(name: &str) -> Vec<&str> {
    let head = name.split(" (").next().unwrap_or(name);
    head.split([',', '/'])
        .flat_map(|p| p.split(" and "))
        .flat_map(|p| p.split(" or "))
        .map(|p| field(p.trim()))
        .filter(|p| !p.is_empty())
        .collect()
}

/// The deepest subcommand given and its matches (`bem rough`).
pub fn innermost<'a>(cmd: &'a Command, m: &'a ArgMatches) -> (&'a Command, &'a ArgMatches) {
    match m.subcommand() {
        Some((name, sub)) => match cmd.find_subcommand(name) {
            Some(c) => innermost(c, sub),
            None => (cmd, m),
        },
        None => (cmd, m),
    }
}

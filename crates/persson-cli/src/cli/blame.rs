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
        persson::Error::InvalidParameter { name, .. } => (vec![name.as_str()], true),
        persson::Error::Inconsistent { name, .. } => (fields(name), false),
        _ => return e,
    };
    let given = |id: &str| m.value_source(id) == Some(ValueSource::CommandLine);
    let mut flags: Vec<String> = Vec::new();
    for name in names {
        let flag = ids(name).into_iter().find_map(|id| {
            cmd.get_arguments()
                .find(|a| a.get_id().as_str() == id && (!only_given || given(&id)))
                .and_then(|a| a.get_long())
        });
        if let Some(long) = flag {
            let f = format!("--{long}");
            if !flags.contains(&f) {
                flags.push(f);
            }
        }
    }
    match flags.is_empty() {
        true => e,
        false => anyhow::anyhow!("{}: {e}", flags.join(", ")),
    }
}

/// Fields whose flag has another name: the names table's JSON key
/// `nominal_pressure` is the flag `--pressure`, and `stress --flat`'s
/// `--pressure` is its start's peak pressure.
const ALIASES: [(&str, &str); 2] = [
    ("nominal_pressure", "pressure"),
    ("peak_pressure", "pressure"),
];

/// The argument ids a field's name may be spelled by here, most specific
/// first: `ball.radius` → `ball_radius`, `radius`, `ball`; `gap_table[3]` →
/// `gap_table`; then its alias, if any.
fn ids(name: &str) -> Vec<String> {
    let name = name.split('[').next().unwrap_or(name);
    let mut out = vec![name.replace('.', "_")];
    if let Some((first, rest)) = name.split_once('.') {
        out.push(rest.rsplit('.').next().unwrap_or(rest).to_string());
        out.push(first.to_string());
    }
    let aliases: Vec<String> = out
        .iter()
        .flat_map(|id| {
            ALIASES
                .iter()
                .filter(move |(k, _)| k == id)
                .map(|(_, a)| a.to_string())
        })
        .collect();
    out.extend(aliases);
    out
}

/// The fields of a list of names (`mean_gap or approach`, `a, b and c`).
fn fields(name: &str) -> Vec<&str> {
    let head = name.split(" (").next().unwrap_or(name);
    head.split([',', '/'])
        .flat_map(|p| p.split(" and "))
        .flat_map(|p| p.split(" or "))
        .map(str::trim)
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

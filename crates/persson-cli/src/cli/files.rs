//! The files of a command line. Every flag that names a file has one of
//! three types: [`InFile`] (read), [`OutFile`] (written) or [`OutDir`] (a
//! folder written into). [`plan`] walks the parsed command line once,
//! before anything is computed, and hands every path to the one output
//! layer ([`persson_studies::output::Files`]): an output onto an input or
//! onto another output, of a format its extension does not name, or in a
//! folder that does not accept it, is refused there, naming both flags. A
//! new flag of one of these types is covered without another line.
//!
//! An output flag whose value name lists extensions (`FILE.svg|png`,
//! `FILE.csv|npy`) picks its format by extension: the file must end in
//! one of them.

use std::path::{Path, PathBuf};

use clap::ArgMatches;
use persson_studies::output::Files;

macro_rules! path_type {
    ($(#[$doc:meta])* $name:ident, $parse:ident) => {
        $(#[$doc])*
        #[derive(Debug, Clone, PartialEq, Eq)]
        pub struct $name(PathBuf);

        impl std::ops::Deref for $name {
            type Target = Path;
            fn deref(&self) -> &Path {
                &self.0
            }
        }

        impl AsRef<Path> for $name {
            fn as_ref(&self) -> &Path {
                &self.0
            }
        }

        impl From<$name> for PathBuf {
            fn from(p: $name) -> PathBuf {
                p.0
            }
        }

        /// clap's value parser: a non-empty path.
        pub fn $parse(s: &str) -> Result<$name, String> {
            if s.is_empty() {
                return Err("an empty file name".into());
            }
            Ok($name(PathBuf::from(s)))
        }
    };
}

path_type!(
    /// A file the command reads.
    InFile,
    in_file
);
path_type!(
    /// A file the command writes.
    OutFile,
    out_file
);
path_type!(
    /// A folder the command writes into (created if missing).
    OutDir,
    out_dir
);

/// Declare every input and reserve every output of the parsed command
/// line `m` of `cmd` (module docs): the inputs first, so that an output
/// given before an input is checked against it too.
///
/// # Errors
/// The output layer's refusal, naming the flags; a plot in a build
/// without the feature `plot`.
pub fn plan(cmd: &clap::Command, m: &ArgMatches, files: &mut Files) -> anyhow::Result<()> {
    let (cmd, m) = super::blame::innermost(cmd, m);
    for arg in cmd.get_arguments() {
        let id = arg.get_id().as_str();
        if let Ok(Some(values)) = m.try_get_many::<InFile>(id) {
            for v in values {
                files.input(&flag(arg), v)?;
            }
        }
    }
    for arg in cmd.get_arguments() {
        let id = arg.get_id().as_str();
        let formats = formats(arg);
        if let Ok(Some(values)) = m.try_get_many::<OutFile>(id) {
            for v in values {
                if cfg!(not(feature = "plot")) && formats.contains(&"svg") {
                    anyhow::bail!(
                        "{} {}: this persson was built without the `plot` feature",
                        flag(arg),
                        v.display()
                    );
                }
                files.reserve(&flag(arg), v, &formats)?;
            }
        }
        if let Ok(Some(values)) = m.try_get_many::<OutDir>(id) {
            for v in values {
                files.folder(&flag(arg), v)?;
            }
        }
    }
    Ok(())
}

/// How the user spelled an argument: `--plot`, or `SCENE` for a positional one.
pub fn flag(arg: &clap::Arg) -> String {
    match arg.get_long() {
        Some(l) => format!("--{l}"),
        None => arg
            .get_value_names()
            .and_then(|v| v.first())
            .map_or_else(|| arg.get_id().to_string(), |v| v.to_string()),
    }
}

/// The extensions a value name such as `FILE.svg|png` lists (none without `|`).
pub fn formats(arg: &clap::Arg) -> Vec<&'static str> {
    let Some(name) = arg.get_value_names().and_then(|v| v.first()) else {
        return Vec::new();
    };
    let name: &str = name.as_str();
    if !name.contains('|') {
        return Vec::new();
    }
    let list = name.split_once('.').map_or("", |(_, exts)| exts);
    KNOWN
        .iter()
        .copied()
        .filter(|e| list.split('|').any(|x| x.eq_ignore_ascii_case(e)))
        .collect()
}

/// Every extension an output's format can be chosen by.
const KNOWN: &[&str] = &["svg", "png", "csv", "npy"];

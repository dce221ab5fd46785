//! The `persson` command-line tool: a thin layer over the library.

use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::{CommandFactory, FromArgMatches};

fn main() -> ExitCode {
    let parsed = persson_cli::Cli::command()
        .try_get_matches()
        .and_then(|m| persson_cli::Cli::from_arg_matches(&m).map(|cli| (cli, m)));
    let (cli, matches) = match parsed {
        Ok(parsed) => parsed,
        Err(e) => return usage_error(&e),
    };
    match persson_cli::run(cli, &matches) {
        Ok(()) => ExitCode::SUCCESS,
        // A closed pipe (`persson … | head`) is not an error of ours.
        Err(e)
            if e.root_cause()
                .downcast_ref::<std::io::Error>()
                .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe) =>
        {
            ExitCode::SUCCESS
        }
        Err(e) => {
            // One line, no backtrace (even with RUST_BACKTRACE set): exit code 2.
            match e.downcast_ref::<persson::Error>() {
                Some(pe) => eprintln!("persson: error: {pe}"),
                None => eprintln!("persson: error: {e:#}"),
            }
            ExitCode::from(2)
        }
    }
}

/// A command line clap could not parse: one line `persson: error: …` and
/// the usage hint after it, exit code 2. `--help`, `--version` and a bare
/// `persson` print as clap does.
fn usage_error(e: &clap::Error) -> ExitCode {
    if matches!(
        e.kind(),
        ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        let _ = e.print();
        return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
    }
    let text = e.render().to_string();
    let (message, usage) = split_usage(&text);
    eprintln!("persson: error: {message}");
    match usage {
        Some(usage) => eprintln!("{usage} (more: --help)"),
        None => {
            // The (sub)subcommand: `bem rough`, `report accuracy`, `compare kappa`.
            let words: Vec<String> = std::env::args()
                .skip(1)
                .take_while(|a| !a.starts_with('-'))
                .take(2)
                .collect();
            let depth = match words.as_slice() {
                [a, b]
                    if matches!(
                        (a.as_str(), b.as_str()),
                        ("bem", "hertz" | "rough")
                            | ("report", "accuracy" | "stability")
                            | ("compare", "kappa")
                    ) =>
                {
                    2
                }
                _ => words.len().min(1),
            };
            let sub: String = words[..depth].iter().map(|w| format!("{w} ")).collect();
            eprintln!("Usage: persson {sub}--help");
        }
    }
    ExitCode::from(2)
}

/// clap's message on one line (its list items and tips joined) and its usage line.
fn split_usage(text: &str) -> (String, Option<String>) {
    let mut one = String::new();
    let mut usage = None;
    for raw in text.lines() {
        let line = raw.trim();
        if let Some(u) = line.strip_prefix("Usage:") {
            usage = Some(format!("Usage: {}", u.trim()));
            break;
        }
        let line = line.strip_prefix("error:").unwrap_or(line).trim();
        if line.is_empty() || line.starts_with("For more information") {
            continue;
        }
        if !one.is_empty() {
            let item = raw.starts_with(' ') && !line.starts_with("tip:");
            one.push_str(match (one.ends_with(':'), item) {
                (true, _) => " ",
                (false, true) => ", ",
                (false, false) => "; ",
            });
        }
        one.push_str(line);
    }
    (one, usage)
}

/// Items of one feature, gated once for the group (as tokio's `cfg_rt!`).
macro_rules! cfg_feature {
    ($feature:literal, $($item:item)*) => {
        $( #[cfg(feature = $feature)] $item )*
    };
}

#[path = "cli/mod.rs"]
mod persson_cli;

//! The `persson` command-line tool: a thin layer over the library.

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let cli = persson_cli::Cli::parse();
    match persson_cli::run(cli) {
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

#[path = "cli/mod.rs"]
mod persson_cli;

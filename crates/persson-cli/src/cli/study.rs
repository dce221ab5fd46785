//! A subcommand that is a study: run it, stage the files its spec names,
//! print its report with its warnings.

use std::path::Path;

use persson_studies::output::Files;
use persson_studies::study::{Context, Study};

use super::output::{print_warned, Format};

/// Run the study `S` with `spec` in `ctx`; its files (paths as given on the
/// command line) are staged into `files`.
pub fn run<S: Study>(
    ctx: &Context<'_>,
    spec: &S::Spec,
    files: &mut Files,
    format: &Format,
) -> anyhow::Result<()> {
    let report = S::run(ctx, spec)?;
    S::write(spec, &report, ctx, Path::new(""), files)?;
    print_warned(&report, &S::warnings(&report), format)
}

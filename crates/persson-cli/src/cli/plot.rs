//! `--plot FILE.svg|png`, flattened into every subcommand that has a curve,
//! and [`draw`], which stages a figure for any output flag.
//!
//! The file was checked before anything was computed ([`super::files`]);
//! after computing, a subcommand draws its figure:
//! ```text
//! a.plot.draw(files, || persson_studies::scene::plot::area(&report))?;
//! ```

use std::path::Path;

use super::files::{out_file, OutFile};

/// The `--plot` flag.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct PlotArg {
    /// Also draw the curve into this file (.svg or .png, 800×560).
    #[arg(long, value_name = "FILE.svg|png", value_parser = out_file)]
    pub plot: Option<OutFile>,
}

impl PlotArg {
    /// Stages the figure made by `build` for the `--plot` file, if given.
    pub fn draw<F: persson_studies::plot::Encode>(
        &self,
        files: &mut persson_studies::output::Files,
        build: impl FnOnce() -> persson::Result<F>,
    ) -> anyhow::Result<()> {
        draw(files, self.plot.as_deref(), build)
    }
}

/// Stages the figure made by `build` for `path`, if given (the format by
/// its extension); written when the whole command has succeeded.
pub fn draw<F: persson_studies::plot::Encode>(
    files: &mut persson_studies::output::Files,
    path: Option<&Path>,
    build: impl FnOnce() -> persson::Result<F>,
) -> anyhow::Result<()> {
    if let Some(p) = path {
        files.write(p, &build()?.encode(p)?)?;
    }
    Ok(())
}

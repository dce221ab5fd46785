//! `persson anisotropy` in a build without the feature `topography`.

use super::Args;

/// Without the feature `topography`, an error.
pub fn run(_: Args, _: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    Err(crate::persson_cli::features::left_out("topography"))
}

//! `--plot FILE.svg|png`, flattened into every subcommand that has a curve.
//!
//! Pattern (see `area.rs`): add `#[command(flatten)] plot: super::plot::PlotArg`
//! to the arguments, then after computing
//! ```text
//! #[cfg(feature = "plot")]
//! a.plot.draw(|| persson_studies::plot::area_vs_load(...))?;
//! #[cfg(not(feature = "plot"))]
//! a.plot.unavailable()?;
//! ```

use std::path::PathBuf;

/// The `--plot` flag.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct PlotArg {
    /// Also draw the curve into this file (.svg or .png, 800×560).
    #[arg(long, value_name = "FILE.svg|png")]
    pub plot: Option<PathBuf>,
}

impl PlotArg {
    /// Before computing: the `--plot` file has a supported extension and its
    /// directory accepts a new file.
    pub fn check(&self) -> anyhow::Result<()> {
        if let Some(path) = &self.plot {
            #[cfg(feature = "plot")]
            persson_studies::plot::Format::from_path(path)?;
            #[cfg(not(feature = "plot"))]
            self.unavailable()?;
            persson::io::check_writable(path)?;
        }
        Ok(())
    }

    /// Renders the figure made by `build` into the `--plot` file, if given.
    #[cfg(feature = "plot")]
    pub fn draw(
        &self,
        build: impl FnOnce() -> persson::Result<persson_studies::plot::Figure>,
    ) -> anyhow::Result<()> {
        if let Some(path) = &self.plot {
            persson_studies::plot::render(&build()?, path)?;
        }
        Ok(())
    }

    /// In a build without the `plot` feature, `--plot` is an error.
    #[cfg(not(feature = "plot"))]
    pub fn unavailable(&self) -> anyhow::Result<()> {
        match &self.plot {
            Some(p) => anyhow::bail!(
                "--plot {}: this persson was built without the `plot` feature",
                p.display()
            ),
            None => Ok(()),
        }
    }
}

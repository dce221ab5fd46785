//! A measured surface as a scene's (and the flags') spectrum: read, condition
//! and analyse the map ([`persson::topography`]), then use its binned spectrum
//! as a [`Tabulated`] one, whose band is the map's. Without the feature
//! `topography` the reading is left out and asking for it is an error.

use persson::error::{Error, Result};
use persson::spectrum::Spectrum;

use super::HeightMapSpec;

#[cfg_attr(not(feature = "topography"), path = "off.rs")]
mod read;
#[cfg(feature = "topography")]
pub use read::describe;

impl HeightMapSpec {
    /// The map's spectrum as a boxed [`Spectrum`].
    ///
    /// # Errors
    /// As [`HeightMapSpec::spectrum_described`].
    pub fn spectrum(&self) -> Result<Box<dyn Spectrum>> {
        Ok(Box::new(self.spectrum_described()?.value))
    }
}

/// An error of reading or analysing `file`, prefixed with the file unless
/// it names it.
pub(crate) fn in_file(file: &std::path::Path, e: Error) -> Error {
    let name = file.display().to_string();
    if e.to_string().contains(&name) {
        e
    } else {
        Error::parse(file, 0, 0, e.to_string())
    }
}

//! A measured surface in a build without the feature `topography`.

use persson::error::{Error, Result};
use persson::spectrum::Tabulated;

use crate::input::{Described, HeightMapSpec};

impl HeightMapSpec {
    /// Without the `topography` feature no file is read: no dataset.
    pub fn dataset_measurements(&self) -> Result<Option<Vec<HeightMapSpec>>> {
        Ok(None)
    }

    /// Without the `topography` feature a measured surface cannot be read.
    pub fn spectrum_described(&self) -> Result<Described<Tabulated>> {
        Err(Error::Inconsistent {
            name: "kind = height_map".into(),
            requirement:
                "a spectrum from a height map needs persson built with the feature `topography`"
                    .into(),
        })
    }
}

//! Figures in a build without the feature `plot`: each is still built
//! from its report, and encoding it is an error naming the feature (a scene
//! asking for a plot is refused before anything is computed,
//! [`crate::scene::Scene::plan`]).

use std::path::Path;

use crate::plot::map::MapFigure;
use crate::plot::spectrum_map::SpectrumMapFigure;
use crate::plot::stress_map::FieldFigure;
use crate::plot::{Encode, Figure};
use crate::{Error, Result};

fn left_out(path: &Path) -> Error {
    Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::new(
            std::io::ErrorKind::Unsupported,
            "plots need persson built with the feature `plot`",
        ),
    }
}

macro_rules! left_out {
    ($($figure:ty),*) => {$(
        impl Encode for $figure {
            fn encode(&self, path: &Path) -> Result<Vec<u8>> {
                Err(left_out(path))
            }
        }
    )*};
}

left_out!(Figure, [Figure], MapFigure, SpectrumMapFigure, FieldFigure);

impl<const N: usize> Encode for [Figure; N] {
    fn encode(&self, path: &Path) -> Result<Vec<u8>> {
        Err(left_out(path))
    }
}

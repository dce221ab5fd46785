//! The figures drawn with the plotting library (feature `plot`): line
//! figures laid out first ([`prepare`]) and drawn ([`draw`]), stacked
//! panels ([`stack`]), and the maps drawn straight on a backend
//! ([`canvas`]).

use std::path::Path;

use crate::plot::{Encode, Figure, Format};
use crate::{Error, Result};

mod canvas;
mod draw;
mod map;
mod prepare;
mod spectrum_map;
mod stack;
mod stress_map;
mod ticks;

impl Encode for Figure {
    fn encode(&self, path: &Path) -> Result<Vec<u8>> {
        let format = Format::from_path(path)?;
        draw::ensure_font(path)?;
        match format {
            Format::Svg => {
                let prepared = prepare::prepare(self, 1, &draw::measure)?;
                let svg = draw::svg_string(&prepared).map_err(|e| backend_error(path, e))?;
                Ok(svg.into_bytes())
            }
            Format::Png => {
                // Drawn at k× the size (fonts and lines scale along) and
                // averaged down: anti-aliased lines and text.
                let k = draw::supersampling(self.size);
                let big = (self.size.0 * k, self.size.1 * k);
                let prepared = prepare::prepare(self, k, &draw::measure)?;
                let pixels = draw::rgb_pixels(&prepared).map_err(|e| backend_error(path, e))?;
                let pixels = draw::downsample(&pixels, big, k);
                draw::png_bytes(self.size, &pixels).map_err(|source| Error::Io {
                    path: path.to_path_buf(),
                    source,
                })
            }
        }
    }
}

fn backend_error(path: &Path, message: String) -> Error {
    Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(format!("plot rendering failed: {message}")),
    }
}

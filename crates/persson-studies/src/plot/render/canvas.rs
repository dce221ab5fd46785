//! The figures drawn straight on a plotters backend (the pressure map, the
//! 2-D spectrum, the stress maps): one way to write them to `.svg` or `.png`.
//!
//! Line figures go through [`super::prepare`] first; these figures have no
//! layout step, so each implements [`Canvas`] (validate, then draw at `k`
//! times its size) and [`encode_canvas`] does the rest: the format from the
//! extension, the font check and PNG supersampling, into the file's bytes
//! ([`crate::plot::Encode`]).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{backend_error, draw};
use crate::plot::Format;
use crate::{Error, Result};

/// What drawing on a backend `DB` returns.
pub(crate) type DrawResult<DB> =
    std::result::Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// A figure that draws itself on any plotters backend.
pub(crate) trait Canvas {
    /// Size in pixels, width × height.
    fn size(&self) -> (u32, u32);
    /// Checks the figure's data before anything is drawn or written.
    fn check(&self) -> Result<()>;
    /// Draws the figure on `root`, at `k` times its size (fonts and lines
    /// scale along).
    fn draw_on<DB: DrawingBackend>(&self, root: DrawingArea<DB, Shift>, k: u32) -> DrawResult<DB>;
}

/// [`crate::plot::Encode`] and [`Canvas`] for a figure type with a `size`
/// field, an inherent `check` and a function `draw(root, &fig, k)`.
macro_rules! canvas_figure {
    ($figure:ty, $draw:ident) => {
        impl crate::plot::Encode for $figure {
            fn encode(&self, path: &std::path::Path) -> crate::Result<Vec<u8>> {
                super::canvas::encode_canvas(self, path)
            }
        }

        impl super::canvas::Canvas for $figure {
            fn size(&self) -> (u32, u32) {
                self.size
            }
            fn check(&self) -> crate::Result<()> {
                <$figure>::check(self)
            }
            fn draw_on<DB: plotters::prelude::DrawingBackend>(
                &self,
                root: plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
                k: u32,
            ) -> super::canvas::DrawResult<DB> {
                $draw(root, self, k)
            }
        }
    };
}
pub(crate) use canvas_figure;

/// The bytes of `fig` as the `.svg` or `.png` file `path` (by extension).
///
/// # Errors
/// [`Error::Io`] for another extension or a backend failure;
/// [`Error::InvalidParameter`] for a size outside [`crate::plot::SIZE_LIMITS`];
/// the figure's own [`Canvas::check`] errors.
pub(crate) fn encode_canvas<C: Canvas>(fig: &C, path: &Path) -> Result<Vec<u8>> {
    let format = Format::from_path(path)?;
    check_size(fig.size())?;
    fig.check()?;
    draw::ensure_font(path)?;
    let size = fig.size();
    match format {
        Format::Svg => Ok(svg_string(fig)
            .map_err(|e| backend_error(path, e))?
            .into_bytes()),
        Format::Png => {
            // Drawn at k× the size and averaged down: anti-aliased.
            let k = draw::supersampling(size);
            let big = (size.0 * k, size.1 * k);
            let mut buf = vec![255u8; big.0 as usize * big.1 as usize * 3];
            {
                let root = BitMapBackend::with_buffer(&mut buf, big).into_drawing_area();
                fig.draw_on(root, k)
                    .map_err(|e| backend_error(path, e.to_string()))?;
            }
            let pixels = draw::downsample(&buf, big, k);
            draw::png_bytes(size, &pixels).map_err(|source| Error::Io {
                path: path.to_path_buf(),
                source,
            })
        }
    }
}

/// Both sides within [`crate::plot::SIZE_LIMITS`].
fn check_size(size: (u32, u32)) -> Result<()> {
    let (lo, hi) = crate::plot::SIZE_LIMITS;
    for v in [size.0, size.1] {
        if !(lo..=hi).contains(&v) {
            return Err(Error::invalid(
                "plot size",
                v as f64,
                format!("between {lo} and {hi} pixels"),
            ));
        }
    }
    Ok(())
}

fn svg_string<C: Canvas>(fig: &C) -> std::result::Result<String, String> {
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, fig.size()).into_drawing_area();
        fig.draw_on(root, 1).map_err(|e| e.to_string())?;
    }
    Ok(s)
}

//! Figures stacked one above the other in one file (panels sharing their
//! width, e.g. μ(v) above A/A0(v)).

use std::path::Path;

use super::{backend_error, draw, prepare};
use crate::plot::{Encode, Figure, Format};
use crate::{Error, Result};

/// Figures one above the other in one file (SVG or PNG by extension); every
/// figure must have the same width.
///
/// # Errors
/// As [`Figure`]'s [`Encode::encode`]; [`Error::Inconsistent`] for no
/// figure or figures of different widths.
impl Encode for [Figure] {
    fn encode(&self, path: &Path) -> Result<Vec<u8>> {
        stacked(self, path)
    }
}

impl<const N: usize> Encode for [Figure; N] {
    fn encode(&self, path: &Path) -> Result<Vec<u8>> {
        stacked(self, path)
    }
}

fn stacked(figs: &[Figure], path: &Path) -> Result<Vec<u8>> {
    let Some(first) = figs.first() else {
        return Err(Error::Inconsistent {
            name: "figures".into(),
            requirement: "at least one panel".into(),
        });
    };
    let width = first.size.0;
    if figs.iter().any(|f| f.size.0 != width) {
        return Err(Error::Inconsistent {
            name: "figures".into(),
            requirement: "panels of one width".into(),
        });
    }
    let format = Format::from_path(path)?;
    draw::ensure_font(path)?;
    let height: u32 = figs.iter().map(|f| f.size.1).sum();
    match format {
        Format::Svg => {
            let mut svg = format!(
                "<svg width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\" \
                 xmlns=\"http://www.w3.org/2000/svg\">\n"
            );
            let mut y = 0;
            for f in figs {
                let p = prepare::prepare(f, 1, &draw::measure)?;
                let inner = draw::svg_string(&p).map_err(|e| backend_error(path, e))?;
                let body = inner.find("<svg").map_or(inner.as_str(), |i| &inner[i..]);
                svg.push_str(&body.replacen("<svg", &format!("<svg y=\"{y}\""), 1));
                svg.push('\n');
                y += f.size.1;
            }
            svg.push_str("</svg>\n");
            Ok(svg.into_bytes())
        }
        Format::Png => {
            let mut rgb = Vec::with_capacity(width as usize * height as usize * 3);
            for f in figs {
                let k = draw::supersampling(f.size);
                let big = (f.size.0 * k, f.size.1 * k);
                let p = prepare::prepare(f, k, &draw::measure)?;
                let pixels = draw::rgb_pixels(&p).map_err(|e| backend_error(path, e))?;
                rgb.extend(draw::downsample(&pixels, big, k));
            }
            draw::png_bytes((width, height), &rgb).map_err(|source| Error::Io {
                path: path.to_path_buf(),
                source,
            })
        }
    }
}

//! Figures drawn from the typed reports alone (feature `plot`).

use crate::plot::{self, Figure};
use persson::error::Result;

pub use crate::area::figure as area;
#[cfg(feature = "bem")]
pub use crate::bem::figures::{bem, patch_areas, subsurface_profiles};
pub use crate::friction::figure as friction;
pub use crate::magnification::{magnification_area, magnification_g};
pub use crate::separation::figure as separation;
pub use crate::spectrum::figure as spectrum;
#[cfg(feature = "topography")]
pub use crate::spectrum::measured_spectrum;
pub use crate::stress::figure as stress;
pub use crate::theories::figure as theories;
pub use crate::transport::{conductance_figure as conductance, leakage_figure as leakage};

/// The spectra of several measurements and their combination (log–log):
/// each measurement's binned spectrum over its band, the combined one on top.
///
/// # Errors
/// A spectrum with no positive point.
pub fn multi_scale(r: &crate::input::multiscale::MultiScaleReport) -> Result<Figure> {
    let mut fig = plot::spectrum(&r.q, &r.c, None)?;
    fig.title = format!(
        "Power spectrum C(q) combined from {} measurements",
        r.measurements.len()
    );
    if let Some(first) = fig.series.first_mut() {
        first.label = "combined".into();
    }
    for m in &r.measurements {
        let name = m
            .file
            .file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_default();
        fig.push(plot::Series::from_xy(name, &m.psd.q, &m.psd.c)?.with_style(plot::Style::Markers));
    }
    Ok(fig)
}

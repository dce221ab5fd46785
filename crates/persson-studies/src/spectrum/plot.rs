//! The figure of `spectrum` (feature `plot`).

use persson::error::Result;

use crate::plot::{self, Figure, PowerLaw};

use super::*;

/// C(q) with the fitted power law over its band.
///
/// # Errors
/// An inconsistent report.
pub fn spectrum(r: &SpectrumReport) -> Result<Figure> {
    let (q, c): (Vec<f64>, Vec<f64>) = r.curve.iter().map(|p| (p.q, p.c)).unzip();
    let law = PowerLaw {
        prefactor: r.power_law_fit.prefactor,
        exponent: r.power_law_fit.exponent,
        q_range: Some((r.power_law_fit.q_min, r.power_law_fit.q_max)),
    };
    plot::spectrum(&q, &c, Some(law))
}

/// C(q) of a measured surface with its Hurst fit over the band.
///
/// # Errors
/// An inconsistent report.
#[cfg(feature = "topography")]
pub fn measured_spectrum(a: &persson::topography::Analysis) -> Result<Figure> {
    let law = a.fit.map(|f| crate::plot::PowerLaw {
        prefactor: f.prefactor,
        exponent: -2.0 * (f.hurst + 1.0),
        q_range: Some((a.q_min, a.q_max)),
    });
    let mut fig = plot::spectrum(&a.psd.q, &a.psd.c, law)?;
    fig.title = match a.fit {
        Some(f) => format!(
            "Power spectrum C(q) of the measured surface, H = {} ± {}",
            crate::table::number(f.hurst, 3),
            crate::table::number(f.hurst_error, 2)
        ),
        None => "Power spectrum C(q) of the measured surface (no Hurst fit)".into(),
    };
    Ok(fig)
}

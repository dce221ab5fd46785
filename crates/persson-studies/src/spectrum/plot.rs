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

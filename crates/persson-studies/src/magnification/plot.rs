//! The figures of `magnification` (feature `plot`).

use persson::error::Result;

use crate::plot::{self, Figure};
use crate::table::number;

use super::*;

/// A/A0 against ζ.
///
/// # Errors
/// An inconsistent report.
pub fn magnification_area(r: &MagnificationReport) -> Result<Figure> {
    let z: Vec<f64> = r.points.iter().map(|x| x.zeta).collect();
    let a: Vec<f64> = r.points.iter().map(|x| x.contact_fraction).collect();
    let label = format!("σ0 = {}", number(r.nominal_pressure, 6));
    plot::area_vs_zeta(&z, &[(label.as_str(), &a)])
}

/// G(ζ).
///
/// # Errors
/// An inconsistent report.
pub fn magnification_g(r: &MagnificationReport) -> Result<Figure> {
    let z: Vec<f64> = r.points.iter().map(|x| x.zeta).collect();
    let g: Vec<f64> = r.points.iter().map(|x| x.g).collect();
    let label = format!("σ0 = {}", number(r.nominal_pressure, 6));
    plot::g_vs_zeta(&z, &[(label.as_str(), &g)])
}

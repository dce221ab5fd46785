//! The figures of `separation` (feature `plot`).

use persson::error::Result;

use crate::plot::{Axis, Figure, Series};
use crate::table::number;

use super::*;

/// ū against load (the report's figure curve, else its points), log axes,
/// with the low-load law u0 ln(p_ref/σ0).
///
/// # Errors
/// None in practice (the figure is built from the report's numbers).
pub fn separation(r: &SeparationReport) -> Result<Figure> {
    let curve = if r.plot_points.is_empty() {
        &r.points
    } else {
        &r.plot_points
    };
    let u: Vec<(f64, f64)> = curve
        .iter()
        .map(|p| (p.nominal_pressure, p.mean_separation))
        .collect();
    let (u0, p_ref) = (r.low_load_length, r.reference_pressure);
    let asymptote: Vec<(f64, f64)> = curve
        .iter()
        .map(|p| (p.nominal_pressure, u0 * (p_ref / p.nominal_pressure).ln()))
        .filter(|&(_, v)| v > 0.0)
        .collect();
    Ok(Figure::new(
        format!(
            "Mean interfacial separation (Persson 2007), E* = {}",
            number(r.contact_modulus, 4)
        ),
        Axis::log("nominal pressure σ0 (unit of E*)"),
        Axis::log("mean separation ū (m)"),
    )
    .with_series(Series::line("ū(σ0)", u))
    .with_series(Series::dashed(
        format!(
            "u0 ln(σ_ref/σ0), u0 = {} m, σ_ref = {}",
            number(u0, 3),
            number(p_ref, 3)
        ),
        asymptote,
    )))
}

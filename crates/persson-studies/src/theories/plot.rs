//! The figures of `theories` (feature `plot`).

use persson::error::Result;

use crate::plot::{self, Figure, LinearLaw};
use crate::table::number;

use super::*;

/// A/A0 against load for every theory, with the linear laws.
///
/// # Errors
/// An inconsistent report.
pub fn theories(r: &TheoriesReport) -> Result<Figure> {
    let p: Vec<f64> = r
        .curves
        .first()
        .map(|c| c.points.iter().map(|x| x.nominal_pressure).collect())
        .unwrap_or_default();
    let labels: Vec<String> = r
        .curves
        .iter()
        .map(|c| match c.gamma {
            None => format!("{} (κ = {})", c.theory, number(c.kappa, 3)),
            Some(g) => format!(
                "{}, γ = {} (κ = {})",
                c.theory,
                number(g, 3),
                number(c.kappa, 3)
            ),
        })
        .collect();
    let a: Vec<Vec<f64>> = r
        .curves
        .iter()
        .map(|c| c.points.iter().map(|x| x.contact_fraction).collect())
        .collect();
    let refs: Vec<(&str, &[f64])> = labels
        .iter()
        .zip(&a)
        .map(|(l, v)| (l.as_str(), v.as_slice()))
        .collect();
    let law = LinearLaw {
        contact_modulus: r.contact_modulus,
        rms_slope: r.rms_slope,
    };
    plot::area_vs_load(&p, &refs, "unit of E*", Some(law))
}

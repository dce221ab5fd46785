//! The figure of `area` (feature `plot`).

use persson::error::Result;

use super::AreaReport;
use crate::input::TheoryName;
use crate::plot::{self, Figure, LinearLaw};
use crate::table::number;

/// A/A0 against load with the Bush and Persson lines; a corrected theory
/// is drawn next to the original one.
///
/// # Errors
/// An empty report.
pub fn area(r: &AreaReport) -> Result<Figure> {
    let p: Vec<f64> = r.points.iter().map(|x| x.nominal_pressure).collect();
    let chosen: Vec<f64> = r.points.iter().map(|x| x.contact_fraction).collect();
    let label = format!("Persson (original theory), ζ = {}", number(r.zeta, 4));
    let other = format!(
        "{} theory{}",
        r.theory,
        r.gamma
            .map_or(String::new(), |g| format!(", γ = {}", number(g, 3)))
    );
    let mut curves = vec![(label.as_str(), r.original_contact_fraction.as_slice())];
    if r.theory != TheoryName::Original {
        curves.push((other.as_str(), chosen.as_slice()));
    }
    let law = LinearLaw {
        contact_modulus: r.contact_modulus,
        rms_slope: r.points.first().map_or(r.rms_slope, |x| x.rms_slope),
    };
    plot::area_vs_load(&p, &curves, "unit of E*", Some(law))
}

//! The figures of `friction` (feature `plot`): μ(v) and A/A0(v).

use persson::error::Result;

use super::FrictionReport;
use crate::plot::{Axis, Figure, Series};
use crate::table::number;

/// Rubber friction: μ against log v (top) and A/A0 against log v (bottom),
/// one curve per (T, σ0), dashed with the flash temperature.
///
/// # Errors
/// An empty report.
pub fn friction(r: &FrictionReport) -> Result<[Figure; 2]> {
    let mut mu = Figure::new(
        "Rubber friction μ(v)",
        Axis::log("sliding velocity v (m/s)"),
        Axis::linear("friction coefficient μ"),
    );
    let mut area = Figure::new(
        "Contact area at q1",
        Axis::log("sliding velocity v (m/s)"),
        Axis::log("contact fraction A/A0"),
    );
    let mut groups: Vec<(f64, f64)> = Vec::new();
    for p in &r.points {
        if !groups.contains(&(p.temperature, p.nominal_pressure)) {
            groups.push((p.temperature, p.nominal_pressure));
        }
    }
    for (t, s) in groups {
        let pts: Vec<_> = r
            .points
            .iter()
            .filter(|p| p.temperature == t && p.nominal_pressure == s)
            .collect();
        let label = format!("T = {} K, σ0 = {} Pa", number(t, 5), number(s, 4));
        let iso = |f: fn(&persson::friction::FrictionResult) -> f64| -> Vec<(f64, f64)> {
            pts.iter().map(|p| (p.velocity, f(&p.isothermal))).collect()
        };
        mu.push(Series::line(label.clone(), iso(|x| x.friction_coefficient)));
        area.push(Series::line(label.clone(), iso(|x| x.contact_fraction)));
        let flash = |f: fn(&persson::friction::FrictionResult) -> f64| -> Vec<(f64, f64)> {
            pts.iter()
                .filter_map(|p| p.flash.as_ref().map(|x| (p.velocity, f(x))))
                .collect()
        };
        let fm = flash(|x| x.friction_coefficient);
        if !fm.is_empty() {
            let l = format!("{label}, flash temperature");
            mu.push(Series::dashed(l.clone(), fm));
            area.push(Series::dashed(l, flash(|x| x.contact_fraction)));
        }
    }
    Ok([mu, area])
}

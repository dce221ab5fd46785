//! The figure of `stress` (feature `plot`).

use persson::error::Result;

use crate::plot::{Axis, Figure, Series, Style};
use crate::table::number;

use super::*;

/// The family of stress distributions.
///
/// # Errors
/// None in practice.
pub fn stress(r: &StressReport) -> Result<Figure> {
    // With a yield stress the legend gives A = A_el + A_pl.
    let plastic = r.yield_stress.is_some() || r.yield_ratio.is_some();
    let plastic_note = |el: f64, pl: f64| {
        if plastic || pl > 0.0 {
            format!(" (A_el {}, A_pl {})", number(el, 3), number(pl, 3))
        } else {
            String::new()
        }
    };
    let (x, y) = if r.physical() {
        ("normal stress σ (Pa, or the unit of E*)", "P(σ, ζ) (1/Pa)")
    } else {
        ("normal stress σ/σH", "σH P(σ, ζ)")
    };
    let yield_note = match (r.yield_stress, r.yield_ratio) {
        (Some(y), _) => format!(", σY = {}", number(y, 4)),
        (None, Some(y)) => format!(", σY/σH = {}", number(y, 4)),
        _ => String::new(),
    };
    let mut fig = Figure::new(
        format!("Stress distribution P(σ, ζ), {} start{yield_note}", r.start),
        Axis::linear(x),
        Axis::linear(y),
    );
    let styles = [Style::Line, Style::Dashed, Style::Dotted];
    for (i, c) in r.curves.iter().enumerate() {
        let (label, s, p) = match c.zeta {
            Some(z) => (
                format!(
                    "ζ = {}, G = {}, A/A0 = {}{}",
                    number(z, 6),
                    number(c.g, 3),
                    number(c.contact_fraction, 3),
                    plastic_note(c.elastic_fraction, c.plastic_fraction)
                ),
                &c.sigma,
                &c.density,
            ),
            None => (
                format!(
                    "G = {}, A/A0 = {}{}",
                    number(c.g, 6),
                    number(c.contact_fraction, 3),
                    plastic_note(c.elastic_fraction, c.plastic_fraction)
                ),
                &c.sigma_ratio,
                &c.scaled_density,
            ),
        };
        // A flat start at G = 0 is a δ at σ0: nothing finite to draw.
        let pts = s
            .iter()
            .copied()
            .zip(p.iter().copied())
            .filter(|p| p.1.is_finite())
            .collect();
        fig.push(Series::new(label, pts, styles[i % styles.len()]));
    }
    // σY marked by a grey vertical line over the height of the curves (the
    // plastic part A_pl/A0 is the δ at σ = σY, not drawn).
    let at = match (r.yield_stress, r.yield_ratio) {
        (Some(y), _) => Some((y, format!("σY = {}", number(y, 4)))),
        (None, Some(y)) => Some((y, format!("σY/σH = {}", number(y, 4)))),
        _ => None,
    };
    if let Some((y, label)) = at {
        let top = r
            .curves
            .iter()
            .flat_map(|c| c.density.iter().chain(&c.scaled_density))
            .copied()
            .filter(|p| p.is_finite())
            .fold(0.0f64, f64::max);
        if top > 0.0 {
            fig.push(
                Series::new(label, vec![(y, 0.0), (y, top)], Style::Dashed)
                    .with_color(crate::plot::Rgb(128, 128, 128)),
            );
        }
    }
    Ok(fig)
}

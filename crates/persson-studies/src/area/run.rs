//! The load curve of a contact-area theory.

use persson::corrected;
use persson::error::{Error, Result};
use persson::kappa::Kappa;

use super::{AreaOutput, AreaReport, LoadPoint};
use crate::contact::RoughContact;
use crate::input::{TheoryName, TheorySpec};
use crate::naming::required;

/// A/A0 against the nominal pressures (`area`).
///
/// # Errors
/// A pressure not finite and positive; ζ < 1; γ invalid; solver failure.
pub fn area(surface: &RoughContact, pressures: &[f64], out: &AreaOutput) -> Result<AreaReport> {
    if pressures.is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.area)",
        ));
    }
    if out.theory.is_asperity() {
        return super::asperity::area(surface, pressures, out);
    }
    if out.yield_stress.is_some() {
        return Err(Error::Inconsistent {
            name: "yield_stress".into(),
            requirement: "only with the overlap theory (the hardness of its load law)".into(),
        });
    }
    let model = surface.model()?;
    let zeta = out.zeta.unwrap_or_else(|| model.zeta_max());
    let theory = TheorySpec {
        theory: out.theory,
        gamma: out.gamma,
    }
    .build()?;
    let tolerance = out.tolerance.unwrap_or(corrected::DEFAULT_TOLERANCE);
    let points = model.load_curve(pressures, zeta)?;
    let chosen = corrected::load_curve(&model, theory, zeta, pressures, tolerance)?;
    let original = out.theory == TheoryName::Original;
    let (q_l, q_s) = surface.band();
    Ok(AreaReport {
        warnings: surface.warnings(pressures, &[zeta]),
        surface: surface.description.clone(),
        contact_modulus: surface.contact_modulus,
        rms_height: surface.spectrum.rms_height(q_l, q_s)?.value,
        rms_slope: surface.spectrum.rms_slope(q_l, q_s)?.value,
        kappa_bush: Kappa::Bush.value(),
        kappa_persson: Kappa::Persson.value(),
        theory: out.theory,
        gamma: theory.gamma(),
        kappa: Some(theory.low_load_kappa()),
        yield_stress: None,
        asperity: None,
        zeta,
        original_contact_fraction: points.iter().map(|p| p.contact_fraction).collect(),
        points: points
            .iter()
            .zip(&chosen)
            .map(|(p, c)| LoadPoint::new(p, c, original))
            .collect(),
    })
}

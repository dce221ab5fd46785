//! The computation of `separation`.

use persson::error::Result;
use persson::separation::Separation;

use crate::contact::RoughContact;
use crate::naming::required;

use super::*;

/// Mean separation, stiffness and energy against load (`separation`);
/// `plot_pressures` adds a curve for a figure.
///
/// # Errors
/// A pressure not finite and positive; a tolerance out of range; an integral
/// that does not converge.
pub fn separation(
    surface: &RoughContact,
    pressures: &[f64],
    out: &SeparationOutput,
    plot_pressures: &[f64],
) -> Result<SeparationReport> {
    if pressures.is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.separation)",
        ));
    }
    let tolerance = out
        .tolerance
        .unwrap_or(persson::separation::DEFAULT_TOLERANCE);
    let model = Separation::new(surface.spectrum.as_ref(), surface.contact_modulus)?
        .with_tolerance(tolerance)?
        .with_breaks(&surface.breaks);
    let points = model.load_curve(pressures)?;
    let law = model.low_load_law()?;
    let full = model.full_contact_energy()?;
    let (q_l, q_s) = surface.band();
    Ok(SeparationReport {
        warnings: surface.warnings(pressures, &[]),
        surface: surface.description.clone(),
        contact_modulus: surface.contact_modulus,
        rms_height: surface.spectrum.rms_height(q_l, q_s)?.value,
        rms_slope: surface.spectrum.rms_slope(q_l, q_s)?.value,
        tolerance,
        low_load_length: law.length.value,
        low_load_length_error_bound: law.length.error,
        reference_pressure: law.reference_pressure.value,
        reference_pressure_error_bound: law.reference_pressure.error,
        full_contact_energy: full.value,
        full_contact_energy_error_bound: full.error,
        points,
        plot_points: if plot_pressures.is_empty() {
            vec![]
        } else {
            model.load_curve(plot_pressures)?
        },
    })
}

//! The computation of `magnification`.

use persson::error::Result;
use persson::theory::log_zetas;

use crate::contact::RoughContact;
use crate::study::check_points;

use super::*;

/// G(ζ) and A/A0 against magnification (`magnification`).
///
/// # Errors
/// ζ < 1; a pressure not finite and positive.
pub fn magnification(
    surface: &RoughContact,
    out: &MagnificationOutput,
) -> Result<MagnificationReport> {
    let model = surface.model()?;
    let zeta = if out.zeta.is_empty() {
        check_points(out.points)?;
        log_zetas(model.zeta_max(), out.points)
    } else {
        out.zeta.clone()
    };
    Ok(MagnificationReport {
        warnings: surface.warnings(&[out.nominal_pressure], &zeta),
        surface: surface.description.clone(),
        nominal_pressure: out.nominal_pressure,
        contact_modulus: surface.contact_modulus,
        zeta_max: model.zeta_max(),
        points: model.magnification_curve(&zeta, out.nominal_pressure)?,
    })
}

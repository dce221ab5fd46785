//! The computation of `theories`.

use persson::corrected;
use persson::error::Result;

use crate::contact::RoughContact;
use crate::input::TheorySpec;
use crate::naming::required;

use super::*;

/// A/A0 against load for several theories (`theories`).
///
/// # Errors
/// As [`corrected::load_curve`].
pub fn theories(
    surface: &RoughContact,
    pressures: &[f64],
    out: &TheoriesOutput,
) -> Result<TheoriesReport> {
    if pressures.is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.theories)",
        ));
    }
    let model = surface.model()?;
    let zeta = out.zeta.unwrap_or_else(|| model.zeta_max());
    let tolerance = out.tolerance.unwrap_or(corrected::DEFAULT_TOLERANCE);
    let list = if out.theories.is_empty() {
        TheorySpec::all()
    } else {
        out.theories.clone()
    };
    let curves = list
        .iter()
        .map(|spec| {
            let th = spec.build()?;
            Ok(TheoryCurve {
                theory: spec.theory,
                gamma: th.gamma(),
                kappa: th.low_load_kappa(),
                points: corrected::load_curve(&model, th, zeta, pressures, tolerance)?,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(TheoriesReport {
        warnings: surface.warnings(pressures, &[zeta]),
        contact_modulus: surface.contact_modulus,
        zeta,
        rms_slope: model.slope_variance(zeta)?.value.sqrt(),
        curves,
    })
}

//! The computation of `kappa`.

use persson::error::{check, Result};
use persson::kappa::Kappa;

use crate::contact::RoughContact;

use super::*;

/// κ of both laws and, with a surface and pressures, the linear fractions (`kappa`).
///
/// # Errors
/// A pressure not finite and positive.
pub fn kappa(surface: Option<(&RoughContact, &[f64])>) -> Result<KappaReport> {
    let mut r = KappaReport {
        surface: surface.and_then(|(s, _)| s.description.clone()),
        kappa_bush: Kappa::Bush.value(),
        kappa_persson: Kappa::Persson.value(),
        rms_slope: None,
        points: vec![],
        warnings: vec![],
    };
    if let Some((s, pressures)) = surface {
        r.warnings = s.warnings(pressures, &[]);
        let (q_l, q_s) = s.band();
        let slope = s.spectrum.rms_slope(q_l, q_s)?.value;
        r.rms_slope = Some(slope);
        for &p in pressures {
            check::positive("nominal_pressure", p)?;
            r.points.push(LinearPoint {
                nominal_pressure: p,
                contact_fraction_bush_linear: Kappa::Bush.checked_linear_fraction(
                    p,
                    s.contact_modulus,
                    slope,
                )?,
                contact_fraction_persson_linear: Kappa::Persson.checked_linear_fraction(
                    p,
                    s.contact_modulus,
                    slope,
                )?,
            });
        }
    }
    Ok(r)
}

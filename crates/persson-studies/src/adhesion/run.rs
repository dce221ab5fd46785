//! Computing the `adhesion` output (and `persson adhesion`): the stickiness
//! balance of [`persson::adhesion`] per magnification, the Pastewka–Robbins
//! criterion when the adhesion range is given, and the adhesive contact at
//! each nominal pressure (tension allowed); the numerics' typed flags become
//! warnings here.

use persson::adhesion::{AdhesionModel, AdhesiveContact, AdhesivePoint, Flag};
use persson::error::{check, Error, Result};
use persson::theory::log_zetas;

use super::{AdhesionOutput, AdhesionReport};
use crate::contact::RoughContact;
use crate::warning::{self, Warning};

/// Default number of log-spaced ζ of the stickiness balance.
pub const DEFAULT_STICKINESS_POINTS: usize = 11;
/// Default absolute tolerance of the adhesive contact fractions (the numerics' default).
pub const DEFAULT_TOLERANCE: f64 = 1e-5;

/// The adhesion report for `surface` at the nominal pressures `pressures`
/// (Pa or the unit of E*; ≤ 0 allowed, may be empty: the stickiness balance only).
///
/// # Errors
/// A work of adhesion negative or not finite (`work_of_adhesion`); a pressure
/// not finite (`nominal_pressure`); ζ outside [1, q_s/q_l] (`zeta`); fewer
/// than 2 points (`points`); a range not positive (`adhesion_range`, or a
/// zero work of adhesion with a range); a tolerance out of [1e-15, 0.1];
/// quadrature failure of a function spectrum.
pub fn adhesion(
    surface: &RoughContact,
    pressures: &[f64],
    out: &AdhesionOutput,
) -> Result<AdhesionReport> {
    for &p in pressures {
        if !p.is_finite() {
            return Err(Error::invalid("nominal_pressure", p, "finite"));
        }
    }
    let enhancement = out.area_enhancement.unwrap_or_default();
    let model = AdhesionModel::new(
        surface.spectrum.as_ref(),
        surface.contact_modulus,
        out.work_of_adhesion,
    )?
    .with_area_enhancement(enhancement);
    let zeta_max = model.zeta_max();
    let zeta = out.zeta.unwrap_or(zeta_max);
    if !(zeta.is_finite() && zeta >= 1.0 && zeta <= zeta_max * (1.0 + 1e-12)) {
        return Err(Error::invalid(
            "zeta",
            zeta,
            format!("in [1, q_s/q_l = {zeta_max:e}]"),
        ));
    }
    let points = out.points.unwrap_or(DEFAULT_STICKINESS_POINTS);
    if points < 2 {
        return Err(Error::invalid("points", points as f64, "at least 2"));
    }
    let tolerance = out.tolerance.unwrap_or(DEFAULT_TOLERANCE);
    let contact = AdhesiveContact::new(model).with_tolerance(tolerance)?;
    let stickiness = model.stickiness(&log_zetas(zeta_max, points))?;
    let pastewka_robbins = out
        .adhesion_range
        .map(|r| {
            check::positive("adhesion_range", r)?;
            model.pastewka_robbins(r)
        })
        .transpose()?;
    let curve = contact.load_curve(pressures, zeta)?;
    let pull = model.pull_off_stress()?;
    let (q_l, q_s) = (surface.spectrum.q_min(), surface.spectrum.q_max());
    let mut warnings = surface.warnings.clone();
    let positive: Vec<f64> = pressures.iter().copied().filter(|p| *p > 0.0).collect();
    warning::push(
        &mut warnings,
        Warning::high_pressure(&positive, surface.contact_modulus),
    );
    for w in flag_warnings(&curve, tolerance) {
        warning::push(&mut warnings, Some(w));
    }
    if let Some(pr) = pastewka_robbins.as_ref().filter(|pr| !pr.short_range) {
        warning::push(
            &mut warnings,
            Some(
                Warning::LongAdhesionRange {
                    adhesion_range: pr.adhesion_range,
                    rms_slope: pr.rms_slope,
                    rms_curvature: pr.rms_curvature,
                    message: String::new(),
                }
                .described(describe),
            ),
        );
    }
    Ok(AdhesionReport {
        surface: surface.description.clone(),
        contact_modulus: surface.contact_modulus,
        work_of_adhesion: out.work_of_adhesion,
        area_enhancement: enhancement,
        rms_slope: surface.spectrum.rms_slope(q_l, q_s)?.value,
        zeta: zeta.min(zeta_max),
        tolerance,
        pull_off_stress: pull.value,
        pull_off_stress_error_bound: pull.error,
        stickiness,
        pastewka_robbins,
        points: curve,
        warnings,
    })
}

/// The warnings of the points' flags: tensions beyond pull-off, tolerances not met.
fn flag_warnings(points: &[AdhesivePoint], tolerance: f64) -> Vec<Warning> {
    let mut out = Vec::new();
    let detached: Vec<&AdhesivePoint> = points
        .iter()
        .filter(|p| p.flags.contains(&Flag::Detached))
        .collect();
    if let Some(first) = detached
        .iter()
        .max_by(|a, b| a.nominal_pressure.total_cmp(&b.nominal_pressure))
    {
        out.push(
            Warning::BeyondPullOff {
                nominal_pressure: first.nominal_pressure,
                pull_off_stress: first.pull_off_stress,
                count: detached.len(),
                message: String::new(),
            }
            .described(describe),
        );
    }
    let missed: Vec<&AdhesivePoint> = points
        .iter()
        .filter(|p| p.flags.contains(&Flag::ToleranceNotMet))
        .collect();
    if !missed.is_empty() {
        let worst = missed
            .iter()
            .map(|p| {
                p.contact_fraction_error_bound
                    .max(p.tensile_fraction_error_bound)
            })
            .fold(0.0, f64::max);
        out.push(
            Warning::AdhesionToleranceNotMet {
                tolerance,
                error_bound: worst,
                count: missed.len(),
                message: String::new(),
            }
            .described(describe),
        );
    }
    out
}

/// The text of the `adhesion` study's warnings ([`Warning::described`]).
pub(crate) fn describe(w: &Warning, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    let n = |v: f64| crate::table::number(v, 6);
    match w {
        Warning::BeyondPullOff {
            nominal_pressure,
            pull_off_stress,
            count,
            ..
        } => write!(
            f,
            "{} at or below −σ_p, minus the pull-off stress σ_p = {} (the highest: \
             σ0 = {}): nothing is in contact there (A/A0 = 0)",
            if *count > 1 {
                format!("{count} nominal pressures are")
            } else {
                "a nominal pressure is".to_string()
            },
            n(*pull_off_stress),
            n(*nominal_pressure)
        ),
        Warning::AdhesionToleranceNotMet {
            tolerance,
            error_bound,
            count,
            ..
        } => write!(
            f,
            "{count} adhesive contact fraction(s) did not reach the tolerance {} at the \
             largest mesh: error estimate up to {} (reported with each point)",
            n(*tolerance),
            n(*error_bound)
        ),
        Warning::LongAdhesionRange {
            adhesion_range,
            rms_slope,
            rms_curvature,
            ..
        } => write!(
            f,
            "the adhesion range Δr = {} is not short against g₀ = (16/3) h'²_rms/h''_rms \
             = {} (Δr/g₀ ≥ 0.1): the Pastewka–Robbins criterion assumes short-ranged \
             adhesion",
            n(*adhesion_range),
            n(16.0 / 3.0 * rms_slope * rms_slope / rms_curvature)
        ),
        _ => Ok(()),
    }
}

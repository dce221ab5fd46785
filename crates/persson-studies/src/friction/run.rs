//! Computing the `friction` output (and `persson friction`): Persson's rubber
//! friction, [`persson::friction`], over the temperatures, nominal pressures
//! and velocities asked for, with the warnings its typed notes call for.

use persson::error::{Error, Result};
use persson::friction::{
    log_velocities, CutOff, Friction, FrictionOptions, FrictionPoint, FrictionResult,
    HorizontalShift, Rubber, TableExcursion, DEFAULT_GAMMA, DEFAULT_POINTS_PER_DECADE,
    DEFAULT_TOLERANCE,
};
use persson::spectrum::Spectrum;

use super::{FrictionOutput, FrictionReport};
use crate::input::spectrum_warnings;
use crate::input::{RubberSpec, SpectrumSpec};
use crate::naming::prefix;
use crate::naming::required;
use crate::warning::{self, Warning};

/// μ, A/A0 and (with `out.flash_temperature`) the flash temperature at every
/// temperature (default the rubber's T_ref), nominal pressure and velocity.
///
/// Errors name the field as in the scene file (`velocity`, `q1`,
/// `temperature`, `wlf_c1`, a file and its line).
///
/// # Errors
/// No pressure; neither or both of `velocity` and `velocity_range`; a
/// velocity, pressure or temperature out of range (a temperature at or below
/// the WLF singularity T_ref − C2); a q1 outside (q_l, q_s]; as
/// [`RubberSpec::build`] and [`SpectrumSpec::build`].
pub fn friction(
    spectrum: &SpectrumSpec,
    rubber: &RubberSpec,
    pressures: &[f64],
    out: &FrictionOutput,
) -> Result<FrictionReport> {
    friction_named(spectrum, rubber, pressures, out, ["", "", ""])
}

/// As [`friction`], the errors' names prefixed by their sections (spectrum,
/// rubber, output) as in a scene file.
pub(crate) fn friction_named(
    spectrum: &SpectrumSpec,
    rubber: &RubberSpec,
    pressures: &[f64],
    out: &FrictionOutput,
    [spectrum_section, rubber_section, output_section]: [&str; 3],
) -> Result<FrictionReport> {
    if pressures.is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.friction)",
        ));
    }
    velocities(out).map_err(|e| prefix(output_section, e))?;
    let built = spectrum
        .build_described()
        .map_err(|e| prefix(spectrum_section, e))?;
    let s = built.value;
    let mut warnings = built.warnings;
    for w in spectrum_warnings(spectrum, s.as_ref()) {
        warning::push(&mut warnings, Some(w));
    }
    let r = rubber
        .build(out.flash_temperature)
        .map_err(|e| prefix(rubber_section, e))?;
    let mut report = friction_on(s.as_ref(), &spectrum.breaks(), &r, pressures, out)
        .map_err(|e| prefix(output_section, e))?;
    report.surface = built.description;
    warnings.append(&mut report.warnings);
    report.warnings = warnings;
    Ok(report)
}

/// As [`friction`] on a built spectrum (with the kinks `breaks` of its C(q),
/// 1/m) and a built rubber (thermal data set when `out.flash_temperature`).
///
/// # Errors
/// As [`friction`].
pub fn friction_on(
    s: &dyn Spectrum,
    breaks: &[f64],
    r: &Rubber,
    pressures: &[f64],
    out: &FrictionOutput,
) -> Result<FrictionReport> {
    if pressures.is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.friction)",
        ));
    }
    if out.flash_temperature && r.thermal().is_none() {
        return Err(required(
            "thermal_conductivity, density and heat_capacity (for flash_temperature)",
        ));
    }
    let velocities = velocities(out)?;
    let temperatures = if out.temperature.is_empty() {
        vec![r.shift().reference_temperature()]
    } else {
        out.temperature.clone()
    };
    let options = options(out, breaks.to_vec())?;
    let model = Friction::new(s, r, &options)?;
    let points = model.sweep(&velocities, &temperatures, pressures)?;
    let q_l = s.q_min();
    let rms_slope = s.rms_slope(q_l, model.q1())?.value;
    Ok(FrictionReport {
        surface: None,
        q_l,
        q1: model.q1(),
        rms_slope,
        gamma: options.gamma,
        tolerance: options.tolerance,
        poisson: r.poisson(),
        reference_temperature: r.shift().reference_temperature(),
        warnings: friction_warnings(&points, r),
        points,
    })
}

/// The velocities: the list or the log-spaced range (exactly one).
fn velocities(out: &FrictionOutput) -> Result<Vec<f64>> {
    match (&out.velocity_range, out.velocity.is_empty()) {
        (Some(r), true) => {
            if r.points > MAX_VELOCITIES {
                return Err(Error::invalid(
                    "velocity_range.points",
                    r.points as f64,
                    format!("at most {MAX_VELOCITIES} (each velocity is a friction integral)"),
                ));
            }
            log_velocities(r.velocity_min, r.velocity_max, r.points)
                .map_err(|e| prefix("velocity_range.", e))
        }
        (None, false) => {
            for &v in &out.velocity {
                if !(v.is_finite() && v > 0.0) {
                    return Err(Error::invalid("velocity", v, "finite and > 0 (m/s)"));
                }
            }
            Ok(out.velocity.clone())
        }
        (None, true) => Err(required(
            "velocity or velocity_range (for outputs.friction)",
        )),
        (Some(_), false) => Err(Error::Inconsistent {
            name: "velocity, velocity_range".into(),
            requirement: "one of them, not both".into(),
        }),
    }
}

/// The most velocities a `velocity_range` may ask for.
pub const MAX_VELOCITIES: usize = 1_000_000;

/// The numerics' options from the output's fields.
fn options(out: &FrictionOutput, breaks: Vec<f64>) -> Result<FrictionOptions> {
    let cutoff = match (out.q1, out.q1_rms_slope) {
        (Some(q1), None) => CutOff::Wavevector(q1),
        (None, Some(s)) => CutOff::RmsSlope(s),
        (None, None) => CutOff::SpectrumEnd,
        (Some(_), Some(_)) => {
            return Err(Error::Inconsistent {
                name: "q1, q1_rms_slope".into(),
                requirement: "at most one of them".into(),
            })
        }
    };
    Ok(FrictionOptions {
        gamma: out.gamma.unwrap_or(DEFAULT_GAMMA),
        cutoff,
        tolerance: out.tolerance.unwrap_or(DEFAULT_TOLERANCE),
        breaks,
        points_per_decade: out.points_per_decade.unwrap_or(DEFAULT_POINTS_PER_DECADE),
    })
}

/// The warnings of a sweep: a master curve sampled outside its range, points
/// that did not converge, a shift table extended by the flash temperature.
pub fn friction_warnings(points: &[FrictionPoint], rubber: &Rubber) -> Vec<Warning> {
    let mut w = Vec::new();
    let results = || points.iter().flat_map(results_of);
    let outside: Vec<_> = points
        .iter()
        .filter_map(|p| {
            let mut ex = results_of(p).filter_map(|r| r.table_excursion);
            let first = ex.next()?;
            let worst = ex.fold(first, |a, b| {
                if b.friction_fraction > a.friction_fraction {
                    b
                } else {
                    a
                }
            });
            (worst.decades_below > 0.0 || worst.decades_above > 0.0).then_some(worst)
        })
        .collect();
    if let Some(first) = outside.first() {
        let max = |f: fn(&TableExcursion) -> f64| outside.iter().map(f).fold(0.0, f64::max);
        w.push(
            Warning::MasterCurveRange {
                frequency_range: (first.frequency_min, first.frequency_max),
                decades_below: max(|e| e.decades_below),
                decades_above: max(|e| e.decades_above),
                friction_fraction: max(|e| e.friction_fraction),
                count: outside.len(),
                of: points.len(),
                message: String::new(),
            }
            .described(describe),
        );
    }
    let failed: Vec<f64> = results()
        .filter(|r| !r.converged)
        .map(|r| relative(r.friction_coefficient_error_bound, r.friction_coefficient))
        .collect();
    if !failed.is_empty() {
        w.push(
            Warning::FrictionNotConverged {
                count: failed.len(),
                of: points.len()
                    * if points.iter().any(|p| p.flash.is_some()) {
                        2
                    } else {
                        1
                    },
                relative_error_bound: failed.iter().copied().fold(0.0, f64::max),
                message: String::new(),
            }
            .described(describe),
        );
    }
    let hottest = results()
        .filter_map(|r| r.shift_table_extended_to)
        .fold(f64::NEG_INFINITY, f64::max);
    if let (true, HorizontalShift::Table(t)) = (hottest.is_finite(), rubber.shift().horizontal()) {
        w.push(
            Warning::ShiftTableExtended {
                temperature_max: t.temperature_range().1,
                temperature: hottest,
                message: String::new(),
            }
            .described(describe),
        );
    }
    w
}

fn results_of(p: &FrictionPoint) -> impl Iterator<Item = &FrictionResult> {
    std::iter::once(&p.isothermal).chain(p.flash.as_ref())
}

fn relative(err: f64, value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        err.abs()
    } else {
        (err / value).abs()
    }
}

/// The text of the rubber-friction warnings ([`Warning::described`]).
pub(crate) fn describe(w: &Warning, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    let n = |v: f64| crate::table::number(v, 3);
    match w {
        Warning::MasterCurveRange {
            frequency_range,
            decades_below,
            decades_above,
            friction_fraction,
            count,
            of,
            ..
        } => write!(
            f,
            "the master curve (ω = {} … {} rad/s) was sampled outside its range at {count} of \
             {of} points, up to {} decade(s) below and {} above (a_T q v; held at its end \
             values there): up to {} % of μ comes from there (extend the master curve, or \
             narrow the velocities, temperatures or q1)",
            n(frequency_range.0),
            n(frequency_range.1),
            n(*decades_below),
            n(*decades_above),
            n(100.0 * friction_fraction)
        ),
        Warning::FrictionNotConverged {
            count,
            of,
            relative_error_bound,
            ..
        } => write!(
            f,
            "the friction integrals did not reach the tolerance at {count} of {of} points \
             (relative error bound of μ up to {}; see friction_coefficient_error_bound)",
            n(*relative_error_bound)
        ),
        Warning::ShiftTableExtended {
            temperature_max,
            temperature,
            ..
        } => write!(
            f,
            "the flash temperature heated the rubber to {} K, beyond the shift table's last \
             row at {} K: a_T was extended linearly in ln a_T there",
            n(*temperature),
            n(*temperature_max)
        ),
        _ => Ok(()),
    }
}

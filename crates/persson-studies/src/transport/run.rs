//! The outputs `conductance` and `leakage` (the subcommands of the same
//! names run these functions): the theory's curve, and with `bem` the
//! FFT-BEM's values at the same loads ([`super::bem`], feature `flow`).

use persson::conductance::{Conductance, ConductanceOptions, Conductivity, GapLaw, Resistivity};
use persson::error::{check, Error, Result};
use persson::gap::DensityOptions;
use persson::leakage::{
    CriticalJunction, Drive, EffectiveMedium, LeakStatus, Seal, DEFAULT_PERCOLATION_THRESHOLD,
};

use super::report::{
    BemTransportPoint, BemTransportReport, ConductanceReport, LeakagePoint, LeakageReport,
};
use super::spec::{ConductanceOutput, LeakageOutput};
use crate::contact::RoughContact;
use crate::naming::prefix;
use crate::naming::required;
use crate::warning::{self, Warning};

pub use super::request::TransportRequest;

/// Default relative tolerance of the wavevector integrals of both outputs.
pub const DEFAULT_TOLERANCE: f64 = persson::gap::DEFAULT_TOLERANCE;

/// One or two values of a property of the two bodies (one: both bodies).
fn pair(name: &str, v: &[f64]) -> Result<Option<(f64, f64)>> {
    match v {
        [] => Ok(None),
        [a] => Ok(Some((*a, *a))),
        [a, b] => Ok(Some((*a, *b))),
        _ => Err(Error::invalid(
            name,
            v.len() as f64,
            "one value (both bodies) or two (body 1, body 2)",
        )),
    }
}

/// κ1[, κ2] as given (W/(m K)).
///
/// # Errors
/// More than two values; a value not finite and positive (named `conductivity`).
pub fn conductivity(v: &[f64]) -> Result<Option<Conductivity>> {
    pair("conductivity", v)?
        .map(|(a, b)| {
            Conductivity::new(a, b)
                .map_err(|e| crate::naming::rename(e, "conductivity2", "conductivity"))
        })
        .transpose()
}

/// ρ1[, ρ2] as given (Ω m).
///
/// # Errors
/// More than two values; a value not finite and positive (named `resistivity`).
pub fn resistivity(v: &[f64]) -> Result<Option<Resistivity>> {
    pair("resistivity", v)?
        .map(|(a, b)| {
            Resistivity::new(a, b)
                .map_err(|e| crate::naming::rename(e, "resistivity2", "resistivity"))
        })
        .transpose()
}

/// The gap law of an output: the gas law, a table, or none.
///
/// # Errors
/// Half a gas law; a gas law and a table; bad values.
pub fn gap_law(
    gas_conductivity: Option<f64>,
    mean_free_path: Option<f64>,
    table: Option<&[(f64, f64)]>,
) -> Result<Option<GapLaw>> {
    let law = match (gas_conductivity, mean_free_path, table) {
        (None, None, None) => return Ok(None),
        (Some(k), Some(l), None) => {
            check::positive("mean_free_path", l)?;
            GapLaw::Gas {
                gas_conductivity: k,
                mean_free_path: l,
            }
        }
        (None, None, Some(t)) => GapLaw::Table { points: t.to_vec() },
        (Some(_), None, None) => return Err(missing("mean_free_path", "gas_conductivity")),
        (None, Some(_), None) => return Err(missing("gas_conductivity", "mean_free_path")),
        _ => {
            return Err(Error::Inconsistent {
                name: "gap_table".into(),
                requirement: "either the gas law (gas_conductivity, mean_free_path) or a table"
                    .into(),
            })
        }
    };
    law.validate()?;
    Ok(Some(law))
}

fn missing(name: &str, with: &str) -> Error {
    Error::Inconsistent {
        name: name.into(),
        requirement: format!("required with {with}"),
    }
}

/// The seal of a `leakage` output: a liquid under ΔP or a gas from P_a to P_b.
///
/// # Errors
/// Neither or both drives; any value not finite and positive; P_b ≥ P_a.
pub fn seal(out: &LeakageOutput) -> Result<Seal> {
    let drive = match (out.pressure_drop, out.inlet_pressure, out.outlet_pressure) {
        (Some(d), None, None) => Drive::Liquid { pressure_drop: d },
        (None, Some(a), Some(b)) => Drive::Gas {
            inlet_pressure: a,
            outlet_pressure: b,
        },
        (None, None, None) => {
            return Err(Error::Inconsistent {
                name: "pressure_drop".into(),
                requirement: "required (a liquid), or inlet_pressure and outlet_pressure (a gas)"
                    .into(),
            })
        }
        (None, Some(_), None) => return Err(missing("outlet_pressure", "inlet_pressure")),
        (None, None, Some(_)) => return Err(missing("inlet_pressure", "outlet_pressure")),
        _ => {
            return Err(Error::Inconsistent {
                name: "pressure_drop".into(),
                requirement: "not with inlet_pressure / outlet_pressure (a liquid or a gas)".into(),
            })
        }
    };
    let seal = Seal {
        seal_width: out.seal_width,
        seal_length: out.seal_length,
        viscosity: out.viscosity,
        drive,
    };
    seal.validate()?;
    Ok(seal)
}

fn band_values(surface: &RoughContact) -> Result<(f64, f64)> {
    let (q_l, q_s) = (surface.spectrum.q_min(), surface.spectrum.q_max());
    Ok((
        surface.spectrum.rms_height(q_l, q_s)?.value,
        surface.spectrum.rms_slope(q_l, q_s)?.value,
    ))
}

/// Contact conductance against load (`conductance`): Barber's identity on
/// the theory's stiffness, the gap term over P(u), and with `out.bem` the
/// FFT-BEM's values at the same loads.
///
/// # Errors
/// No pressure or a bad one; bad conductivities, resistivities, gap law or
/// tolerance (named as the output's fields); a failed integral or solve.
pub fn conductance(
    surface: &RoughContact,
    pressures: &[f64],
    out: &ConductanceOutput,
) -> Result<ConductanceReport> {
    if pressures.is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.conductance)",
        ));
    }
    let tolerance = check::tolerance("tolerance", out.tolerance.unwrap_or(DEFAULT_TOLERANCE))?;
    let kappa = conductivity(&out.conductivity)?;
    let rho = resistivity(&out.resistivity)?;
    let law = gap_law(
        out.gas_conductivity,
        out.mean_free_path,
        out.gap_table.as_deref(),
    )?;
    let options = ConductanceOptions {
        conductivity: kappa,
        resistivity: rho,
        gap_law: law.clone(),
        density: density_options(surface, tolerance),
    };
    let model = Conductance::new(surface.spectrum.as_ref(), surface.contact_modulus, options)?;
    let points = model.load_curve(pressures)?;
    let request = TransportRequest::new(kappa, rho, law, None);
    let bem = out
        .bem
        .map(|b| super::bem::on_contact(surface, pressures, &b, &request))
        .transpose()
        .map_err(|e| prefix("bem.", e))?;
    let (rms_height, rms_slope) = band_values(surface)?;
    Ok(ConductanceReport {
        warnings: surface_warnings(surface, pressures, bem.as_ref()),
        surface: surface.description.clone(),
        contact_modulus: surface.contact_modulus,
        rms_height,
        rms_slope,
        tolerance,
        conductivity: kappa.map(|k| k.conductivity),
        conductivity2: kappa.map(|k| k.conductivity2),
        resistivity: rho.map(|r| r.resistivity),
        resistivity2: rho.map(|r| r.resistivity2),
        gas_conductivity: out.gas_conductivity,
        mean_free_path: out.mean_free_path,
        gap_table: out.gap_table.clone().unwrap_or_default(),
        points,
        bem,
    })
}

/// Leak rate against load (`leakage`): critical junction and effective
/// medium, and with `out.bem` Reynolds flow on the FFT-BEM's gap. A load at
/// which the contact already percolates gives Q = 0 and a warning.
///
/// # Errors
/// No pressure or a bad one; a bad seal, threshold or tolerance (named as the
/// output's fields); a failed integral or solve.
pub fn leakage(
    surface: &RoughContact,
    pressures: &[f64],
    out: &LeakageOutput,
) -> Result<LeakageReport> {
    if pressures.is_empty() {
        return Err(required(
            "nominal_pressure (a non-empty list, for outputs.leakage)",
        ));
    }
    let tolerance = check::tolerance("tolerance", out.tolerance.unwrap_or(DEFAULT_TOLERANCE))?;
    let seal = seal(out)?;
    let threshold = out
        .percolation_threshold
        .unwrap_or(DEFAULT_PERCOLATION_THRESHOLD);
    let s = surface.spectrum.as_ref();
    let e_star = surface.contact_modulus;
    let junction = CriticalJunction::new(s, e_star, seal)?
        .with_threshold(threshold)?
        .with_tolerance(tolerance)?
        .with_breaks(&surface.breaks);
    let medium = EffectiveMedium::new(s, e_star, seal, density_options(surface, tolerance))?;
    let cj = junction.load_curve(pressures)?;
    let em = medium.load_curve(pressures)?;
    let points: Vec<LeakagePoint> = cj
        .into_iter()
        .zip(em)
        .map(|(c, e)| LeakagePoint {
            nominal_pressure: c.nominal_pressure,
            critical_junction: c,
            effective_medium: e,
        })
        .collect();
    let request = TransportRequest::new(None, None, None, Some(seal));
    let bem = out
        .bem
        .map(|b| super::bem::on_contact(surface, pressures, &b, &request))
        .transpose()
        .map_err(|e| prefix("bem.", e))?;
    let mut warnings = surface_warnings(surface, pressures, bem.as_ref());
    let sealed = |f: &dyn Fn(&LeakagePoint) -> (LeakStatus, f64)| {
        points
            .iter()
            .filter(|p| f(p).0 == LeakStatus::Sealed)
            .map(|p| (p.nominal_pressure, f(p).1))
            .collect::<Vec<_>>()
    };
    let cj_sealed = sealed(&|p| {
        (
            p.critical_junction.status,
            p.critical_junction.contact_fraction,
        )
    });
    let em_sealed = sealed(&|p| {
        (
            p.effective_medium.status,
            p.effective_medium.contact_fraction,
        )
    });
    warning::push(
        &mut warnings,
        sealed_warning("critical-junction", &cj_sealed, Some(threshold)),
    );
    warning::push(
        &mut warnings,
        sealed_warning("effective-medium", &em_sealed, Some(0.5)),
    );
    let (rms_height, rms_slope) = band_values(surface)?;
    let fluid = seal.drive.fluid();
    let (pressure_drop, inlet, outlet) = match seal.drive {
        Drive::Liquid { pressure_drop } => (Some(pressure_drop), None, None),
        Drive::Gas {
            inlet_pressure,
            outlet_pressure,
        } => (None, Some(inlet_pressure), Some(outlet_pressure)),
    };
    Ok(LeakageReport {
        warnings,
        surface: surface.description.clone(),
        contact_modulus: e_star,
        rms_height,
        rms_slope,
        tolerance,
        fluid,
        viscosity: seal.viscosity,
        pressure_drop,
        inlet_pressure: inlet,
        outlet_pressure: outlet,
        seal_width: seal.seal_width,
        seal_length: seal.seal_length,
        percolation_threshold: threshold,
        points,
        bem,
    })
}

fn density_options(surface: &RoughContact, tolerance: f64) -> DensityOptions {
    DensityOptions {
        tolerance,
        breaks: surface.breaks.clone(),
        ..DensityOptions::default()
    }
}

/// The surface's warnings, those of the pressures, and the BEM's.
fn surface_warnings(
    surface: &RoughContact,
    pressures: &[f64],
    bem: Option<&BemTransportReport>,
) -> Vec<Warning> {
    let mut w = surface.warnings.clone();
    warning::push(
        &mut w,
        Warning::high_pressure(pressures, surface.contact_modulus),
    );
    if let Some(b) = bem {
        for x in bem_warnings(b, surface.spectrum.as_ref()) {
            warning::push(&mut w, Some(x));
        }
    }
    w
}

/// The BEM's warnings: a surface band-limited by its grid, loads at which
/// no open path crosses the gap.
pub fn bem_warnings(
    b: &BemTransportReport,
    spectrum: &dyn persson::spectrum::Spectrum,
) -> Vec<Warning> {
    let mut w = Vec::new();
    if let Ok(m) = spectrum.rms_slope(spectrum.q_min(), spectrum.q_max()) {
        warning::push(
            &mut w,
            Warning::band_limited(b.grid, b.surface_rms_slope, m.value),
        );
    }
    warning::push(&mut w, sealed_bem(&b.points));
    w
}

/// [`Warning::Sealed`] of the BEM: the loads whose gap does not percolate.
pub fn sealed_bem(points: &[BemTransportPoint]) -> Option<Warning> {
    let sealed: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.percolates == Some(false))
        .map(|p| (p.nominal_pressure, p.contact_fraction))
        .collect();
    sealed_warning("bem", &sealed, None)
}

fn sealed_warning(method: &str, sealed: &[(f64, f64)], threshold: Option<f64>) -> Option<Warning> {
    let first = sealed.iter().copied().min_by(|a, b| a.0.total_cmp(&b.0))?;
    Some(
        Warning::Sealed {
            method: method.into(),
            nominal_pressure: first.0,
            count: sealed.len(),
            contact_fraction: first.1,
            percolation_threshold: threshold,
            message: String::new(),
        }
        .described(describe),
    )
}

/// The text of `leakage` and its comparison with the BEM's warnings ([`Warning::described`]).
pub(crate) fn describe(w: &Warning, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    let n = |v: f64| crate::table::number(v, 6);
    match w {
        Warning::Sealed {
            method,
            nominal_pressure,
            count,
            contact_fraction,
            percolation_threshold,
            ..
        } => {
            let why = match percolation_threshold {
                Some(a) => format!(
                    "A/A0 = {} is at or above the percolation threshold {}",
                    n(*contact_fraction),
                    n(*a)
                ),
                None => format!(
                    "A/A0 = {}, no open path joins inlet and outlet",
                    n(*contact_fraction)
                ),
            };
            write!(
                f,
                "the contact already percolates at {count} load(s) from σ0 = {} ({why}): \
                 the {method} leak rate is 0 there",
                n(*nominal_pressure)
            )
        }
        _ => Ok(()),
    }
}

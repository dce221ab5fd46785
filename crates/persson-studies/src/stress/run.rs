//! The stress distributions P(σ, ζ).

use persson::error::{Error, Result};
use persson::stress::{HertzContact, Solver, Start, StressScene};

use crate::contact::RoughContact;
use crate::input::StartName;
use crate::naming::{prefix, required};
use crate::study::check_points;

use super::*;

/// Dimensionless stress distributions at each G (`stress`): σ/σH at
/// `sigma_ratio`, or `points` values over the distribution when empty.
///
/// # Errors
/// As [`Solver::new`] and [`Solver::curve`].
pub fn stress_dimensionless(
    start: &Start,
    g: &[f64],
    yield_ratio: Option<f64>,
    tolerance: f64,
    sigma_ratio: &[f64],
    points: usize,
) -> Result<StressReport> {
    if g.is_empty() {
        return Err(required(
            "outputs.stress.g (dimensionless) or outputs.stress.zeta (pressure unit)",
        ));
    }
    if sigma_ratio.is_empty() {
        check_points(points)?;
    }
    let curves = g
        .iter()
        .map(|&g| {
            let solver = Solver::new(start, g, yield_ratio, tolerance)?;
            let sigma = if sigma_ratio.is_empty() {
                solver.grid(points)
            } else {
                sigma_ratio.to_vec()
            };
            let c = solver.curve(&sigma)?;
            Ok(StressCurveReport {
                g,
                zeta: None,
                tau: Some(c.tau),
                sigma_ratio: c.sigma_ratio,
                scaled_density: c.scaled_density,
                sigma: vec![],
                density: vec![],
                contact_fraction: c.contact_fraction,
                elastic_fraction: c.elastic_fraction,
                plastic_fraction: c.plastic_fraction,
                non_contact_fraction: Some(c.non_contact_fraction),
                scaled_density_error_bound: c.scaled_density_error_bound,
                elastic_fraction_error_bound: c.elastic_fraction_error_bound,
                plastic_fraction_error_bound: c.plastic_fraction_error_bound,
                method: c.method,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(StressReport {
        start: start.kind(),
        mean_ratio: start.mean_ratio(),
        peak_pressure: None,
        nominal_pressure: None,
        contact_radius: None,
        yield_ratio,
        yield_stress: None,
        curves,
        warnings: vec![],
    })
}

/// Stress distributions in the pressure unit at the magnifications of `out`.
///
/// # Errors
/// Inconsistent start and contact; as [`StressScene::curves`].
pub fn stress_physical(surface: &RoughContact, out: &StressOutput) -> Result<StressReport> {
    check_points(out.points)?;
    out.check_mode()?;
    if out.zeta.is_empty() {
        return Err(required("zeta (a non-empty list of magnifications)"));
    }
    let model = surface.model()?;
    let e_star = surface.contact_modulus;
    let start = Start::from(out.start);
    let contact = match (&out.ball, &out.cylinder, out.peak_pressure) {
        (Some(b), None, None) if out.start == StartName::Hertz => {
            Some(HertzContact::ball(b.radius, b.load, e_star).map_err(|e| prefix("ball.", e))?)
        }
        (None, Some(c), None) if out.start == StartName::Cylinder => Some(
            HertzContact::cylinder(c.radius, c.load_per_length, e_star)
                .map_err(|e| prefix("cylinder.", e))?,
        ),
        (None, None, Some(_)) => None,
        _ => {
            return Err(Error::Inconsistent {
                name: "peak_pressure, ball, cylinder".into(),
                requirement: "give exactly one: peak_pressure, ball (with start hertz) or \
                              cylinder (with start cylinder)"
                    .into(),
            })
        }
    };
    let problem = match (&contact, out.peak_pressure) {
        (Some(c), _) => StressScene::hertz(c, out.yield_stress),
        (None, Some(p)) => StressScene::new(start.clone(), p, out.yield_stress),
        (None, None) => Err(required("peak_pressure, ball or cylinder")),
    }?;
    // σ from 0 to σY, or (elastic) to σH plus four standard deviations
    // √(2G) σ0 of the widest curve.
    let mut g_max = 0.0f64;
    // The mean pressure of a ball or cylinder comes from its radius and load:
    // a pressure G cannot take is theirs.
    let given = match (&out.ball, &out.cylinder) {
        (Some(_), _) => "ball.radius, ball.load",
        (_, Some(_)) => "cylinder.radius, cylinder.load_per_length",
        _ => "peak_pressure",
    };
    for &z in &out.zeta {
        let g = model
            .g(z, problem.nominal_pressure())
            .map_err(|e| match e {
                Error::InvalidParameter {
                    name, requirement, ..
                } if name == "nominal_pressure" => Error::Inconsistent {
                    name: given.into(),
                    requirement: format!(
                        "a mean pressure σ0 = {} of the contact that G can take: {requirement}",
                        crate::table::number(problem.nominal_pressure(), 4)
                    ),
                },
                e => e,
            })?;
        g_max = g_max.max(g.value);
    }
    let top = out
        .yield_stress
        .unwrap_or(problem.peak_pressure + 4.0 * (2.0 * g_max).sqrt() * problem.nominal_pressure());
    let n = out.points;
    let sigma: Vec<f64> = (0..n).map(|i| top * i as f64 / (n - 1) as f64).collect();
    let curves = problem
        .curves(&model, &out.zeta, &sigma, out.tolerance)?
        .into_iter()
        .map(|c| StressCurveReport {
            g: c.g.value,
            zeta: Some(c.zeta),
            tau: None,
            sigma_ratio: vec![],
            scaled_density: vec![],
            sigma: c.sigma,
            density: c.density,
            contact_fraction: c.contact_fraction,
            elastic_fraction: c.elastic_fraction,
            plastic_fraction: c.plastic_fraction,
            non_contact_fraction: None,
            scaled_density_error_bound: c.scaled_density_error_bound,
            elastic_fraction_error_bound: c.elastic_fraction_error_bound,
            plastic_fraction_error_bound: c.plastic_fraction_error_bound,
            method: c.method,
        })
        .collect();
    Ok(StressReport {
        start: start.kind(),
        mean_ratio: start.mean_ratio(),
        peak_pressure: Some(problem.peak_pressure),
        nominal_pressure: Some(problem.nominal_pressure()),
        contact_radius: contact.map(|c| c.contact_radius),
        yield_ratio: None,
        yield_stress: out.yield_stress,
        curves,
        warnings: surface.warnings(&[problem.nominal_pressure()], &out.zeta),
    })
}

//! The Hertz ball on the FFT-BEM (feature `bem`): which result the spec asks
//! for, and the solves that give it.

use persson::bem::adhesive::AdhesiveOptions;
use persson::bem::hertz::{self, HertzCase};
use persson::bem::{check_memory, Iteration, Options};
use persson::error::{check, Error, Result};
use persson::names::{Boundary, LawKind};

use std::path::Path;

use super::report::{BemHertzReport, BemHertzRow, BemHertzTable};
use super::spec::{BemHertzOutput, DEFAULT_GRID};
use crate::bem_detail::{adhesive_sphere, hertz_subsurface, DEFAULT_POISSON};
use crate::output::Files;
use crate::validation::{self, HertzValidation};

/// What the study reports in this build.
pub type Report = BemHertzReport;

/// The report's remarks ([`BemHertzReport::warnings`]).
pub fn warnings(r: &Report) -> Vec<crate::warning::Warning> {
    r.warnings()
}

/// Stage `stress_plot`: the von Mises stress on the vertical section
/// through the axis.
///
/// # Errors
/// A figure that cannot be drawn or encoded; a file that cannot be staged.
pub fn write(h: &BemHertzOutput, r: &Report, dir: &Path, out: &mut Files) -> Result<()> {
    let BemHertzReport::Subsurface(s) = r else {
        return Ok(());
    };
    crate::study::draw(out, dir, h.stress_plot.as_ref(), || {
        let section = crate::bem_detail::hertz_section(s)?;
        Ok(Box::new(crate::bem_detail::hertz_section_figure(
            s, &section,
        )))
    })
}

/// `outputs.bem_hertz`, `persson bem hertz`: the result the spec asks for
/// (its docs), errors named as the spec's fields.
///
/// # Errors
/// Fields that do not go together or are out of range; a grid too large for
/// memory; a solve that fails.
pub fn bem_hertz(h: &BemHertzOutput) -> Result<BemHertzReport> {
    // The solvers name a grid side `grid`; the spec's field is `grids`.
    run(h).map_err(|e| crate::naming::rename(e, "grid", "grids"))
}

fn run(h: &BemHertzOutput) -> Result<BemHertzReport> {
    check_combination(h)?;
    let grids = if h.grids.is_empty() {
        vec![DEFAULT_GRID]
    } else {
        h.grids.clone()
    };
    let boundary = h.boundary.unwrap_or(Boundary::Free);
    let opts = Options {
        tolerance: check::tolerance("tolerance", h.tolerance.unwrap_or(1e-10))?,
        max_iterations: h
            .max_iterations
            .unwrap_or(Options::default().max_iterations),
        ..Options::default()
    };
    let size = h.size.unwrap_or(1.0);
    let case = HertzCase {
        grid: grids[0],
        boundary,
        size,
        radius: h.radius.unwrap_or(1.0),
        e_star: h.contact_modulus.unwrap_or(1.0),
        contact_radius: h.contact_radius.unwrap_or(0.1 * size),
    };
    if let Some(dg) = h.work_of_adhesion {
        return adhesive(h, &grids, &case, dg, &opts);
    }
    if h.subsurface {
        let [n] = grids[..] else {
            return Err(Error::invalid(
                "grids",
                grids.len() as f64,
                "one grid side with subsurface",
            ));
        };
        check_memory(n, boundary)?;
        let poisson = h.poisson.unwrap_or(DEFAULT_POISSON);
        let r = hertz_subsurface(&case, &opts, poisson, &mut report(0, 1))?;
        return Ok(BemHertzReport::Subsurface(r));
    }
    let rows = grids
        .iter()
        .enumerate()
        .map(|(k, &n)| {
            let case = HertzCase { grid: n, ..case };
            validation::hertz(&case, &opts, &mut report(k, grids.len()))
        })
        .collect::<Result<Vec<_>>>()?;
    if let ([one], None) = (&rows[..], h.yield_stress) {
        return Ok(BemHertzReport::Validation(*one));
    }
    let plastic = h
        .yield_stress
        .map(|y| {
            hertz::plastic_disc(&case, &grids, y, &opts, &mut |k, it| {
                report(k, grids.len())(it)
            })
        })
        .transpose()?;
    Ok(BemHertzReport::Convergence(BemHertzTable {
        boundary,
        tolerance: opts.tolerance,
        case,
        rows: rows.iter().map(row).collect(),
        plastic,
    }))
}

/// The fields that belong to one result only, refused beside another; each
/// error names both fields.
fn check_combination(h: &BemHertzOutput) -> Result<()> {
    let refuse = |name: &str, with: &str, why: &str| {
        Err(Error::Inconsistent {
            name: format!("{name} and {with}"),
            requirement: why.into(),
        })
    };
    if h.work_of_adhesion.is_some() {
        for (given, name) in [
            (h.yield_stress.is_some(), "yield_stress"),
            (h.subsurface, "subsurface"),
            (h.contact_radius.is_some(), "contact_radius"),
        ] {
            if given {
                return refuse(
                    name,
                    "work_of_adhesion",
                    "not together: the adhesive sphere runs its own path",
                );
            }
        }
    } else {
        for (given, name) in [
            (h.adhesion_range.is_some(), "adhesion_range"),
            (h.adhesion.is_some(), "adhesion"),
        ] {
            if given {
                return refuse(name, "work_of_adhesion", "the adhesive sphere's: give both");
            }
        }
    }
    if h.subsurface && h.yield_stress.is_some() {
        return refuse(
            "yield_stress",
            "subsurface",
            "not together: the stress below the surface is of the elastic solve",
        );
    }
    if !h.subsurface {
        for (given, name) in [
            (h.poisson.is_some(), "poisson"),
            (h.stress_plot.is_some(), "stress_plot"),
        ] {
            if given {
                return refuse(
                    name,
                    "subsurface",
                    "the stress below the surface's: give both",
                );
            }
        }
    }
    Ok(())
}

/// The adhesive sphere on each grid (periodic, mean-gap control).
fn adhesive(
    h: &BemHertzOutput,
    grids: &[usize],
    case: &HertzCase,
    work_of_adhesion: f64,
    opts: &Options,
) -> Result<BemHertzReport> {
    let range = h.adhesion_range.ok_or_else(|| Error::Inconsistent {
        name: "adhesion_range and work_of_adhesion".into(),
        requirement: "the adhesive sphere's: give both".into(),
    })?;
    if case.boundary != Boundary::Periodic {
        return Err(Error::Inconsistent {
            name: "boundary".into(),
            requirement: format!(
                "periodic for the adhesive sphere, which is solved on a periodic cell (got {})",
                case.boundary
            ),
        });
    }
    let options = AdhesiveOptions {
        tolerance: opts.tolerance,
        max_iterations: opts.max_iterations,
    };
    let law = h.adhesion.unwrap_or(LawKind::Maugis);
    let r = adhesive_sphere(
        grids,
        (case.size, case.radius, case.e_star),
        (law, work_of_adhesion, range),
        &options,
    )?;
    Ok(BemHertzReport::Adhesive(r))
}

/// One row of the η table.
fn row(v: &HertzValidation) -> BemHertzRow {
    BemHertzRow {
        grid: v.grid,
        energy_error: v.energy_error,
        energy_error_published: v.energy_error_published,
        contact_radius_error: v.contact_radius_error,
        peak_pressure_error: v.peak_pressure_error,
        contact_fraction: v.contact_fraction,
        iterations: v.iterations,
        seconds: v.seconds,
    }
}

/// The solver's iterations of solve `step` of `steps`, to the progress hook.
fn report(step: usize, steps: usize) -> impl FnMut(Iteration) {
    move |it| {
        crate::progress::report(&crate::progress::Progress {
            study: "bem_hertz",
            step,
            steps,
            iteration: it.iteration,
            residual: it.residual,
        })
    }
}

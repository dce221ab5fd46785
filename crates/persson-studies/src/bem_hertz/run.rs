//! The Hertz convergence table (feature `bem`).

use persson::bem::{check_memory, hertz, Options};
use persson::error::{check, Error, Result};

use super::report::{BemHertzReport, BemHertzRow};
use super::spec::BemHertzOutput;
use crate::naming::prefix;
use persson::names::Boundary;

/// `outputs.bem_hertz`: η per grid.
///
/// # Errors
/// A grid too large for memory; a tolerance out of range; a solve that fails.
pub fn bem_hertz(h: &BemHertzOutput) -> Result<BemHertzReport> {
    let named = |e: Error| prefix("outputs.bem_hertz.", e);
    let boundary = h.boundary.unwrap_or(Boundary::Free);
    let tol = check::tolerance("tolerance", h.tolerance.unwrap_or(1e-10)).map_err(named)?;
    let grids = if h.grids.is_empty() {
        vec![64, 128, 256]
    } else {
        h.grids.clone()
    };
    let opts = Options {
        tolerance: tol,
        ..Options::default()
    };
    let rows = grids
        .iter()
        .map(|&n| {
            check_memory(n, boundary).map_err(named)?;
            let r = hertz::validate(&hertz::HertzCase::new(n, boundary), &opts).map_err(named)?;
            let reference = hertz::lecture_eta(n).filter(|_| boundary == Boundary::Free);
            Ok(BemHertzRow {
                grid: n,
                energy_error: r.energy_error,
                energy_error_published: reference,
                contact_radius_error: r.contact_radius_error,
                peak_pressure_error: r.peak_pressure_error,
                contact_fraction: r.contact_fraction,
                iterations: r.iterations,
                seconds: r.seconds,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let plastic = match h.yield_stress {
        Some(y) => Some(
            hertz::plastic_disc(
                &hertz::HertzCase::new(grids[0], boundary),
                &grids,
                y,
                &opts,
                &mut |_, _| {},
            )
            .map_err(named)?,
        ),
        None => None,
    };
    Ok(BemHertzReport {
        boundary,
        tolerance: tol,
        rows,
        plastic,
    })
}

//! [`hertz`]: the FFT-BEM against the Hertz closed form, as `persson bem
//! hertz` reports it (η of Molinari's EPFL lecture "From single asperity to
//! multi asperity contact", Table 1).

use serde::Serialize;

use crate::table::{number, Cell, Table, Tabulate};
use persson::bem::hertz::{self as closed, HertzCase};
use persson::bem::{check_memory, Boundary, Iteration, Options};
use persson::error::Result;

/// The report of `persson bem hertz`: the case, then the errors against the
/// closed form.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct HertzValidation {
    /// Grid side N.
    pub grid: usize,
    /// Boundary condition.
    pub boundary: Boundary,
    /// Side L of the domain.
    pub size: f64,
    /// Ball radius R.
    pub radius: f64,
    /// Contact modulus E*.
    pub contact_modulus: f64,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// Hertz contact radius a that sets the load.
    pub hertz_contact_radius: f64,
    /// Hertz peak pressure p₀.
    pub hertz_peak_pressure: f64,
    /// Nominal pressure σ0 = load / L².
    pub nominal_pressure: f64,
    /// η: energy norm of the pressure error relative to that of the exact pressure.
    pub energy_error: f64,
    /// The lecture's own measure with the exact displacement (free boundary only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_error_displacement: Option<f64>,
    /// η listed in the lecture's Table 1 for this grid (free boundary), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_error_published: Option<f64>,
    /// Contact radius from the fit of p² = p₀²(1 − r²/a²).
    pub contact_radius: f64,
    /// |a_fit − a| / a.
    pub contact_radius_error: f64,
    /// Peak pressure from the same fit.
    pub peak_pressure: f64,
    /// |p₀_fit − p₀| / p₀.
    pub peak_pressure_error: f64,
    /// A/A0 of the numerical solution (exact: π a²/L²).
    pub contact_fraction: f64,
    /// Solver iterations.
    pub iterations: usize,
    /// Final residual ε.
    pub residual: f64,
    /// Wall time, s.
    pub seconds: f64,
}

/// Solve the Hertz case and compare with the closed form
/// ([`persson::bem::hertz::validate`]), calling `progress` once per iteration.
///
/// # Errors
/// As [`check_memory`] and [`persson::bem::hertz::validate`].
pub fn hertz(
    case: &HertzCase,
    options: &Options,
    progress: &mut dyn FnMut(Iteration),
) -> Result<HertzValidation> {
    check_memory(case.grid, case.boundary)?;
    let r = closed::validate_observed(case, options, progress)?;
    Ok(HertzValidation {
        grid: case.grid,
        boundary: case.boundary,
        size: case.size,
        radius: case.radius,
        contact_modulus: case.e_star,
        tolerance: options.tolerance,
        hertz_contact_radius: case.contact_radius,
        hertz_peak_pressure: case.peak_pressure(),
        nominal_pressure: case.mean_pressure(),
        energy_error: r.energy_error,
        energy_error_displacement: r.energy_error_displacement,
        energy_error_published: match case.boundary {
            Boundary::Free => closed::lecture_eta(case.grid),
            Boundary::Periodic => None,
        },
        contact_radius: r.contact_radius,
        contact_radius_error: r.contact_radius_error,
        peak_pressure: r.peak_pressure,
        peak_pressure_error: r.peak_pressure_error,
        contact_fraction: r.contact_fraction,
        iterations: r.iterations,
        residual: r.residual,
        seconds: r.seconds,
    })
}

impl Tabulate for HertzValidation {
    fn tables(&self) -> Vec<Table> {
        let n = self.grid;
        let mut t = Table::new(
            "bem_hertz",
            format!(
                "Hertz validation of the FFT-BEM, {n}×{n} grid, {} boundary, a = {}, R = {}, E* = {}",
                self.boundary.name(),
                number(self.hertz_contact_radius, 6),
                number(self.radius, 6),
                number(self.contact_modulus, 6)
            ),
        )
        .scalar("tolerance", "tolerance ε", self.tolerance)
        .scalar("energy_error", "η (energy-norm error)", self.energy_error);
        if let Some(l) = self.energy_error_published {
            t = t.scalar(
                "energy_error_published",
                "η in Molinari's lecture, Table 1",
                l,
            );
        }
        if let Some(l) = self.energy_error_displacement {
            t = t.scalar(
                "energy_error_displacement",
                "η with the exact displacement (the lecture's measure)",
                l,
            );
        }
        vec![t
            .scalar(
                "contact_radius",
                "contact radius a (fit)",
                self.contact_radius,
            )
            .scalar(
                "contact_radius_error",
                "relative error of a",
                self.contact_radius_error,
            )
            .scalar(
                "peak_pressure",
                "peak pressure p₀ (fit)",
                self.peak_pressure,
            )
            .scalar(
                "peak_pressure_error",
                "relative error of p₀",
                self.peak_pressure_error,
            )
            .scalar("contact_fraction", "A/A0", self.contact_fraction)
            .scalar(
                "iterations",
                "iterations",
                Cell::Int(self.iterations as i64),
            )
            .scalar("residual", "residual", self.residual)
            .scalar("seconds", "time (s)", self.seconds)]
    }
}

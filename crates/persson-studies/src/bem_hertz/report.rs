//! What the study `bem_hertz` reports (feature `bem`): one of four results,
//! chosen by its spec.

use serde::Serialize;

use crate::bem_detail::{AdhesiveSphereReport, HertzSubsurface};
use crate::table::{Table, Tabulate};
use crate::validation::HertzValidation;
use crate::warning::Warning;

/// What `bem_hertz` computed; its JSON is the variant's own (untagged), the
/// JSON of `persson bem hertz` with the same flags.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
#[non_exhaustive]
pub enum BemHertzReport {
    /// One grid: the validation against Hertz's closed form.
    Validation(HertzValidation),
    /// Several grids, or a yield stress: η per grid, and the plastic disc.
    Convergence(BemHertzTable),
    /// `subsurface`: the stress on the contact's axis.
    Subsurface(HertzSubsurface),
    /// `work_of_adhesion`: the adhesive sphere's pull-off per grid.
    Adhesive(AdhesiveSphereReport),
}

impl BemHertzReport {
    /// Its remarks: the adhesive sphere's (a cell too small for the contact,
    /// a pull-off not reached).
    pub fn warnings(&self) -> Vec<Warning> {
        match self {
            BemHertzReport::Adhesive(r) => crate::bem_detail::sphere_warnings(r),
            _ => Vec::new(),
        }
    }
}

impl Tabulate for BemHertzReport {
    fn tables(&self) -> Vec<Table> {
        match self {
            BemHertzReport::Validation(r) => r.tables(),
            BemHertzReport::Convergence(r) => r.tables(),
            BemHertzReport::Subsurface(r) => r.tables(),
            BemHertzReport::Adhesive(r) => r.tables(),
        }
    }
}

/// One row of the FFT-BEM Hertz convergence table.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemHertzRow {
    /// Grid side N.
    pub grid: usize,
    /// η: energy-norm error against the exact Hertz pressure.
    pub energy_error: f64,
    /// η of Molinari's lecture, Table 1 (free boundary, where listed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_error_published: Option<f64>,
    /// Relative error of the fitted contact radius.
    pub contact_radius_error: f64,
    /// Relative error of the fitted peak pressure.
    pub peak_pressure_error: f64,
    /// A/A0 (exact π a²/L² = 0.0314159…).
    pub contact_fraction: f64,
    /// Solver iterations.
    pub iterations: usize,
    /// Wall time of the solve, s.
    pub seconds: f64,
}

/// η per grid, with the plastic disc.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemHertzTable {
    /// Boundary condition.
    pub boundary: persson::names::Boundary,
    /// Solver tolerance.
    pub tolerance: f64,
    /// The ball, its load and the first grid (in the table's title).
    #[serde(skip)]
    pub case: persson::bem::hertz::HertzCase,
    /// One row per grid.
    pub rows: Vec<BemHertzRow>,
    /// With `yield_stress`: the plastic disc per grid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic: Option<persson::bem::hertz::PlasticDiscReport>,
}

impl Tabulate for BemHertzTable {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_hertz",
            format!(
                "Hertz convergence (FFT-BEM, {} boundary; {}); reference η: \
                 Molinari, EPFL lecture \"From single asperity to multi asperity contact\", Table 1 (free boundary)",
                self.boundary,
                ball(&self.case)
            ),
        )
        .column("grid", "N")
        .column_digits("energy_error", "η", 4)
        .column_digits("energy_error_published", "η (lecture)", 4)
        .column_digits("contact_radius_error", "a error", 3)
        .column_digits("peak_pressure_error", "σH error", 3)
        .column("contact_fraction", "A/A0")
        .column("iterations", "iterations")
        .column_digits("seconds", "time (s)", 3);
        for r in &self.rows {
            t.push(vec![
                r.grid.into(),
                r.energy_error.into(),
                r.energy_error_published.into(),
                r.contact_radius_error.into(),
                r.peak_pressure_error.into(),
                r.contact_fraction.into(),
                r.iterations.into(),
                r.seconds.into(),
            ]);
        }
        let plastic = self.plastic.iter().flat_map(|p| p.tables());
        std::iter::once(t).chain(plastic).collect()
    }
}

/// The ball in the table's title: the lecture's words for its case.
fn ball(c: &persson::bem::hertz::HertzCase) -> String {
    let n = |v: f64| crate::table::number(v, 6);
    if (c.size, c.radius, c.e_star, c.contact_radius) == (1.0, 1.0, 1.0, 0.1) {
        "sphere R = L, a = 0.1 L".into()
    } else {
        format!(
            "sphere R = {}, a = {}, L = {}, E* = {}",
            n(c.radius),
            n(c.contact_radius),
            n(c.size),
            n(c.e_star)
        )
    }
}

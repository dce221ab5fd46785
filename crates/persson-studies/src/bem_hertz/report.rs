//! The FFT-BEM Hertz convergence of a scene, with the plastic disc.

use serde::Serialize;

use crate::table::{Table, Tabulate};

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

/// FFT-BEM Hertz convergence (scene output `bem_hertz`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemHertzReport {
    /// Boundary condition.
    pub boundary: persson::names::Boundary,
    /// Solver tolerance.
    pub tolerance: f64,
    /// One row per grid.
    pub rows: Vec<BemHertzRow>,
    /// With `yield_stress`: the plastic disc per grid.
    #[cfg(feature = "bem")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic: Option<persson::bem::hertz::PlasticDiscReport>,
}

impl Tabulate for BemHertzReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_hertz",
            format!(
                "Hertz convergence (FFT-BEM, {} boundary; sphere R = L, a = 0.1 L); reference η: \
                 Molinari, EPFL lecture \"From single asperity to multi asperity contact\", Table 1 (free boundary)",
                self.boundary
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
        #[cfg(feature = "bem")]
        let plastic = self.plastic.iter().flat_map(|p| p.tables());
        #[cfg(not(feature = "bem"))]
        let plastic = std::iter::empty();
        std::iter::once(t).chain(plastic).collect()
    }
}

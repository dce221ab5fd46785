//! What `theories` computed, with its table.

use serde::Serialize;

use persson::corrected::TheoryPoint;

use crate::area::theory_heading;
use crate::input::TheoryName;
use crate::table::{input_digits, number, Table, Tabulate};

/// One theory's load curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct TheoryCurve {
    /// The theory.
    pub theory: TheoryName,
    /// Its γ (none for the original theory).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// Its low-load κ.
    pub kappa: f64,
    /// The points.
    pub points: Vec<TheoryPoint>,
}

/// A/A0 against load for several theories (scene output `theories`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct TheoriesReport {
    /// E*.
    pub contact_modulus: f64,
    /// Magnification ζ.
    pub zeta: f64,
    /// rms slope up to ζ (for the linear law).
    pub rms_slope: f64,
    /// One curve per theory.
    pub curves: Vec<TheoryCurve>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

impl Tabulate for TheoriesReport {
    fn tables(&self) -> Vec<Table> {
        self.curves
            .iter()
            .map(|c| {
                let mut t = Table::new(
                    format!("theories_{}", c.theory),
                    format!(
                        "Contact area against nominal pressure, {} (κ = {}), ζ = {}",
                        theory_heading(c.theory, c.gamma),
                        number(c.kappa, 4),
                        number(self.zeta, 6)
                    ),
                )
                .column_digits(
                    "nominal_pressure",
                    "σ0",
                    input_digits(c.points.iter().map(|p| p.nominal_pressure)),
                )
                .column("g", "G")
                .column("effective_g", "G_e")
                .column_digits("contact_fraction", "A/A0", 10)
                .column_digits("error_bound", "± bound", 2);
                for p in &c.points {
                    t.push(vec![
                        p.nominal_pressure.into(),
                        p.g.into(),
                        p.effective_g.into(),
                        p.contact_fraction.into(),
                        p.error_bound.into(),
                    ]);
                }
                t
            })
            .collect()
    }
}

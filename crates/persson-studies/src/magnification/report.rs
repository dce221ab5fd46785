//! What `magnification` computed, with its table.

use serde::Serialize;

use persson::theory::AreaPoint;

use crate::table::{number, surface_prefix, Table, Tabulate};

/// G(ζ) and A/A0 against magnification (`persson magnification`, scene output `magnification`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct MagnificationReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// E*.
    pub contact_modulus: f64,
    /// q_s/q_l.
    pub zeta_max: f64,
    /// One point per magnification (original theory).
    pub points: Vec<AreaPoint>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

impl Tabulate for MagnificationReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "magnification",
            format!(
                "{}G(ζ) and A/A0 against magnification at σ0 = {}, E* = {}",
                surface_prefix(&self.surface),
                number(self.nominal_pressure, 6),
                number(self.contact_modulus, 6)
            ),
        )
        .scalar("zeta_max", "ζ max = q_s/q_l", self.zeta_max)
        .column("zeta", "ζ")
        .column_digits("g", "G", 10)
        .column_digits("g_error_bound", "± bound", 2)
        .column_digits("contact_fraction", "A/A0", 10)
        .column_digits("error_bound", "± bound", 2)
        .column("rms_slope", "h'_rms(ζ)");
        for p in &self.points {
            t.push(vec![
                p.zeta.into(),
                p.g.into(),
                p.g_error_bound.into(),
                p.contact_fraction.into(),
                p.error_bound.into(),
                p.rms_slope.into(),
            ]);
        }
        vec![t]
    }
}

//! The mean separation ū, the stiffness and the elastic energy against load.

use serde::Serialize;

use crate::table::{number, Table, Tabulate};
use persson::separation::SeparationPoint;

use crate::table::{input_digits, surface_prefix};

/// Mean separation, stiffness and elastic energy against load (`persson
/// separation`, scene output `separation`; Persson, Phys. Rev. Lett. 99, 125502 (2007)).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SeparationReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// E*.
    pub contact_modulus: f64,
    /// rms height over [q_l, q_s].
    pub rms_height: f64,
    /// rms slope over [q_l, q_s].
    pub rms_slope: f64,
    /// Relative tolerance of the integrals.
    pub tolerance: f64,
    /// u0 of the low-load law ū ≈ u0 ln(p_ref/σ0).
    pub low_load_length: f64,
    /// Bound on the absolute error of u0.
    pub low_load_length_error_bound: f64,
    /// p_ref of the low-load law.
    pub reference_pressure: f64,
    /// Bound on the absolute error of p_ref.
    pub reference_pressure_error_bound: f64,
    /// Elastic energy per nominal area at full contact.
    pub full_contact_energy: f64,
    /// Bound on its absolute error.
    pub full_contact_energy_error_bound: f64,
    /// One point per pressure.
    pub points: Vec<SeparationPoint>,
    /// The curve for the figure (log-spaced pressures), when one is drawn.
    #[serde(skip)]
    pub plot_points: Vec<SeparationPoint>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

fn relative(err: f64, value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        0.0
    } else {
        (err / value).abs()
    }
}

impl Tabulate for SeparationReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "separation",
            format!(
                "{}Mean interfacial separation against load (Persson, Phys. Rev. Lett. 99, 125502 (2007)), E* = {}",
                surface_prefix(&self.surface),
                number(self.contact_modulus, 6)
            ),
        )
        .scalar("rms_height", "rms height h_rms", self.rms_height)
        .scalar("rms_slope", "rms slope h'_rms", self.rms_slope)
        .scalar("low_load_length", "u0 of ū ≈ u0 ln(σ_ref/σ0)", self.low_load_length)
        .scalar("reference_pressure", "σ_ref", self.reference_pressure)
        .scalar("full_contact_energy", "U_el at full contact", self.full_contact_energy)
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(self.points.iter().map(|p| p.nominal_pressure)),
        )
        .column("mean_separation", "ū")
        .column("stiffness", "K = −dσ0/dū")
        .column("elastic_energy", "U_el")
        .column_digits("relative_error_bound", "largest relative bound", 2);
        for p in &self.points {
            let rel = relative(p.mean_separation_error_bound, p.mean_separation)
                .max(relative(p.stiffness_error_bound, p.stiffness))
                .max(relative(p.elastic_energy_error_bound, p.elastic_energy));
            t.push(vec![
                p.nominal_pressure.into(),
                p.mean_separation.into(),
                p.stiffness.into(),
                p.elastic_energy.into(),
                rel.into(),
            ]);
        }
        vec![t]
    }
}

//! What `kappa` computed, with its table.

use serde::Serialize;

use crate::table::{input_digits, surface_prefix, Table, Tabulate};

/// The linear low-load contact fractions at one pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct LinearPoint {
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// κ_Bush σ0/(E* h'_rms).
    pub contact_fraction_bush_linear: f64,
    /// κ_Persson σ0/(E* h'_rms).
    pub contact_fraction_persson_linear: f64,
}

/// κ of the linear law A/A0 = κ σ0/(E* h'_rms) (`persson kappa`, scene output `kappa`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct KappaReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// √(2π), Bush, Gibson & Thomas, Wear 35, 87 (1975).
    pub kappa_bush: f64,
    /// √(8/π), Persson, J. Chem. Phys. 115, 3840 (2001).
    pub kappa_persson: f64,
    /// rms slope over [q_l, q_s] (with a surface).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rms_slope: Option<f64>,
    /// The linear fractions at the pressures (with a surface).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<LinearPoint>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

impl Tabulate for KappaReport {
    fn tables(&self) -> Vec<Table> {
        let title = format!(
            "{}κ of the low-load law A/A0 = κ σ0/(E* h'_rms): Bush, Gibson & Thomas (1975) \
             κ = √(2π); Persson (2001) κ = √(8/π)",
            surface_prefix(&self.surface)
        );
        if self.points.is_empty() {
            let mut t = Table::new("kappa", title)
                .column("kappa_bush", "κ Bush")
                .column("kappa_persson", "κ Persson");
            t.push(vec![self.kappa_bush.into(), self.kappa_persson.into()]);
            return vec![t];
        }
        let mut t = Table::new("kappa", title)
            .scalar("kappa_bush", "κ Bush", self.kappa_bush)
            .scalar("kappa_persson", "κ Persson", self.kappa_persson)
            .scalar("rms_slope", "rms slope h'_rms", self.rms_slope)
            .column_digits(
                "nominal_pressure",
                "σ0",
                input_digits(self.points.iter().map(|p| p.nominal_pressure)),
            )
            .column("contact_fraction_bush_linear", "A/A0 Bush linear")
            .column("contact_fraction_persson_linear", "A/A0 Persson linear");
        for p in &self.points {
            t.push(vec![
                p.nominal_pressure.into(),
                p.contact_fraction_bush_linear.into(),
                p.contact_fraction_persson_linear.into(),
            ]);
        }
        vec![t]
    }
}

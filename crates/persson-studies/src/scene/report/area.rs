//! Load curves and magnification curves of the theories: A/A0 against σ0
//! (one theory or all of them), G(ζ) and A/A0 against ζ, and κ.

use serde::Serialize;

use crate::area::theory_heading;
use crate::table::{input_digits, number, surface_prefix, Table, Tabulate};
use persson::corrected::TheoryPoint;
use persson::theory::AreaPoint;

use super::super::schema::TheoryName;

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

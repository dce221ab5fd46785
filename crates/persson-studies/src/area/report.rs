//! What `area` computed: a load curve, with its table.

use serde::Serialize;

use persson::corrected::TheoryPoint;
use persson::theory::AreaPoint;

use crate::input::TheoryName;
use crate::table::{input_digits, number, surface_prefix, Table, Tabulate};

/// One point of a load curve: G, A/A0 of the chosen theory and the linear laws.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct LoadPoint {
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// Magnification ζ.
    pub zeta: f64,
    /// G(ζ).
    pub g: f64,
    /// Bound on the absolute error of G.
    pub g_error_bound: f64,
    /// G_e of the theory (= G for the original theory; none for an asperity theory).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effective_g: Option<f64>,
    /// A/A0 of the theory.
    pub contact_fraction: f64,
    /// 1 − A/A0, computed without cancellation.
    pub non_contact_fraction: f64,
    /// Bound on the absolute error of A/A0.
    pub error_bound: f64,
    /// rms slope of the roughness up to ζ.
    pub rms_slope: f64,
    /// Bush–Gibson–Thomas linear law κ σ0/(E* h'_rms), κ = √(2π).
    pub contact_fraction_bush_linear: f64,
    /// Persson's linear law, κ = √(8/π).
    pub contact_fraction_persson_linear: f64,
    /// An asperity theory: the separation d of the flat from the mean plane, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separation: Option<f64>,
    /// An asperity theory (GW, BGT): contacts per unit nominal area, 1/m².
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_number_density: Option<f64>,
    /// An asperity theory: Persson's (original) A/A0 at the same σ0, beside it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_fraction_original: Option<f64>,
}

impl LoadPoint {
    /// The original theory's point, with G_e and (a corrected theory) A/A0 from `theory`.
    pub(crate) fn new(p: &AreaPoint, theory: &TheoryPoint, original: bool) -> Self {
        let (contact_fraction, non_contact_fraction, error_bound) = if original {
            (p.contact_fraction, p.non_contact_fraction, p.error_bound)
        } else {
            (
                theory.contact_fraction,
                theory.non_contact_fraction,
                theory.error_bound,
            )
        };
        LoadPoint {
            nominal_pressure: p.nominal_pressure,
            zeta: p.zeta,
            g: p.g,
            g_error_bound: p.g_error_bound,
            effective_g: Some(theory.effective_g),
            contact_fraction,
            non_contact_fraction,
            error_bound,
            rms_slope: p.rms_slope,
            contact_fraction_bush_linear: p.contact_fraction_bush_linear,
            contact_fraction_persson_linear: p.contact_fraction_persson_linear,
            separation: None,
            contact_number_density: None,
            contact_fraction_original: None,
        }
    }

    /// Persson's point `p` with the A/A0 of an asperity theory's point `a`
    /// (relative error bound `relative_error`).
    pub(crate) fn asperity(
        p: &AreaPoint,
        a: &persson::asperity::AsperityPoint,
        relative_error: f64,
    ) -> Self {
        LoadPoint {
            nominal_pressure: p.nominal_pressure,
            zeta: p.zeta,
            g: p.g,
            g_error_bound: p.g_error_bound,
            effective_g: None,
            contact_fraction: a.contact_fraction,
            non_contact_fraction: 1.0 - a.contact_fraction,
            error_bound: relative_error * a.contact_fraction,
            rms_slope: p.rms_slope,
            contact_fraction_bush_linear: p.contact_fraction_bush_linear,
            contact_fraction_persson_linear: p.contact_fraction_persson_linear,
            separation: Some(a.separation),
            contact_number_density: a.contact_number_density,
            contact_fraction_original: Some(p.contact_fraction),
        }
    }
}

/// A/A0 against nominal pressure (`persson area`, scene output `area`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AreaReport {
    /// What the surface is (the built-in example says so), if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// E*.
    pub contact_modulus: f64,
    /// rms height over [q_l, q_s].
    pub rms_height: f64,
    /// rms slope over [q_l, q_s].
    pub rms_slope: f64,
    /// √(2π), Bush, Gibson & Thomas (1975).
    pub kappa_bush: f64,
    /// √(8/π), Persson (2001).
    pub kappa_persson: f64,
    /// The theory of `contact_fraction`.
    pub theory: TheoryName,
    /// Its γ (none for the original theory).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// The theory's low-load κ (none for GW and the overlap model).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kappa: Option<f64>,
    /// The overlap model: the hardness σY of its load law.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// An asperity theory: the surface's moments and summit statistics
    /// (their keys at the top level of the report).
    #[serde(flatten)]
    pub asperity: Option<crate::asperity::AsperityParameters>,
    /// Magnification ζ.
    pub zeta: f64,
    /// One point per pressure.
    pub points: Vec<LoadPoint>,
    /// A/A0 of the original theory at each pressure (for the figure of a
    /// corrected theory).
    #[serde(skip)]
    pub original_contact_fraction: Vec<f64>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

pub(crate) fn theory_heading(theory: TheoryName, gamma: Option<f64>) -> String {
    match gamma {
        Some(g) => format!("{theory} theory, γ = {}", number(g, 6)),
        None => format!("{theory} theory"),
    }
}

impl Tabulate for AreaReport {
    fn tables(&self) -> Vec<Table> {
        if self.theory.is_asperity() {
            return vec![self.asperity_table()];
        }
        let mut t = Table::new(
            "area",
            format!(
                "{}Contact area against nominal pressure ({}), E* = {}, ζ = {}",
                surface_prefix(&self.surface),
                theory_heading(self.theory, self.gamma),
                number(self.contact_modulus, 6),
                number(self.zeta, 6)
            ),
        )
        .scalar("rms_height", "rms height h_rms", self.rms_height)
        .scalar("rms_slope", "rms slope h'_rms", self.rms_slope)
        .scalar("kappa_bush", "κ Bush", self.kappa_bush)
        .scalar("kappa_persson", "κ Persson", self.kappa_persson)
        .scalar("kappa", "κ of the theory", self.kappa)
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(self.points.iter().map(|p| p.nominal_pressure)),
        )
        .column("g", "G")
        .column("effective_g", "G_e")
        .column_digits("contact_fraction", "A/A0", 10)
        .column_digits("error_bound", "± bound", 2)
        .column("contact_fraction_bush_linear", "A/A0 Bush linear")
        .column("contact_fraction_persson_linear", "A/A0 Persson linear");
        for p in &self.points {
            t.push(vec![
                p.nominal_pressure.into(),
                p.g.into(),
                p.effective_g.into(),
                p.contact_fraction.into(),
                p.error_bound.into(),
                p.contact_fraction_bush_linear.into(),
                p.contact_fraction_persson_linear.into(),
            ]);
        }
        vec![t]
    }
}

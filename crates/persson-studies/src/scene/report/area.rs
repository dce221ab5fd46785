//! Load curves and magnification curves of the theories: A/A0 against σ0
//! (one theory or all of them), G(ζ) and A/A0 against ζ, and κ.

use serde::Serialize;

use crate::table::{number, Table, Tabulate};
use persson::corrected::TheoryPoint;
use persson::theory::AreaPoint;

use super::super::schema::TheoryName;

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

/// Significant digits that print every input as given (its shortest
/// round-trip form): `1e4`, `3e8`, `4.26e8`.
pub(crate) fn input_digits(values: impl IntoIterator<Item = f64>) -> usize {
    values
        .into_iter()
        .filter(|v| v.is_finite() && *v != 0.0)
        .map(|v| {
            let s = format!("{:e}", v.abs());
            s.split('e')
                .next()
                .unwrap_or("")
                .chars()
                .filter(char::is_ascii_digit)
                .count()
        })
        .max()
        .unwrap_or(1)
        .max(1)
}

fn theory_heading(theory: TheoryName, gamma: Option<f64>) -> String {
    match gamma {
        Some(g) => format!("{theory} theory, γ = {}", number(g, 6)),
        None => format!("{theory} theory"),
    }
}

pub(crate) fn surface_prefix(surface: &Option<String>) -> String {
    surface.as_ref().map_or(String::new(), |s| format!("{s}\n"))
}

impl Tabulate for AreaReport {
    fn tables(&self) -> Vec<Table> {
        if crate::asperity::is_asperity(self.theory) {
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

//! Typed reports: what each scene output (and the subcommand of the same
//! name) computed. Every report is `Serialize` (its JSON) and [`Tabulate`]
//! (its text and CSV tables); the figures are drawn from them alone.

use serde::Serialize;

use crate::table::{number, Cell, Table, Tabulate};
use persson::corrected::TheoryPoint;
use persson::separation::SeparationPoint;
use persson::theory::AreaPoint;

use super::schema::TheoryName;

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
    /// G_e of the theory (= G for the original theory).
    pub effective_g: f64,
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
            effective_g: theory.effective_g,
            contact_fraction,
            non_contact_fraction,
            error_bound,
            rms_slope: p.rms_slope,
            contact_fraction_bush_linear: p.contact_fraction_bush_linear,
            contact_fraction_persson_linear: p.contact_fraction_persson_linear,
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
    /// The theory's low-load κ.
    pub kappa: f64,
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
fn input_digits(values: impl IntoIterator<Item = f64>) -> usize {
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

fn surface_prefix(surface: &Option<String>) -> String {
    surface.as_ref().map_or(String::new(), |s| format!("{s}\n"))
}

impl Tabulate for AreaReport {
    fn tables(&self) -> Vec<Table> {
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

/// One stress distribution: dimensionless (σ/σH, σH·P) at a given G, or in
/// the pressure unit (σ, P) at a magnification ζ.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct StressCurveReport {
    /// G of this curve.
    pub g: f64,
    /// ζ (pressure-unit curves only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zeta: Option<f64>,
    /// τ = (σ0/σH)² G (dimensionless curves).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tau: Option<f64>,
    /// σ/σH (dimensionless curves).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub sigma_ratio: Vec<f64>,
    /// σH·P(σ) (dimensionless curves).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub scaled_density: Vec<f64>,
    /// σ in the pressure unit (pressure-unit curves).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub sigma: Vec<f64>,
    /// P(σ, ζ) in 1/(pressure unit) (pressure-unit curves).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub density: Vec<f64>,
    /// A/A0, total (elastic + plastic).
    pub contact_fraction: f64,
    /// A_el/A0.
    pub elastic_fraction: f64,
    /// A_pl/A0.
    pub plastic_fraction: f64,
    /// 1 − A/A0 (dimensionless curves).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub non_contact_fraction: Option<f64>,
    /// Bound on the absolute error of σH·P (dimensionless; divided by σH, the
    /// bound on P of a pressure-unit curve).
    pub scaled_density_error_bound: f64,
    /// Bound on the absolute error of A_el/A0.
    pub elastic_fraction_error_bound: f64,
    /// Bound on the absolute error of A_pl/A0.
    pub plastic_fraction_error_bound: f64,
    /// How the density and the fractions were computed.
    pub method: persson::stress::StressMethod,
}

impl StressCurveReport {
    /// The largest of the three error bounds: of σH·P, A_el/A0 and A_pl/A0.
    pub fn error_bound(&self) -> f64 {
        self.scaled_density_error_bound
            .max(self.elastic_fraction_error_bound)
            .max(self.plastic_fraction_error_bound)
    }
}

/// Stress distributions P(σ, ζ) (`persson stress`, scene output `stress`;
/// Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002)).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct StressReport {
    /// Start condition (`flat`, `hertz`, `cylinder`, `tabulated`).
    pub start: persson::stress::StartKind,
    /// σ0/σH of the start.
    pub mean_ratio: f64,
    /// σH (pressure-unit curves).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub peak_pressure: Option<f64>,
    /// σ0 = (σ0/σH) σH, the nominal mean pressure of the start (pressure-unit curves).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nominal_pressure: Option<f64>,
    /// Contact radius a (ball) or half-width a (cylinder) of the smooth
    /// Hertz contact, m (pressure-unit curves of a ball or a cylinder).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_radius: Option<f64>,
    /// σY/σH (dimensionless curves; absent: elastic).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub yield_ratio: Option<f64>,
    /// σY (pressure-unit curves; absent: elastic).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// One curve per G or ζ.
    pub curves: Vec<StressCurveReport>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

impl StressReport {
    /// Whether σ is in the pressure unit (else σ/σH).
    pub fn physical(&self) -> bool {
        self.peak_pressure.is_some()
    }
}

impl Tabulate for StressReport {
    fn tables(&self) -> Vec<Table> {
        let plastic = match (self.yield_ratio, self.yield_stress) {
            (Some(y), _) => format!("σY/σH = {}", number(y, 6)),
            (_, Some(y)) => format!("σY = {}", number(y, 6)),
            _ => "elastic".into(),
        };
        self.curves
            .iter()
            .map(|c| {
                let (name, at) = match c.zeta {
                    Some(z) => (
                        format!("stress_zeta{}", number(z, 6)),
                        format!("ζ = {}, G = {}", number(z, 6), number(c.g, 6)),
                    ),
                    None => (
                        format!("stress_G{}", number(c.g, 6)),
                        format!("G = {}", number(c.g, 6)),
                    ),
                };
                let unit = match self.peak_pressure {
                    Some(sh) => format!("σH = {}; σ in the pressure unit", number(sh, 6)),
                    None => "σ in units of σH".into(),
                };
                let mut t = Table::new(
                    name,
                    format!(
                        "Stress distribution P(σ), {} start, {at}, {plastic}; {unit}\n  method: {}",
                        self.start, c.method
                    ),
                )
                .scalar("contact_fraction", "A/A0", c.contact_fraction)
                .scalar("elastic_fraction", "A_el/A0", c.elastic_fraction)
                .scalar("plastic_fraction", "A_pl/A0", c.plastic_fraction)
                .scalar("error_bound", "error bound", c.error_bound());
                if let Some(sh) = self.peak_pressure {
                    t = t.scalar("peak_pressure", "σH", sh);
                }
                if let Some(s0) = self.nominal_pressure {
                    t = t.scalar("nominal_pressure", "σ0", s0);
                }
                if let Some(a) = self.contact_radius {
                    let label = if self.start == persson::stress::StartKind::Cylinder {
                        "half-width a (m)"
                    } else {
                        "contact radius a (m)"
                    };
                    t = t.scalar("contact_radius", label, a);
                }
                if let Some(y) = self.yield_stress {
                    t = t.scalar("yield_stress", "σY", y);
                }
                if let Some(tau) = c.tau {
                    t = t.scalar("tau", "τ = (σ0/σH)² G", tau);
                }
                let (s, p) = if c.zeta.is_some() {
                    t = t.column("sigma", "σ").column("density", "P(σ)");
                    (&c.sigma, &c.density)
                } else {
                    t = t
                        .column("sigma_ratio", "σ/σH")
                        .column("scaled_density", "σH P(σ)");
                    (&c.sigma_ratio, &c.scaled_density)
                };
                for (s, p) in s.iter().zip(p) {
                    t.push(vec![Cell::Num(*s), Cell::Num(*p)]);
                }
                t
            })
            .collect()
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

/// FFT-BEM Hertz convergence (scene output `bem_hertz`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemHertzReport {
    /// Boundary condition.
    pub boundary: super::schema::BoundaryName,
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

/// The spectrum's moments, a power-law fit and C(q) (`persson spectrum`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SpectrumReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// Lower cut-off q_l.
    pub q_l: f64,
    /// Upper cut-off q_s.
    pub q_s: f64,
    /// Lower end of the band of the moments.
    pub q_min: f64,
    /// Upper end of the band of the moments.
    pub q_max: f64,
    /// rms height over the band.
    pub rms_height: f64,
    /// Its error bound.
    pub rms_height_error_bound: f64,
    /// rms slope over the band.
    pub rms_slope: f64,
    /// Its error bound.
    pub rms_slope_error_bound: f64,
    /// rms curvature over the band.
    pub rms_curvature: f64,
    /// Its error bound.
    pub rms_curvature_error_bound: f64,
    /// Power law C = prefactor q^exponent fitted over the upper half (in log q) of [q_l, q_s].
    pub power_law_fit: PowerLawFit,
    /// C(q) at log-spaced q.
    pub table: Vec<SpectrumPoint>,
    /// C(q) on a fine grid, for the figure.
    #[serde(skip)]
    pub curve: Vec<SpectrumPoint>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

/// A power law fitted to C(q).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PowerLawFit {
    /// Prefactor.
    pub prefactor: f64,
    /// Exponent −2(H + 1).
    pub exponent: f64,
    /// H = −exponent/2 − 1.
    pub hurst: f64,
    /// Lower end of the fit.
    pub q_min: f64,
    /// Upper end of the fit.
    pub q_max: f64,
}

/// One point of C(q).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SpectrumPoint {
    /// Wavevector q.
    pub q: f64,
    /// C(q), Persson's normalisation.
    pub c: f64,
}

impl Tabulate for SpectrumReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "spectrum",
            format!(
                "{}Spectrum (Persson's normalisation), moments over q in [{}, {}] 1/m",
                surface_prefix(&self.surface),
                number(self.q_min, 6),
                number(self.q_max, 6)
            ),
        )
        .scalar("q_l", "q_l", self.q_l)
        .scalar("q_s", "q_s", self.q_s)
        .scalar("rms_height", "rms height h_rms", self.rms_height)
        .scalar("rms_slope", "rms slope h'_rms", self.rms_slope)
        .scalar("rms_curvature", "rms curvature h''_rms", self.rms_curvature)
        .scalar(
            "exponent",
            "fitted exponent of C(q)",
            self.power_law_fit.exponent,
        )
        .scalar("hurst", "fitted H", self.power_law_fit.hurst)
        .column("q", "q")
        .column("c", "C(q)");
        for p in &self.table {
            t.push(vec![p.q.into(), p.c.into()]);
        }
        vec![t]
    }
}

/// What a scene computed: one entry per output asked for.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SceneReport {
    /// The scene's name.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// The scene's description.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// Spectrum summary.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spectrum: Option<SpectrumReport>,
    /// Load curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub area: Option<AreaReport>,
    /// Magnification curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub magnification: Option<MagnificationReport>,
    /// κ values.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kappa: Option<KappaReport>,
    /// Corrected-theory load curves.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theories: Option<TheoriesReport>,
    /// Mean separation against load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separation: Option<SeparationReport>,
    /// Stress distributions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stress: Option<StressReport>,
    /// FFT-BEM rough contact (feature `bem`).
    #[cfg(feature = "bem")]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem: Option<persson::bem::rough::RoughReport>,
    /// FFT-BEM Hertz convergence.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_hertz: Option<BemHertzReport>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

impl SceneReport {
    /// Gather the warnings of every output into the scene's, once each.
    pub(crate) fn collect_warnings(&mut self) {
        let lists = [
            self.spectrum.as_ref().map(|r| &r.warnings),
            self.kappa.as_ref().map(|r| &r.warnings),
            self.area.as_ref().map(|r| &r.warnings),
            self.magnification.as_ref().map(|r| &r.warnings),
            self.theories.as_ref().map(|r| &r.warnings),
            self.separation.as_ref().map(|r| &r.warnings),
            self.stress.as_ref().map(|r| &r.warnings),
        ];
        let mut all = std::mem::take(&mut self.warnings);
        for w in lists.into_iter().flatten().flatten() {
            crate::warning::push(&mut all, Some(w.clone()));
        }
        #[cfg(feature = "bem")]
        if let Some(r) = &self.bem {
            for w in crate::warning::of_rough(r) {
                crate::warning::push(&mut all, Some(w));
            }
        }
        self.warnings = all;
    }
}

impl Tabulate for SceneReport {
    fn tables(&self) -> Vec<Table> {
        let mut out = Vec::new();
        #[cfg(feature = "bem")]
        let bem = self.bem.as_ref().map(|r| r as &dyn Tabulate);
        #[cfg(not(feature = "bem"))]
        let bem = None;
        let parts: [Option<&dyn Tabulate>; 9] = [
            self.spectrum.as_ref().map(|r| r as &dyn Tabulate),
            self.kappa.as_ref().map(|r| r as &dyn Tabulate),
            self.area.as_ref().map(|r| r as &dyn Tabulate),
            self.magnification.as_ref().map(|r| r as &dyn Tabulate),
            self.theories.as_ref().map(|r| r as &dyn Tabulate),
            self.separation.as_ref().map(|r| r as &dyn Tabulate),
            self.stress.as_ref().map(|r| r as &dyn Tabulate),
            bem,
            self.bem_hertz.as_ref().map(|r| r as &dyn Tabulate),
        ];
        for p in parts.into_iter().flatten() {
            out.extend(p.tables());
        }
        out
    }
}

//! Stress distributions P(σ, ζ): dimensionless at given G, or in the
//! pressure unit at given magnifications.

use serde::Serialize;

use crate::table::{number, Cell, Table, Tabulate};

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

//! What passes through the interface: contact conductance and the leak rate
//! of a seal, from Persson's theory and (when asked) from the FFT-BEM.

use serde::Serialize;

cfg_feature! {
    "bem",
    mod rough;
    pub use rough::RoughTransportReport;
}

use crate::table::{number, Table, Tabulate};
use persson::conductance::ConductancePoint;
use persson::leakage::{
    CriticalJunctionPoint, EffectiveMediumPoint, FlowDirection, Fluid, LeakStatus,
};

use crate::table::{input_digits, surface_prefix};

/// Contact conductance against load (`persson conductance`, scene output
/// `conductance`): Barber's identity on the stiffness of Persson's theory,
/// and the gap term over P(u); beside them the FFT-BEM's when asked.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ConductanceReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// E*, Pa.
    pub contact_modulus: f64,
    /// rms height over [q_l, q_s], m.
    pub rms_height: f64,
    /// rms slope over [q_l, q_s].
    pub rms_slope: f64,
    /// Relative tolerance of the wavevector integrals.
    pub tolerance: f64,
    /// κ1, W/(m K).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conductivity: Option<f64>,
    /// κ2, W/(m K).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conductivity2: Option<f64>,
    /// ρ1, Ω m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resistivity: Option<f64>,
    /// ρ2, Ω m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resistivity2: Option<f64>,
    /// κ_gas of the gas law, W/(m K).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gas_conductivity: Option<f64>,
    /// ℓ of the gas law, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_free_path: Option<f64>,
    /// The user's α(u) table, (m, W/(m² K)).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub gap_table: Vec<(f64, f64)>,
    /// One point per pressure (theory).
    pub points: Vec<ConductancePoint>,
    /// The FFT-BEM at the same pressures, when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem: Option<BemTransportReport>,
    /// Remarks on the input; the CLI prints them on stderr and in `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

/// Leak rate of a static seal against load (`persson leakage`, scene output
/// `leakage`): the critical junction and the effective medium of Persson's
/// theory; beside them Reynolds flow on the FFT-BEM's gap when asked.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct LeakageReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// E*, Pa.
    pub contact_modulus: f64,
    /// rms height over [q_l, q_s], m.
    pub rms_height: f64,
    /// rms slope over [q_l, q_s].
    pub rms_slope: f64,
    /// Relative tolerance of the wavevector integrals.
    pub tolerance: f64,
    /// `liquid` or `gas`.
    pub fluid: Fluid,
    /// η, Pa s.
    pub viscosity: f64,
    /// ΔP of a liquid, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_drop: Option<f64>,
    /// P_a of a gas, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inlet_pressure: Option<f64>,
    /// P_b of a gas, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outlet_pressure: Option<f64>,
    /// L_x, m.
    pub seal_width: f64,
    /// L_y, m.
    pub seal_length: f64,
    /// a_c of the critical junction.
    pub percolation_threshold: f64,
    /// One point per pressure (both theories).
    pub points: Vec<LeakagePoint>,
    /// The FFT-BEM and Reynolds flow at the same pressures, when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem: Option<BemTransportReport>,
    /// Remarks on the input; the CLI prints them on stderr and in `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

/// Both theories of the leak rate at one load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct LeakagePoint {
    /// σ0, Pa.
    pub nominal_pressure: f64,
    /// Persson & Yang (2008), Lorenz & Persson (2009).
    pub critical_junction: CriticalJunctionPoint,
    /// Lorenz & Persson (2010), 2-D Bruggeman.
    pub effective_medium: EffectiveMediumPoint,
}

/// The FFT-BEM's transport values at the pressures of a theory's curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemTransportReport {
    /// Grid side N.
    pub grid: usize,
    /// Side L, m.
    pub size: f64,
    /// Seed of the synthesised surface (absent for a height map).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// rms height of the surface on the grid, m.
    pub surface_rms_height: f64,
    /// rms slope of the surface on the grid.
    pub surface_rms_slope: f64,
    /// One point per pressure.
    pub points: Vec<BemTransportPoint>,
}

/// The BEM's values at one load. The error bounds are those of the solve
/// (CG residuals, conservation defect); the discretisation error of the
/// grid is not in them (see `persson compare`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemTransportPoint {
    /// σ0, Pa.
    pub nominal_pressure: f64,
    /// A/A0 of the solution.
    pub contact_fraction: f64,
    /// Mean gap, m.
    pub mean_separation: f64,
    /// K/A0 from a linear solve on the converged contact set, Pa/m.
    pub stiffness: f64,
    /// Bound on the CG error of K/A0.
    pub stiffness_error_bound: f64,
    /// h_c, W/(m² K).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal_conductance: Option<f64>,
    /// Bound on the solve's error of h_c.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal_conductance_error_bound: Option<f64>,
    /// h_e, S/m².
    #[serde(skip_serializing_if = "Option::is_none")]
    pub electrical_conductance: Option<f64>,
    /// Bound on the solve's error of h_e.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub electrical_conductance_error_bound: Option<f64>,
    /// h_gap: mean of α(g) over the nodes out of contact, W/(m² K).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_conductance: Option<f64>,
    /// Whether the non-contact region percolates along x or along y.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub percolates: Option<bool>,
    /// σ_eff, the mean of the flows along x and y, m³/(Pa s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effective_flow_conductivity: Option<f64>,
    /// Bound on the solve's error of σ_eff.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effective_flow_conductivity_error_bound: Option<f64>,
    /// Q = (L_y/L_x) σ_eff Δ, m³/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leak_rate: Option<f64>,
    /// Bound on the solve's error of Q.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leak_rate_error_bound: Option<f64>,
    /// The flow along x and along y.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub flows: Vec<BemFlow>,
}

/// Reynolds flow on the BEM's gap in one direction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemFlow {
    /// `x` or `y`.
    pub direction: FlowDirection,
    /// Whether the non-contact region connects inlet and outlet.
    pub percolates: bool,
    /// σ_eff, m³/(Pa s).
    pub effective_flow_conductivity: f64,
    /// Bound on its error (conservation defect + rounding).
    pub effective_flow_conductivity_error_bound: f64,
}

fn relative(err: f64, value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        0.0
    } else {
        (err / value).abs()
    }
}

/// theory / BEM, empty where the BEM's value is 0 or absent.
fn ratio(theory: Option<f64>, bem: Option<f64>) -> Option<f64> {
    match (theory, bem) {
        (Some(t), Some(b)) if b > 0.0 => Some(t / b),
        _ => None,
    }
}

impl Tabulate for ConductanceReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "conductance",
            format!(
                "{}Contact conductance against load (Barber's identity on Persson's stiffness; gap over P(u)), E* = {}",
                surface_prefix(&self.surface),
                number(self.contact_modulus, 6)
            ),
        )
        .scalar("rms_height", "rms height h_rms", self.rms_height)
        .scalar("rms_slope", "rms slope h'_rms", self.rms_slope)
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(self.points.iter().map(|p| p.nominal_pressure)),
        )
        .column("stiffness", "K/A0 = −dσ0/dū");
        let th = self.conductivity.is_some();
        let el = self.resistivity.is_some();
        let gap = self.gas_conductivity.is_some() || !self.gap_table.is_empty();
        if th {
            t = t.column("thermal_conductance", "h_c W/(m² K)");
        }
        if el {
            t = t.column("electrical_conductance", "h_e S/m²");
        }
        if gap {
            t = t.column("gap_conductance", "h_gap W/(m² K)");
        }
        t = t.column_digits("relative_error_bound", "largest relative bound", 2);
        for p in &self.points {
            let mut row = vec![p.nominal_pressure.into(), p.stiffness.into()];
            let mut rel = relative(p.stiffness_error_bound, p.stiffness);
            let mut add = |on: bool, v: Option<f64>, e: Option<f64>| {
                if on {
                    row.push(v.into());
                    rel = rel.max(relative(e.unwrap_or(0.0), v.unwrap_or(0.0)));
                }
            };
            add(th, p.thermal_conductance, p.thermal_conductance_error_bound);
            add(
                el,
                p.electrical_conductance,
                p.electrical_conductance_error_bound,
            );
            add(gap, p.gap_conductance, p.gap_conductance_error_bound);
            row.push(rel.into());
            t.push(row);
        }
        let mut out = vec![t];
        if let Some(b) = &self.bem {
            out.push(self.bem_table(b, gap));
        }
        out
    }
}

impl ConductanceReport {
    /// The BEM's stiffness and gap conductance with the theory's over them.
    fn bem_table(&self, b: &BemTransportReport, gap: bool) -> Table {
        let mut t = Table::new(
            "conductance_bem",
            format!(
                "FFT-BEM {}², seed {}: stiffness (linear solve on the contact set) and gap conductance; theory/BEM",
                b.grid,
                b.seed.map_or("–".to_string(), |s| s.to_string())
            ),
        )
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(b.points.iter().map(|p| p.nominal_pressure)),
        )
        .column("bem_contact_fraction", "A/A0 BEM")
        .column("bem_stiffness", "K/A0 BEM")
        .column_digits("stiffness_ratio", "K theory/BEM", 3);
        if gap {
            t = t.column("bem_gap_conductance", "h_gap BEM").column_digits(
                "gap_conductance_ratio",
                "h_gap theory/BEM",
                3,
            );
        }
        for (p, th) in b.points.iter().zip(&self.points) {
            let mut row = vec![
                p.nominal_pressure.into(),
                p.contact_fraction.into(),
                p.stiffness.into(),
                ratio(Some(th.stiffness), Some(p.stiffness)).into(),
            ];
            if gap {
                row.push(p.gap_conductance.into());
                row.push(ratio(th.gap_conductance, p.gap_conductance).into());
            }
            t.push(row);
        }
        t
    }
}

fn status(s: LeakStatus) -> &'static str {
    match s {
        LeakStatus::Leaking => "leaking",
        LeakStatus::Sealed => "sealed",
    }
}

impl Tabulate for LeakageReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "leakage",
            format!(
                "{}Leak rate against load: critical junction (a_c = {}) and effective medium, E* = {}, η = {}, L_y/L_x = {}",
                surface_prefix(&self.surface),
                number(self.percolation_threshold, 3),
                number(self.contact_modulus, 6),
                number(self.viscosity, 6),
                number(self.seal_length / self.seal_width, 6)
            ),
        )
        .scalar("rms_height", "rms height h_rms", self.rms_height)
        .scalar("rms_slope", "rms slope h'_rms", self.rms_slope)
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(self.points.iter().map(|p| p.nominal_pressure)),
        )
        .column("contact_fraction", "A/A0")
        .column("critical_zeta", "ζ_c")
        .column("critical_separation", "u1(ζ_c) m")
        .column("leak_rate_critical_junction", "Q junction m³/s")
        .column("leak_rate_effective_medium", "Q medium m³/s")
        .column_digits("relative_error_bound", "largest relative bound", 2)
        .omittable(1);
        for p in &self.points {
            let (c, e) = (&p.critical_junction, &p.effective_medium);
            let rel = relative(c.leak_rate_error_bound, c.leak_rate)
                .max(relative(e.leak_rate_error_bound, e.leak_rate));
            t.push(vec![
                p.nominal_pressure.into(),
                c.contact_fraction.into(),
                c.critical_zeta.into(),
                match c.status {
                    LeakStatus::Leaking => c.critical_separation.into(),
                    LeakStatus::Sealed => status(c.status).into(),
                },
                c.leak_rate.into(),
                e.leak_rate.into(),
                rel.into(),
            ]);
        }
        let mut out = vec![t];
        if let Some(b) = &self.bem {
            out.push(self.bem_table(b));
        }
        out
    }
}

impl LeakageReport {
    /// Reynolds flow on the BEM's gap with the theories over it.
    fn bem_table(&self, b: &BemTransportReport) -> Table {
        let mut t = Table::new(
            "leakage_bem",
            format!(
                "FFT-BEM {}², seed {}: Reynolds flow on the gap (mean of x and y); theory/BEM",
                b.grid,
                b.seed.map_or("–".to_string(), |s| s.to_string())
            ),
        )
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(b.points.iter().map(|p| p.nominal_pressure)),
        )
        .column("bem_contact_fraction", "A/A0 BEM")
        .column("percolates", "percolates")
        .column("bem_leak_rate", "Q BEM m³/s")
        .column_digits("leak_rate_ratio_critical_junction", "junction/BEM", 3)
        .column_digits("leak_rate_ratio_effective_medium", "medium/BEM", 3);
        for (p, th) in b.points.iter().zip(&self.points) {
            let percolates = match p.percolates {
                Some(true) => "yes",
                Some(false) => "no",
                None => "–",
            };
            t.push(vec![
                p.nominal_pressure.into(),
                p.contact_fraction.into(),
                percolates.into(),
                p.leak_rate.into(),
                ratio(Some(th.critical_junction.leak_rate), p.leak_rate).into(),
                ratio(Some(th.effective_medium.leak_rate), p.leak_rate).into(),
            ]);
        }
        t
    }
}

/// The BEM's transport values per load, the columns present in the first point.
pub fn transport_table(points: &[BemTransportPoint]) -> Table {
    let first = points.first();
    let has = |f: &dyn Fn(&BemTransportPoint) -> bool| first.is_some_and(f);
    let th = has(&|p| p.thermal_conductance.is_some());
    let el = has(&|p| p.electrical_conductance.is_some());
    let gap = has(&|p| p.gap_conductance.is_some());
    let flow = has(&|p| p.leak_rate.is_some());
    let mut t = Table::new(
        "bem_transport",
        "FFT-BEM conductance (Barber's identity on the stiffness of a linear solve on the contact set) and Reynolds flow on the gap",
    )
    .column_digits(
        "nominal_pressure",
        "σ0",
        input_digits(points.iter().map(|p| p.nominal_pressure)),
    )
    .column("stiffness", "K/A0");
    if th {
        t = t.column("thermal_conductance", "h_c W/(m² K)");
    }
    if el {
        t = t.column("electrical_conductance", "h_e S/m²");
    }
    if gap {
        t = t.column("gap_conductance", "h_gap W/(m² K)");
    }
    if flow {
        t = t
            .column("percolates", "percolates")
            .column("effective_flow_conductivity", "σ_eff m³/(Pa s)")
            .omittable(1)
            .column("leak_rate", "Q m³/s");
    }
    for p in points {
        let mut row = vec![p.nominal_pressure.into(), p.stiffness.into()];
        for (on, v) in [
            (th, p.thermal_conductance),
            (el, p.electrical_conductance),
            (gap, p.gap_conductance),
        ] {
            if on {
                row.push(v.into());
            }
        }
        if flow {
            row.push(
                match p.percolates {
                    Some(true) => "yes",
                    Some(false) => "no",
                    None => "–",
                }
                .into(),
            );
            row.push(p.effective_flow_conductivity.into());
            row.push(p.leak_rate.into());
        }
        t.push(row);
    }
    t
}

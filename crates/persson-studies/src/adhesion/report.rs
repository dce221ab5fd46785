//! Adhesion from Persson's theory: the stickiness energy balance per
//! magnification, A/A0 against load (tension included) and the pull-off stress.

use serde::Serialize;

use crate::table::{number, Cell, Table, Tabulate};
use persson::adhesion::AreaEnhancement;
use persson::adhesion::{AdhesivePoint, PastewkaRobbins, Stickiness};

use crate::table::{input_digits, surface_prefix};

/// Adhesion against load and magnification (`persson adhesion`, scene output
/// `adhesion`; Persson & Tosatti, J. Chem. Phys. 115, 5597 (2001); Persson,
/// Eur. Phys. J. E 8, 385 (2002)).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AdhesionReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// E*.
    pub contact_modulus: f64,
    /// Δγ (J/m²).
    pub work_of_adhesion: f64,
    /// Whether Δγ acts on the true or the projected area.
    pub area_enhancement: AreaEnhancement,
    /// rms slope over [q_l, q_s].
    pub rms_slope: f64,
    /// Magnification ζ of the contact points.
    pub zeta: f64,
    /// Absolute tolerance of the contact fractions.
    pub tolerance: f64,
    /// σ_p = σ_a(ζ = 1), the largest tension the contact holds (unit of E*).
    pub pull_off_stress: f64,
    /// Bound on the absolute error of `pull_off_stress`.
    pub pull_off_stress_error_bound: f64,
    /// The full-contact energy balance per ζ and its verdict.
    pub stickiness: Stickiness,
    /// The Pastewka–Robbins criterion (when the adhesion range is given).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pastewka_robbins: Option<PastewkaRobbins>,
    /// One point per nominal pressure (may be ≤ 0).
    pub points: Vec<AdhesivePoint>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

fn yes_no(b: bool) -> Cell {
    Cell::Text(if b { "yes" } else { "no" }.into())
}

impl AdhesionReport {
    fn stickiness_table(&self) -> Table {
        let s = &self.stickiness;
        let transitions = if s.stickiness_transitions.is_empty() {
            Cell::Text("none".into())
        } else {
            Cell::Text(
                s.stickiness_transitions
                    .iter()
                    .map(|z| number(*z, 6))
                    .collect::<Vec<_>>()
                    .join(", "),
            )
        };
        let mut t = Table::new(
            "adhesion_stickiness",
            format!(
                "{}Stickiness: Δγ_eff(ζ) = Δγ A_true/A0 − U_el/A0 (Persson & Tosatti 2001), \
                 E* = {}, Δγ = {}",
                surface_prefix(&self.surface),
                number(self.contact_modulus, 6),
                number(self.work_of_adhesion, 6)
            ),
        )
        .scalar("sticky", "sticky at full magnification", yes_no(s.sticky))
        .scalar(
            "effective_interfacial_energy",
            "Δγ_eff(q_s/q_l)",
            Cell::Measured {
                value: s.effective_interfacial_energy,
                error: s.effective_interfacial_energy_error_bound,
            },
        )
        .scalar(
            "threshold_work_of_adhesion",
            "Δγ where Δγ_eff(q_s/q_l) = 0",
            s.threshold_work_of_adhesion,
        )
        .scalar(
            "stickiness_transitions",
            "ζ where Δγ_eff changes sign",
            transitions,
        );
        if let Some(pr) = &self.pastewka_robbins {
            t = t
                .scalar(
                    "stickiness_parameter",
                    "Pastewka–Robbins S (sticky when < 1)",
                    pr.stickiness_parameter,
                )
                .scalar(
                    "pastewka_robbins_threshold",
                    "Pastewka–Robbins Δγ where S = 1",
                    pr.threshold_work_of_adhesion,
                );
        }
        t = t
            .column("zeta", "ζ")
            .column("full_contact_energy", "U_el/A0")
            .column("true_area_ratio", "A_true/A0")
            .column("effective_interfacial_energy", "Δγ_eff")
            .column("sticky", "sticky");
        for p in &s.points {
            t.push(vec![
                p.zeta.into(),
                p.full_contact_energy.into(),
                p.true_area_ratio.into(),
                p.effective_interfacial_energy.into(),
                yes_no(p.sticky),
            ]);
        }
        t
    }

    fn contact_table(&self) -> Table {
        let mut t = Table::new(
            "adhesion",
            format!(
                "Adhesive contact area against nominal pressure (Persson 2002), ζ = {}",
                number(self.zeta, 6)
            ),
        )
        .scalar(
            "pull_off_stress",
            "pull-off stress σ_p",
            Cell::Measured {
                value: self.pull_off_stress,
                error: self.pull_off_stress_error_bound,
            },
        )
        .column_digits(
            "nominal_pressure",
            "σ0",
            input_digits(self.points.iter().map(|p| p.nominal_pressure)),
        )
        .column("contact_fraction", "A/A0")
        .column_digits("contact_fraction_error_bound", "bound", 2)
        .column("tensile_fraction", "A/A0 in tension")
        .column("detachment_stress", "σ_a(ζ)")
        .column("carried_pressure", "∫σP dσ")
        .omittable(1);
        for p in &self.points {
            t.push(vec![
                p.nominal_pressure.into(),
                p.contact_fraction.into(),
                p.contact_fraction_error_bound.into(),
                p.tensile_fraction.into(),
                p.detachment_stress.into(),
                p.carried_pressure.into(),
            ]);
        }
        t
    }
}

impl Tabulate for AdhesionReport {
    fn tables(&self) -> Vec<Table> {
        let mut out = vec![self.stickiness_table()];
        if !self.points.is_empty() {
            out.push(self.contact_table());
        }
        out
    }
}

//! The tables of `compare --leakage / --conductance`: the leak rates and the
//! conductances, theory beside the BEM.

use persson::leakage::LeakStatus;

use super::compare_transport::{ConductanceCompared, TransportComparison};
use crate::table::{number, Cell, Table};

impl TransportComparison {
    /// The text tables: the leak rates and the conductances, theory beside BEM.
    pub fn tables(&self) -> Vec<Table> {
        let mut out = Vec::new();
        let grids: Vec<String> = self.bem.iter().map(|g| format!("{}²", g.grid)).collect();
        let grids = grids.join(", ");
        if self.points.iter().any(|p| p.leakage.is_some()) {
            let mut t = Table::new(
                "leakage_compare",
                "Leak rate Q (m³/s): theories against Reynolds flow on the BEM's gap",
            )
            .scalar("grids", "grids", grids.as_str())
            .scalar(
                "flow_method",
                "BEM",
                "finest grid's Reynolds flow, mean of x, y and seeds; not extrapolated",
            )
            .column("nominal_pressure", "σ0")
            .column_digits("bem_contact_fraction", "A/A0 BEM", 4)
            .column_digits("critical_junction_leak_rate", "Q CJ", 4)
            .column_digits("effective_medium_leak_rate", "Q EMT", 4)
            .column_digits("bem_leak_rate", "Q BEM", 4)
            .column_digits("critical_junction_ratio", "CJ/BEM", 3)
            .column_digits("effective_medium_ratio", "EMT/BEM", 3)
            .column_digits("bem_resolution_change", "Q(N)/Q(N/2)−1", 2)
            .omittable(1);
            for (i, (p, note)) in self.short_notes().into_iter().enumerate() {
                t = t.scalar(&format!("note_{i}"), &format!("σ0 = {p}"), note);
            }
            for p in &self.points {
                let Some(l) = &p.leakage else { continue };
                t.push(vec![
                    Cell::Num(p.nominal_pressure),
                    Cell::Num(p.bem_contact_fraction),
                    Cell::Num(l.critical_junction_leak_rate),
                    Cell::Num(l.effective_medium_leak_rate),
                    Cell::Num(l.bem_leak_rate),
                    l.critical_junction_ratio.into(),
                    l.effective_medium_ratio.into(),
                    l.bem_resolution_change.into(),
                ]);
            }
            out.push(t);
        }
        if self.points.iter().any(|p| p.conductance.is_some()) {
            out.push(self.conductance_table(&grids));
        }
        out
    }

    fn conductance_table(&self, grids: &str) -> Table {
        let first = self.points.iter().find_map(|p| p.conductance.as_ref());
        let has = |f: fn(&ConductanceCompared) -> Option<f64>| first.and_then(f).is_some();
        let (thermal, electrical, gap) = (
            has(|c| c.theory_thermal_conductance),
            has(|c| c.theory_electrical_conductance),
            has(|c| c.theory_gap_conductance),
        );
        let mut t = Table::new(
            "conductance_compare",
            "Contact conductance: Barber's identity on the theory's and the BEM's stiffness (BEM: N → ∞)",
        )
        .scalar("grids", "grids", grids)
        .scalar(
            "stiffness_method",
            "BEM stiffness",
            "linear solve on the converged contact set",
        )
        .column("nominal_pressure", "σ0")
        .column_digits("theory_stiffness", "K/A0 theory", 4)
        .column_digits("bem_stiffness", "K/A0 BEM", 4)
        .column_digits("stiffness_ratio", "theory/BEM", 3);
        if thermal {
            t = t
                .column_digits("theory_thermal_conductance", "h_c theory", 4)
                .omittable(3)
                .column_digits("bem_thermal_conductance", "h_c BEM", 4)
                .omittable(2);
        }
        if electrical {
            t = t
                .column_digits("theory_electrical_conductance", "h_e theory", 4)
                .omittable(3)
                .column_digits("bem_electrical_conductance", "h_e BEM", 4)
                .omittable(2);
        }
        if gap {
            t = t
                .column_digits("theory_gap_conductance", "h_gap theory", 4)
                .column_digits("bem_gap_conductance", "h_gap BEM", 4)
                .column_digits("gap_conductance_ratio", "gap theory/BEM", 3);
        }
        for p in &self.points {
            let Some(c) = &p.conductance else { continue };
            let mut row = vec![
                Cell::Num(p.nominal_pressure),
                Cell::Num(c.theory_stiffness),
                Cell::Measured {
                    value: c.bem_stiffness,
                    error: c.bem_stiffness_error,
                },
                Cell::Num(c.stiffness_ratio),
            ];
            if thermal {
                row.push(c.theory_thermal_conductance.into());
                row.push(c.bem_thermal_conductance.into());
            }
            if electrical {
                row.push(c.theory_electrical_conductance.into());
                row.push(c.bem_electrical_conductance.into());
            }
            if gap {
                row.push(c.theory_gap_conductance.into());
                row.push(c.bem_gap_conductance.into());
                row.push(c.gap_conductance_ratio.into());
            }
            t.push(row);
        }
        t
    }

    /// The notes of the loads for a text table: (σ0, which methods give Q = 0).
    fn short_notes(&self) -> Vec<(String, String)> {
        self.points
            .iter()
            .filter_map(|p| {
                let l = p.leakage.as_ref()?;
                let mut parts = Vec::new();
                if l.bem_leak_rate == 0.0 {
                    parts.push("BEM: no open path");
                }
                if l.critical_junction_status == LeakStatus::Sealed {
                    parts.push("critical junction: sealed");
                }
                if l.effective_medium_status == LeakStatus::Sealed {
                    parts.push("effective medium: sealed");
                }
                (!parts.is_empty()).then(|| {
                    (
                        number(p.nominal_pressure, 4),
                        format!("{}; Q = 0", parts.join(", ")),
                    )
                })
            })
            .collect()
    }

    /// The notes of the loads (a leak rate 0, a method sealed), one line each.
    pub fn notes(&self) -> Vec<String> {
        self.points
            .iter()
            .filter_map(|p| {
                let n = p.leakage.as_ref()?.note.as_ref()?;
                Some(format!("σ0 = {}: {n}", number(p.nominal_pressure, 4)))
            })
            .collect()
    }
}

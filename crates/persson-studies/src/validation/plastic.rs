//! The elastic–perfectly-plastic side of [`super::compare`] (a yield stress
//! σY on [`persson::bem::Options::yield_stress`]): its table. The input is
//! checked by [`persson::error::check::yield_stress`], as the saturated BEM
//! checks it.

use super::report::Comparison;
use crate::table::{number, Cell, Table};

impl Comparison {
    /// With a yield stress: A/A0, A_el/A0 and A_pl/A0 of Persson's finite-σY
    /// theory, of the saturated BEM on every grid and extrapolated, one row
    /// each per pressure (a long table, as narrow for many grids as for few).
    pub(super) fn yield_table(&self) -> Option<Table> {
        let y = self.yield_stress?;
        let mut t = Table::new(
            "yield",
            format!(
                "Elastic–plastic contact, σY = {}: Persson's finite-σY theory (ζ = {}) and the \
                 saturated FFT-BEM",
                number(y, 6),
                number(self.spectrum.zeta, 6)
            ),
        )
        .scalar("yield_stress", "σY", y)
        .column("nominal_pressure", "σ0")
        .column("source", "source")
        .column("grid", "N")
        .column("contact_fraction", "A/A0")
        .column("elastic_fraction", "A_el/A0")
        .column("plastic_fraction", "A_pl/A0")
        .column_digits("plastic_fraction_standard_error", "A_pl standard error", 2)
        .column_digits("plastic_displacement_mean", "u_pl mean", 4);
        for (k, &p) in self.nominal_pressure.iter().enumerate() {
            if let Some(d) = self.pressure_distribution.get(k) {
                t.push(vec![
                    p.into(),
                    "theory".into(),
                    Cell::Empty,
                    d.theory_contact_fraction.into(),
                    d.theory_elastic_fraction.into(),
                    d.theory_plastic_fraction.into(),
                    Cell::Empty,
                    Cell::Empty,
                ]);
            }
            let measured = self.measured.iter().map(|g| ("BEM, map as measured", g));
            for (source, g) in self.bem.iter().map(|g| ("BEM", g)).chain(measured) {
                let at = |v: &Option<Vec<f64>>| v.as_ref().and_then(|v| v.get(k).copied());
                t.push(vec![
                    p.into(),
                    source.into(),
                    g.grid.into(),
                    g.contact_fraction[k].into(),
                    at(&g.elastic_fraction).into(),
                    at(&g.plastic_fraction).into(),
                    Cell::Empty,
                    at(&g.plastic_displacement_mean).into(),
                ]);
            }
            if let Some(c) = self.extrapolated.get(k) {
                t.push(vec![
                    p.into(),
                    "BEM, N → ∞".into(),
                    Cell::Empty,
                    c.contact_fraction.into(),
                    c.elastic_fraction.into(),
                    c.plastic_fraction.into(),
                    c.plastic_fraction_standard_error.into(),
                    Cell::Empty,
                ]);
            }
        }
        Some(t)
    }
}

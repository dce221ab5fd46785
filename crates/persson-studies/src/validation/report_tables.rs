//! The tables of a [`Comparison`], one function each: the theories' A/A0,
//! the BEM's A(N) and its continuum limit, κ, (with σY) the elastic–plastic
//! split, the mean separation, the shown pressure distribution, the user's
//! data and the solves.

use super::asperity::asperity_table;
use super::kappa::KappaEstimate;
use super::report::{Comparison, Fitted};
use crate::table::{number, Cell, Table, Tabulate};

impl Tabulate for Comparison {
    fn tables(&self) -> Vec<Table> {
        let mut tables = vec![self.theory_table(), self.bem_table()];
        let a_inf: Vec<f64> = self
            .extrapolated
            .iter()
            .map(|c| c.contact_fraction)
            .collect();
        tables.push(asperity_table(
            &self.asperity,
            &self.nominal_pressure,
            &a_inf,
            self.yield_stress.is_some(),
        ));
        if let Some(a) = &self.anisotropy {
            tables.push(super::anisotropic::anisotropy_table(a, &self.seeds));
        }
        tables.push(self.kappa_table());
        tables.extend(self.yield_table());
        tables.push(self.separation_table());
        tables.extend(self.distribution_table());
        tables.extend(self.data_table());
        tables.push(self.solves_table());
        // Last, so that the other tables keep their places (their indices are
        // part of the report's JSON).
        tables.push(super::patches::patch_table(
            &self.patches,
            &self.nominal_pressure,
        ));
        // compare --leakage / --conductance (absent by default)
        tables.extend(self.transport.iter().flat_map(|t| t.tables()));
        // compare --work-of-adhesion (absent by default)
        tables.extend(self.adhesion.iter().flat_map(|a| a.tables()));
        tables
    }
}

/// With a yield stress the BEM is the saturated one (0 ≤ p ≤ σY): said where
/// its A/A0 and κ stand beside the elastic theories (empty without σY).
fn saturated(c: &Comparison) -> String {
    c.yield_stress
        .map(|y| format!(", saturated (σY = {})", number(y, 6)))
        .unwrap_or_default()
}

/// A row of the κ table: κ in the column's one style; the standard error
/// only for a measured κ (BEM, data). A theory's curve is exact, and its
/// fit's standard error only measures the curve's bend (it stays in the JSON).
fn kappa_row(
    t: &mut Table,
    source: &str,
    grid: Option<usize>,
    kappa: f64,
    se: Option<f64>,
    closed: Option<f64>,
    points: usize,
) {
    t.push(vec![
        source.into(),
        grid.map_or(Cell::Empty, Cell::from),
        Cell::Num(kappa),
        // A theory's fit error only measures its curve's bend: not shown.
        if closed.is_some() {
            Cell::Empty
        } else {
            se.into()
        },
        closed.into(),
        points.into(),
    ]);
}

fn estimate_row(t: &mut Table, source: &str, grid: Option<usize>, e: &KappaEstimate) {
    kappa_row(t, source, grid, e.kappa, e.standard_error, None, e.points);
}

impl Comparison {
    fn grid_list(&self) -> String {
        let g: Vec<String> = self.grids.iter().map(|g| format!("{g}²")).collect();
        g.join(", ")
    }

    /// The theories' A/A0 at each pressure.
    fn theory_table(&self) -> Table {
        let s = &self.spectrum;
        let mut theory = Table::new(
            "area_theory",
            format!(
                "Contact area A/A0 of the theories, ζ = {}{}",
                number(s.zeta, 6),
                if self.yield_stress.is_some() {
                    " (elastic; with σY: the table \"Elastic–plastic contact\")"
                } else {
                    ""
                }
            ),
        )
        .scalar("contact_modulus", "E*", self.contact_modulus)
        .scalar("q_l", "q_l", s.q_l)
        .scalar("q_s", "q_s", s.q_s);
        if s.clipped {
            theory = theory.scalar(
                "q_s_requested",
                "q_s given (not resolved by the coarsest grid)",
                s.q_s_requested,
            );
        }
        theory = theory
            .scalar("rms_height", "h_rms", s.rms_height)
            .scalar("rms_slope", "h'_rms", s.rms_slope)
            .column("nominal_pressure", "σ0");
        for c in &self.theories {
            let key = format!("contact_fraction_{}", c.theory.name().replace('-', "_"));
            theory = theory.column(&key, c.theory.label());
        }
        for (k, &p) in self.nominal_pressure.iter().enumerate() {
            let mut row = vec![Cell::Num(p)];
            row.extend(
                self.theories
                    .iter()
                    .map(|c| Cell::Num(c.contact_fraction[k])),
            );
            theory.push(row);
        }
        theory
    }

    /// The BEM's A(N) per grid and its continuum limit; the coarser grids'
    /// columns may be left out of a narrow text table.
    fn bem_table(&self) -> Table {
        let mut bem = Table::new(
            "area_bem",
            format!(
                "Contact area A/A0 of the FFT-BEM{} and its continuum limit (Campañá & Müser 2007)",
                saturated(self)
            ),
        )
        .scalar("grids", "grids", self.grid_list().as_str())
        .scalar("size", "L", self.size)
        .scalar("seeds", "seeds", self.seeds.len())
        .scalar("tolerance", "tolerance ε", self.tolerance)
        .column("nominal_pressure", "σ0");
        for (i, g) in self.bem.iter().enumerate() {
            bem = bem.column(
                &format!("contact_fraction_{}", g.grid),
                &format!("N = {}", g.grid),
            );
            // a narrow text table leaves out the coarser grids, coarsest first
            if i + 1 < self.bem.len() {
                bem = bem.omittable(0);
            }
        }
        if let Some(m) = &self.measured {
            bem = bem.column(
                "contact_fraction_as_measured",
                &format!("{} as measured", m.grid),
            );
        }
        bem = bem
            .column("contact_fraction_extrapolated", "N → ∞")
            .column_digits("standard_error", "standard error", 2)
            .column_digits("alpha", "α", 3);
        for (k, c) in self.extrapolated.iter().enumerate() {
            let mut row = vec![Cell::Num(c.nominal_pressure)];
            row.extend(self.bem.iter().map(|g| Cell::Num(g.contact_fraction[k])));
            if let Some(m) = &self.measured {
                row.push(Cell::Num(m.contact_fraction[k]));
            }
            row.extend([
                Cell::Num(c.contact_fraction),
                Cell::Num(c.standard_error),
                Cell::Num(c.alpha),
            ]);
            bem.push(row);
        }
        bem
    }

    /// κ of each theory (fitted and closed form), of the BEM per grid and
    /// extrapolated, and of the user's data.
    fn kappa_table(&self) -> Table {
        let saturated = saturated(self);
        let mut kappa = Table::new(
            "kappa",
            format!(
                "κ of A/A0 = κ σ0/(E* h'_rms), fitted where A/A0 < {}{}",
                number(self.kappa.max_fraction, 6),
                if saturated.is_empty() {
                    String::new()
                } else {
                    format!(" (BEM rows{saturated})")
                }
            ),
        )
        .column("source", "source")
        .column("grid", "N")
        .column_digits("kappa", "κ", 4)
        .column_digits("standard_error", "standard error", 2)
        .column_digits("low_load_kappa", "closed form", 4)
        .column("points", "points");
        for tk in &self.kappa.theories {
            match tk.fit.fit() {
                Some(f) => kappa_row(
                    &mut kappa,
                    tk.theory.label(),
                    None,
                    f.kappa,
                    f.standard_error,
                    Some(tk.low_load_kappa),
                    f.points,
                ),
                None => kappa.push(vec![
                    tk.theory.label().into(),
                    Cell::Empty,
                    Cell::Empty,
                    Cell::Empty,
                    tk.low_load_kappa.into(),
                    Cell::Int(0),
                ]),
            }
        }
        match &self.kappa.bem {
            Fitted::Fit(k) => {
                for g in &k.per_grid {
                    estimate_row(&mut kappa, "BEM", Some(g.grid), &g.estimate);
                }
                estimate_row(&mut kappa, "BEM, N → ∞", None, &k.extrapolated);
            }
            Fitted::NotFitted { reason } => {
                kappa = kappa.scalar("bem_not_fitted", "BEM not fitted", reason.to_string());
            }
        }
        if let Some(Fitted::Fit(f)) = &self.kappa.data {
            // The fit's standard error of your curve measures only its bend
            // (no noise model): in the JSON, not here.
            kappa.push(vec![
                "your data".into(),
                Cell::Empty,
                Cell::Num(f.kappa),
                Cell::Empty,
                Cell::Empty,
                f.points.into(),
            ]);
        }
        kappa
    }

    /// The finest grid's mean gap against Persson's ū(σ0).
    fn separation_table(&self) -> Table {
        let finest = self.grids.last().copied().unwrap_or(0);
        let mut sep = Table::new(
            "mean_separation",
            format!(
                "Mean separation ū: BEM mean gap ({finest}²) and Persson's theory{}",
                if self.yield_stress.is_some() {
                    " (elastic; the BEM's plastic interpenetration enters as a negative gap)"
                } else {
                    ""
                }
            ),
        )
        .column("nominal_pressure", "σ0")
        .column("bem_mean_separation", "ū BEM")
        .column("theory_mean_separation", "ū theory");
        for (k, &p) in self.nominal_pressure.iter().enumerate() {
            sep.push(vec![
                p.into(),
                self.mean_separation.bem[k].into(),
                self.mean_separation.theory[k].into(),
            ]);
        }
        sep
    }

    /// The shown pressure distribution: the BEM's histogram against
    /// Persson's P(σ) (with σY, the δ-peaks at σY as scalars).
    fn distribution_table(&self) -> Option<Table> {
        let d = self.shown_distribution()?;
        let mut t = Table::new(
            "pressure_distribution",
            format!(
                "Pressure distribution P(σ) at σ0 = {}: BEM {}² and Persson, flat start",
                number(d.nominal_pressure, 4),
                d.grid,
            ),
        )
        .scalar("bem_contact_fraction", "A/A0 BEM", d.bem_contact_fraction)
        .scalar(
            "theory_contact_fraction",
            "A/A0 theory",
            d.theory_contact_fraction,
        );
        if let (Some(y), Some(bp), Some(tp)) = (
            self.yield_stress,
            d.bem_plastic_fraction,
            d.theory_plastic_fraction,
        ) {
            t = t
                .scalar("yield_stress", "σY", y)
                .scalar(
                    "bem_plastic_fraction",
                    "δ-peak at σY: A_pl/A0 BEM (not in the bins)",
                    bp,
                )
                .scalar(
                    "theory_plastic_fraction",
                    "δ-peak at σY: A_pl/A0 theory",
                    tp,
                );
        }
        t = t
            .column("sigma_low", "σ low")
            .column("sigma_high", "σ high")
            .column("bem_density", "P(σ) BEM")
            .column("theory_density", "P(σ) theory");
        for (b, th) in d.bem.iter().zip(&d.theory_density) {
            t.push(vec![
                b.sigma_low.into(),
                b.sigma_high.into(),
                b.density.into(),
                (*th).into(),
            ]);
        }
        Some(t)
    }

    /// The user's data: relative deviations from each reference, and the
    /// distance of their histogram from Persson's P(σ).
    fn data_table(&self) -> Option<Table> {
        let histogram = self.data_histogram.as_ref();
        let Some(d) = &self.data else {
            let h = histogram?;
            return Some(
                Table::new("data_histogram", "Your pressure histogram").scalar(
                    "relative_l1_distance",
                    &format!(
                        "relative L1 distance from Persson's P(σ) at σ0 = {}",
                        number(h.nominal_pressure, 4)
                    ),
                    h.relative_l1_distance,
                ),
            );
        };
        let mut t = Table::new(
            "data_scores",
            "Your data: relative deviation of A/A0 from each reference",
        )
        .column("reference", "reference")
        .column_digits("rms_relative_deviation", "rms", 3)
        .column_digits("max_relative_deviation", "max", 3)
        .column("points", "points");
        for s in &d.scores {
            t.push(vec![
                s.reference.name().into(),
                s.score.rms_relative_deviation.into(),
                s.score.max_relative_deviation.into(),
                s.score.points.into(),
            ]);
        }
        if let Some(h) = histogram {
            t = t.scalar(
                "relative_l1_distance",
                &format!(
                    "your histogram at σ0 = {}: relative L1 distance from Persson's P(σ)",
                    number(h.nominal_pressure, 4)
                ),
                h.relative_l1_distance,
            );
        }
        Some(t)
    }

    /// Iterations, residual and time of the solves of each grid (and of the
    /// map as measured).
    fn solves_table(&self) -> Table {
        let mut solves = Table::new("bem_solves", "FFT-BEM solves (Polonsky & Keer 1999)");
        let labelled = self.measured.is_some();
        if labelled {
            solves = solves.column("surface", "surface");
        }
        solves = solves
            .column("grid", "N")
            .column("iterations", "iterations")
            .column_digits("residual", "largest residual ε", 2)
            .column_digits("seconds", "time (s)", 3);
        let rows = self.bem.iter().map(|g| ("band-limited map", g));
        for (what, g) in rows.chain(self.measured.iter().map(|g| ("map as measured", g))) {
            let mut row = if labelled { vec![what.into()] } else { vec![] };
            row.extend([
                g.grid.into(),
                g.iterations.into(),
                g.residual.into(),
                g.seconds.into(),
            ]);
            solves.push(row);
        }
        solves
    }
}

//! The typed report of `persson compare` ([`Comparison`]): theory curves,
//! BEM per grid, continuum limit, κ fits, pressure distributions, mean
//! separation and the user's data, printed as several short tables.

use serde::Serialize;

use super::data::Score;
use super::kappa::{KappaEstimate, KappaFit, SweepKappa};
use crate::table::{number, Cell, Table, Tabulate};
use persson::bem::HistogramBin;
use persson::corrected::Theory;

/// A contact-area law compared with the BEM.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum AreaTheory {
    /// Persson (2001), A/A0 = erf(1/(2√G)).
    Original,
    /// Bush, Gibson & Thomas (1975): A/A0 = √(2π) σ0/(E* h'_rms).
    BushLinear,
    /// Persson's linear law: A/A0 = √(8/π) σ0/(E* h'_rms).
    PerssonLinear,
    /// Yang & Persson (2008).
    YangPersson,
    /// Wang & Müser (2017).
    WangMuser,
    /// Xu et al. (2024).
    Xu,
}

impl AreaTheory {
    /// The name as on the command line (`wang-muser`).
    pub fn name(self) -> &'static str {
        match self {
            AreaTheory::Original => "original",
            AreaTheory::BushLinear => "bush-linear",
            AreaTheory::PerssonLinear => "persson-linear",
            AreaTheory::YangPersson => "yang-persson",
            AreaTheory::WangMuser => "wang-muser",
            AreaTheory::Xu => "xu",
        }
    }

    /// The name for people (`Wang–Müser`).
    pub fn label(self) -> &'static str {
        match self {
            AreaTheory::Original => "Persson",
            AreaTheory::BushLinear => "Bush linear",
            AreaTheory::PerssonLinear => "Persson linear",
            AreaTheory::YangPersson => "Yang–Persson",
            AreaTheory::WangMuser => "Wang–Müser",
            AreaTheory::Xu => "Xu",
        }
    }
}

impl From<Theory> for AreaTheory {
    fn from(t: Theory) -> Self {
        match t {
            Theory::Original => AreaTheory::Original,
            Theory::YangPersson { .. } => AreaTheory::YangPersson,
            Theory::WangMuser { .. } => AreaTheory::WangMuser,
            Theory::Xu { .. } => AreaTheory::Xu,
        }
    }
}

/// A theory's A/A0 at the compared pressures.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct TheoryArea {
    /// Which law.
    pub theory: AreaTheory,
    /// Its γ, for the corrected theories.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// A/A0 at each nominal pressure.
    pub contact_fraction: Vec<f64>,
    /// Its closed-form low-load κ.
    pub low_load_kappa: f64,
}

/// The spectrum as compared: what the BEM and the theories used.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ComparedSpectrum {
    /// Lower cut-off q_l.
    pub q_l: f64,
    /// Upper cut-off q_s used (after clipping).
    pub q_s: f64,
    /// Upper cut-off of the given spectrum.
    pub q_s_requested: f64,
    /// Whether q_s was clipped to what the coarsest grid resolves.
    pub clipped: bool,
    /// rms height over [q_l, q_s].
    pub rms_height: f64,
    /// rms slope over [q_l, q_s].
    pub rms_slope: f64,
    /// ζ = q_s/q_l.
    pub zeta: f64,
}

/// The BEM on one grid (seed-averaged).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemGrid {
    /// Grid side N.
    pub grid: usize,
    /// A/A0 at each pressure, mean over seeds.
    pub contact_fraction: Vec<f64>,
    /// Its standard error over seeds (`None` for one seed).
    pub seed_scatter: Vec<Option<f64>>,
    /// Mean gap ū at each pressure, mean over seeds.
    pub mean_separation: Vec<f64>,
    /// rms slope of each seed's surface on this grid.
    pub surface_rms_slope: Vec<f64>,
    /// With a yield stress: A_el/A0 (nodes with 0 < p < σY) at each
    /// pressure, mean over seeds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub elastic_fraction: Option<Vec<f64>>,
    /// With a yield stress: A_pl/A0 (nodes at p = σY) at each pressure,
    /// mean over seeds; `elastic_fraction + plastic_fraction = contact_fraction`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_fraction: Option<Vec<f64>>,
    /// With a yield stress: mean plastic displacement over the nodes at σY
    /// (unit of L) at each pressure, mean over seeds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_displacement_mean: Option<Vec<f64>>,
    /// Solver iterations, all solves of this grid.
    pub iterations: usize,
    /// Largest final residual.
    pub residual: f64,
    /// Wall time of this grid's solves, s.
    pub seconds: f64,
}

/// The continuum limit A∞ at one pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ContinuumPoint {
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// A∞ of the seed-averaged A(N).
    pub contact_fraction: f64,
    /// Combined error of the fit and over seeds.
    pub standard_error: f64,
    /// Standard error of the fit (where it has more points than parameters).
    pub fit_standard_error: Option<f64>,
    /// |A∞ − A(N_max)|.
    pub extrapolation_step: f64,
    /// Standard error of A∞ over seeds (`None` for one seed).
    pub seed_scatter: Option<f64>,
    /// Exponent α used.
    pub alpha: f64,
    /// Amplitude c of the correction c N^−α.
    pub coefficient: f64,
    /// With a yield stress: A_el/A0 extrapolated to N → ∞ (same α).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub elastic_fraction: Option<f64>,
    /// Its combined error of the fit and over seeds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub elastic_fraction_standard_error: Option<f64>,
    /// With a yield stress: A_pl/A0 extrapolated to N → ∞ (same α).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_fraction: Option<f64>,
    /// Its combined error of the fit and over seeds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_fraction_standard_error: Option<f64>,
}

/// A fit, or why there is none.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Fitted<T> {
    /// The fit.
    Fit(T),
    /// No fit, and why.
    NotFitted {
        /// Why (e.g. no point in the low-load regime).
        reason: String,
    },
}

impl<T> Fitted<T> {
    pub(crate) fn from_result(r: persson::Result<T>) -> Self {
        match r {
            Ok(t) => Fitted::Fit(t),
            Err(e) => Fitted::NotFitted {
                reason: e.to_string(),
            },
        }
    }

    /// The fit, if there is one.
    pub fn fit(&self) -> Option<&T> {
        match self {
            Fitted::Fit(t) => Some(t),
            Fitted::NotFitted { .. } => None,
        }
    }
}

/// κ fitted to a theory's curve, next to its closed form.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct TheoryKappa {
    /// Which law.
    pub theory: AreaTheory,
    /// κ fitted on the compared pressures.
    pub fit: Fitted<KappaFit>,
    /// Its closed-form low-load κ.
    pub low_load_kappa: f64,
}

/// Every κ of a comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct KappaFits {
    /// The low-load regime: points with A/A0 below this.
    pub max_fraction: f64,
    /// κ of each theory.
    pub theories: Vec<TheoryKappa>,
    /// κ of the BEM per grid and in the continuum limit.
    pub bem: Fitted<SweepKappa>,
    /// κ of the user's data.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub data: Option<Fitted<KappaFit>>,
}

/// P(σ) at one nominal pressure: the finest grid's histogram against
/// Persson's P(σ) from a flat start.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PressureDistribution {
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// Grid of the histogram (the finest).
    pub grid: usize,
    /// The BEM histogram, over seeds; integrates to the BEM's A/A0.
    pub bem: Vec<HistogramBin>,
    /// The BEM's A/A0 (finest grid, mean over seeds).
    pub bem_contact_fraction: f64,
    /// Persson's P(σ) at the bin centres.
    pub theory_density: Vec<f64>,
    /// Persson's A/A0.
    pub theory_contact_fraction: f64,
    /// G at ζ = q_s/q_l.
    pub g: f64,
    /// Persson's P(σ) beyond the BEM's largest pressure, for the tail
    /// (with a yield stress: on (0, σY]).
    pub theory_curve: DensityCurve,
    /// With a yield stress: the BEM's A_el/A0 (finest grid, mean over
    /// seeds); `bem` holds only these nodes and integrates to it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_elastic_fraction: Option<f64>,
    /// With a yield stress: the BEM's A_pl/A0, the weight of the δ-peak at σY.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_plastic_fraction: Option<f64>,
    /// With a yield stress: Persson's A_el/A0 (P(σ) on (0, σY) with P(σY) = 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theory_elastic_fraction: Option<f64>,
    /// With a yield stress: Persson's A_pl/A0, the weight of the δ-peak at σY.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theory_plastic_fraction: Option<f64>,
}

/// A density P(σ) sampled at points σ.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct DensityCurve {
    /// σ (unit of E*).
    pub sigma: Vec<f64>,
    /// P(σ).
    pub density: Vec<f64>,
}

/// ū of the finest BEM grid against the theory.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct MeanSeparation {
    /// Mean gap of the finest grid (mean over seeds).
    pub bem: Vec<f64>,
    /// Persson's ū(σ0).
    pub theory: Vec<f64>,
}

/// A score of the user's data against one reference.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct DataScore {
    /// A theory's name, or `bem-extrapolated`.
    pub reference: String,
    /// The score.
    #[serde(flatten)]
    pub score: Score,
}

/// The user's contact fractions against the theories and the BEM.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct DataComparison {
    /// Their nominal pressures.
    pub nominal_pressure: Vec<f64>,
    /// Their A/A0.
    pub contact_fraction: Vec<f64>,
    /// The theories at their pressures.
    pub theories: Vec<TheoryArea>,
    /// A∞ interpolated (log–log) at their pressures, where inside the range.
    pub bem_extrapolated: Vec<Option<f64>>,
    /// Scores against each theory and A∞.
    pub scores: Vec<DataScore>,
}

/// The user's pressure histogram against Persson's P(σ).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct HistogramComparison {
    /// Nominal pressure of the comparison.
    pub nominal_pressure: f64,
    /// Their σ.
    pub sigma: Vec<f64>,
    /// Their P(σ).
    pub density: Vec<f64>,
    /// Persson's P(σ) at their σ.
    pub theory_density: Vec<f64>,
    /// ∫|P_user − P_theory| dσ / ∫ P_theory dσ.
    pub relative_l1_distance: f64,
}

/// Everything `persson compare` computes.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct Comparison {
    /// E*.
    pub contact_modulus: f64,
    /// The spectrum compared.
    pub spectrum: ComparedSpectrum,
    /// Side L = 2π/q_l.
    pub size: f64,
    /// Grids, ascending.
    pub grids: Vec<usize>,
    /// Seeds.
    pub seeds: Vec<u64>,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// Yield stress σY of the saturated BEM and of Persson's finite-σY
    /// P(σ) (`None`: elastic).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub yield_stress: Option<f64>,
    /// Nominal pressures σ0.
    pub nominal_pressure: Vec<f64>,
    /// The theories' A/A0.
    pub theories: Vec<TheoryArea>,
    /// The BEM per grid.
    pub bem: Vec<BemGrid>,
    /// The continuum limit per pressure.
    pub extrapolated: Vec<ContinuumPoint>,
    /// κ fits.
    pub kappa: KappaFits,
    /// P(σ) per pressure.
    pub pressure_distribution: Vec<PressureDistribution>,
    /// Index into `pressure_distribution` of the one shown and plotted.
    pub histogram_index: usize,
    /// Mean separation.
    pub mean_separation: MeanSeparation,
    /// The user's contact fractions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub data: Option<DataComparison>,
    /// The user's pressure histogram.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub data_histogram: Option<HistogramComparison>,
    /// `compare --surface` on a periodic map: the BEM on the map as measured
    /// (unfiltered, its own grid), beside the band-limited sweep.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub measured: Option<BemGrid>,
    /// Text tables with every column; `false` (the default): each table
    /// fits [`TEXT_WIDTH`] characters, the coarser grids' columns of a wide
    /// table left out (named under its title). Not in the JSON.
    #[serde(skip)]
    pub wide: bool,
}

impl Comparison {
    /// The theory curve of `t`, if compared.
    pub fn theory(&self, t: AreaTheory) -> Option<&TheoryArea> {
        self.theories.iter().find(|c| c.theory == t)
    }

    /// The distribution shown in text and plotted.
    pub fn shown_distribution(&self) -> Option<&PressureDistribution> {
        self.pressure_distribution.get(self.histogram_index)
    }

    fn grid_list(&self) -> String {
        let g: Vec<String> = self.grids.iter().map(|g| format!("{g}²")).collect();
        g.join(", ")
    }
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

impl Tabulate for Comparison {
    fn tables(&self) -> Vec<Table> {
        let s = &self.spectrum;
        let np = self.nominal_pressure.len();
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
        for k in 0..np {
            let mut row = vec![Cell::Num(self.nominal_pressure[k])];
            row.extend(
                self.theories
                    .iter()
                    .map(|c| Cell::Num(c.contact_fraction[k])),
            );
            theory.push(row);
        }

        // With a yield stress the BEM is the saturated one (0 ≤ p ≤ σY): say
        // so where its A/A0 and κ stand beside the elastic theories.
        let saturated = self
            .yield_stress
            .map(|y| format!(", saturated (σY = {})", number(y, 6)))
            .unwrap_or_default();
        let mut bem = Table::new(
            "area_bem",
            format!(
                "Contact area A/A0 of the FFT-BEM{saturated} and its continuum limit (Campañá & Müser 2007)"
            ),
        )
        .scalar("grids", "grids", self.grid_list().as_str())
        .scalar("size", "L", self.size)
        .scalar("seeds", "seeds", self.seeds.len())
        .scalar("tolerance", "tolerance ε", self.tolerance)
        .column("nominal_pressure", "σ0");
        for g in &self.bem {
            bem = bem.column(
                &format!("contact_fraction_{}", g.grid),
                &format!("N = {}", g.grid),
            );
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
                kappa = kappa.scalar("bem_not_fitted", "BEM not fitted", reason.as_str());
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
        let mut tables = vec![theory, bem, kappa];
        if let Some(y) = self.yield_table() {
            tables.push(y);
        }

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
        for k in 0..np {
            sep.push(vec![
                self.nominal_pressure[k].into(),
                self.mean_separation.bem[k].into(),
                self.mean_separation.theory[k].into(),
            ]);
        }
        tables.push(sep);

        if let Some(d) = self.shown_distribution() {
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
            tables.push(t);
        }

        if let Some(d) = &self.data {
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
                    s.reference.as_str().into(),
                    s.score.rms_relative_deviation.into(),
                    s.score.max_relative_deviation.into(),
                    s.score.points.into(),
                ]);
            }
            if let Some(h) = &self.data_histogram {
                t = t.scalar(
                    "relative_l1_distance",
                    &format!(
                        "your histogram at σ0 = {}: relative L1 distance from Persson's P(σ)",
                        number(h.nominal_pressure, 4)
                    ),
                    h.relative_l1_distance,
                );
            }
            tables.push(t);
        } else if let Some(h) = &self.data_histogram {
            tables.push(
                Table::new("data_histogram", "Your pressure histogram").scalar(
                    "relative_l1_distance",
                    &format!(
                        "relative L1 distance from Persson's P(σ) at σ0 = {}",
                        number(h.nominal_pressure, 4)
                    ),
                    h.relative_l1_distance,
                ),
            );
        }

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
        tables.push(solves);
        if !self.wide {
            for t in &mut tables {
                narrow(t, TEXT_WIDTH);
            }
        }
        tables
    }
}

/// Width in characters that the default text tables of a [`Comparison`] fit
/// (`wide` prints every column).
pub const TEXT_WIDTH: usize = 100;

/// Widest line of a table's text.
fn text_width(t: &Table) -> usize {
    t.to_text()
        .lines()
        .map(|l| l.chars().count())
        .max()
        .unwrap_or(0)
}

/// Fit a table into `width` characters: a long title wrapped at spaces,
/// then the columns of the coarser grids (`contact_fraction_<N>`, all but
/// the finest) dropped, coarsest first, with a line saying so.
fn narrow(t: &mut Table, width: usize) {
    if t.title.chars().count() > width {
        let mut lines = vec![String::new()];
        for word in t.title.split(' ') {
            let last = lines.last_mut().expect("one line");
            if !last.is_empty() && last.chars().count() + 1 + word.chars().count() > width {
                lines.push(format!("  {word}"));
            } else {
                if !last.is_empty() {
                    last.push(' ');
                }
                last.push_str(word);
            }
        }
        t.title = lines.join("\n");
    }
    let grid_columns = |t: &Table| -> Vec<usize> {
        (0..t.columns.len())
            .filter(|&j| {
                t.columns[j]
                    .key
                    .strip_prefix("contact_fraction_")
                    .is_some_and(|g| g.parse::<usize>().is_ok())
            })
            .collect()
    };
    let mut dropped = Vec::new();
    while text_width(t) > width {
        let cols = grid_columns(t);
        if cols.len() < 2 {
            break;
        }
        let j = cols[0];
        dropped.push(t.columns.remove(j).heading);
        for r in &mut t.rows {
            r.remove(j);
        }
    }
    if !dropped.is_empty() {
        t.scalars.push((
            "omitted".into(),
            "not shown (--wide shows them)".into(),
            Cell::Text(dropped.join(", ")),
        ));
    }
}

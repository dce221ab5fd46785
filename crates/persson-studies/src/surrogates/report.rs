//! What the study `surrogates` computed, with its tables.

use serde::Serialize;

use crate::input::SurrogateKindName;
use crate::table::{number, Cell, Table, Tabulate};
use persson::names::Boundary;

/// The map against its surrogates (scene output `surrogates`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SurrogatesReport {
    /// Where the map came from.
    pub map: String,
    /// The kind of surrogate.
    pub kind: SurrogateKindName,
    /// Number K of surrogates.
    pub count: usize,
    /// |z| beyond which a difference is significant: Student's t₀.₉₇₅ with
    /// K − 1 degrees of freedom.
    pub threshold: f64,
    /// Seeds of the surrogates: `seed … seed + K − 1`.
    pub seed: u64,
    /// Grid side N.
    pub grid: usize,
    /// Side L of the map (m).
    pub size: f64,
    /// Boundary condition of every solve.
    pub boundary: Boundary,
    /// Solver tolerance of every solve.
    pub tolerance: f64,
    /// E* (Pa).
    pub contact_modulus: f64,
    /// Skewness and kurtosis of the map's heights.
    pub map_heights: HeightMoments,
    /// Mean skewness and kurtosis of the surrogates' heights.
    pub surrogate_heights: HeightMoments,
    /// Amplitude-adjusted surrogates: the largest relative difference of a
    /// surrogate's radial spectrum from the map's over the radial bins.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spectrum_mismatch: Option<f64>,
    /// Amplitude-adjusted surrogates: the most IAAFT iterations one took.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub iterations: Option<usize>,
    /// One row per nominal pressure, in the scene's order.
    pub points: Vec<SurrogatePoint>,
    /// Seconds of the whole study.
    pub seconds: f64,
    /// The surrogates' heights (row-major N × N), kept when a scene asks to
    /// write them (`surfaces`); not in the JSON.
    #[serde(skip)]
    pub surfaces: Vec<Vec<f64>>,
}

/// Skewness `⟨δh³⟩/σ³` and kurtosis `⟨δh⁴⟩/σ⁴` (3 for a Gaussian).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HeightMoments {
    /// Skewness.
    pub skewness: f64,
    /// Kurtosis.
    pub kurtosis: f64,
}

/// The map against its surrogates at one nominal pressure.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SurrogatePoint {
    /// σ0 (Pa).
    pub nominal_pressure: f64,
    /// A/A0 of the map.
    pub map_contact_fraction: f64,
    /// Mean A/A0 of the surrogates.
    pub surrogate_contact_fraction: f64,
    /// Standard deviation of the surrogates' A/A0 (one surface's scatter).
    pub surrogate_standard_deviation: f64,
    /// Standard error of their mean, sd/√K.
    pub surrogate_standard_error: f64,
    /// Map over surrogates' mean.
    pub ratio: f64,
    /// The ratio's uncertainty from the surrogates' standard error.
    pub ratio_error: f64,
    /// (map − mean)/(sd·√(1 + 1/K)): how many standard errors of the
    /// difference the map lies from its surrogates, were it one more of them.
    pub z: f64,
    /// |z| above Student's t₀.₉₇₅ with K − 1 degrees of freedom (the 95 %
    /// prediction interval of one more surrogate): the map does not make
    /// contact like its surrogates. A map that is itself random is flagged
    /// at 5 % of the loads.
    pub significant: bool,
    /// Persson's theory on the scene's spectrum up to the grid's πN/L.
    pub theory_contact_fraction: f64,
    /// Contact patches of the map.
    pub map_patches: usize,
    /// Mean number of contact patches of the surrogates.
    pub surrogate_patches: f64,
    /// The map's pressure tail (above the mean contact pressure).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub map_tail: Option<Tail>,
    /// The surrogates' tails: the share that is exponential and the mean
    /// log-likelihood advantage of the exponential fit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surrogate_tail: Option<Tail>,
    /// (map's advantage − surrogates' mean)/(sd·√(1 + 1/K)): beyond the
    /// same t₀.₉₇₅, the map's tail is not shaped like its surrogates'.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tail_z: Option<f64>,
    /// P(p) of the map (bins `(p low, p high, density)`, integrating to A/A0).
    pub map_distribution: Vec<(f64, f64, f64)>,
    /// P(p) of the surrogates pooled.
    pub surrogate_distribution: Vec<(f64, f64, f64)>,
}

/// Which tail fits the contact pressures above the mean contact pressure
/// better (maximum likelihood, [`persson::bem::patches`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tail {
    /// Share of the surfaces whose tail is exponential (0 or 1 for the map).
    pub exponential_share: f64,
    /// Mean per-sample log-likelihood of the exponential fit minus the
    /// Gaussian's (> 0: exponential).
    pub log_likelihood_advantage: f64,
    /// Surrogates: the standard deviation of that advantage over them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub standard_deviation: Option<f64>,
}

impl Tail {
    /// `exponential` or `Gaussian` by the share.
    pub fn shape(&self) -> &'static str {
        if self.exponential_share > 0.5 {
            "exponential"
        } else {
            "Gaussian"
        }
    }
}

impl Tabulate for SurrogatesReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "surrogates",
            format!(
                "{}: the FFT-BEM on the map and on {} {} surrogates (seeds {} …), {}×{} {}, ε = {}; \
                 z = (map − mean)/(sd·√(1 + 1/K)), significant beyond {} (Student's t, 95 %); tail: \
                 the better fit (exponential − Gaussian log-likelihood per sample)",
                self.map,
                self.count,
                self.kind,
                self.seed,
                self.grid,
                self.grid,
                self.boundary,
                number(self.tolerance, 2),
                number(self.threshold, 4),
            ),
        )
        .column("nominal_pressure", "σ0 (Pa)")
        .column_digits("map_contact_fraction", "A/A0 map", 4)
        .column_digits("surrogate_contact_fraction", "A/A0 surrogates", 4)
        .column_digits("surrogate_standard_error", "± s.e.", 2)
        .column_digits("ratio", "ratio", 4)
        .column_digits("ratio_error", "± ratio", 2)
        .column_digits("z", "z", 3)
        .column_digits("theory_contact_fraction", "A/A0 theory", 4)
        .column("map_patches", "patches map")
        .column_digits("surrogate_patches", "patches surr.", 4)
        .column("map_tail", "tail map")
        .column("surrogate_tail", "tail surr.")
        .column_digits("tail_z", "tail z", 3);
        let tail = |t: &Option<Tail>| -> Cell {
            t.map_or_else(
                || "–".to_string(),
                |t| format!("{} ({})", t.shape(), number(t.log_likelihood_advantage, 2)),
            )
            .into()
        };
        for p in &self.points {
            t.push(vec![
                p.nominal_pressure.into(),
                p.map_contact_fraction.into(),
                p.surrogate_contact_fraction.into(),
                p.surrogate_standard_error.into(),
                p.ratio.into(),
                p.ratio_error.into(),
                p.z.into(),
                p.theory_contact_fraction.into(),
                p.map_patches.into(),
                p.surrogate_patches.into(),
                tail(&p.map_tail),
                tail(&p.surrogate_tail),
                p.tail_z.into(),
            ]);
        }
        let mut s = Table::new("surrogate_heights", "Height distribution".to_string())
            .column("surface", "surface")
            .column_digits("skewness", "skewness", 4)
            .column_digits("kurtosis", "kurtosis (Gaussian 3)", 4);
        for (name, m) in [
            ("map", self.map_heights),
            ("surrogates (mean)", self.surrogate_heights),
        ] {
            s.push(vec![name.into(), m.skewness.into(), m.kurtosis.into()]);
        }
        if let Some(m) = self.spectrum_mismatch {
            s = s.scalar(
                "spectrum_mismatch",
                "largest radial-spectrum mismatch of a surrogate",
                m,
            );
        }
        vec![t, s]
    }
}

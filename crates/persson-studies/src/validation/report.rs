//! The typed report of `persson compare` ([`Comparison`]): theory curves,
//! BEM per grid, continuum limit, κ fits, pressure distributions, mean
//! separation and the user's data, printed as several short tables.

use serde::Serialize;

use super::asperity::AsperityComparison;
use super::data::Score;
use super::kappa::{KappaFit, SweepKappa};
use crate::table::number;
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
        /// Why.
        reason: NotFitted,
    },
}

/// Why a κ fit could not be made. Serialised as `{"kind": …, <its fields>,
/// "message": <its text>}`.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(remote = "Self", tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum NotFitted {
    /// No point with 0 < A/A0 < `max_fraction`: the pressures do not reach
    /// the low-load regime (or every A/A0 is 0).
    NoLowLoadPoint {
        /// The low-load regime: A/A0 below this.
        max_fraction: f64,
    },
    /// The fit's input was rejected (the library's error, as text).
    Rejected {
        /// What was wrong.
        message: String,
    },
}

impl NotFitted {
    /// Why `e` (an error of [`super::fit_kappa`] or of a sweep's κ) left no fit.
    pub(crate) fn from_error(e: &persson::Error, max_fraction: f64) -> Self {
        match e {
            // fit_kappa's refusal of a curve without a low-load point
            persson::Error::Inconsistent { name, .. } if name == "pressures" => {
                NotFitted::NoLowLoadPoint { max_fraction }
            }
            _ => NotFitted::Rejected {
                message: e.to_string(),
            },
        }
    }
}

impl std::fmt::Display for NotFitted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NotFitted::NoLowLoadPoint { max_fraction } => write!(
                f,
                "no point with 0 < A/A0 < {} to fit κ",
                number(*max_fraction, 6)
            ),
            NotFitted::Rejected { message } => f.write_str(message),
        }
    }
}

impl Serialize for NotFitted {
    /// `{"kind": …, <the variant's fields>, "message": <the text>}`
    /// (`Rejected` has its message as its one field).
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct Tagged<'a> {
            #[serde(flatten, with = "NotFitted")]
            reason: &'a NotFitted,
            #[serde(skip_serializing_if = "Option::is_none")]
            message: Option<String>,
        }
        Tagged {
            reason: self,
            message: match self {
                NotFitted::Rejected { .. } => None,
                _ => Some(self.to_string()),
            },
        }
        .serialize(serializer)
    }
}

impl<T> Fitted<T> {
    /// The fit, or why there is none (`max_fraction`: the fit's low-load regime).
    pub(crate) fn from_result(r: persson::Result<T>, max_fraction: f64) -> Self {
        match r {
            Ok(t) => Fitted::Fit(t),
            Err(e) => Fitted::NotFitted {
                reason: NotFitted::from_error(&e, max_fraction),
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

/// What the user's data are scored against.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ScoreReference {
    /// A theory's A/A0 at the data's pressures.
    Theory(AreaTheory),
    /// The BEM's continuum limit A∞, interpolated (log–log) at the data's
    /// pressures inside the compared range.
    BemExtrapolated,
}

impl ScoreReference {
    /// The name as on the command line: a theory's (`wang-muser`) or
    /// `bem-extrapolated`.
    pub fn name(self) -> &'static str {
        match self {
            ScoreReference::Theory(t) => t.name(),
            ScoreReference::BemExtrapolated => "bem-extrapolated",
        }
    }
}

impl Serialize for ScoreReference {
    /// The name, a label from a closed set.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}

/// A score of the user's data against one reference.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct DataScore {
    /// A theory, or the extrapolated BEM.
    pub reference: ScoreReference,
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
    /// The asperity theories (GW, BGT; with σY the overlap model) against A∞.
    pub asperity: AsperityComparison,
    /// The BEM's contact patches per grid and σ0 ([`super::patches`]).
    pub patches: super::patches::PatchComparison,
    /// An anisotropic spectrum's Peklenik number and lay, and its surfaces'.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub anisotropy: Option<super::anisotropic::ComparedAnisotropy>,
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
    /// `compare --leakage / --conductance`: the theories' leak rate and
    /// conductance against the BEM's ([`super::compare_transport`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub transport: Option<super::compare_transport::TransportComparison>,
    /// `compare --work-of-adhesion`: Persson's adhesive theory against the
    /// adhesive BEM ([`super::compare_adhesion`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub adhesion: Option<super::compare_adhesion::AdhesionComparison>,
    /// Remarks on the comparison: q_s clipped to what the coarsest grid
    /// resolves (`clipped_band`), a map solved with a free boundary
    /// (`map_not_periodic`), solves the plain loop finished after the
    /// preconditioned one stalled (`preconditioner_fallback`), and the
    /// asperity theories' warnings (`small_bandwidth`, `coalescence`, also in
    /// [`Comparison::asperity`]). Printed on
    /// stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::Warning>,
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
}

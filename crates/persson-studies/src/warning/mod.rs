//! Warnings: remarks on the input that never change a number.
//!
//! A report that can warn carries a list of [`Warning`]s next to its numbers:
//! an input that is valid but probably not what was meant (a pressure close
//! to the modulus, a slope outside the small-slope theory, a magnification
//! beyond the band), or an assumption the computation made that the user
//! should know of (the normalisation of a spectrum file). Each is one line of
//! text ([`std::fmt::Display`]) that names the input (the spectrum's
//! convention, the grid, the quantity), never a command-line flag: the same
//! text reaches a Python user, and the `persson` binary adds its flag when it
//! prints the line on stderr (`persson: warning: <text>`).
//!
//! In JSON each warning is an object with its kind (a label from a closed
//! set, to filter on), its text and its typed fields:
//! ```text
//! {"kind": "steep_slope", "rms_slope": 1.2e5, "message": "rms slope h'_rms = 120000 is above 1: …"}
//! ```
//!
//! The text of the shared warnings (the inputs', the spectrum's, the BEM
//! solver's) is written here (`text.rs`); a warning that belongs to one
//! study (adhesion, the adhesive BEM, friction, leakage, surrogates, the
//! asperity theories, `compare`'s patches) carries its text in a `message`
//! field, written by that study's `describe` when it raises it
//! ([`Warning::described`]), so this module imports no study.

use std::path::PathBuf;

use serde::{Serialize, Serializer};

use crate::naming::names::ConventionName;

mod text;
cfg_feature! {
    "bem",
    mod rough;
    pub use rough::{of_rough, preconditioner_fallback};
}
cfg_feature! {
    "topography",
    mod measured;
    pub use measured::{of_measured, of_notes};
}

/// A study's text of its warnings ([`Warning::described`]).
pub type Describe = fn(&Warning, &mut std::fmt::Formatter<'_>) -> std::fmt::Result;

/// σ0 above this fraction of E* is warned of ([`Warning::HighPressure`]).
pub const HIGH_PRESSURE_RATIO: f64 = 0.1;

/// An rms slope above this is warned of ([`Warning::SteepSlope`]).
pub const STEEP_SLOPE: f64 = 1.0;

/// The bands of two rough bodies' spectra further apart than this factor
/// (at either end) are warned of ([`Warning::SumBands`]).
pub const SUM_BAND_RATIO: f64 = 10.0;

/// One remark on the input of a calculation; it never changes a number.
///
/// Serialised as `{"kind": …, <its fields>, "message": <its text>}`, the kind
/// the variant's name in snake_case (`high_pressure`, `psd_convention`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(remote = "Self", tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum Warning {
    /// A measured map too small for a curvature (fewer than 3 points along
    /// x or y, not periodic): h''_rms and the rms mean curvature are `null`.
    CurvatureNotComputed {
        /// The file.
        file: PathBuf,
        /// `[ny, nx]` of the map.
        shape: [usize; 2],
    },
    /// A quantity of a report could not be computed (it came out NaN or
    /// ±∞): it is printed as `–` in text, empty in CSV and `null` in JSON.
    NotComputed {
        /// The table ([`crate::table::Table::name`]).
        table: String,
        /// The quantity (the column's or scalar's key).
        quantity: String,
        /// How many of its values.
        count: usize,
    },
    /// The nominal pressure σ0 is above [`HIGH_PRESSURE_RATIO`] E*: strains of
    /// order one, or (above E*) most likely a modulus and a pressure in
    /// different units (E in MPa, σ0 in Pa).
    HighPressure {
        /// The largest σ0 given.
        nominal_pressure: f64,
        /// E*.
        contact_modulus: f64,
        /// How many of the pressures are above the threshold.
        count: usize,
    },
    /// The rms slope over the band is above [`STEEP_SLOPE`]: outside the
    /// small-slope theory (often a height in µm given as m).
    SteepSlope {
        /// The rms slope h'_rms over [q_l, q_s].
        rms_slope: f64,
    },
    /// A magnification beyond q_s/q_l: C(q) = 0 above q_s, so the result is
    /// that of full magnification.
    ZetaBeyondBand {
        /// The largest ζ given.
        zeta: f64,
        /// q_s/q_l.
        zeta_max: f64,
    },
    /// A BEM surface band-limited by its grid: its rms slope is well below
    /// the spectrum's.
    BandLimited {
        /// Grid side N.
        grid: usize,
        /// rms slope of the surface on the grid.
        surface_rms_slope: f64,
        /// rms slope of the spectrum over [q_l, q_s].
        rms_slope: f64,
    },
    /// A spectrum file was read in this normalisation.
    PsdConvention {
        /// The file.
        file: PathBuf,
        /// The convention.
        convention: ConventionName,
    },
    /// A spectrum file whose C(q) does not fall with q: perhaps a height
    /// profile given as a spectrum.
    RisingSpectrum {
        /// The file.
        file: PathBuf,
        /// C at the first q of the file.
        c_first: f64,
        /// C at the last q.
        c_last: f64,
    },
    /// q_s is not resolved by the coarsest grid of a comparison and was
    /// clipped.
    ClippedBand {
        /// The q_s asked for.
        q_s_requested: f64,
        /// The q_s used.
        q_s: f64,
        /// q_l.
        q_l: f64,
        /// Side of the coarsest grid.
        grid: usize,
        /// Pixels per shortest wavelength of the sweep.
        pixels_per_wavelength: f64,
    },
    /// A non-periodic measured map in a resolution study: its coarser copies
    /// are block averages, so N → ∞ is a resolution trend.
    MapNotPeriodic,
    /// A measured line scan whose x positions are not equally spaced was
    /// linearly interpolated onto equally spaced points.
    Resampled {
        /// The file.
        file: PathBuf,
        /// Points of the scan.
        points: usize,
        /// The largest deviation of an x from the equally spaced grid, in pixels.
        max_deviation: f64,
    },
    /// No Hurst exponent for a measured surface: too few spectrum bins.
    HurstNotFitted {
        /// The file.
        file: PathBuf,
        /// Bins with C > 0 in the band.
        bins: usize,
    },
    /// No Hurst exponent for a measured surface: the fit is outside (0, 1).
    HurstOutOfRange {
        /// The file.
        file: PathBuf,
        /// The fitted H.
        hurst: f64,
        /// Its standard error.
        hurst_error: f64,
    },
    /// Bins of a measured line scan's 1D spectrum without an isotropic 2D
    /// counterpart, left out of C(q).
    BinsLeftOut {
        /// The file.
        file: PathBuf,
        /// Bins left out.
        count: usize,
        /// Bins of the 1D spectrum.
        of: usize,
        /// Smallest and largest q left out, 1/m.
        q_range: (f64, f64),
    },
    /// Nominal pressures at or below −σ_p, the pull-off stress of the
    /// adhesive theory: nothing is in contact there (A/A0 = 0).
    BeyondPullOff {
        /// The highest of them (the σ0 closest to −σ_p).
        nominal_pressure: f64,
        /// σ_p.
        pull_off_stress: f64,
        /// How many of the pressures are beyond it.
        count: usize,
        /// Its text, written by the study that raises it (module `adhesion`).
        #[serde(skip)]
        message: String,
    },
    /// Adhesive contact fractions whose error estimate exceeds the tolerance
    /// at the largest mesh allowed.
    AdhesionToleranceNotMet {
        /// The requested absolute tolerance.
        tolerance: f64,
        /// The largest error estimate.
        error_bound: f64,
        /// How many points missed it.
        count: usize,
        /// Its text, written by the study that raises it (module `adhesion`).
        #[serde(skip)]
        message: String,
    },
    /// The adhesion range is not short against g₀ = (16/3) h'²_rms/h''_rms
    /// (Δr/g₀ ≥ 0.1), as the Pastewka–Robbins criterion assumes.
    LongAdhesionRange {
        /// Δr, m.
        adhesion_range: f64,
        /// h'_rms over the band.
        rms_slope: f64,
        /// h''_rms over the band, 1/m.
        rms_curvature: f64,
        /// Its text, written by the study that raises it (module `adhesion`).
        #[serde(skip)]
        message: String,
    },
    /// The spectra of two (or more) rough bodies cover bands more than
    /// [`SUM_BAND_RATIO`] apart: outside their common band the sum is one
    /// body's roughness alone.
    SumBands {
        /// Each body's band (q_min, q_max), 1/m.
        bands: Vec<(f64, f64)>,
        /// The largest ratio of the lower or of the upper ends.
        ratio: f64,
    },
    /// Measurements of one surface whose reliable bands do not overlap: the
    /// combined spectrum is interpolated across the gap.
    MeasurementGap {
        /// The measurement below the gap (its file).
        below: PathBuf,
        /// The measurement above it.
        above: PathBuf,
        /// The gap (q_max of the one below, q_min of the one above), 1/m.
        q_range: (f64, f64),
    },
    /// The BEM's preconditioned solver stalled (ε not falling) at these
    /// nominal pressures and the plain Polonsky–Keer loop finished the solves:
    /// the same answer to the same tolerance, in more time.
    PreconditionerFallback {
        /// σ0 of the solves that fell back.
        nominal_pressure: Vec<f64>,
        /// Iterations of the preconditioned loop before it was abandoned (per solve).
        iterations: Vec<usize>,
    },
    /// The adhesive BEM's grid does not resolve the cohesive zone: the range
    /// ρ is below one grid spacing L/N, or the cohesive length ℓ = E*Δγ/σ_c²
    /// below 8 spacings (`persson::bem::adhesive::RESOLVED_COHESIVE_LENGTH`). The
    /// answer depends on the grid and, for Maugis–Dugdale, on the iteration's
    /// path (the discrete energy has several stationary points).
    CohesiveZoneUnresolved {
        /// ρ, m.
        adhesion_range: f64,
        /// ℓ = E*Δγ/σ_c² = E*ρ²/Δγ, m.
        cohesive_length: f64,
        /// L/N, m.
        grid_spacing: f64,
        /// Its text, written by the study that raises it (module `bem_detail`).
        #[serde(skip)]
        message: String,
    },
    /// The adhesive BEM's preconditioned iteration stalled at these mean gaps
    /// and the plain one finished: the same tolerance, more time.
    AdhesiveFallback {
        /// ḡ of the solves that fell back, m.
        mean_gap: Vec<f64>,
        /// Its text, written by the study that raises it (module `bem_detail`).
        #[serde(skip)]
        message: String,
    },
    /// Adhesive BEM solves that stopped short of the tolerance (iteration limit).
    AdhesiveNotConverged {
        /// ḡ of those solves, m.
        mean_gap: Vec<f64>,
        /// The tolerance ε asked for.
        tolerance: f64,
        /// Its text, written by the study that raises it (module `bem_detail`).
        #[serde(skip)]
        message: String,
    },
    /// Rubber friction sampled a master curve outside its frequency range,
    /// where it is held at its end values.
    MasterCurveRange {
        /// Lowest and highest tabulated ω, rad/s.
        frequency_range: (f64, f64),
        /// Most decades of a_T q v below the table over the points.
        decades_below: f64,
        /// Most decades of a_T q v above the table over the points.
        decades_above: f64,
        /// The largest share of μ from outside the table over the points.
        friction_fraction: f64,
        /// Points (T, σ0, v) that sampled outside the table.
        count: usize,
        /// Points in all.
        of: usize,
        /// Its text, written by the study that raises it (module `friction`).
        #[serde(skip)]
        message: String,
    },
    /// Rubber friction whose integrals did not reach the tolerance at some
    /// points (their error bounds say how far off).
    FrictionNotConverged {
        /// Points that did not converge.
        count: usize,
        /// Points in all.
        of: usize,
        /// The largest relative error bound of μ among them.
        relative_error_bound: f64,
        /// Its text, written by the study that raises it (module `friction`).
        #[serde(skip)]
        message: String,
    },
    /// The flash temperature heated the rubber beyond a shift table's last
    /// row: a_T was extended linearly in ln a_T.
    ShiftTableExtended {
        /// The table's highest temperature, K.
        temperature_max: f64,
        /// The highest temperature reached, K.
        temperature: f64,
        /// Its text, written by the study that raises it (module `friction`).
        #[serde(skip)]
        message: String,
    },
    /// The contact already percolates at these loads: no channel crosses
    /// the seal, the leak rate of `method` is 0 there (a result, not an error).
    Sealed {
        /// `critical-junction`, `effective-medium` or `bem`.
        method: String,
        /// The lowest sealed σ0.
        nominal_pressure: f64,
        /// How many of the loads are sealed.
        count: usize,
        /// A/A0 at the lowest sealed load (full magnification, or the BEM's).
        contact_fraction: f64,
        /// The A/A0 above which the method calls the contact percolating
        /// (a_c, ½ for the effective medium; absent for the BEM, which
        /// finds no open path).
        #[serde(skip_serializing_if = "Option::is_none")]
        percolation_threshold: Option<f64>,
        /// Its text, written by the study that raises it (module `transport`).
        #[serde(skip)]
        message: String,
    },
    /// Nayak's bandwidth parameter α of the surface is below the asperity
    /// theories' threshold ([`persson::asperity::moments::SMALL_BANDWIDTH`]).
    SmallBandwidth {
        /// The asperity theory.
        theory: crate::naming::names::TheoryName,
        /// α = m0 m4/m2².
        bandwidth_parameter: f64,
        /// The threshold.
        threshold: f64,
        /// Its text, written by the study that raises it (module `asperity`).
        #[serde(skip)]
        message: String,
    },
    /// An asperity theory's A/A0 is above the fraction where its contacts
    /// coalesce ([`persson::asperity::COALESCENCE_FRACTION`]).
    Coalescence {
        /// The asperity theory.
        theory: crate::naming::names::TheoryName,
        /// The first σ0 above the threshold.
        nominal_pressure: f64,
        /// Its A/A0.
        contact_fraction: f64,
        /// How many of the pressures are above the threshold.
        count: usize,
        /// The threshold.
        threshold: f64,
        /// Its text, written by the study that raises it (module `asperity`).
        #[serde(skip)]
        message: String,
    },
    /// `compare`'s patch-area exponent τ rests on fewer than `min_patches`
    /// patches, or could not be fitted, in some solves.
    FewPatches {
        /// The first grid where it happens.
        grid: usize,
        /// Its first σ0.
        nominal_pressure: f64,
        /// How many (grid, σ0) points are affected.
        count: usize,
        /// The threshold.
        min_patches: usize,
        /// Its text, written by the study that raises it (module `validation::patches`).
        #[serde(skip)]
        message: String,
    },
    /// Amplitude-adjusted surrogates whose radial spectrum stays off the
    /// map's (a map whose spectrum falls below what rearranging its heights
    /// adds): the comparison mixes a height-distribution effect with a
    /// spectrum one.
    SurrogateSpectrum {
        /// The largest relative difference over the radial bins.
        mismatch: f64,
        /// Its text, written by the study that raises it (module `surrogates`).
        #[serde(skip)]
        message: String,
    },
    /// Loads at which the map touches on so few grid nodes that its A/A0,
    /// patches and tail rest on too few points (`surrogates`).
    CoarseContact {
        /// σ0 of those loads.
        nominal_pressure: Vec<f64>,
        /// The map's contact nodes at each.
        nodes: Vec<usize>,
        /// The threshold.
        min_nodes: usize,
        /// Its text, written by the study that raises it (module `surrogates`).
        #[serde(skip)]
        message: String,
    },
    /// A height map's fourth moment depends on its pixel size
    /// ([`persson::asperity::moments::CURVATURE_RESOLUTION_RATIO`]).
    CurvatureUnresolved {
        /// The file.
        file: PathBuf,
        /// m4 over 2Δ / m4 over Δ.
        curvature_resolution_ratio: f64,
        /// The threshold.
        threshold: f64,
        /// Its text, written by the study that raises it (module `asperity`).
        #[serde(skip)]
        message: String,
    },
}

/// The warnings whose text is their study's (module docs): their `message`,
/// read by `Display` and written by [`Warning::described`].
macro_rules! study_text {
    ($($v:ident),+ $(,)?) => {
        impl Warning {
            /// The text its study wrote, for a study's warning.
            fn message(&self) -> Option<&str> {
                match self {
                    $(Warning::$v { message, .. })|+ => Some(message),
                    _ => None,
                }
            }

            /// The same, to write.
            fn message_mut(&mut self) -> Option<&mut String> {
                match self {
                    $(Warning::$v { message, .. })|+ => Some(message),
                    _ => None,
                }
            }
        }
    };
}

study_text!(
    SmallBandwidth,
    Coalescence,
    CurvatureUnresolved,
    FewPatches,
    BeyondPullOff,
    AdhesionToleranceNotMet,
    LongAdhesionRange,
    CohesiveZoneUnresolved,
    AdhesiveFallback,
    AdhesiveNotConverged,
    MasterCurveRange,
    FrictionNotConverged,
    ShiftTableExtended,
    Sealed,
    SurrogateSpectrum,
    CoarseContact,
);

impl Warning {
    /// This warning with its text written by `describe`, the function of the
    /// study that raises it (module docs): kept in its `message` field, which
    /// [`std::fmt::Display`] prints. A shared warning, which has no such
    /// field, is returned as it is.
    pub fn described(mut self, describe: Describe) -> Self {
        struct Text<'a>(&'a Warning, Describe);
        impl std::fmt::Display for Text<'_> {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                (self.1)(self.0, f)
            }
        }
        let text = Text(&self, describe).to_string();
        if let Some(m) = self.message_mut() {
            *m = text;
        }
        self
    }

    /// [`Warning::HighPressure`] when some σ0 is above [`HIGH_PRESSURE_RATIO`] E*.
    pub fn high_pressure(pressures: &[f64], contact_modulus: f64) -> Option<Self> {
        let above: Vec<f64> = pressures
            .iter()
            .copied()
            .filter(|p| *p > HIGH_PRESSURE_RATIO * contact_modulus)
            .collect();
        let max = above.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (!above.is_empty()).then_some(Warning::HighPressure {
            nominal_pressure: max,
            contact_modulus,
            count: above.len(),
        })
    }

    /// [`Warning::SteepSlope`] when `rms_slope` is above [`STEEP_SLOPE`].
    pub fn steep_slope(rms_slope: f64) -> Option<Self> {
        (rms_slope > STEEP_SLOPE).then_some(Warning::SteepSlope { rms_slope })
    }

    /// [`Warning::ZetaBeyondBand`] when some ζ is beyond `zeta_max` (by more
    /// than rounding).
    pub fn zeta_beyond_band(zetas: &[f64], zeta_max: f64) -> Option<Self> {
        let max = zetas.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (max > zeta_max * (1.0 + 1e-12)).then_some(Warning::ZetaBeyondBand {
            zeta: max,
            zeta_max,
        })
    }

    /// [`Warning::SumBands`] when the parts' bands are more than
    /// [`SUM_BAND_RATIO`] apart.
    pub fn sum_bands(sum: &persson::spectrum::Sum) -> Option<Self> {
        let ratio = sum.band_mismatch();
        (ratio > SUM_BAND_RATIO).then(|| Warning::SumBands {
            bands: sum.bands(),
            ratio,
        })
    }

    /// [`Warning::BandLimited`] when the surface's rms slope on its grid is
    /// below 90 % of the spectrum's.
    pub fn band_limited(grid: usize, surface_rms_slope: f64, rms_slope: f64) -> Option<Self> {
        (surface_rms_slope < 0.9 * rms_slope).then_some(Warning::BandLimited {
            grid,
            surface_rms_slope,
            rms_slope,
        })
    }
}

impl Warning {
    /// What to change in a scene to act on the warning (its field and
    /// value), where one field does it: the text `persson run` prints after
    /// the warning, in brackets, and the browser page too.
    pub fn scene_hint(&self) -> Option<&'static str> {
        match self {
            Warning::BandLimited { .. } => Some("outputs.bem.grid"),
            Warning::PsdConvention {
                convention: ConventionName::Persson,
                ..
            } => Some("spectrum.convention: \"surface-topography\""),
            Warning::RisingSpectrum { .. } => Some("spectrum.kind: \"height_map\""),
            _ => None,
        }
    }

    /// The kind of the warning, as in its JSON (`high_pressure`, `steep_slope`,
    /// `zeta_beyond_band`, `band_limited`, `psd_convention`,
    /// `rising_spectrum`, `clipped_band`, `map_not_periodic`, `resampled`,
    /// `hurst_not_fitted`, `hurst_out_of_range`, `bins_left_out`,
    /// `preconditioner_fallback`, `cohesive_zone_unresolved`, `adhesive_fallback`,
    /// `adhesive_not_converged`, `master_curve_range`, `friction_not_converged`, `shift_table_extended`,
    /// `sum_bands`, `measurement_gap`, `sealed`, `small_bandwidth`, `coalescence`,
    /// `curvature_unresolved`, `beyond_pull_off`, `adhesion_tolerance_not_met`,
    /// `long_adhesion_range`, `not_computed`, `curvature_not_computed`).
    pub fn kind(&self) -> &'static str {
        match self {
            Warning::NotComputed { .. } => "not_computed",
            Warning::CurvatureNotComputed { .. } => "curvature_not_computed",
            Warning::HighPressure { .. } => "high_pressure",
            Warning::SteepSlope { .. } => "steep_slope",
            Warning::ZetaBeyondBand { .. } => "zeta_beyond_band",
            Warning::BandLimited { .. } => "band_limited",
            Warning::PsdConvention { .. } => "psd_convention",
            Warning::RisingSpectrum { .. } => "rising_spectrum",
            Warning::ClippedBand { .. } => "clipped_band",
            Warning::MapNotPeriodic => "map_not_periodic",
            Warning::Resampled { .. } => "resampled",
            Warning::HurstNotFitted { .. } => "hurst_not_fitted",
            Warning::HurstOutOfRange { .. } => "hurst_out_of_range",
            Warning::BinsLeftOut { .. } => "bins_left_out",
            Warning::BeyondPullOff { .. } => "beyond_pull_off",
            Warning::AdhesionToleranceNotMet { .. } => "adhesion_tolerance_not_met",
            Warning::LongAdhesionRange { .. } => "long_adhesion_range",
            Warning::SumBands { .. } => "sum_bands",
            Warning::MeasurementGap { .. } => "measurement_gap",
            Warning::PreconditionerFallback { .. } => "preconditioner_fallback",
            Warning::CohesiveZoneUnresolved { .. } => "cohesive_zone_unresolved",
            Warning::AdhesiveFallback { .. } => "adhesive_fallback",
            Warning::AdhesiveNotConverged { .. } => "adhesive_not_converged",
            Warning::MasterCurveRange { .. } => "master_curve_range",
            Warning::FrictionNotConverged { .. } => "friction_not_converged",
            Warning::ShiftTableExtended { .. } => "shift_table_extended",
            Warning::Sealed { .. } => "sealed",
            Warning::SmallBandwidth { .. } => "small_bandwidth",
            Warning::Coalescence { .. } => "coalescence",
            Warning::CurvatureUnresolved { .. } => "curvature_unresolved",
            Warning::FewPatches { .. } => "few_patches",
            Warning::SurrogateSpectrum { .. } => "surrogate_spectrum",
            Warning::CoarseContact { .. } => "coarse_contact",
        }
    }
}

impl Serialize for Warning {
    /// `{"kind": …, <the variant's fields>, "message": <the text>}`.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct Tagged<'a> {
            #[serde(flatten, with = "Warning")]
            warning: &'a Warning,
            message: String,
        }
        Tagged {
            warning: self,
            message: self.to_string(),
        }
        .serialize(serializer)
    }
}

/// A report with the warnings of its calculation, serialised as the report
/// with a top-level `"warnings"` array (empty when there are none): the shape
/// of the `persson` binary's `--json` output and of the Python package's dicts.
#[derive(Serialize)]
pub struct Warned<'a, R: Serialize> {
    #[serde(flatten)]
    report: &'a R,
    warnings: &'a [Warning],
}

impl<'a, R: Serialize> Warned<'a, R> {
    /// The report and its warnings.
    pub fn new(report: &'a R, warnings: &'a [Warning]) -> Self {
        Warned { report, warnings }
    }
}

/// [`Warning::PreconditionerFallback`] from the (σ0, preconditioned
/// iterations) of the solves that fell back; `None` when there are none.
pub fn fallen_back(solves: impl IntoIterator<Item = (f64, usize)>) -> Option<Warning> {
    let (nominal_pressure, iterations): (Vec<f64>, Vec<usize>) = solves.into_iter().unzip();
    (!nominal_pressure.is_empty()).then_some(Warning::PreconditionerFallback {
        nominal_pressure,
        iterations,
    })
}

/// Append `w` to `list` unless it is already there.
pub(crate) fn push(list: &mut Vec<Warning>, w: Option<Warning>) {
    if let Some(w) = w {
        if !list.contains(&w) {
            list.push(w);
        }
    }
}

/// A [`Warning::NotComputed`] for every column and scalar of `tables` that
/// holds a value that is not finite (module [`crate::table`]).
pub fn not_computed(tables: &[crate::table::Table]) -> Vec<Warning> {
    let mut out = Vec::new();
    for t in tables {
        let mut push = |quantity: &str, count: usize| {
            if count > 0 {
                out.push(Warning::NotComputed {
                    table: t.name.clone(),
                    quantity: quantity.to_string(),
                    count,
                });
            }
        };
        for (key, _, value) in &t.scalars {
            push(key, usize::from(value.is_not_finite()));
        }
        for (j, c) in t.columns.iter().enumerate() {
            push(
                &c.key,
                t.rows.iter().filter(|r| r[j].is_not_finite()).count(),
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A study's warning carries the text its study writes: printed, and in
    /// JSON as `message` beside its fields (not twice); a shared warning is
    /// left as it is.
    #[test]
    fn a_study_writes_its_warnings_text() {
        let w = Warning::Sealed {
            method: "bem".into(),
            nominal_pressure: 2e6,
            count: 3,
            contact_fraction: 0.5,
            percolation_threshold: None,
            message: String::new(),
        }
        .described(crate::transport::describe);
        assert_eq!(
            w.to_string(),
            "the contact already percolates at 3 load(s) from σ0 = 2e6 (A/A0 = 0.5, no open \
             path joins inlet and outlet): the bem leak rate is 0 there"
        );
        let json = serde_json::to_value(&w).unwrap();
        assert_eq!(json["kind"], "sealed");
        assert_eq!(json["message"], w.to_string());
        assert_eq!(json.as_object().unwrap().len(), 6, "{json}");
        let shared = Warning::MapNotPeriodic;
        assert_eq!(shared.clone().described(crate::transport::describe), shared);
    }

    #[test]
    fn one_line_and_serialised_with_its_kind() {
        let w = Warning::high_pressure(&[1e5, 1e6], 1.333e6).unwrap();
        let text = w.to_string();
        assert!(!text.contains('\n'), "{text}");
        assert!(text.contains("1e6") && text.contains("1.333e6"), "{text}");
        assert_eq!(
            serde_json::to_value(&w).unwrap(),
            serde_json::json!({
                "kind": "high_pressure",
                "nominal_pressure": 1e6,
                "contact_modulus": 1.333e6,
                "count": 1,
                "message": text,
            })
        );
        assert_eq!(w.kind(), "high_pressure");
        let psd = Warning::PsdConvention {
            file: "psd.csv".into(),
            convention: ConventionName::Persson,
        };
        let v = serde_json::to_value(&psd).unwrap();
        assert_eq!(v["kind"], "psd_convention");
        assert_eq!(v["convention"], "persson");
        assert_eq!(v["file"], "psd.csv");
        // the text names the input, never a command-line flag
        for w in [
            psd,
            Warning::band_limited(32, 0.01, 0.5).unwrap(),
            Warning::RisingSpectrum {
                file: "c.csv".into(),
                c_first: 1.0,
                c_last: 2.0,
            },
        ] {
            assert!(!w.to_string().contains("--"), "{w}");
        }
        assert_eq!(
            serde_json::to_value(Warning::MapNotPeriodic).unwrap()["kind"],
            "map_not_periodic"
        );
        assert!(Warning::high_pressure(&[1e6], 1e7).is_none()); // exactly 0.1 E*
        assert!(Warning::steep_slope(1.0).is_none());
        assert!(Warning::zeta_beyond_band(&[1e4], 1e4).is_none());
    }
}

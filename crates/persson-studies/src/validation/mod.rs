//! Validating numerical codes: the theories against the FFT-BEM and against
//! the user's own results.
//!
//! - [`compare`] (feature `bem`): every theory against the BEM at several
//!   resolutions of one physical surface, its continuum limit, κ, pressure
//!   distributions, mean separation and the user's data, as one typed
//!   [`Comparison`] (what `persson compare` prints and plots). With a yield
//!   stress on the solver options (`config.sweep.options.yield_stress`) the
//!   BEM is the saturated one and the theory Persson's finite-σY P(σ), with
//!   A_el/A0 and A_pl/A0 on both sides (`persson compare --yield-stress`).
//! - [`kappa_study`] (feature `bem`): κ against the Hurst exponent
//!   ([`KappaStudy`], `persson compare kappa`).
//! - [`ensemble()`] (feature `bem`): the BEM on seeds × grids of independent
//!   surfaces, mean and standard error per grid and pressure
//!   ([`EnsembleReport`], `persson compare ensemble`; the Python package runs
//!   its jobs on Dask).
//! - [`hertz`] (feature `bem`): the BEM against the Hertz closed form
//!   ([`HertzValidation`], `persson bem hertz`).
//!
//! The pieces, usable alone: [`extrapolate`] (A(N) = A∞ + c N^{−α}),
//! [`fit_kappa`], the resolution [`sweep()`], [`UserData`] and [`score`].
//!
//! # Example
//! ```
//! use persson_studies::validation::{extrapolate, fit_kappa};
//! # fn main() -> persson::Result<()> {
//! // A(N) = 0.3 + 0.5 N^−0.7 on three grids: the continuum limit is 0.3
//! let n = [64.0, 128.0, 256.0];
//! let a: Vec<f64> = n.iter().map(|x: &f64| 0.3 + 0.5 * x.powf(-0.7)).collect();
//! let e = extrapolate(&n, &a, Some(0.7))?;
//! assert!((e.value - 0.3).abs() < 1e-12);
//! // A/A0 = 2 σ0/(E* h'_rms) below A/A0 = 0.1: κ = 2
//! let p = [1e-3, 2e-3, 4e-3];
//! let frac: Vec<f64> = p.iter().map(|x| 2.0 * x / (1.0 * 0.1)).collect();
//! assert!((fit_kappa(&p, &frac, 1.0, 0.1, 0.1)?.kappa - 2.0).abs() < 1e-12);
//! # Ok(()) }
//! ```
//!
//! # References
//! Campañá & Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005
//! (continuum extrapolation, κ from the low-load regime); Persson, J. Chem.
//! Phys. 115, 3840 (2001) (κ = √(8/π)); Bush, Gibson & Thomas, Wear 35, 87
//! (1975) (κ = √(2π)).

pub mod continuum;
pub mod data;
pub mod kappa;

cfg_feature! {
    "bem",
    pub mod anisotropic;
    pub mod asperity;
    mod compare;
    pub mod compare_adhesion;
    pub mod compare_transport;
    mod compare_transport_tables;
    mod distribution;
    pub mod ensemble;
    mod hertz;
    mod kappa_study;
    pub mod limits;
    pub mod patches;
    mod plastic;
    pub mod report;
    mod report_tables;
    pub mod resolution;
    pub mod sweep;
    mod spec;
}

pub use continuum::{extrapolate, mean_and_error, Extrapolation, SampleMean, DEFAULT_ALPHA};
pub use data::{density_distance, interpolate_log, score, Score, UserData, UserHistogram};
pub use kappa::{fit_kappa, KappaEstimate, KappaFit};

cfg_feature! {
    "bem",
    pub use compare::{
        check_bins, compare, compare_surface, ComparisonConfig, DEFAULT_BINS, KAPPA_MAX_FRACTION,
    };
    pub use compare_transport::{TransportCompareConfig, TransportComparison};
    pub use ensemble::{ensemble, EnsembleConfig, EnsembleJob, EnsembleReport, EnsembleSolve};
    pub use hertz::{hertz, HertzValidation};
    pub use kappa::{GridKappa, SweepKappa};
    pub use kappa_study::{kappa_study, HurstKappa, KappaStudy, KappaStudyConfig};
    pub use limits::{continuum_limit, Continuum, ContinuumSplit, PlasticSplit, SeedMean};
    pub use report::Comparison;
    pub use resolution::{
        default_pressures, resolution_grids, resolvable_q_max, resolve_q_s, ResolvedBand,
        SweepConfig, SweepSettings, DEFAULT_LEVELS, DEFAULT_PIXELS_PER_WAVELENGTH,
    };
    pub use sweep::{sweep, sweep_one, sweep_source, GridResult, Sweep, SweepProgress, SweepSource};
    pub use spec::{spec_schema, CompareSpec, EnsembleSpec, SweepSpec, DEFAULT_SWEEP_GRID};
}

//! The typed results of the friction theory: μ and the contact at one
//! (v, T, σ0), its profile over the magnification and its decade bins.
//! A leaf of the friction module, shared by the problem (`theory.rs`) and
//! the panel march that fills it (`march.rs`).

use std::f64::consts::LN_10;

/// The contribution of one decade of q to μ.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct DecadeContribution {
    /// Lower end of the band, 1/m.
    pub q_min: f64,
    /// Upper end of the band, 1/m.
    pub q_max: f64,
    /// Δμ from q_min ≤ q < q_max.
    pub friction_coefficient: f64,
    /// Bound on the absolute error of Δμ.
    pub friction_coefficient_error_bound: f64,
}

/// The state of the contact at one magnification ζ = q/q_l.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct MagnificationPoint {
    /// ζ.
    pub zeta: f64,
    /// q = ζ q_l, 1/m.
    pub q: f64,
    /// G(q).
    pub g: f64,
    /// A/A0 = P(q) = erf(1/(2√G)).
    pub contact_fraction: f64,
    /// μ from the roughness with q_l ≤ q′ ≤ q (cumulative).
    pub friction_coefficient: f64,
    /// T_q, K (the background temperature without the flash temperature).
    pub temperature: f64,
    /// T_q − T, K (0 without the flash temperature).
    pub flash_temperature: f64,
}

/// Where the theory used a master curve outside its table, and how much of
/// μ and G came from there.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct TableExcursion {
    /// Lowest tabulated ω, rad/s.
    pub frequency_min: f64,
    /// Highest tabulated ω, rad/s.
    pub frequency_max: f64,
    /// Lowest principal reduced frequency a_T q v (at q_l, φ = 0), rad/s.
    pub reduced_frequency_min: f64,
    /// Highest principal reduced frequency a_T q v (at q1, φ = 0), rad/s.
    pub reduced_frequency_max: f64,
    /// Decades of a_T q v below the table, log10(ω_min/(a_T q_l v)) (0 if none).
    pub decades_below: f64,
    /// Decades of a_T q v above the table, log10(a_T q1 v/ω_max) (0 if none).
    pub decades_above: f64,
    /// Share of μ from frequencies outside the table (held end values);
    /// frequencies a_T q v cos φ → 0 are always sampled, with weight cos² φ.
    pub friction_fraction: f64,
    /// Share of G(q1) from frequencies outside the table.
    pub g_fraction: f64,
}

/// μ and the contact at one (v, T, σ0), with or without the flash temperature.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct FrictionResult {
    /// μ.
    pub friction_coefficient: f64,
    /// Bound on the absolute error of μ.
    pub friction_coefficient_error_bound: f64,
    /// A/A0 at the largest magnification q1/q_l.
    pub contact_fraction: f64,
    /// Bound on the absolute error of A/A0.
    pub contact_fraction_error_bound: f64,
    /// G(q1).
    pub g: f64,
    /// Bound on the absolute error of G(q1).
    pub g_error_bound: f64,
    /// T_{q1} − T, K (0 without the flash temperature).
    pub flash_temperature: f64,
    /// Bound on the absolute error of the flash temperature, K.
    pub flash_temperature_error_bound: f64,
    /// Δμ per decade of q, from q_l up.
    pub decades: Vec<DecadeContribution>,
    /// The contact against magnification.
    pub profile: Vec<MagnificationPoint>,
    /// A master curve's use outside its table (`None` for a Prony series).
    pub table_excursion: Option<TableExcursion>,
    /// The highest temperature beyond a shift table's last row that the flash
    /// temperature reached (a_T extended linearly in ln a_T), K.
    pub shift_table_extended_to: Option<f64>,
    /// Whether every panel reached the tolerance (else the error bounds say how far off).
    pub converged: bool,
    /// Integrand evaluations spent.
    pub evaluations: usize,
}

/// The friction at one sliding velocity, temperature and nominal pressure.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct FrictionPoint {
    /// Sliding velocity v, m/s.
    pub velocity: f64,
    /// Background temperature T, K.
    pub temperature: f64,
    /// Nominal pressure σ0, Pa.
    pub nominal_pressure: f64,
    /// The cut-off q1, 1/m.
    pub q1: f64,
    /// a_T at T.
    pub shift_factor: f64,
    /// b_T at T.
    pub vertical_shift: f64,
    /// The isothermal result (the rubber at T throughout).
    #[serde(flatten)]
    pub isothermal: FrictionResult,
    /// With the flash temperature (when the rubber has thermal properties).
    pub flash: Option<FrictionResult>,
}

/// ln 10, for the decade bins.
pub(crate) const DECADE: f64 = LN_10;

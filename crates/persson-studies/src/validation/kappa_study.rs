//! [`kappa_study`]: κ against the Hurst exponent from the low-load BEM
//! regime, in the continuum limit, averaged over seeds (Campañá & Müser,
//! EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005).

use serde::Serialize;

use super::compare::KAPPA_MAX_FRACTION;
use super::kappa::{GridKappa, KappaEstimate};
use super::resolution::{default_pressures, ResolvedBand, SweepSettings};
use super::sweep::{sweep, SweepProgress};
use crate::table::{number, Cell, Table, Tabulate};
use persson::error::{check, Error, Result};
use persson::kappa::Kappa;
use persson::spectrum::{Amplitude, SelfAffine};

/// What [`kappa_study`] computes: one self-affine surface per Hurst exponent.
#[derive(Debug, Clone, PartialEq)]
pub struct KappaStudyConfig {
    /// Hurst exponents H.
    pub hurst: Vec<f64>,
    /// Lower cut-off q_l (sets L = 2π/q_l).
    pub q_l: f64,
    /// Roll-off q_r (`None`: q_l).
    pub q_r: Option<f64>,
    /// Upper cut-off q_s (`None` and maximum: what the coarsest grid resolves).
    pub q_s: Option<f64>,
    /// rms slope over [q_l, q_s] of every surface.
    pub rms_slope: f64,
    /// Contact modulus E*.
    pub contact_modulus: f64,
    /// Nominal pressures (empty: 8 with linear-law A/A0 ≈ 0.005 … 0.09).
    pub nominal_pressure: Vec<f64>,
    /// The BEM side.
    pub sweep: SweepSettings,
}

impl Default for KappaStudyConfig {
    /// q_l = 1, rms slope 0.1, E* = 1, default pressures and sweep, no H.
    fn default() -> Self {
        KappaStudyConfig {
            hurst: Vec::new(),
            q_l: 1.0,
            q_r: None,
            q_s: None,
            rms_slope: 0.1,
            contact_modulus: 1.0,
            nominal_pressure: Vec::new(),
            sweep: SweepSettings::default(),
        }
    }
}

/// κ at one Hurst exponent.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct HurstKappa {
    /// H.
    pub hurst: f64,
    /// κ per grid, ascending.
    pub per_grid: Vec<GridKappa>,
    /// κ of the continuum limit.
    pub bem_extrapolated: KappaEstimate,
    /// Seed-averaged A/A0, `[grid][pressure]`.
    pub contact_fraction: Vec<Vec<f64>>,
}

/// κ(H) of the BEM next to Persson's √(8/π) and Bush's √(2π).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct KappaStudy {
    /// Nominal pressures σ0.
    pub nominal_pressure: Vec<f64>,
    /// Grids, ascending.
    pub grids: Vec<usize>,
    /// Seeds.
    pub seeds: Vec<u64>,
    /// q_l.
    pub q_l: f64,
    /// q_r.
    pub q_r: f64,
    /// q_s used, and whether the requested one was clipped.
    #[serde(flatten)]
    pub band: ResolvedBand,
    /// rms slope of every surface.
    pub rms_slope: f64,
    /// E*.
    pub contact_modulus: f64,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// The low-load regime: points with A/A0 below this.
    pub max_fraction: f64,
    /// Persson's κ = √(8/π).
    pub kappa_persson: f64,
    /// Bush's κ = √(2π).
    pub kappa_bush: f64,
    /// One entry per Hurst exponent.
    pub points: Vec<HurstKappa>,
}

/// κ against H: for each Hurst exponent a self-affine surface of the given
/// rms slope, the resolution sweep and κ of each grid and of the continuum
/// limit. q_s is clipped as in [`super::compare`] (one rule,
/// [`super::resolve_q_s`]).
///
/// # Errors
/// No Hurst exponent; invalid settings; as [`sweep`]; no point below
/// A/A0 = [`KAPPA_MAX_FRACTION`] at some H.
pub fn kappa_study(
    config: &KappaStudyConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<KappaStudy> {
    if config.hurst.is_empty() {
        return Err(Error::invalid("hurst", 0.0, "at least one"));
    }
    let e_star = check::positive("contact_modulus", config.contact_modulus)?;
    let q_l = check::positive("q_l", config.q_l)?;
    let sweep_config = config.sweep.config(q_l)?;
    let band = config.sweep.band(q_l, config.q_s)?;
    let q_r = config.q_r.unwrap_or(q_l);
    let pressures = if config.nominal_pressure.is_empty() {
        default_pressures(e_star, config.rms_slope, 8, 0.005, 0.09)
    } else {
        config.nominal_pressure.clone()
    };
    let per_sweep = pressures.len() * sweep_config.seeds.len() * sweep_config.grids.len();
    let total = per_sweep * config.hurst.len();
    let mut points = Vec::with_capacity(config.hurst.len());
    for (i, &h) in config.hurst.iter().enumerate() {
        let s = SelfAffine::new(q_l, q_r, band.q_s, h, Amplitude::RmsSlope(config.rms_slope))?;
        let sw = sweep(&s, e_star, &pressures, &sweep_config, &mut |mut p| {
            p.done += i * per_sweep;
            p.total = total;
            progress(p)
        })?;
        let k = sw
            .kappa(
                e_star,
                config.rms_slope,
                KAPPA_MAX_FRACTION,
                config.sweep.alpha,
            )
            .map_err(|e| Error::Inconsistent {
                name: format!("kappa at H = {h}"),
                requirement: e.to_string(),
            })?;
        points.push(HurstKappa {
            hurst: h,
            per_grid: k.per_grid,
            bem_extrapolated: k.extrapolated,
            contact_fraction: sw
                .mean_contact_fraction()
                .into_iter()
                .map(|m| m.mean)
                .collect(),
        });
    }
    Ok(KappaStudy {
        nominal_pressure: pressures,
        grids: sweep_config.grids,
        seeds: sweep_config.seeds,
        q_l,
        q_r,
        band,
        rms_slope: config.rms_slope,
        contact_modulus: e_star,
        tolerance: sweep_config.options.tolerance,
        max_fraction: KAPPA_MAX_FRACTION,
        kappa_persson: Kappa::Persson.value(),
        kappa_bush: Kappa::Bush.value(),
        points,
    })
}

impl Tabulate for KappaStudy {
    fn tables(&self) -> Vec<Table> {
        let grids: Vec<String> = self.grids.iter().map(|g| format!("{g}²")).collect();
        let mut t = Table::new(
            "kappa_hurst",
            format!(
                "κ from the low-load FFT-BEM regime (A/A0 < {}) on {}, {} seed(s)",
                number(self.max_fraction, 6),
                grids.join(", "),
                self.seeds.len()
            ),
        )
        .scalar(
            "kappa_persson",
            "Persson (2001): √(8/π)",
            self.kappa_persson,
        )
        .scalar("kappa_bush", "Bush et al. (1975): √(2π)", self.kappa_bush)
        .scalar("q_l", "q_l", self.q_l)
        .scalar("q_s", "q_s", self.band.q_s)
        .scalar("rms_slope", "h'_rms", self.rms_slope)
        .scalar("contact_modulus", "E*", self.contact_modulus)
        .scalar("tolerance", "tolerance ε", self.tolerance)
        .column_digits("hurst", "H", 3);
        for g in &self.grids {
            t = t.column_digits(&format!("kappa_{g}"), &format!("κ, N = {g}"), 4);
        }
        t = t
            .column_digits("kappa_extrapolated", "κ, N → ∞", 4)
            .column_digits("standard_error", "standard error", 2);
        for p in &self.points {
            let mut row = vec![Cell::Num(p.hurst)];
            row.extend(p.per_grid.iter().map(|g| Cell::Num(g.estimate.kappa)));
            let e = &p.bem_extrapolated;
            row.push(Cell::Num(e.kappa));
            row.push(e.standard_error.into());
            t.push(row);
        }
        vec![t]
    }
}

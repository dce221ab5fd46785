//! `persson compare --leakage / --conductance`: the leak rate and the contact
//! conductance of Persson's theory against the FFT-BEM on the surfaces of the
//! resolution sweep.
//!
//! # What is compared, per load σ0
//! - **Conductance.** The theory's stiffness K/A0 = −dσ0/dū
//!   ([`persson::separation`]) and, by Barber's identity (Barber, Proc. R.
//!   Soc. Lond. A 459, 53 (2003)), `h_c = 2 κ_s (K/A0)/E*`,
//!   `h_e = 2 (K/A0)/((ρ1 + ρ2) E*)`; with a gap law the gap term
//!   `h_gap = ∫ P(u) α(u) du` ([`persson::conductance`]). The BEM's K/A0 is a
//!   **linear solve on the converged contact set**
//!   ([`persson::bem::stiffness`]: the exact derivative of the discrete
//!   load–approach curve, no finite differences), the same identity turns it
//!   into h_c and h_e, and its gap term is the mean of α(g) over the solved
//!   gap field. K(N) and h_gap(N) are extrapolated to N → ∞ with the area's
//!   law `X(N) = X∞ + c N^−α` ([`super::extrapolate`], the same α).
//!   Barber's factor is common to theory and BEM, so the ratio of the
//!   thermal and electrical conductances is the stiffness ratio.
//! - **Leakage.** The critical-junction (Persson & Yang, J. Phys.: Condens.
//!   Matter 20, 315011 (2008); Lorenz & Persson, EPL 86, 44006 (2009)) and
//!   the effective-medium (Lorenz & Persson, Eur. Phys. J. E 32, 281 (2010))
//!   leak rates ([`persson::leakage`]) against Reynolds flow on the BEM's gap
//!   along x and along y ([`persson::bem::reynolds`]), Q the mean of the two,
//!   each averaged over the seeds. **Flow is not extrapolated**: near
//!   percolation the open channels of a finer grid are not a smooth
//!   correction of a coarser grid's (a channel one pixel wide closes or opens
//!   as the grid refines), so no law Q(N) = Q∞ + c N^−α holds. The BEM's Q is
//!   the finest grid's, and `bem_resolution_change` = Q(N)/Q(N/2) − 1 of the
//!   two finest grids tells how far it has converged; every grid's Q is in
//!   [`TransportComparison::bem`].
//!
//! The ratio theory/BEM is reported at every load where the BEM's gap
//! percolates (Dapp, Lücke, Persson & Müser, Phys. Rev. Lett. 108, 244301
//! (2012) compared the critical junction with exact flow this way); where it
//! does not, the BEM's leak rate is 0, the ratio absent and a note says so.
//!
//! The BEM solves of this study are the sweep's surfaces solved once more
//! (same grids, seeds and solver tolerance) with the stiffness and flow
//! computed on each solution ([`crate::scene::transport_bem`]): the area
//! sweep itself is unchanged.

use serde::Serialize;

use persson::bem::GridSurface;
use persson::conductance::{Conductance, ConductanceOptions, ConductancePoint};
use persson::error::{check, Error, Result};
use persson::gap::DensityOptions;
use persson::leakage::{
    CriticalJunction, CriticalJunctionPoint, Drive, EffectiveMedium, EffectiveMediumPoint,
    LeakStatus, Seal, DEFAULT_PERCOLATION_THRESHOLD,
};
use persson::spectrum::Spectrum;

use super::continuum::extrapolate;
use super::resolution::SweepConfig;
use crate::transport::TransportRequest;
use crate::transport::BemTransportPoint;
use crate::table::number;
use crate::warning::Warning;
use persson::leakage::Fluid;

/// How the BEM's stiffness is computed (shown in the tables and the JSON).
pub const STIFFNESS_METHOD: &str =
    "linear solve on the converged contact set (exact derivative of the discrete load-approach curve)";

/// How the BEM's flow is taken from the sweep (shown in the tables and the JSON).
pub const FLOW_METHOD: &str =
    "Reynolds flow on the finest grid's gap, mean of x and y and of the seeds; not extrapolated";

/// What `compare --leakage / --conductance` computes besides the area.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct TransportCompareConfig {
    /// Conductivities, resistivities, gap law and seal (which parts to compare).
    pub request: TransportRequest,
    /// a_c of the critical junction, in (0, 1).
    pub percolation_threshold: f64,
    /// Relative tolerance of the theory's wavevector integrals.
    pub tolerance: f64,
    /// Kinks of C(q) inside the band (the roll-off), for the theory's integrals.
    pub breaks: Vec<f64>,
}

impl TransportCompareConfig {
    /// `request` with a_c = 0.42, tolerance 1e-9 and no breaks.
    pub fn new(request: TransportRequest) -> Self {
        TransportCompareConfig {
            request,
            percolation_threshold: DEFAULT_PERCOLATION_THRESHOLD,
            tolerance: 1e-9,
            breaks: Vec::new(),
        }
    }

    /// Check the settings against the comparison they join: a threshold in
    /// (0, 1), a tolerance in range, something to compare, a periodic
    /// surface (`boundary` of a map, `None` synthesised) and no yield stress.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `percolation_threshold` or
    /// `tolerance`; [`Error::Inconsistent`] naming `leakage / conductance`.
    pub fn validate(
        &self,
        boundary: Option<persson::bem::Boundary>,
        yield_stress: Option<f64>,
    ) -> Result<()> {
        check::tolerance("tolerance", self.tolerance)?;
        let a_c = self.percolation_threshold;
        if !(a_c > 0.0 && a_c < 1.0) {
            return Err(Error::invalid("percolation_threshold", a_c, "in (0, 1)"));
        }
        if let Some(seal) = &self.request.seal {
            seal.validate()?;
        }
        let inconsistent = |requirement: &str| {
            Err(Error::Inconsistent {
                name: "leakage / conductance".into(),
                requirement: requirement.into(),
            })
        };
        if !self.conductance() && self.request.seal.is_none() {
            return inconsistent("a seal, conductivities, resistivities or a gap law to compare");
        }
        if yield_stress.is_some() {
            return inconsistent(
                "not with yield_stress (Barber's identity and the stiffness solve are elastic)",
            );
        }
        if boundary == Some(persson::bem::Boundary::Free) {
            return inconsistent(
                "a periodic surface (the stiffness and the flow of the periodic cell)",
            );
        }
        if cfg!(not(feature = "flow")) {
            return inconsistent("a persson built with the `flow` feature");
        }
        Ok(())
    }

    /// Whether the conductance part is asked for.
    pub fn conductance(&self) -> bool {
        let r = &self.request;
        r.conductivity.is_some() || r.resistivity.is_some() || r.gap_law.is_some()
    }
}

/// The BEM's transport values on one grid, mean over the seeds, per load.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct TransportGrid {
    /// Grid side N.
    pub grid: usize,
    /// A/A0 of the transport solves.
    pub contact_fraction: Vec<f64>,
    /// K/A0 (linear solve on the contact set), Pa/m.
    pub stiffness: Vec<f64>,
    /// h_gap over the gap field, W/(m² K) (with a gap law).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_conductance: Option<Vec<f64>>,
    /// Q of the flow along x, m³/s (with a seal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leak_rate_x: Option<Vec<f64>>,
    /// Q of the flow along y, m³/s (with a seal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leak_rate_y: Option<Vec<f64>>,
    /// Seeds whose gap percolates along x or y (with a seal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub percolating_seeds: Option<Vec<usize>>,
}

/// Theory against BEM for the conductance at one load.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ConductanceCompared {
    /// The theory's K/A0, Pa/m.
    pub theory_stiffness: f64,
    /// The BEM's K/A0 extrapolated to N → ∞.
    pub bem_stiffness: f64,
    /// Its uncertainty: the fit's standard error, else the extrapolation
    /// step from the finest grid (whose K/A0 is `bem[last].stiffness`).
    pub bem_stiffness_error: f64,
    /// theory / BEM (extrapolated); also the ratio of h_c and of h_e.
    pub stiffness_ratio: f64,
    /// Theory's h_c, W/(m² K) (with conductivities).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theory_thermal_conductance: Option<f64>,
    /// BEM's h_c from K∞.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_thermal_conductance: Option<f64>,
    /// Theory's h_e, S/m² (with resistivities).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theory_electrical_conductance: Option<f64>,
    /// BEM's h_e from K∞.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_electrical_conductance: Option<f64>,
    /// Theory's h_gap, W/(m² K) (with a gap law).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theory_gap_conductance: Option<f64>,
    /// BEM's h_gap extrapolated to N → ∞.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_gap_conductance: Option<f64>,
    /// theory / BEM of h_gap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_conductance_ratio: Option<f64>,
}

/// Theory against BEM for the leak rate at one load.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct LeakageCompared {
    /// Critical junction: Q, m³/s (0 when sealed).
    pub critical_junction_leak_rate: f64,
    /// Critical junction: whether the seal leaks.
    pub critical_junction_status: LeakStatus,
    /// Critical junction: u1(ζ_c), m.
    pub critical_separation: f64,
    /// Effective medium: Q, m³/s (0 when sealed).
    pub effective_medium_leak_rate: f64,
    /// Effective medium: whether the seal leaks.
    pub effective_medium_status: LeakStatus,
    /// BEM: Q of the finest grid, mean of x and y and of the seeds, m³/s.
    pub bem_leak_rate: f64,
    /// BEM: Q along x (finest grid).
    pub bem_leak_rate_x: f64,
    /// BEM: Q along y (finest grid).
    pub bem_leak_rate_y: f64,
    /// BEM: whether the finest grid's gap percolates (any seed, x or y).
    pub bem_percolates: bool,
    /// Q(N)/Q(N/2) − 1 of the two finest grids (absent when either is 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_resolution_change: Option<f64>,
    /// Critical junction / BEM (absent where the BEM does not leak).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_junction_ratio: Option<f64>,
    /// Effective medium / BEM (absent where the BEM does not leak).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effective_medium_ratio: Option<f64>,
    /// Why a leak rate is 0 or a ratio absent.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// Theory against BEM at one load.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct TransportComparedPoint {
    /// σ0.
    pub nominal_pressure: f64,
    /// A/A0 of the finest grid's transport solve (mean over seeds).
    pub bem_contact_fraction: f64,
    /// The conductance (with `--conductance`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conductance: Option<ConductanceCompared>,
    /// The leak rate (with `--leakage`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leakage: Option<LeakageCompared>,
}

/// `compare --leakage / --conductance`: the theories against the BEM.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct TransportComparison {
    /// How the BEM's stiffness is computed ([`STIFFNESS_METHOD`]).
    pub stiffness_method: &'static str,
    /// How the BEM's flow is taken ([`FLOW_METHOD`]; with a seal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flow_method: Option<&'static str>,
    /// The fluid (with `--leakage`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fluid: Option<Fluid>,
    /// η, Pa s (with `--leakage`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub viscosity: Option<f64>,
    /// ΔP of a liquid, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_drop: Option<f64>,
    /// P_a of a gas, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inlet_pressure: Option<f64>,
    /// P_b of a gas, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outlet_pressure: Option<f64>,
    /// L_x, m (with `--leakage`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seal_width: Option<f64>,
    /// L_y, m (with `--leakage`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seal_length: Option<f64>,
    /// a_c of the critical junction (with `--leakage`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub percolation_threshold: Option<f64>,
    /// The exponent α of the stiffness extrapolation per load.
    pub alpha: Vec<f64>,
    /// Per load.
    pub points: Vec<TransportComparedPoint>,
    /// The BEM per grid, ascending.
    pub bem: Vec<TransportGrid>,
    /// Wall-clock seconds of the BEM's transport solves (contact, stiffness, flow).
    pub seconds: f64,
}

/// The surfaces of the comparison on every grid of `config`, per seed.
pub(super) enum Surfaces<'a> {
    /// Synthesised from the band-limited spectrum.
    Synthesised(&'a dyn Spectrum),
    /// A periodic map low-passed at q_s (first seed only).
    BandLimitedMap(&'a GridSurface, f64),
}

impl Surfaces<'_> {
    pub(super) fn seeds<'s>(&self, seeds: &'s [u64]) -> &'s [u64] {
        match self {
            Surfaces::Synthesised(_) => seeds,
            Surfaces::BandLimitedMap(..) => seeds.get(..1).unwrap_or_default(),
        }
    }

    pub(super) fn on_grids(&self, config: &SweepConfig, seed: u64) -> Result<Vec<GridSurface>> {
        match *self {
            Surfaces::Synthesised(s) => {
                persson::bem::resample::nested_surfaces(s, &config.grids, config.size, seed)
            }
            Surfaces::BandLimitedMap(m, q_s) => {
                persson::bem::resample::band_limited_copies(m, q_s, &config.grids)
            }
        }
    }
}

/// The theory's conductance and leak rate at `pressures`.
struct TheoryValues {
    conductance: Option<Vec<ConductancePoint>>,
    leakage: Option<Vec<(CriticalJunctionPoint, EffectiveMediumPoint)>>,
}

fn theory(
    band: &dyn Spectrum,
    e_star: f64,
    pressures: &[f64],
    t: &TransportCompareConfig,
) -> Result<TheoryValues> {
    let density = DensityOptions {
        tolerance: t.tolerance,
        breaks: t.breaks.clone(),
        ..DensityOptions::default()
    };
    let conductance = if t.conductance() {
        let options = ConductanceOptions {
            conductivity: t.request.conductivity,
            resistivity: t.request.resistivity,
            gap_law: t.request.gap_law.clone(),
            density: density.clone(),
        };
        Some(Conductance::new(band, e_star, options)?.load_curve(pressures)?)
    } else {
        None
    };
    let leakage = match t.request.seal {
        Some(seal) => {
            let cj = CriticalJunction::new(band, e_star, seal)?
                .with_threshold(t.percolation_threshold)?
                .with_tolerance(t.tolerance)?
                .with_breaks(&t.breaks)
                .load_curve(pressures)?;
            let em = EffectiveMedium::new(band, e_star, seal, density)?.load_curve(pressures)?;
            Some(cj.into_iter().zip(em).collect())
        }
        None => None,
    };
    Ok(TheoryValues {
        conductance,
        leakage,
    })
}

/// The BEM's transport points, `[grid][seed][pressure]` in the caller's order.
fn bem_points(
    surfaces: &Surfaces<'_>,
    e_star: f64,
    pressures: &[f64],
    config: &SweepConfig,
    request: &TransportRequest,
) -> Result<Vec<Vec<Vec<BemTransportPoint>>>> {
    let mut order: Vec<usize> = (0..pressures.len()).collect();
    order.sort_by(|&a, &b| pressures[a].total_cmp(&pressures[b]));
    let sorted: Vec<f64> = order.iter().map(|&k| pressures[k]).collect();
    let mut out: Vec<Vec<Vec<BemTransportPoint>>> = vec![Vec::new(); config.grids.len()];
    for &seed in surfaces.seeds(&config.seeds) {
        for (gi, surface) in surfaces.on_grids(config, seed)?.iter().enumerate() {
            let r = crate::transport::bem::transport(
                surface,
                Some(seed),
                e_star,
                &sorted,
                config.options.tolerance,
                request,
            )?;
            let mut points: Vec<Option<BemTransportPoint>> = vec![None; pressures.len()];
            for (p, &k) in r.points.into_iter().zip(&order) {
                points[k] = Some(p);
            }
            out[gi].push(points.into_iter().flatten().collect());
        }
    }
    Ok(out)
}

/// Mean over the seeds of `f` at each pressure.
fn seed_mean(
    seeds: &[Vec<BemTransportPoint>],
    np: usize,
    f: &dyn Fn(&BemTransportPoint) -> f64,
) -> Vec<f64> {
    (0..np)
        .map(|k| seeds.iter().map(|s| f(&s[k])).sum::<f64>() / seeds.len().max(1) as f64)
        .collect()
}

/// σ_eff of the flow along `x` (true) or y of one point (0 without flows).
fn sigma(p: &BemTransportPoint, x: bool) -> f64 {
    use persson::leakage::FlowDirection;
    let want = if x {
        FlowDirection::X
    } else {
        FlowDirection::Y
    };
    p.flows
        .iter()
        .find(|f| f.direction == want)
        .map_or(0.0, |f| f.effective_flow_conductivity)
}

fn grid_values(
    grid: usize,
    seeds: &[Vec<BemTransportPoint>],
    np: usize,
    seal: Option<&Seal>,
) -> Result<TransportGrid> {
    let leak = |x: bool| -> Result<Option<Vec<f64>>> {
        seal.map(|s| {
            seed_mean(seeds, np, &|p| sigma(p, x))
                .into_iter()
                .map(|sig| s.leak_rate(sig))
                .collect()
        })
        .transpose()
    };
    Ok(TransportGrid {
        grid,
        contact_fraction: seed_mean(seeds, np, &|p| p.contact_fraction),
        stiffness: seed_mean(seeds, np, &|p| p.stiffness),
        gap_conductance: seeds
            .first()
            .and_then(|s| s.first())
            .and_then(|p| p.gap_conductance)
            .map(|_| seed_mean(seeds, np, &|p| p.gap_conductance.unwrap_or(0.0))),
        leak_rate_x: leak(true)?,
        leak_rate_y: leak(false)?,
        percolating_seeds: seal.map(|_| {
            (0..np)
                .map(|k| {
                    seeds
                        .iter()
                        .filter(|s| s[k].percolates == Some(true))
                        .count()
                })
                .collect()
        }),
    })
}

/// Compare the theory's conductance and leak rate with the BEM's on
/// `surfaces` (the sweep's grids and seeds of `sweep`), at `pressures`; with
/// the warnings of the loads at which a method finds the seal sealed.
///
/// # Errors
/// A bad threshold or tolerance (named `percolation_threshold`,
/// `tolerance`); as the theories, [`crate::scene::transport_bem::transport`]
/// and [`super::extrapolate`]; without the feature `flow`, an error.
pub(super) fn compare_transport(
    band: &dyn Spectrum,
    surfaces: Surfaces<'_>,
    e_star: f64,
    pressures: &[f64],
    sweep: &SweepConfig,
    alpha: Option<f64>,
    t: &TransportCompareConfig,
) -> Result<(TransportComparison, Vec<Warning>)> {
    t.validate(None, None)?;
    let a_c = t.percolation_threshold;
    let th = theory(band, e_star, pressures, t)?;
    let start = persson::clock::Instant::now();
    let raw = bem_points(&surfaces, e_star, pressures, sweep, &t.request)?;
    let seconds = start.elapsed().as_secs_f64();
    let np = pressures.len();
    let seal = t.request.seal;
    let grids: Vec<TransportGrid> = sweep
        .grids
        .iter()
        .zip(&raw)
        .map(|(&g, seeds)| grid_values(g, seeds, np, seal.as_ref()))
        .collect::<Result<_>>()?;
    let n: Vec<f64> = grids.iter().map(|g| g.grid as f64).collect();
    let (finest, coarser) = match grids.as_slice() {
        [.., c, f] => (f, c),
        _ => {
            return Err(Error::invalid(
                "levels",
                grids.len() as f64,
                "at least 2 grids",
            ))
        }
    };
    let mut alphas = Vec::with_capacity(np);
    let mut points = Vec::with_capacity(np);
    for (k, &p) in pressures.iter().enumerate() {
        let ks: Vec<f64> = grids.iter().map(|g| g.stiffness[k]).collect();
        let k_inf = extrapolate(&n, &ks, alpha)?;
        alphas.push(k_inf.alpha);
        let conductance = match &th.conductance {
            Some(c) => Some(conductance_point(
                &c[k],
                k_inf.value,
                k_inf.uncertainty(),
                &grids,
                &n,
                k,
                alpha,
                e_star,
                &t.request,
            )?),
            None => None,
        };
        let leakage = match (&th.leakage, seal) {
            (Some(l), Some(_)) => Some(leakage_point(&l[k].0, &l[k].1, finest, coarser, k)),
            _ => None,
        };
        points.push(TransportComparedPoint {
            nominal_pressure: p,
            bem_contact_fraction: finest.contact_fraction[k],
            conductance,
            leakage,
        });
    }
    let warnings = sealed_warnings(&points, a_c);
    Ok((
        TransportComparison {
            stiffness_method: STIFFNESS_METHOD,
            flow_method: seal.map(|_| FLOW_METHOD),
            fluid: seal.map(|s| s.drive.fluid()),
            viscosity: seal.map(|s| s.viscosity),
            pressure_drop: seal.and_then(|s| match s.drive {
                Drive::Liquid { pressure_drop } => Some(pressure_drop),
                Drive::Gas { .. } => None,
            }),
            inlet_pressure: seal.and_then(|s| match s.drive {
                Drive::Gas { inlet_pressure, .. } => Some(inlet_pressure),
                Drive::Liquid { .. } => None,
            }),
            outlet_pressure: seal.and_then(|s| match s.drive {
                Drive::Gas {
                    outlet_pressure, ..
                } => Some(outlet_pressure),
                Drive::Liquid { .. } => None,
            }),
            seal_width: seal.map(|s| s.seal_width),
            seal_length: seal.map(|s| s.seal_length),
            percolation_threshold: seal.map(|_| a_c),
            alpha: alphas,
            points,
            bem: grids,
            seconds,
        },
        warnings,
    ))
}

#[allow(clippy::too_many_arguments)]
fn conductance_point(
    c: &ConductancePoint,
    k_inf: f64,
    k_uncertainty: f64,
    grids: &[TransportGrid],
    n: &[f64],
    k: usize,
    alpha: Option<f64>,
    e_star: f64,
    request: &TransportRequest,
) -> Result<ConductanceCompared> {
    let exact = |v| persson::Estimate {
        value: v,
        error: 0.0,
    };
    let bem_thermal = request
        .conductivity
        .map(|kc| persson::conductance::thermal_conductance(exact(k_inf), e_star, &kc))
        .transpose()?
        .map(|e| e.value);
    let bem_electrical = request
        .resistivity
        .map(|r| persson::conductance::electrical_conductance(exact(k_inf), e_star, &r))
        .transpose()?
        .map(|e| e.value);
    let bem_gap = grids
        .iter()
        .map(|g| g.gap_conductance.as_ref().map(|v| v[k]))
        .collect::<Option<Vec<f64>>>()
        .map(|h| extrapolate(n, &h, alpha).map(|e| e.value))
        .transpose()?;
    Ok(ConductanceCompared {
        theory_stiffness: c.stiffness,
        bem_stiffness: k_inf,
        bem_stiffness_error: k_uncertainty,
        stiffness_ratio: c.stiffness / k_inf,
        theory_thermal_conductance: c.thermal_conductance,
        bem_thermal_conductance: bem_thermal,
        theory_electrical_conductance: c.electrical_conductance,
        bem_electrical_conductance: bem_electrical,
        theory_gap_conductance: c.gap_conductance,
        bem_gap_conductance: bem_gap,
        gap_conductance_ratio: c
            .gap_conductance
            .zip(bem_gap)
            .and_then(|(t, b)| (b > 0.0).then_some(t / b)),
    })
}

fn leakage_point(
    cj: &CriticalJunctionPoint,
    em: &EffectiveMediumPoint,
    finest: &TransportGrid,
    coarser: &TransportGrid,
    k: usize,
) -> LeakageCompared {
    let q = |g: &TransportGrid| {
        let x = g.leak_rate_x.as_ref().map_or(0.0, |v| v[k]);
        let y = g.leak_rate_y.as_ref().map_or(0.0, |v| v[k]);
        (x, y, 0.5 * (x + y))
    };
    let (qx, qy, q_bem) = q(finest);
    let q_coarse = q(coarser).2;
    let percolates = finest.percolating_seeds.as_ref().is_some_and(|v| v[k] > 0);
    let leaks = q_bem > 0.0;
    let ratio = |t: f64| leaks.then_some(t / q_bem);
    let mut notes = Vec::new();
    if !leaks {
        notes.push(format!(
            "BEM: no open path joins inlet and outlet on the {}² grid (A/A0 = {}): its leak rate is 0",
            finest.grid,
            number(finest.contact_fraction[k], 3)
        ));
    }
    if cj.status == LeakStatus::Sealed {
        notes.push("critical junction: A/A0 at or above a_c, sealed (Q = 0)".into());
    }
    if em.status == LeakStatus::Sealed {
        notes.push("effective medium: A/A0 at or above 1/2, sealed (Q = 0)".into());
    }
    LeakageCompared {
        critical_junction_leak_rate: cj.leak_rate,
        critical_junction_status: cj.status,
        critical_separation: cj.critical_separation,
        effective_medium_leak_rate: em.leak_rate,
        effective_medium_status: em.status,
        bem_leak_rate: q_bem,
        bem_leak_rate_x: qx,
        bem_leak_rate_y: qy,
        bem_percolates: percolates,
        bem_resolution_change: (leaks && q_coarse > 0.0).then(|| q_bem / q_coarse - 1.0),
        critical_junction_ratio: ratio(cj.leak_rate),
        effective_medium_ratio: ratio(em.leak_rate),
        note: (!notes.is_empty()).then(|| notes.join("; ")),
    }
}

/// [`Warning::Sealed`] of each method (critical junction, effective medium,
/// BEM) at the loads where it finds no leak.
fn sealed_warnings(points: &[TransportComparedPoint], a_c: f64) -> Vec<Warning> {
    type Pick = fn(&LeakageCompared) -> bool;
    let methods: [(&str, Option<f64>, Pick); 3] = [
        ("critical-junction", Some(a_c), |l| {
            l.critical_junction_status == LeakStatus::Sealed
        }),
        ("effective-medium", Some(0.5), |l| {
            l.effective_medium_status == LeakStatus::Sealed
        }),
        ("bem", None, |l| l.bem_leak_rate == 0.0),
    ];
    let mut out = Vec::new();
    for (method, threshold, sealed) in methods {
        let hits: Vec<&TransportComparedPoint> = points
            .iter()
            .filter(|p| p.leakage.as_ref().is_some_and(sealed))
            .collect();
        let Some(first) = hits
            .iter()
            .min_by(|a, b| a.nominal_pressure.total_cmp(&b.nominal_pressure))
        else {
            continue;
        };
        out.push(Warning::Sealed {
            method: method.into(),
            nominal_pressure: first.nominal_pressure,
            count: hits.len(),
            contact_fraction: first.bem_contact_fraction,
            percolation_threshold: threshold, message: String::new(), }.described(crate::transport::describe));
    }
    out
}

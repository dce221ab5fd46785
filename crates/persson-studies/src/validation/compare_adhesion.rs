//! `persson compare --work-of-adhesion`: Persson's adhesive contact theory
//! against the adhesive FFT-BEM on the surfaces of the resolution sweep.
//!
//! # What is compared, per work of adhesion Δγ
//! - **The BEM** ([`persson::bem::adhesive`], gap-based
//!   Polonsky–Keer of Rey, Anciaux & Molinari, Comput. Mech. 60, 69 (2017))
//!   runs each seed's surface on the two finest grids along one path of mean
//!   gaps, in then out (warm-started: a loading–unloading curve): in from
//!   ḡ_hi = the largest first-touch gap max h − mean h of the seeds' finest
//!   surfaces, plus ρ, to ḡ_lo = the theory's ū at the largest compared
//!   load ([`persson::separation`]), then out to ḡ_hi + 2ρ and on by the
//!   same step while any node still touches or attracts (a sticky contact
//!   stretches far beyond first touch before it lets go). The same ḡ list
//!   for every seed and grid (a path that let go earlier is detached, p̄ = 0,
//!   at the points of the longer ones), so the seeds are averaged point by
//!   point. The BEM reports σ0 = p̄ (negative in
//!   tension), the repulsive contact fraction and the pull-off −min p̄.
//! - **The theory** ([`persson::adhesion::AdhesiveContact`], Persson 2002,
//!   the stress diffusion with the detachment boundary σ_a(ζ)) at the BEM's
//!   seed-mean σ0 of each point and ζ = q_s/q_l of the sweep's band, and its
//!   pull-off stress σ_p. A σ0 at or below −σ_p is detached in the theory
//!   (A/A0 = 0).
//!
//! The BEM needs a range ρ of the cohesive law that the theory does not
//! have (its detachment is a Griffith balance, the limit of short range).
//! The default ρ = h'_rms L/N is the height the surface changes by over one
//! spacing of the finest grid at its rms slope: the shortest range whose
//! cohesive zone (a band of lateral width ~ρ/h'_rms around each contact)
//! the grid resolves; `adhesion_range` sets another. The default law is Maugis–Dugdale (as
//! `bem rough`).
//!
//! The BEM's values are the finest grid's; `bem_resolution_change` =
//! X(N)/X(N/2) − 1 of the two finest grids tells how far they have
//! converged. They are not extrapolated: the adhesive contact of a finer
//! grid resolves finer asperities that stick or not, and no smooth law
//! X(N) = X∞ + c N^−α was assumed.

use serde::Serialize;

use persson::adhesion::{AdhesionModel, AdhesiveContact};
use persson::bem::adhesive::{AdhesiveOptions, AdhesiveSolver};
use persson::bem::{Boundary, Operator};
use persson::error::{check, Error, Result};
use persson::separation::Separation;
use persson::spectrum::Spectrum;

use super::compare_transport::Surfaces;
use super::continuum::mean_and_error;
use super::resolution::SweepConfig;
use crate::bem_detail::LawKind;
use crate::table::{Cell, Table};

/// Points of the path in (the way out has twice as many).
pub const DEFAULT_PATH_POINTS: usize = 8;

/// What `compare --work-of-adhesion` computes besides the area.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct AdhesionCompareConfig {
    /// The works of adhesion Δγ compared, each > 0 (J/m², unit of E* × L).
    pub work_of_adhesion: Vec<f64>,
    /// Range ρ of the BEM's cohesive law (`None`: h'_rms times the finest
    /// grid's spacing).
    pub adhesion_range: Option<f64>,
    /// The BEM's cohesive law.
    pub adhesion: LawKind,
    /// Points of the path in; the way out has twice as many.
    pub path_points: usize,
}

impl AdhesionCompareConfig {
    /// `work_of_adhesion` with the default range, the Maugis–Dugdale law and
    /// [`DEFAULT_PATH_POINTS`].
    pub fn new(work_of_adhesion: Vec<f64>) -> Self {
        AdhesionCompareConfig {
            work_of_adhesion,
            adhesion_range: None,
            adhesion: LawKind::Maugis,
            path_points: DEFAULT_PATH_POINTS,
        }
    }

    /// Check the settings against the comparison they join: Δγ and ρ
    /// finite and > 0, at least 2 path points, a periodic surface
    /// (`boundary` of a map, `None` synthesised) and no yield stress.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `work_of_adhesion`,
    /// `adhesion_range` or `path_points`; [`Error::Inconsistent`] naming
    /// `work_of_adhesion`.
    pub fn validate(
        &self,
        boundary: Option<persson::bem::Boundary>,
        yield_stress: Option<f64>,
    ) -> Result<()> {
        if self.work_of_adhesion.is_empty() {
            return Err(Error::Inconsistent {
                name: "work_of_adhesion".into(),
                requirement: "at least one work of adhesion".into(),
            });
        }
        for &w in &self.work_of_adhesion {
            check::positive("work_of_adhesion", w)?;
        }
        if let Some(r) = self.adhesion_range {
            check::positive("adhesion_range", r)?;
        }
        if self.path_points < 2 {
            return Err(Error::invalid(
                "path_points",
                self.path_points as f64,
                "at least 2",
            ));
        }
        let inconsistent = |requirement: &str| {
            Err(Error::Inconsistent {
                name: "work_of_adhesion".into(),
                requirement: requirement.into(),
            })
        };
        if yield_stress.is_some() {
            return inconsistent("not with yield_stress (the adhesive BEM is elastic)");
        }
        if boundary == Some(persson::bem::Boundary::Free) {
            return inconsistent(
                "a periodic surface (the adhesive path is under mean-gap control)",
            );
        }
        Ok(())
    }
}

/// The longest cohesive range over the surface's highest point above its
/// mean height a comparison runs (its path reaches 3ρ above first touch).
pub const MAX_RANGE_OVER_HEIGHTS: f64 = 100.0;

/// Theory against BEM at one point of the path.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AdhesionComparedPoint {
    /// ḡ, the prescribed mean gap (unit of L).
    pub mean_separation: f64,
    /// σ0 = p̄ of the finest grid, mean over the seeds (negative in tension).
    pub nominal_pressure: f64,
    /// Its standard error over the seeds (`None` for one seed).
    pub nominal_pressure_standard_error: Option<f64>,
    /// The BEM's repulsive contact fraction, finest grid, mean over seeds.
    pub bem_contact_fraction: f64,
    /// A(N)/A(N/2) − 1 of the two finest grids (absent when either is 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_resolution_change: Option<f64>,
    /// The theory's A/A0 at σ0 (0 at or below −σ_p).
    pub theory_contact_fraction: f64,
    /// Theory / BEM of A/A0 (absent where the BEM has no contact).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_fraction_ratio: Option<f64>,
}

/// Theory against BEM for one work of adhesion.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AdhesionCompared {
    /// Δγ.
    pub work_of_adhesion: f64,
    /// ρ of the BEM's law.
    pub adhesion_range: f64,
    /// The theory's pull-off stress σ_p = σ_a(ζ = 1).
    pub theory_pull_off_stress: f64,
    /// The BEM's pull-off −min p̄ of the finest grid, mean over the seeds.
    pub bem_pull_off_stress: f64,
    /// Its standard error over the seeds (`None` for one seed).
    pub bem_pull_off_stress_standard_error: Option<f64>,
    /// F(N)/F(N/2) − 1 of the pull-off of the two finest grids.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bem_pull_off_resolution_change: Option<f64>,
    /// Theory / BEM of the pull-off stress (absent when the BEM never pulls).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pull_off_ratio: Option<f64>,
    /// The path, in then out.
    pub points: Vec<AdhesionComparedPoint>,
}

/// `compare --work-of-adhesion`: the adhesive theory against the BEM.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AdhesionComparison {
    /// The BEM's cohesive law.
    pub adhesion: LawKind,
    /// The two grids solved (the sweep's finest two).
    pub grids: Vec<usize>,
    /// One entry per Δγ, in the order given.
    pub per_work: Vec<AdhesionCompared>,
    /// Seconds of the adhesive BEM solves.
    pub seconds: f64,
}

/// One seed's path on one grid: (p̄ per point, A_rep per point, pull-off).
type SeedPath = (Vec<f64>, Vec<f64>, f64);

/// Compare Persson's adhesive theory with the adhesive BEM on `surfaces`
/// (the two finest grids of `sweep`), for each Δγ of `t`, along a mean-gap
/// path reaching the theory's ū at `max_pressure`; `rms_slope` is the
/// band's h'_rms (the default range).
///
/// # Errors
/// Fewer than 2 grids; the theory or the BEM failing. (The settings are
/// checked by [`AdhesionCompareConfig::validate`] before the sweep.)
pub(super) fn compare_adhesion(
    band: &dyn Spectrum,
    surfaces: Surfaces<'_>,
    (e_star, rms_slope): (f64, f64),
    max_pressure: f64,
    sweep: &SweepConfig,
    t: &AdhesionCompareConfig,
) -> Result<AdhesionComparison> {
    let (coarser, finest) = match sweep.grids.as_slice() {
        [.., c, f] => (*c, *f),
        _ => {
            return Err(Error::invalid(
                "levels",
                sweep.grids.len() as f64,
                "at least 2 grids",
            ))
        }
    };
    let seeds = surfaces.seeds(&sweep.seeds);
    // The two finest grids of each seed.
    let maps: Vec<[persson::bem::GridSurface; 2]> = seeds
        .iter()
        .map(|&s| {
            let mut g = surfaces.on_grids(sweep, s)?;
            let f = g
                .pop()
                .ok_or_else(|| Error::invalid("levels", 0.0, "≥ 2"))?;
            let c = g
                .pop()
                .ok_or_else(|| Error::invalid("levels", 1.0, "≥ 2"))?;
            Ok([c, f])
        })
        .collect::<Result<_>>()?;
    let touch = maps
        .iter()
        .map(|[_, f]| {
            let (max, mean) = stats(&f.heights);
            max - mean
        })
        .fold(0.0f64, f64::max);
    let u_lo = Separation::new(band, e_star)?
        .mean_separation(max_pressure)?
        .value;
    let zeta = band.q_max() / band.q_min();
    let options = AdhesiveOptions {
        tolerance: sweep.options.tolerance.max(1e-10),
        max_iterations: sweep.options.max_iterations.max(20_000),
    };
    let start = persson::clock::Instant::now();
    let mut per_work = Vec::with_capacity(t.work_of_adhesion.len());
    for &dg in &t.work_of_adhesion {
        let rho = t
            .adhesion_range
            .unwrap_or(rms_slope * sweep.size / finest as f64);
        // The path runs out to touch + 3ρ: a range far beyond the heights
        // (the theory's gaps then overflow) attracts across the whole surface.
        if rho.is_nan() || rho > MAX_RANGE_OVER_HEIGHTS * touch {
            return Err(Error::invalid(
                "adhesion_range",
                rho,
                format!(
                    "at most {MAX_RANGE_OVER_HEIGHTS} × the surface's highest point above its mean \
                     ({} m)",
                    crate::table::number(touch, 4)
                ),
            ));
        }
        let gaps = path(
            touch + rho,
            u_lo.min(touch),
            touch + 3.0 * rho,
            t.path_points,
        );
        let law = t.adhesion.law(dg, rho)?;
        let step = (gaps[gaps.len() - 1] - gaps[gaps.len() - 2]).abs();
        let cap = 4 * gaps.len();
        let mut runs: [Vec<SeedPath>; 2] = [Vec::new(), Vec::new()];
        for pair in &maps {
            for (slot, s) in runs.iter_mut().zip(pair) {
                slot.push(seed_path(s, e_star, &law, &gaps, (step, cap), &options)?);
            }
        }
        // The longest way out sets the list; a path that ended earlier was
        // detached there (p̄ = 0, A = 0) and stays so.
        let len = runs.iter().flatten().map(|r| r.0.len()).max().unwrap_or(0);
        for r in runs.iter_mut().flatten() {
            r.0.resize(len, 0.0);
            r.1.resize(len, 0.0);
        }
        let last = gaps[gaps.len() - 1];
        let gaps: Vec<f64> = gaps
            .iter()
            .copied()
            .chain((1..=len - gaps.len()).map(|k| last + step * k as f64))
            .collect();
        let theory = AdhesiveContact::new(AdhesionModel::new(band, e_star, dg)?);
        per_work.push(compared(&theory, zeta, dg, rho, &gaps, &runs)?);
    }
    Ok(AdhesionComparison {
        adhesion: t.adhesion,
        grids: vec![coarser, finest],
        per_work,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// One seed's path on one grid: the planned `gaps` (warm-started from each
/// other), then further out by `step` while any node still touches or
/// attracts, at most `cap` more.
fn seed_path(
    s: &persson::bem::GridSurface,
    e_star: f64,
    law: &persson::bem::adhesive::CohesiveLaw,
    gaps: &[f64],
    (step, cap): (f64, usize),
    options: &AdhesiveOptions,
) -> Result<SeedPath> {
    let op = Operator::new(Boundary::Periodic, s.n, s.size, e_star)?;
    let mut solver = AdhesiveSolver::new(op)?;
    let (mut p, mut a) = (Vec::new(), Vec::new());
    let mut attached = true;
    let mut g = 0.0;
    for k in 0..gaps.len() + cap {
        if k >= gaps.len() && !attached {
            break;
        }
        g = gaps.get(k).copied().unwrap_or(g + step);
        let point = solver.solve(&s.heights, law, g, options)?;
        attached = point.contact_fraction > 0.0 || point.cohesive_fraction > 0.0;
        p.push(point.mean_pressure);
        a.push(point.contact_fraction);
    }
    let pull = -p.iter().copied().fold(0.0, f64::min) + 0.0;
    Ok((p, a, pull))
}

/// `n` gaps from `hi` down to `lo`, then `2n` back up to `out` (the first
/// of the way out is the next after `lo`).
fn path(hi: f64, lo: f64, out: f64, n: usize) -> Vec<f64> {
    let down = (0..n).map(|k| hi + (lo - hi) * k as f64 / (n - 1) as f64);
    let up = (1..=2 * n).map(|k| lo + (out - lo) * k as f64 / (2 * n) as f64);
    down.chain(up).collect()
}

/// max h and mean h.
fn stats(h: &[f64]) -> (f64, f64) {
    let max = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (max, h.iter().sum::<f64>() / h.len().max(1) as f64)
}

/// X(N)/X(N/2) − 1 (absent when either is 0).
fn change(fine: f64, coarse: f64) -> Option<f64> {
    (fine != 0.0 && coarse != 0.0).then(|| fine / coarse - 1.0)
}

/// The comparison of one Δγ from the seeds' paths on the two grids.
fn compared(
    theory: &AdhesiveContact<'_>,
    zeta: f64,
    dg: f64,
    rho: f64,
    gaps: &[f64],
    runs: &[Vec<SeedPath>; 2],
) -> Result<AdhesionCompared> {
    let [coarse, fine] = runs;
    let pressure =
        |r: &[SeedPath], k: usize| mean_and_error(&r.iter().map(|s| s.0[k]).collect::<Vec<_>>());
    let area = |r: &[SeedPath], k: usize| {
        mean_and_error(&r.iter().map(|s| s.1[k]).collect::<Vec<_>>()).mean
    };
    let points = gaps
        .iter()
        .enumerate()
        .map(|(k, &g)| {
            let p = pressure(fine, k);
            let a = area(fine, k);
            let a_theory = theory.point(p.mean, zeta)?.contact_fraction;
            Ok(AdhesionComparedPoint {
                mean_separation: g,
                nominal_pressure: p.mean,
                nominal_pressure_standard_error: p.standard_error,
                bem_contact_fraction: a,
                bem_resolution_change: change(a, area(coarse, k)),
                theory_contact_fraction: a_theory,
                contact_fraction_ratio: (a > 0.0).then(|| a_theory / a),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let pulls = |r: &[SeedPath]| mean_and_error(&r.iter().map(|s| s.2).collect::<Vec<f64>>());
    let (pull, pull_coarse) = (pulls(fine), pulls(coarse).mean);
    let sigma_p = theory.model().pull_off_stress()?.value;
    Ok(AdhesionCompared {
        work_of_adhesion: dg,
        adhesion_range: rho,
        theory_pull_off_stress: sigma_p,
        bem_pull_off_stress: pull.mean,
        bem_pull_off_stress_standard_error: pull.standard_error,
        bem_pull_off_resolution_change: change(pull.mean, pull_coarse),
        pull_off_ratio: (pull.mean > 0.0).then(|| sigma_p / pull.mean),
        points,
    })
}

impl AdhesionComparison {
    /// One table per Δγ: the path, theory beside BEM, and the pull-offs.
    pub fn tables(&self) -> Vec<Table> {
        let grids = format!("{}², {}²", self.grids[0], self.grids[1]);
        self.per_work
            .iter()
            .enumerate()
            .map(|(i, w)| {
                let mut t = Table::new(
                    format!("adhesion_compare_{i}"),
                    format!(
                        "Adhesive contact, Δγ = {}: Persson's theory against the adhesive BEM \
                         ({}) along a mean-gap path in and out",
                        crate::table::number(w.work_of_adhesion, 4),
                        match self.adhesion {
                            LawKind::Maugis => "Maugis–Dugdale",
                            LawKind::Exponential => "exponential law",
                        }
                    ),
                )
                .scalar("grids", "grids", grids.as_str())
                .scalar("adhesion_range", "ρ (BEM)", w.adhesion_range)
                .scalar(
                    "theory_pull_off_stress",
                    "pull-off σ_p theory",
                    w.theory_pull_off_stress,
                )
                .scalar("bem_pull_off_stress", "pull-off BEM", w.bem_pull_off_stress)
                .scalar("pull_off_ratio", "theory/BEM", Cell::from(w.pull_off_ratio))
                .column("mean_separation", "ḡ")
                .column_digits("nominal_pressure", "σ0 (BEM)", 4)
                .column_digits("bem_contact_fraction", "A/A0 BEM", 4)
                .column_digits("theory_contact_fraction", "A/A0 theory", 4)
                .column_digits("contact_fraction_ratio", "theory/BEM", 3)
                .column_digits("bem_resolution_change", "A(N)/A(N/2)−1", 2)
                .omittable(1);
                for p in &w.points {
                    t.push(vec![
                        Cell::Num(p.mean_separation),
                        Cell::Num(p.nominal_pressure),
                        Cell::Num(p.bem_contact_fraction),
                        Cell::Num(p.theory_contact_fraction),
                        p.contact_fraction_ratio.into(),
                        p.bem_resolution_change.into(),
                    ]);
                }
                t
            })
            .collect()
    }
}

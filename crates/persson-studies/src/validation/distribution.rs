//! The pressure distributions of a comparison: the finest grid's histogram
//! at each pressure against Persson's P(σ) of a flat start at ζ_max, and the
//! user's histogram against the same P(σ).

use super::data::{density_distance, UserHistogram};
use super::report::{DensityCurve, HistogramComparison, PressureDistribution};
use super::sweep::Sweep;
use super::KAPPA_MAX_FRACTION;
use persson::error::{Error, Result};
use persson::stress::StressScene;
use persson::theory::Persson;

/// The theory's P(σ) is drawn up to this multiple of the BEM's largest pressure.
const THEORY_TAIL: f64 = 1.5;

/// Points of the theory's P(σ) curve.
const THEORY_POINTS: usize = 150;

/// Relative tolerance of P(σ) and ū(p) of the theory.
const STRESS_TOLERANCE: f64 = 1e-9;

/// The finest grid's pressure histogram at each pressure against Persson's
/// P(σ) of a flat start at ζ_max (with σY: the finite-σY P(σ) and both
/// δ-peaks at σY).
pub(super) fn pressure_distributions(
    sw: &Sweep,
    model: &Persson,
    bins: usize,
) -> Result<Vec<PressureDistribution>> {
    let zeta = model.zeta_max();
    let yield_stress = sw.yield_stress;
    let finest = sw
        .mean_contact_fraction()
        .pop()
        .ok_or_else(|| Error::invalid("grids", 0.0, "at least one"))?;
    let finest_split = sw
        .mean_plastic_split()
        .pop()
        .ok_or_else(|| Error::invalid("grids", 0.0, "at least one"))?;
    let finest_grid = sw.grids.last().map_or(0, |g| g.grid);
    let mut distributions = Vec::with_capacity(sw.nominal_pressure.len());
    for (k, &p) in sw.nominal_pressure.iter().enumerate() {
        let bins = sw.histograms[k].bins(bins);
        let centres: Vec<f64> = bins.iter().map(|b| b.sigma()).collect();
        let scene = StressScene::flat(p, yield_stress)?;
        let curve = first(scene.curves(model, &[zeta], &centres, STRESS_TOLERANCE)?)?;
        // The theory also beyond the BEM's largest pressure, to show its tail
        // (up to σY with a yield stress: P(σ) = 0 beyond).
        let top = THEORY_TAIL * bins.last().map_or(p, |b| b.sigma_high);
        let top = yield_stress.unwrap_or(top);
        let sigma: Vec<f64> = (1..=THEORY_POINTS)
            .map(|i| top * i as f64 / THEORY_POINTS as f64)
            .collect();
        let tail = first(scene.curves(model, &[zeta], &sigma, STRESS_TOLERANCE)?)?;
        distributions.push(PressureDistribution {
            nominal_pressure: p,
            grid: finest_grid,
            bem: bins,
            bem_contact_fraction: finest.mean[k],
            theory_density: curve.density,
            theory_contact_fraction: curve.contact_fraction,
            g: curve.g.value,
            theory_curve: DensityCurve {
                sigma,
                density: tail.density,
            },
            bem_elastic_fraction: yield_stress.map(|_| finest_split.elastic_fraction[k]),
            bem_plastic_fraction: yield_stress.map(|_| finest_split.plastic_fraction[k]),
            theory_elastic_fraction: yield_stress.map(|_| curve.elastic_fraction),
            theory_plastic_fraction: yield_stress.map(|_| curve.plastic_fraction),
        });
    }
    Ok(distributions)
}

/// The user's histogram against Persson's P(σ) at the pressure `p`.
pub(super) fn user_histogram(
    h: &UserHistogram,
    model: &Persson,
    p: f64,
    yield_stress: Option<f64>,
) -> Result<HistogramComparison> {
    let theory = first(StressScene::flat(p, yield_stress)?.curves(
        model,
        &[model.zeta_max()],
        &h.sigma,
        STRESS_TOLERANCE,
    )?)?;
    let d = density_distance(&h.sigma, &h.density, &theory.density)?;
    Ok(HistogramComparison {
        nominal_pressure: p,
        sigma: h.sigma.clone(),
        density: h.density.clone(),
        theory_density: theory.density,
        relative_l1_distance: d,
    })
}

/// The single curve of a one-ζ stress computation.
fn first<T>(mut v: Vec<T>) -> Result<T> {
    v.pop()
        .ok_or_else(|| Error::invalid("zeta", 0.0, "one stress curve"))
}

/// Index of the pressure nearest `wanted` (log distance), else of the
/// finest-grid A nearest 0.1.
pub(super) fn chosen_histogram(wanted: Option<f64>, pressures: &[f64], finest: &[f64]) -> usize {
    let key = |k: usize| match wanted {
        Some(w) if w > 0.0 => (pressures[k] / w).ln().abs(),
        _ => (finest[k] - KAPPA_MAX_FRACTION).abs(),
    };
    (0..pressures.len())
        .min_by(|&i, &j| key(i).total_cmp(&key(j)))
        .unwrap_or(0)
}

//! [`compare`]: every theory against the FFT-BEM at several resolutions of one
//! physical surface, in one call.

use super::data::{density_distance, interpolate_log, score, UserData, UserHistogram};
use super::kappa::fit_kappa;
use super::report::{
    AreaTheory, BemGrid, ComparedSpectrum, Comparison, ContinuumPoint, DataComparison, DataScore,
    DensityCurve, Fitted, HistogramComparison, KappaFits, MeanSeparation, PressureDistribution,
    TheoryArea, TheoryKappa,
};
use super::sweep::{
    default_pressures, resolution_grids, sweep_source, BandLimited, SweepConfig, SweepProgress,
    SweepSettings, SweepSource,
};
use persson::bem::{Boundary, Surface};
use persson::corrected::{self, Theory};
use persson::error::{check, Error, Result};
use persson::kappa::Kappa;
use persson::separation::Separation;
use persson::spectrum::Spectrum;
use persson::stress::StressScene;
use persson::theory::Persson;

/// Bins of a BEM pressure histogram unless asked otherwise (`persson compare`,
/// `persson bem rough --histogram`, the Python `compare`).
pub const DEFAULT_BINS: usize = 50;

/// Low-load regime of the κ fits: points with A/A0 below this.
pub const KAPPA_MAX_FRACTION: f64 = 0.1;

/// Absolute tolerance on A/A0 of the corrected theories.
const THEORY_TOLERANCE: f64 = 1e-10;

/// The theory's P(σ) is drawn up to this multiple of the BEM's largest pressure.
const THEORY_TAIL: f64 = 1.5;

/// Points of the theory's P(σ) curve.
const THEORY_POINTS: usize = 150;

/// Relative tolerance of P(σ) and ū(p) of the theory.
const STRESS_TOLERANCE: f64 = 1e-9;

/// What [`compare`] compares.
#[derive(Debug, Clone, PartialEq)]
pub struct ComparisonConfig {
    /// Contact modulus E*.
    pub contact_modulus: f64,
    /// Nominal pressures σ0 (empty: the data's pressures, else 8 pressures
    /// with linear-law A/A0 ≈ 0.01 … 0.3).
    pub nominal_pressure: Vec<f64>,
    /// The BEM side.
    pub sweep: SweepSettings,
    /// The user's contact fractions.
    pub data: Option<UserData>,
    /// The user's pressure histogram (at `histogram_pressure`).
    pub data_histogram: Option<UserHistogram>,
    /// Nominal pressure of the shown distribution (nearest computed one;
    /// `None`: the one whose finest-grid A/A0 is nearest 0.1).
    pub histogram_pressure: Option<f64>,
    /// Bins of the BEM pressure histograms.
    pub bins: usize,
    /// Text tables with every column (see [`Comparison::wide`]).
    pub wide: bool,
}

impl ComparisonConfig {
    /// Defaults for modulus `contact_modulus`: default pressures, the
    /// default sweep, no data, [`DEFAULT_BINS`] bins.
    pub fn new(contact_modulus: f64) -> Self {
        ComparisonConfig {
            contact_modulus,
            nominal_pressure: Vec::new(),
            sweep: SweepSettings::default(),
            data: None,
            data_histogram: None,
            histogram_pressure: None,
            bins: DEFAULT_BINS,
            wide: false,
        }
    }
}

/// The theories' A/A0 at `pressures`.
fn theory_curves(model: &Persson, pressures: &[f64]) -> Result<Vec<TheoryArea>> {
    let zeta = model.zeta_max();
    let points = model.load_curve(pressures, zeta)?;
    let curve = |theory, gamma, f: &dyn Fn(&persson::theory::AreaPoint) -> f64, kappa| TheoryArea {
        theory,
        gamma,
        contact_fraction: points.iter().map(f).collect(),
        low_load_kappa: kappa,
    };
    let mut out = vec![
        curve(
            AreaTheory::Original,
            None,
            &|p| p.contact_fraction,
            Kappa::Persson.value(),
        ),
        curve(
            AreaTheory::BushLinear,
            None,
            &|p| p.contact_fraction_bush_linear,
            Kappa::Bush.value(),
        ),
        curve(
            AreaTheory::PerssonLinear,
            None,
            &|p| p.contact_fraction_persson_linear,
            Kappa::Persson.value(),
        ),
    ];
    for t in Theory::all_defaults() {
        if t == Theory::Original {
            continue;
        }
        let c = corrected::load_curve(model, t, zeta, pressures, THEORY_TOLERANCE)?;
        out.push(TheoryArea {
            theory: t.into(),
            gamma: t.gamma(),
            contact_fraction: c.iter().map(|p| p.contact_fraction).collect(),
            low_load_kappa: t.low_load_kappa(),
        });
    }
    Ok(out)
}

/// Compare every theory with the FFT-BEM on one physical surface.
///
/// The spectrum is clipped to what the coarsest grid resolves
/// ([`SweepSettings::band`]); the theories use the clipped spectrum too. The
/// BEM runs on every grid for every seed ([`super::sweep::sweep`]), A(N) is extrapolated
/// to N → ∞ ([`super::continuum_limit`]), κ is fitted to every curve below
/// A/A0 = [`KAPPA_MAX_FRACTION`], the finest grid's pressure histograms are
/// set against Persson's P(σ) from a flat start, the BEM mean gap against
/// ū(σ0), and the user's data are scored against each theory and A∞.
///
/// With a yield stress σY (`config.sweep.options.yield_stress`) the BEM is
/// the saturated solver ([`persson::bem::saturated`]): each grid reports
/// A_el/A0 and A_pl/A0 beside A/A0, both extrapolated with the α of A; the
/// histograms hold the nodes below σY and the δ-peak at σY is the finest
/// grid's A_pl/A0; Persson's P(σ) is the finite-σY series (P(σY) = 0, flat
/// start at σ0, ζ = q_s/q_l) with its A_el/A0 and A_pl/A0
/// ([`persson::stress::StressScene::flat`]).
///
/// # Errors
/// Invalid settings or pressures; σY not finite and positive or not above
/// every nominal pressure (no solution exists); a theory or the BEM failing
/// (NotConverged). A κ that cannot be fitted is reported in the result, not
/// as an error.
pub fn compare(
    spectrum: &dyn Spectrum,
    config: &ComparisonConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Comparison> {
    compare_on(spectrum, None, config, progress)
}

/// Compare every theory, evaluated on a measured map's spectrum, with the
/// FFT-BEM on the map itself (`persson compare --surface`).
///
/// A **periodic** map (`N × N`, side L) is treated as a synthesised surface
/// is in [`compare`]: q_s is clipped to what the coarsest grid `N/2^(levels−1)`
/// resolves ([`SweepSettings::map_band`], `config.sweep.pixels_per_wavelength`),
/// the map is low-passed there ([`super::sweep::band_limited_map`]) and
/// sampled on every grid ([`super::sweep::band_limited_copies`]), so that
/// every grid holds the same continuous surface and A(N) converges to its
/// continuum limit; the theories use `spectrum` clipped at the same q_s. The
/// unfiltered map is solved too, on its own grid, and reported as
/// [`Comparison::measured`] ("the map as measured").
///
/// A map with a **free** boundary cannot be low-passed without ringing at its
/// edges: the BEM runs on the map and on its block-averaged copies
/// ([`super::sweep::coarsened`]), each a smoother surface, and the theories
/// use `spectrum` over its whole band; the extrapolation is then a trend, not
/// a continuum limit.
///
/// The map is one realisation: only the first seed is used and the seed
/// scatter is absent. `config.sweep.grid` is ignored.
///
/// # Errors
/// As [`compare`]; `N` not divisible by `2^(levels−1)` or a coarsest grid
/// below [`persson::bem::MIN_GRID`]; `pixels_per_wavelength` ≤ 2 on a periodic map.
pub fn compare_surface(
    spectrum: &dyn Spectrum,
    map: &Surface,
    boundary: Boundary,
    config: &ComparisonConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Comparison> {
    compare_on(spectrum, Some((map, boundary)), config, progress)
}

fn compare_on(
    spectrum: &dyn Spectrum,
    map: Option<(&Surface, Boundary)>,
    config: &ComparisonConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Comparison> {
    let e_star = check::positive("contact_modulus", config.contact_modulus)?;
    let q_l = spectrum.q_min();
    let mut sweep_config = config.sweep.config(q_l)?;
    let q_s = match map {
        None => config.sweep.band(q_l, Some(spectrum.q_max()))?.q_s,
        Some((m, b)) => {
            sweep_config.grids = resolution_grids(m.n, config.sweep.levels)?;
            sweep_config.size = m.size;
            sweep_config.seeds.truncate(1);
            match b {
                Boundary::Periodic => config.sweep.map_band(q_l, spectrum.q_max(), m.n)?.q_s,
                Boundary::Free => spectrum.q_max(),
            }
        }
    };
    let band = BandLimited::new(spectrum, q_s)?;
    let rms_slope = band.rms_slope(q_l, band.q_max())?.value;
    let rms_height = band.rms_height(q_l, band.q_max())?.value;
    let pressures = if !config.nominal_pressure.is_empty() {
        config.nominal_pressure.clone()
    } else if let Some(d) = &config.data {
        d.nominal_pressure.clone()
    } else {
        default_pressures(e_star, rms_slope, 8, 0.01, 0.3)
    };
    for &p in &pressures {
        check::positive("nominal_pressure", p)?;
    }
    let yield_stress = config.sweep.options.yield_stress;
    super::plastic::check_yield_stress(yield_stress, &pressures)?;
    let model = Persson::new(&band, e_star)?;
    let zeta = model.zeta_max();
    let theories = theory_curves(&model, &pressures)?;

    // The BEM sweep and its continuum limit.
    let source = match map {
        None => SweepSource::Synthesised(&band),
        Some((m, Boundary::Periodic)) => SweepSource::BandLimitedMap(m, q_s),
        Some((m, b)) => SweepSource::Map(m, b),
    };
    let sw = sweep_source(source, e_star, &pressures, &sweep_config, progress)?;
    // The periodic map as measured (unfiltered), on its own grid.
    let measured = match map {
        Some((m, Boundary::Periodic)) => {
            let own = SweepConfig {
                grids: vec![m.n],
                ..sweep_config.clone()
            };
            let s = sweep_source(
                SweepSource::Map(m, Boundary::Periodic),
                e_star,
                &pressures,
                &own,
                progress,
            )?;
            s.grids.first().map(|g| BemGrid {
                grid: g.grid,
                contact_fraction: g.contact_fraction[0].clone(),
                seed_scatter: vec![None; pressures.len()],
                mean_separation: g.mean_separation[0].clone(),
                surface_rms_slope: g.surface_rms_slope.clone(),
                elastic_fraction: yield_stress.map(|_| g.elastic_fraction[0].clone()),
                plastic_fraction: yield_stress.map(|_| g.plastic_fraction[0].clone()),
                plastic_displacement_mean: yield_stress
                    .map(|_| g.plastic_displacement_mean[0].clone()),
                iterations: g.iterations,
                residual: g.residual,
                seconds: g.seconds,
            })
        }
        _ => None,
    };
    let means = sw.mean_contact_fraction();
    let gaps = sw.mean_separation();
    let cont = sw.extrapolate(config.sweep.alpha)?;
    let a_inf: Vec<f64> = cont.iter().map(|c| c.fit.value).collect();
    let finest = means
        .last()
        .ok_or_else(|| Error::invalid("grids", 0.0, "at least one"))?;
    let finest_grid = sweep_config.grids.last().copied().unwrap_or(0);

    // κ: theories (fitted on the same pressures, and closed), BEM grids, extrapolated.
    let fit = |a: &[f64]| fit_kappa(&pressures, a, e_star, rms_slope, KAPPA_MAX_FRACTION);
    let theory_kappa = theories
        .iter()
        .map(|c| TheoryKappa {
            theory: c.theory,
            fit: Fitted::from_result(fit(&c.contact_fraction)),
            low_load_kappa: c.low_load_kappa,
        })
        .collect();
    let bem_kappa =
        Fitted::from_result(sw.kappa(e_star, rms_slope, KAPPA_MAX_FRACTION, config.sweep.alpha));

    // Pressure distributions: finest-grid histogram against flat-start P(σ) at ζ_max.
    let split = sw.mean_plastic_split();
    let finest_split = split
        .last()
        .ok_or_else(|| Error::invalid("grids", 0.0, "at least one"))?;
    let mut distributions = Vec::with_capacity(pressures.len());
    for (k, &p) in pressures.iter().enumerate() {
        let bins = sw.histograms[k].bins(config.bins);
        let centres: Vec<f64> = bins.iter().map(|b| b.sigma()).collect();
        let scene = StressScene::flat(p, yield_stress)?;
        let curve = first(scene.curves(&model, &[zeta], &centres, STRESS_TOLERANCE)?)?;
        // The theory also beyond the BEM's largest pressure, to show its tail
        // (up to σY with a yield stress: P(σ) = 0 beyond).
        let top = THEORY_TAIL * bins.last().map_or(p, |b| b.sigma_high);
        let top = yield_stress.unwrap_or(top);
        let sigma: Vec<f64> = (1..=THEORY_POINTS)
            .map(|i| top * i as f64 / THEORY_POINTS as f64)
            .collect();
        let tail = first(scene.curves(&model, &[zeta], &sigma, STRESS_TOLERANCE)?)?;
        distributions.push(PressureDistribution {
            nominal_pressure: p,
            grid: finest_grid,
            bem: bins,
            bem_contact_fraction: finest.0[k],
            theory_density: curve.density,
            theory_contact_fraction: curve.contact_fraction,
            g: curve.g.value,
            theory_curve: DensityCurve {
                sigma,
                density: tail.density,
            },
            bem_elastic_fraction: yield_stress.map(|_| finest_split.0[k]),
            bem_plastic_fraction: yield_stress.map(|_| finest_split.1[k]),
            theory_elastic_fraction: yield_stress.map(|_| curve.elastic_fraction),
            theory_plastic_fraction: yield_stress.map(|_| curve.plastic_fraction),
        });
    }
    let histogram_index = chosen_histogram(config.histogram_pressure, &pressures, &finest.0);

    // The user's histogram against P(σ) at the histogram pressure.
    let data_histogram = match &config.data_histogram {
        Some(h) => {
            let p = pressures[histogram_index];
            let theory = first(StressScene::flat(p, yield_stress)?.curves(
                &model,
                &[zeta],
                &h.sigma,
                STRESS_TOLERANCE,
            )?)?;
            let d = density_distance(&h.sigma, &h.density, &theory.density)?;
            Some(HistogramComparison {
                nominal_pressure: p,
                sigma: h.sigma.clone(),
                density: h.density.clone(),
                theory_density: theory.density,
                relative_l1_distance: d,
            })
        }
        None => None,
    };

    // Mean separation: BEM mean gap against ū(σ0).
    let sep = Separation::new(&band, e_star)?;
    let u_theory: Vec<f64> = pressures
        .iter()
        .map(|&p| sep.mean_separation(p).map(|u| u.value))
        .collect::<Result<_>>()?;
    let u_bem = gaps.last().map(|g| g.0.clone()).unwrap_or_default();

    // The user's results, scored against each theory and the extrapolated BEM.
    let mut data_kappa = None;
    let data = match &config.data {
        Some(d) => {
            let curves = theory_curves(&model, &d.nominal_pressure)?;
            let mut scores: Vec<DataScore> = curves
                .iter()
                .map(|c| DataScore {
                    reference: c.theory.name().into(),
                    score: score(&d.contact_fraction, &c.contact_fraction),
                })
                .collect();
            let bem_at: Vec<Option<f64>> = d
                .nominal_pressure
                .iter()
                .map(|&p| interpolate_log(&pressures, &a_inf, p))
                .collect();
            let (uv, rv): (Vec<f64>, Vec<f64>) = d
                .contact_fraction
                .iter()
                .zip(&bem_at)
                .filter_map(|(&u, r)| r.map(|r| (u, r)))
                .unzip();
            if !rv.is_empty() {
                scores.push(DataScore {
                    reference: "bem-extrapolated".into(),
                    score: score(&uv, &rv),
                });
            }
            data_kappa = Some(Fitted::from_result(fit_kappa(
                &d.nominal_pressure,
                &d.contact_fraction,
                e_star,
                rms_slope,
                KAPPA_MAX_FRACTION,
            )));
            Some(DataComparison {
                nominal_pressure: d.nominal_pressure.clone(),
                contact_fraction: d.contact_fraction.clone(),
                theories: curves,
                bem_extrapolated: bem_at,
                scores,
            })
        }
        None => None,
    };

    let displacement = sw.mean_plastic_displacement();
    let bem = sw
        .grids
        .iter()
        .zip(means.iter().zip(&gaps))
        .zip(split.iter().zip(displacement))
        .map(|((g, (m, u)), (s, d))| BemGrid {
            grid: g.grid,
            contact_fraction: m.0.clone(),
            seed_scatter: m.1.clone(),
            mean_separation: u.0.clone(),
            surface_rms_slope: g.surface_rms_slope.clone(),
            elastic_fraction: yield_stress.map(|_| s.0.clone()),
            plastic_fraction: yield_stress.map(|_| s.1.clone()),
            plastic_displacement_mean: yield_stress.map(|_| d),
            iterations: g.iterations,
            residual: g.residual,
            seconds: g.seconds,
        })
        .collect();
    let split_limit = match yield_stress {
        Some(_) => sw
            .extrapolate_plastic_split(&cont)?
            .into_iter()
            .map(Some)
            .collect(),
        None => vec![None; cont.len()],
    };
    let extrapolated = cont
        .iter()
        .zip(&pressures)
        .zip(&split_limit)
        .map(|((c, &p), s)| ContinuumPoint {
            nominal_pressure: p,
            contact_fraction: c.fit.value,
            standard_error: c.standard_error,
            fit_standard_error: c.fit.standard_error,
            extrapolation_step: c.fit.extrapolation_step,
            seed_scatter: c.seed_scatter,
            alpha: c.fit.alpha,
            coefficient: c.fit.coefficient,
            elastic_fraction: s.map(|s| s.0.fit.value),
            elastic_fraction_standard_error: s.map(|s| s.0.standard_error),
            plastic_fraction: s.map(|s| s.1.fit.value),
            plastic_fraction_standard_error: s.map(|s| s.1.standard_error),
        })
        .collect();
    Ok(Comparison {
        contact_modulus: e_star,
        spectrum: ComparedSpectrum {
            q_l,
            q_s: band.q_max(),
            q_s_requested: spectrum.q_max(),
            clipped: band.clipped(),
            rms_height,
            rms_slope,
            zeta,
        },
        size: sweep_config.size,
        grids: sweep_config.grids.clone(),
        seeds: sweep_config.seeds.clone(),
        tolerance: sweep_config.options.tolerance,
        yield_stress,
        nominal_pressure: pressures,
        theories,
        bem,
        extrapolated,
        kappa: KappaFits {
            max_fraction: KAPPA_MAX_FRACTION,
            theories: theory_kappa,
            bem: bem_kappa,
            data: data_kappa,
        },
        pressure_distribution: distributions,
        histogram_index,
        mean_separation: MeanSeparation {
            bem: u_bem,
            theory: u_theory,
        },
        data,
        data_histogram,
        measured,
        wide: config.wide,
    })
}

/// The single curve of a one-ζ stress computation.
fn first<T>(mut v: Vec<T>) -> Result<T> {
    v.pop()
        .ok_or_else(|| Error::invalid("zeta", 0.0, "one stress curve"))
}

/// Index of the pressure nearest `wanted` (log distance), else of the
/// finest-grid A nearest 0.1.
fn chosen_histogram(wanted: Option<f64>, pressures: &[f64], finest: &[f64]) -> usize {
    let key = |k: usize| match wanted {
        Some(w) if w > 0.0 => (pressures[k] / w).ln().abs(),
        _ => (finest[k] - KAPPA_MAX_FRACTION).abs(),
    };
    (0..pressures.len())
        .min_by(|&i, &j| key(i).total_cmp(&key(j)))
        .unwrap_or(0)
}

//! [`compare`]: every theory against the FFT-BEM at several resolutions of one
//! physical surface, in one call.

use super::asperity::asperity_comparison;
use super::data::{interpolate_log, score, UserData, UserHistogram};
use super::distribution::{chosen_histogram, pressure_distributions, user_histogram};
use super::kappa::fit_kappa;
use super::limits::{Continuum, ContinuumSplit, PlasticSplit, SeedMean};
use super::patches::PatchCollector;
use super::report::{
    AreaTheory, BemGrid, ComparedSpectrum, Comparison, ContinuumPoint, DataComparison, DataScore,
    Fitted, KappaFits, MeanSeparation, ScoreReference, TheoryArea, TheoryKappa,
};
use super::resolution::{default_pressures, resolution_grids, SweepConfig, SweepSettings};
use super::sweep::{
    sweep_source, sweep_source_observed, GridResult, Sweep, SweepProgress, SweepSource,
};
use crate::warning::{fallen_back, Warning};
use persson::bem::{Boundary, GridSurface, Method};
use persson::corrected::{self, Theory};
use persson::error::{check, Result};
use persson::kappa::Kappa;
use persson::separation::Separation;
use persson::spectrum::{BandLimited, Spectrum};
use persson::theory::Persson;

/// Bins of a BEM pressure histogram unless asked otherwise (`persson compare`,
/// `persson bem rough --histogram`, the Python `compare`).
pub const DEFAULT_BINS: usize = 50;

/// The bins of a BEM pressure histogram: at least 1 (the one check of the
/// command line, the scene and Python, whether or not a histogram is drawn).
///
/// # Errors
/// [`persson::Error::InvalidParameter`] naming `bins`.
pub fn check_bins(bins: usize) -> persson::Result<usize> {
    match bins {
        0 => Err(persson::Error::invalid("bins", 0.0, ">= 1")),
        n => Ok(n),
    }
}

/// Low-load regime of the κ fits: points with A/A0 below this.
pub const KAPPA_MAX_FRACTION: f64 = 0.1;

/// Absolute tolerance on A/A0 of the corrected theories.
const THEORY_TOLERANCE: f64 = 1e-10;

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
    /// The BEM solver's method (default: preconditioned; a stall falls back
    /// to the plain loop with the warning `preconditioner_fallback` in
    /// [`Comparison::warnings`]).
    pub method: Method,
    /// `compare --leakage / --conductance`: the leak rate and conductance
    /// of the theories against the BEM's (`None`: not compared).
    pub transport: Option<super::compare_transport::TransportCompareConfig>,
    /// `compare --work-of-adhesion`: Persson's adhesive theory against the
    /// adhesive BEM (`None`: not compared).
    pub adhesion: Option<super::compare_adhesion::AdhesionCompareConfig>,
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
            method: Method::default(),
            transport: None,
            adhesion: None,
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
/// the map is low-passed there ([`persson::bem::resample::band_limited_map`]) and
/// sampled on every grid ([`persson::bem::resample::band_limited_copies`]), so that
/// every grid holds the same continuous surface and A(N) converges to its
/// continuum limit; the theories use `spectrum` clipped at the same q_s. The
/// unfiltered map is solved too, on its own grid, and reported as
/// [`Comparison::measured`] ("the map as measured").
///
/// A map with a **free** boundary cannot be low-passed without ringing at its
/// edges: the BEM runs on the map and on its block-averaged copies
/// ([`persson::bem::resample::coarsened`]), each a smoother surface, and the theories
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
    map: &GridSurface,
    boundary: Boundary,
    config: &ComparisonConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Comparison> {
    compare_on(spectrum, Some((map, boundary)), config, progress)
}

/// The BEM side of a comparison on `map` (or a synthesised surface): the
/// sweep's grids, size and seeds, and the q_s of both sides; with the
/// warning that q_s was clipped to what the coarsest grid resolves, or (a
/// free map) that the map is not periodic.
fn sweep_setup(
    spectrum: &dyn Spectrum,
    map: Option<(&GridSurface, Boundary)>,
    config: &ComparisonConfig,
) -> Result<(SweepConfig, f64, Option<Warning>)> {
    let q_l = spectrum.q_min();
    let mut sweep_config = config.sweep.config(q_l)?;
    sweep_config.method = config.method;
    let band = match map {
        None => config.sweep.band(q_l, Some(spectrum.q_max()))?,
        Some((m, b)) => {
            sweep_config.grids = resolution_grids(m.n, config.sweep.levels)?;
            sweep_config.size = m.size;
            sweep_config.seeds.truncate(1);
            match b {
                Boundary::Periodic => config.sweep.map_band(q_l, spectrum.q_max(), m.n)?,
                Boundary::Free => {
                    let q_s = spectrum.q_max();
                    return Ok((sweep_config, q_s, Some(Warning::MapNotPeriodic)));
                }
            }
        }
    };
    let clipped = match (band.clipped, band.q_s_requested) {
        (true, Some(q)) => Some(Warning::ClippedBand {
            q_s_requested: q,
            q_s: band.q_s,
            q_l,
            grid: sweep_config.grids.first().copied().unwrap_or_default(),
            pixels_per_wavelength: config.sweep.pixels_per_wavelength,
        }),
        _ => None,
    };
    Ok((sweep_config, band.q_s, clipped))
}

/// The compared pressures: the given ones, else the data's, else eight
/// whose linear-law A/A0 runs from 0.01 to 0.3; each finite and positive.
fn compared_pressures(config: &ComparisonConfig, rms_slope: f64) -> Result<Vec<f64>> {
    let pressures = if !config.nominal_pressure.is_empty() {
        config.nominal_pressure.clone()
    } else if let Some(d) = &config.data {
        d.nominal_pressure.clone()
    } else {
        default_pressures(config.contact_modulus, rms_slope, 8, 0.01, 0.3)
    };
    for &p in &pressures {
        check::positive("nominal_pressure", p)?;
    }
    Ok(pressures)
}

/// The BEM on one grid, seed-averaged (one seed: `seed_scatter` all `None`).
fn bem_grid(
    g: &GridResult,
    mean: &SeedMean,
    gap: &SeedMean,
    split: &PlasticSplit,
    displacement: Vec<f64>,
    yield_stress: Option<f64>,
) -> BemGrid {
    BemGrid {
        grid: g.grid,
        contact_fraction: mean.mean.clone(),
        seed_scatter: mean.standard_error.clone(),
        mean_separation: gap.mean.clone(),
        surface_rms_slope: g.surface_rms_slope.clone(),
        elastic_fraction: yield_stress.map(|_| split.elastic_fraction.clone()),
        plastic_fraction: yield_stress.map(|_| split.plastic_fraction.clone()),
        plastic_displacement_mean: yield_stress.map(|_| displacement),
        iterations: g.iterations,
        residual: g.residual,
        seconds: g.seconds,
    }
}

/// σ0 and preconditioned iterations of the solves that fell back ([`GridResult::fallbacks`]).
type Fallbacks = Vec<(f64, usize)>;

/// A periodic map as measured (unfiltered), solved on its own grid; with the
/// solves that fell back to the plain loop ([`GridResult::fallbacks`]).
fn measured_map(
    m: &GridSurface,
    e_star: f64,
    pressures: &[f64],
    sweep_config: &SweepConfig,
    yield_stress: Option<f64>,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<(Option<BemGrid>, Fallbacks)> {
    let own = SweepConfig {
        grids: vec![m.n],
        ..sweep_config.clone()
    };
    let s = sweep_source(
        SweepSource::Map(m, Boundary::Periodic),
        e_star,
        pressures,
        &own,
        progress,
    )?;
    let (means, gaps, split) = (
        s.mean_contact_fraction(),
        s.mean_separation(),
        s.mean_plastic_split(),
    );
    let (Some(g), Some(mean), Some(gap), Some(split), Some(d)) = (
        s.grids.first(),
        means.first(),
        gaps.first(),
        split.first(),
        s.mean_plastic_displacement().pop(),
    ) else {
        return Ok((None, Vec::new()));
    };
    Ok((
        Some(bem_grid(g, mean, gap, split, d, yield_stress)),
        g.fallbacks.clone(),
    ))
}

/// Every grid of the sweep, seed-averaged.
fn bem_grids(sw: &Sweep) -> Vec<BemGrid> {
    let (means, gaps) = (sw.mean_contact_fraction(), sw.mean_separation());
    let (split, displacement) = (sw.mean_plastic_split(), sw.mean_plastic_displacement());
    sw.grids
        .iter()
        .zip(means.iter().zip(&gaps))
        .zip(split.iter().zip(displacement))
        .map(|((g, (m, u)), (s, d))| bem_grid(g, m, u, s, d, sw.yield_stress))
        .collect()
}

/// The continuum limit at each pressure, with (σY) the limits of A_el and A_pl.
fn extrapolated_points(sw: &Sweep, cont: &[Continuum]) -> Result<Vec<ContinuumPoint>> {
    let split: Vec<Option<ContinuumSplit>> = match sw.yield_stress {
        Some(_) => sw
            .extrapolate_plastic_split(cont)?
            .into_iter()
            .map(Some)
            .collect(),
        None => vec![None; cont.len()],
    };
    Ok(cont
        .iter()
        .zip(&sw.nominal_pressure)
        .zip(&split)
        .map(|((c, &p), s)| ContinuumPoint {
            nominal_pressure: p,
            contact_fraction: c.fit.value,
            standard_error: c.standard_error,
            fit_standard_error: c.fit.standard_error,
            extrapolation_step: c.fit.extrapolation_step,
            seed_scatter: c.seed_scatter,
            alpha: c.fit.alpha,
            coefficient: c.fit.coefficient,
            elastic_fraction: s.map(|s| s.elastic_fraction.fit.value),
            elastic_fraction_standard_error: s.map(|s| s.elastic_fraction.standard_error),
            plastic_fraction: s.map(|s| s.plastic_fraction.fit.value),
            plastic_fraction_standard_error: s.map(|s| s.plastic_fraction.standard_error),
        })
        .collect())
}

/// The user's contact fractions scored against each theory and against the
/// BEM's continuum limit `a_inf` at `pressures` (where inside their range).
fn user_data(
    d: &UserData,
    model: &Persson,
    pressures: &[f64],
    a_inf: &[f64],
) -> Result<DataComparison> {
    let curves = theory_curves(model, &d.nominal_pressure)?;
    let mut scores: Vec<DataScore> = curves
        .iter()
        .map(|c| DataScore {
            reference: ScoreReference::Theory(c.theory),
            score: score(&d.contact_fraction, &c.contact_fraction),
        })
        .collect();
    let bem_at: Vec<Option<f64>> = d
        .nominal_pressure
        .iter()
        .map(|&p| interpolate_log(pressures, a_inf, p))
        .collect();
    let (uv, rv): (Vec<f64>, Vec<f64>) = d
        .contact_fraction
        .iter()
        .zip(&bem_at)
        .filter_map(|(&u, r)| r.map(|r| (u, r)))
        .unzip();
    if !rv.is_empty() {
        scores.push(DataScore {
            reference: ScoreReference::BemExtrapolated,
            score: score(&uv, &rv),
        });
    }
    Ok(DataComparison {
        nominal_pressure: d.nominal_pressure.clone(),
        contact_fraction: d.contact_fraction.clone(),
        theories: curves,
        bem_extrapolated: bem_at,
        scores,
    })
}

/// κ fitted to every theory's curve, to the BEM per grid and extrapolated,
/// and to the user's data.
fn kappa_fits(
    theories: &[TheoryArea],
    sw: &Sweep,
    data: Option<&UserData>,
    (e_star, rms_slope): (f64, f64),
    alpha: Option<f64>,
) -> KappaFits {
    let max = KAPPA_MAX_FRACTION;
    let p = &sw.nominal_pressure;
    let fitted = |pressures: &[f64], a: &[f64]| {
        Fitted::from_result(fit_kappa(pressures, a, e_star, rms_slope, max), max)
    };
    KappaFits {
        max_fraction: max,
        theories: theories
            .iter()
            .map(|c| TheoryKappa {
                theory: c.theory,
                fit: fitted(p, &c.contact_fraction),
                low_load_kappa: c.low_load_kappa,
            })
            .collect(),
        bem: Fitted::from_result(sw.kappa(e_star, rms_slope, max, alpha), max),
        data: data.map(|d| fitted(&d.nominal_pressure, &d.contact_fraction)),
    }
}

fn compare_on(
    spectrum: &dyn Spectrum,
    map: Option<(&GridSurface, Boundary)>,
    config: &ComparisonConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<Comparison> {
    let e_star = check_settings(config)?;
    let (sweep_config, q_s, setup_warning) = sweep_setup(spectrum, map, config)?;
    let band = BandLimited::new(spectrum, q_s)?;
    let compared = compared_spectrum(spectrum, &band, e_star)?;
    let rms_slope = compared.rms_slope;
    let pressures = compared_pressures(config, rms_slope)?;
    let yield_stress = config.sweep.options.yield_stress;
    check_before_sweep(config, map.map(|m| m.1), &pressures)?;
    let model = Persson::new(&band, e_star)?;
    let theories = theory_curves(&model, &pressures)?;

    // An anisotropic spectrum's Peklenik number and its surfaces' (cheap; before the BEM).
    let anisotropy = match map {
        None => synthesised_anisotropy(&band, &sweep_config)?,
        Some(_) => None,
    };

    // The BEM sweep, its continuum limit and the periodic map as measured.
    let (sw, patches, few_patches) =
        patched_sweep(&band, (map, q_s), e_star, &pressures, &sweep_config, progress)?;
    let (measured, measured_fallbacks) = match map {
        Some((m, Boundary::Periodic)) => {
            measured_map(m, e_star, &pressures, &sweep_config, yield_stress, progress)?
        }
        _ => (None, Vec::new()),
    };
    let fallbacks = sw
        .grids
        .iter()
        .flat_map(|g| g.fallbacks.iter().copied())
        .chain(measured_fallbacks);
    let cont = sw.extrapolate(config.sweep.alpha)?;
    let a_inf: Vec<f64> = cont.iter().map(|c| c.fit.value).collect();
    let asperity = asperity_comparison(&band, e_star, yield_stress, &pressures, &a_inf);

    // One list for every front end (CLI stderr/JSON, Python): the study's own
    // remarks, then the asperity theories' (their assumptions failing).
    let mut warnings: Vec<Warning> = setup_warning
        .into_iter()
        .chain(fallen_back(fallbacks))
        .chain(asperity.warnings.iter().cloned())
        .chain(few_patches)
        .collect();
    let transport = config
        .transport
        .as_ref()
        .map(|t| transport_comparison(&band, map, q_s, e_star, &pressures, &sweep_config, config, t))
        .transpose()?
        .map(|(report, w)| {
            warnings.extend(w);
            report
        });
    let adhesion = match &config.adhesion {
        Some(a) => Some(adhesion_comparison(
            &band,
            (map, q_s),
            (e_star, rms_slope),
            &pressures,
            &sweep_config,
            a,
        )?),
        None => None,
    };

    let distributions = pressure_distributions(&sw, &model, config.bins)?;
    let finest = sw.mean_contact_fraction().pop().map(|m| m.mean);
    let histogram_index =
        chosen_histogram(config.histogram_pressure, &pressures, &finest.unwrap_or_default());
    let data_histogram = config
        .data_histogram
        .as_ref()
        .map(|h| user_histogram(h, &model, pressures[histogram_index], yield_stress))
        .transpose()?;
    let data = config
        .data
        .as_ref()
        .map(|d| user_data(d, &model, &pressures, &a_inf))
        .transpose()?;
    let kappa = kappa_fits(
        &theories,
        &sw,
        config.data.as_ref(),
        (e_star, rms_slope),
        config.sweep.alpha,
    );
    let mean_separation = mean_separations(&band, e_star, &pressures, &sw)?;
    Ok(Comparison {
        contact_modulus: e_star,
        spectrum: compared,
        size: sweep_config.size,
        grids: sweep_config.grids.clone(),
        seeds: sweep_config.seeds.clone(),
        tolerance: sweep_config.options.tolerance,
        yield_stress,
        nominal_pressure: pressures,
        theories,
        asperity,
        patches,
        anisotropy,
        bem: bem_grids(&sw),
        extrapolated: extrapolated_points(&sw, &cont)?,
        kappa,
        pressure_distribution: distributions,
        histogram_index,
        mean_separation,
        data,
        data_histogram,
        measured,
        transport,
        adhesion,
        warnings,
    })
}

/// The Peklenik number of a synthesised anisotropic spectrum and of its
/// surfaces on the finest grid.
fn synthesised_anisotropy(
    band: &BandLimited<'_>,
    sweep_config: &SweepConfig,
) -> Result<Option<super::anisotropic::ComparedAnisotropy>> {
    super::anisotropic::compared_anisotropy(
        band,
        sweep_config.grids.last().copied().unwrap_or_default(),
        sweep_config.size,
        &sweep_config.seeds,
    )
}

/// The settings checked before anything is computed; E*.
fn check_settings(config: &ComparisonConfig) -> Result<f64> {
    let e_star = check::positive("contact_modulus", config.contact_modulus)?;
    if let Some(p) = config.histogram_pressure {
        check::positive("histogram_pressure", p)?;
    }
    check_bins(config.bins)?;
    Ok(e_star)
}

/// The compared spectrum: its band as the BEM resolves it, rms height and
/// slope over it, and the magnification of the theories.
fn compared_spectrum(
    spectrum: &dyn Spectrum,
    band: &BandLimited<'_>,
    e_star: f64,
) -> Result<ComparedSpectrum> {
    let (q_l, q_max) = (spectrum.q_min(), band.q_max());
    Ok(ComparedSpectrum {
        q_l,
        q_s: q_max,
        q_s_requested: spectrum.q_max(),
        clipped: band.clipped(),
        rms_height: band.rms_height(q_l, q_max)?.value,
        rms_slope: band.rms_slope(q_l, q_max)?.value,
        zeta: Persson::new(band, e_star)?.zeta_max(),
    })
}

/// Every setting that would fail after the sweep, checked before it: the
/// yield stress against the pressures, the transport and adhesion settings.
fn check_before_sweep(
    config: &ComparisonConfig,
    boundary: Option<Boundary>,
    pressures: &[f64],
) -> Result<()> {
    let yield_stress = config.sweep.options.yield_stress;
    if let Some(y) = yield_stress {
        check::yield_stress("yield_stress", y, pressures)?;
    }
    if let Some(t) = &config.transport {
        t.validate(boundary, yield_stress)?;
    }
    if let Some(a) = &config.adhesion {
        a.validate(boundary, yield_stress)?;
    }
    Ok(())
}

/// The BEM sweep on the compared surfaces (synthesised, a periodic map's
/// band-limited copies, or a map as given), with the patches of every solve
/// as it arrives (module `patches`).
fn patched_sweep(
    band: &BandLimited<'_>,
    (map, q_s): (Option<(&GridSurface, Boundary)>, f64),
    e_star: f64,
    pressures: &[f64],
    sweep_config: &SweepConfig,
    progress: &mut dyn FnMut(SweepProgress),
) -> Result<(Sweep, super::patches::PatchComparison, Option<Warning>)> {
    let source = match map {
        None => SweepSource::Synthesised(band),
        Some((m, Boundary::Periodic)) => SweepSource::BandLimitedMap(m, q_s),
        Some((m, b)) => SweepSource::Map(m, b),
    };
    let boundary = map.map_or(Boundary::Periodic, |(_, b)| b);
    let mut collector = PatchCollector::new(
        &sweep_config.grids,
        sweep_config.seeds.len(),
        pressures.len(),
        sweep_config.size,
        boundary,
    );
    let sw = sweep_source_observed(
        source,
        e_star,
        pressures,
        sweep_config,
        progress,
        Some(&mut |g, s, k, solution| collector.add(g, s, k, solution)),
    )?;
    let (patches, few_patches) = collector.finish(pressures);
    Ok((sw, patches, few_patches))
}

/// `compare --work-of-adhesion`: the adhesive BEM on the sweep's surfaces.
fn adhesion_comparison(
    band: &BandLimited<'_>,
    (map, q_s): (Option<(&GridSurface, Boundary)>, f64),
    (e_star, rms_slope): (f64, f64),
    pressures: &[f64],
    sweep_config: &SweepConfig,
    a: &super::compare_adhesion::AdhesionCompareConfig,
) -> Result<super::compare_adhesion::AdhesionComparison> {
    use super::compare_transport::Surfaces;
    let surfaces = match map {
        Some((m, Boundary::Periodic)) => Surfaces::BandLimitedMap(m, q_s),
        _ => Surfaces::Synthesised(band),
    };
    let max_pressure = pressures.iter().copied().fold(0.0, f64::max);
    super::compare_adhesion::compare_adhesion(
        band,
        surfaces,
        (e_star, rms_slope),
        max_pressure,
        sweep_config,
        a,
    )
}

/// The mean separation: the finest grid's mean gap against ū(σ0).
fn mean_separations(
    band: &BandLimited<'_>,
    e_star: f64,
    pressures: &[f64],
    sw: &Sweep,
) -> Result<MeanSeparation> {
    let sep = Separation::new(band, e_star)?;
    let theory: Vec<f64> = pressures
        .iter()
        .map(|&p| sep.mean_separation(p).map(|u| u.value))
        .collect::<Result<_>>()?;
    let bem = sw
        .mean_separation()
        .pop()
        .map(|g| g.mean)
        .unwrap_or_default();
    Ok(MeanSeparation { bem, theory })
}

/// `compare --leakage / --conductance` on the sweep's surfaces: synthesised
/// ones, or a periodic map's band-limited copies (a free map and σY are
/// refused by [`super::compare_transport::TransportCompareConfig::validate`]).
#[allow(clippy::too_many_arguments)]
fn transport_comparison(
    band: &BandLimited<'_>,
    map: Option<(&GridSurface, Boundary)>,
    q_s: f64,
    e_star: f64,
    pressures: &[f64],
    sweep_config: &SweepConfig,
    config: &ComparisonConfig,
    t: &super::compare_transport::TransportCompareConfig,
) -> Result<(super::compare_transport::TransportComparison, Vec<Warning>)> {
    use super::compare_transport::{compare_transport, Surfaces};
    let surfaces = match map {
        Some((m, Boundary::Periodic)) => Surfaces::BandLimitedMap(m, q_s),
        _ => Surfaces::Synthesised(band),
    };
    compare_transport(
        band,
        surfaces,
        e_star,
        pressures,
        sweep_config,
        config.sweep.alpha,
        t,
    )
}

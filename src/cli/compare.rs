//! `persson compare`: every theory against the FFT-BEM at several resolutions
//! of one physical surface, its continuum limit, κ, pressure distributions,
//! mean separation, and the user's own results; `persson compare kappa`: κ(H)
//! averaged over seeds.

use std::path::PathBuf;

use anyhow::Context;
use persson::compare::{fit_kappa, score, UserData, UserHistogram, DEFAULT_ALPHA};
use persson::compare_bem::{
    default_pressures, interpolate_log, resolution_grids, resolvable_q_max, sweep, BandLimited,
    Sweep, SweepConfig, SweepProgress, DEFAULT_LEVELS, DEFAULT_PIXELS_PER_WAVELENGTH,
};
use persson::corrected::{self, Theory};
use persson::error::check;
use persson::kappa::Kappa;
use persson::separation::Separation;
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::stress::StressScene;
use persson::theory::Persson;
use serde_json::{json, Value};

use super::args::{MaterialArgs, SpectrumArgs};
use super::output::{Format, Report};

/// Low-load regime of the κ fits: points with A/A0 below this.
const KAPPA_MAX_FRACTION: f64 = 0.1;

/// Absolute tolerance on A/A0 of the corrected theories.
const THEORY_TOLERANCE: f64 = 1e-10;

/// The theory's P(σ) is drawn up to this multiple of the BEM's largest pressure.
const THEORY_TAIL: f64 = 1.5;

/// Points of the theory's P(σ) curve.
const THEORY_POINTS: usize = 150;

/// Relative tolerance of P(σ) and ū(p) of the theory.
const STRESS_TOLERANCE: f64 = 1e-9;

/// Arguments of `persson compare`.
#[derive(clap::Args, Debug)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct Args {
    #[command(subcommand)]
    study: Option<Study>,
    #[command(flatten)]
    main: Box<MainArgs>,
}

#[derive(clap::Subcommand, Debug)]
enum Study {
    /// κ(H) from the low-load BEM regime, averaged over seeds, next to √(8/π) and √(2π).
    Kappa(Box<KappaArgs>),
}

/// BEM knobs shared by `compare` and `compare kappa`.
#[derive(clap::Args, Debug, Clone)]
struct BemArgs {
    /// Finest grid side N; the BEM runs on N/4, N/2 and N (see --levels).
    #[arg(long, default_value_t = 256)]
    grid: usize,
    /// Number of grids, each half the next (≥ 2).
    #[arg(long, default_value_t = DEFAULT_LEVELS)]
    levels: usize,
    /// Number of realisations (seeds first-seed … first-seed + K − 1); A is averaged.
    #[arg(long, default_value_t = 1)]
    seeds: usize,
    /// First seed (Pcg64Mcg, value-stable).
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Exponent α of A(N) = A∞ + c N^−α (seed 002: 0.7).
    #[arg(long, default_value_t = DEFAULT_ALPHA, allow_negative_numbers = true, conflicts_with = "fit_alpha")]
    alpha: f64,
    /// Fit α from three grids (Richardson) instead of fixing it.
    #[arg(long)]
    fit_alpha: bool,
    /// Pixels of the coarsest grid per shortest wavelength 2π/q_s: q_s is clipped to
    /// N_coarsest q_l / this (with a warning).
    #[arg(long, default_value_t = DEFAULT_PIXELS_PER_WAVELENGTH, allow_negative_numbers = true)]
    pixels_per_wavelength: f64,
    /// Relative tolerance ε of the Polonsky–Keer solver (1e-8 … 1e-12 give the same
    /// contact fractions on the default case; the default matches `persson bem`).
    #[arg(long, default_value_t = 1e-10, allow_negative_numbers = true)]
    tol: f64,
    /// Maximum number of iterations per solve.
    #[arg(long, default_value_t = 10_000)]
    max_iter: usize,
}

impl BemArgs {
    fn alpha(&self) -> anyhow::Result<Option<f64>> {
        if self.fit_alpha {
            Ok(None)
        } else {
            Ok(Some(check::positive("alpha", self.alpha)?))
        }
    }

    fn config(&self, q_l: f64) -> anyhow::Result<(SweepConfig, f64)> {
        check::tolerance("tol", self.tol)?;
        check::positive("pixels_per_wavelength", self.pixels_per_wavelength)?;
        if self.seeds == 0 {
            anyhow::bail!("--seeds must be at least 1");
        }
        let grids = resolution_grids(self.grid, self.levels)?;
        let q_max = resolvable_q_max(q_l, grids[0], self.pixels_per_wavelength);
        let config = SweepConfig {
            grids,
            seeds: (0..self.seeds as u64).map(|k| self.seed + k).collect(),
            options: persson::bem::Options {
                tol: self.tol,
                max_iter: self.max_iter,
                warm_start: true,
            },
            size: std::f64::consts::TAU / q_l,
        };
        Ok((config, q_max))
    }
}

#[derive(clap::Args, Debug)]
struct MainArgs {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    material: MaterialArgs,
    /// Nominal (mean) pressure, same unit as the modulus; repeatable or comma-separated
    /// (default: the --data pressures, else 8 pressures with A/A0 ≈ 0.01 … 0.3).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pressure: Vec<f64>,
    #[command(flatten)]
    bem: BemArgs,
    /// Your own results: CSV with columns pressure, contact_fraction (header and # comments allowed).
    #[arg(long, value_name = "FILE.csv")]
    data: Option<PathBuf>,
    /// Your own pressure histogram at --histogram-pressure: CSV with columns pressure, density
    /// (normalised so that ∫ density dσ = A/A0).
    #[arg(long, value_name = "FILE.csv")]
    data_histogram: Option<PathBuf>,
    /// Nominal pressure of the plotted pressure distribution (nearest computed one; default:
    /// the one whose finest-grid A/A0 is nearest 0.1).
    #[arg(long, allow_negative_numbers = true)]
    histogram_pressure: Option<f64>,
    /// Number of bins of the BEM pressure histograms.
    #[arg(long, default_value_t = 40)]
    bins: usize,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
    /// Draw the pressure distribution (BEM histogram, Persson's P(σ), your histogram) on linear axes.
    #[arg(long, value_name = "FILE.svg|png")]
    plot_histogram: Option<PathBuf>,
    /// The same with a logarithmic P(σ) axis, to compare the tails.
    #[arg(long, value_name = "FILE.svg|png")]
    plot_histogram_log: Option<PathBuf>,
}

#[derive(clap::Args, Debug)]
struct KappaArgs {
    /// Hurst exponents, comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        required = true,
        allow_negative_numbers = true
    )]
    hurst: Vec<f64>,
    /// Lower cut-off q_l (sets L = 2π/q_l).
    #[arg(long = "q-l", default_value_t = 1.0, allow_negative_numbers = true)]
    q_l: f64,
    /// Roll-off q_r (default q_l).
    #[arg(long = "q-r", allow_negative_numbers = true)]
    q_r: Option<f64>,
    /// Upper cut-off q_s (default and maximum: what the coarsest grid resolves).
    #[arg(long = "q-s", allow_negative_numbers = true)]
    q_s: Option<f64>,
    /// rms slope over [q_l, q_s] of every surface.
    #[arg(long, default_value_t = 0.1, allow_negative_numbers = true)]
    rms_slope: f64,
    /// Contact modulus E*.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    modulus: f64,
    /// Nominal pressures (default: 8 with linear-law A/A0 ≈ 0.005 … 0.09).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pressure: Vec<f64>,
    #[command(flatten)]
    bem: BemArgs,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    plot: super::plot::PlotArg,
}

/// Run `persson compare`.
pub fn run(a: Args) -> anyhow::Result<()> {
    match a.study {
        Some(Study::Kappa(k)) => kappa_study(&k)?.print(&k.format),
        None => {
            let f = a.main.format.clone();
            compare(&a.main)?.print(&f)
        }
    }
}

/// Finest grid from which each solve is also announced by a line on stderr
/// when stderr is not a terminal (logs of long runs).
const LOG_GRID: usize = 512;

/// Progress of a sweep on stderr: a bar on a terminal (feature `progress`),
/// one line per solve otherwise for grids from [`LOG_GRID`].
struct Bar {
    #[cfg(feature = "progress")]
    bar: indicatif::ProgressBar,
    log: bool,
    last: std::cell::Cell<Option<usize>>,
}

impl Bar {
    #[allow(unused_variables)]
    fn new(total: usize, finest: usize) -> Self {
        use std::io::IsTerminal;
        let log = finest >= LOG_GRID && !std::io::stderr().is_terminal();
        let last = std::cell::Cell::new(None);
        #[cfg(feature = "progress")]
        {
            let bar = indicatif::ProgressBar::new(total as u64);
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{bar:30} {pos}/{len} solves {msg} [{elapsed}]",
            ) {
                bar.set_style(style);
            }
            Bar { bar, log, last }
        }
        #[cfg(not(feature = "progress"))]
        Bar { log, last }
    }

    #[allow(unused_variables)]
    fn update(&self, p: SweepProgress) {
        if self.log && self.last.get() != Some(p.done) {
            self.last.set(Some(p.done));
            eprintln!(
                "persson compare: solve {}/{}: {}² seed {} pressure {:e}",
                p.done + 1,
                p.total,
                p.grid,
                p.seed,
                p.pressure
            );
        }
        #[cfg(feature = "progress")]
        if p.iteration.iteration.is_multiple_of(10) {
            self.bar.set_position(p.done as u64);
            self.bar.set_message(format!(
                "{0}² seed {1} p {2:.3e}: iteration {3} ε {4:.1e} A {5:.4}",
                p.grid,
                p.seed,
                p.pressure,
                p.iteration.iteration,
                p.iteration.residual,
                p.iteration.contact_fraction
            ));
        }
    }

    fn finish(&self) {
        #[cfg(feature = "progress")]
        self.bar.finish_and_clear();
    }
}

fn run_sweep(
    spectrum: &dyn Spectrum,
    e_star: f64,
    pressures: &[f64],
    config: &SweepConfig,
) -> anyhow::Result<Sweep> {
    let bar = Bar::new(
        pressures.len() * config.seeds.len() * config.grids.len(),
        config.grids.last().copied().unwrap_or(0),
    );
    let s = sweep(spectrum, e_star, pressures, config, &mut |p| bar.update(p));
    bar.finish();
    Ok(s?)
}

/// The theories' A/A0 at `pressures`: `(name, values, closed low-load κ)`.
fn theory_curves(
    model: &Persson,
    pressures: &[f64],
) -> anyhow::Result<Vec<(String, Vec<f64>, f64)>> {
    let zeta = model.zeta_max();
    let points = model.load_curve(pressures, zeta)?;
    let mut out = vec![
        (
            "original".to_string(),
            points.iter().map(|p| p.contact_fraction).collect(),
            Kappa::Persson.value(),
        ),
        (
            "bush_linear".to_string(),
            points
                .iter()
                .map(|p| p.contact_fraction_bush_linear)
                .collect(),
            Kappa::Bush.value(),
        ),
        (
            "persson_linear".to_string(),
            points
                .iter()
                .map(|p| p.contact_fraction_persson_linear)
                .collect(),
            Kappa::Persson.value(),
        ),
    ];
    for t in Theory::all_defaults() {
        if t == Theory::Original {
            continue;
        }
        let c = corrected::load_curve(model, t, zeta, pressures, THEORY_TOLERANCE)?;
        out.push((
            t.name().to_string(),
            c.iter().map(|p| p.contact_fraction).collect(),
            t.low_load_kappa(),
        ));
    }
    Ok(out)
}

fn kappa_json(f: persson::Result<persson::compare::KappaFit>) -> Value {
    match f {
        Ok(k) => json!(k),
        Err(e) => json!({ "kappa": null, "reason": e.to_string() }),
    }
}

fn compare(a: &MainArgs) -> anyhow::Result<Report> {
    a.plot.check()?;
    for p in [&a.plot_histogram, &a.plot_histogram_log]
        .into_iter()
        .flatten()
    {
        #[cfg(feature = "plot")]
        persson::plot::Format::from_path(p)?;
        #[cfg(not(feature = "plot"))]
        anyhow::bail!(
            "{}: this persson was built without the `plot` feature",
            p.display()
        );
        persson::io::check_writable(p)?;
    }
    let data = a.data.as_deref().map(UserData::from_csv).transpose()?;
    let data_hist = a
        .data_histogram
        .as_deref()
        .map(UserHistogram::from_csv)
        .transpose()?;
    let full = a.spectrum.build()?;
    let e_star = a.material.build(a.spectrum.example)?.contact_modulus();
    let q_l = full.q_min();
    let (config, q_max) = a.bem.config(q_l)?;
    let alpha = a.bem.alpha()?;
    let band = BandLimited::new(full.as_ref(), q_max)?;
    if band.clipped() {
        eprintln!(
            "warning: q_s = {:e} is not resolved by the coarsest grid ({}², {} pixels per wavelength); \
             the theories and the BEM use q_s = {:e} (= {}·q_l)",
            full.q_max(),
            config.grids[0],
            a.bem.pixels_per_wavelength,
            band.q_max(),
            band.q_max() / q_l
        );
    }
    let rms_slope = band.rms_slope(q_l, band.q_max())?.value;
    let rms_height = band.rms_height(q_l, band.q_max())?.value;
    let pressures = if !a.pressure.is_empty() {
        a.pressure.clone()
    } else if let Some(d) = &data {
        d.pressures.clone()
    } else {
        default_pressures(e_star, rms_slope, 8, 0.01, 0.3)
    };
    for &p in &pressures {
        check::positive("pressure", p)?;
    }
    let model = Persson::new(&band, e_star)?;
    let zeta = model.zeta_max();
    let theories = theory_curves(&model, &pressures)?;

    // The BEM sweep and its continuum limit.
    let sw = run_sweep(&band, e_star, &pressures, &config)?;
    let means = sw.mean_contact_fraction();
    let gaps = sw.mean_gap();
    let cont = sw.extrapolate(alpha)?;
    let a_inf: Vec<f64> = cont.iter().map(|c| c.fit.value).collect();
    let a_inf_err: Vec<f64> = cont.iter().map(|c| c.uncertainty).collect();

    // κ: theories (fitted on the same pressures, and closed), BEM grids, extrapolated.
    let mut kappa = serde_json::Map::new();
    let mut kappa_fits = serde_json::Map::new();
    for (name, values, closed) in &theories {
        let f = fit_kappa(&pressures, values, e_star, rms_slope, KAPPA_MAX_FRACTION);
        kappa.insert(name.clone(), json!(f.as_ref().ok().map(|k| k.kappa)));
        let mut v = kappa_json(f);
        v["low_load_kappa"] = json!(closed);
        kappa_fits.insert(name.clone(), v);
    }
    let bem_kappa = sw.kappa(e_star, rms_slope, KAPPA_MAX_FRACTION, alpha);
    match &bem_kappa {
        Ok(k) => {
            for (g, est) in &k.per_grid {
                kappa.insert(format!("bem_{g}"), json!(est.kappa));
                kappa_fits.insert(format!("bem_{g}"), json!(est));
            }
            kappa.insert("bem_extrapolated".into(), json!(k.extrapolated.kappa));
            kappa_fits.insert("bem_extrapolated".into(), json!(k.extrapolated));
        }
        Err(e) => {
            kappa.insert("bem_extrapolated".into(), Value::Null);
            kappa_fits.insert(
                "bem_extrapolated".into(),
                json!({ "kappa": null, "reason": e.to_string() }),
            );
        }
    }

    // Pressure distributions: BEM finest-grid histogram against flat-start P(σ) at ζ_max.
    let mut distributions = Vec::new();
    for (k, &p) in pressures.iter().enumerate() {
        let (lo, hi, bem_density) = sw.histograms[k].density(a.bins);
        let centres: Vec<f64> = lo.iter().zip(&hi).map(|(l, h)| 0.5 * (l + h)).collect();
        let scene = StressScene::flat(p, None)?;
        let curve = scene
            .curves(&model, &[zeta], &centres, STRESS_TOLERANCE)?
            .pop()
            .context("no stress curve")?;
        // The theory also beyond the BEM's largest pressure, to show its tail.
        let top = THEORY_TAIL * hi.last().copied().unwrap_or(p);
        let sigma: Vec<f64> = (1..=THEORY_POINTS)
            .map(|i| top * i as f64 / THEORY_POINTS as f64)
            .collect();
        let tail = scene
            .curves(&model, &[zeta], &sigma, STRESS_TOLERANCE)?
            .pop()
            .context("no stress curve")?;
        distributions.push(json!({
            "pressure": p,
            "grid": config.grids.last(),
            "bins": centres,
            "pressure_low": lo,
            "pressure_high": hi,
            "bem_density": bem_density,
            "bem_contact_fraction": means.last().map(|m| m.0[k]),
            "theory_density": curve.density,
            "theory_contact_fraction": curve.contact_fraction,
            "theory_curve": { "sigma": sigma, "density": tail.density },
            "g": curve.g.value,
        }));
    }
    let hist_index = chosen_histogram(
        a.histogram_pressure,
        &pressures,
        &means.last().context("no grid")?.0,
    );
    // The user's histogram against P(σ) at the histogram pressure.
    let data_hist_score = match &data_hist {
        Some(h) => {
            let p = pressures[hist_index];
            let theory = StressScene::flat(p, None)?
                .curves(&model, &[zeta], &h.pressures, STRESS_TOLERANCE)?
                .pop()
                .context("no stress curve")?;
            let d =
                persson::compare::density_distance(&h.pressures, &h.densities, &theory.density)?;
            json!({ "pressure": p, "relative_l1_distance_from_theory": d })
        }
        None => Value::Null,
    };

    // Mean separation: BEM mean gap against ū(p).
    let sep = Separation::new(&band, e_star)?;
    let u_theory: Vec<f64> = pressures
        .iter()
        .map(|&p| sep.mean_separation(p).map(|u| u.value))
        .collect::<persson::Result<_>>()?;
    let u_bem = gaps.last().context("no grid")?.0.clone();

    // The user's results, scored against each theory and the extrapolated BEM.
    let data_json = match &data {
        Some(d) => {
            let curves = theory_curves(&model, &d.pressures)?;
            let mut scores = serde_json::Map::new();
            for (name, values, _) in &curves {
                scores.insert(name.clone(), json!(score(&d.contact_fractions, values)));
            }
            let bem_at: Vec<Option<f64>> = d
                .pressures
                .iter()
                .map(|&p| interpolate_log(&pressures, &a_inf, p))
                .collect();
            let (uv, rv): (Vec<f64>, Vec<f64>) = d
                .contact_fractions
                .iter()
                .zip(&bem_at)
                .filter_map(|(&u, r)| r.map(|r| (u, r)))
                .unzip();
            if !rv.is_empty() {
                let mut s = json!(score(&uv, &rv));
                s["points"] = json!(rv.len());
                scores.insert("bem_extrapolated".into(), s);
            }
            let kd = fit_kappa(
                &d.pressures,
                &d.contact_fractions,
                e_star,
                rms_slope,
                KAPPA_MAX_FRACTION,
            );
            kappa.insert("data".into(), json!(kd.as_ref().ok().map(|k| k.kappa)));
            kappa_fits.insert("data".into(), kappa_json(kd));
            json!({
                "file": a.data.as_ref().map(|p| p.display().to_string()),
                "pressures": d.pressures,
                "contact_fraction": d.contact_fractions,
                "theories": curves.iter().map(|(n, v, _)| (n.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
                "bem_extrapolated": bem_at,
                "scores": scores,
            })
        }
        None => Value::Null,
    };

    #[cfg(feature = "plot")]
    draw_plots(
        a,
        &pressures,
        &theories,
        &config.grids,
        &means,
        &a_inf,
        data.as_ref(),
        &distributions,
        hist_index,
        data_hist.as_ref(),
        e_star,
        rms_slope,
    )?;

    // Table: one row per pressure.
    let mut columns: Vec<String> = vec!["pressure".into()];
    columns.extend(theories.iter().map(|t| t.0.clone()));
    columns.extend(config.grids.iter().map(|g| format!("bem_{g}")));
    columns.extend(
        [
            "bem_extrapolated",
            "uncertainty",
            "bem_mean_gap",
            "theory_mean_separation",
        ]
        .map(String::from),
    );
    let rows: Vec<Vec<f64>> = (0..pressures.len())
        .map(|k| {
            let mut r = vec![pressures[k]];
            r.extend(theories.iter().map(|t| t.1[k]));
            r.extend(means.iter().map(|m| m.0[k]));
            r.extend([a_inf[k], a_inf_err[k], u_bem[k], u_theory[k]]);
            r
        })
        .collect();
    let mut scalars: Vec<(String, f64)> = vec![
        ("contact_modulus".into(), e_star),
        ("q_s".into(), band.q_max()),
        ("rms_slope".into(), rms_slope),
        ("rms_height".into(), rms_height),
    ];
    for (k, v) in &kappa {
        if let Some(x) = v.as_f64() {
            scalars.push((format!("kappa_{k}"), x));
            if let Some(se) = kappa_fits[k]["standard_error"].as_f64() {
                scalars.push((format!("kappa_{k}_se"), se));
            }
        }
    }
    let bem_json: Vec<Value> = sw
        .grids
        .iter()
        .zip(means.iter().zip(&gaps))
        .map(|(g, (m, u))| {
            json!({
                "grid": g.grid,
                "contact_fraction": m.0,
                "seed_scatter": m.1,
                "mean_gap": u.0,
                "surface_rms_slope": g.surface_rms_slope,
                "iterations": g.iterations,
                "residual": g.residual,
                "seconds": g.seconds,
            })
        })
        .collect();
    let theory_json: serde_json::Map<String, Value> = theories
        .iter()
        .map(|(n, v, _)| (n.clone(), json!(v)))
        .collect();
    Ok(Report {
        title: format!(
            "Theory against FFT-BEM (grids {:?}, {} seed(s), tol {:e}), E* = {e_star:e}, q_l = {q_l:e}, q_s = {:e}, L = {:e}",
            config.grids,
            config.seeds.len(),
            config.options.tol,
            band.q_max(),
            config.size
        ),
        scalars,
        columns,
        rows,
        json: json!({
            "pressures": pressures,
            "contact_modulus": e_star,
            "spectrum": {
                "q_l": q_l,
                "q_s": band.q_max(),
                "q_s_requested": full.q_max(),
                "clipped": band.clipped(),
                "rms_height": rms_height,
                "rms_slope": rms_slope,
                "zeta": zeta,
            },
            "size": config.size,
            "grids": config.grids,
            "seeds": config.seeds,
            "tol": config.options.tol,
            "theories": theory_json,
            "bem": bem_json,
            "extrapolated": {
                "contact_fraction": a_inf,
                "uncertainty": a_inf_err,
                "fit_uncertainty": cont.iter().map(|c| c.fit.uncertainty).collect::<Vec<_>>(),
                "seed_scatter": cont.iter().map(|c| c.seed_scatter).collect::<Vec<_>>(),
                "alpha": cont.iter().map(|c| c.fit.alpha).collect::<Vec<_>>(),
                "c": cont.iter().map(|c| c.fit.c).collect::<Vec<_>>(),
            },
            "kappa": kappa,
            "kappa_fits": kappa_fits,
            "kappa_max_fraction": KAPPA_MAX_FRACTION,
            "pressure_distribution": distributions,
            "histogram_pressure": pressures[hist_index],
            "mean_separation": { "bem": u_bem, "theory": u_theory },
            "data": data_json,
            "data_histogram": data_hist,
            "data_histogram_score": data_hist_score,
        }),
    })
}

/// Index of the pressure nearest `wanted` (log distance), else of the finest-grid A nearest 0.1.
fn chosen_histogram(wanted: Option<f64>, pressures: &[f64], finest: &[f64]) -> usize {
    let key = |k: usize| match wanted {
        Some(w) if w > 0.0 => (pressures[k] / w).ln().abs(),
        _ => (finest[k] - KAPPA_MAX_FRACTION).abs(),
    };
    (0..pressures.len())
        .min_by(|&i, &j| key(i).total_cmp(&key(j)))
        .unwrap_or(0)
}

#[cfg(feature = "plot")]
#[allow(clippy::too_many_arguments)]
fn draw_plots(
    a: &MainArgs,
    pressures: &[f64],
    theories: &[(String, Vec<f64>, f64)],
    grids: &[usize],
    means: &[(Vec<f64>, Vec<f64>)],
    a_inf: &[f64],
    data: Option<&UserData>,
    distributions: &[Value],
    hist_index: usize,
    data_hist: Option<&UserHistogram>,
    e_star: f64,
    rms_slope: f64,
) -> anyhow::Result<()> {
    use persson::plot::{Axis, Figure, Series, Style};
    let xy = |x: &[f64], y: &[f64]| -> Vec<(f64, f64)> {
        x.iter().copied().zip(y.iter().copied()).collect()
    };
    a.plot.draw(|| {
        let curves: Vec<(&str, &[f64])> = theories
            .iter()
            .filter(|t| t.0 != "persson_linear" && t.0 != "bush_linear")
            .map(|t| (t.0.as_str(), t.1.as_slice()))
            .collect();
        let mut fig = persson::plot::area_vs_load(
            pressures,
            &curves,
            "unit of E*",
            Some(persson::plot::LinearLaw {
                contact_modulus: e_star,
                rms_slope,
            }),
        )?;
        fig.title = "Contact area: theories, BEM and continuum limit".into();
        for (g, m) in grids.iter().zip(means) {
            fig.push(Series::new(
                format!("BEM {g}²"),
                xy(pressures, &m.0),
                Style::Markers,
            ));
        }
        fig.push(Series::line_markers("BEM, N → ∞", xy(pressures, a_inf)));
        if let Some(d) = data {
            fig.push(Series::markers(
                "your data",
                xy(&d.pressures, &d.contact_fractions),
            ));
        }
        Ok(fig)
    })?;
    let d = &distributions[hist_index];
    let get = |k: &str| -> Vec<f64> {
        d[k].as_array()
            .map(|v| v.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default()
    };
    let (bins, bem) = (get("bins"), get("bem_density"));
    let curve = &d["theory_curve"];
    let pick = |k: &str| -> Vec<f64> {
        curve[k]
            .as_array()
            .map(|v| v.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default()
    };
    let (sigma, theory) = (pick("sigma"), pick("density"));
    let p = pressures[hist_index];
    for (path, log) in [(&a.plot_histogram, false), (&a.plot_histogram_log, true)] {
        let Some(path) = path else { continue };
        let y = if log {
            Axis::log("P(σ) (1/unit of σ)")
        } else {
            Axis::linear("P(σ) (1/unit of σ)")
        };
        let mut fig = Figure::new(
            format!("Pressure distribution at σ0 = {p:.3e}"),
            Axis::linear("contact pressure σ (unit of E*)"),
            y,
        );
        fig.push(Series::line_markers(
            format!("BEM {}²", grids.last().copied().unwrap_or(0)),
            xy(&bins, &bem),
        ));
        fig.push(Series::line(
            "Persson P(σ), flat start",
            xy(&sigma, &theory),
        ));
        if let Some(h) = data_hist {
            fig.push(Series::markers(
                "your histogram",
                xy(&h.pressures, &h.densities),
            ));
        }
        persson::plot::render(&fig, path)?;
    }
    Ok(())
}

fn kappa_study(a: &KappaArgs) -> anyhow::Result<Report> {
    a.plot.check()?;
    let e_star = check::positive("modulus", a.modulus)?;
    let q_l = check::positive("q_l", a.q_l)?;
    let (config, q_max) = a.bem.config(q_l)?;
    let alpha = a.bem.alpha()?;
    let q_s = match a.q_s {
        Some(q) if q > q_max => {
            eprintln!(
                "warning: q_s = {q:e} is not resolved by the coarsest grid ({}²); using q_s = {q_max:e}",
                config.grids[0]
            );
            q_max
        }
        Some(q) => q,
        None => q_max,
    };
    let pressures = if a.pressure.is_empty() {
        default_pressures(e_star, a.rms_slope, 8, 0.005, 0.09)
    } else {
        a.pressure.clone()
    };
    let mut rows = Vec::new();
    let mut out = Vec::new();
    let mut plot_points: Vec<(f64, f64, f64)> = Vec::new();
    for &h in &a.hurst {
        let s = SelfAffine::new(
            q_l,
            a.q_r.unwrap_or(q_l),
            q_s,
            h,
            Amplitude::RmsSlope(a.rms_slope),
        )?;
        let sw = run_sweep(&s, e_star, &pressures, &config)?;
        let k = sw
            .kappa(e_star, a.rms_slope, KAPPA_MAX_FRACTION, alpha)
            .with_context(|| format!("κ at H = {h}"))?;
        let mut row = vec![h];
        for (_, e) in &k.per_grid {
            row.push(e.kappa);
        }
        row.extend([k.extrapolated.kappa, k.extrapolated.standard_error]);
        rows.push(row);
        plot_points.push((h, k.extrapolated.kappa, k.extrapolated.standard_error));
        out.push(json!({
            "hurst": h,
            "per_grid": k.per_grid.iter().map(|(g, e)| json!({ "grid": g, "kappa": e.kappa, "standard_error": e.standard_error, "seed_scatter": e.seed_scatter, "points": e.points })).collect::<Vec<_>>(),
            "bem_extrapolated": k.extrapolated,
            "contact_fraction": sw.mean_contact_fraction().iter().map(|m| m.0.clone()).collect::<Vec<_>>(),
        }));
    }
    #[cfg(feature = "plot")]
    a.plot.draw(|| {
        use persson::plot::{Axis, Figure, Series, Style};
        let (lo, hi) = (0.0, 1.0);
        let mut fig = Figure::new(
            "κ against the Hurst exponent (BEM, N → ∞)",
            Axis::linear("Hurst exponent H"),
            Axis::linear("κ"),
        );
        let colour = persson::plot::PALETTE[0];
        fig.push(
            Series::line_markers(
                "BEM, N → ∞ (± standard error)",
                plot_points.iter().map(|p| (p.0, p.1)).collect(),
            )
            .with_color(colour),
        );
        for &(h, k, se) in &plot_points {
            fig.push(Series::line("", vec![(h, k - se), (h, k + se)]).with_color(colour));
        }
        fig.push(
            Series::new(
                "Bush et al.: √(2π)",
                vec![(lo, Kappa::Bush.value()), (hi, Kappa::Bush.value())],
                Style::Dashed,
            )
            .with_color(persson::plot::PALETTE[1]),
        );
        fig.push(
            Series::new(
                "Persson: √(8/π)",
                vec![(lo, Kappa::Persson.value()), (hi, Kappa::Persson.value())],
                Style::Dotted,
            )
            .with_color(persson::plot::PALETTE[2]),
        );
        Ok(fig)
    })?;
    #[cfg(not(feature = "plot"))]
    a.plot.unavailable()?;
    let mut columns = vec!["hurst".to_string()];
    columns.extend(config.grids.iter().map(|g| format!("kappa_{g}")));
    columns.extend(["kappa_extrapolated", "standard_error"].map(String::from));
    Ok(Report {
        title: format!(
            "κ from the low-load BEM regime (A/A0 < {KAPPA_MAX_FRACTION}), grids {:?}, {} seed(s), q_s/q_l = {}, rms slope {}",
            config.grids,
            config.seeds.len(),
            q_s / q_l,
            a.rms_slope
        ),
        scalars: vec![
            ("kappa_persson".into(), Kappa::Persson.value()),
            ("kappa_bush".into(), Kappa::Bush.value()),
        ],
        columns,
        rows,
        json: json!({
            "pressures": pressures,
            "grids": config.grids,
            "seeds": config.seeds,
            "q_l": q_l,
            "q_s": q_s,
            "rms_slope": a.rms_slope,
            "contact_modulus": e_star,
            "kappa_persson": Kappa::Persson.value(),
            "kappa_bush": Kappa::Bush.value(),
            "hurst": out,
        }),
    })
}

//! `persson compare`: every theory against the FFT-BEM at several resolutions
//! of one physical surface, its continuum limit, κ, pressure distributions,
//! mean separation, and the user's own results; `persson compare kappa`: κ(H)
//! averaged over seeds. The computation is [`persson::validation`].

use std::path::PathBuf;

use persson::table::number;
use persson::validation::{
    self, ComparisonConfig, KappaStudyConfig, SweepProgress, SweepSettings, UserData,
    UserHistogram, DEFAULT_ALPHA, DEFAULT_LEVELS, DEFAULT_PIXELS_PER_WAVELENGTH,
};

use super::args::{MaterialArgs, SpectrumArgs};
use super::bem::SolverArgs;
use super::output::{print, Format};
use super::progress::Progress;

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
    #[arg(long, default_value = "256")]
    grid: usize,
    /// Number of grids, each half the next (≥ 2).
    #[arg(long, default_value_t = DEFAULT_LEVELS)]
    levels: usize,
    /// Number of realisations (seeds first-seed … first-seed + K − 1); A is averaged.
    #[arg(long, default_value = "1")]
    seeds: usize,
    /// First seed (Pcg64Mcg, value-stable).
    #[arg(long, default_value = "1")]
    seed: u64,
    /// Exponent α of A(N) = A∞ + c N^−α (Campañá & Müser 2007: 0.7).
    #[arg(long, default_value_t = DEFAULT_ALPHA, allow_negative_numbers = true, conflicts_with = "fit_alpha")]
    alpha: f64,
    /// Fit α from three grids (Richardson) instead of fixing it.
    #[arg(long)]
    fit_alpha: bool,
    /// Pixels of the coarsest grid per shortest wavelength 2π/q_s: q_s is clipped to
    /// N_coarsest q_l / this (with a warning).
    #[arg(long, default_value_t = DEFAULT_PIXELS_PER_WAVELENGTH, allow_negative_numbers = true)]
    pixels_per_wavelength: f64,
    #[command(flatten)]
    solver: SolverArgs,
}

impl BemArgs {
    fn settings(&self) -> anyhow::Result<SweepSettings> {
        anyhow::ensure!(self.seeds >= 1, "--seeds must be at least 1");
        Ok(SweepSettings {
            grid: self.grid,
            levels: self.levels,
            seeds: (0..self.seeds as u64).map(|k| self.seed + k).collect(),
            alpha: (!self.fit_alpha).then_some(self.alpha),
            pixels_per_wavelength: self.pixels_per_wavelength,
            options: self.solver.options()?,
        })
    }
}

#[derive(clap::Args, Debug)]
pub(super) struct MainArgs {
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
    /// Your own results: CSV with columns nominal_pressure, contact_fraction (header and # comments allowed).
    #[arg(long, value_name = "FILE.csv")]
    data: Option<PathBuf>,
    /// Your own pressure histogram at --histogram-pressure: CSV with columns sigma, density
    /// (normalised so that ∫ density dσ = A/A0).
    #[arg(long, value_name = "FILE.csv")]
    data_histogram: Option<PathBuf>,
    /// Nominal pressure of the shown pressure distribution (nearest computed one; default:
    /// the one whose finest-grid A/A0 is nearest 0.1).
    #[arg(long, allow_negative_numbers = true)]
    histogram_pressure: Option<f64>,
    /// Number of bins of the BEM pressure histograms.
    #[arg(long, default_value = "40")]
    bins: usize,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    pub(super) plot: super::plot::PlotArg,
    /// Draw the pressure distribution (BEM histogram, Persson's P(σ), your histogram) on linear axes.
    #[arg(long, value_name = "FILE.svg|png")]
    pub(super) plot_histogram: Option<PathBuf>,
    /// The same with a logarithmic P(σ) axis, to compare the tails.
    #[arg(long, value_name = "FILE.svg|png")]
    pub(super) plot_histogram_log: Option<PathBuf>,
}

#[derive(clap::Args, Debug)]
pub(super) struct KappaArgs {
    /// Hurst exponents, comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        required = true,
        allow_negative_numbers = true
    )]
    hurst: Vec<f64>,
    /// Lower cut-off q_l (sets L = 2π/q_l).
    #[arg(long = "q-l", default_value = "1", allow_negative_numbers = true)]
    q_l: f64,
    /// Roll-off q_r (default q_l).
    #[arg(long = "q-r", allow_negative_numbers = true)]
    q_r: Option<f64>,
    /// Upper cut-off q_s (default and maximum: what the coarsest grid resolves).
    #[arg(long = "q-s", allow_negative_numbers = true)]
    q_s: Option<f64>,
    /// rms slope over [q_l, q_s] of every surface.
    #[arg(long, default_value = "0.1", allow_negative_numbers = true)]
    rms_slope: f64,
    /// Contact modulus E*.
    #[arg(
        long,
        alias = "modulus",
        default_value = "1",
        allow_negative_numbers = true
    )]
    contact_modulus: f64,
    /// Nominal pressures (default: 8 with linear-law A/A0 ≈ 0.005 … 0.09).
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    pressure: Vec<f64>,
    #[command(flatten)]
    bem: BemArgs,
    #[command(flatten)]
    format: Format,
    #[command(flatten)]
    pub(super) plot: super::plot::PlotArg,
}

/// Run `persson compare`.
pub fn run(a: Args) -> anyhow::Result<()> {
    match a.study {
        Some(Study::Kappa(k)) => kappa_study(&k),
        None => compare(&a.main),
    }
}

/// Warn on stderr when q_s is clipped to what the coarsest grid resolves.
fn warn_clipped(band: &validation::ResolvedBand, q_l: f64, bem: &BemArgs) -> anyhow::Result<()> {
    if let (true, Some(q)) = (band.clipped, band.q_s_requested) {
        eprintln!(
            "warning: q_s = {} is not resolved by the coarsest grid ({}², {} pixels per wavelength); \
             the theories and the BEM use q_s = {} (= {}·q_l)",
            number(q, 6),
            bem.settings()?.grids()?[0],
            number(bem.pixels_per_wavelength, 6),
            number(band.q_s, 6),
            number(band.q_s / q_l, 6)
        );
    }
    Ok(())
}

/// The sweep's progress on stderr (one line per solve in logs of runs from 512²).
fn with_progress<T>(run: impl FnOnce(&mut dyn FnMut(SweepProgress)) -> T) -> T {
    let mut bar: Option<Progress> = None;
    let out = run(&mut |p| {
        let log = (p.grid >= 512).then_some("persson compare");
        let what = || format!("{}² seed {} σ0 = {:e}", p.grid, p.seed, p.nominal_pressure);
        bar.get_or_insert_with(|| Progress::solves(p.total, log))
            .update(p.done, &what, p.iteration)
    });
    if let Some(b) = bar {
        b.finish();
    }
    out
}

fn compare(a: &MainArgs) -> anyhow::Result<()> {
    super::compare_plot::check(a)?;
    let spectrum = a.spectrum.build()?;
    let mut config = ComparisonConfig::new(a.material.build(a.spectrum.example)?.contact_modulus());
    config.nominal_pressure = a.pressure.clone();
    config.sweep = a.bem.settings()?;
    config.data = a.data.as_deref().map(UserData::from_csv).transpose()?;
    config.data_histogram = a
        .data_histogram
        .as_deref()
        .map(UserHistogram::from_csv)
        .transpose()?;
    config.histogram_pressure = a.histogram_pressure;
    config.bins = a.bins;
    let q_l = spectrum.q_min();
    warn_clipped(
        &config.sweep.band(q_l, Some(spectrum.q_max()))?,
        q_l,
        &a.bem,
    )?;
    let report = with_progress(|p| validation::compare(spectrum.as_ref(), &config, p))?;
    super::compare_plot::comparison(a, &report)?;
    print(&report, &a.format)
}

fn kappa_study(a: &KappaArgs) -> anyhow::Result<()> {
    a.plot.check()?;
    let config = KappaStudyConfig {
        hurst: a.hurst.clone(),
        q_l: a.q_l,
        q_r: a.q_r,
        q_s: a.q_s,
        rms_slope: a.rms_slope,
        contact_modulus: a.contact_modulus,
        nominal_pressure: a.pressure.clone(),
        sweep: a.bem.settings()?,
    };
    warn_clipped(&config.sweep.band(a.q_l, a.q_s)?, a.q_l, &a.bem)?;
    let report = with_progress(|p| validation::kappa_study(&config, p))?;
    super::compare_plot::kappa(a, &report)?;
    print(&report, &a.format)
}

//! `persson compare`: every theory against the FFT-BEM at several resolutions
//! of one physical surface, its continuum limit, κ, pressure distributions,
//! mean separation, and the user's own results; `persson compare kappa`: κ(H)
//! averaged over seeds. The computation is [`persson_studies::validation`], the flags
//! are in `compare_args.rs`, the figures in `compare_plot.rs`.

use persson::bem::Boundary;
use persson_studies::output::Files;
use persson_studies::scene::SpectrumSpec;
use persson_studies::validation::{
    self, KappaStudyConfig, SweepProgress, UserData, UserHistogram,
};

pub use super::compare_args::Args;
use super::compare_args::{EnsembleArgs, KappaArgs, MainArgs, Study, EXAMPLE_HURST};
use super::output::{print_narrowed, print_warned};
use super::progress::Progress;
use persson_studies::Warning;

/// Run `persson compare`.
pub fn run(a: Args, files: &mut Files) -> anyhow::Result<()> {
    match a.study {
        Some(Study::Kappa(k)) => kappa_study(&k, files),
        Some(Study::Ensemble(e)) => ensemble(&e),
        None => compare(&a.main, files),
    }
}

/// The warning when q_s is clipped to what the coarsest grid resolves.
fn warn_clipped(
    band: &validation::ResolvedBand,
    q_l: f64,
    coarsest: usize,
    pixels_per_wavelength: f64,
) -> Option<Warning> {
    match (band.clipped, band.q_s_requested) {
        (true, Some(q)) => Some(Warning::ClippedBand {
            q_s_requested: q,
            q_s: band.q_s,
            q_l,
            grid: coarsest,
            pixels_per_wavelength,
        }),
        _ => None,
    }
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

fn compare(a: &MainArgs, files: &mut Files) -> anyhow::Result<()> {
    if a.spectrum.example {
        // Say what the example is (stdout stays the report alone).
        eprintln!("persson: {}", persson_studies::scene::EXAMPLE);
    }
    let map = a.measured.spec(a.spectrum.q_s)?;
    if let (Some(_), Some(flag)) = (&map, a.bem.unused_with_surface()?) {
        anyhow::bail!("{flag} is not used with --surface: the map sets the grid");
    }
    if map.is_some() && a.spectrum.anisotropy.is_some() {
        anyhow::bail!("--anisotropy is not used with --surface: a measured map has its own anisotropy (persson anisotropy --surface FILE measures it)");
    }
    let (spectrum, described) = match &map {
        Some(m) => {
            let built = SpectrumSpec::HeightMap(m.clone()).build_described()?;
            (built.value, built.description)
        }
        None => (a.spectrum.build()?, None),
    };
    let e_star = a.material.build(a.spectrum.example)?.contact_modulus();
    let mut config = a.compare.spec()?.config(e_star, &a.bem.spec.spec()?)?;
    config.data = a.data.as_deref().map(UserData::from_csv).transpose()?;
    config.data_histogram = a
        .data_histogram
        .as_deref()
        .map(UserHistogram::from_csv)
        .transpose()?;
    let breaks = match &map {
        Some(_) => Vec::new(),
        None => a.spectrum.spec()?.breaks(),
    };
    config.transport = a.transport.config(breaks)?;
    let mut warnings = a.spectrum.file_warnings();
    let report = match &map {
        Some(m) => {
            let boundary = if m.periodic {
                Boundary::Periodic
            } else {
                Boundary::Free
            };
            let surface = m.bem_surface(boundary)?;
            if let Some(d) = described {
                eprintln!("note: {d}; BEM on the map, {} boundary", boundary.name());
            }
            with_progress(|p| {
                validation::compare_surface(spectrum.as_ref(), &surface, boundary, &config, p)
            })?
        }
        None => with_progress(|p| validation::compare(spectrum.as_ref(), &config, p))?,
    };
    warnings.extend(report.warnings.iter().cloned());
    super::compare_plot::comparison(a, &report, files)?;
    print_narrowed(&report, &warnings, &a.format, a.wide)
}

fn kappa_study(a: &KappaArgs, files: &mut Files) -> anyhow::Result<()> {
    let hurst = match (a.example, a.hurst.is_empty()) {
        (true, true) => {
            eprintln!("persson: built-in example: H = 0.2, 0.5, 0.8");
            EXAMPLE_HURST.to_vec()
        }
        _ => a.hurst.clone(),
    };
    let config = KappaStudyConfig {
        hurst,
        q_l: a.q_l,
        q_r: a.q_r,
        q_s: a.q_s,
        rms_slope: a.rms_slope,
        contact_modulus: a.contact_modulus,
        nominal_pressure: a.pressure.clone(),
        sweep: a.bem.settings(None)?,
    };
    let warnings: Vec<Warning> = warn_clipped(
        &config.sweep.band(a.q_l, a.q_s)?,
        a.q_l,
        config.sweep.grids()?[0],
        config.sweep.pixels_per_wavelength,
    )
    .into_iter()
    .collect();
    let report = with_progress(|p| validation::kappa_study(&config, p))?;
    super::compare_plot::kappa(a, &report, files)?;
    print_warned(&report, &warnings, &a.format)
}

/// `persson compare ensemble`: the jobs (seed, grid) on local threads, the
/// same study the Python package runs on Dask.
fn ensemble(a: &EnsembleArgs) -> anyhow::Result<()> {
    let spectrum = a.spectrum.build()?;
    let config = validation::EnsembleConfig {
        contact_modulus: a.material.build(a.spectrum.example)?.contact_modulus(),
        nominal_pressure: super::args::pressures(&a.pressure, a.spectrum.example)?,
        sweep: a.spec.spec()?.settings()?,
    };
    let report = validation::ensemble(spectrum.as_ref(), &config, a.threads)?;
    print_warned(&report, &report.warnings, &a.format)
}

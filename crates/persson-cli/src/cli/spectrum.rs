//! `persson spectrum`: moments of the spectrum, a power-law fit and C(q); with
//! `--surface`, the measured surface's spectrum and statistics
//! ([`persson::topography::analyse`]).

use persson_studies::output::Files;
use persson_studies::scene::run;

use super::args::{MeasuredArgs, SpectrumArgs};
use super::output::{print_warned, Format};
use super::spec_args::{SpecArgs, SpecFlags};
use persson_studies::scene::SpectrumOutput;

/// Arguments of `persson spectrum`: the shared ones, the spec's
/// ([`SpectrumOutput`]) derived from it, and the measured spectrum's CSV.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    spectrum: SpectrumArgs,
    #[command(flatten)]
    measured: MeasuredArgs,
    #[command(flatten)]
    spec: SpecArgs<SpectrumOutput>,
    /// Upper end of the q range for the moments (default q_s), 1/m; with
    /// --surface the upper end of the band (default the Nyquist wavevector π/Δ).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number::number)]
    q_max: Option<f64>,
    /// Write the --surface spectrum as CSV (q, c; Persson), which --psd reads back as is.
    #[arg(long, value_name = "FILE.csv", requires = "surface", value_parser = super::files::out_file)]
    psd_out: Option<super::files::OutFile>,
    #[command(flatten)]
    format: Format,
}

/// `--q-max` ends a measured surface's band too (the height map's `q_max`
/// in a scene), so the command declares it.
impl SpecFlags for SpectrumOutput {
    const OWN: &'static [&'static str] = &["q_max"];
}

/// Run `persson spectrum`.
pub fn run(a: Args, files: &mut Files) -> anyhow::Result<()> {
    use persson_studies::scene::SpectrumSpec;
    let out = SpectrumOutput {
        q_max: a.q_max,
        ..a.spec.spec()?
    };
    let surface = !a.measured.surface.is_empty();
    if surface && (a.spec.has("q_min") || a.spec.has("points")) {
        anyhow::bail!(
            "--q-min and --points are for a spectrum of flags or a table: a --surface's band \
             and bins are its own (--q-max ends its band)"
        );
    }
    match a.measured.spectrum_spec(out.q_max)? {
        Some(SpectrumSpec::MultiScale { measurements }) => {
            return multi_scale(&a, &out, &measurements, files)
        }
        Some(SpectrumSpec::HeightMap(map)) if map.dataset_measurements()?.is_some() => {
            return multi_scale(&a, &out, &[map], files)
        }
        Some(SpectrumSpec::HeightMap(map)) => return measured(&a, &out, &map, files),
        _ => {}
    }
    let spec = a.spectrum.spec()?;
    let s = spec.build().map_err(|e| a.spectrum.psd_hint(e))?;
    let description = a.spectrum.is_example().then(|| {
        let example = persson_studies::scene::EXAMPLE;
        if spec == persson_studies::scene::SpectrumSpec::example() {
            example.to_string()
        } else {
            format!("{example} (the given flags replace parts of it)")
        }
    });
    let mut report = run::spectrum(s.as_ref(), description, out.q_min, out.q_max, out.points)?;
    for w in run::spectrum_warnings(&spec, s.as_ref()) {
        if !report.warnings.contains(&w) {
            report.warnings.push(w);
        }
    }
    super::plot::draw(files, out.plot.as_deref(), || {
        persson_studies::scene::plot::spectrum(&report)
    })?;
    print_warned(&report, &report.warnings, &a.format)
}

/// `--surface`: the analysis of the map, its CSV and plot.
#[cfg(feature = "topography")]
fn measured(
    a: &Args,
    out: &SpectrumOutput,
    map: &persson_studies::scene::HeightMapSpec,
    files: &mut Files,
) -> anyhow::Result<()> {
    let report = map.analyse()?;
    if let Some(path) = &a.psd_out {
        files.write(path, report.psd.to_csv().as_bytes())?;
    }
    super::plot::draw(files, out.plot.as_deref(), || {
        persson_studies::scene::plot::measured_spectrum(&report)
    })?;
    let warnings = persson_studies::warning::of_measured(&map.file, &report);
    print_warned(&report, &warnings, &a.format)
}

/// Without the feature `topography`, `--surface` is an error.
#[cfg(not(feature = "topography"))]
fn measured(
    _: &Args,
    _: &SpectrumOutput,
    map: &persson_studies::scene::HeightMapSpec,
    _: &mut Files,
) -> anyhow::Result<()> {
    Err(super::features::left_out("topography"))
        .map_err(|e| e.context(format!("--surface {}", map.file.display())))
}

/// Several `--surface`, or a dataset of several measurements: each
/// measurement's band and the combined spectrum.
fn multi_scale(
    a: &Args,
    out: &SpectrumOutput,
    measurements: &[persson_studies::scene::HeightMapSpec],
    files: &mut Files,
) -> anyhow::Result<()> {
    let report = persson_studies::input::multiscale::multi_scale(measurements)?;
    super::plot::draw(files, out.plot.as_deref(), || {
        persson_studies::scene::plot::multi_scale(&report)
    })?;
    if let Some(path) = &a.psd_out {
        use persson::io::csv_number as num;
        let mut text = String::from(
            "# combined isotropic power spectrum, Persson's normalisation: q (1/m, angular), c (m^4)\nq,c\n",
        );
        for (q, c) in report.q.iter().zip(&report.c) {
            text.push_str(&format!("{},{}\n", num(*q), num(*c)));
        }
        files.write(path, text.as_bytes())?;
    }
    print_warned(&report, &report.warnings, &a.format)
}

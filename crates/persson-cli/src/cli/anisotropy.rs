//! `persson anisotropy --surface FILE`: the Peklenik number and the ISO
//! 25178-2 texture parameters of a height map
//! ([`persson::topography::anisotropy`]); `--plot` draws its 2-D spectrum,
//! `--spectrum-2d` writes it as CSV or `.npy`.

use super::measured_args::MeasuredArgs;
use super::output::Format;

/// Arguments of `persson anisotropy`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    measured: MeasuredArgs,
    /// The built-in example instead of a map: the guide's stretched surface
    /// (self-affine H = 0.8, rms slope 0.1, stretched by γ = 3 along 30°,
    /// 128², L = 1 mm, seed 7), synthesised (needs the feature `bem`).
    #[arg(long, conflicts_with = "surface")]
    example: bool,
    /// Draw log10 C(q_x, q_y), the 2-D spectrum, with the lay (the principal
    /// direction) into this file (.svg or .png).
    #[arg(long, value_name = "FILE.svg|png", value_parser = super::files::out_file)]
    plot: Option<super::files::OutFile>,
    /// Write the 2-D spectrum: .csv as columns q_x, q_y, C (1/m, 1/m, m⁴), or
    /// .npy as the ny × nx array C with q = 0 at (ny/2, nx/2) and
    /// q = (index − n/2)·2π/L (numpy's fftshift order).
    #[arg(long = "spectrum-2d", value_name = "FILE.csv|npy", value_parser = super::files::out_file)]
    spectrum_2d: Option<super::files::OutFile>,
    #[command(flatten)]
    format: Format,
}

/// Run `persson anisotropy`.
#[cfg(feature = "topography")]
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    use super::output::print;
    use persson::topography::{anisotropy, Conditioning};
    // The map and how errors (its path as given) and the title (its file's
    // name) call it.
    let (t, label, detrend, window) = match a.measured.spec(None)? {
        Some(map) => {
            let name = map.file.file_name().map_or_else(
                || map.file.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            );
            let path = map.file.display().to_string();
            (map.read()?, (path, name), map.detrend, map.window)
        }
        None if a.example => {
            let name = "the built-in example".to_string();
            (example_map()?, (name.clone(), name), None, None)
        }
        None => {
            anyhow::bail!("persson anisotropy needs a height map: --surface FILE (or --example)")
        }
    };
    let defaults = Conditioning::for_topography(&t);
    let conditioning = Conditioning {
        detrend: detrend.map_or(defaults.detrend, Into::into),
        window: window.map_or(defaults.window, Into::into),
    };
    let report = anisotropy(&t, conditioning).map_err(|e| anyhow::anyhow!("{}: {e}", label.0))?;
    if let Some(path) = &a.spectrum_2d {
        files.write(path, &spectrum_bytes(path, &report.spectrum)?)?;
    }
    #[cfg(feature = "plot")]
    if let Some(path) = &a.plot {
        use persson_studies::plot::spectrum_map::{SpectrumMapFigure, SPECTRUM_MAP_SIZE};
        use persson_studies::plot::Encode;
        let number = |v: f64| persson_studies::table::number(v, 4);
        let fig = SpectrumMapFigure {
            title: format!(
                "2-D spectrum of {}: Peklenik γ = {}, lay {}°",
                label.1,
                number(report.peklenik_number),
                number(report.principal_direction)
            ),
            qx: report.spectrum.qx.clone(),
            qy: report.spectrum.qy.clone(),
            c: report.spectrum.c.clone(),
            lay: Some(report.principal_direction),
            size: SPECTRUM_MAP_SIZE,
        };
        files.write(path, &fig.encode(path)?)?;
    }
    print(&report, &a.format)
}

/// The built-in example's map (the guide's `docs/data/stretched.npy`).
#[cfg(all(feature = "topography", feature = "bem"))]
fn example_map() -> anyhow::Result<persson::topography::Topography> {
    use persson::spectrum::{Amplitude, SelfAffine, Stretched};
    let (l, n) = (1e-3, 128);
    let q = std::f64::consts::TAU / l;
    let iso = SelfAffine::new(q, 8.0 * q, 60.0 * q, 0.8, Amplitude::RmsSlope(0.1))?;
    let s = Stretched::new(std::sync::Arc::new(iso), 3.0, 30f64.to_radians())?;
    let g = persson::bem::surface::synthesize_2d(&s, n, l, 7)?;
    Ok(persson::topography::Topography::map(
        n, n, l, l, g.heights, true,
    )?)
}

/// Without the feature `bem`, the example cannot be synthesised.
#[cfg(all(feature = "topography", not(feature = "bem")))]
fn example_map() -> anyhow::Result<persson::topography::Topography> {
    Err(super::features::left_out("bem"))
}

/// The 2-D spectrum as the bytes of `path`: `.npy` (C), else CSV (q_x,
/// q_y, C per mode; the extension was checked before computing).
#[cfg(feature = "topography")]
fn spectrum_bytes(
    path: &std::path::Path,
    s: &persson::topography::Spectrum2dMap,
) -> anyhow::Result<Vec<u8>> {
    let (nx, ny) = (s.qx.len(), s.qy.len());
    let npy = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("npy"));
    match npy {
        true => Ok(persson::io::npy::encode(ny, nx, &s.c)?),
        false => {
            use std::fmt::Write as _;
            let mut out = String::with_capacity(40 * nx * ny + 16);
            out.push_str("q_x,q_y,C\n");
            for (j, qy) in s.qy.iter().enumerate() {
                for (i, qx) in s.qx.iter().enumerate() {
                    let _ = writeln!(out, "{qx:e},{qy:e},{:e}", s.c[j * nx + i]);
                }
            }
            Ok(out.into_bytes())
        }
    }
}

/// Without the feature `topography`, an error.
#[cfg(not(feature = "topography"))]
pub fn run(_: Args, _: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    Err(super::features::left_out("topography"))
}

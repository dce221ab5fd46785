//! `persson anisotropy --surface FILE`: the Peklenik number and the ISO
//! 25178-2 texture parameters of a height map
//! ([`persson::topography::anisotropy`]); `--plot` draws its 2-D spectrum,
//! `--spectrum-2d` writes it as CSV or `.npy`.

use std::path::PathBuf;

use super::measured_args::MeasuredArgs;
use super::output::Format;

/// Arguments of `persson anisotropy`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    measured: MeasuredArgs,
    /// Draw log10 C(q_x, q_y), the 2-D spectrum, with the lay (the principal
    /// direction) into this file (.svg or .png).
    #[arg(long, value_name = "FILE.svg|png")]
    plot: Option<PathBuf>,
    /// Write the 2-D spectrum: .csv as columns q_x, q_y, C (1/m, 1/m, m⁴), or
    /// .npy as the ny × nx array C with q = 0 at (ny/2, nx/2) and
    /// q = (index − n/2)·2π/L (numpy's fftshift order).
    #[arg(long = "spectrum-2d", value_name = "FILE.csv|npy")]
    spectrum_2d: Option<PathBuf>,
    #[command(flatten)]
    format: Format,
}

/// The `--spectrum-2d` file's format by extension.
#[cfg(feature = "topography")]
#[derive(Clone, Copy, PartialEq, Debug)]
enum Table2d {
    Csv,
    Npy,
}

#[cfg(feature = "topography")]
fn table_format(path: &std::path::Path) -> anyhow::Result<Table2d> {
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("csv") => Ok(Table2d::Csv),
        Some("npy") => Ok(Table2d::Npy),
        _ => anyhow::bail!(
            "--spectrum-2d {}: the file must end in .csv or .npy",
            path.display()
        ),
    }
}

/// Run `persson anisotropy`.
#[cfg(feature = "topography")]
pub fn run(a: Args) -> anyhow::Result<()> {
    use super::output::print;
    use persson::topography::{anisotropy, Conditioning};
    let Some(map) = a.measured.spec(None)? else {
        anyhow::bail!("persson anisotropy needs a height map: --surface FILE");
    };
    // Before any computation: the output files' formats and directories.
    let table = a.spectrum_2d.as_deref().map(table_format).transpose()?;
    if let Some(p) = &a.spectrum_2d {
        persson::io::check_writable(p)?;
    }
    if let Some(p) = &a.plot {
        #[cfg(not(feature = "plot"))]
        anyhow::bail!(
            "--plot {}: this persson was built without the `plot` feature",
            p.display()
        );
        #[cfg(feature = "plot")]
        {
            persson_studies::plot::Format::from_path(p)?;
            persson::io::check_writable(p)?;
        }
    }
    let t = map.read()?;
    let defaults = Conditioning::for_topography(&t);
    let conditioning = Conditioning {
        detrend: map.detrend.map_or(defaults.detrend, Into::into),
        window: map.window.map_or(defaults.window, Into::into),
    };
    let report =
        anisotropy(&t, conditioning).map_err(|e| anyhow::anyhow!("{}: {e}", map.file.display()))?;
    if let (Some(path), Some(kind)) = (&a.spectrum_2d, table) {
        write_spectrum(path, kind, &report.spectrum)?;
    }
    #[cfg(feature = "plot")]
    if let Some(path) = &a.plot {
        use persson_studies::plot::spectrum_map::{
            render_spectrum_map, SpectrumMapFigure, SPECTRUM_MAP_SIZE,
        };
        let number = |v: f64| persson_studies::table::number(v, 4);
        let fig = SpectrumMapFigure {
            title: format!(
                "2-D spectrum of {}: Peklenik γ = {}, lay {}°",
                map.file.file_name().map_or_else(
                    || map.file.display().to_string(),
                    |n| n.to_string_lossy().into_owned()
                ),
                number(report.peklenik_number),
                number(report.principal_direction)
            ),
            qx: report.spectrum.qx.clone(),
            qy: report.spectrum.qy.clone(),
            c: report.spectrum.c.clone(),
            lay: Some(report.principal_direction),
            size: SPECTRUM_MAP_SIZE,
        };
        render_spectrum_map(&fig, path)?;
    }
    print(&report, &a.format)
}

/// Write the 2-D spectrum as CSV (q_x, q_y, C per mode) or `.npy` (C).
#[cfg(feature = "topography")]
fn write_spectrum(
    path: &std::path::Path,
    kind: Table2d,
    s: &persson::topography::Spectrum2dMap,
) -> anyhow::Result<()> {
    let (nx, ny) = (s.qx.len(), s.qy.len());
    match kind {
        Table2d::Npy => persson::io::npy::write(path, ny, nx, &s.c)?,
        Table2d::Csv => {
            use std::fmt::Write as _;
            let mut out = String::with_capacity(40 * nx * ny + 16);
            out.push_str("q_x,q_y,C\n");
            for (j, qy) in s.qy.iter().enumerate() {
                for (i, qx) in s.qx.iter().enumerate() {
                    let _ = writeln!(out, "{qx:e},{qy:e},{:e}", s.c[j * nx + i]);
                }
            }
            persson::io::write_atomic(path, out.as_bytes())?;
        }
    }
    Ok(())
}

/// Without the feature `topography`, an error.
#[cfg(not(feature = "topography"))]
pub fn run(_: Args) -> anyhow::Result<()> {
    anyhow::bail!("this persson was built without the `topography` feature")
}

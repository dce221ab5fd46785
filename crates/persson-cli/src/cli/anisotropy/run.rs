//! `persson anisotropy`: the 2-D spectrum of a map (feature `topography`).

use super::Args;

/// Run `persson anisotropy`.
pub fn run(a: Args, files: &mut persson_studies::output::Files) -> anyhow::Result<()> {
    use crate::persson_cli::output::print;
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
        detrend: detrend.unwrap_or(defaults.detrend),
        window: window.unwrap_or(defaults.window),
    };
    let report = anisotropy(&t, conditioning).map_err(|e| anyhow::anyhow!("{}: {e}", label.0))?;
    if let Some(path) = &a.spectrum_2d {
        files.write(path, &spectrum_bytes(path, &report.spectrum)?)?;
    }
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
#[cfg(feature = "bem")]
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
#[cfg(not(feature = "bem"))]
fn example_map() -> anyhow::Result<persson::topography::Topography> {
    Err(crate::persson_cli::features::left_out("bem"))
}

/// The 2-D spectrum as the bytes of `path`: `.npy` (C), else CSV (q_x,
/// q_y, C per mode; the extension was checked before computing).
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

//! `surrogates`: does the map make contact like a random surface of the
//! same spectrum? The FFT-BEM on the scene's height map and on K surrogates
//! of it ([`persson::bem::surrogate`]), at the scene's nominal pressures:
//! A/A0 against the surrogates' mean and spread, the pressure tails, the
//! contact patches and the height moments (Campañá & Müser 2007, the
//! project's seed, asked of the user's own map).

use std::path::Path;

use persson::error::Result;

mod plot;
mod report;
// The solves (feature `bem`).
#[cfg_attr(not(feature = "bem"), path = "off.rs")]
mod run;
mod spec;

use crate::output::Files;
use crate::study::{draw, plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::table::number;
use crate::warning::Warning;
pub use plot::{area as figure, distribution as distribution_figure};
pub use report::*;
pub use run::*;
pub use spec::*;

/// The radial-spectrum mismatch of amplitude-adjusted surrogates above
/// which a warning says so (1 %).
pub const SPECTRUM_TOLERANCE: f64 = 0.01;

/// Contact nodes of the map below which a load is warned of as too coarse
/// (its tail fit needs 10 pressures above the mean; its A/A0 a few dozen
/// nodes to mean anything).
pub const MIN_CONTACT_NODES: usize = 25;

/// The study `surrogates`.
pub struct Surrogates;

impl Study for Surrogates {
    const KEY: &'static str = "surrogates";
    type Spec = SurrogatesOutput;
    type Report = SurrogatesReport;

    fn reads(_: &SurrogatesOutput, _: &Inputs<'_>) -> Reads {
        Reads::CONTACT
    }

    fn run(ctx: &Context<'_>, s: &SurrogatesOutput) -> Result<SurrogatesReport> {
        surrogates(ctx, s)
    }

    fn warnings(r: &SurrogatesReport) -> Vec<Warning> {
        let nodes = |p: &SurrogatePoint| {
            (p.map_contact_fraction * (r.grid * r.grid) as f64).round() as usize
        };
        let coarse: Vec<&SurrogatePoint> = r
            .points
            .iter()
            .filter(|p| nodes(p) < MIN_CONTACT_NODES)
            .collect();
        let mut w: Vec<Warning> = r
            .spectrum_mismatch
            .filter(|m| *m > SPECTRUM_TOLERANCE)
            .map(|mismatch| {
                Warning::SurrogateSpectrum {
                    mismatch,
                    message: String::new(),
                }
                .described(describe)
            })
            .into_iter()
            .collect();
        if !coarse.is_empty() {
            w.push(
                Warning::CoarseContact {
                    nominal_pressure: coarse.iter().map(|p| p.nominal_pressure).collect(),
                    nodes: coarse.iter().map(|p| nodes(p)).collect(),
                    min_nodes: MIN_CONTACT_NODES,
                    message: String::new(),
                }
                .described(describe),
            );
        }
        w
    }

    fn files(s: &SurrogatesOutput) -> Vec<OutFile> {
        let mut f: Vec<OutFile> = [
            plot_file(Self::KEY, "plot", s.plot.as_ref()),
            plot_file(Self::KEY, "plot_distribution", s.plot_distribution.as_ref()),
        ]
        .into_iter()
        .flatten()
        .collect();
        if let Some(p) = &s.surfaces {
            f.push(("outputs.surrogates.surfaces".into(), p.clone(), &["npy"]));
        }
        f
    }

    fn write(
        s: &SurrogatesOutput,
        r: &SurrogatesReport,
        _: &Context<'_>,
        dir: &Path,
        out: &mut Files,
    ) -> Result<()> {
        draw(out, dir, s.plot.as_ref(), || Ok(Box::new(figure(r)?)))?;
        draw(out, dir, s.plot_distribution.as_ref(), || {
            Ok(Box::new(distribution_figure(r)?))
        })?;
        if let Some(p) = &s.surfaces {
            write_surfaces(r, &dir.join(p), out)?;
        }
        Ok(())
    }
}

/// Each surrogate as `.npy` at `path` with `_k` (k = 1 … K) before the extension.
fn write_surfaces(r: &SurrogatesReport, path: &Path, out: &mut Files) -> Result<()> {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().into_owned())
        .unwrap_or_else(|| "npy".into());
    for (k, h) in r.surfaces.iter().enumerate() {
        let p = path.with_file_name(format!("{stem}_{}.{ext}", k + 1));
        out.write(&p, &persson::io::npy::encode(r.grid, r.grid, h)?)?;
    }
    Ok(())
}

/// The text of `surrogates`'s warnings ([`Warning::described`]).
pub(crate) fn describe(w: &Warning, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    match w {
        Warning::SurrogateSpectrum { mismatch, .. } => write!(
            f,
            "the amplitude-adjusted surrogates' radial spectrum differs from the map's by up \
             to {} in some bins (their heights are the map's exactly): part of a difference \
             may be the spectrum's; compare with kind = phase",
            number(*mismatch * 100.0, 3) + " %"
        ),
        Warning::CoarseContact {
            nominal_pressure,
            nodes,
            min_nodes,
            ..
        } => write!(
            f,
            "at σ0 = {} the map touches on fewer than {min_nodes} grid nodes ({}): its A/A0, \
             patches and tail rest on too few points there; use a finer map or larger loads",
            nominal_pressure
                .iter()
                .map(|p| number(*p, 4))
                .collect::<Vec<_>>()
                .join(", "),
            nodes
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
        _ => Ok(()),
    }
}

//! `bem`: FFT-BEM rough contact at the scene's nominal pressures, with the
//! contact-patch statistics and the stress below the surface.

use std::path::Path;

use persson::error::Result;

use crate::output::Files;
mod spec;

use crate::study::{Context, Inputs, OutFile, Reads, Study};
pub use spec::*;

/// The study `bem`.
pub struct Bem;

impl Study for Bem {
    const KEY: &'static str = "bem";
    type Spec = BemOutput;
    type Report = Report;

    fn reads(_: &BemOutput, _: &Inputs<'_>) -> Reads {
        Reads {
            spectrum: true,
            material: true,
            nominal_pressure: true,
            ..Reads::NOTHING
        }
    }

    fn run(ctx: &Context<'_>, b: &BemOutput) -> Result<Report> {
        run(ctx, b)
    }

    fn warnings(r: &Report) -> Vec<crate::warning::Warning> {
        warnings(r)
    }

    fn entries<M: serde::ser::SerializeMap>(r: &Report, map: &mut M) -> Result<(), M::Error> {
        entries(r, map)
    }

    fn files(b: &BemOutput) -> Vec<OutFile> {
        use crate::study::plot_file;
        let sub = b.subsurface.as_ref();
        let data = |field: &str, p: Option<&std::path::PathBuf>| {
            p.map(|p| (format!("outputs.bem.{field}"), p.clone(), &[][..]))
        };
        [
            plot_file(Self::KEY, "plot", b.plot.as_ref()),
            plot_file(Self::KEY, "pressure_plot", b.pressure_plot.as_ref()),
            plot_file(
                Self::KEY,
                "patches.plot",
                b.patches.as_ref().and_then(|p| p.plot.as_ref()),
            ),
            plot_file(
                Self::KEY,
                "subsurface.plot",
                sub.and_then(|s| s.plot.as_ref()),
            ),
            data("histogram", b.histogram.as_ref()),
            data(
                "subsurface.stress_field",
                sub.and_then(|s| s.stress_field.as_ref()),
            ),
        ]
        .into_iter()
        .flatten()
        .collect()
    }

    fn write(
        b: &BemOutput,
        r: &Report,
        ctx: &Context<'_>,
        dir: &Path,
        out: &mut Files,
    ) -> Result<()> {
        write(b, r, ctx, dir, out)
    }
}

#[cfg(feature = "bem")]
pub mod figures;
#[cfg_attr(not(feature = "bem"), path = "unavailable.rs")]
mod rough;
#[cfg(feature = "bem")]
pub mod solve;
use rough::{entries, run, warnings, write, Report};

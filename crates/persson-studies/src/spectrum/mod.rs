//! `spectrum`: moments of the spectrum, a power-law fit and C(q).

use persson::error::Result;

use crate::input::spectrum_warnings;
use crate::input::{SpectrumSpec, EXAMPLE};

mod plot;
mod report;
mod run;
mod spec;

use crate::study::{plot_file, Context, Inputs, OutFile, Reads, Study};
use crate::warning::Warning;
#[cfg(feature = "topography")]
pub use plot::measured_spectrum;
pub use plot::spectrum as figure;
pub use report::*;
pub use run::spectrum;
pub use spec::*;

/// The study `spectrum`.
pub struct Spectrum;

impl Study for Spectrum {
    const KEY: &'static str = "spectrum";
    type Spec = SpectrumOutput;
    type Report = SpectrumReport;

    fn reads(_: &SpectrumOutput, _: &Inputs<'_>) -> Reads {
        Reads {
            spectrum: true,
            ..Reads::NOTHING
        }
    }

    fn run(ctx: &Context<'_>, sp: &SpectrumOutput) -> Result<SpectrumReport> {
        let spec = ctx.spectrum()?;
        let s = ctx.build_spectrum()?;
        let example = *spec == SpectrumSpec::example();
        let mut r = spectrum(
            s.as_ref(),
            example.then(|| EXAMPLE.to_string()),
            sp.q_min,
            sp.q_max,
            sp.points,
        )?;
        for w in spectrum_warnings(spec, s.as_ref()) {
            crate::warning::push(&mut r.warnings, Some(w));
        }
        Ok(r)
    }

    fn warnings(r: &SpectrumReport) -> Vec<Warning> {
        r.warnings.clone()
    }

    fn files(s: &SpectrumOutput) -> Vec<OutFile> {
        plot_file(Self::KEY, "plot", s.plot.as_ref())
            .into_iter()
            .collect()
    }

    fn write(
        s: &SpectrumOutput,
        r: &SpectrumReport,
        _: &Context<'_>,
        dir: &std::path::Path,
        out: &mut crate::output::Files,
    ) -> Result<()> {
        crate::study::draw(out, dir, s.plot.as_ref(), || figure(r).map(Box::new))
    }
}

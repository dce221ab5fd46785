//! `bem rough --patches` and `--subsurface`: what each solve gives besides the
//! area, computed as the solves arrive, and the report that carries them
//! beside the load curve.

use persson::bem::rough::RoughReport;
use persson::bem::Boundary;
use persson_studies::bem::solve::{patch_options, subsurface_options};
use persson_studies::bem_detail::{Details, PatchReport, SubsurfaceStudy, DEFAULT_POISSON};
use persson_studies::scene::BemOutput;
use persson_studies::table::{Table, Tabulate};
use serde::Serialize;


/// The patch and stress studies `b` asks for, on an `n × n` grid of side
/// `size`, the Poisson ratio the material's (default 0.3); checked here,
/// before any solve ([`Details::new`]).
pub fn details(
    b: &BemOutput,
    (n, size, boundary): (usize, f64, Boundary),
    poisson: Option<f64>,
    pressures: &[f64],
) -> anyhow::Result<Details> {
    let patches = b.patches.as_ref().map(|p| patch_options(p, boundary));
    let poisson = poisson.unwrap_or(DEFAULT_POISSON);
    let subsurface = b.subsurface.as_ref().map(|s| subsurface_options(s, poisson));
    // The library names the field; the command line's blame names its flag.
    Ok(Details::new(
        (n, size, boundary),
        pressures,
        patches,
        subsurface,
    )?)
}

/// The load curve (with its transport values, if asked) with the patch and
/// stress studies beside it.
#[derive(Serialize)]
pub struct RoughWithDetails<'a, R = RoughReport> {
    /// The load curve.
    #[serde(flatten)]
    pub rough: &'a R,
    /// Patch statistics.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub patches: Option<PatchReport>,
    /// Stress below the surface.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub subsurface: Option<SubsurfaceStudy>,
}

impl<R: Tabulate> Tabulate for RoughWithDetails<'_, R> {
    fn tables(&self) -> Vec<Table> {
        let mut t = self.rough.tables();
        if let Some(p) = &self.patches {
            t.extend(p.tables());
        }
        if let Some(s) = &self.subsurface {
            t.extend(s.tables());
        }
        t
    }
}

//! `bem rough --patches` and `--subsurface`: what each solve gives besides the
//! area, computed as the solves arrive, and the report that carries them
//! beside the load curve.

use std::path::Path;

use persson::bem::patches::{Connectivity, PatchOptions};
use persson::bem::rough::RoughReport;
use persson::bem::{Boundary, Solution};
use persson::io::npy;
use persson_studies::bem_detail::{self, PatchReport, SubsurfaceStudy};
use persson_studies::table::{Table, Tabulate};
use serde::Serialize;

use super::bem_args::DetailArgs;

/// Poisson ratio of the body when the material is given by E* alone.
pub const DEFAULT_POISSON: f64 = 0.3;

/// The patch and stress studies of the solves of one `bem rough`.
pub struct Details<'a> {
    args: &'a DetailArgs,
    n: usize,
    size: f64,
    boundary: Boundary,
    poisson: f64,
    pressures: &'a [f64],
    /// The patch report, with `--patches`.
    pub patches: Option<PatchReport>,
    /// The stress study, with `--subsurface`.
    pub subsurface: Option<SubsurfaceStudy>,
}

impl<'a> Details<'a> {
    /// The studies `args` asks for, on an `n × n` grid of side `size`; the
    /// depths are checked here, before any solve.
    pub fn new(
        args: &'a DetailArgs,
        n: usize,
        size: f64,
        boundary: Boundary,
        poisson: Option<f64>,
        pressures: &'a [f64],
    ) -> anyhow::Result<Self> {
        let options = PatchOptions {
            connectivity: if args.connectivity == "eight" {
                Connectivity::Eight
            } else {
                Connectivity::Four
            },
            boundary,
            bins_per_decade: args.bins_per_decade,
        };
        if args.subsurface {
            bem_detail::check_depths(&args.depth, size)
                .map_err(|e| anyhow::anyhow!("--depth: {e}"))?;
        }
        Ok(Details {
            args,
            n,
            size,
            boundary,
            poisson: poisson.unwrap_or(DEFAULT_POISSON),
            pressures,
            patches: args.patches.then(|| PatchReport::new(n, size, &options)),
            subsurface: args.subsurface.then(|| SubsurfaceStudy::new(&args.depth)),
        })
    }

    /// Study solve `k`.
    pub fn solution(&mut self, k: usize, s: &Solution) -> persson::Result<()> {
        let sigma0 = self.pressures.get(k).copied().unwrap_or(s.mean_pressure);
        if let Some(p) = &mut self.patches {
            p.push(sigma0, &s.pressure)?;
        }
        if let Some(study) = &mut self.subsurface {
            let (n, field) = (self.n, self.args.stress_field.as_deref());
            let point = bem_detail::subsurface(
                sigma0,
                &s.pressure,
                n,
                self.size,
                self.boundary,
                self.poisson,
                &self.args.depth,
                self.args.tensile_yield_stress,
                &mut |j, map| match field {
                    Some(path) => npy::write(&indexed(path, k, j), n, n, map),
                    None => Ok(()),
                },
            )?;
            study.points.push(point);
        }
        Ok(())
    }
}

/// `dir/name.ext` → `dir/name_k_j.ext`.
fn indexed(path: &Path, k: usize, j: usize) -> std::path::PathBuf {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = match path.extension() {
        Some(e) => format!("{stem}_{k}_{j}.{}", e.to_string_lossy()),
        None => format!("{stem}_{k}_{j}"),
    };
    path.with_file_name(name)
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

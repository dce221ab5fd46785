//! The patch and stress studies of the solves of one rough contact, computed
//! as the solves arrive (`bem rough --patches/--subsurface` and the scene's
//! `outputs.bem.patches/subsurface`).

use std::path::{Path, PathBuf};

use persson::bem::kernel::Boundary;
use persson::bem::patches::PatchOptions;
use persson::bem::Solution;
use persson::error::Result;

use super::{check_depths, subsurface, PatchReport, SubsurfaceStudy};

/// Poisson ratio of the body when the material is given by E* alone.
pub const DEFAULT_POISSON: f64 = 0.3;

/// What to study below each solve.
#[derive(Debug, Clone, PartialEq)]
pub struct SubsurfaceOptions {
    /// Depths of the planes, m (unit of L): each > 0 and at most L.
    pub depth: Vec<f64>,
    /// Poisson ratio ν of the body.
    pub poisson: f64,
    /// Uniaxial yield stress Y of the von Mises criterion (unit of p).
    pub tensile_yield_stress: Option<f64>,
    /// Keep each plane's von Mises map in [`Details::maps`] (written or
    /// drawn once the whole run has succeeded).
    pub keep_maps: bool,
}

/// The von Mises map of plane `depth_index` under solve `index`.
#[derive(Debug, Clone, PartialEq)]
pub struct StressMap {
    /// Index of the solve (pressure).
    pub index: usize,
    /// Index of the depth.
    pub depth_index: usize,
    /// σ_vM, `N × N` row-major (unit of p).
    pub von_mises_stress: Vec<f64>,
}

/// The patch and stress studies of the solves of one rough contact.
#[derive(Debug)]
pub struct Details {
    n: usize,
    size: f64,
    boundary: Boundary,
    pressures: Vec<f64>,
    subsurface_options: Option<SubsurfaceOptions>,
    /// The patch report (with patch options).
    pub patches: Option<PatchReport>,
    /// The stress study (with subsurface options).
    pub subsurface: Option<SubsurfaceStudy>,
    /// The von Mises maps, when asked to keep them.
    pub maps: Vec<StressMap>,
}

impl Details {
    /// The studies asked for, on an `n × n` grid of side `size` solved at
    /// `pressures`; the depths are checked here, before any solve.
    ///
    /// # Errors
    /// Patches' bins per decade 0 (named `bins_per_decade`); a depth out of
    /// (0, L] (named `depth`); no depth; a tensile yield stress not finite
    /// and > 0 (named `tensile_yield_stress`): the one check of the command
    /// line and the scene, before any solve.
    pub fn new(
        (n, size, boundary): (usize, f64, Boundary),
        pressures: &[f64],
        patches: Option<PatchOptions>,
        subsurface: Option<SubsurfaceOptions>,
    ) -> Result<Self> {
        if patches.as_ref().is_some_and(|p| p.bins_per_decade == 0) {
            return Err(persson::Error::invalid("bins_per_decade", 0.0, ">= 1"));
        }
        if let Some(s) = &subsurface {
            check_depths(&s.depth, size)?;
            if let Some(y) = s.tensile_yield_stress {
                persson::error::check::positive("tensile_yield_stress", y)?;
            }
        }
        Ok(Details {
            n,
            size,
            boundary,
            pressures: pressures.to_vec(),
            patches: patches.map(|o| PatchReport::new(n, size, &o)),
            subsurface: subsurface.as_ref().map(|s| SubsurfaceStudy::new(&s.depth)),
            subsurface_options: subsurface,
            maps: Vec::new(),
        })
    }

    /// Study solve `k`.
    ///
    /// # Errors
    /// The studies' own errors.
    pub fn solution(&mut self, k: usize, s: &Solution) -> Result<()> {
        let sigma0 = self.pressures.get(k).copied().unwrap_or(s.mean_pressure);
        if let Some(p) = &mut self.patches {
            p.push(sigma0, &s.pressure)?;
        }
        if let (Some(study), Some(o)) = (&mut self.subsurface, &self.subsurface_options) {
            let (n, kept) = (self.n, &mut self.maps);
            let point = subsurface(
                sigma0,
                &s.pressure,
                n,
                self.size,
                self.boundary,
                o.poisson,
                &o.depth,
                o.tensile_yield_stress,
                &mut |j, map| {
                    if o.keep_maps {
                        kept.push(StressMap {
                            index: k,
                            depth_index: j,
                            von_mises_stress: map.to_vec(),
                        });
                    }
                    Ok(())
                },
            )?;
            study.points.push(point);
        }
        Ok(())
    }
}

impl persson::bem::rough::Observer for Details {
    fn iteration(&mut self, p: persson::bem::rough::RoughProgress) {
        crate::progress::report(&crate::progress::Progress {
            study: "bem",
            step: p.index,
            steps: p.total,
            iteration: p.iteration.iteration,
            residual: p.iteration.residual,
        });
    }
    fn solution(&mut self, index: usize, solution: &Solution) -> Result<()> {
        Details::solution(self, index, solution)
    }
}

/// `dir/name.ext` → `dir/name_k_j.ext`.
pub fn indexed(path: &Path, k: usize, j: usize) -> PathBuf {
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

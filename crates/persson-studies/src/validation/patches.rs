//! Contact-patch statistics in `compare`: per grid and nominal pressure, the
//! number of connected contact patches of the BEM solution, the largest
//! patch's share of the contact area, and the exponent τ of the patch-area
//! distribution n(A) ∝ A^{−τ} ([`crate::bem_detail::area_exponent`]), each
//! the mean over the seeds; computed as the sweep's solves arrive
//! ([`super::sweep::sweep_source_observed`]).
//!
//! # Formula
//! ```text
//! patch_count          = number of 4-connected patches of {p > 0} (periodic wrap on a periodic surface)
//! largest_patch_share  = A_largest / A_contact
//! patch_area_exponent  = τ of ln n_k = c − τ ln √(A_low,k A_high,k), 5 log bins per decade
//! ```
//! The fit is taken as reliable only on at least [`MIN_PATCHES`] patches;
//! below that (or with fewer than three occupied bins, no τ at all) the
//! comparison carries the warning `few_patches` (grid, first σ0, how many).
//! docs/asperity.md sets τ beside Hyun, Pei, Molinari & Robbins (2004).
//!
//! # References
//! - S. Hyun, L. Pei, J.-F. Molinari, M. O. Robbins, Phys. Rev. E 70, 026117
//!   (2004), doi:10.1103/PhysRevE.70.026117.
//! - M. H. Müser, A. Wang, Lubricants 6, 85 (2018), doi:10.3390/lubricants6040085.

use serde::Serialize;

use crate::bem_detail::area_exponent;
use crate::table::{number, Cell, Table};
use crate::warning::Warning;
use persson::bem::patches::{pressure_patches, Connectivity, PatchOptions};
use persson::bem::{Boundary, Solution};
use persson::error::Result;

/// Fewest patches on which τ is reported without the `few_patches` warning.
pub const MIN_PATCHES: usize = 20;

/// Log bins per decade of the distribution fitted.
pub const BINS_PER_DECADE: usize = 5;

/// The patches of one grid, per nominal pressure (seed means).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PatchGrid {
    /// Grid side N.
    pub grid: usize,
    /// Number of patches, mean over the seeds.
    pub patch_count: Vec<f64>,
    /// Largest patch area / contact area, mean over the seeds (0 without contact).
    pub largest_patch_share: Vec<f64>,
    /// τ, mean over the seeds where it could be fitted (`None`: nowhere).
    pub patch_area_exponent: Vec<Option<f64>>,
}

/// The patch statistics of a comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PatchComparison {
    /// Neighbourhood of a patch.
    pub connectivity: Connectivity,
    /// Log bins per decade of the fitted distribution.
    pub bins_per_decade: usize,
    /// Fewest patches for a τ without warning.
    pub min_patches: usize,
    /// One entry per grid, ascending.
    pub per_grid: Vec<PatchGrid>,
}

/// One solve's numbers.
#[derive(Debug, Clone, Copy, Default)]
struct Solve {
    count: usize,
    share: f64,
    exponent: Option<f64>,
}

/// Collects the solves of a sweep (`[grid][seed][pressure]`).
#[derive(Debug)]
pub struct PatchCollector {
    grids: Vec<usize>,
    size: f64,
    options: PatchOptions,
    solves: Vec<Vec<Vec<Option<Solve>>>>,
}

impl PatchCollector {
    /// For `grids` × `seeds` × `pressures` solves on a domain of side `size`.
    pub fn new(
        grids: &[usize],
        seeds: usize,
        pressures: usize,
        size: f64,
        boundary: Boundary,
    ) -> Self {
        PatchCollector {
            grids: grids.to_vec(),
            size,
            options: PatchOptions {
                connectivity: Connectivity::Four,
                boundary,
                bins_per_decade: BINS_PER_DECADE,
            },
            solves: vec![vec![vec![None; pressures]; seeds.max(1)]; grids.len()],
        }
    }

    /// The patches of solve (`grid`, `seed`, `pressure`) (indices).
    ///
    /// # Errors
    /// As [`pressure_patches`].
    pub fn add(&mut self, grid: usize, seed: usize, pressure: usize, s: &Solution) -> Result<()> {
        self.add_field(grid, seed, pressure, &s.pressure)
    }

    /// [`PatchCollector::add`] of a pressure field (`N × N`, N the grid's).
    ///
    /// # Errors
    /// As [`pressure_patches`].
    pub fn add_field(
        &mut self,
        grid: usize,
        seed: usize,
        pressure: usize,
        field: &[f64],
    ) -> Result<()> {
        let Some(&n) = self.grids.get(grid) else {
            return Ok(());
        };
        let st = pressure_patches(field, n, self.size, &self.options)?;
        let total = st.mean_patch_area * st.patch_count as f64;
        let solve = Solve {
            count: st.patch_count,
            share: if total > 0.0 {
                st.largest_patch_area / total
            } else {
                0.0
            },
            exponent: area_exponent(&st.area_distribution),
        };
        if let Some(slot) = self
            .solves
            .get_mut(grid)
            .and_then(|g| g.get_mut(seed))
            .and_then(|g| g.get_mut(pressure))
        {
            *slot = Some(solve);
        }
        Ok(())
    }

    /// The seed means per grid and pressure, and the `few_patches` warning
    /// (`pressures` in the caller's order).
    pub fn finish(self, pressures: &[f64]) -> (PatchComparison, Option<Warning>) {
        let mut few: Option<(usize, f64, usize)> = None;
        let per_grid = self
            .grids
            .iter()
            .zip(&self.solves)
            .map(|(&grid, seeds)| {
                let np = pressures.len();
                let mut g = PatchGrid {
                    grid,
                    patch_count: vec![0.0; np],
                    largest_patch_share: vec![0.0; np],
                    patch_area_exponent: vec![None; np],
                };
                for k in 0..np {
                    let solves: Vec<Solve> = seeds.iter().filter_map(|s| s[k]).collect();
                    let m = solves.len().max(1) as f64;
                    g.patch_count[k] = solves.iter().map(|s| s.count as f64).sum::<f64>() / m;
                    g.largest_patch_share[k] = solves.iter().map(|s| s.share).sum::<f64>() / m;
                    let taus: Vec<f64> = solves.iter().filter_map(|s| s.exponent).collect();
                    g.patch_area_exponent[k] =
                        (!taus.is_empty()).then(|| taus.iter().sum::<f64>() / taus.len() as f64);
                    let weak = solves
                        .iter()
                        .any(|s| s.count < MIN_PATCHES || s.exponent.is_none());
                    if weak && !solves.is_empty() {
                        let f = few.get_or_insert((grid, pressures[k], 0));
                        f.2 += 1;
                    }
                }
                g
            })
            .collect();
        let warning = few.map(|(grid, nominal_pressure, count)| Warning::FewPatches {
            grid,
            nominal_pressure,
            count,
            min_patches: MIN_PATCHES, message: String::new(), }.described(describe));
        (
            PatchComparison {
                connectivity: self.options.connectivity,
                bins_per_decade: BINS_PER_DECADE,
                min_patches: MIN_PATCHES,
                per_grid,
            },
            warning,
        )
    }
}


/// The table "Contact patches": per grid and σ0 the count, the largest
/// patch's share and τ.
pub fn patch_table(p: &PatchComparison, pressures: &[f64]) -> Table {
    let mut t = Table::new(
        "compare_patches",
        format!(
            "Contact patches of the BEM ({}-neighbour; τ of n(A) ∝ A^(−τ), {} log bins per decade; seed means)",
            match p.connectivity {
                Connectivity::Four => 4,
                Connectivity::Eight => 8,
            },
            p.bins_per_decade
        ),
    )
    .column("grid", "N")
    .column("nominal_pressure", "σ0")
    .column("patch_count", "patches")
    .column_digits("largest_patch_share", "largest/A", 3)
    .column_digits("patch_area_exponent", "τ", 3);
    for g in &p.per_grid {
        for (k, &sigma0) in pressures.iter().enumerate() {
            t.push(vec![
                g.grid.into(),
                sigma0.into(),
                g.patch_count
                    .get(k)
                    .copied()
                    .map_or(Cell::Empty, Cell::from),
                g.largest_patch_share
                    .get(k)
                    .copied()
                    .map_or(Cell::Empty, Cell::from),
                g.patch_area_exponent.get(k).copied().flatten().into(),
            ]);
        }
    }
    t
}

/// The text of the `few_patches` warning ([`Warning::described`]).
pub(crate) fn describe(w: &Warning, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    match w {
        Warning::FewPatches {
            grid,
            nominal_pressure,
            count,
            min_patches,
            ..
        } => write!(
            f,
            "at {count} (grid, σ0) point(s), from N = {grid}, σ0 = {}, a solve has fewer \
             than {min_patches} contact patches or too few occupied bins: the patch-area \
             exponent τ there is rough or absent",
            number(*nominal_pressure, 4)
        ),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A field of `n × n` with the given cells pressed.
    fn field(n: usize, cells: &[usize]) -> Vec<f64> {
        let mut p = vec![0.0; n * n];
        for &c in cells {
            p[c] = 1.0;
        }
        p
    }

    #[test]
    fn seed_means_of_counts_and_shares_and_the_warning() {
        let mut c = PatchCollector::new(&[8], 2, 1, 1.0, Boundary::Periodic);
        // seed 0: a single cell and a 3-cell bar apart → 2 patches, 3/4
        c.add_field(0, 0, 0, &field(8, &[0, 18, 19, 20])).unwrap();
        // seed 1: a 2 × 2 block → 1 patch, share 1
        c.add_field(0, 1, 0, &field(8, &[27, 28, 35, 36])).unwrap();
        let (p, w) = c.finish(&[0.5]);
        let g = &p.per_grid[0];
        assert_eq!(g.patch_count, vec![1.5]);
        assert_eq!(g.largest_patch_share, vec![0.875]);
        // one or two bins hold patches: no τ
        assert_eq!(g.patch_area_exponent, vec![None]);
        match w {
            Some(Warning::FewPatches {
                grid: 8,
                count: 1,
                min_patches: MIN_PATCHES,
                nominal_pressure,
                ..
            }) => assert_eq!(nominal_pressure, 0.5),
            other => panic!("{other:?}"),
        }
    }

    /// τ is the exponent of the density n(A) (Müser & Wang 2018's form),
    /// not of the counts per logarithmic bin (which fall as A^{1−τ}): counts
    /// halving from one octave bin to the next are n(A) ∝ A^{−2}, τ = 2.
    #[test]
    fn the_exponent_is_that_of_the_density() {
        let total: usize = (0..8).map(|k| 1usize << (7 - k)).sum();
        let bins: Vec<persson::bem::patches::AreaBin> = (0..8)
            .map(|k| {
                let (lo, hi) = (f64::from(1u32 << k), f64::from(2u32 << k));
                let count = 1usize << (7 - k);
                persson::bem::patches::AreaBin {
                    area_low: lo,
                    area_high: hi,
                    count,
                    density: count as f64 / (total as f64 * (hi - lo)),
                }
            })
            .collect();
        let tau = area_exponent(&bins).unwrap();
        assert!((tau - 2.0).abs() < 1e-12, "{tau}");
    }

    #[test]
    fn a_patch_cut_by_a_periodic_boundary_is_one() {
        // cells (0, 0) and (0, 7) touch across the wrap
        let mut c = PatchCollector::new(&[8], 1, 1, 1.0, Boundary::Periodic);
        c.add_field(0, 0, 0, &field(8, &[0, 7])).unwrap();
        let mut f = PatchCollector::new(&[8], 1, 1, 1.0, Boundary::Free);
        f.add_field(0, 0, 0, &field(8, &[0, 7])).unwrap();
        assert_eq!(c.finish(&[1.0]).0.per_grid[0].patch_count, vec![1.0]);
        assert_eq!(f.finish(&[1.0]).0.per_grid[0].patch_count, vec![2.0]);
    }
}

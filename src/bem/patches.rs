//! Contact-patch statistics of a BEM solution and the tail of its pressure
//! distribution.
//!
//! # What it computes
//! The contact mask (p > 0) on the `N × N` grid of side L is split into
//! connected patches, with 4-neighbour (edge) or 8-neighbour (edge or
//! corner) connectivity; on a periodic grid a patch cut by the boundary is
//! joined across it. For each patch: its area (cells × Δ², Δ = L/N) and its
//! perimeter (cell edges between the patch and non-contact cells × Δ; on a
//! free grid the domain boundary counts as perimeter). Then the number of
//! patches, the largest, and the log-binned distribution of patch areas
//! ```text
//! n(A) = (patches with A_low ≤ A < A_high) / (patch_count · (A_high − A_low))     [1/m²]
//! ```
//! on bins A_low = Δ² 10^{k/b}, b bins per decade (∫ n dA = 1), the
//! quantity Hyun, Pei, Molinari & Robbins (2004) plot.
//!
//! The staircase perimeter of a smooth patch exceeds its true length by
//! 4/π on average over orientations (the grid measures |dx| + |dy|): the
//! raw value is reported, as it converges with N only in that sense.
//!
//! # Pressure tail
//! The pressures p ≥ p_t (p_t = `tail_start`, by default the mean contact
//! pressure) are fitted by maximum likelihood with two one-parameter tails,
//! ```text
//! exponential:  f(p) = e^{−(p − p_t)/λ} / λ,                 λ = ⟨p − p_t⟩
//! Gaussian:     f(p) = φ(p/s) / (s Q(p_t/s)),   s from  ⟨p²⟩/s² − 1 − x φ(x)/Q(x) = 0,  x = p_t/s
//! ```
//! (φ the standard normal density, Q its upper tail), and the one with the
//! larger mean log-likelihood is named: Campañá & Müser (2007) find Gaussian
//! tails for random surfaces, exponential ones for measured topographies.
//!
//! # Method
//! One pass of union–find (path halving) over the cells, joining each
//! contact cell with its earlier neighbours (left, up; up-left and up-right
//! for 8-connectivity), then the wrap-around pairs of the first and last
//! rows and columns on a periodic grid; a second pass resolves roots to
//! dense labels and accumulates area and perimeter. O(N²) time, 4 bytes
//! per cell.
//!
//! # References
//! - S. Hyun, L. Pei, J.-F. Molinari, M. O. Robbins, Phys. Rev. E 70, 026117
//!   (2004), doi:10.1103/PhysRevE.70.026117: patch-size distributions.
//! - C. Campañá, M. H. Müser, EPL 77, 38005 (2007),
//!   doi:10.1209/0295-5075/77/38005: Gaussian against exponential tails.

use super::kernel::Boundary;
use crate::asperity::gaussian::{phi, scaled_tail_moment, Order};
use crate::error::{check, Error, Result};

pub use crate::names::Connectivity;

/// Settings of [`patch_statistics`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchOptions {
    /// Neighbourhood.
    pub connectivity: Connectivity,
    /// Periodic grids join patches across the boundary.
    pub boundary: Boundary,
    /// Log bins per decade of the area distribution (≥ 1).
    pub bins_per_decade: usize,
}

impl Default for PatchOptions {
    fn default() -> Self {
        PatchOptions {
            connectivity: Connectivity::Four,
            boundary: Boundary::Periodic,
            bins_per_decade: 5,
        }
    }
}

/// One contact patch.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Patch {
    /// Number of grid cells.
    pub cells: usize,
    /// Area, m² (cells × Δ²).
    pub area: f64,
    /// Perimeter, m (exposed cell edges × Δ).
    pub perimeter: f64,
}

/// One bin of the patch-area distribution.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct AreaBin {
    /// Lower edge, m².
    pub area_low: f64,
    /// Upper edge, m².
    pub area_high: f64,
    /// Patches in the bin.
    pub count: usize,
    /// count / (patch_count · (area_high − area_low)), 1/m².
    pub density: f64,
}

/// The patches of one contact mask.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct PatchStatistics {
    /// Grid side N.
    pub grid: usize,
    /// Side L, m.
    pub size: f64,
    /// Neighbourhood used.
    pub connectivity: Connectivity,
    /// Boundary used.
    pub boundary: Boundary,
    /// Fraction of cells in contact.
    pub contact_fraction: f64,
    /// Number of patches.
    pub patch_count: usize,
    /// Area of the largest patch, m².
    pub largest_patch_area: f64,
    /// Mean patch area, m².
    pub mean_patch_area: f64,
    /// Sum of the perimeters, m.
    pub total_perimeter: f64,
    /// Log-binned distribution of the patch areas.
    pub area_distribution: Vec<AreaBin>,
    /// Every patch, in the order of its first cell (row-major).
    pub patches: Vec<Patch>,
}

/// The patches of a contact mask (`true` = in contact), `n × n` row-major,
/// side `size` (module docs).
///
/// # Errors
/// [`Error::Inconsistent`] if `contact.len() != n²`; [`Error::InvalidParameter`]
/// naming `grid` (n < 1), `size` (not finite and > 0) or `bins_per_decade` (0).
///
/// # Examples
/// ```
/// use persson::bem::patches::{patch_statistics, PatchOptions};
/// // Two cells touching at a corner: one patch with 8 neighbours, two with 4.
/// let mut m = vec![false; 16];
/// m[5] = true;
/// m[10] = true;
/// let mut o = PatchOptions::default();
/// assert_eq!(patch_statistics(&m, 4, 1.0, &o).unwrap().patch_count, 2);
/// o.connectivity = persson::bem::patches::Connectivity::Eight;
/// assert_eq!(patch_statistics(&m, 4, 1.0, &o).unwrap().patch_count, 1);
/// ```
pub fn patch_statistics(
    contact: &[bool],
    n: usize,
    size: f64,
    options: &PatchOptions,
) -> Result<PatchStatistics> {
    check::positive("size", size)?;
    if n == 0 {
        return Err(Error::invalid("grid", 0.0, ">= 1"));
    }
    if contact.len() != n * n {
        return Err(Error::Inconsistent {
            name: "contact mask".into(),
            requirement: format!("N² = {} cells, got {}", n * n, contact.len()),
        });
    }
    if options.bins_per_decade == 0 {
        return Err(Error::invalid("bins_per_decade", 0.0, ">= 1"));
    }
    let periodic = options.boundary == Boundary::Periodic;
    let eight = options.connectivity == Connectivity::Eight;
    let mut forest = Forest::new(n * n);
    join_interior(contact, n, eight, &mut forest);
    if periodic && n > 1 {
        join_wrap(contact, n, eight, &mut forest);
    }
    let (label, count) = forest.labels(contact);
    let delta = size / n as f64;
    let mut cells = vec![0usize; count];
    let mut edges = vec![0usize; count];
    for i in 0..n {
        for j in 0..n {
            let k = i * n + j;
            if !contact[k] {
                continue;
            }
            let l = label[k] as usize;
            cells[l] += 1;
            edges[l] += exposed_edges(contact, n, i, j, periodic);
        }
    }
    let patches: Vec<Patch> = cells
        .iter()
        .zip(&edges)
        .map(|(&c, &e)| Patch {
            cells: c,
            area: c as f64 * delta * delta,
            perimeter: e as f64 * delta,
        })
        .collect();
    let total_cells: usize = cells.iter().sum();
    let largest = cells.iter().copied().max().unwrap_or(0);
    Ok(PatchStatistics {
        grid: n,
        size,
        connectivity: options.connectivity,
        boundary: options.boundary,
        contact_fraction: total_cells as f64 / (n * n) as f64,
        patch_count: count,
        largest_patch_area: largest as f64 * delta * delta,
        mean_patch_area: if count > 0 {
            total_cells as f64 * delta * delta / count as f64
        } else {
            0.0
        },
        total_perimeter: edges.iter().sum::<usize>() as f64 * delta,
        area_distribution: area_bins(&cells, delta * delta, options.bins_per_decade),
        patches,
    })
}

/// [`patch_statistics`] of the mask p > 0 of a pressure field.
///
/// # Errors
/// As [`patch_statistics`].
pub fn pressure_patches(
    pressure: &[f64],
    n: usize,
    size: f64,
    options: &PatchOptions,
) -> Result<PatchStatistics> {
    let mask: Vec<bool> = pressure.iter().map(|&p| p > 0.0).collect();
    patch_statistics(&mask, n, size, options)
}

/// Union–find with path halving over `u32` parents.
struct Forest {
    parent: Vec<u32>,
}

impl Forest {
    fn new(len: usize) -> Self {
        Forest {
            parent: (0..len as u32).collect(),
        }
    }

    fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let p = self.parent[x as usize];
            self.parent[x as usize] = self.parent[p as usize];
            x = self.parent[x as usize];
        }
        x
    }

    fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a as u32), self.find(b as u32));
        if ra != rb {
            // The smaller index becomes the root: labels follow the first cell.
            let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
            self.parent[hi as usize] = lo;
        }
    }

    /// Dense labels 0 … count−1 in the order of each patch's first cell.
    fn labels(&mut self, contact: &[bool]) -> (Vec<u32>, usize) {
        let mut label = vec![u32::MAX; contact.len()];
        let mut count = 0u32;
        for k in 0..contact.len() {
            if !contact[k] {
                continue;
            }
            let r = self.find(k as u32) as usize;
            if label[r] == u32::MAX {
                label[r] = count;
                count += 1;
            }
            label[k] = label[r];
        }
        (label, count as usize)
    }
}

/// Join each contact cell with its contact neighbours above and to the left
/// (and the upper diagonals for 8-connectivity), inside the grid.
fn join_interior(contact: &[bool], n: usize, eight: bool, f: &mut Forest) {
    for i in 0..n {
        for j in 0..n {
            let k = i * n + j;
            if !contact[k] {
                continue;
            }
            if j > 0 && contact[k - 1] {
                f.union(k, k - 1);
            }
            if i > 0 {
                let up = k - n;
                if contact[up] {
                    f.union(k, up);
                }
                if eight {
                    if j > 0 && contact[up - 1] {
                        f.union(k, up - 1);
                    }
                    if j + 1 < n && contact[up + 1] {
                        f.union(k, up + 1);
                    }
                }
            }
        }
    }
}

/// The wrap-around neighbours of a periodic grid: last row with first row,
/// last column with first column (and the diagonals across them).
fn join_wrap(contact: &[bool], n: usize, eight: bool, f: &mut Forest) {
    let at = |i: usize, j: usize| (i % n) * n + (j % n);
    for t in 0..n {
        // Row n−1 ↔ row 0 at column t (and t ± 1).
        let (a, b) = (at(n - 1, t), at(0, t));
        if contact[a] && contact[b] {
            f.union(a, b);
        }
        // Column n−1 ↔ column 0 at row t.
        let (a, b) = (at(t, n - 1), at(t, 0));
        if contact[a] && contact[b] {
            f.union(a, b);
        }
        if eight {
            for (a, b) in [
                (at(n - 1, t), at(0, t + 1)),
                (at(n - 1, t + 1), at(0, t)),
                (at(t, n - 1), at(t + 1, 0)),
                (at(t + 1, n - 1), at(t, 0)),
            ] {
                if contact[a] && contact[b] {
                    f.union(a, b);
                }
            }
        }
    }
}

/// Edges of cell (i, j) facing a non-contact cell (or the boundary of a free grid).
fn exposed_edges(contact: &[bool], n: usize, i: usize, j: usize, periodic: bool) -> usize {
    let neighbour = |di: isize, dj: isize| -> bool {
        let (a, b) = (i as isize + di, j as isize + dj);
        let inside = a >= 0 && b >= 0 && (a as usize) < n && (b as usize) < n;
        if inside {
            contact[a as usize * n + b as usize]
        } else if periodic {
            let (a, b) = (
                a.rem_euclid(n as isize) as usize,
                b.rem_euclid(n as isize) as usize,
            );
            contact[a * n + b]
        } else {
            false
        }
    };
    [(-1, 0), (1, 0), (0, -1), (0, 1)]
        .iter()
        .filter(|&&(di, dj)| !neighbour(di, dj))
        .count()
}

/// Log bins of the patch areas (cells → m² with `cell_area`).
fn area_bins(cells: &[usize], cell_area: f64, per_decade: usize) -> Vec<AreaBin> {
    let Some(&max) = cells.iter().max() else {
        return Vec::new();
    };
    let b = per_decade as f64;
    let bins = ((max as f64).log10() * b).floor() as usize + 1;
    let edge = |k: usize| 10f64.powf(k as f64 / b);
    let mut count = vec![0usize; bins];
    for &c in cells {
        // Bin k holds edge(k) ≤ c < edge(k+1); guard the rounding of log10.
        let mut k = ((c as f64).log10() * b).floor() as usize;
        while k > 0 && (c as f64) < edge(k) {
            k -= 1;
        }
        while k + 1 < bins && (c as f64) >= edge(k + 1) {
            k += 1;
        }
        count[k.min(bins - 1)] += 1;
    }
    let total = cells.len() as f64;
    (0..bins)
        .map(|k| {
            let (lo, hi) = (edge(k) * cell_area, edge(k + 1) * cell_area);
            AreaBin {
                area_low: lo,
                area_high: hi,
                count: count[k],
                density: count[k] as f64 / (total * (hi - lo)),
            }
        })
        .collect()
}

/// Which tail fits better.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TailShape {
    /// e^{−p/λ}.
    Exponential,
    /// e^{−p²/(2s²)}.
    Gaussian,
}

/// Maximum-likelihood fits of the pressure tail (module docs).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct PressureTail {
    /// p_t: the tail is p ≥ p_t (unit of the pressures).
    pub tail_start: f64,
    /// Pressures in the tail.
    pub samples: usize,
    /// λ of the exponential tail.
    pub exponential_scale: f64,
    /// Mean log-likelihood per sample of the exponential tail.
    pub exponential_log_likelihood: f64,
    /// s of the Gaussian tail.
    pub gaussian_width: f64,
    /// Mean log-likelihood per sample of the Gaussian tail.
    pub gaussian_log_likelihood: f64,
    /// The tail with the larger likelihood.
    pub better: TailShape,
}

/// Fewest pressures a tail fit accepts.
pub const MIN_TAIL_SAMPLES: usize = 10;

/// Fit the tail p ≥ p_t of the contact pressures (p > 0) of `pressure`
/// (module docs). `tail_start` defaults to the mean contact pressure.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `tail_start` when it is not finite and
/// ≥ 0 or leaves fewer than [`MIN_TAIL_SAMPLES`] pressures (or all equal to p_t).
pub fn pressure_tail(pressure: &[f64], tail_start: Option<f64>) -> Result<PressureTail> {
    let contact: Vec<f64> = pressure.iter().copied().filter(|&p| p > 0.0).collect();
    let start = match tail_start {
        Some(t) => check::non_negative("tail_start", t)?,
        None => contact.iter().sum::<f64>() / contact.len().max(1) as f64,
    };
    let tail: Vec<f64> = contact.into_iter().filter(|&p| p >= start).collect();
    let n = tail.len() as f64;
    let excess = tail.iter().map(|p| p - start).sum::<f64>() / n;
    if tail.len() < MIN_TAIL_SAMPLES || excess.is_nan() || excess <= 0.0 {
        return Err(Error::invalid(
            "tail_start",
            start,
            format!(
                "below at least {MIN_TAIL_SAMPLES} distinct contact pressures (it leaves {})",
                tail.len()
            ),
        ));
    }
    let exp_ll = -excess.ln() - 1.0;
    let m2 = tail.iter().map(|p| p * p).sum::<f64>() / n;
    let s = gaussian_width(m2, start);
    // ln f = −p²/(2s²) − ln s − ln √(2π) − ln Q(x); Q = φ(x) R_0(x).
    let x = start / s;
    let ln_q = (phi(x) * scaled_tail_moment(Order::Zero, x)).ln();
    let gauss_ll = -m2 / (2.0 * s * s) - s.ln() - 0.5 * std::f64::consts::TAU.ln() - ln_q;
    Ok(PressureTail {
        tail_start: start,
        samples: tail.len(),
        exponential_scale: excess,
        exponential_log_likelihood: exp_ll,
        gaussian_width: s,
        gaussian_log_likelihood: gauss_ll,
        better: if gauss_ll > exp_ll {
            TailShape::Gaussian
        } else {
            TailShape::Exponential
        },
    })
}

/// The MLE width s of the truncated zero-mean Gaussian: the root of
/// m2/s² − 1 − x/R_0(x) = 0, x = p_t/s (R_0 = Q/φ the Mills ratio; the
/// truncated normal has ⟨p²⟩ = s²(1 + xφ/Q)), by bisection in ln s (the left
/// side falls from +∞, as m2 > p_t², to −1 as s grows).
fn gaussian_width(m2: f64, start: f64) -> f64 {
    let g = |s: f64| {
        let x = start / s;
        m2 / (s * s) - 1.0 - x / scaled_tail_moment(Order::Zero, x)
    };
    // s ≤ √m2 · … : bracket on a log scale around √m2.
    let (mut lo, mut hi) = (m2.sqrt() * 1e-3, m2.sqrt() * 1e3);
    while g(lo) < 0.0 && lo > 1e-300 {
        lo *= 1e-3;
    }
    while g(hi) > 0.0 && hi < 1e300 {
        hi *= 1e3;
    }
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if g(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi / lo - 1.0 < 1e-14 {
            break;
        }
    }
    (lo * hi).sqrt()
}

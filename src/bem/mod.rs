//! FFT boundary-element cross-check (feature `bem`): elastic half-space,
//! Polonsky–Keer solver, Hertz validation, rough surfaces.
//!
//! # Conventions
//! - A square `L × L` domain on an `N × N` grid of nodes `x_i = iL/N`,
//!   fields stored row-major (`f[i·N + j]`). Pressures are nodal values
//!   (collocation), in the unit of the contact modulus E*.
//! - Heights `h` are those of the **rigid rough surface**, pointing towards
//!   the elastic body: its peaks touch first. Lengths are in the unit of L.
//! - The elastic half-space is either periodic (the grid is one period) or
//!   free (an isolated contact; convolution zero-padded to 2N), see
//!   [`kernel`].
//! - `contact_fraction` is the fraction of nodes with p > 0 (A/A0 at this
//!   resolution; areas converge slowly with N, ~N^−0.7 (Campañá & Müser,
//!   EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005): report the grid
//!   with every area).
//!
//! # Pieces
//! - `fft` (internal): planned 2-D real FFT (rustfft + realfft), no allocation per call.
//! - [`kernel`]: the compliance operators 𝒢 (periodic, free) and the stiffness 𝒦.
//! - [`problem`]: the set-up of a solve ([`Problem`]: heights, control,
//!   offset, σ_h) and its knobs ([`Options`], [`Method`]).
//! - [`workspace`]: the operator and the fields every loop works in.
//! - [`solver`]: the solver ([`Solver`]), its stopping rule and the load
//!   path ([`LoadPath`], warm starts).
//! - [`preconditioned`]: the stiffness-preconditioned constrained conjugate
//!   gradient (default); [`polonsky_keer`]: the plain Polonsky–Keer loop
//!   (its fallback); `elastic` (internal) chooses between them.
//! - [`saturated`]: the same with a yield stress, 0 ≤ p ≤ σY.
//! - [`adhesive`]: adhesive contact (Maugis–Dugdale and exponential cohesive
//!   laws) in the gap-based formulation under mean-gap control (periodic) or
//!   approach control (periodic or free); loading–unloading sequences and
//!   their pull-off. It uses the shared [`Operator`] (its stiffness 𝒦; free:
//!   its own padded 2N circulant) but its own buffers: [`Problem`] has no
//!   mean-gap control.
//! - [`hertz`]: closed-form Hertz solution and the η validation; with a
//!   yield stress, the plastic disc per grid ([`hertz::plastic_disc`]).
//! - [`surface`]: Fourier synthesis from any [`crate::Spectrum`], height-map I/O.
//! - [`surrogate`]: random surfaces with a map's spectrum (phase-randomised and IAAFT).
//! - [`resample`]: one surface on several grids (subsampled, low-passed, block-averaged).
//! - [`rough`]: the rough-contact loop (one solve per nominal pressure) and its report.
//! - [`histogram`]: pressure histograms P(σ) that integrate to A/A0.
//! - [`reynolds`], [`stiffness`]: the exact flow through a solved gap (Reynolds' equation) and the exact contact stiffness (conductance by Barber's identity).
//! - [`patches`]: connected contact patches (4/8 neighbours, periodic wrap), their areas,
//!   perimeters and log-binned size distribution; exponential against Gaussian pressure tails.
//! - [`subsurface`]: the stress tensor below the surface (periodic or free half-space),
//!   von Mises and maximum shear, first yield.
//!
//! # Example
//! ```
//! use persson::bem::{hertz, Boundary, Options};
//! # fn main() -> persson::Result<()> {
//! let r = hertz::validate(&hertz::HertzCase::new(64, Boundary::Free), &Options::default())?;
//! assert!(r.energy_error < 1.40e-2); // Molinari's lecture, Table 1 (64²)
//! # Ok(()) }
//! ```

pub mod adhesive;
mod driver;
mod elastic;
pub mod fft;
pub mod hertz;
pub mod histogram;
pub mod kernel;
pub mod patches;
pub mod polonsky_keer;
pub mod preconditioned;
pub mod problem;
pub mod resample;
#[cfg(feature = "flow")]
pub mod reynolds;
pub mod rough;
pub mod saturated;
pub mod solution;
pub mod solver;
mod steps;
pub mod stiffness;
pub mod subsurface;
pub mod surface;
pub mod surrogate;
pub mod workspace;

pub use histogram::{pressure_histogram, saturated_histogram, HistogramBin, SaturatedHistogram};
pub use kernel::{Boundary, Operator};
pub use problem::{Control, Method, Options, Problem};
pub use solution::{Fallback, Iteration, Solution};
pub use solver::{LoadPath, Solver};
pub use surface::GridSurface;
pub use workspace::{Displacement, Fields, Finish, Start, Workspace};

/// The name of [`GridSurface`] in persson 0.3 (kept for one release).
#[deprecated(
    since = "0.4.0",
    note = "renamed GridSurface: a periodic height map on the BEM's N × N grid"
)]
pub type Surface = GridSurface;

use crate::error::{Error, Result};

/// Smallest grid side accepted.
pub const MIN_GRID: usize = 8;

/// Largest grid side accepted before the memory check (keeps N² in range).
pub const MAX_GRID: usize = 1 << 15;

/// Check a grid side: `MIN_GRID ≤ n ≤ MAX_GRID`.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `grid`.
pub fn check_grid(n: usize) -> Result<()> {
    if (MIN_GRID..=MAX_GRID).contains(&n) {
        Ok(())
    } else {
        Err(Error::invalid(
            "grid",
            n as f64,
            format!(
                "between {MIN_GRID} and {MAX_GRID} points a side (of the BEM's N × N grid, \
                 or of a square height map solved on it: {n} × {n} here)"
            ),
        ))
    }
}

/// Bytes a solve on an `n × n` grid needs: the solver's four fields (which
/// move into the returned [`Solution`]), the surface, two transient fields
/// of its synthesis or reading, and the operator's buffers (2.25 N² values
/// periodic: row spectra, multiplier and real-space kernel; 3 N² free: row
/// spectra of the padded grid and multiplier): 9.25 N² values periodic,
/// 10 N² free. Measured peak resident size of `persson bem rough` at 1024²
/// (synthesised surface, tol 1e-10), allocator retention and the binary
/// included: 9.0 N² values periodic, 9.7 N² free.
pub fn required_bytes(n: usize, boundary: Boundary) -> u64 {
    let n2 = (n as u64) * (n as u64);
    // In quarters of N² values.
    let fields = 4 * 7;
    let operator = match boundary {
        Boundary::Periodic => 9,
        Boundary::Free => 12,
    };
    8 * n2 * (fields + operator) / 4
}

/// Check that a solve on an `n × n` grid fits in the memory available now
/// (`MemAvailable` of `/proc/meminfo`; skipped where that is unreadable).
///
/// # Errors
/// [`Error::InvalidParameter`] naming `grid`, with the bytes needed and available.
pub fn check_memory(n: usize, boundary: Boundary) -> Result<()> {
    check_grid(n)?;
    let need = required_bytes(n, boundary);
    if let Some(avail) = available_memory() {
        if need > avail {
            return Err(Error::invalid(
                "grid",
                n as f64,
                format!(
                    "small enough for this machine: a {n}×{n} solve needs {:.1} GiB, {:.1} GiB are available",
                    need as f64 / (1u64 << 30) as f64,
                    avail as f64 / (1u64 << 30) as f64
                ),
            ));
        }
    }
    Ok(())
}

fn available_memory() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

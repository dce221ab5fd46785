//! Measured surfaces: height maps and line scans, their conditioning, power
//! spectrum and statistics (feature `topography`).
//!
//! A [`Topography`] holds heights on a regular grid with its physical size and
//! whether it is periodic. It is read from a file ([`read()`]: `.npy`, text
//! matrix, XYZ triples, Gwyddion `.gsf`, ISO 25178-72 `.x3p`, two-column line
//! scans) or built in memory ([`Topography::map`], [`Topography::line_scans`]).
//! From it [`analyse`] gives, in one call, the isotropic power spectrum C(q) in
//! Persson's normalisation, the reliable band, the rms height, slope and
//! curvature in real space and from the spectrum, and a Hurst fit.
//!
//! # Conventions
//! - Heights are row-major: `heights[iy·nx + ix]`, `ix` along x (the fastest
//!   index, a row of a `.npy` or text matrix, `XRes` of a `.gsf`, `SizeX` of
//!   an `.x3p`), `iy` along y. [`Topography::shape`] is `[ny, nx]` as numpy
//!   writes it.
//! - The physical size is `Lx = nx·Δx`, `Ly = ny·Δy` (pixel size times the
//!   number of points, as SurfaceTopography and Gwyddion count it), for
//!   periodic and non-periodic maps alike.
//! - q is the angular wavevector (1/m) and C(q) is in Persson's normalisation
//!   (crate docs, [`crate::spectrum`]):
//!   ```text
//!   C(q) = Lx·Ly / ((2π)² N²) · |ĥ(q)|²,   ĥ(q) = Σ_x h(x) e^{−i q·x},   N = nx·ny
//!   Σ_q C(q) (2π/Lx)(2π/Ly) = ⟨h²⟩        (Parseval: 2π∫ q C dq = ⟨h²⟩)
//!   ```
//!   SurfaceTopography's 2D spectrum is `(2π)² C`; its 1D spectrum is `2π C_1D`.
//!
//! # Defaults
//! Periodic maps: no detrending, no window. Non-periodic maps (measurements):
//! least-squares plane removed and a radial Hann window (Jacobs, Junge &
//! Pastewka 2017). See [`Conditioning::for_topography`].
//!
//! # References
//! Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002) (normalisation);
//! T. D. B. Jacobs, T. Junge & L. Pastewka, Surf. Topogr.: Metrol. Prop. 5,
//! 013001 (2017), doi:10.1088/2051-672X/aa51f8 (spectra of measured surfaces,
//! windows, reliable band).

mod analysis;
mod anisotropy;
mod condition;
mod fill;
mod fit;
mod multiscale;
mod note;
mod psd;
pub mod read;
mod stats;
mod window;

pub use analysis::{analyse, Analysis, AnalysisOptions, Conditioning};
pub use anisotropy::{anisotropy, spectrum_2d, Anisotropy, Spectrum2dMap, STR_THRESHOLD};
pub use condition::Detrend;
pub use fit::{fit_hurst, fit_hurst_profile, HurstFit};
pub use multiscale::{
    multi_scale, tip_radius_cutoff, Contribution, Gap, Measurement, MultiScale, LOW_MODES,
    TIP_SAFETY_FACTOR,
};
pub use note::Note;
pub use psd::{
    isotropic_spectrum, profile_spectrum, Bins, IsotropicConversion, ProfileSpectrum, Psd,
};
pub use read::{read, LengthUnit, ReadOptions, SizeSpec};
pub use stats::{real_space_stats, RealSpaceStats};
pub use window::Window;

use crate::error::{Error, Result};

/// `(min, max, all finite)` of the heights in one pass, in lanes the
/// compiler can keep in vector registers (a NaN is neither min nor max, as
/// with `f64::min`; it clears `all finite`).
fn span(h: &[f64]) -> (f64, f64, bool) {
    const LANES: usize = 4;
    let (mut lo, mut hi) = ([f64::INFINITY; LANES], [f64::NEG_INFINITY; LANES]);
    let mut finite = [true; LANES];
    let mut chunks = h.chunks_exact(LANES);
    for c in &mut chunks {
        for l in 0..LANES {
            let v = c[l];
            lo[l] = if v < lo[l] { v } else { lo[l] };
            hi[l] = if v > hi[l] { v } else { hi[l] };
            finite[l] &= v.abs() < f64::INFINITY;
        }
    }
    for &v in chunks.remainder() {
        lo[0] = if v < lo[0] { v } else { lo[0] };
        hi[0] = if v > hi[0] { v } else { hi[0] };
        finite[0] &= v.abs() < f64::INFINITY;
    }
    (
        lo.iter().fold(f64::INFINITY, |a, &b| a.min(b)),
        hi.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b)),
        finite.iter().all(|&f| f),
    )
}

/// How the heights are laid out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Layout {
    /// A 2D height map `ny × nx`.
    Map,
    /// `ny` independent line scans (profiles along x) of `nx` points each.
    LineScans,
}

/// A measured (or synthesised) surface: heights on a regular grid.
///
/// Heights are in m (or any one length unit, the same as the sizes), finite
/// and not all equal.
#[derive(Debug, Clone, PartialEq)]
pub struct Topography {
    nx: usize,
    ny: usize,
    lx: f64,
    ly: f64,
    periodic: bool,
    layout: Layout,
    heights: Vec<f64>,
    notes: Vec<Note>,
}

impl Topography {
    /// A 2D height map of `ny` rows and `nx` columns, row-major, with physical
    /// sizes `lx = nx·Δx` and `ly = ny·Δy`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a size that is not finite and > 0 or a
    /// non-finite height (named `height[iy, ix]`); [`Error::Inconsistent`]
    /// for fewer than 2 points along an axis, a wrong number of heights, or
    /// all heights equal.
    ///
    /// # Examples
    /// ```
    /// use persson::topography::Topography;
    /// # fn main() -> persson::Result<()> {
    /// let t = Topography::map(3, 2, 3e-6, 2e-6, vec![0.0, 1e-9, 2e-9, 1e-9, 0.0, 3e-9], false)?;
    /// assert_eq!(t.shape(), [2, 3]);
    /// assert_eq!(t.pixel_size(), vec![1e-6, 1e-6]);
    /// # Ok(()) }
    /// ```
    pub fn map(
        nx: usize,
        ny: usize,
        lx: f64,
        ly: f64,
        heights: Vec<f64>,
        periodic: bool,
    ) -> Result<Self> {
        let t = Topography {
            nx,
            ny,
            lx,
            ly,
            periodic,
            layout: Layout::Map,
            heights,
            notes: Vec::new(),
        };
        t.validate()?;
        Ok(t)
    }

    /// `ny` line scans of `nx` points each along x, row-major, each of length
    /// `lx = nx·Δx`.
    ///
    /// # Errors
    /// As [`Topography::map`] (one profile is enough).
    pub fn line_scans(
        nx: usize,
        ny: usize,
        lx: f64,
        heights: Vec<f64>,
        periodic: bool,
    ) -> Result<Self> {
        let t = Topography {
            nx,
            ny,
            lx,
            ly: 0.0,
            periodic,
            layout: Layout::LineScans,
            heights,
            notes: Vec::new(),
        };
        t.validate()?;
        Ok(t)
    }

    fn validate(&self) -> Result<()> {
        crate::error::check::positive("size", self.lx)?;
        let min_rows = match self.layout {
            Layout::Map => {
                crate::error::check::positive("size", self.ly)?;
                2
            }
            Layout::LineScans => 1,
        };
        if self.nx < 2 || self.ny < min_rows {
            return Err(Error::Inconsistent {
                name: "shape".into(),
                requirement: format!(
                    "at least 2 points along x{}, got {} row(s) of {} point(s)",
                    if min_rows == 2 { " and y" } else { "" },
                    self.ny,
                    self.nx
                ),
            });
        }
        if self.heights.len() != self.nx * self.ny {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!(
                    "{} × {} = {} values, got {}",
                    self.ny,
                    self.nx,
                    self.nx * self.ny,
                    self.heights.len()
                ),
            });
        }
        // One pass for the three checks: finite, not all equal, the span.
        let (lo, hi, finite) = span(&self.heights);
        if !finite {
            let k = self
                .heights
                .iter()
                .position(|h| !h.is_finite())
                .unwrap_or(0);
            return Err(Error::invalid(
                format!("height[{}, {}]", k / self.nx, k % self.nx),
                self.heights[k],
                "finite",
            ));
        }
        let h0 = self.heights[0];
        if lo == hi {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!(
                    "every height is {}: a flat surface has no spectrum (it needs heights \
                     not all equal)",
                    crate::error::num(h0)
                ),
            });
        }
        self.check_scales(lo, hi)
    }

    /// Refuse heights (or a pixel size) whose statistics overflow: heights
    /// of 1e290 m gave every moment and C(q) as ∞ with exit 0.
    ///
    /// # Bound
    /// With s the span max h − min h, d the smaller pixel size and n the
    /// number of points, the analysis sums n squares of the heights (≤ s),
    /// of forward differences over d (≤ s/d), of 5-point Laplacians
    /// (≤ 4s/d²), and the spectrum's |ĥ|² ≤ n²s² weighted by up to |q|⁴ ≤
    /// (π√2/d)⁴ over n modes. All stay finite when each of s, s/d and 4s/d²
    /// is at most B = √(f64::MAX/n)/(8n) (the factor n for the spectrum's
    /// sum, 8 for the stencils' and π√2's constants), decided on
    /// logarithms. The heights are named unless the pixel size is the
    /// further from 1 in order of magnitude of the two. `lo`, `hi`: the
    /// smallest and largest height.
    fn check_scales(&self, lo: f64, hi: f64) -> Result<()> {
        let ln_span = (0.5 * hi - 0.5 * lo).ln() + std::f64::consts::LN_2;
        let d = match self.layout {
            Layout::Map => self.dx().min(self.dy()),
            Layout::LineScans => self.dx(),
        };
        let n = (self.nx * self.ny) as f64;
        let ln_b = 0.5 * (f64::MAX.ln() - n.ln()) - (8.0 * n).ln();
        let ln_d = d.ln();
        let worst = ln_span
            .max(ln_span - ln_d)
            .max(4f64.ln() + ln_span - 2.0 * ln_d);
        if worst <= ln_b {
            return Ok(());
        }
        let approx = crate::error::approx;
        if ln_span.abs() >= ln_d.abs() {
            // the largest span the pixel size d leaves
            let span = (ln_b - 0f64.max(-ln_d).max(4f64.ln() - 2.0 * ln_d)).exp();
            Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!(
                    "heights spanning at most {} (pixel size {}, {} points) so that their \
                     squares, slopes and curvatures summed over the map stay finite; these \
                     span {}",
                    approx(span),
                    crate::error::num(d),
                    self.nx * self.ny,
                    approx(ln_span.exp())
                ),
            })
        } else {
            // the smallest pixel size the span leaves: s/d ≤ B and 4s/d² ≤ B
            let d_min = (ln_span - ln_b)
                .exp()
                .max((0.5 * (4f64.ln() + ln_span - ln_b)).exp());
            Err(Error::invalid(
                "pixel_size",
                d,
                format!(
                    "at least {} (heights spanning {}, {} points) so that the slopes and \
                     curvatures summed over the map stay finite",
                    approx(d_min),
                    approx(ln_span.exp()),
                    self.nx * self.ny
                ),
            ))
        }
    }

    /// Points along x (per row or profile).
    pub fn nx(&self) -> usize {
        self.nx
    }

    /// Rows (maps) or profiles (line scans).
    pub fn ny(&self) -> usize {
        self.ny
    }

    /// `[ny, nx]`, numpy's order.
    pub fn shape(&self) -> [usize; 2] {
        [self.ny, self.nx]
    }

    /// Physical size along x, `Lx = nx·Δx`, m.
    pub fn lx(&self) -> f64 {
        self.lx
    }

    /// Physical size along y, `Ly = ny·Δy`, m (0 for line scans).
    pub fn ly(&self) -> f64 {
        self.ly
    }

    /// Pixel sizes `[Δx, Δy]` (maps) or `[Δx]` (line scans), m.
    pub fn pixel_size(&self) -> Vec<f64> {
        match self.layout {
            Layout::Map => vec![self.dx(), self.dy()],
            Layout::LineScans => vec![self.dx()],
        }
    }

    pub(crate) fn dx(&self) -> f64 {
        self.lx / self.nx as f64
    }

    pub(crate) fn dy(&self) -> f64 {
        self.ly / self.ny as f64
    }

    /// Whether the surface repeats itself with period (Lx, Ly).
    pub fn periodic(&self) -> bool {
        self.periodic
    }

    /// Map or line scans.
    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// The heights, row-major `ny × nx`.
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// The heights with the least-squares trend `detrend` removed, row-major
    /// `ny × nx` (the heights the spectrum and the statistics of [`analyse`]
    /// use; a line per profile for line scans).
    pub fn detrended(&self, detrend: Detrend) -> Vec<f64> {
        condition::detrended(self, detrend)
    }

    /// The same surface with another periodicity flag.
    pub fn with_periodic(mut self, periodic: bool) -> Self {
        self.periodic = periodic;
        self
    }

    /// What the reader did to the data that the user should know of
    /// (empty for a surface built in memory).
    pub fn notes(&self) -> &[Note] {
        &self.notes
    }

    /// The same surface with these notes.
    pub(crate) fn with_notes(mut self, notes: Vec<Note>) -> Self {
        self.notes = notes;
        self
    }

    /// A map with its axes swapped: `nx' = ny`, `Lx' = Ly`, and height
    /// `(ix, iy)` of the result is height `(iy, ix)` of `self` (line scans
    /// are returned as they are).
    pub(crate) fn transposed(&self) -> Self {
        if self.layout != Layout::Map {
            return self.clone();
        }
        let m = crate::io::Matrix {
            rows: self.ny,
            cols: self.nx,
            values: self.heights.clone(),
        }
        .transposed();
        Topography {
            nx: self.ny,
            ny: self.nx,
            lx: self.ly,
            ly: self.lx,
            heights: m.values,
            ..self.clone()
        }
    }

    /// The reliable band `[q_min, q_max]` of the spectrum, 1/m:
    /// `q_min = 2π/min(Lx, Ly)` (the longest wavelength present in every
    /// direction) and `q_max = π/max(Δx, Δy)` (the Nyquist wavevector of the
    /// coarser axis). For line scans `2π/Lx … π/Δx`.
    pub fn band(&self) -> (f64, f64) {
        use std::f64::consts::{PI, TAU};
        match self.layout {
            Layout::Map => (TAU / self.lx.min(self.ly), PI / self.dx().max(self.dy())),
            Layout::LineScans => (TAU / self.lx, PI / self.dx()),
        }
    }
}

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

mod condition;
mod fill;
mod fit;
mod psd;
pub mod read;
mod stats;
mod window;

pub use condition::Detrend;
pub use fit::{fit_hurst, HurstFit};
pub use psd::{isotropic_spectrum, profile_spectrum, Bins, ProfileSpectrum, Psd};
pub use read::{read, ReadOptions, SizeSpec};
pub use stats::{real_space_stats, RealSpaceStats};
pub use window::Window;

use crate::error::{Error, Result};

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
        if let Some(k) = self.heights.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid(
                format!("height[{}, {}]", k / self.nx, k % self.nx),
                self.heights[k],
                "finite",
            ));
        }
        let h0 = self.heights[0];
        if self.heights.iter().all(|&h| h == h0) {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!(
                    "not all equal (every height is {h0}: a flat surface has no spectrum)"
                ),
            });
        }
        Ok(())
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

    /// The same surface with another periodicity flag.
    pub fn with_periodic(mut self, periodic: bool) -> Self {
        self.periodic = periodic;
        self
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

/// Conditioning of the heights before the spectrum: detrending and window.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct Conditioning {
    /// The least-squares trend removed.
    pub detrend: Detrend,
    /// The window applied (power normalised).
    pub window: Window,
}

impl Conditioning {
    /// The defaults: periodic surfaces are taken as they are (no detrending,
    /// no window); measured, non-periodic ones get the least-squares plane
    /// removed and a Hann window.
    pub fn for_topography(t: &Topography) -> Self {
        if t.periodic() {
            Conditioning {
                detrend: Detrend::None,
                window: Window::None,
            }
        } else {
            Conditioning {
                detrend: Detrend::Plane,
                window: Window::Hann,
            }
        }
    }
}

/// Options of [`analyse`]; `None` fields take the defaults.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct AnalysisOptions {
    /// Detrending; default from [`Conditioning::for_topography`].
    pub detrend: Option<Detrend>,
    /// Window; default from [`Conditioning::for_topography`].
    pub window: Option<Window>,
    /// Upper end of the band, 1/m; default the Nyquist wavevector.
    pub q_max: Option<f64>,
    /// Bins of the radial average; default [`Bins::default`].
    pub bins: Option<Bins>,
}

/// Everything [`analyse`] finds about a topography; serialises with the keys
/// of the names table (`shape`, `pixel_size`, `rms_height`, …, `psd`).
#[derive(Debug, Clone, serde::Serialize)]
#[non_exhaustive]
pub struct Analysis {
    /// `[ny, nx]`.
    pub shape: [usize; 2],
    /// `[Δx, Δy]` or `[Δx]`, m.
    pub pixel_size: Vec<f64>,
    /// Whether the surface was taken as periodic.
    pub periodic: bool,
    /// Map or line scans.
    pub layout: Layout,
    /// The conditioning applied.
    pub detrend: Detrend,
    /// The window applied.
    pub window: Window,
    /// rms height of the detrended heights (real space), m.
    pub rms_height: f64,
    /// rms slope (real space, forward differences; 2D-equivalent √2·h'_x for
    /// line scans), dimensionless.
    pub rms_slope: f64,
    /// rms Laplacian (real space, 5-point; 2D-equivalent √(8/3)·h''_x for line
    /// scans), 1/m.
    pub rms_curvature: f64,
    /// The same three from the spectrum: exact sums over the Fourier modes
    /// inside the bins, `sqrt(Σ_q |q|^{k} C(q) Δq_x Δq_y)` (k = 0, 2, 4), the
    /// discrete form of `sqrt(2π ∫ q^{k+1} C dq)` ([`Psd`]).
    pub rms_height_from_spectrum: f64,
    /// See `rms_height_from_spectrum`.
    pub rms_slope_from_spectrum: f64,
    /// See `rms_height_from_spectrum`.
    pub rms_curvature_from_spectrum: f64,
    /// Hurst exponent fitted over the band.
    pub hurst: f64,
    /// Its standard error.
    pub hurst_error: f64,
    /// Lower end of the reliable band, 1/m.
    pub q_min: f64,
    /// Upper end of the reliable band, 1/m.
    pub q_max: f64,
    /// The binned isotropic spectrum (Persson's normalisation).
    pub psd: Psd,
    /// The Hurst fit (its prefactor draws the fit line; `hurst` and
    /// `hurst_error` above are its H and standard error).
    #[serde(skip)]
    pub fit: HurstFit,
}

/// Condition the topography, compute its isotropic spectrum (for line scans:
/// the averaged 1D spectrum converted with [`crate::spectrum::Convention::Profile1D`]),
/// its real-space and spectral statistics and a Hurst fit over the band.
///
/// # Errors
/// An empty band (`q_max` below `q_min`), fewer than 3 bins for the fit, a
/// 1D spectrum that is not decaying (line scans; see the conversion).
///
/// # Examples
/// ```
/// use persson::topography::{analyse, AnalysisOptions, Topography};
/// # fn main() -> persson::Result<()> {
/// // A periodic 32 × 32 map of one cosine with a 4-pixel wavelength, h = a cos(2π x/λ).
/// let (n, size, a) = (32, 1e-5, 1e-8);
/// let h = (0..n * n).map(|k| a * (std::f64::consts::TAU * (k % n) as f64 / 4.0).cos()).collect();
/// let t = Topography::map(n, n, size, size, h, true)?;
/// let r = analyse(&t, &AnalysisOptions::default())?;
/// // ⟨h²⟩ = a²/2 in real space and from the spectrum (Parseval).
/// assert!((r.rms_height - a / 2f64.sqrt()).abs() < 1e-12 * a);
/// assert!((r.rms_height_from_spectrum - r.rms_height).abs() < 1e-12 * a);
/// # Ok(()) }
/// ```
pub fn analyse(t: &Topography, options: &AnalysisOptions) -> Result<Analysis> {
    let defaults = Conditioning::for_topography(t);
    let conditioning = Conditioning {
        detrend: options.detrend.unwrap_or(defaults.detrend),
        window: options.window.unwrap_or(defaults.window),
    };
    let bins = options.bins.clone().unwrap_or_default();
    let psd = match t.layout() {
        Layout::Map => isotropic_spectrum(t, conditioning, &bins, options.q_max)?,
        Layout::LineScans => {
            profile_spectrum(t, conditioning, &bins, options.q_max)?.to_isotropic()?
        }
    };
    let real = real_space_stats(t, conditioning.detrend)?;
    let fit = fit_hurst(&psd, psd.q_min, psd.q_max)?;
    Ok(Analysis {
        shape: t.shape(),
        pixel_size: t.pixel_size(),
        periodic: t.periodic(),
        layout: t.layout(),
        detrend: conditioning.detrend,
        window: conditioning.window,
        rms_height: real.rms_height,
        rms_slope: real.rms_slope,
        rms_curvature: real.rms_curvature,
        rms_height_from_spectrum: psd.rms_height,
        rms_slope_from_spectrum: psd.rms_slope,
        rms_curvature_from_spectrum: psd.rms_curvature,
        hurst: fit.hurst,
        hurst_error: fit.hurst_error,
        q_min: psd.q_min,
        q_max: psd.q_max,
        psd,
        fit,
    })
}

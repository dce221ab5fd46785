//! [`analyse`]: conditioning, spectrum, real-space and spectral statistics
//! and a Hurst fit of a topography, in one call.
//!
//! For line scans the averaged 1D spectrum and the statistics along the
//! profiles are reported as they are (`psd_profile`, `rms_slope_profile`,
//! `rms_curvature_profile`), beside their 2D counterparts for an isotropic
//! surface; bins of the 1D spectrum that have no 2D counterpart are left out
//! of the 2D spectrum with a [`Note::BinsLeftOut`], and nothing aborts the
//! statistics. A Hurst fit that fails or falls outside (0, 1) is `None`
//! with a [`Note`].

use super::{
    fit_hurst, fit_hurst_profile, profile_spectrum, real_space_stats, Bins, Detrend, HurstFit,
    Layout, Note, ProfileSpectrum, Psd, Topography, Window,
};
use crate::error::Result;

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
    /// scans), 1/m; `None` (JSON `null`) when the map has no point with the
    /// stencil's neighbours, with [`Note::CurvatureNotComputed`].
    pub rms_curvature: Option<f64>,
    /// Half of `rms_curvature`: the rms mean curvature `∇²h/2`, 1/m. This is
    /// the number SurfaceTopography and contact.engineering call
    /// `rms_curvature` (`rms_curvature_from_area`); persson's
    /// `rms_curvature` is Persson's `√⟨(∇²h)²⟩`, twice it. (For line scans
    /// contact.engineering's rms curvature is `rms_curvature_profile`.)
    ///
    /// # Formula
    /// ```text
    /// mean_curvature_rms = ½ √⟨(∇²h)²⟩ = rms_curvature / 2
    /// ```
    /// `None` with `rms_curvature`.
    pub mean_curvature_rms: Option<f64>,
    /// Line scans: rms slope along the profiles `h'_x` (real space, forward
    /// differences), dimensionless; `None` for maps.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rms_slope_profile: Option<f64>,
    /// Line scans: rms second derivative along the profiles `h''_x` (real
    /// space, 3-point), 1/m; `None` for maps.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rms_curvature_profile: Option<f64>,
    /// The same three from the spectrum: exact sums over the Fourier modes
    /// inside the bins, `sqrt(Σ_q |q|^{k} C(q) Δq_x Δq_y)` (k = 0, 2, 4), the
    /// discrete form of `sqrt(2π ∫ q^{k+1} C dq)` ([`Psd`]).
    pub rms_height_from_spectrum: f64,
    /// See `rms_height_from_spectrum`.
    pub rms_slope_from_spectrum: f64,
    /// See `rms_height_from_spectrum`.
    pub rms_curvature_from_spectrum: f64,
    /// Hurst exponent fitted over the band (for line scans from the 1D
    /// spectrum, `C_1D ∝ q^{−(2H+1)}`); `None` (JSON `null`) when the fit
    /// fails or gives H outside (0, 1), with a [`Note`] saying why.
    pub hurst: Option<f64>,
    /// Its standard error (`None` with `hurst`).
    pub hurst_error: Option<f64>,
    /// Lower end of the reliable band, 1/m.
    pub q_min: f64,
    /// Upper end of the reliable band, 1/m.
    pub q_max: f64,
    /// The binned isotropic spectrum (Persson's normalisation).
    pub psd: Psd,
    /// Line scans: the averaged 1D spectrum (Persson's 1D normalisation) and
    /// its rms values along the profiles; `None` for maps.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub psd_profile: Option<ProfileSpectrum>,
    /// The Hurst fit (its prefactor draws the fit line; `hurst` and
    /// `hurst_error` above are its H and standard error).
    #[serde(skip)]
    pub fit: Option<HurstFit>,
    /// What the reader did and what the analysis could not do (the
    /// application shows them as warnings).
    #[serde(skip)]
    pub notes: Vec<Note>,
}

/// Condition the topography, compute its isotropic spectrum (for line scans:
/// the averaged 1D spectrum converted with [`crate::spectrum::Convention::Profile1D`],
/// bins without a 2D counterpart left out), its real-space and spectral
/// statistics and a Hurst fit over the band (module docs).
///
/// # Errors
/// An empty band (`q_max` below `q_min`), bad bins, no Fourier mode in any
/// bin. A failed Hurst fit is not an error ([`Note::HurstNotFitted`]).
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
/// // One mode is one bin: no Hurst exponent, and a note says why.
/// assert!(r.hurst.is_none() && !r.notes.is_empty());
/// # Ok(()) }
/// ```
pub fn analyse(t: &Topography, options: &AnalysisOptions) -> Result<Analysis> {
    let defaults = Conditioning::for_topography(t);
    let conditioning = Conditioning {
        detrend: options.detrend.unwrap_or(defaults.detrend),
        window: options.window.unwrap_or(defaults.window),
    };
    let bins = options.bins.clone().unwrap_or_default();
    let mut notes = t.notes().to_vec();
    let (psd, profile, real) = match t.layout() {
        Layout::Map => {
            // The trend is fitted once, and the statistics are taken from
            // the spectrum's detrended rows as they are made (one pass).
            let trend = super::condition::map_trend(t, conditioning.detrend);
            let mut rows = super::stats::MapRows::new(t, trend.as_ref());
            let psd = super::psd::map_spectrum(
                t,
                trend.as_ref(),
                conditioning.window,
                &bins,
                options.q_max,
                Some(&mut rows),
            )?;
            (psd, None, rows.finish())
        }
        Layout::LineScans => {
            let p = profile_spectrum(t, conditioning, &bins, options.q_max)?;
            let c = p.to_isotropic()?;
            if !c.left_out.is_empty() {
                notes.push(Note::BinsLeftOut {
                    q: c.left_out,
                    of: p.q.len(),
                });
            }
            let real = real_space_stats(t, conditioning.detrend)?;
            (c.psd, Some(p), real)
        }
    };
    if real.rms_curvature.is_none() {
        notes.push(Note::CurvatureNotComputed {
            shape: t.shape(),
            periodic: t.periodic(),
        });
    }
    let fit = hurst(&psd, profile.as_ref(), &mut notes);
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
        mean_curvature_rms: real.rms_curvature.map(|c| c / 2.0),
        rms_slope_profile: real.rms_slope_profile,
        rms_curvature_profile: real.rms_curvature_profile,
        rms_height_from_spectrum: psd.rms_height,
        rms_slope_from_spectrum: psd.rms_slope,
        rms_curvature_from_spectrum: psd.rms_curvature,
        hurst: fit.map(|f| f.hurst),
        hurst_error: fit.map(|f| f.hurst_error),
        q_min: psd.q_min,
        q_max: psd.q_max,
        psd,
        psd_profile: profile,
        fit,
        notes,
    })
}

/// The Hurst fit over the band (line scans: of the 1D spectrum), `None`
/// with a note when it fails or falls outside (0, 1).
fn hurst(psd: &Psd, profile: Option<&ProfileSpectrum>, notes: &mut Vec<Note>) -> Option<HurstFit> {
    let (q_lo, q_hi) = (psd.q_min, psd.q_max);
    let fit = match profile {
        Some(p) => fit_hurst_profile(p, q_lo, q_hi),
        None => fit_hurst(psd, q_lo, q_hi),
    };
    match fit {
        Ok(f) if f.hurst > 0.0 && f.hurst < 1.0 => Some(f),
        Ok(f) => {
            notes.push(Note::HurstOutOfRange {
                hurst: f.hurst,
                hurst_error: f.hurst_error,
            });
            None
        }
        Err(_) => {
            let (q, c) = match profile {
                Some(p) => (&p.q, &p.c_1d),
                None => (&psd.q, &psd.c),
            };
            let bins = super::fit::in_band(q, c, q_lo, q_hi);
            notes.push(Note::HurstNotFitted { bins });
            None
        }
    }
}

//! Spectral moments m0, m2, m4 of a profile, Nayak's bandwidth parameter α
//! and the summit statistics of an isotropic Gaussian surface.
//!
//! # Formula
//! The moments are those of a straight profile through the surface (Nayak
//! 1971, Longuet-Higgins 1957): m0 = ⟨h²⟩, m2 = ⟨(∂h/∂x)²⟩, m4 = ⟨(∂²h/∂x²)²⟩.
//! For an isotropic surface with the 2-D spectrum C(q) in Persson's
//! normalisation (⟨h²⟩ = ∫d²q C = 2π∫qC dq), q_x = q cos θ gives
//! ```text
//! m0 = ∫d²q C(q)       = 2π   ∫ q  C(q) dq = ⟨h²⟩
//! m2 = ∫d²q q_x² C(q)  = π    ∫ q³ C(q) dq = ⟨|∇h|²⟩ / 2
//! m4 = ∫d²q q_x⁴ C(q)  = 3π/4 ∫ q⁵ C(q) dq = (3/8) ⟨(∇²h)²⟩
//! α  = m0 m4 / m2²  ≥ 3/2                        (Cauchy–Schwarz; = 3/2 for a ring spectrum)
//! ```
//! (∫_0^{2π} cos²θ dθ = π, ∫_0^{2π} cos⁴θ dθ = 3π/4.) In the crate's names:
//! m0 = h_rms², m2 = h'_rms²/2, m4 = 3h''_rms²/8.
//!
//! Summits (local maxima) of an isotropic Gaussian surface, exact for every α
//! (Kac–Rice count over the joint density of height, gradient and Hessian):
//! ```text
//! summit density           η   = m4 / (6π√3 m2)                       [1/m²]  (Nayak 1971)
//! mean summit curvature    κ̄   = (8/3) √(m4/π),  radius β = 1/κ̄        [1/m]   (Nayak 1971; McCool 1986: β = 0.375 √(π/m4))
//! mean summit height       y_s = 4 √(m0/(π α))                        [m]     (McCool 1986)
//! summit height variance   σ_s² = m0 [1 − (1 + 16/π − 3√3)/α]          [m²]    (McCool 1986: 1 − 0.8968/α)
//! ```
//! The constant 1 + 16/π − 3√3 = 0.896 805 756… is McCool's 0.8968 to all
//! digits; its closed form follows from ⟨ξ²⟩_summits = 1 + (3√3 − 1)/α, and all
//! four lines are checked against a direct mpmath quadrature of the summit
//! density (tests/reference/asperity_reference.py, tests/asperity.rs).
//!
//! # References
//! - P. R. Nayak, J. Lubr. Technol. 93, 398 (1971), doi:10.1115/1.3451608:
//!   the random-process model of an isotropic surface, summit density and
//!   curvature.
//! - J. I. McCool, Wear 107, 37 (1986), doi:10.1016/0043-1648(86)90045-1:
//!   GW parameters from m0, m2, m4 (summit height mean and variance).
//! - M. S. Longuet-Higgins, Phil. Trans. R. Soc. A 250, 157 (1957): the profile
//!   moments of an isotropic random surface.

use super::Validity;
use crate::error::{Error, Result};
use crate::spectrum::Spectrum;

/// 1 + 16/π − 3√3, the α-coefficient of the summit height variance (McCool's 0.8968).
const SUMMIT_VARIANCE_COEFFICIENT: f64 = 1.0 + 16.0 / std::f64::consts::PI - 3.0 * SQRT_3;

const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// Smallest bandwidth parameter of an isotropic surface (a ring spectrum).
const MIN_BANDWIDTH_PARAMETER: f64 = 1.5;

/// Rounding allowance when checking α ≥ 3/2 (moments from sums or quadrature).
const BANDWIDTH_ROUNDING: f64 = 1e-9;

/// Below this α the summit picture of the asperity theories is poor and a
/// [`Validity::SmallBandwidth`] flag is raised (a convention of this crate: at
/// α = 10 the summits' mean height is already 0.71 h_rms and their height
/// variance 0.91 m0, so the summit heights are far from the surface heights
/// and Nayak's summit-height density is visibly skewed).
pub const SMALL_BANDWIDTH: f64 = 10.0;

/// Below this ratio m4(2Δ)/m4(Δ) a map's fourth moment is taken as
/// unresolved (a convention: halving the resolution changes m4 by more than 2×).
pub const CURVATURE_RESOLUTION_RATIO: f64 = 0.5;

/// The profile moments m0, m2, m4 of an isotropic surface.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SpectralMoments {
    /// m0 = ⟨h²⟩, m².
    pub m0: f64,
    /// m2 = ⟨(∂h/∂x)²⟩ = h'_rms²/2, dimensionless.
    pub m2: f64,
    /// m4 = ⟨(∂²h/∂x²)²⟩ = 3h''_rms²/8, 1/m².
    pub m4: f64,
}

/// Summit statistics of an isotropic Gaussian surface (module docs).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SummitStatistics {
    /// Nayak's bandwidth parameter α = m0 m4/m2².
    pub bandwidth_parameter: f64,
    /// Number of summits per unit area η, 1/m².
    pub summit_density: f64,
    /// Mean summit curvature κ̄ (mean of the two principal curvatures), 1/m.
    pub summit_curvature: f64,
    /// Mean summit radius β = 1/κ̄, m.
    pub summit_radius: f64,
    /// Mean height of the summits above the mean plane of the surface, m.
    pub summit_mean_height: f64,
    /// Standard deviation of the summit heights, m.
    pub summit_rms_height: f64,
}

/// A map's moments with the check of its resolution.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct MapMoments {
    /// The moments (average of the x and y profiles).
    pub moments: SpectralMoments,
    /// m4 from second differences over 2Δ over m4 over Δ (`None` when the map
    /// has fewer than 5 points along an axis).
    pub curvature_resolution_ratio: Option<f64>,
    /// [`Validity::CurvatureUnresolved`] when the ratio is below
    /// [`CURVATURE_RESOLUTION_RATIO`].
    pub validity: Vec<Validity>,
}

impl SpectralMoments {
    /// Moments given directly.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `m0`, `m2` or `m4` unless finite
    /// and positive; naming `bandwidth_parameter` when α = m0 m4/m2² < 3/2,
    /// which no isotropic surface has.
    ///
    /// # Examples
    /// ```
    /// use persson::asperity::SpectralMoments;
    /// let m = SpectralMoments::new(1e-12, 1e-2, 1e9).unwrap();
    /// assert!((m.bandwidth_parameter() - 10.0).abs() < 1e-13); // α = 1e-12·1e9/1e-4
    /// assert!(SpectralMoments::new(1.0, 1.0, 1.0).is_err()); // α = 1 < 3/2
    /// ```
    pub fn new(m0: f64, m2: f64, m4: f64) -> Result<Self> {
        for (name, v) in [("m0", m0), ("m2", m2), ("m4", m4)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::invalid(name, v, "finite and > 0"));
            }
        }
        let m = SpectralMoments { m0, m2, m4 };
        let alpha = m.bandwidth_parameter();
        if alpha.is_nan() || alpha < MIN_BANDWIDTH_PARAMETER * (1.0 - BANDWIDTH_ROUNDING) {
            return Err(Error::invalid(
                "bandwidth_parameter",
                alpha,
                ">= 1.5 (m0 m4/m2² of an isotropic surface; 1.5 for a ring spectrum)",
            ));
        }
        Ok(m)
    }

    /// The moments of an isotropic spectrum in Persson's normalisation over
    /// its band `[q_min, q_max]` (module docs).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming the moment (`m0`, `m2` or `m4`)
    /// that is not finite: an infinite `q_max` or a moment integral that
    /// diverges or does not converge (for a self-affine tail C ∝ q^{−2(H+1)}
    /// with H < 2, m4 needs a finite upper cut-off q_s).
    ///
    /// # Examples
    /// ```
    /// use persson::asperity::SpectralMoments;
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// let s = SelfAffine::new(1e4, 1e4, 1e6, 0.8, Amplitude::RmsSlope(0.2)).unwrap();
    /// let m = SpectralMoments::from_spectrum(&s).unwrap();
    /// assert!((m.m2 - 0.02).abs() < 1e-15); // h'_rms²/2
    /// ```
    pub fn from_spectrum(spectrum: &dyn Spectrum) -> Result<Self> {
        let (a, b) = (spectrum.q_min(), spectrum.q_max());
        let pi = std::f64::consts::PI;
        let m0 = 2.0 * pi * moment(spectrum, 1, a, b, "m0")?;
        let m2 = pi * moment(spectrum, 3, a, b, "m2")?;
        let m4 = 0.75 * pi * moment(spectrum, 5, a, b, "m4")?;
        SpectralMoments::new(m0, m2, m4)
    }

    /// The moments of a measured (or synthesised) height map of `nx × ny`
    /// points, row-major `heights[j·nx + i]`, pixel sizes `dx`, `dy` (m),
    /// from finite differences along x and along y, averaged (an isotropic
    /// surface has the same profile moments in every direction):
    /// ```text
    /// m0 = ⟨(h − h̄)²⟩,   m2 = ⟨(D⁺h)²⟩,  D⁺h = (h_{i+1} − h_i)/Δ
    /// m4 = ⟨(D²h)²⟩,      D²h = (h_{i+1} − 2h_i + h_{i−1})/Δ²
    /// ```
    /// over the points where the stencil exists (all points, wrapping around,
    /// when `periodic`): the stencils of `topography::real_space_stats`,
    /// whose h'_rms² = 2 m2 here. The resolution check compares m4 with the
    /// same stencil over 2Δ. Finite-difference moments need not satisfy
    /// α ≥ 3/2 (a map rough at the pixel scale can fall below); they are
    /// returned as they are, and each theory checks what it needs.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `m4` when the map is too coarse to
    /// form a second difference (fewer than 3 points along an axis) or its
    /// second differences all vanish (a plane); naming `m0` or `m2` for a flat
    /// map; naming `dx`, `dy` or the heights when they are not finite; [`Error::Inconsistent`] when the
    /// number of heights is not `nx·ny`.
    pub fn from_heights(
        heights: &[f64],
        nx: usize,
        ny: usize,
        dx: f64,
        dy: f64,
        periodic: bool,
    ) -> Result<MapMoments> {
        crate::error::check::positive("dx", dx)?;
        crate::error::check::positive("dy", dy)?;
        if heights.len() != nx * ny {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!("nx·ny = {} values, got {}", nx * ny, heights.len()),
            });
        }
        if nx < 3 || ny < 3 {
            return Err(Error::invalid(
                "m4",
                f64::NAN,
                format!("resolved: a second difference needs 3 points along each axis, the map has {nx} × {ny}"),
            ));
        }
        if let Some(k) = heights.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid(
                format!("height[{}, {}]", k / nx, k % nx),
                heights[k],
                "finite",
            ));
        }
        let mean = heights.iter().sum::<f64>() / heights.len() as f64;
        let m0 = heights.iter().map(|h| (h - mean).powi(2)).sum::<f64>() / heights.len() as f64;
        let map = Grid {
            h: heights,
            nx,
            ny,
            periodic,
        };
        let m2 = 0.5 * (map.first(1, 0) / (dx * dx) + map.first(0, 1) / (dy * dy));
        let m4 = 0.5 * (map.second(1, 0) / dx.powi(4) + map.second(0, 1) / dy.powi(4));
        if m4.is_nan() || m4 <= 0.0 {
            return Err(Error::invalid(
                "m4",
                m4,
                "> 0: the map's second differences all vanish (a plane cannot be resolved into summits)",
            ));
        }
        let ratio = (nx >= 5 && ny >= 5).then(|| {
            let coarse = 0.5
                * (map.second(2, 0) / (4.0 * dx * dx).powi(2)
                    + map.second(0, 2) / (4.0 * dy * dy).powi(2));
            coarse / m4
        });
        // Finite-difference moments of a map need not obey α ≥ 3/2 (a map
        // rough at the pixel can have α < 3/2): no check here; the theories
        // check what they need.
        for (name, v) in [("m0", m0), ("m2", m2)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::invalid(name, v, "finite and > 0 (the map is flat)"));
            }
        }
        let moments = SpectralMoments { m0, m2, m4 };
        let validity = match ratio {
            Some(r) if r < CURVATURE_RESOLUTION_RATIO => vec![Validity::CurvatureUnresolved {
                curvature_resolution_ratio: r,
                threshold: CURVATURE_RESOLUTION_RATIO,
            }],
            _ => Vec::new(),
        };
        Ok(MapMoments {
            moments,
            curvature_resolution_ratio: ratio,
            validity,
        })
    }

    /// Nayak's bandwidth parameter α = m0 m4/m2².
    pub fn bandwidth_parameter(&self) -> f64 {
        self.m0 * self.m4 / (self.m2 * self.m2)
    }

    /// rms height √m0, m.
    pub fn rms_height(&self) -> f64 {
        self.m0.sqrt()
    }

    /// rms slope of the surface h'_rms = √⟨|∇h|²⟩ = √(2 m2).
    pub fn rms_slope(&self) -> f64 {
        (2.0 * self.m2).sqrt()
    }

    /// The moments of the gap between two independent rough surfaces, the
    /// sum of theirs (the composite surface of Greenwood & Tripp, Proc.
    /// Inst. Mech. Eng. 185, 625 (1970)): the difference of two independent
    /// Gaussian fields is a Gaussian field whose spectrum is the sum, so the
    /// random-process theories (GW with these moments, BGT) apply unchanged.
    pub fn combined(&self, other: &SpectralMoments) -> SpectralMoments {
        SpectralMoments {
            m0: self.m0 + other.m0,
            m2: self.m2 + other.m2,
            m4: self.m4 + other.m4,
        }
    }

    /// Summit statistics (module docs), exact for every α.
    ///
    /// # Examples
    /// ```
    /// use persson::asperity::SpectralMoments;
    /// let s = SpectralMoments::new(1.0, 1.0, 10.0).unwrap().summits();
    /// assert!((s.summit_density - 10.0 / (6.0 * std::f64::consts::PI * 3f64.sqrt())).abs() < 1e-15);
    /// ```
    pub fn summits(&self) -> SummitStatistics {
        let pi = std::f64::consts::PI;
        let alpha = self.bandwidth_parameter();
        let kappa = 8.0 / 3.0 * (self.m4 / pi).sqrt();
        SummitStatistics {
            bandwidth_parameter: alpha,
            summit_density: self.m4 / (6.0 * pi * SQRT_3 * self.m2),
            summit_curvature: kappa,
            summit_radius: 1.0 / kappa,
            summit_mean_height: 4.0 * self.m2 / (pi * self.m4).sqrt(),
            summit_rms_height: (self.m0 * (1.0 - SUMMIT_VARIANCE_COEFFICIENT / alpha)).sqrt(),
        }
    }

    /// [`Validity::SmallBandwidth`] when α < [`SMALL_BANDWIDTH`].
    pub fn validity(&self) -> Vec<Validity> {
        let alpha = self.bandwidth_parameter();
        if alpha < SMALL_BANDWIDTH {
            vec![Validity::SmallBandwidth {
                bandwidth_parameter: alpha,
                threshold: SMALL_BANDWIDTH,
            }]
        } else {
            Vec::new()
        }
    }
}

/// `∫ q^k C dq` over the band, or an error naming the moment.
fn moment(s: &dyn Spectrum, k: i32, a: f64, b: f64, name: &str) -> Result<f64> {
    let requirement = format!(
        "finite: the spectrum's moment ∫ q^{k} C(q) dq over [{a:e}, {b:e}] 1/m is not (give a finite upper cut-off q_s where C ∝ q^(−2(H+1)) with H < {})",
        (k as f64 - 1.0) / 2.0
    );
    match s.moment(k, a, b) {
        Ok(e) if e.value.is_finite() => Ok(e.value),
        Ok(e) => Err(Error::invalid(name, e.value, requirement)),
        Err(_) => Err(Error::invalid(name, f64::NAN, requirement)),
    }
}

/// A height map and its finite-difference sums.
struct Grid<'a> {
    h: &'a [f64],
    nx: usize,
    ny: usize,
    periodic: bool,
}

impl Grid<'_> {
    fn at(&self, i: usize, j: usize) -> f64 {
        self.h[j * self.nx + i]
    }

    /// Mean of (h(x + s) − h(x))² with the offset `s = (si, sj)` (one of them 0).
    fn first(&self, si: usize, sj: usize) -> f64 {
        let (mut sum, mut n) = (0.0, 0usize);
        for j in 0..self.ny {
            for i in 0..self.nx {
                if let Some((a, b)) = self.shift(i, j, si, sj) {
                    sum += (self.at(a, b) - self.at(i, j)).powi(2);
                    n += 1;
                }
            }
        }
        sum / n as f64
    }

    /// Mean of (h(x + s) − 2h(x) + h(x − s))².
    fn second(&self, si: usize, sj: usize) -> f64 {
        let (mut sum, mut n) = (0.0, 0usize);
        for j in 0..self.ny {
            for i in 0..self.nx {
                let fwd = self.shift(i, j, si, sj);
                let back = self.back(i, j, si, sj);
                if let (Some((a, b)), Some((c, d))) = (fwd, back) {
                    sum += (self.at(a, b) - 2.0 * self.at(i, j) + self.at(c, d)).powi(2);
                    n += 1;
                }
            }
        }
        sum / n as f64
    }

    fn shift(&self, i: usize, j: usize, si: usize, sj: usize) -> Option<(usize, usize)> {
        let (a, b) = (i + si, j + sj);
        if self.periodic {
            Some((a % self.nx, b % self.ny))
        } else {
            (a < self.nx && b < self.ny).then_some((a, b))
        }
    }

    fn back(&self, i: usize, j: usize, si: usize, sj: usize) -> Option<(usize, usize)> {
        if self.periodic {
            Some((
                (i + self.nx - si % self.nx) % self.nx,
                (j + self.ny - sj % self.ny) % self.ny,
            ))
        } else {
            (i >= si && j >= sj).then(|| (i - si, j - sj))
        }
    }
}

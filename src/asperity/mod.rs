//! Asperity theories of rough contact from the same spectrum (or map):
//! the overlap (bearing-area) model, Greenwood & Williamson, and Bush, Gibson
//! & Thomas.
//!
//! # What they solve
//! A nominally flat rough surface (or the gap of two, [`SpectralMoments::combined`])
//! is pressed by a rigid flat to the separation d, the distance of the flat
//! from the mean plane of the heights (`separation`, m). Each theory gives the
//! real contact area A/A0 (`contact_fraction`), the nominal pressure σ0
//! (`nominal_pressure`, unit of E* or of the hardness) and, for the summit
//! theories, the number of contacts per unit nominal area
//! (`contact_number_density`, 1/m²); [`AsperityTheory::at_pressure`] inverts
//! σ0(d) to give A/A0 against σ0.
//!
//! ```text
//! overlap:  A/A0 = Prob(h > d) = F_0(d/h_rms) (Gaussian) or #{h_i > d}/N (a map);   σ0 = σY A/A0 (hardness law)
//! GW:       t = (d − y_s)/σ_s
//!           n = η F_0(t),   A/A0 = π η β σ_s F_1(t),   σ0 = (4/3) η E* β^{1/2} σ_s^{3/2} F_{3/2}(t)
//! BGT:      summits with Nayak's joint density of height and principal curvatures κ1, κ2,
//!           each an elliptic paraboloid in Hertz contact ([`bush`])
//! ```
//! with F_n the Gaussian integrals of [`gw_integral`], summit density η,
//! radius β, summit mean height y_s and rms σ_s from the profile moments m0,
//! m2, m4 ([`moments`]). At low load GW and BGT give A/A0 ∝ σ0; BGT's slope is
//! exactly κ = √(2π) in A/A0 = κ σ0/(E* h'_rms) for every α
//! ([`Bush::low_load_kappa`]).
//!
//! # Conventions
//! - Moments m0, m2, m4 are those of a profile (Nayak 1971); from Persson's
//!   C(q): m0 = 2π∫qC dq, m2 = π∫q³C dq = h'_rms²/2, m4 = (3π/4)∫q⁵C dq = 3h''_rms²/8.
//! - E* is the contact modulus; two elastic bodies enter only through E*.
//! - Where an assumption of a theory fails (Nayak's α small, contacts
//!   coalescing at high load, a map's unresolved m4) the result carries a
//!   [`Validity`] flag: the numbers are still computed, never silently.
//!
//! # References
//! - J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. Lond. A 295, 300
//!   (1966), doi:10.1098/rspa.1966.0242.
//! - A. W. Bush, R. D. Gibson, T. R. Thomas, Wear 35, 87 (1975),
//!   doi:10.1016/0043-1648(75)90145-3.
//! - P. R. Nayak, J. Lubr. Technol. 93, 398 (1971), doi:10.1115/1.3451608.
//! - J. I. McCool, Wear 107, 37 (1986), doi:10.1016/0043-1648(86)90045-1.
//! - E. J. Abbott, F. A. Firestone, Mech. Eng. 55, 569 (1933) (bearing area);
//!   F. P. Bowden, D. Tabor, *The Friction and Lubrication of Solids* (1950)
//!   (F = H·A).
//! - G. Carbone, F. Bottiglione, J. Mech. Phys. Solids 56, 2555 (2008),
//!   doi:10.1016/j.jmps.2008.03.011: GW, BGT and Persson side by side.

pub mod bush;
pub(crate) mod gaussian;
pub mod greenwood_williamson;
mod hertz_ellipse;
mod kernel;
pub mod moments;
pub mod overlap;
mod separation_table;
mod summit_table;

pub use bush::{Bush, EllipticHertz};
pub use gaussian::gw_integral;
pub use greenwood_williamson::{GreenwoodWilliamson, SummitParameters};
pub use moments::{MapMoments, SpectralMoments, SummitStatistics};
pub use overlap::Overlap;

use crate::error::{Error, Result};

/// Above this A/A0 neighbouring asperity contacts are taken to coalesce and a
/// [`Validity::Coalescence`] flag is raised (a convention of this crate: the
/// theories assume independent contacts, and with a tenth of the area in
/// contact a spot's neighbourhood is covered to the same order).
pub const COALESCENCE_FRACTION: f64 = 0.1;

/// An assumption of an asperity theory that does not hold for this input:
/// returned with the numbers, for the caller to report.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Validity {
    /// Nayak's bandwidth parameter α is small: few, broad summits whose heights
    /// differ from the surface heights ([`moments::SMALL_BANDWIDTH`]).
    SmallBandwidth {
        /// α = m0 m4/m2².
        bandwidth_parameter: f64,
        /// The threshold below which the flag is raised.
        threshold: f64,
    },
    /// The contacts cover so much of the area that they coalesce; the theory
    /// treats them as independent ([`COALESCENCE_FRACTION`]).
    Coalescence {
        /// A/A0 of the point.
        contact_fraction: f64,
        /// The threshold above which the flag is raised.
        threshold: f64,
    },
    /// A map's fourth moment depends on its pixel size
    /// ([`moments::CURVATURE_RESOLUTION_RATIO`]): the summit density and
    /// curvature are those of the pixel scale.
    CurvatureUnresolved {
        /// m4 over 2Δ / m4 over Δ.
        curvature_resolution_ratio: f64,
        /// The threshold below which the flag is raised.
        threshold: f64,
    },
}

/// One point of an asperity theory.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct AsperityPoint {
    /// Separation d of the flat from the mean plane of the heights, m.
    pub separation: f64,
    /// A/A0.
    pub contact_fraction: f64,
    /// Nominal pressure σ0 (unit of E*, or of the hardness for the overlap model).
    pub nominal_pressure: f64,
    /// Contacts per unit nominal area, 1/m² (`None` for the overlap model).
    pub contact_number_density: Option<f64>,
    /// Assumptions that fail at this point.
    pub validity: Vec<Validity>,
}

/// A theory that gives A/A0, σ0 and the contact count against the separation.
pub trait AsperityTheory {
    /// The point at separation `separation` (m, from the mean plane).
    ///
    /// # Errors
    /// `separation` not finite; a quadrature that fails (BGT).
    fn at_separation(&self, separation: f64) -> Result<AsperityPoint>;

    /// The point whose nominal pressure is `nominal_pressure`.
    ///
    /// # Errors
    /// `nominal_pressure` not finite and > 0 (or above the hardness of the
    /// overlap model); the separation search not converging.
    fn at_pressure(&self, nominal_pressure: f64) -> Result<AsperityPoint>;

    /// Points at each separation.
    ///
    /// # Errors
    /// As [`AsperityTheory::at_separation`].
    fn separation_curve(&self, separations: &[f64]) -> Result<Vec<AsperityPoint>> {
        separations.iter().map(|&d| self.at_separation(d)).collect()
    }

    /// Points at each nominal pressure.
    ///
    /// # Errors
    /// As [`AsperityTheory::at_pressure`].
    fn pressure_curve(&self, pressures: &[f64]) -> Result<Vec<AsperityPoint>> {
        pressures.iter().map(|&p| self.at_pressure(p)).collect()
    }
}

/// Relative tolerance of the separation search, in units of the length scale.
const SEPARATION_TOLERANCE: f64 = 1e-14;

/// Iteration cap of the separation search (bracketing + Illinois).
const SEPARATION_ITERATIONS: usize = 200;

/// Solve `ln σ0(d) = ln target` for d, with σ0 decreasing in d. `scale` is
/// the length over which σ0 changes (the rms height); `ln_sigma` returns
/// ln σ0(d) (−∞ allowed where σ0 underflows).
pub(crate) fn solve_separation(
    ln_sigma: &dyn Fn(f64) -> Result<f64>,
    target: f64,
    scale: f64,
    start: f64,
) -> Result<f64> {
    crate::error::check::positive("nominal_pressure", target)?;
    let lt = target.ln();
    // The highest load reached so far, for the error when the theory's
    // integrals leave f64 deeper in (a load far beyond E* h'_rms: E* = 1e-10
    // at σ0 = 1e7 gave "BGT u-integral (integrand not finite at 21 nodes) did
    // not converge … residual 0 > tolerance 1e-300").
    let reached = std::cell::Cell::new(f64::NEG_INFINITY);
    let g = |d: f64| -> Result<f64> {
        match ln_sigma(d) {
            Ok(v) => {
                reached.set(reached.get().max(v));
                Ok(v - lt)
            }
            Err(Error::NotConverged { .. }) if d < start => Err(Error::invalid(
                "nominal_pressure",
                target,
                format!(
                    "at most {} (the largest load reached before the theory's integrals \
                     leave f64 at a separation of {} rms heights): far beyond E* h'_rms, \
                     outside the asperity theory",
                    crate::error::approx(reached.get().exp()),
                    crate::error::approx(d / scale)
                ),
            )),
            Err(e) => Err(e),
        }
    };
    // Bracket: g(lo) ≥ 0 ≥ g(hi).
    let (mut lo, mut hi) = (start, start);
    let mut glo = g(lo)?;
    let mut ghi: f64;
    let mut step = scale;
    if glo < 0.0 {
        hi = lo;
        ghi = glo;
        loop {
            lo -= step;
            step *= 2.0;
            glo = g(lo)?;
            if glo >= 0.0 {
                break;
            }
            if step > 1e6 * scale {
                return Err(not_bracketed(target));
            }
        }
    } else {
        loop {
            hi += step;
            step *= 2.0;
            ghi = g(hi)?;
            if ghi <= 0.0 {
                break;
            }
            if step > 1e6 * scale {
                return Err(not_bracketed(target));
            }
        }
    }
    // Illinois (regula falsi with halving), robust when g = −∞ at hi.
    let mut side = 0i8;
    for _ in 0..SEPARATION_ITERATIONS {
        if (hi - lo).abs() <= SEPARATION_TOLERANCE * scale.max(lo.abs().max(hi.abs())) {
            return Ok(0.5 * (lo + hi));
        }
        let d = if ghi.is_finite() && glo.is_finite() && glo != ghi {
            let x = hi - ghi * (hi - lo) / (ghi - glo);
            if x > lo.min(hi) && x < lo.max(hi) {
                x
            } else {
                0.5 * (lo + hi)
            }
        } else {
            0.5 * (lo + hi)
        };
        let gd = g(d)?;
        if gd == 0.0 {
            return Ok(d);
        }
        if gd > 0.0 {
            lo = d;
            glo = gd;
            if side == 1 {
                ghi *= 0.5;
            }
            side = 1;
        } else {
            hi = d;
            ghi = gd;
            if side == -1 {
                glo *= 0.5;
            }
            side = -1;
        }
    }
    Err(Error::NotConverged {
        what: "separation at the nominal pressure".into(),
        iterations: SEPARATION_ITERATIONS,
        residual: (hi - lo).abs() / scale,
        tolerance: SEPARATION_TOLERANCE,
    })
}

fn not_bracketed(target: f64) -> Error {
    Error::invalid(
        "nominal_pressure",
        target,
        "reachable by the theory (no separation within 10⁶ rms heights gives it)",
    )
}

/// The flags of a point: the model's own, plus coalescence above [`COALESCENCE_FRACTION`].
pub(crate) fn point_validity(model: &[Validity], contact_fraction: f64) -> Vec<Validity> {
    let mut v = model.to_vec();
    if contact_fraction > COALESCENCE_FRACTION {
        v.push(Validity::Coalescence {
            contact_fraction,
            threshold: COALESCENCE_FRACTION,
        });
    }
    v
}

/// A finite separation, or an error naming it.
pub(crate) fn check_separation(d: f64) -> Result<f64> {
    if d.is_finite() {
        Ok(d)
    } else {
        Err(Error::invalid("separation", d, "finite"))
    }
}

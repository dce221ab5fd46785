//! The cohesive laws W(g) of the adhesive BEM: Maugis–Dugdale and
//! exponential, with their bounds.

use crate::error::{check, Error, Result};
use crate::names::LawKind;

/// Shortest cohesive length ℓ = E*Δγ/σ_c² ([`CohesiveLaw::cohesive_length`])
/// that counts as resolved, in grid spacings L/N (below it a study warns).
/// Measured on
/// a rough surface (docs/adhesion.md, "Which stationary point"): at 4.7 L/N
/// the plain and the preconditioned iteration from one start reach
/// Maugis–Dugdale solutions 0.8 % apart in A/A0, at 6.7 L/N 0.47 %, from
/// 9.3 L/N on at most 0.18 %.
pub const RESOLVED_COHESIVE_LENGTH: f64 = 8.0;

/// The cohesive law of the gap.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "law", rename_all = "kebab-case")]
pub enum CohesiveLaw {
    /// Constant attraction Δγ/ρ for gaps below ρ (Maugis–Dugdale).
    Maugis {
        /// Δγ, (unit of E*)·(unit of L).
        work_of_adhesion: f64,
        /// ρ, unit of L.
        adhesion_range: f64,
    },
    /// Attraction (Δγ/ρ) e^{−g/ρ}.
    Exponential {
        /// Δγ, (unit of E*)·(unit of L).
        work_of_adhesion: f64,
        /// ρ, unit of L.
        adhesion_range: f64,
    },
}

/// The largest peak attraction σ_c = Δγ/ρ of a [`CohesiveLaw`]: √f64::MAX/
/// [`MAX_GRID`](crate::bem::MAX_GRID) ≈ 4.1e149 (unit of E*).
///
/// # Bound
/// The solvers' KKT residual sums the squares of the tractions W′(g) ≤ σ_c
/// over N² ≤ MAX_GRID² nodes: N² σ_c² ≤ f64::MAX on every grid.
pub const MAX_PEAK_ATTRACTION: f64 = 1.340_780_792_994_259_6e154 / crate::bem::MAX_GRID as f64;

/// Δγ ≥ 0 and ρ > 0, finite, with σ_c = Δγ/ρ ≤ [`MAX_PEAK_ATTRACTION`],
/// naming Δγ or ρ (the one further from 1 in order of magnitude: an
/// overflowing ratio needs one of them far outside every unit system).
fn check_law(work_of_adhesion: f64, adhesion_range: f64) -> Result<()> {
    check::non_negative("work_of_adhesion", work_of_adhesion)?;
    check::positive("adhesion_range", adhesion_range)?;
    if work_of_adhesion / adhesion_range <= MAX_PEAK_ATTRACTION {
        return Ok(());
    }
    let approx = crate::error::approx;
    let why = "so that the peak attraction Δγ/ρ, summed in squares over the grid, stays finite \
               in f64";
    Err(
        if work_of_adhesion.log10().abs() >= adhesion_range.log10().abs() {
            Error::invalid(
                "work_of_adhesion",
                work_of_adhesion,
                format!(
                    "at most {} (ρ = {}) {why}",
                    approx(MAX_PEAK_ATTRACTION * adhesion_range),
                    crate::error::num(adhesion_range)
                ),
            )
        } else {
            Error::invalid(
                "adhesion_range",
                adhesion_range,
                format!(
                    "at least {} (Δγ = {}) {why}",
                    approx(work_of_adhesion / MAX_PEAK_ATTRACTION),
                    crate::error::num(work_of_adhesion)
                ),
            )
        },
    )
}

impl LawKind {
    /// The law of this kind with work of adhesion Δγ = `work_of_adhesion`
    /// and range ρ = `adhesion_range`.
    ///
    /// # Errors
    /// As [`CohesiveLaw::maugis`].
    pub fn law(self, work_of_adhesion: f64, adhesion_range: f64) -> Result<CohesiveLaw> {
        match self {
            LawKind::Maugis => CohesiveLaw::maugis(work_of_adhesion, adhesion_range),
            LawKind::Exponential => CohesiveLaw::exponential(work_of_adhesion, adhesion_range),
        }
    }
}

impl CohesiveLaw {
    /// The law's kind.
    pub fn kind(&self) -> LawKind {
        match self {
            CohesiveLaw::Maugis { .. } => LawKind::Maugis,
            CohesiveLaw::Exponential { .. } => LawKind::Exponential,
        }
    }

    /// The Maugis–Dugdale law.
    ///
    /// # Errors
    /// `work_of_adhesion` negative or not finite; `adhesion_range` not finite
    /// and > 0; Δγ/ρ above [`MAX_PEAK_ATTRACTION`] (naming the one of the
    /// two further from 1 in order of magnitude).
    pub fn maugis(work_of_adhesion: f64, adhesion_range: f64) -> Result<Self> {
        check_law(work_of_adhesion, adhesion_range)?;
        Ok(CohesiveLaw::Maugis {
            work_of_adhesion,
            adhesion_range,
        })
    }

    /// The exponential law.
    ///
    /// # Errors
    /// As [`CohesiveLaw::maugis`].
    pub fn exponential(work_of_adhesion: f64, adhesion_range: f64) -> Result<Self> {
        check_law(work_of_adhesion, adhesion_range)?;
        Ok(CohesiveLaw::Exponential {
            work_of_adhesion,
            adhesion_range,
        })
    }

    /// (Δγ, ρ).
    pub fn parameters(&self) -> (f64, f64) {
        match *self {
            CohesiveLaw::Maugis {
                work_of_adhesion,
                adhesion_range,
            }
            | CohesiveLaw::Exponential {
                work_of_adhesion,
                adhesion_range,
            } => (work_of_adhesion, adhesion_range),
        }
    }

    /// The law's cohesive length ℓ = E* Δγ/σ_c², σ_c = Δγ/ρ its peak
    /// attraction (both laws), so ℓ = E* ρ²/Δγ (unit of L; ∞ at Δγ = 0).
    ///
    /// The one length made of E*, Δγ and σ_c: the scale of the cohesive zone
    /// at the edge of an adhesive contact (Maugis, J. Colloid Interface Sci.
    /// 150, 243 (1992); the zone of a Dugdale crack of constant cohesive
    /// stress σ_c in a homogeneous body is (π/8) E′Δγ/σ_c² in the small-zone
    /// limit, Dugdale, J. Mech. Phys. Solids 8, 100 (1960)). A grid must
    /// resolve it: [`RESOLVED_COHESIVE_LENGTH`].
    pub fn cohesive_length(&self, contact_modulus: f64) -> f64 {
        let (work_of_adhesion, adhesion_range) = self.parameters();
        contact_modulus * adhesion_range * adhesion_range / work_of_adhesion
    }

    /// W′(g) ≥ 0: the attraction (tension) at gap g.
    pub fn attraction(&self, g: f64) -> f64 {
        match *self {
            CohesiveLaw::Maugis {
                work_of_adhesion,
                adhesion_range,
            } => {
                if g < adhesion_range {
                    work_of_adhesion / adhesion_range
                } else {
                    0.0
                }
            }
            CohesiveLaw::Exponential {
                work_of_adhesion,
                adhesion_range,
            } => work_of_adhesion / adhesion_range * (-g / adhesion_range).exp(),
        }
    }

    /// Whether W′ jumps between gaps a and b (Maugis–Dugdale: ρ between them).
    pub(super) fn jumps_between(&self, a: f64, b: f64) -> bool {
        match *self {
            CohesiveLaw::Maugis { adhesion_range, .. } => {
                (a < adhesion_range) != (b < adhesion_range)
            }
            CohesiveLaw::Exponential { .. } => false,
        }
    }

    /// Whether gap g is inside the cohesive zone (g < ρ).
    pub(super) fn cohesive(&self, g: f64) -> bool {
        g > 0.0 && g < self.parameters().1
    }
}

//! The asperity theories of [`persson::asperity`] as studies: the overlap
//! (bearing-area) model, Greenwood & Williamson and Bush, Gibson & Thomas,
//! built from a spectrum or a height map, their load curves, the asperity
//! parameters reported beside them, and the warnings their validity flags
//! turn into.
//!
//! # From a spectrum or a map
//! ```text
//! spectrum (Persson's C(q), band [q_l, q_max]):
//!   m0 = 2π ∫ q C dq,   m2 = π ∫ q³ C dq,   m4 = (3π/4) ∫ q⁵ C dq
//! height map (nx × ny, pixels Δx, Δy), detrended as its spectrum is:
//!   m0 = ⟨(h − h̄)²⟩,   m2 = ⟨(D⁺h)²⟩,   m4 = ⟨(D²h)²⟩   (x and y averaged)
//! ```
//! ([`persson::asperity::SpectralMoments`]). The overlap model cuts Gaussian
//! heights of rms √m0 (a spectrum) or the map's own heights, and carries the
//! load by the hardness law σ0 = σY A/A0; GW and BGT need m4, and a spectrum
//! or map that cannot give it is an error naming `m4`.
//!
//! # Validity
//! The theories flag their assumptions ([`Validity`]); [`warnings`] turns
//! the flags of a curve into [`Warning`]s: Nayak's α below 10
//! ([`Warning::SmallBandwidth`]), contacts coalescing above A/A0 = 0.1
//! ([`Warning::Coalescence`]), a map's m4 unresolved
//! ([`Warning::CurvatureUnresolved`]).
//!
//! # References
//! Greenwood & Williamson, Proc. R. Soc. Lond. A 295, 300 (1966); Bush,
//! Gibson & Thomas, Wear 35, 87 (1975); Nayak, J. Lubr. Technol. 93, 398
//! (1971); McCool, Wear 107, 37 (1986); Carbone & Bottiglione, J. Mech.
//! Phys. Solids 56, 2555 (2008).

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::naming::names::TheoryName;
use crate::table::number;
use crate::warning::Warning;
use persson::asperity::{
    self, AsperityPoint, AsperityTheory, Bush, EllipticHertz, GreenwoodWilliamson, Overlap,
    SpectralMoments, SummitStatistics, Validity,
};
use persson::error::{check, Error, Result};
use persson::spectrum::{BandLimited, Spectrum};

/// Relative error of a GW point: F_n to 1.2e-15 (tested against mpmath),
/// the separation solved to 1e-14 of σ_s, with room for d ln F/dt ≤ 10.
const GW_RELATIVE_ERROR: f64 = 1e-13;

/// A BGT point's relative error per unit of its integrals' tolerance (the
/// summit-table path is tested to 1e-12 against the direct integrals).
const BUSH_ERROR_FACTOR: f64 = 10.0;

/// Where the moments of a surface come from.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum MomentSource {
    /// A spectrum over `[q_min, q_max]`, 1/m.
    Spectrum {
        /// Lower end of the band.
        q_min: f64,
        /// Upper end of the band.
        q_max: f64,
    },
    /// A height map's finite differences.
    HeightMap {
        /// The file.
        file: PathBuf,
    },
}

/// The asperity parameters of a surface: its profile moments and the
/// summit statistics of a Gaussian surface with them.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AsperityParameters {
    /// Where the moments come from.
    pub moments_from: MomentSource,
    /// m0, m2, m4.
    #[serde(flatten)]
    pub moments: SpectralMoments,
    /// α, η, κ̄, β, y_s, σ_s.
    #[serde(flatten)]
    pub summits: SummitStatistics,
    /// A map's m4 over 2Δ against m4 over Δ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curvature_resolution_ratio: Option<f64>,
}

/// What the theory is built with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AsperitySettings {
    /// overlap, greenwood-williamson or bush.
    pub theory: TheoryName,
    /// The hardness σY of the overlap model's load law (required by it).
    pub yield_stress: Option<f64>,
    /// Relative tolerance of BGT's integrals.
    pub tolerance: f64,
    /// BGT's elliptic Hertz treatment.
    pub hertz: EllipticHertz,
}

impl AsperitySettings {
    /// `theory` with BGT's defaults and no hardness.
    pub fn new(theory: TheoryName) -> Self {
        AsperitySettings {
            theory,
            yield_stress: None,
            tolerance: asperity::bush::DEFAULT_TOLERANCE,
            hertz: EllipticHertz::Exact,
        }
    }
}

/// An asperity theory ready for load curves, with the parameters of its surface.
pub struct AsperityModel {
    /// Which theory.
    pub theory: TheoryName,
    /// The surface's asperity parameters (`None` only for the overlap model
    /// of a spectrum without a finite m4).
    pub parameters: Option<AsperityParameters>,
    /// The flags of the surface (α small, m4 unresolved).
    pub validity: Vec<Validity>,
    /// Where the moments come from.
    pub source: MomentSource,
    /// The hardness of the overlap model.
    pub yield_stress: Option<f64>,
    model: Box<dyn AsperityTheory + Send + Sync>,
    relative_error: f64,
}

impl std::fmt::Debug for AsperityModel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AsperityModel")
            .field("theory", &self.theory)
            .field("parameters", &self.parameters)
            .finish()
    }
}

/// The overlap model's hardness, or an error naming it.
fn hardness(s: &AsperitySettings) -> Result<f64> {
    match s.yield_stress {
        Some(y) => check::positive("yield_stress", y),
        None => Err(Error::Inconsistent {
            name: "yield_stress".into(),
            requirement: "required by the overlap model: the hardness σY of its load law \
                          σ0 = σY A/A0 (Abbott & Firestone; Bowden & Tabor)"
                .into(),
        }),
    }
}

impl AsperityModel {
    /// The theory for a spectrum over `[q_l, q_max]` (`q_max` default its
    /// upper cut-off q_s) and the contact modulus E*.
    ///
    /// # Errors
    /// Not an asperity theory; `q_max` not above q_l; a moment that is not
    /// finite (named `m0`, `m2` or `m4`); the overlap model without a
    /// hardness; the theory's own range checks.
    pub fn from_spectrum(
        spectrum: &dyn Spectrum,
        q_max: Option<f64>,
        contact_modulus: f64,
        settings: &AsperitySettings,
    ) -> Result<Self> {
        let band = BandLimited::new(spectrum, q_max.unwrap_or(spectrum.q_max()))?;
        let source = MomentSource::Spectrum {
            q_min: spectrum.q_min(),
            q_max: band.q_max(),
        };
        let moments = SpectralMoments::from_spectrum(&band);
        if settings.theory == TheoryName::Overlap {
            let m0 = band.rms_height(band.q_min(), band.q_max())?.value;
            let model = Overlap::gaussian(m0, hardness(settings)?)?;
            return Ok(Self::overlap(model, moments.ok(), None, source, settings));
        }
        let m = moments?;
        Self::summit_theory(m, None, Vec::new(), source, contact_modulus, settings)
    }

    /// The theory for a height map (`heights` row-major `ny × nx`, already
    /// detrended; pixels `dx`, `dy` m).
    ///
    /// # Errors
    /// As [`SpectralMoments::from_heights`] (`m4` named for a map too
    /// coarse); the overlap model without a hardness; the theory's checks.
    #[allow(clippy::too_many_arguments)]
    pub fn from_heights(
        file: &Path,
        heights: &[f64],
        [nx, ny]: [usize; 2],
        [dx, dy]: [f64; 2],
        periodic: bool,
        contact_modulus: f64,
        settings: &AsperitySettings,
    ) -> Result<Self> {
        let source = MomentSource::HeightMap {
            file: file.to_path_buf(),
        };
        let map = SpectralMoments::from_heights(heights, nx, ny, dx, dy, periodic);
        if settings.theory == TheoryName::Overlap {
            let model = Overlap::from_heights(heights, hardness(settings)?)?;
            let (m, r) = match map {
                Ok(m) => (Some(m.moments), m.curvature_resolution_ratio),
                Err(_) => (None, None),
            };
            return Ok(Self::overlap(model, m, r, source, settings));
        }
        let m = map?;
        Self::summit_theory(
            m.moments,
            m.curvature_resolution_ratio,
            m.validity,
            source,
            contact_modulus,
            settings,
        )
    }

    fn overlap(
        model: Overlap,
        moments: Option<SpectralMoments>,
        ratio: Option<f64>,
        source: MomentSource,
        settings: &AsperitySettings,
    ) -> Self {
        AsperityModel {
            theory: TheoryName::Overlap,
            parameters: moments.map(|m| AsperityParameters {
                moments_from: source.clone(),
                moments: m,
                summits: m.summits(),
                curvature_resolution_ratio: ratio,
            }),
            validity: Vec::new(),
            source,
            yield_stress: settings.yield_stress,
            model: Box::new(model),
            relative_error: 0.0,
        }
    }

    fn summit_theory(
        m: SpectralMoments,
        ratio: Option<f64>,
        mut validity: Vec<Validity>,
        source: MomentSource,
        e_star: f64,
        settings: &AsperitySettings,
    ) -> Result<Self> {
        let (model, relative_error): (Box<dyn AsperityTheory + Send + Sync>, f64) = match settings
            .theory
        {
            TheoryName::GreenwoodWilliamson => (
                Box::new(GreenwoodWilliamson::from_moments(&m, e_star)?),
                GW_RELATIVE_ERROR,
            ),
            TheoryName::Bush => (
                Box::new(
                    Bush::new(&m, e_star, settings.hertz)?.with_tolerance(settings.tolerance)?,
                ),
                BUSH_ERROR_FACTOR * settings.tolerance,
            ),
            other => {
                return Err(Error::Inconsistent {
                    name: "theory".into(),
                    requirement: format!(
                        "an asperity theory (overlap, greenwood-williamson, bush), not {other}"
                    ),
                })
            }
        };
        validity.extend(m.validity());
        Ok(AsperityModel {
            theory: settings.theory,
            parameters: Some(AsperityParameters {
                moments_from: source.clone(),
                moments: m,
                summits: m.summits(),
                curvature_resolution_ratio: ratio,
            }),
            validity,
            source,
            yield_stress: None,
            model,
            relative_error,
        })
    }

    /// The points at each nominal pressure (in order; BGT warm-starts
    /// each separation search from the previous point).
    ///
    /// # Errors
    /// A pressure not finite and positive (or above the overlap model's
    /// hardness); a search that does not converge.
    pub fn pressure_curve(&self, pressures: &[f64]) -> Result<Vec<AsperityPoint>> {
        self.model.pressure_curve(pressures)
    }

    /// A bound on the relative error of a point's A/A0 (module constants).
    pub fn relative_error(&self) -> f64 {
        self.relative_error
    }

    /// κ of the theory's low-load law A/A0 = κ σ0/(E* h'_rms): √(2π) for
    /// BGT; none for GW (its A/A0/σ0 grows without bound as σ0 → 0) and the
    /// overlap model (no elasticity).
    pub fn low_load_kappa(&self) -> Option<f64> {
        (self.theory == TheoryName::Bush).then(|| persson::kappa::Kappa::Bush.value())
    }
}

/// The warnings of a theory's flags over a load curve: the surface's own
/// flags once, and coalescence at the first pressure where A/A0 exceeds
/// the threshold (with the count of such pressures).
pub fn warnings(model: &AsperityModel, points: &[AsperityPoint]) -> Vec<Warning> {
    let mut w = Vec::new();
    for v in &model.validity {
        match *v {
            Validity::SmallBandwidth {
                bandwidth_parameter,
                threshold,
            } => w.push(
                Warning::SmallBandwidth {
                    theory: model.theory,
                    bandwidth_parameter,
                    threshold,
                    message: String::new(),
                }
                .described(describe),
            ),
            Validity::CurvatureUnresolved {
                curvature_resolution_ratio,
                threshold,
            } => {
                if let MomentSource::HeightMap { file } = &model.source {
                    w.push(
                        Warning::CurvatureUnresolved {
                            file: file.clone(),
                            curvature_resolution_ratio,
                            threshold,
                            message: String::new(),
                        }
                        .described(describe),
                    );
                }
            }
            _ => {}
        }
    }
    let coalesced: Vec<(&AsperityPoint, f64)> = points
        .iter()
        .filter_map(|p| {
            p.validity.iter().find_map(|v| match v {
                Validity::Coalescence { threshold, .. } => Some((p, *threshold)),
                _ => None,
            })
        })
        .collect();
    if let Some(&(first, threshold)) = coalesced.first() {
        w.push(
            Warning::Coalescence {
                theory: model.theory,
                nominal_pressure: first.nominal_pressure,
                contact_fraction: first.contact_fraction,
                count: coalesced.len(),
                threshold,
                message: String::new(),
            }
            .described(describe),
        );
    }
    w
}

/// The text of the asperity warnings ([`Warning::described`]).
pub(crate) fn describe(w: &Warning, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    let n = |v: f64| number(v, 4);
    match w {
        Warning::SmallBandwidth {
            theory,
            bandwidth_parameter,
            threshold,
            ..
        } => write!(
            f,
            "Nayak's bandwidth parameter α = m0 m4/m2² = {} of the surface is below {}: few, \
             broad summits whose heights differ from the surface heights, so the {theory} \
             theory's summit picture is poor",
            n(*bandwidth_parameter),
            n(*threshold)
        ),
        Warning::Coalescence {
            theory,
            nominal_pressure,
            contact_fraction,
            count,
            threshold,
            ..
        } => write!(
            f,
            "the {theory} theory's A/A0 exceeds {} at {count} nominal pressure(s), from σ0 = {} \
             (A/A0 = {}): its contacts coalesce there, which it treats as independent",
            n(*threshold),
            number(*nominal_pressure, 6),
            n(*contact_fraction)
        ),
        Warning::CurvatureUnresolved {
            file,
            curvature_resolution_ratio,
            threshold,
            ..
        } => write!(
            f,
            "{}: the fourth moment m4 is not resolved by the map's pixels (m4 over 2 pixels is \
             {} of m4 over one, below {}): the summit density and curvature are those of the \
             pixel scale",
            file.display(),
            n(*curvature_resolution_ratio),
            n(*threshold)
        ),
        _ => Ok(()),
    }
}

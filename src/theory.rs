//! Persson's theory, elastic and frictionless: G(ζ) and the contact area.

use crate::error::{check, Error, Result};
use crate::kappa::Kappa;
use crate::quad::Estimate;
use crate::special::{erf, erfc, ln_erfc};
use crate::spectrum::Spectrum;

/// Rounding budget of `contact_fraction` itself (erf/erfc are ≤ 1 ulp, the
/// argument `1/(2√G)` adds two roundings, amplified by at most 2x² ≲ 2 near x = 1).
const AREA_ULPS: f64 = 8.0;

/// The contact area A/A0 and its complement, each to full relative accuracy.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct ContactFraction {
    /// A/A0 = erf(1/(2√G)).
    pub fraction: f64,
    /// 1 − A/A0 = erfc(1/(2√G)) (underflows to 0 below G ≈ 3.4e-4).
    pub complement: f64,
    /// ln(1 − A/A0), finite for every G > 0 (−∞ at G = 0).
    pub ln_complement: f64,
    /// Bound on the absolute error of `fraction` (from the error of G and rounding).
    pub error: f64,
}

/// A/A0 from G (flat start, elastic; Persson, Bucher & Chiaia (2002) Eq. 3).
///
/// # Formula
/// ```text
/// A/A0 = (2/π) ∫₀^∞ (sin x / x) e^{−x² G} dx = erf(1/(2√G))
/// 1 − A/A0 = erfc(1/(2√G)),   ln(1 − A/A0) = ln erfcx(x) − x²
/// ```
/// erf and erfc are evaluated separately so that both A/A0 (large G, where
/// A/A0 → (πG)^{−1/2}, their Eq. 4) and 1 − A/A0 (small G) keep full relative
/// accuracy. `g_error` (the absolute error of G) is propagated through
/// `|dA/dG| = x e^{−x²} / (√π G)`.
///
/// # Errors
/// G or its error negative or non-finite.
///
/// # Examples
/// ```
/// // Persson, Bucher & Chiaia (2002), Fig. 2: A/A0 = 0.638690 at G = 0.6 (docs/accuracy.md)
/// let a = persson::theory::contact_fraction(0.6, 0.0).unwrap();
/// assert!((a.fraction - 0.638_690).abs() < 5e-7);
/// ```
pub fn contact_fraction(g: f64, g_error: f64) -> Result<ContactFraction> {
    check::non_negative("g", g)?;
    check::non_negative("g_error", g_error)?;
    if g == 0.0 {
        return Ok(ContactFraction {
            fraction: 1.0,
            complement: 0.0,
            ln_complement: f64::NEG_INFINITY,
            error: 0.0,
        });
    }
    let x = 0.5 / g.sqrt();
    let fraction = erf(x);
    let slope = x * (-x * x).exp() / (std::f64::consts::PI.sqrt() * g);
    Ok(ContactFraction {
        fraction,
        complement: erfc(x),
        ln_complement: ln_erfc(x),
        error: AREA_ULPS * f64::EPSILON * fraction + slope * g_error,
    })
}

/// The error for an E*/σ0 so large that G overflows, naming E* or σ0
/// ([`crate::error::ratio_culprit`]) with the bound on it.
///
/// # Bound
/// ```text
/// G = (E*/σ0)² ⟨|∇h|²⟩/8 ≤ f64::MAX  and  (E*/σ0)² ≤ f64::MAX
///   ⇔  E*/σ0 ≤ r_max = √(f64::MAX / max(1, ⟨|∇h|²⟩/8))
/// ```
/// The second condition is that of the load factor g = (π/4)(E*/σ0)² alone,
/// which the P(u) routes ([`crate::gap`]) carry apart from the moment. The
/// bound is σ0 ≥ E*/r_max when σ0 is named, E* ≤ r_max σ0 when E* is.
pub(crate) fn g_overflow(contact_modulus: f64, pressure: f64, slope_variance: f64) -> Error {
    let r_max = (f64::MAX / (slope_variance / 8.0).max(1.0)).sqrt();
    let (num, approx) = (crate::error::num, crate::error::approx);
    let why = format!(
        "⟨|∇h|²⟩ = {}) so that G = (E*/σ0)²⟨|∇h|²⟩/8 stays finite in f64",
        approx(slope_variance)
    );
    match crate::error::ratio_culprit(contact_modulus, pressure) {
        "contact_modulus" => Error::invalid(
            "contact_modulus",
            contact_modulus,
            format!(
                "at most {} (σ0 = {}, {why}",
                approx(r_max * pressure),
                num(pressure)
            ),
        ),
        _ => Error::invalid(
            "nominal_pressure",
            pressure,
            format!(
                "at least {} (E* = {}, {why}",
                approx(contact_modulus / r_max),
                num(contact_modulus)
            ),
        ),
    }
}

/// Refuse an E*/σ0 for which G = (E*/σ0)²⟨|∇h|²⟩/8 or (E*/σ0)² overflows
/// (the bound of [`g_overflow`]), evaluated as the routes evaluate them.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `contact_modulus` or
/// `nominal_pressure` (see [`crate::error::ratio_culprit`]).
pub(crate) fn check_g_finite(
    contact_modulus: f64,
    pressure: f64,
    slope_variance: f64,
) -> Result<()> {
    let r = contact_modulus / pressure;
    let r2 = r * r;
    if r2.is_finite() && (r2 / 8.0 * slope_variance).is_finite() {
        Ok(())
    } else {
        Err(g_overflow(contact_modulus, pressure, slope_variance))
    }
}

/// One point of an area curve.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct AreaPoint {
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// Magnification ζ.
    pub zeta: f64,
    /// G(ζ).
    pub g: f64,
    /// Absolute error bound of G.
    pub g_error_bound: f64,
    /// A/A0 (original theory).
    pub contact_fraction: f64,
    /// 1 − A/A0, computed without cancellation.
    pub non_contact_fraction: f64,
    /// Absolute error bound of A/A0.
    pub error_bound: f64,
    /// rms slope of the roughness up to ζ.
    pub rms_slope: f64,
    /// Bush–Gibson–Thomas linear law κ_B σ0/(E* rms slope).
    pub contact_fraction_bush_linear: f64,
    /// Persson's linear law κ_P σ0/(E* rms slope).
    pub contact_fraction_persson_linear: f64,
}

/// Persson's theory for a spectrum and a contact modulus.
pub struct Persson<'a> {
    spectrum: &'a dyn Spectrum,
    contact_modulus: f64,
}

impl<'a> Persson<'a> {
    /// The model for `spectrum` and E* = `contact_modulus`.
    ///
    /// # Errors
    /// `contact_modulus` not finite and positive.
    pub fn new(spectrum: &'a dyn Spectrum, contact_modulus: f64) -> Result<Self> {
        Ok(Persson {
            spectrum,
            contact_modulus: check::positive("contact_modulus", contact_modulus)?,
        })
    }

    /// The spectrum.
    pub fn spectrum(&self) -> &dyn Spectrum {
        self.spectrum
    }

    /// E*.
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }

    /// `⟨|∇h|²⟩` up to magnification ζ: 2π ∫_{q_l}^{ζ q_l} q³ C dq.
    ///
    /// # Errors
    /// ζ < 1 or non-finite; quadrature failure for a spectrum given as a function ([`crate::spectrum::FnSpectrum`]).
    pub fn slope_variance(&self, zeta: f64) -> Result<Estimate> {
        check::at_least("zeta", zeta, 1.0)?;
        let q_l = self.spectrum.q_min();
        let m = self.spectrum.moment(3, q_l, zeta * q_l)?;
        let tau = std::f64::consts::TAU;
        Ok(Estimate {
            value: tau * m.value,
            error: tau * m.error + f64::EPSILON * tau * m.value,
        })
    }

    /// G(ζ) at nominal pressure σ0 (Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Eq. 2).
    ///
    /// # Formula
    /// ```text
    /// G(ζ) = (π/4) (E*/σ0)² ∫_{q_l}^{ζ q_l} q³ C(q) dq = (E*/σ0)² ⟨|∇h|²⟩_ζ / 8
    /// ```
    /// Exact for self-affine and tabulated spectra (closed-form moments),
    /// quadrature for [`crate::spectrum::FnSpectrum`]; the error bound is returned with the value.
    ///
    /// # Errors
    /// σ0 not finite and positive, ζ < 1.
    pub fn g(&self, zeta: f64, pressure: f64) -> Result<Estimate> {
        self.g_from(self.slope_variance(zeta)?, pressure)
    }

    /// G from a slope variance ⟨|∇h|²⟩_ζ already computed (see
    /// [`Persson::slope_variance`]): `(E*/σ0)² ⟨|∇h|²⟩_ζ / 8` with its error,
    /// so that a load curve computes the spectrum's moment once.
    ///
    /// # Errors
    /// σ0 not finite and positive, or so small that G overflows.
    pub fn g_from(&self, slope_variance: Estimate, pressure: f64) -> Result<Estimate> {
        check::positive("nominal_pressure", pressure)?;
        let r = self.contact_modulus / pressure;
        let f = r * r / 8.0;
        let s = slope_variance;
        let g = Estimate {
            value: f * s.value,
            error: f * s.error + 2.0 * f64::EPSILON * f * s.value,
        };
        if !g.value.is_finite() {
            return Err(g_overflow(self.contact_modulus, pressure, s.value));
        }
        Ok(g)
    }

    /// A/A0 at (ζ, σ0), original theory.
    ///
    /// # Errors
    /// As [`Persson::g`].
    pub fn contact_fraction(&self, zeta: f64, pressure: f64) -> Result<ContactFraction> {
        let g = self.g(zeta, pressure)?;
        contact_fraction(g.value, g.error)
    }

    /// Full magnification ζ_max = q_s / q_l.
    pub fn zeta_max(&self) -> f64 {
        self.spectrum.q_max() / self.spectrum.q_min()
    }

    /// The area at one (ζ, σ0) with the linear laws beside it.
    ///
    /// # Errors
    /// As [`Persson::g`]; σ0/E* so large that the linear laws κσ0/(E* h'_rms)
    /// overflow f64 (naming `nominal_pressure`, or `contact_modulus` beyond
    /// 1e±30).
    pub fn point(&self, zeta: f64, pressure: f64) -> Result<AreaPoint> {
        self.point_from(self.slope_variance(zeta)?, zeta, pressure)
    }

    /// [`Persson::point`] with ⟨|∇h|²⟩_ζ already computed.
    fn point_from(&self, slope_variance: Estimate, zeta: f64, pressure: f64) -> Result<AreaPoint> {
        let g = self.g_from(slope_variance, pressure)?;
        let a = contact_fraction(g.value, g.error)?;
        let slope = slope_variance.value.sqrt();
        crate::kappa::check_linear_laws(self.contact_modulus, pressure, slope)?;
        Ok(AreaPoint {
            nominal_pressure: pressure,
            zeta,
            g: g.value,
            g_error_bound: g.error,
            contact_fraction: a.fraction,
            non_contact_fraction: a.complement,
            error_bound: a.error,
            rms_slope: slope,
            contact_fraction_bush_linear: Kappa::Bush.linear_fraction(
                pressure,
                self.contact_modulus,
                slope,
            ),
            contact_fraction_persson_linear: Kappa::Persson.linear_fraction(
                pressure,
                self.contact_modulus,
                slope,
            ),
        })
    }

    /// A/A0 against load at fixed ζ (the load curve).
    ///
    /// # Errors
    /// As [`Persson::point`], for the first bad pressure.
    pub fn load_curve(&self, pressures: &[f64], zeta: f64) -> Result<Vec<AreaPoint>> {
        let s = self.slope_variance(zeta)?;
        pressures
            .iter()
            .map(|&p| self.point_from(s, zeta, p))
            .collect()
    }

    /// A/A0 against magnification at fixed σ0 (the magnification curve).
    ///
    /// # Errors
    /// As [`Persson::point`], for the first bad ζ.
    pub fn magnification_curve(&self, zetas: &[f64], pressure: f64) -> Result<Vec<AreaPoint>> {
        zetas.iter().map(|&z| self.point(z, pressure)).collect()
    }
}

/// `n` magnifications spaced evenly in log from 1 to `zeta_max` (inclusive).
pub fn log_zetas(zeta_max: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let l = zeta_max.ln();
    (0..n)
        .map(|i| {
            if i + 1 == n {
                zeta_max
            } else {
                (l * i as f64 / (n - 1) as f64).exp()
            }
        })
        .collect()
}

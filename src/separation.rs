//! Mean interfacial separation ū(p), normal contact stiffness K = −dp/dū and
//! the stored elastic energy, from Persson's theory.
//!
//! # Formula
//! ```text
//! w(q)  = (π ∫_{q_l}^{q} q′³ C(q′) dq′)^{−1/2}                      (dimensionless)
//! ū(p)  = √π ∫_{q_l}^{q_s} q² C(q) w(q) ∫_p^∞ (1/p′) e^{−(w p′/E*)²} dp′ dq
//!       = √π ∫ q² C(q) w(q) · ½ E1((w p/E*)²) dq                         [m]
//! K(p)  = −dp/dū = p / (√π ∫ q² C(q) w(q) e^{−(w p/E*)²} dq)             [Pa/m]
//! U/A0  = (π/2) E* ∫ q² C(q) erf(w p/E*) dq = ∫_ū^∞ p(ū′) dū′            [J/m²]
//! ```
//! The inner p′ integral is exact: with s = (w p′/E*)², dp′/p′ = ds/(2s), so it
//! equals ½ ∫_{(wp/E*)²}^∞ e^{−s}/s ds = ½ E1((w p/E*)²) (E1 by its series and continued fraction).
//! K follows analytically from d/dp ½E1((wp/E*)²) = −(1/p) e^{−(wp/E*)²}.
//!
//! The energy is the work of the load, U/A0 = ∫_0^p p′ (−dū/dp′) dp′: with
//! P(q, p) = erf(w p/E*) the contact area of the original theory at magnification
//! q/q_l (so that (w p/E*)² = p²/(2 V_c(q)), see [`crate::corrected`]) this is
//! Persson's U_el = (π/2) E* A0 ∫ q² C(q) P(q, p) dq, whose p-derivative
//! generates ū(p) above: the three results are one consistent set (tested).
//!
//! Limits: full contact (p → ∞) ū → 0, U → (π/2)E* ∫ q² C dq; small load
//! ```text
//! ū ≈ u0 ln(p_ref/p),   u0 = √π ∫ q² C w dq,
//! ln p_ref = ln E* − γ_E/2 − (√π/u0) ∫ q² C w ln w dq                (p → 0)
//! ```
//! from E1(x²) = −γ_E − 2 ln x + O(x²); equivalently p ∝ e^{−ū/u0}.
//!
//! # Method
//! Each q-integral runs over all decades of the spectrum in the variable
//! v = √(ln(q/q_l)), q = q_l e^{v²}, dq = 2 v q dv: near q_l,
//! ∫_{q_l}^q q′³C dq′ ≈ q_l⁴ C(q_l) v², so the w ~ 1/v singularity is cancelled
//! by the Jacobian and the integrand is smooth (on the first segment v = t²
//! also tames the ln v left by ln w and by E1 at small p). Adaptive Gauss–Kronrod with
//! relative tolerance `tolerance`; w(q) comes from the spectrum's exact
//! `moment(3, q_l, q)` (closed form for self-affine and tabulated spectra).
//! Kinks of C (a roll-off, table nodes) can be given as break points.
//!
//! # References
//! - B. N. J. Persson, "Relation between interfacial separation and load: a
//!   general theory of contact mechanics", Phys. Rev. Lett. 99, 125502 (2007),
//!   Eqs. (4)–(6) (ū(p), w(q), U_el) and the small-load law p ∝ exp(−ū/u0).
//! - C. Yang and B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214 (2008),
//!   Sec. 3 (the same ū(p); their γ-corrected w(q, p) is not implemented here).
//! - Abramowitz & Stegun 5.1.1 (E1) and 5.1.11 (its small-x expansion).

use std::cell::RefCell;

use crate::error::{check, Error, Result};
use crate::quad::{integrate_counted, Estimate};
use crate::special::{e1, erf, EULER_GAMMA};
use crate::spectrum::Spectrum;

/// Default relative tolerance of the q-integrals.
pub const DEFAULT_TOLERANCE: f64 = 1e-10;

/// Integrand evaluations allowed per integral.
const MAX_EVALS: usize = 2_000_000;

/// (w p/E*)² beyond which e^{−x²} and E1(x²) underflow (E1(745) ≈ 0).
const UNDERFLOW_ARG: f64 = 745.0;

/// Mean separation, stiffness and elastic energy at one pressure.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct SeparationPoint {
    /// Nominal pressure σ0, Pa.
    pub nominal_pressure: f64,
    /// Mean interfacial separation ū, m.
    pub mean_separation: f64,
    /// Absolute error estimate of ū, m.
    pub mean_separation_error_bound: f64,
    /// Normal contact stiffness per unit area K = −dp/dū, Pa/m (`+∞`, JSON
    /// `null`, when it overflows f64 near full contact).
    pub stiffness: f64,
    /// Absolute error estimate of K, Pa/m.
    pub stiffness_error_bound: f64,
    /// Elastic energy stored per unit nominal area U/A0, J/m².
    pub elastic_energy: f64,
    /// Absolute error estimate of U/A0, J/m².
    pub elastic_energy_error_bound: f64,
}

/// Small-load asymptote ū ≈ u0 ln(p_ref/p).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct LowLoadLaw {
    /// u0 = √π ∫ q² C w dq, m.
    pub length: Estimate,
    /// p_ref, Pa.
    pub reference_pressure: Estimate,
}

/// ū(p), K(p) and U(p) for one spectrum and contact modulus.
pub struct Separation<'a> {
    spectrum: &'a dyn Spectrum,
    contact_modulus: f64,
    tolerance: f64,
    /// Segment ends in v = √(ln(q/q_l)), ascending, from 0 to v_max.
    knots: Vec<f64>,
}

impl<'a> Separation<'a> {
    /// The model for `spectrum` and E* = `contact_modulus` (Pa).
    ///
    /// # Errors
    /// `contact_modulus` not finite and positive.
    pub fn new(spectrum: &'a dyn Spectrum, contact_modulus: f64) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        let q_l = spectrum.q_min();
        let v_max = (spectrum.q_max() / q_l).ln().sqrt();
        check::positive("q_max / q_min - 1", spectrum.q_max() / q_l - 1.0)?;
        Ok(Separation {
            spectrum,
            contact_modulus,
            tolerance: DEFAULT_TOLERANCE,
            knots: vec![0.0, v_max],
        })
    }

    /// Set the relative tolerance of every q-integral.
    ///
    /// # Errors
    /// Tolerance outside [1e-15, 0.1].
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        self.tolerance = check::tolerance("tolerance", tolerance)?;
        Ok(self)
    }

    /// Split the q-integrals at these wavevectors (1/m), e.g. the roll-off q_r:
    /// kinks of C(q) then fall on segment ends. Values outside (q_l, q_s) are ignored.
    pub fn with_breaks(mut self, breaks: &[f64]) -> Self {
        let q_l = self.spectrum.q_min();
        let q_s = self.spectrum.q_max();
        for &q in breaks {
            if q.is_finite() && q > q_l && q < q_s {
                self.knots.push((q / q_l).ln().sqrt());
            }
        }
        self.knots.sort_by(f64::total_cmp);
        self.knots.dedup();
        self
    }

    /// E*.
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }

    /// ∫_{q_l}^{q_s} kernel(q, C(q), w(q)) dq in v = √(ln(q/q_l)).
    ///
    /// Near q_l, rounding q = q_l + Δ to f64 perturbs Δ by up to ε q_l, and
    /// w ∝ (π q_l³ C Δ)^{−1/2} would inherit a relative error ε q_l/(2Δ) that
    /// makes the integrand noisy as Δ → 0. The moment over the rounded
    /// interval is therefore rescaled by Δ/(q − q_l): the mean of q³C over the
    /// interval barely depends on its width, so m3 keeps full precision.
    fn integral(
        &self,
        what: &str,
        abs_tol: f64,
        kernel: impl Fn(f64, f64, f64) -> f64,
    ) -> Result<(Estimate, usize)> {
        let q_l = self.spectrum.q_min();
        let failure: RefCell<Option<Error>> = RefCell::new(None);
        let integrand = |v: f64| {
            // q − q_l = Δ is known to full relative precision, q itself only
            // to ε·q: rescale the moment by Δ/(q − q_l) so that w is accurate
            // even where Δ ≪ q_l (w ∝ Δ^{−1/2} there; see `integral` docs).
            let delta = q_l * (v * v).exp_m1();
            let q = q_l + delta;
            let width = q - q_l;
            let m3 = if width > 0.0 {
                match self.spectrum.moment(3, q_l, q) {
                    Ok(m) => m.value * (delta / width),
                    Err(e) => {
                        failure.borrow_mut().get_or_insert(e);
                        return f64::NAN;
                    }
                }
            } else {
                q_l * q_l * q_l * self.spectrum.c(q_l) * delta
            };
            let c = self.spectrum.c(q);
            if m3.is_nan() || m3 <= 0.0 || c == 0.0 {
                return 0.0;
            }
            let w = 1.0 / (std::f64::consts::PI * m3).sqrt();
            kernel(q, c, w) * 2.0 * v * q
        };
        let mut total = (
            Estimate {
                value: 0.0,
                error: 0.0,
            },
            0,
        );
        for (i, pair) in self.knots.windows(2).enumerate() {
            let r = if i == 0 {
                // v = t² on the first segment: ln w ~ −ln v (u0's p_ref and ū at
                // small p) becomes 2t ln t, which Gauss–Kronrod resolves.
                integrate_counted(
                    what,
                    |t: f64| integrand(t * t) * 2.0 * t,
                    pair[0].sqrt(),
                    pair[1].sqrt(),
                    abs_tol,
                    self.tolerance,
                    MAX_EVALS,
                )
            } else {
                integrate_counted(
                    what,
                    integrand,
                    pair[0],
                    pair[1],
                    abs_tol,
                    self.tolerance,
                    MAX_EVALS,
                )
            };
            if let Some(e) = failure.borrow_mut().take() {
                return Err(e);
            }
            let r = r?;
            total.0.value += r.0.value;
            total.0.error += r.0.error;
            total.1 += r.1;
        }
        Ok(total)
    }

    /// Mean interfacial separation ū(p), m (see the module docs).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `nominal_pressure` not finite and
    /// positive, or naming `nominal_pressure` or `contact_modulus` when
    /// E*/σ0 is so large that G = (E*/σ0)²⟨|∇h|²⟩/8 overflows f64 (the bound
    /// of `theory::check_g_finite`: (w(q_s)σ0/E*)² = 1/(4G) underflows
    /// there); quadrature failure.
    ///
    /// # Examples
    /// ```
    /// use persson::separation::Separation;
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// let s = SelfAffine::new(1e3, 1e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
    /// let sep = Separation::new(&s, 1.0).unwrap().with_breaks(&[1e4]);
    /// // mpmath (tanh-sinh, 25 digits): ū(p = 1e-3 E*) = 6.8432763617407e-5 m
    /// let u = sep.mean_separation(1e-3).unwrap();
    /// assert!((u.value - 6.843_276_361_740_7e-5).abs() < 1e-9 * u.value);
    /// ```
    pub fn mean_separation(&self, pressure: f64) -> Result<Estimate> {
        self.check_pressure(pressure)?;
        let r = pressure / self.contact_modulus;
        let sqrt_pi = std::f64::consts::PI.sqrt();
        let (q, _) = self.integral("mean separation", f64::MIN_POSITIVE, |q, c, w| {
            let x2 = (w * r) * (w * r);
            if x2 >= UNDERFLOW_ARG {
                0.0
            } else {
                sqrt_pi * q * q * c * w * 0.5 * e1(x2)
            }
        })?;
        Ok(with_rounding(q))
    }

    /// Normal contact stiffness per unit area K = −dp/dū, Pa/m.
    ///
    /// # Formula
    /// ```text
    /// −dū/dp = (√π/p) ∫ q² C w e^{−(w p/E*)²} dq,   K = 1/(−dū/dp)
    /// ```
    /// The exponential is scaled by its largest value e^{−x_s²},
    /// x_s = w(q_s) p/E* (w decreases with q), so K stays accurate until it
    /// overflows f64 near full contact (ln K > ln f64::MAX, decided in log
    /// space); it is then `+∞` (error 0), the full-contact limit, beside a
    /// finite ū and U.
    ///
    /// # Errors
    /// As [`Separation::mean_separation`]; [`Error::InvalidParameter`] naming
    /// `nominal_pressure` (or `contact_modulus` beyond 1e±30) where the
    /// exponent (w(q_s)σ0/E*)² itself overflows, σ0/E* > √f64::MAX/w(q_s)
    /// (`check_stiffness_exponent`).
    pub fn stiffness(&self, pressure: f64) -> Result<Estimate> {
        self.check_pressure(pressure)?;
        let r = pressure / self.contact_modulus;
        let sqrt_pi = std::f64::consts::PI.sqrt();
        let w_min = check_stiffness_exponent(self.spectrum, self.contact_modulus, pressure)?;
        let x_s2 = (w_min * r).powi(2);
        let (q, evals) = self.integral("contact stiffness", f64::MIN_POSITIVE, |q, c, w| {
            let x2 = (w * r) * (w * r) - x_s2;
            if x2 >= UNDERFLOW_ARG {
                0.0
            } else {
                sqrt_pi * q * q * c * w * (-x2).exp()
            }
        })?;
        let scaled = with_rounding(q);
        // A scaled integral of exactly 0 (every node underflowed) is full
        // contact: ln K = +∞ below, like an overflowing K.
        if scaled.value.is_nan() || scaled.value < 0.0 {
            return Err(Error::NotConverged {
                what: format!("contact stiffness at p = {pressure:e} (compliance vanishes)"),
                iterations: evals,
                residual: scaled.value,
                tolerance: self.tolerance,
            });
        }
        // K = p e^{x_s²} / I_scaled, computed from its logarithm: +∞ where
        // it overflows f64 (an I_scaled of exactly 0, every node underflowed,
        // is ln K = +∞)
        let k = (pressure.ln() + x_s2 - scaled.value.ln()).exp();
        if !k.is_finite() {
            return Ok(Estimate {
                value: f64::INFINITY,
                error: 0.0,
            });
        }
        Ok(Estimate {
            value: k,
            error: k * scaled.error / scaled.value + 4.0 * f64::EPSILON * k * (1.0 + x_s2),
        })
    }

    /// σ0 finite and positive, and E*/σ0 within the bound of
    /// [`crate::theory::check_g_finite`]: beyond it (w(q_s)σ0/E*)² underflows
    /// (it is 1/(4G) at full magnification) and E1 of it is +∞.
    fn check_pressure(&self, pressure: f64) -> Result<()> {
        check::positive("nominal_pressure", pressure)?;
        let q = (self.spectrum.q_min(), self.spectrum.q_max());
        let slope_variance = std::f64::consts::TAU * self.spectrum.moment(3, q.0, q.1)?.value;
        crate::theory::check_g_finite(self.contact_modulus, pressure, slope_variance)
    }

    /// Elastic energy stored per unit nominal area U/A0, J/m².
    ///
    /// # Formula
    /// ```text
    /// U/A0 = (π/2) E* ∫ q² C(q) erf(w p/E*) dq
    /// ```
    ///
    /// # Errors
    /// As [`Separation::mean_separation`].
    pub fn elastic_energy(&self, pressure: f64) -> Result<Estimate> {
        self.check_pressure(pressure)?;
        let r = pressure / self.contact_modulus;
        let pre = 0.5 * std::f64::consts::PI * self.contact_modulus;
        let (q, _) = self.integral("elastic energy", f64::MIN_POSITIVE, |q, c, w| {
            pre * q * q * c * erf(w * r)
        })?;
        Ok(with_rounding(q))
    }

    /// Elastic energy at full contact, (π/2) E* ∫ q² C dq, J/m² (the p → ∞ limit).
    ///
    /// # Errors
    /// Quadrature failure for a spectrum given as a function ([`crate::spectrum::FnSpectrum`]).
    pub fn full_contact_energy(&self) -> Result<Estimate> {
        let m = self
            .spectrum
            .moment(2, self.spectrum.q_min(), self.spectrum.q_max())?;
        let pre = 0.5 * std::f64::consts::PI * self.contact_modulus;
        Ok(Estimate {
            value: pre * m.value,
            error: pre * m.error + 2.0 * f64::EPSILON * pre * m.value,
        })
    }

    /// ū, K and U at one pressure.
    ///
    /// # Errors
    /// As [`Separation::mean_separation`].
    pub fn point(&self, pressure: f64) -> Result<SeparationPoint> {
        let u = self.mean_separation(pressure)?;
        let k = self.stiffness(pressure)?;
        let e = self.elastic_energy(pressure)?;
        Ok(SeparationPoint {
            nominal_pressure: pressure,
            mean_separation: u.value,
            mean_separation_error_bound: u.error,
            stiffness: k.value,
            stiffness_error_bound: k.error,
            elastic_energy: e.value,
            elastic_energy_error_bound: e.error,
        })
    }

    /// [`Separation::point`] for each pressure.
    ///
    /// # Errors
    /// As [`Separation::point`], for the first bad pressure.
    pub fn load_curve(&self, pressures: &[f64]) -> Result<Vec<SeparationPoint>> {
        for &p in pressures {
            self.check_pressure(p)?;
        }
        pressures.iter().map(|&p| self.point(p)).collect()
    }

    /// The small-load law ū ≈ u0 ln(p_ref/p) (see the module docs).
    ///
    /// # Errors
    /// Quadrature failure.
    pub fn low_load_law(&self) -> Result<LowLoadLaw> {
        let sqrt_pi = std::f64::consts::PI.sqrt();
        let (u0, _) = self.integral("low-load length u0", f64::MIN_POSITIVE, |q, c, w| {
            sqrt_pi * q * q * c * w
        })?;
        // ln w changes sign over the band: an absolute tolerance scaled by u0
        // gives ln p_ref (hence p_ref relatively) to about `tolerance`.
        let abs_tol = self.tolerance * u0.value.abs();
        let (lw, _) = self.integral("low-load ∫ q² C w ln w", abs_tol, |q, c, w| {
            sqrt_pi * q * q * c * w * w.ln()
        })?;
        let ratio = lw.value / u0.value;
        let ln_p = self.contact_modulus.ln() - 0.5 * EULER_GAMMA - ratio;
        let p_ref = ln_p.exp();
        let ratio_err = (lw.error + ratio.abs() * u0.error) / u0.value.abs();
        Ok(LowLoadLaw {
            length: with_rounding(u0),
            reference_pressure: Estimate {
                value: p_ref,
                error: p_ref * (ratio_err + 8.0 * f64::EPSILON * (1.0 + ln_p.abs())),
            },
        })
    }
}

/// Refuse a load whose stiffness exponent x_s² = (w(q_s)σ0/E*)² overflows
/// f64, naming σ0 or E* ([`crate::error::ratio_culprit`]): σ0 = 1e300 at
/// E* = 1e7 (or E* = 1e-300 at 1e7) gave "contact stiffness (integrand not
/// finite at 21 nodes) did not converge … residual 0 > tolerance 2.2e-308".
///
/// # Bound
/// x_s² ≤ f64::MAX ⇔ σ0/E* ≤ √f64::MAX/w(q_s), w(q_s) = (π ∫_{q_l}^{q_s}
/// q³C dq)^{−1/2}, tested as the routes evaluate it. Below it K is computed,
/// and is +∞ where ln K = ln σ0 + x_s² − ln I exceeds ln f64::MAX, far in
/// full contact (the theory's limit there).
/// Returns w(q_s).
pub(crate) fn check_stiffness_exponent(
    spectrum: &dyn Spectrum,
    contact_modulus: f64,
    pressure: f64,
) -> Result<f64> {
    let m = spectrum.moment(3, spectrum.q_min(), spectrum.q_max())?;
    let w_min = 1.0 / (std::f64::consts::PI * m.value).sqrt();
    let x_s2 = (w_min * (pressure / contact_modulus)).powi(2);
    if x_s2.is_finite() {
        return Ok(w_min);
    }
    let (num, approx) = (crate::error::num, crate::error::approx);
    let ratio = f64::MAX.sqrt() / w_min;
    let why = format!(
        "so that the exponent (w(q_s)σ0/E*)² of the contact stiffness K = σ0 e^{{(w(q_s)σ0/E*)²}}/I \
         stays finite in f64 (w(q_s) = {}): far beyond full contact",
        approx(w_min)
    );
    Err(
        match crate::error::ratio_culprit(contact_modulus, pressure) {
            "contact_modulus" => Error::invalid(
                "contact_modulus",
                contact_modulus,
                format!(
                    "at least {} (σ0 = {}) {why}",
                    approx(pressure / ratio),
                    num(pressure)
                ),
            ),
            _ => Error::invalid(
                "nominal_pressure",
                pressure,
                format!(
                    "at most {} (E* = {}) {why}",
                    approx(ratio * contact_modulus),
                    num(contact_modulus)
                ),
            ),
        },
    )
}

/// A quadrature's value and error plus a few ulps of rounding.
fn with_rounding(q: Estimate) -> Estimate {
    Estimate {
        value: q.value,
        error: q.error + 8.0 * f64::EPSILON * q.value.abs(),
    }
}

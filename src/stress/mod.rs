//! Stress distributions P(σ, ζ) for flat, Hertz, cylinder and tabulated
//! starts, elastic or with a finite yield stress σY.
//!
//! # Formula
//! Persson's diffusion equation (Persson, Bucher & Chiaia (2002), Eq. 1) in dimensionless form:
//! ```text
//! s = σ/σH,   y = σY/σH,   τ = (σ0/σH)² G(ζ),   w = 2√τ
//! ∂P/∂τ = ∂²P/∂s²,   P(s, 0) = P0(s),   P(0, τ) = 0,   P(y, τ) = 0
//! A_el = ∫₀^y P ds,   A_pl = ∫₀^τ −∂ₛP(y, t) dt,   A_el + A_pl + A_nc = 1
//! ```
//! σH is the largest pressure of the start (the Hertz peak; σH = σ0 for a flat
//! punch) and σ0 the nominal **mean** pressure, so G is the G(ζ) of
//! [`crate::theory::Persson::g`]. Densities are in units of 1/σH.
//!
//! Three representations are used, each where it is fast and accurate, and
//! every result says which (`method`):
//! - elastic (y = ∞): the method of images, P(s) = Q(s) = ∫₀¹ P0(u)[φ(s−u) − φ(s+u)] du
//!   in closed form (flat, Hertz) or by Gauss rules with a Bernstein-ellipse
//!   error bound (cylinder);
//! - finite y, τ ≳ y²/400: the Fourier sine series (their Eqs. 7, 10) with a
//!   rigorous tail bound;
//! - finite y, τ small: the sum over images for two absorbing walls.
//!
//! ```text
//! φ(z) = e^{−z²/w²}/(w√π)
//! flat:   P = φ(s − 1)(1 − e^{−4s/w²})
//! Hertz:  P = s[erf((1−s)/w) + erf((1+s)/w)] − (w/√π) e^{−(1−s)²/w²}(1 − e^{−4s/w²})
//! series: P = (2/y) Σ Bₙ e^{−(nπ/y)²τ} sin(nπs/y),  Bₙ = sin(nπ/y), 2j₁(nπ/y), (π/2)J₁(nπ/y)
//! images: P = Σₖ Q(s − 2ky)
//! A∞    = ∫₀¹ P0(u) erf(u/w) du      (flat erf(1/w); Hertz, cylinder: HertzContact)
//! A_el  = Σ_{n odd} (4/(nπ)) Bₙ Eₙ            = A∞ − F(y) + F(2y) − …
//! A_pl  = σ0/σY − Σ (−1)ⁿ⁺¹ (2/(nπ)) Bₙ Eₙ   = Σ_{j≥0} F((2j+1)y)
//! F(x)  = ∫₀¹ P0(u)[erfc((x−u)/w) − erfc((x+u)/w)] du
//! ```
//! Every sum is absolutely convergent: the plastic series has its τ → ∞ limit
//! σ0/σY subtracted analytically, and the image sum for A_pl has positive
//! terms. The series is used for A_el when τ/y² ≥ 0.02 and for A_pl when
//! τ/y² ≥ 0.25, where the image sums would cancel.
//!
//! # Accuracy
//! Each result carries a bound on its absolute error: series tails bounded by
//! Σ_{n>N} e^{−n²a} (|Bₙ| ≤ 1), Gauss rules by the Bernstein-ellipse theorem,
//! the Gaussian windows by their cut tails, adaptive quadrature by its
//! estimate, plus rounding. Relative rounding of the density is a few 1e-15,
//! so tolerances below ~1e-14 (relative to the density) cannot be met; the
//! bound then says so rather than the tolerance. G and y are taken as exact;
//! the series exponents n²π²(σ0/σH)²G/y² are formed in double-double so that
//! σ0/σH = 2/3, π/4 add no error to e^{−n²a} even when n²a is in the hundreds.
//!
//! # References
//! B. N. J. Persson, F. Bucher, B. Chiaia, PRB 65, 184106 (2002), Eqs. 1, 3, 7–12
//! doi:10.1103/PhysRevB.65.184106.

mod elastic;
mod gauss;
mod images;
mod method;
mod physical;
mod series;
mod start;

pub use method::{DensityMethod, FractionMethod, FractionMethods, ImageQuadrature, StressMethod};
pub use physical::{PhysicalCurve, StressScene};
pub use start::{HertzContact, Start, StartKind, TabulatedStart};

use crate::error::{check, Error, Result};
use crate::quad::Estimate;
use elastic::Images;
use series::Series;

/// Above this many sine terms for the density, the image sum is used.
const MAX_SERIES_TERMS: usize = 40;
/// τ/y² above which A_el comes from the sine series (below: images, whose
/// alternating sum would cancel for larger τ).
const SERIES_CONTACT_RATIO: f64 = 0.02;
/// τ/y² above which A_pl comes from the sine series (below: the positive image sum).
const SERIES_PLASTIC_RATIO: f64 = 0.25;

/// A stress distribution at one magnification, dimensionless.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct StressCurve {
    /// s = σ/σH where the density was evaluated.
    pub sigma_ratio: Vec<f64>,
    /// σH P(σ): the density over s = σ/σH (dimensionless).
    pub scaled_density: Vec<f64>,
    /// A/A0 = A_el/A0 + A_pl/A0, the total contact fraction.
    pub contact_fraction: f64,
    /// A_el/A0 = ∫₀^σY P dσ, the elastically loaded fraction.
    pub elastic_fraction: f64,
    /// A_pl/A0, the plastically yielded fraction (0 when elastic).
    pub plastic_fraction: f64,
    /// 1 − A_el − A_pl, the fraction that lost contact.
    pub non_contact_fraction: f64,
    /// Bound on the absolute error of every density value (1/σH) and of both
    /// fractions: the largest of the three bounds below.
    pub error_bound: f64,
    /// Bound on the absolute error of the density values (1/σH).
    pub scaled_density_error_bound: f64,
    /// Bound on the absolute error of `elastic_fraction`.
    pub elastic_fraction_error_bound: f64,
    /// Bound on the absolute error of `plastic_fraction`.
    pub plastic_fraction_error_bound: f64,
    /// G(ζ).
    pub g: f64,
    /// τ = (σ0/σH)² G.
    pub tau: f64,
    /// y = σY/σH, `None` when elastic.
    pub yield_ratio: Option<f64>,
    /// How the density and the fractions were computed.
    pub method: StressMethod,
}

/// A_el/A0 and A_pl/A0 of a [`Solver`], each with a bound on its absolute
/// error, and how they were computed.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Fractions {
    /// A_el/A0, the elastically loaded fraction (the contact fraction when
    /// elastic).
    pub elastic_fraction: Estimate,
    /// A_pl/A0, the plastically yielded fraction (0 when elastic).
    pub plastic_fraction: Estimate,
    /// How each was computed.
    pub method: FractionMethods,
}

/// Which representation of the finite-yield density to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Sine series when it needs at most 40 terms, else images.
    #[default]
    Auto,
    /// Always the sine series (however many terms; for cross-checks).
    Series,
    /// Always the image sum.
    Images,
}

/// How the density is evaluated.
enum Density<'a> {
    /// G = 0: P = P0.
    Start,
    Images(Images<'a>),
    Series(Series),
}

/// The stress distribution for one start, one G and one yield ratio,
/// prepared once (coefficients, rules) and evaluated at any s.
pub struct Solver<'a> {
    start: &'a Start,
    g: f64,
    y: f64,
    tau: f64,
    tol: f64,
    density: Density<'a>,
}

impl<'a> Solver<'a> {
    /// Prepare P(s) for `start` at G = `g` with yield ratio y = σY/σH
    /// (`None`: elastic), to absolute tolerance `tol` (units of 1/σH).
    ///
    /// # Formula
    /// ```text
    /// series if N(τ) ≤ 40 terms, N: (2/y) Σ_{n>N} e^{−n²π²τ/y²} ≤ tol/100; else images
    /// ```
    ///
    /// # Errors
    /// G negative or non-finite; y ≤ 1 or non-finite; tol outside [1e-15, 0.1];
    /// quadrature failure (tabulated starts).
    ///
    /// # Examples
    /// ```
    /// use persson::stress::{Solver, Start};
    /// // Persson, Bucher & Chiaia (2002), Fig. 3: Hertz ball at G = 0.6, A/A0 = 0.615097 (docs/accuracy.md)
    /// let s = Solver::new(&Start::Hertz, 0.6, None, 1e-12).unwrap();
    /// let c = s.curve(&[0.5]).unwrap();
    /// assert!((c.contact_fraction - 0.615_097).abs() < 1e-6);
    /// ```
    pub fn new(start: &'a Start, g: f64, yield_ratio: Option<f64>, tol: f64) -> Result<Self> {
        Self::with_method(start, g, yield_ratio, tol, Method::Auto)
    }

    /// As [`Solver::new`], forcing the representation of a finite-yield density
    /// (ignored when elastic or at G = 0).
    ///
    /// # Errors
    /// As [`Solver::new`]; [`Method::Series`] needing more than 10⁶ terms.
    pub fn with_method(
        start: &'a Start,
        g: f64,
        yield_ratio: Option<f64>,
        tol: f64,
        method: Method,
    ) -> Result<Self> {
        check::non_negative("g", g)?;
        check::tolerance("tolerance", tol)?;
        let y = match yield_ratio {
            None => f64::INFINITY,
            Some(r) => {
                if !(r.is_finite() && r > 1.0) {
                    return Err(Error::invalid(
                        "yield_ratio",
                        r,
                        "finite and > 1 (σY above the peak pressure σH)",
                    ));
                }
                r
            }
        };
        let m = start.mean_ratio();
        let tau = m * m * g;
        let density = if g == 0.0 {
            Density::Start
        } else if y.is_finite() {
            let a = series::decay_rate(start, g, y);
            let n = series::terms_for(a.0, 2.0 / y, 0.01 * tol);
            let use_series = match method {
                Method::Auto => n <= MAX_SERIES_TERMS,
                Method::Series => true,
                Method::Images => false,
            };
            if use_series && n > 1_000_000 {
                return Err(Error::NotConverged {
                    what: "stress: sine series (too many terms; use images)".into(),
                    iterations: n,
                    residual: f64::INFINITY,
                    tolerance: tol,
                });
            }
            if use_series {
                Density::Series(Series::new(start, y, a, 0.01 * tol, tol)?)
            } else {
                Density::Images(Images::new(start, 2.0 * tau.sqrt(), tol))
            }
        } else {
            Density::Images(Images::new(start, 2.0 * tau.sqrt(), tol))
        };
        Ok(Solver {
            start,
            g,
            y,
            tau,
            tol,
            density,
        })
    }

    /// τ = (σ0/σH)² G.
    pub fn tau(&self) -> f64 {
        self.tau
    }

    /// P(s) (units of 1/σH) with a bound on its absolute error.
    ///
    /// # Errors
    /// s not finite; quadrature failure (tabulated starts).
    pub fn density(&self, s: f64) -> Result<Estimate> {
        if !s.is_finite() {
            return Err(Error::invalid("sigma", s, "finite"));
        }
        let zero = Estimate {
            value: 0.0,
            error: 0.0,
        };
        if s <= 0.0 || s >= self.y {
            return Ok(zero);
        }
        match &self.density {
            Density::Start => Ok(Estimate {
                value: self.start.density(s),
                error: 0.0,
            }),
            Density::Series(ser) => Ok(ser.density(s)),
            Density::Images(img) => Ok(images::density(img, self.y, s)?.0),
        }
    }

    /// A_el and A_pl with error bounds, and how each was computed.
    ///
    /// # Errors
    /// Quadrature failure.
    pub fn fractions(&self) -> Result<Fractions> {
        let zero = Estimate {
            value: 0.0,
            error: 0.0,
        };
        if self.g == 0.0 {
            return Ok(Fractions {
                elastic_fraction: Estimate {
                    value: 1.0,
                    error: 0.0,
                },
                plastic_fraction: zero,
                method: FractionMethods {
                    elastic_fraction: FractionMethod::StartCondition,
                    plastic_fraction: None,
                },
            });
        }
        let w = 2.0 * self.tau.sqrt();
        if !self.y.is_finite() {
            let (el, _, _) = images::fractions(self.start, w, self.y)?;
            let c = 1.0 / w;
            let how = match self.start {
                Start::Flat => FractionMethod::ErfClosedForm,
                Start::Hertz if c >= std::f64::consts::FRAC_1_SQRT_2 => {
                    FractionMethod::ErfClosedForm
                }
                Start::Hertz => FractionMethod::PowerSeries,
                Start::Cylinder if c <= 1.0 => FractionMethod::PowerSeries,
                _ => FractionMethod::AdaptiveQuadrature,
            };
            return Ok(Fractions {
                elastic_fraction: el,
                plastic_fraction: zero,
                method: FractionMethods {
                    elastic_fraction: how,
                    plastic_fraction: None,
                },
            });
        }
        let r = self.tau / (self.y * self.y);
        let a = series::decay_rate(self.start, self.g, self.y);
        let ser = if r >= SERIES_CONTACT_RATIO {
            Some(series::fractions(self.start, self.y, a, self.tol)?)
        } else {
            None
        };
        let img = if r < SERIES_PLASTIC_RATIO {
            Some(images::fractions(self.start, w, self.y)?)
        } else {
            None
        };
        let (el, how_el) = match (&ser, &img) {
            (Some(s), _) => (s.0, FractionMethod::SineSeries { terms: s.2 }),
            (None, Some(i)) => (i.0, FractionMethod::ImageSum { images: i.2 }),
            _ => unreachable!("SERIES_CONTACT_RATIO < SERIES_PLASTIC_RATIO"),
        };
        let (pl, how_pl) = match (&ser, &img) {
            (_, Some(i)) => (i.1, FractionMethod::ImageSum { images: i.2 }),
            (Some(s), None) => (s.1, FractionMethod::SineSeries { terms: s.2 }),
            _ => unreachable!("SERIES_CONTACT_RATIO < SERIES_PLASTIC_RATIO"),
        };
        Ok(Fractions {
            elastic_fraction: el,
            plastic_fraction: pl,
            method: FractionMethods {
                elastic_fraction: how_el,
                plastic_fraction: Some(how_pl),
            },
        })
    }

    /// How the density is evaluated.
    pub(crate) fn method(&self) -> DensityMethod {
        match &self.density {
            Density::Start => DensityMethod::StartCondition,
            Density::Series(s) => DensityMethod::SineSeries { terms: s.len() },
            Density::Images(i) => DensityMethod::ImageSum {
                walls: if self.y.is_finite() { 2 } else { 1 },
                quadrature: i.method,
                images: None,
            },
        }
    }

    /// The density at every s of `sigma` and both fractions.
    ///
    /// # Errors
    /// A non-finite s; quadrature failure.
    pub fn curve(&self, sigma: &[f64]) -> Result<StressCurve> {
        let mut density = Vec::with_capacity(sigma.len());
        let mut derr: f64 = 0.0;
        let mut images_used = 0;
        for &s in sigma {
            let e = match &self.density {
                Density::Images(img) if self.y.is_finite() && s > 0.0 && s < self.y => {
                    let (e, k) = images::density(img, self.y, s)?;
                    images_used = images_used.max(k);
                    e
                }
                _ => self.density(s)?,
            };
            density.push(e.value);
            derr = derr.max(e.error);
        }
        let Fractions {
            elastic_fraction: el,
            plastic_fraction: pl,
            method: how,
        } = self.fractions()?;
        let error_bound = derr.max(el.error).max(pl.error);
        let mut density_method = self.method();
        if let DensityMethod::ImageSum { images, .. } = &mut density_method {
            *images = (images_used > 0).then_some(images_used);
        }
        Ok(StressCurve {
            sigma_ratio: sigma.to_vec(),
            scaled_density: density,
            contact_fraction: el.value + pl.value,
            elastic_fraction: el.value,
            plastic_fraction: pl.value,
            non_contact_fraction: 1.0 - el.value - pl.value,
            error_bound,
            scaled_density_error_bound: derr,
            elastic_fraction_error_bound: el.error,
            plastic_fraction_error_bound: pl.error,
            g: self.g,
            tau: self.tau,
            yield_ratio: self.y.is_finite().then_some(self.y),
            method: StressMethod {
                density: density_method,
                fractions: how,
            },
        })
    }

    /// `n` evenly spaced s from 0 to the end of the distribution:
    /// min(y, 1 + L w) with e^{−L²} ≈ 1e-17 (and 1 at G = 0).
    pub fn grid(&self, n: usize) -> Vec<f64> {
        let top = (1.0 + 12.5 * self.tau.sqrt()).min(self.y);
        let n = n.max(2);
        (0..n).map(|i| top * i as f64 / (n - 1) as f64).collect()
    }
}

/// P(σ, ζ) for given G in dimensionless form: convenience over [`Solver`].
///
/// # Errors
/// As [`Solver::new`] and [`Solver::curve`].
pub fn distribution(
    start: &Start,
    g: f64,
    yield_ratio: Option<f64>,
    sigma: &[f64],
    tol: f64,
) -> Result<StressCurve> {
    Solver::new(start, g, yield_ratio, tol)?.curve(sigma)
}

/// A_el and A_pl from the first `terms` terms of the sine series: the series'
/// accuracy knob made explicit (the solver picks the terms from its tolerance).
///
/// # Formula
/// ```text
/// A_el = Σ_{n ≤ N, odd} (4/(nπ)) Bₙ Eₙ,   A_pl = σ0/σY − Σ_{n ≤ N} (−1)ⁿ⁺¹ (2/(nπ)) Bₙ Eₙ
/// |truncation| ≤ (4/π) Σ_{n>N} e^{−n²π²τ/y²}
/// ```
/// Both bounds include the truncation, the coefficients' and the rounding error.
///
/// # Errors
/// G not finite and positive; y ≤ 1 or non-finite; `terms` outside 1 … 10⁶;
/// quadrature failure (tabulated starts).
///
/// # Examples
/// ```
/// use persson::stress::{series_fractions, Start};
/// // Hertz, G = 0.6, σY/σH = 2: A_el = 0.534395493429437 (mpmath, tests/reference)
/// let (few, _) = series_fractions(&Start::Hertz, 0.6, 2.0, 2).unwrap();
/// let (el, pl) = series_fractions(&Start::Hertz, 0.6, 2.0, 12).unwrap();
/// assert!((few.value - 0.534_395_493_429_437).abs() <= few.error);
/// assert!((el.value - 0.534_395_493_429_437).abs() < 1e-14);
/// assert!((pl.value - 0.080_712_734_513_447).abs() < 1e-14);
/// ```
///
/// # References
/// Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Eqs. 7, 10.
pub fn series_fractions(
    start: &Start,
    g: f64,
    yield_ratio: f64,
    terms: usize,
) -> Result<(Estimate, Estimate)> {
    check::positive("g", g)?;
    if !(yield_ratio.is_finite() && yield_ratio > 1.0) {
        return Err(Error::invalid(
            "yield_ratio",
            yield_ratio,
            "finite and > 1 (σY above the peak pressure σH)",
        ));
    }
    if !(1..=1_000_000).contains(&terms) {
        return Err(Error::invalid("terms", terms as f64, "from 1 to 1e6"));
    }
    let a = series::decay_rate(start, g, yield_ratio);
    let (el, pl, _) = series::fractions_with_terms(start, yield_ratio, a, 1e-15, terms)?;
    Ok((el, pl))
}

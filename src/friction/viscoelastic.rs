//! The rubber's complex modulus E(ω) = E′(ω) + i E″(ω) at the reference
//! temperature: a Prony series (a standard linear solid is its one-term case)
//! or a tabulated master curve, and the two angular integrals the friction
//! theory needs.
//!
//! # Formula
//! Time convention e^{−iωt}, so that E″(ω) > 0 for ω > 0 (dissipation) and
//! E(−ω) = conj E(ω). The angular integrals, for w = q v ≥ 0 (rad/s):
//! ```text
//! ∫₀^{2π} dφ cos φ Im E(w cos φ) = 4 A(w),   A(w) = ∫₀^{π/2} dφ cos φ E″(w cos φ)   [Pa]
//! ∫₀^{2π} dφ |E(w cos φ)|²       = 4 B(w),   B(w) = ∫₀^{π/2} dφ |E(w cos φ)|²       [Pa²]
//! ```
//! (the four quadrants are equal because E″ is odd and |E|² even in ω).
//! For a Prony series E(ω) = E∞ + Σ_k E_k iωτ_k/(1 + iωτ_k) both are closed
//! forms (a_k = w τ_k, h_k = √(1 + a_k²)):
//! ```text
//! J(a) = ∫₀^{π/2} a² cos²φ/(1 + a² cos²φ) dφ = (π/2) a²/(h (1 + h))
//! A(w) = Σ_k E_k J(a_k)/a_k
//! B(w) = (π/2) E∞² + 2 E∞ Σ_k E_k J(a_k)
//!        + Σ_j Σ_k E_j E_k (a_k J(a_j) + a_j J(a_k))/(a_j + a_k)
//! ```
//! Every term is non-negative, so B keeps full relative accuracy even where
//! |E|² ≪ E_k² (the rubbery plateau under a glassy modulus a thousand times
//! larger). The double-sum term is ∫ Re[(iωτ_j/(1+iωτ_j)) conj(iωτ_k/(1+iωτ_k))] dφ,
//! reduced by partial fractions in cos²φ (derived here; checked against
//! quadrature in the tests).

use std::f64::consts::FRAC_PI_2;
use std::path::Path;

use super::columns::{cell_error, parse_rows};
use super::master_curve::MasterCurve;
pub(crate) use super::modulus::modulus_requirement;
pub use super::modulus::{AngularIntegrals, Modulus, MAX_MODULUS};
use crate::error::{Error, Result};

/// One term E_k e^{−t/τ_k} of a Prony series.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PronyTerm {
    /// E_k, Pa.
    pub modulus: f64,
    /// τ_k, s.
    pub relaxation_time: f64,
}

/// A generalised Maxwell solid: E(t) = E∞ + Σ_k E_k e^{−t/τ_k}.
///
/// # Formula
/// ```text
/// E(ω) = E∞ + Σ_k E_k iωτ_k/(1 + iωτ_k)
/// E′ = E∞ + Σ_k E_k ω²τ_k²/(1 + ω²τ_k²),   E″ = Σ_k E_k ωτ_k/(1 + ω²τ_k²)
/// ```
/// E∞ (`relaxed_modulus`) is the long-time (ω → 0) modulus, E∞ + Σ E_k the
/// instantaneous (ω → ∞) one; E_k in Pa, τ_k in s.
///
/// # References
/// J. D. Ferry, *Viscoelastic Properties of Polymers*, 3rd ed. (Wiley, 1980),
/// ch. 3 (the generalised Maxwell model).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Prony {
    relaxed_modulus: f64,
    terms: Vec<PronyTerm>,
}

impl Prony {
    /// A Prony series from E∞ and its terms (none: an elastic solid, E″ = 0).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `relaxed_modulus` (finite, ≥ 0),
    /// `prony_modulus[k]` or `relaxation_time[k]` (finite, > 0); E∞ = 0 with
    /// no terms (a zero modulus); a glassy modulus E∞ + Σ E_k above
    /// [`MAX_MODULUS`] (naming `relaxed_modulus` or the largest term's
    /// `prony_modulus[k]`).
    pub fn new(relaxed_modulus: f64, terms: &[PronyTerm]) -> Result<Self> {
        if !(relaxed_modulus.is_finite() && relaxed_modulus >= 0.0) {
            return Err(Error::invalid(
                "relaxed_modulus",
                relaxed_modulus,
                "finite and >= 0",
            ));
        }
        for (k, t) in terms.iter().enumerate() {
            if !(t.modulus.is_finite() && t.modulus > 0.0) {
                return Err(Error::invalid(
                    format!("prony_modulus[{k}]"),
                    t.modulus,
                    "finite and > 0",
                ));
            }
            if !(t.relaxation_time.is_finite() && t.relaxation_time > 0.0) {
                return Err(Error::invalid(
                    format!("relaxation_time[{k}]"),
                    t.relaxation_time,
                    "finite and > 0",
                ));
            }
        }
        if relaxed_modulus == 0.0 && terms.is_empty() {
            return Err(Error::invalid(
                "relaxed_modulus",
                0.0,
                "> 0 when the series has no terms",
            ));
        }
        let glassy = relaxed_modulus + terms.iter().map(|t| t.modulus).sum::<f64>();
        if glassy > MAX_MODULUS {
            // name the largest part of the sum: the typing error
            let (name, value) = terms
                .iter()
                .enumerate()
                .map(|(k, t)| (format!("prony_modulus[{k}]"), t.modulus))
                .fold(
                    ("relaxed_modulus".to_string(), relaxed_modulus),
                    |best, x| if x.1 > best.1 { x } else { best },
                );
            return Err(Error::invalid(
                name,
                value,
                format!(
                    "such that the glassy modulus E∞ + Σ E_k (here {}) is at most \
                     √f64::MAX/4 = {} Pa, so that |E|² stays finite",
                    crate::error::approx(glassy),
                    crate::error::approx(MAX_MODULUS)
                ),
            ));
        }
        Ok(Prony {
            relaxed_modulus,
            terms: terms.to_vec(),
        })
    }

    /// The standard linear solid E(t) = E∞ + (E0 − E∞) e^{−t/τ}: the Prony
    /// series with one term.
    ///
    /// # Formula
    /// ```text
    /// E(ω) = E∞ + (E0 − E∞) iωτ/(1 + iωτ)
    /// ```
    /// E0 (`instantaneous_modulus`, ω → ∞) and E∞ (`relaxed_modulus`, ω → 0)
    /// in Pa, τ (`relaxation_time`) in s.
    ///
    /// # Errors
    /// E∞ not finite and > 0; E0 not finite or not > E∞ (E″ > 0 is required;
    /// an elastic solid is `Prony::new(E, &[])`) or above [`MAX_MODULUS`]; τ
    /// not finite and > 0.
    ///
    /// # Examples
    /// ```
    /// use persson::friction::Prony;
    /// let sls = Prony::standard_linear_solid(1e9, 1e6, 1e-3).unwrap();
    /// // At ωτ = 1: E″ = (E0 − E∞)/2.
    /// let e = sls.modulus(1e3);
    /// assert!((e.loss_modulus - 0.5 * (1e9 - 1e6)).abs() < 1e-6);
    /// ```
    pub fn standard_linear_solid(
        instantaneous_modulus: f64,
        relaxed_modulus: f64,
        relaxation_time: f64,
    ) -> Result<Self> {
        if !(relaxed_modulus.is_finite() && relaxed_modulus > 0.0) {
            return Err(Error::invalid(
                "relaxed_modulus",
                relaxed_modulus,
                "finite and > 0",
            ));
        }
        if !(instantaneous_modulus.is_finite() && instantaneous_modulus > relaxed_modulus) {
            return Err(Error::invalid(
                "instantaneous_modulus",
                instantaneous_modulus,
                format!("finite and > relaxed_modulus = {relaxed_modulus:e}"),
            ));
        }
        if instantaneous_modulus > MAX_MODULUS {
            return Err(Error::invalid(
                "instantaneous_modulus",
                instantaneous_modulus,
                modulus_requirement(),
            ));
        }
        Self::new(
            relaxed_modulus,
            &[PronyTerm {
                modulus: instantaneous_modulus - relaxed_modulus,
                relaxation_time,
            }],
        )
        .map_err(|e| match e {
            Error::InvalidParameter {
                value, requirement, ..
            } => Error::invalid("relaxation_time", value, requirement),
            e => e,
        })
    }

    /// Read a Prony series: rows `E_k, tau_k` (Pa, s); a row with `tau = inf`
    /// gives E∞ (at most one; E∞ = 0 without it).
    ///
    /// # Errors
    /// [`Error::Io`]; [`Error::Parse`] naming the line of a cell that is not a
    /// number, a modulus not finite and > 0, a time not > 0, a second `inf` row.
    pub fn from_file(path: &Path) -> Result<Self> {
        Self::from_bytes(path, &crate::io::read(path)?)
    }

    /// [`Prony::from_file`] on content in memory (`path` names it in errors).
    ///
    /// # Errors
    /// As [`Prony::from_file`], without the I/O errors.
    pub(crate) fn from_bytes(path: &Path, bytes: &[u8]) -> Result<Self> {
        let rows = parse_rows(path, bytes, &["E_k", "tau_k"], 0)?;
        let mut relaxed = None;
        let mut terms = Vec::new();
        for row in &rows {
            let (e, tau) = (row.values[0], row.values[1]);
            if !(e.is_finite() && e > 0.0 && e <= MAX_MODULUS) {
                return Err(cell_error(path, row, "E_k", e, &modulus_requirement()));
            }
            if tau == f64::INFINITY {
                if relaxed.replace(e).is_some() {
                    return Err(cell_error(
                        path,
                        row,
                        "tau_k",
                        tau,
                        "inf on one row only (E∞)",
                    ));
                }
            } else if !(tau.is_finite() && tau > 0.0) {
                return Err(cell_error(
                    path,
                    row,
                    "tau_k",
                    tau,
                    "finite and > 0, or inf for E∞",
                ));
            } else {
                terms.push(PronyTerm {
                    modulus: e,
                    relaxation_time: tau,
                });
            }
        }
        Self::new(relaxed.unwrap_or(0.0), &terms)
            .map_err(|e| Error::parse(path, 0, 0, e.to_string()))
    }

    /// E∞, Pa.
    pub fn relaxed_modulus(&self) -> f64 {
        self.relaxed_modulus
    }

    /// The terms (E_k, τ_k).
    pub fn terms(&self) -> &[PronyTerm] {
        &self.terms
    }

    /// E(ω) (ω in rad/s, any sign: E(−ω) = conj E(ω)).
    pub fn modulus(&self, omega: f64) -> Modulus {
        let (mut re, mut im) = (self.relaxed_modulus, 0.0);
        for t in &self.terms {
            let (s, l) = debye(omega * t.relaxation_time);
            re += t.modulus * s;
            im += t.modulus * l;
        }
        Modulus::new(re, im)
    }

    /// A(w) and B(w) in closed form (module docs), w ≥ 0 in rad/s.
    pub fn angular(&self, w: f64) -> AngularIntegrals {
        let e_inf = self.relaxed_modulus;
        let (mut a, mut b) = (0.0, FRAC_PI_2 * e_inf * e_inf);
        // (E_k, a_k, J(a_k), J(a_k)/a_k) per term.
        let parts: Vec<(f64, f64, f64, f64)> = self
            .terms
            .iter()
            .map(|t| {
                let x = w * t.relaxation_time;
                let l = j_over_a(x);
                (t.modulus, x, x * l, l)
            })
            .collect();
        for (j, &(ej, aj, jj, lj)) in parts.iter().enumerate() {
            a += ej * lj;
            b += 2.0 * e_inf * ej * jj + ej * ej * jj;
            for &(ek, ak, _, lk) in &parts[j + 1..] {
                // a_j a_k (L_j + L_k)/(a_j + a_k), written with 1/a to avoid overflow.
                let harmonic = 1.0 / (1.0 / aj + 1.0 / ak);
                b += 2.0 * ej * ek * (lj + lk) * harmonic;
            }
        }
        AngularIntegrals {
            loss: a,
            modulus_squared: b,
            ..Default::default()
        }
    }
}

/// (x²/(1 + x²), x/(1 + x²)) without overflow.
#[inline]
fn debye(x: f64) -> (f64, f64) {
    if x.abs() <= 1.0 {
        let d = 1.0 + x * x;
        (x * x / d, x / d)
    } else {
        let r = 1.0 / x;
        let d = 1.0 + r * r;
        (1.0 / d, r / d)
    }
}

/// J(a)/a = (π/2) a/(h (1 + h)), h = √(1 + a²): A of one Debye term per unit E_k.
#[inline]
fn j_over_a(a: f64) -> f64 {
    let h = a.hypot(1.0);
    FRAC_PI_2 * (a / h) / (1.0 + h)
}

/// The rubber's modulus at the reference temperature.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Viscoelastic {
    /// A Prony series (or standard linear solid): E(ω) analytic.
    Prony(Prony),
    /// A measured master curve, log-log interpolated.
    MasterCurve(MasterCurve),
}

impl Viscoelastic {
    /// E(ω) at the reference temperature (ω in rad/s, any sign).
    pub(crate) fn modulus(&self, omega: f64) -> Modulus {
        match self {
            Viscoelastic::Prony(p) => p.modulus(omega),
            Viscoelastic::MasterCurve(m) => m.modulus(omega),
        }
    }

    /// A(w), B(w) (module docs) at the reference temperature, exactly (a
    /// closed form, or the master curve's per-segment series), w ≥ 0 in rad/s.
    pub(crate) fn angular(&self, w: f64) -> AngularIntegrals {
        match self {
            Viscoelastic::Prony(p) => p.angular(w),
            Viscoelastic::MasterCurve(m) => m.angular(w),
        }
    }

    /// An upper bound of |E(ω)| over every ω, Pa: a Prony series' glassy
    /// modulus E∞ + Σ E_k; for a master curve √(max E′² + max E″²) over the
    /// table (log-log interpolation and the held ends stay between a
    /// segment's end values).
    pub(crate) fn max_modulus(&self) -> f64 {
        match self {
            Viscoelastic::Prony(p) => {
                p.relaxed_modulus + p.terms.iter().map(|t| t.modulus).sum::<f64>()
            }
            Viscoelastic::MasterCurve(m) => {
                let (mut e1, mut e2) = (0.0f64, 0.0f64);
                for (_, s, l) in m.points() {
                    e1 = e1.max(s);
                    e2 = e2.max(l);
                }
                e1.hypot(e2)
            }
        }
    }

    /// The tabulated frequency range (rad/s) of a master curve; `None` for a
    /// Prony series.
    pub(crate) fn frequency_range(&self) -> Option<(f64, f64)> {
        match self {
            Viscoelastic::Prony(_) => None,
            Viscoelastic::MasterCurve(m) => Some(m.frequency_range()),
        }
    }
}

impl From<Prony> for Viscoelastic {
    fn from(p: Prony) -> Self {
        Viscoelastic::Prony(p)
    }
}

impl From<MasterCurve> for Viscoelastic {
    fn from(m: MasterCurve) -> Self {
        Viscoelastic::MasterCurve(m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quad::integrate;

    /// Adaptive Gauss–Kronrod to 1e-14 against closed forms of ~10 terms.
    const ANGULAR_TOL: f64 = 1e-12;

    fn rubber() -> Prony {
        let terms: Vec<PronyTerm> = (0..8)
            .map(|k| PronyTerm {
                modulus: 1e8 * (0.3 + 0.1 * k as f64),
                relaxation_time: 10f64.powi(k - 6),
            })
            .collect();
        Prony::new(1e6, &terms).unwrap()
    }

    #[test]
    fn angular_closed_forms_match_quadrature() {
        let p = rubber();
        for &w in &[1e-3, 1.0, 3e2, 1e5, 1e9, 1e14] {
            let ang = p.angular(w);
            let a = integrate(
                "A",
                |phi| phi.cos() * p.modulus(w * phi.cos()).loss_modulus,
                0.0,
                FRAC_PI_2,
                0.0,
                1e-14,
                1_000_000,
            )
            .unwrap();
            let b = integrate(
                "B",
                |phi| {
                    let e = p.modulus(w * phi.cos());
                    e.storage_modulus.powi(2) + e.loss_modulus.powi(2)
                },
                0.0,
                FRAC_PI_2,
                0.0,
                1e-14,
                1_000_000,
            )
            .unwrap();
            assert!(
                (ang.loss - a.value).abs() <= ANGULAR_TOL * a.value,
                "A({w})"
            );
            assert!(
                (ang.modulus_squared - b.value).abs() <= ANGULAR_TOL * b.value,
                "B({w})"
            );
        }
    }

    #[test]
    fn modulus_is_hermitian_and_overflow_free() {
        let p = rubber();
        let (e, f) = (p.modulus(123.0), p.modulus(-123.0));
        assert_eq!(e.storage_modulus, f.storage_modulus);
        assert_eq!(e.loss_modulus, -f.loss_modulus);
        let huge = p.modulus(1e300);
        assert!(huge.storage_modulus.is_finite() && huge.loss_modulus >= 0.0);
        let a = p.angular(1e300);
        assert!(a.loss.is_finite() && a.modulus_squared.is_finite());
    }

    #[test]
    fn bad_series() {
        assert!(Prony::new(-1.0, &[]).is_err());
        assert!(Prony::new(0.0, &[]).is_err());
        let e = Prony::standard_linear_solid(1e6, 1e6, 1.0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("instantaneous_modulus"), "{e}");
        let e = Prony::standard_linear_solid(1e9, 1e6, f64::NAN)
            .unwrap_err()
            .to_string();
        assert!(e.contains("relaxation_time"), "{e}");
        let e = Prony::from_bytes(Path::new("p.txt"), b"1e8 1e-3\n1e6 inf\n2e6 inf\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("p.txt:3"), "{e}");
        let p = Prony::from_bytes(Path::new("p"), b"# E_k tau_k\n1e8 1e-3\n1e6 inf\n").unwrap();
        assert_eq!(p.relaxed_modulus(), 1e6);
        assert_eq!(p.terms().len(), 1);
    }
}

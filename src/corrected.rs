//! Corrected contact-area theories: Yang–Persson, Wang–Müser and Xu et al.
//! next to the original theory, each with its parameter γ.
//!
//! # Formula
//! All four theories share the pressure variance at full contact
//! ```text
//! V_c(ζ) = (π/2) E*² ∫_{q_l}^{ζ q_l} q³ C(q) dq = 2 σ0² G(ζ)      [Pa²]
//! A/A0   = erf(σ0 / √(2 V(ζ))) = erf(1 / (2 √G_e)),  G_e = V / (2 σ0²)
//! ```
//! and differ in how the variance V of the partial contact follows V_c:
//! ```text
//! original      V = V_c                                   (G_e = G)
//! Yang–Persson  dV/dV_c = γ + (1 − γ) A²                   γ = 0.45
//! Wang–Müser    dV/dV_c = γ − (2/9) A² + (11/9 − γ) A⁴      γ = 5/9
//! Xu et al.     V = (γ + (1 − γ) A) V_c   (implicit in A)  γ = 0.42
//! ```
//! Written in the dimensionless G_e = V/(2σ0²) and G = V_c/(2σ0²) the two ODEs
//! read dG_e/dG = f(A(G_e)): they involve neither the spectrum nor the load,
//! so one solution serves every spectrum, magnification and pressure.
//!
//! # Method
//! The ODEs are solved by separation of variables: since f > 0,
//! ```text
//! G(G_e) = ∫₀^{G_e} dg / f(A(g)) = G_e + ∫₀^{G_e} (1 − f)/f dg
//! ```
//! is a quadrature (adaptive Gauss–Kronrod in ln g, by bilby),
//! inverted for G_e by safeguarded Newton steps (dG/dG_e = 1/f). Several loads
//! are solved in increasing G, each one continuing the quadrature of the last,
//! so a load curve costs little more than its largest point. The error bound
//! adds every quadrature error estimate along the way and the final Newton
//! residual, and is propagated to A/A0 through |dA/dG_e|. Xu's implicit equation
//! is solved by safeguarded Newton in A on the bracket that γ ≤ 1 guarantees.
//! Nothing is discretised on a fixed ζ grid.
//!
//! `1 − f` is written in terms of `c = 1 − A² = erfc(x)(1 + A)` so that it
//! keeps full relative accuracy near full contact.
//!
//! # References
//! - B. N. J. Persson, J. Chem. Phys. 115, 3840 (2001) (original theory).
//! - C. Yang and B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214 (2008):
//!   the elastic energy factor S = γ + (1 − γ) P², γ ≈ 0.42–0.45. We default
//!   to 0.45, the value named for "YP08" in the notes of the gateway function
//!   of the public MATLAB code of Xu et al. 2024 (xylcsi/PerssonModelFudgeFactor);
//!   that code's individual YP08 functions default to 0.42 instead.
//! - A. Wang and M. H. Müser, "Gauging Persson theory on adhesion",
//!   Tribol. Lett. 65, 103 (2017): S = γ − (2/9) P² + (11/9 − γ) P⁴, γ = 5/9.
//! - Y. Xu, L. Zhu, F. Xiao, Y. Zhou, "A new fudge factor for Persson's theory
//!   of purely normal elastic rough surface contact", Tribol. Lett. 72 (2024),
//!   doi:10.1007/s11249-024-01838-4: S = γ + (1 − γ) P at the present scale only;
//!   γ = 0.42 is the default of the authors' `Persson_LE_Area_Xu24` (their
//!   gateway notes say 0.45).
//!
//! The formulas were checked against the public MATLAB code accompanying Xu et
//! al. (2024) (xylcsi/PerssonModelFudgeFactor: `Persson_LE_Area_YP08/WM17/Xu24`,
//! `Variance_pressure`), which integrates the same relations by implicit Euler
//! steps on a fixed grid of 500 magnifications; read, not copied.

use crate::error::{check, Error, Result};
use crate::kappa::Kappa;
use crate::quad::integrate_counted;
use crate::special::{erf, erfc};
use crate::theory::Persson;

/// Default γ of Yang & Persson (2008).
pub const YANG_PERSSON_GAMMA: f64 = 0.45;
/// Default γ of Wang & Müser (2017).
pub const WANG_MUSER_GAMMA: f64 = 5.0 / 9.0;
/// Default γ of Xu et al. (2024).
pub const XU_GAMMA: f64 = 0.42;

/// Smallest γ accepted for Yang–Persson and Xu. The ODE rate 1/f reaches
/// 1/γ and G_e ≈ γ G: at γ = 1e-4 the solver's error bound already exceeds
/// 1e-12 near G ~ 1e4–1e6, while γ ≥ 1e-3 reaches it for every G up to 1e300
/// (measured). The published values are 0.42–0.56; Wang–Müser's own bound
/// is ≈ 0.0102.
pub const GAMMA_MIN: f64 = 1e-3;

/// Smallest γ accepted for Wang–Müser. The rate f stays positive down to
/// [`wang_muser_gamma_min`] ≈ 0.0102, but its minimum
/// γ − 1/(9(11 − 9γ)) then tends to 0 and the solver's bound misses 1e-12 for
/// some G at γ ≤ 0.012 (measured); from 0.015 up it is met for every G up to
/// 1e300. 0.02 keeps f_min ≥ 0.0097.
pub const WANG_MUSER_GAMMA_MIN: f64 = 0.02;

/// Default absolute tolerance on A/A0.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// Below this G the ODE correction ∫(1 − f)/f dg is below 1e-100 (the
/// integrand is ≤ 2 erfc(1/(2√g))/γ ≈ 1e-110 at g = 1e-3): G_e = G there.
const G_START: f64 = 1e-3;

/// Rounding budget of erf/erfc and the argument 1/(2√G_e), in ulps.
const AREA_ULPS: f64 = 8.0;

/// Newton/bisection iterations before giving up (Newton needs ~5; bisection
/// from the analytic bracket to 1e-16 relative needs ≤ ~60 more).
const MAX_NEWTON: usize = 200;

/// Integrand evaluations allowed per quadrature segment.
const MAX_EVALS: usize = 200_000;

/// Which contact-area theory, with its parameter γ.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "theory", rename_all = "kebab-case", deny_unknown_fields)]
pub enum Theory {
    /// Persson (2001): V = V_c, A/A0 = erf(1/(2√G)).
    Original,
    /// Yang & Persson (2008): dV/dV_c = γ + (1 − γ) A², γ ∈ [1e-3, 1].
    YangPersson {
        /// γ, default [`YANG_PERSSON_GAMMA`].
        gamma: f64,
    },
    /// Wang & Müser (2017): dV/dV_c = γ − (2/9) A² + (11/9 − γ) A⁴,
    /// γ ∈ [0.02, 11/9] (f > 0 needs γ > (99 − √9477)/162 ≈ 0.0102).
    WangMuser {
        /// γ, default [`WANG_MUSER_GAMMA`].
        gamma: f64,
    },
    /// Xu et al. (2024): A = erf(σ0 / √(2 (γ + (1 − γ) A) V_c)), γ ∈ [1e-3, 1].
    Xu {
        /// γ, default [`XU_GAMMA`].
        gamma: f64,
    },
}

/// The smallest γ for which the Wang–Müser rate f stays positive for all A.
///
/// # Formula
/// ```text
/// min_{A²∈[0,1]} f = γ − 1/(9(11 − 9γ)) > 0  ⇔  81γ² − 99γ + 1 < 0
/// γ_min = (99 − √9477)/162 ≈ 0.010 18
/// ```
pub fn wang_muser_gamma_min() -> f64 {
    (99.0 - 9477f64.sqrt()) / 162.0
}

/// The names accepted by [`Theory::from_name`].
pub const THEORY_NAMES: [&str; 4] = ["original", "yang-persson", "wang-muser", "xu"];

impl Theory {
    /// Yang–Persson with its default γ = 0.45.
    pub fn yang_persson() -> Self {
        Theory::YangPersson {
            gamma: YANG_PERSSON_GAMMA,
        }
    }

    /// Wang–Müser with its default γ = 5/9.
    pub fn wang_muser() -> Self {
        Theory::WangMuser {
            gamma: WANG_MUSER_GAMMA,
        }
    }

    /// Xu et al. with its default γ = 0.42.
    pub fn xu() -> Self {
        Theory::Xu { gamma: XU_GAMMA }
    }

    /// All four theories with their default γ.
    pub fn all_defaults() -> [Theory; 4] {
        [
            Theory::Original,
            Theory::yang_persson(),
            Theory::wang_muser(),
            Theory::xu(),
        ]
    }

    /// The theory named `name` (one of [`THEORY_NAMES`]), with `gamma` or
    /// its default; validated.
    ///
    /// # Errors
    /// Unknown name; γ given for the original theory; γ outside its range
    /// (see [`Theory::validate`]).
    pub fn from_name(name: &str, gamma: Option<f64>) -> Result<Self> {
        let t = match name {
            "original" => {
                if let Some(g) = gamma {
                    return Err(Error::invalid(
                        "gamma",
                        g,
                        "absent for the original theory (it has no γ)",
                    ));
                }
                Theory::Original
            }
            "yang-persson" => Theory::YangPersson {
                gamma: gamma.unwrap_or(YANG_PERSSON_GAMMA),
            },
            "wang-muser" => Theory::WangMuser {
                gamma: gamma.unwrap_or(WANG_MUSER_GAMMA),
            },
            "xu" => Theory::Xu {
                gamma: gamma.unwrap_or(XU_GAMMA),
            },
            other => {
                return Err(Error::Inconsistent {
                    name: "theory".into(),
                    requirement: format!("one of {}, got '{other}'", THEORY_NAMES.join(", ")),
                })
            }
        };
        t.validate()
    }

    /// The theory's name as in [`THEORY_NAMES`].
    pub(crate) fn name(&self) -> &'static str {
        match self {
            Theory::Original => "original",
            Theory::YangPersson { .. } => "yang-persson",
            Theory::WangMuser { .. } => "wang-muser",
            Theory::Xu { .. } => "xu",
        }
    }

    /// γ, or `None` for the original theory.
    pub fn gamma(&self) -> Option<f64> {
        match *self {
            Theory::Original => None,
            Theory::YangPersson { gamma } | Theory::WangMuser { gamma } | Theory::Xu { gamma } => {
                Some(gamma)
            }
        }
    }

    /// Check γ against the theory's valid range and return the theory.
    ///
    /// Ranges: Yang–Persson and Xu γ ∈ [[`GAMMA_MIN`], 1] (γ = 1 is the original theory;
    /// for Xu, γ ≤ 1 makes the implicit equation's solution unique); Wang–Müser
    /// γ ∈ [[`WANG_MUSER_GAMMA_MIN`], 11/9] (f > 0 for all A needs
    /// γ > [`wang_muser_gamma_min`]; above 11/9 the A⁴ coefficient turns negative).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `gamma` and its range.
    pub fn validate(self) -> Result<Self> {
        match self {
            Theory::Original => {}
            Theory::YangPersson { gamma } | Theory::Xu { gamma } => {
                if !(gamma.is_finite() && (GAMMA_MIN..=1.0).contains(&gamma)) {
                    return Err(Error::invalid(
                        "gamma",
                        gamma,
                        format!("in [{GAMMA_MIN:e}, 1] for the {} theory", self.name()),
                    ));
                }
            }
            Theory::WangMuser { gamma } => {
                if !(gamma.is_finite() && (WANG_MUSER_GAMMA_MIN..=11.0 / 9.0).contains(&gamma)) {
                    return Err(Error::invalid(
                        "gamma",
                        gamma,
                        format!("in [{WANG_MUSER_GAMMA_MIN}, 11/9] for the wang-muser theory"),
                    ));
                }
            }
        }
        Ok(self)
    }

    /// κ of the low-load law A/A0 → κ σ0/(E* √⟨|∇h|²⟩) as σ0 → 0.
    ///
    /// # Formula
    /// ```text
    /// original: κ = √(8/π);   corrected: f → γ as A → 0, so V → γ V_c and κ = √(8/(π γ))
    /// ```
    /// (The Yang–Persson and Wang–Müser limits approach it with a relative
    /// correction ~ ln G / G.)
    pub fn low_load_kappa(&self) -> f64 {
        let persson = Kappa::Persson.value();
        match self.gamma() {
            None => persson,
            Some(g) => persson / g.sqrt(),
        }
    }

    /// The rate f(A) = dV/dV_c of the ODE theories, as `1 − f` from `c = 1 − A²`.
    fn one_minus_rate(&self, c: f64) -> f64 {
        match *self {
            Theory::YangPersson { gamma } => (1.0 - gamma) * c,
            Theory::WangMuser { gamma } => {
                c * ((20.0 / 9.0 - 2.0 * gamma) - (11.0 / 9.0 - gamma) * c)
            }
            Theory::Original | Theory::Xu { .. } => 0.0,
        }
    }

    /// Bounds (f_min, f_max) of the ODE rate f over A ∈ [0, 1].
    fn rate_bounds(&self) -> (f64, f64) {
        match *self {
            Theory::YangPersson { gamma } => (gamma.min(1.0), gamma.max(1.0)),
            Theory::WangMuser { gamma } => {
                // f = γ − (2/9)x + (11/9 − γ)x², x = A²: vertex x* = 1/(11 − 9γ).
                let fmin = if gamma <= 10.0 / 9.0 {
                    gamma - 1.0 / (9.0 * (11.0 - 9.0 * gamma))
                } else {
                    1.0
                };
                (fmin, gamma.max(1.0))
            }
            Theory::Original | Theory::Xu { .. } => (1.0, 1.0),
        }
    }

    /// `(1 − f, f)` at effective G_e.
    fn rate_at(&self, g_e: f64) -> (f64, f64) {
        let x = 0.5 / g_e.sqrt();
        let c = erfc(x) * (1.0 + erf(x));
        let omf = self.one_minus_rate(c);
        (omf, 1.0 - omf)
    }

    /// A/A0 for one G = V_c/(2σ0²) (the original theory's G(ζ)).
    ///
    /// `g_error` (absolute error of G) is propagated; `tolerance` is the
    /// absolute accuracy asked of A/A0.
    ///
    /// # Errors
    /// G or its error negative/non-finite; γ invalid; tolerance outside
    /// [1e-15, 0.1]; [`Error::NotConverged`] if the quadrature or Newton
    /// iteration fails.
    ///
    /// # Examples
    /// ```
    /// use persson::corrected::Theory;
    /// // γ = 1 is the original theory: erf(1/(2√0.6)) = 0.638690 (Persson, Bucher & Chiaia 2002)
    /// let a = Theory::YangPersson { gamma: 1.0 }.contact_fraction(0.6, 0.0, 1e-12).unwrap();
    /// assert!((a.contact_fraction - 0.638_690).abs() < 5e-7);
    /// ```
    pub fn contact_fraction(&self, g: f64, g_error: f64, tolerance: f64) -> Result<Solution> {
        let mut v = self.contact_fractions(&[g], tolerance)?;
        let mut s = v.pop().ok_or_else(|| Error::Inconsistent {
            name: "g".into(),
            requirement: "one value".into(),
        })?;
        check::non_negative("g_error", g_error)?;
        s.error += s.slope.abs() * g_error;
        Ok(s)
    }

    /// A/A0 for many G at once (any order; solved in increasing G).
    ///
    /// # Errors
    /// As [`Theory::contact_fraction`], for the first bad G.
    pub fn contact_fractions(&self, gs: &[f64], tolerance: f64) -> Result<Vec<Solution>> {
        self.validate()?;
        check::tolerance("tolerance", tolerance)?;
        for &g in gs {
            check::non_negative("g", g)?;
        }
        match *self {
            Theory::Original => Ok(gs.iter().map(|&g| closed_form(g, 1.0, 0.0, 0)).collect()),
            Theory::Xu { gamma } => gs.iter().map(|&g| xu(g, gamma, tolerance)).collect(),
            Theory::YangPersson { .. } | Theory::WangMuser { .. } => {
                OdeSolver::new(*self, tolerance).solve_many(gs)
            }
        }
    }
}

/// A/A0 from one theory at one G, with its error bound.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Solution {
    /// G = V_c/(2σ0²), the input.
    pub g: f64,
    /// G_e = V/(2σ0²), the effective G of the theory (= G for the original).
    pub effective_g: f64,
    /// A/A0 = erf(1/(2√G_e)).
    pub contact_fraction: f64,
    /// 1 − A/A0 = erfc(1/(2√G_e)), full relative accuracy.
    pub complement: f64,
    /// Bound on the absolute error of A/A0 (solver + rounding + input error).
    pub error: f64,
    /// dA/dG (for error propagation; ≤ 0).
    pub slope: f64,
    /// Integrand (or residual) evaluations spent.
    pub evaluations: usize,
}

/// A/A0 = erf(1/(2√G_e)) with G_e known to `ge_error`, and dG_e/dG = `rate`.
fn closed_form(g: f64, rate: f64, ge_error: f64, evaluations: usize) -> Solution {
    closed_form_at(g, g, rate, ge_error, evaluations)
}

fn closed_form_at(g: f64, g_e: f64, rate: f64, ge_error: f64, evaluations: usize) -> Solution {
    if g_e == 0.0 {
        return Solution {
            g,
            effective_g: 0.0,
            contact_fraction: 1.0,
            complement: 0.0,
            error: 0.0,
            slope: 0.0,
            evaluations,
        };
    }
    let x = 0.5 / g_e.sqrt();
    let a = erf(x);
    // dA/dG_e = −x e^{−x²}/(√π G_e)
    let d_a = -x * (-x * x).exp() / (std::f64::consts::PI.sqrt() * g_e);
    Solution {
        g,
        effective_g: g_e,
        contact_fraction: a,
        complement: erfc(x),
        error: AREA_ULPS * f64::EPSILON * a + d_a.abs() * ge_error,
        slope: d_a * rate,
        evaluations,
    }
}

/// Xu et al.: solve F(A) = A − erf(1/(2√(G (γ + (1 − γ) A)))) = 0.
///
/// F' = 1 + (1 − γ) x e^{−x²} / (√π h) > 0, so the root is unique in the
/// bracket [erf(1/(2√G)), erf(1/(2√(γ G)))].
fn xu(g: f64, gamma: f64, tolerance: f64) -> Result<Solution> {
    if g == 0.0 {
        return Ok(closed_form(0.0, 1.0, 0.0, 0));
    }
    let eval = |a: f64| {
        let h = gamma + (1.0 - gamma) * a;
        let x = 0.5 / (g * h).sqrt();
        let f = a - erf(x);
        let d = 1.0 + (1.0 - gamma) * x * (-x * x).exp() / (std::f64::consts::PI.sqrt() * h);
        (f, d)
    };
    let mut lo = erf(0.5 / g.sqrt());
    let mut hi = erf(0.5 / (gamma * g).sqrt());
    let mut a = 0.5 * (lo + hi);
    let mut evals = 0;
    for _ in 0..MAX_NEWTON {
        let (f, d) = eval(a);
        evals += 1;
        if f == 0.0 {
            break;
        }
        if f > 0.0 {
            hi = a;
        } else {
            lo = a;
        }
        let mut next = a - f / d;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        let step = (next - a).abs();
        a = next;
        if step <= 0.01 * tolerance.min(1e-13) || hi - lo <= 4.0 * f64::EPSILON {
            break;
        }
    }
    let (f, d) = eval(a);
    evals += 1;
    let residual_bound = f.abs() / d + 4.0 * f64::EPSILON;
    if residual_bound > tolerance {
        return Err(Error::NotConverged {
            what: "Xu et al. implicit contact area".into(),
            iterations: evals,
            residual: residual_bound,
            tolerance,
        });
    }
    let h = gamma + (1.0 - gamma) * a;
    let g_e = g * h;
    let mut s = closed_form_at(g, g_e, 1.0, 0.0, evals);
    s.contact_fraction = a;
    s.complement = erfc(0.5 / g_e.sqrt());
    s.error = residual_bound + AREA_ULPS * f64::EPSILON;
    // Implicit differentiation: dA/dG = −(∂F/∂G)/(∂F/∂A); ∂F/∂G = x e^{−x²}/(√π G).
    let x = 0.5 / g_e.sqrt();
    s.slope = -(x * (-x * x).exp() / (std::f64::consts::PI.sqrt() * g)) / d;
    Ok(s)
}

/// G(G_e) = G_e + D(G_e) by marching quadrature, inverted by Newton.
struct OdeSolver {
    theory: Theory,
    tolerance: f64,
    /// Current G_e.
    g_e: f64,
    /// D(G_e) = ∫₀^{G_e} (1 − f)/f dg.
    d: f64,
    /// Accumulated absolute error bound of `d`.
    d_error: f64,
    evals: usize,
}

impl OdeSolver {
    fn new(theory: Theory, tolerance: f64) -> Self {
        OdeSolver {
            theory,
            tolerance,
            g_e: G_START,
            d: 0.0,
            d_error: 0.0,
            evals: 0,
        }
    }

    /// Move the state to G_e = `to`, integrating (1 − f)/f in ln g.
    fn advance(&mut self, to: f64) -> Result<()> {
        if to == self.g_e {
            return Ok(());
        }
        let theory = self.theory;
        let integrand = |y: f64| {
            let g = y.exp();
            let (omf, f) = theory.rate_at(g);
            omf / f * g
        };
        let (a, b) = (self.g_e.ln(), to.ln());
        // An error δ in G moves G_e by f δ and A by |dA/dG_e| f δ ≤ 0.242 f δ/G_e
        // (max of x e^{−x²}/√π): the allowed absolute error in G is ~ tol G_e/f.
        // f at the solution is unknown here; the larger endpoint value is the
        // safe guess when the segment ends near it (the final bound uses the
        // solution's f and is checked against the tolerance).
        let hi = self.g_e.max(to);
        let scale = hi / theory.rate_at(self.g_e).1.max(theory.rate_at(to).1);
        let (q, evals) = integrate_counted(
            "corrected-theory ODE quadrature",
            integrand,
            a.min(b),
            a.max(b),
            0.02 * self.tolerance * scale,
            0.02 * self.tolerance,
            MAX_EVALS,
        )?;
        let sign = if b >= a { 1.0 } else { -1.0 };
        self.d += sign * q.value;
        self.d_error += q.error + f64::EPSILON * q.value.abs();
        self.evals += evals;
        self.g_e = to;
        Ok(())
    }

    fn solve_many(mut self, gs: &[f64]) -> Result<Vec<Solution>> {
        let mut order: Vec<usize> = (0..gs.len()).collect();
        order.sort_by(|&i, &j| gs[i].total_cmp(&gs[j]));
        let mut out = vec![None; gs.len()];
        for i in order {
            out[i] = Some(self.solve(gs[i])?);
        }
        out.into_iter()
            .map(|s| {
                s.ok_or_else(|| Error::Inconsistent {
                    name: "g".into(),
                    requirement: "every G solved".into(),
                })
            })
            .collect()
    }

    /// Solve G_e + D(G_e) = g for one g ≥ the previous one.
    fn solve(&mut self, g: f64) -> Result<Solution> {
        let evals0 = self.evals;
        if g <= G_START {
            // D < 1e-100 here: G_e = G to rounding.
            let (_, f) = self.theory.rate_at(g.max(f64::MIN_POSITIVE));
            return Ok(closed_form(g, f, f64::EPSILON * g, 0));
        }
        let (fmin, fmax) = self.theory.rate_bounds();
        // Bracket: dG/dG_e = 1/f ∈ [1/f_max, 1/f_min] and G(G_START) = G_START.
        let mut lo = G_START + fmin * (g - G_START);
        let mut hi = G_START + fmax * (g - G_START);
        let (_, f0) = self.theory.rate_at(self.g_e);
        let residual0 = self.g_e + self.d - g;
        let mut next = (self.g_e - residual0 * f0).clamp(lo, hi);
        let mut converged = false;
        let mut residual = f64::INFINITY;
        let mut last_residual = f64::INFINITY;
        let mut f = f0;
        for _ in 0..MAX_NEWTON {
            self.advance(next)?;
            residual = self.g_e + self.d - g;
            f = self.theory.rate_at(self.g_e).1;
            if residual > 0.0 {
                hi = hi.min(self.g_e);
            } else {
                lo = lo.max(self.g_e);
            }
            // Allowed residual in G: δA ≤ 0.242 f δG/G_e (see `advance`).
            let tol_g = 0.1 * self.tolerance * self.g_e / f;
            if residual.abs() <= tol_g.max(4.0 * f64::EPSILON * g) {
                converged = true;
                break;
            }
            // Newton, clamped to the bracket (the root can sit on the analytic
            // bound G_START + f_min (G − G_START) to rounding at huge G);
            // bisection when clamping makes no progress.
            // A step that did not halve the residual (f varies fast near the
            // Wang–Müser γ_min) is followed by a bisection (as in rtsafe).
            next = (self.g_e - residual * f).clamp(lo, hi);
            if next == self.g_e || next.is_nan() || residual.abs() > 0.5 * last_residual {
                next = 0.5 * (lo + hi);
            }
            last_residual = residual.abs();
            if next == self.g_e {
                // No representable progress: the residual is at its rounding
                // floor, which the error bound below includes.
                converged = true;
                break;
            }
        }
        // Residual, quadrature errors, and the rounding of G_e + D − G.
        let floor = 4.0 * f64::EPSILON * (self.d.abs() + g);
        let ge_error = f * (residual.abs() + self.d_error + floor) + 2.0 * f64::EPSILON * self.g_e;
        let s = closed_form_at(g, self.g_e, f, ge_error, self.evals - evals0);
        if !converged || s.error > self.tolerance {
            return Err(Error::NotConverged {
                what: format!("{} contact area at G = {g:e}", self.theory.name()),
                iterations: self.evals - evals0,
                residual: s.error,
                tolerance: self.tolerance,
            });
        }
        Ok(s)
    }
}

/// One point of a corrected-theory area curve.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct TheoryPoint {
    /// Nominal pressure σ0.
    pub nominal_pressure: f64,
    /// Magnification ζ.
    pub zeta: f64,
    /// G(ζ) = V_c/(2σ0²).
    pub g: f64,
    /// Effective G_e = V/(2σ0²) of the theory.
    pub effective_g: f64,
    /// A/A0 from the theory.
    pub contact_fraction: f64,
    /// 1 − A/A0, computed without cancellation.
    pub non_contact_fraction: f64,
    /// Absolute error bound of A/A0 (solver, rounding and the error of G).
    pub error_bound: f64,
}

/// A/A0 against load at magnification ζ for `theory`.
///
/// # Formula
/// ```text
/// G(ζ, σ0) = V_c(ζ)/(2σ0²) = (E*/σ0)² ⟨|∇h|²⟩_ζ / 8,   A/A0 = theory(G)
/// ```
/// ⟨|∇h|²⟩_ζ is computed once; all pressures share one ODE solution.
///
/// # Errors
/// A pressure not finite and positive; ζ < 1; γ invalid; solver failure.
///
/// # Examples
/// ```
/// use persson::corrected::{load_curve, Theory};
/// use persson::spectrum::{Amplitude, SelfAffine};
/// use persson::theory::Persson;
/// let s = SelfAffine::new(1e3, 1e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
/// let model = Persson::new(&s, 1.0).unwrap();
/// let pts = load_curve(&model, Theory::yang_persson(), model.zeta_max(), &[1e-6], 1e-12).unwrap();
/// // Low load: A/A0 → κ σ0/(E* rms slope), κ = √(8/(π γ)) = 2.379 for γ = 0.45
/// let kappa = pts[0].contact_fraction / 1e-6;
/// assert!((kappa - Theory::yang_persson().low_load_kappa()).abs() < 1e-4);
/// ```
pub fn load_curve(
    model: &Persson,
    theory: Theory,
    zeta: f64,
    pressures: &[f64],
    tolerance: f64,
) -> Result<Vec<TheoryPoint>> {
    let s = model.slope_variance(zeta)?;
    let gs: Vec<(f64, f64)> = pressures
        .iter()
        .map(|&p| model.g_from(s, p).map(|g| (g.value, g.error)))
        .collect::<Result<_>>()?;
    let values: Vec<f64> = gs.iter().map(|g| g.0).collect();
    let sols = theory.contact_fractions(&values, tolerance)?;
    Ok(pressures
        .iter()
        .zip(gs.iter().zip(sols))
        .map(|(&p, (&(g, g_err), s))| TheoryPoint {
            nominal_pressure: p,
            zeta,
            g,
            effective_g: s.effective_g,
            contact_fraction: s.contact_fraction,
            non_contact_fraction: s.complement,
            error_bound: s.error + s.slope.abs() * g_err,
        })
        .collect())
}

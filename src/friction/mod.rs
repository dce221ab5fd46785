//! Rubber friction: Persson's theory of the viscoelastic (hysteretic)
//! friction of a rubber block sliding on a hard, randomly rough surface, with
//! the rubber's measured master curve, time–temperature superposition and the
//! flash temperature.
//!
//! # What it solves
//! A rubber block (complex modulus E(ω, T), Poisson ratio ν) slides at
//! velocity v on a rigid surface with power spectrum C(q) under nominal
//! pressure σ0. The surface's roughness deforms the rubber at frequencies
//! ω = q v cos φ; the energy dissipated gives the friction coefficient μ.
//!
//! # Formula
//! ```text
//! μ    = ½ ∫_{q_l}^{q1} dq q³ C(q) S(q) P(q) ∫₀^{2π} dφ cos φ Im E(q v cos φ, T_q) / ((1 − ν²) σ0)
//! G(q) = ⅛ ∫_{q_l}^{q} dq′ q′³ C(q′) ∫₀^{2π} dφ |E(q′ v cos φ, T_q′) / ((1 − ν²) σ0)|²
//! P(q) = erf(1 / (2√G(q))),      S(q) = γ + (1 − γ) P(q)²
//! E(ω, T) = b_T E(a_T ω, T_ref),  E(−ω) = conj E(ω)
//! ```
//! q in 1/m (angular wavevector), C in m⁴ (Persson's normalisation, see the
//! crate docs), v in m/s, moduli and σ0 in Pa, T in K; μ, G, P, S, γ
//! dimensionless. P(q) is the contact area A/A0 at magnification q/q_l (the
//! `contact_fraction` at q1 is A(v)/A0 at the largest magnification). G uses
//! |E| (not E′), and S enters μ only. Without the flash temperature T_q = T;
//! with it T_q follows from the heat produced at the larger scales (see
//! [`heat`](self#flash-temperature) below).
//!
//! Checks of the factors (derived here): in full contact (P = S = 1) the
//! rubber surface follows h(x − vt); the half-space's normal stress is
//! σ(q, ω) = E(ω) q u(q, ω)/(2(1 − ν²)) and the dissipated power per area
//! ⟨σ u̇⟩ = ∫ d²q C(q) ω Im[E(ω) q/(2(1 − ν²))], ω = q v cos φ (Persson's
//! normalisation ⟨h²⟩ = ∫ d²q C), so μ = ⟨σ u̇⟩/(v σ0) is the formula above
//! with its ½. For a frequency-independent real E the φ-integral of |E|² is
//! 2π E² and G reduces to the crate's elastic G = (π/4)(E*/σ0)² ∫ q³ C dq,
//! E* = E/(1 − ν²) ([`crate::theory`]), which fixes the ⅛. The four quadrants
//! of the φ-integrals are equal (E″ odd, |E|² even in ω), so
//! μ = 2 ∫ dq q³ C S P A(qv)/((1 − ν²)σ0) and G = ½ ∫ dq q³ C B(qv)/((1 − ν²)σ0)²
//! with A, B the quarter-period integrals of [`AngularIntegrals`].
//!
//! ## Flash temperature
//! T_q = T + ∫_{q_l}^{q} dq′ f(q′) h(q′): f is the heating rate per unit
//! volume under the contact spots of magnification q′ (over ρc), h the time
//! over which a spot heats, reduced by conduction ([`heat_kernel`], [`Thermal`]).
//! T_q enters E in μ, G and f itself; the resulting ODE in ln q is solved by
//! collocation with Newton's method. The isothermal μ is always reported
//! beside it. Choices made here (the paper's heat kernel could not be checked
//! factor by factor): heat stays in the rubber (no flow into the substrate),
//! the dissipation of band q sits in a layer of depth 1/(2q) under spots of
//! size π/q crossed in τ = π/(qv), and the background heating of the whole
//! nominal contact is not modelled (T is its temperature).
//!
//! # Choices where the papers leave one
//! - γ = ½ by default (Persson 2006: "γ ≈ 1/2"); a parameter.
//! - q1: the spectrum's end, a given value, or where the rms slope of the
//!   roughness up to q1 reaches a given value ([`CutOff::RmsSlope`], the
//!   criterion of Lorenz et al. 2011 with the value left to the caller).
//! - A master curve is log-log interpolated and held at its end values
//!   outside the table; every use outside is reported ([`TableExcursion`]).
//! - Standard linear solid and Prony conventions in the time domain:
//!   E(t) = E∞ + Σ E_k e^{−t/τ_k}; E0 = E(t = 0) the instantaneous (glassy),
//!   E∞ the relaxed (rubbery) modulus.
//!
//! # Method
//! - **Angular integrals** A(w), B(w): closed forms for a Prony series;
//!   exact per-segment series for a table, interpolated once per rubber by
//!   piecewise Chebyshev polynomials in ln w with panel boundaries (and a
//!   t² map) at the table's kinks ([`viscoelastic`], [`master_curve`],
//!   `angular`). a_T and b_T act as w → a_T w and factors b_T, b_T².
//! - **q-integrals**: G, μ (and T_q) are integrated together over x = ln q
//!   by an adaptive march of 17-point Chebyshev–Lobatto panels, left to right
//!   (G is cumulative, evaluated at the nodes by cumulative Chebyshev
//!   integration). Panel boundaries at the profile magnifications, the
//!   caller's breaks of C and (isothermally, for a table) at q = ω_i/(a_T v),
//!   where A and B have their (q − q_i)^{3/2} terms, removed by a t² map.
//!
//! # Stopping rule and error bounds
//! A panel is accepted when the nested 17- and 9-point Clenshaw–Curtis values
//! of ∫dG, ∫dμ (and ∫dT) differ by at most `tolerance` times the panel's
//! value plus its share (by length in ln q) of the total so far; else it is
//! bisected (at most 40 times; a panel that cannot converge is accepted, its
//! estimate kept in the bound and `converged` set false). `friction_coefficient_error_bound`
//! sums the panels' estimates, the propagation of G's (and T's) accumulated
//! error bounds through ∂μ/∂G (and ∂μ/∂T), the interpolant's relative error
//! and rounding.
//!
//! # References
//! - B. N. J. Persson, *Theory of rubber friction and contact mechanics*,
//!   J. Chem. Phys. 115, 3840 (2001), doi:10.1063/1.1388626: μ, G and P(q).
//! - B. N. J. Persson, *Rubber friction: role of the flash temperature*,
//!   J. Phys.: Condens. Matter 18, 7789 (2006), doi:10.1088/0953-8984/18/32/025
//!   (arXiv:cond-mat/0605273): S(q) = γ + (1 − γ)P², γ ≈ ½, and T_q.
//! - B. Lorenz, B. N. J. Persson, S. Dieluweit, T. Tada, *Rubber friction:
//!   comparison of theory with experiment*, Eur. Phys. J. E 34, 129 (2011),
//!   doi:10.1140/epje/i2011-11129-1: q1 from the rms slope.
//! - M. L. Williams, R. F. Landel, J. D. Ferry, J. Am. Chem. Soc. 77, 3701
//!   (1955): the WLF shift.
//!
//! The equations above were compared with the issue's statement, with the
//! open implementation `perssonmodelling` (read, not copied: the same μ, G,
//! P, S; |E| in G; S in μ only) and with the two limits derived above; the
//! papers' full texts (beyond their abstracts) were not available here, so
//! their equation numbers are not quoted.
//!
//! # Examples
//! A standard linear solid in full contact (σ0 ≫ E, so P = S = 1) on a
//! one-decade flat spectrum: μ = 2 C ∫ q³ A(qv) dq/((1 − ν²)σ0).
//! ```
//! use persson::friction::{Friction, FrictionOptions, Prony, Rubber, TemperatureShift};
//! use persson::spectrum::FnSpectrum;
//! # fn main() -> persson::Result<()> {
//! let spectrum = FnSpectrum::new(|_q| 1e-20, 1e3, 1e4, 1e-14)?;
//! let sls = Prony::standard_linear_solid(2e6, 1e6, 1e-3)?;
//! let rubber = Rubber::new(sls.clone(), TemperatureShift::none(293.15)?);
//! let options = FrictionOptions { tolerance: 1e-12, ..Default::default() };
//! let friction = Friction::new(&spectrum, &rubber, &options)?;
//! let (v, sigma0) = (0.1, 1e12);
//! let point = friction.point(v, 293.15, sigma0)?;
//! // The oracle: Simpson on the closed-form A(w) = (E0 − E∞)(π/2)(1 − 1/√(1+a²))/a, a = q v τ.
//! let a_of = |q: f64| { let a = q * v * 1e-3; 1e6 * std::f64::consts::FRAC_PI_2 * (1.0 - 1.0 / (1.0 + a * a).sqrt()) / a };
//! let n = 20_000;
//! let h = (1e4 - 1e3) / n as f64;
//! let mut s = 0.0;
//! for i in 0..=n {
//!     let q = 1e3 + i as f64 * h;
//!     let w = if i == 0 || i == n { 1.0 } else if i % 2 == 1 { 4.0 } else { 2.0 };
//!     s += w * q.powi(3) * 1e-20 * a_of(q);
//! }
//! let mu = 2.0 * (s * h / 3.0) / (0.75 * sigma0);
//! assert!(((point.isothermal.friction_coefficient - mu) / mu).abs() < 1e-8);
//! # Ok(())
//! # }
//! ```

mod angular;
mod chebyshev;
mod columns;
mod flash;
mod heat;
mod march;
pub mod master_curve;
mod modulus;
mod problem;
mod result;
mod rubber;
mod shift;
mod theory;
pub mod viscoelastic;

pub use heat::{heat_kernel, heat_kernel_ratio, Thermal};
pub use master_curve::{FrequencyUnit, MasterCurve};
pub use modulus::{AngularIntegrals, Modulus, MAX_MODULUS};
pub use problem::Friction;
pub use result::{
    DecadeContribution, FrictionPoint, FrictionResult, MagnificationPoint, TableExcursion,
};
pub use rubber::{Rubber, DEFAULT_POISSON};
pub use shift::{
    HorizontalShift, ShiftFactors, ShiftTable, TemperatureShift, VerticalShift, MAX_WLF_C1,
};
pub use theory::{
    log_velocities, CutOff, FrictionOptions, DEFAULT_GAMMA, DEFAULT_POINTS_PER_DECADE,
    DEFAULT_TOLERANCE,
};
pub use viscoelastic::{Prony, PronyTerm, Viscoelastic};

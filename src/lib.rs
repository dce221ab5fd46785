//! # persson
//!
//! Contact mechanics of randomly rough surfaces. From the roughness power
//! spectrum C(q) of a surface and the contact modulus E* of the bodies,
//! Persson's theory gives, at every magnification ζ, the quantity G(ζ), the
//! real contact area A/A0 and the distribution P(σ, ζ) of the local contact
//! pressure (for a flat, Hertz-ball, cylinder or tabulated macroscopic
//! contact, elastic or with a yield stress). Next to it the crate computes the
//! low-load slope κ, the corrected theories of Yang–Persson, Wang–Müser and Xu
//! et al., the mean interfacial separation ū with the contact stiffness and the
//! stored elastic energy, and (feature `bem`) solves the same contact problem
//! with an FFT boundary-element method to cross-check the theory.
//!
//! Every number comes with a bound on its error or a stated tolerance, and
//! every function that can fail returns [`Result`] with a typed [`Error`] that
//! names the offending parameter.
//!
//! ## Quick start
//!
//! A/A0 of a self-affine surface pressed by a rubber block, checked against
//! the closed form A/A0 = erf(1/(2√G)) with G = (E*/σ0)² h'²_rms / 8 at full
//! magnification:
//!
//! ```
//! use persson::material::Body;
//! use persson::spectrum::{Amplitude, SelfAffine};
//! use persson::theory::Persson;
//! use persson::Material;
//!
//! # fn main() -> persson::Result<()> {
//! // Hurst exponent H = 0.8, C(q) flat from q_l = 1e4 to the roll-off
//! // q_r = 1e5 and a power law up to q_s = 1e8 (1/m); rms slope 1 over the band.
//! let rms_slope = 1.0;
//! let spectrum = SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(rms_slope))?;
//! // Rubber (E = 10 MPa, ν = 0.5) on a rigid surface: E* = E/(1 − ν²).
//! let material = Material::from_body(Body { young: 10e6, poisson: 0.5 })?;
//! let e_star = material.contact_modulus();
//!
//! // A/A0 at the nominal pressure σ0 = 2 MPa and full magnification ζ = q_s/q_l.
//! let theory = Persson::new(&spectrum, e_star)?;
//! let nominal_pressure = 2e6;
//! let point = theory.point(theory.zeta_max(), nominal_pressure)?;
//!
//! // The oracle: G = (E*/σ0)² ⟨|∇h|²⟩ / 8 and erf by its Maclaurin series.
//! let g = (e_star / nominal_pressure).powi(2) * rms_slope * rms_slope / 8.0;
//! let erf = |x: f64| {
//!     let (mut term, mut sum) = (x, x);
//!     for n in 1..60 {
//!         term *= -x * x / n as f64;
//!         sum += term / (2 * n + 1) as f64;
//!     }
//!     sum * 2.0 / std::f64::consts::PI.sqrt()
//! };
//! assert!((point.g - g).abs() < 1e-14 * g);
//! assert!((point.contact_fraction - erf(1.0 / (2.0 * g.sqrt()))).abs() < 1e-14);
//! assert!((point.contact_fraction - 0.235_823).abs() < 1e-6); // G = 5.556, A/A0 = 0.235823
//! # Ok(())
//! # }
//! ```
//!
//! This crate is the numerics only (features `bem`, `flow` and `topography`,
//! all on by default); the command-line tool and the scene files are the
//! `persson-cli` and `persson-studies` crates of the same workspace.
//!
//! ## Conventions
//!
//! Stated once here; every formula in the crate uses them.
//!
//! - **Units.** SI units and `f64` throughout: lengths in m, wavevectors in
//!   1/m. Pressures and moduli may be in any one unit (Pa, or E* = 1); every
//!   pressure-like result comes out in that unit. Dimensionless results are
//!   named `*_fraction` or `*_ratio`.
//! - **Wavevector.** `q` is the *angular* wavevector, q = 2π/λ, in 1/m (never
//!   in units of 2π/L).
//! - **Power spectrum.** C(q) is the isotropic power spectrum in **Persson's
//!   normalisation**, in m⁴:
//!   ```text
//!   C(q) = (2π)⁻² ∫ d²x ⟨h(x) h(0)⟩ e^{−i q·x}
//!   ⟨h²⟩ = 2π ∫ q C(q) dq,   ⟨|∇h|²⟩ = 2π ∫ q³ C(q) dq,   ⟨|∇²h|²⟩ = 2π ∫ q⁵ C(q) dq
//!   ```
//!   A spectrum in another normalisation (SurfaceTopography, a 1D profile
//!   spectrum, an FFT grid) enters only through an explicit
//!   [`spectrum::Convention`], never by guessing.
//! - **Contact modulus.** E* (`contact_modulus`) is the reduced modulus,
//!   1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ ([`Material`]); the theory depends on the
//!   materials through E* only.
//! - **Nominal pressure.** σ0 (`nominal_pressure`) is the nominal **mean**
//!   pressure, load / nominal area. For a Hertz ball σ0 = 2σH/3 and for a
//!   cylinder σ0 = πσH/4, σH the peak pressure of the smooth contact.
//! - **Magnification.** ζ (`zeta`) is the magnification, q = ζ q_l, ζ ≥ 1; the
//!   full magnification is ζ = q_s/q_l.
//! - **G and the contact area.** G(ζ) = (π/4)(E*/σ0)² ∫_{q_l}^{ζ q_l} q³ C(q) dq.
//!   `contact_fraction` is always the total A/A0 (elastic plus plastic);
//!   `elastic_fraction` and `plastic_fraction` are its parts where a yield
//!   stress exists, and `non_contact_fraction` is 1 − A/A0, computed without
//!   cancellation.
//! - **Errors.** `error_bound` (or `<quantity>_error_bound`) bounds the
//!   absolute error of the value it follows; `error` is an achieved error
//!   against an independent reference; `standard_error` is statistical.
//!
//! ## Names
//!
//! One name per quantity: the Rust field, the JSON key and the CSV header are
//! the same snake_case word, and the command-line flag is its kebab-case form.
//! Values from a closed set (theory, boundary, start, convention) are spelled
//! as on the command line (`yang-persson`, `surface-topography`), in scene
//! files too.
//!
#![doc = include_str!("names.md")]
//!
//! ## Modules
//!
//! | module | what it holds |
//! |---|---|
//! | [`spectrum`] | the [`Spectrum`] trait, the self-affine, tabulated and function spectra, and the conversions from other normalisations |
//! | [`material`] | elastic bodies and the contact modulus E* |
//! | [`theory`] | Persson's theory: G(ζ), A/A0 and 1 − A/A0 with error bounds, load and magnification curves |
//! | [`kappa`] | κ of the low-load law A/A0 = κ σ0/(E* h'_rms): Bush and Persson |
//! | [`asperity`] | the asperity theories from the same moments m0, m2, m4 (or a map): overlap (bearing area), Greenwood–Williamson, Bush–Gibson–Thomas at finite load, with validity flags |
//! | [`corrected`] | the corrected theories (Yang–Persson, Wang–Müser, Xu et al.) with their parameter γ |
//! | [`stress`] | the stress distribution P(σ, ζ) for flat, Hertz, cylinder and tabulated starts, elastic or with a yield stress |
//! | [`adhesion`] | adhesion: the Persson–Tosatti energy balance Δγ_eff(ζ), the adhesive stress diffusion with the moving detachment boundary (A/A0 down to tensile σ0, pull-off stress) and the Pastewka–Robbins criterion |
//! | [`separation`] | the mean interfacial separation ū, the contact stiffness and the stored elastic energy |
//! | [`friction`] | rubber friction: Persson's viscoelastic μ(v, T) from a master curve, a Prony series or a standard linear solid, with time–temperature superposition, A(v)/A0 and the flash temperature |
//! | [`conductance`] | thermal and electrical contact conductance from the stiffness (Barber's identity) and the conductance through the gap |
//! | [`leakage`] | the leak rate of a static seal: critical junction and effective medium |
//! | [`gap`] | the distribution of interfacial separations P(u) and the magnification-resolved separation u1(ζ) |
//! | [`reference`](mod@reference) | closed-form Hertz contacts (ball and cylinder): the smooth starts of the stress distributions and the BEM's validation |
//! | `bem` | (feature `bem`) the FFT boundary-element solver: elastic kernels, surface synthesis, the Polonsky–Keer, preconditioned, saturated and adhesive loops, Hertz validation, Reynolds flow on the gap (feature `flow`) |
//! | `topography` | (feature `topography`) measured surfaces: the instrument file readers, detrending, windows, radially averaged spectra, statistics |
//! | [`names`] | the closed sets of names (boundary, window, cohesive law, …): each value's name and description, serde by name |
//! | [`io`] | grid file I/O: the one `.npy` reader and writer, the one text reader, atomic writes, input files held in memory (a host without a file system) |
//! | [`clock`] | the solvers' wall-clock time on every target (a host without a clock, e.g. a browser, gives its own) |
//! | [`error`] | the crate's [`Error`] and [`Result`]; [`Estimate`] is a value with its error bound, which many functions return |
//!
//! ## References
//!
//! - B. N. J. Persson, F. Bucher, B. Chiaia, *Elastoplastic contact between
//!   randomly rough surfaces*, Phys. Rev. B 65, 184106 (2002),
//!   doi:10.1103/PhysRevB.65.184106: G(ζ), A/A0, the stress distribution P(σ, ζ)
//!   and its starts.
//! - B. N. J. Persson, J. Chem. Phys. 115, 3840 (2001): the theory; κ = √(8/π).
//! - A. W. Bush, R. D. Gibson, T. R. Thomas, Wear 35, 87 (1975): κ = √(2π).
//! - C. Yang, B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214 (2008);
//!   A. Wang, M. H. Müser, Tribol. Lett. 65, 103 (2017); Y. Xu et al., Tribol.
//!   Lett. (2024), doi:10.1007/s11249-024-01838-4: the corrected theories.
//! - B. N. J. Persson, Phys. Rev. Lett. 99, 125502 (2007): the mean separation.
//! - C. Campañá, M. H. Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005:
//!   κ ≈ 2 from Green's function molecular dynamics, the N^−0.7 resolution correction.
//! - I. A. Polonsky, L. M. Keer, Wear 231, 206 (1999),
//!   doi:10.1016/S0043-1648(99)00113-1: the constrained conjugate-gradient solver.
//! - J. F. Molinari, EPFL lecture "From single asperity to multi asperity
//!   contact": the FFT-BEM and its Hertz error table (Table 1).

#![warn(missing_docs)]

pub mod adhesion;
pub mod asperity;
#[cfg(feature = "bem")]
pub mod bem;
pub mod clock;
pub mod conductance;
pub mod corrected;
pub mod error;
#[cfg(any(feature = "bem", feature = "topography"))]
mod fft;
pub mod friction;
pub mod gap;
pub mod io;
pub mod kappa;
pub mod leakage;
pub mod material;
pub mod names;
mod quad;
pub mod reference;
pub mod separation;
mod special;
pub mod spectrum;
pub mod stress;
pub mod theory;
#[cfg(feature = "topography")]
pub mod topography;

pub use error::{Error, Result};
pub use material::Material;
/// A value with a bound on its absolute error, returned by every integral.
pub use quad::Estimate;
pub use spectrum::Spectrum;

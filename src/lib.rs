//! # persson
//!
//! Contact mechanics of randomly rough surfaces: Persson's theory of contact
//! (G(ζ), the real contact area A/A0, the stress distribution P(σ, ζ)), the
//! Bush and Persson κ, and (feature `bem`) an FFT boundary-element solver to
//! cross-check the theory against an exact numerical solution.
//!
//! ## Conventions (stated once, used everywhere)
//! - SI units and `f64`; pressures and moduli may be in any one unit (Pa, or E* = 1).
//! - `q` is the angular wavevector in 1/m; `C(q)` is the isotropic power
//!   spectrum in **Persson's normalisation**
//!   `C(q) = (2π)⁻² ∫ d²x ⟨h(x)h(0)⟩ e^{−iq·x}` (m⁴), so that
//!   `⟨h²⟩ = 2π ∫ q C dq`, `⟨|∇h|²⟩ = 2π ∫ q³ C dq`. Other conventions enter
//!   only through [`spectrum::Convention`].
//! - `E*` (`contact_modulus`) is the reduced modulus, 1/E* = Σ (1 − ν²)/E.
//! - `σ0` (`nominal_pressure`) is the nominal **mean** pressure, load / nominal area.
//! - `ζ` (`zeta`) is the magnification, `q = ζ q_l`, ζ ≥ 1.
//! - `contact_fraction` is A/A0, the dimensionless real contact area.
//!
//! The equations are those of Persson, Bucher & Chiaia, PRB 65, 184106 (2002)
//! (seed 001), reconstructed in `../shared/theory.md`.

#![warn(missing_docs)]

#[cfg(feature = "bem")]
pub mod bem;
pub mod compare;
#[cfg(feature = "bem")]
pub mod compare_bem;
pub mod corrected;
pub mod error;
pub mod io;
pub mod kappa;
pub mod material;
#[cfg(feature = "plot")]
pub mod plot;
pub mod quad;
pub mod reference;
pub mod report;
pub mod scene;
pub mod separation;
pub mod special;
pub mod spectrum;
pub mod stress;
pub mod table;
pub mod theory;

pub use error::{Error, Result};
pub use material::Material;
pub use spectrum::Spectrum;

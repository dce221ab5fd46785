//! Adhesion between an elastic body and a randomly rough rigid surface, from
//! Persson's theory: the energy balance at full contact (Persson & Tosatti
//! 2001), the adhesive stress diffusion with a moving detachment boundary
//! (Persson 2002) and, beside them, the stickiness criterion of Pastewka &
//! Robbins (2014); and, as the oracle of the adhesive BEM's sphere, Maugis's
//! (1992) Dugdale-zone solution between JKR and DMT ([`MaugisDugdale`]).
//!
//! # Formula
//! Conventions of the crate (C(q) in Persson's normalisation, E* the contact
//! modulus, σ0 the nominal mean pressure, ζ = q/q_l); Δγ is the work of
//! adhesion (J/m²), the energy per unit area gained when the two surfaces come
//! into atomic contact.
//! ```text
//! ξ²(ζ)        = 2π ∫_{q_l}^{ζq_l} q³ C dq                     mean-square slope up to ζ
//! U_el(ζ)/A0   = (π E*/2) ∫_{q_l}^{ζq_l} q² C dq                elastic energy of full contact   [J/m²]
//! A_true/A0    = ∫₀^∞ e^{−x} (1 + ξ² x)^{1/2} dx
//!              = 1 + (√π ξ/2) erfcx(1/ξ)                        true (surface) area over projected
//! Δγ_eff(ζ)    = Δγ A_true(ζ)/A0 − U_el(ζ)/A0                   sticky at ζ when > 0          [J/m²]
//! ```
//! The adhesive contact (module [`AdhesiveContact`]) resolves the same balance
//! from the other end: the contact seen at magnification ζ must still flatten
//! the roughness finer than ζ,
//! ```text
//! γ_eff(ζ)  = Δγ a(ξ²_>(ζ)) − (π E*/2) ∫_{ζq_l}^{q_s} q² C dq,   ξ²_>(ζ) = 2π ∫_{ζq_l}^{q_s} q³ C dq
//! σ_a(ζ)    = [c_a γ_eff(ζ) E* ζ q_l]^{1/2}  (γ_eff > 0),  0 otherwise       detachment stress
//! t(ζ)      = σ0² G(ζ) = (π/4) E*² ∫_{q_l}^{ζq_l} q³ C dq = E*² ξ²(ζ)/8      [Pa²]
//! ∂P/∂t     = ∂²P/∂σ²,   σ > −σ_a(t),   P(−σ_a(t), t) = 0,   P(σ, 0) = δ(σ − σ0)
//! A/A0      = ∫_{−σ_a}^∞ P dσ;   pull-off stress σ_p = σ_a(ζ = 1)
//! ```
//! with a(x) = 1 + (√π/2)√x erfcx(1/√x) the true-area ratio for mean-square
//! slope x (or a ≡ 1, [`AreaEnhancement::None`]) and c_a the detachment
//! prefactor (1 by default). G = 0 and Δγ = 0 give σ_a ≡ 0 and the
//! non-adhesive A/A0 = erf(1/(2√G)) exactly.
//!
//! # Choices where the papers leave one
//! 1. **Area enhancement.** Persson & Tosatti (2001) multiply Δγ by the true
//!    surface area of Gaussian slopes; later work (Persson & Scaraggi 2014)
//!    drops it, and Ciavarella (Int. J. Mech. Sci. 2017) questions it. Both
//!    are offered ([`AreaEnhancement`]); the default keeps it (P&T).
//! 2. **γ_eff(ζ) of the diffusion.** Persson (2002) uses an effective
//!    interfacial energy at magnification ζ that pays for flattening the
//!    roughness finer than ζ. We take exactly the P&T full-contact balance over
//!    the band (ζ q_l, q_s), so γ_eff(ζ_max) = Δγ and γ_eff(1) is the P&T
//!    Δγ_eff of the whole band (full contact below every scale: an upper bound
//!    of the elastic cost, hence a lower bound of γ_eff).
//! 3. **σ_a where γ_eff ≤ 0.** The scale does not adhere: σ_a = 0 (the
//!    non-adhesive boundary P(0) = 0).
//! 4. **Detachment prefactor.** The local Griffith balance (stored elastic
//!    energy ~ σ² r³/E* of a contact of radius r ~ 1/q against γ_eff r²)
//!    fixes σ_a only up to a number of order one; Persson (2002) writes
//!    σ_a = [γ_eff E q/(1 − ν²)]^{1/2}, i.e. c_a = 1, which is the default;
//!    [`AdhesionModel::with_detachment_prefactor`] changes it.
//! 5. **Pull-off.** The start δ(σ − σ0) at ζ = 1 must lie inside the domain
//!    σ > −σ_a(1): a tension beyond σ_a(1) detaches the nominal contact at the
//!    largest scale (a Griffith crack of size ~1/q_l). A/A0 at full
//!    magnification falls continuously to 0 as σ0 → −σ_a(1), so the pull-off
//!    stress is σ_p = σ_a(ζ = 1) = [c_a γ_eff(1) E* q_l]^{1/2}, positive
//!    exactly when the P&T balance of the whole band says sticky.
//! 6. **Load.** The absorbing boundary removes contact that carried the
//!    tension σ_a: the pressure carried by the contact at ζ is
//!    σ0 + ∫ σ_a dA_detached ≥ σ0 (reported as `carried_pressure` and
//!    `released_tension`, whose difference is σ0 identically).
//!
//! # Method
//! Energy terms: closed-form moments of the spectrum and erfcx. The moving
//! boundary is solved as a Volterra integral equation of the second kind for
//! the rate g(t) at which contact detaches (first-passage density of the
//! diffusion), with a kernel that is regular on the diagonal (Buonocore,
//! Nobile & Ricciardi 1987); see [`AdhesiveContact`] for the equation, the
//! mesh, the accuracy knob and the error estimate. Where σ_a is constant the
//! kernel vanishes and the solution is the method of images of
//! [`crate::stress`] in closed form.
//!
//! # References
//! - B. N. J. Persson, E. Tosatti, *The effect of surface roughness on the
//!   adhesion of elastic solids*, J. Chem. Phys. 115, 5597 (2001),
//!   doi:10.1063/1.1398300: U_el, A_true and Δγ_eff.
//! - B. N. J. Persson, *Adhesion between an elastic body and a randomly rough
//!   hard surface*, Eur. Phys. J. E 8, 385 (2002), doi:10.1140/epje/i2001-10104-5,
//!   and *Adhesion between elastic bodies with randomly rough surfaces*, Phys.
//!   Rev. Lett. 89, 245502 (2002), doi:10.1103/PhysRevLett.89.245502: the
//!   boundary condition P(−σ_a(ζ), ζ) = 0 and σ_a from the local energy balance.
//! - B. N. J. Persson, M. Scaraggi, *Theory of adhesion: role of surface
//!   roughness*, J. Chem. Phys. 141, 124701 (2014), doi:10.1063/1.4895789.
//! - L. Pastewka, M. O. Robbins, *Contact between rough surfaces and a
//!   criterion for macroscopic adhesion*, Proc. Natl. Acad. Sci. 111, 3298
//!   (2014), doi:10.1073/pnas.1320846111: [`PastewkaRobbins`].
//! - A. Buonocore, A. G. Nobile, L. M. Ricciardi, *A new integral equation for
//!   the evaluation of first-passage-time probability densities*, Adv. Appl.
//!   Probab. 19, 784 (1987), doi:10.2307/1427102: the regular kernel.
//!
//! # What is verified, and what is this crate's derivation
//! The papers' texts could not be read from this workplace: a search of the
//! public pages and documentation corpora (Nov 2026) returned their abstracts
//! and the section headings of Persson's review (Surf. Sci. Rep. 61, 201
//! (2006), Sec. 8.1 "Boundary condition and physical interpretation"), not
//! their equations. No equation number or prefactor above is therefore
//! checked against a paper. What is checked, against independent
//! computations (`tests/adhesion.rs`): U_el (the full-contact energy ½⟨pu⟩
//! with p̂ = E*qû/2), A_true/A0 of Gaussian slopes (mpmath), Δγ_eff, the
//! non-adhesive limit erf(1/(2√G)), and the moving-boundary diffusion
//! (finite differences). Choices 2–5 above, and c_a = 1 in particular, are
//! this crate's derivation (a Griffith balance fixes σ_a only up to a number
//! of order one), as are the Pastewka–Robbins constants κ_rep = 2 and
//! d_rep = 4h'_rms/h''_rms (taken from the authors' group's code, not from
//! their Eq. 10).

mod contact;
mod detachment;
mod energy;
mod maugis_dugdale;
mod model;
mod moving;
mod pastewka_robbins;

pub use contact::{AdhesiveContact, AdhesivePoint, Flag};
pub use detachment::DetachmentPoint;
pub use energy::{true_area_ratio, EnergyPoint, Stickiness};
pub use maugis_dugdale::{MaugisDugdale, MaugisPoint};
pub use model::{AdhesionModel, AreaEnhancement};
pub use pastewka_robbins::{PastewkaRobbins, StickinessComparison};

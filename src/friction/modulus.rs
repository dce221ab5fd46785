//! The values the rubber's modulus models share: E′ and E″ at one
//! frequency, the angular integrals A(w) and B(w) of the friction theory
//! (see [`super::viscoelastic`]), and the bound on a modulus that keeps
//! |E|² finite. A leaf of the friction module: the Prony series and the
//! master curve both return these.

/// E′ and E″ at one angular frequency, Pa.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Modulus {
    /// Storage modulus E′ = Re E, Pa.
    pub storage_modulus: f64,
    /// Loss modulus E″ = Im E, Pa (odd in ω).
    pub loss_modulus: f64,
}

impl Modulus {
    /// E′ + i E″ from its parts.
    pub fn new(storage_modulus: f64, loss_modulus: f64) -> Self {
        Modulus {
            storage_modulus,
            loss_modulus,
        }
    }
}

/// The angular integrals A(w) and B(w) at one w = q v (see the module docs),
/// with the parts that came from frequencies outside a master curve's table.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
#[non_exhaustive]
pub struct AngularIntegrals {
    /// A(w) = ∫₀^{π/2} cos φ E″(w cos φ) dφ, Pa.
    pub loss: f64,
    /// B(w) = ∫₀^{π/2} |E(w cos φ)|² dφ, Pa².
    pub modulus_squared: f64,
    /// The part of A from frequencies outside the table (0 for a Prony series), Pa.
    pub loss_outside: f64,
    /// The part of B from frequencies outside the table (0 for a Prony series), Pa².
    pub modulus_squared_outside: f64,
}

/// The largest modulus a rubber may have, Pa: √f64::MAX/4 ≈ 3.35e153.
///
/// # Bound
/// The friction theory squares the modulus, |E|² = E′² + E″², and sums it
/// over the angular integral B(w) = ∫₀¹ |E(wu)|² (1 − u²)^{−1/2} du, whose
/// weight totals π/2: with E′, E″ ≤ √f64::MAX/4, |E|² ≤ f64::MAX/8 and
/// B ≤ (π/2) f64::MAX/8 < f64::MAX/4 (a Prony series' |E| is at most its
/// glassy modulus E∞ + Σ E_k, which is held to the bound).
pub const MAX_MODULUS: f64 = 1.340_780_792_994_259_6e154 / 4.0;

/// The requirement stated when a modulus exceeds [`MAX_MODULUS`].
pub(crate) fn modulus_requirement() -> String {
    format!(
        "finite, > 0 and at most √f64::MAX/4 = {} Pa so that |E|² = E′² + E″² stays finite",
        crate::error::approx(MAX_MODULUS)
    )
}

//! The rubber's thermal properties and the heat kernel of the flash
//! temperature: how much a contact spot of size ~π/q warms up while a rubber
//! element slides across it.
//!
//! # Formula
//! The dissipation of roughness band q is produced under the contact spots of
//! that magnification, with depth profile e^{−2qz} (the strain of a surface
//! mode of wavevector q decays as e^{−qz}) and lateral wavevector q; a rubber
//! element stays in a spot for τ = π/(q v) (half a wavelength). The heat
//! equation ∂T/∂t = D∇²T + Q̇/(ρc) in the rubber (z > 0, no heat flow into the
//! substrate) gives at the spot's surface, after τ, T = (Q̇0/ρc) h(q) with
//! ```text
//! h(q) = (1/π) ∫₀^∞ dk [4q/(4q² + k²)] (1 − e^{−D(q² + k²)τ}) / (D(q² + k²))
//!      = τ R(x),   x² = D q² τ = π D q / v
//! R(x) = [2 erf(x) − 1 + e^{−x²} erfcx(2x)] / (3x²)
//! ```
//! R → 1 (adiabatic: h = τ) for x → 0 and R → 1/(3x²) (steady conduction:
//! h = 1/(3 D q²)) for x → ∞. D = κ/(ρc) in m²/s; q in 1/m; v in m/s; h in s.
//! The k-integral was done by partial fractions in k² and
//! ∫₀^∞ e^{−sk²}/(k² + a²) dk = (π/2a) erfcx(a√s); for x < 0.1 R is summed
//! from its Taylor series (coefficients from mpmath,
//! `tests/reference/friction_heat_kernel.py`), which avoids the cancellation
//! of the O(1) terms of the numerator.
//!
//! # Checks
//! - The closed form solves the heat equation of the model: in the units
//!   z → qz, t → Dq²t, u = Dq² ρc T/Q̇0 it reads u_t = u_zz − u + e^{−2z},
//!   u_z(0) = 0, u(z, 0) = 0, whose surface value has the Laplace transform
//!   U(0, s) = 1/(s √(s+1) (√(s+1) + 2)); R(x) = u(0, x²)/x² from its
//!   numerical inversion (mpmath) is a test (`tests/friction/flash.rs`),
//!   independent of the k-integral and of the erf form, as are both limits.
//! - Energy: the adiabatic rise of band q is Q̇0 τ/(ρc) with Q̇0 = 2q × the
//!   band's power per unit contact area, i.e. 2π σ0 dμ/(P ρc): the frictional
//!   work of half a wavelength deposited in a layer 1/(2q) deep. In full
//!   contact the adiabatic flash temperature is 2π σ0 μ/(ρc) (tested in
//!   closed form for a frequency-independent loss).
//!
//! # References
//! - B. N. J. Persson, J. Phys.: Condens. Matter 18, 7789 (2006),
//!   doi:10.1088/0953-8984/18/32/025 (arXiv:cond-mat/0605273): the
//!   flash temperature T_q of the contact regions at magnification q/q_L,
//!   built up from the heat produced at the larger scales q′ < q and fed back
//!   into E(ω, T_q). **Not checked factor by factor.** The stored copies of
//!   the paper reachable here (ar5iv, core.ac.uk, tomesphere) hold only its
//!   title, abstract and first paragraph; the later papers that restate the
//!   equations (Fortunato et al., J. Phys.: Condens. Matter 27, 175008
//!   (2015); Fortunato et al., arXiv:1512.01359; Lorenz et al., Eur. Phys.
//!   J. E 34, 129 (2011)) only their abstracts; the open implementations
//!   found either have no flash temperature (`perssonmodelling`) or use
//!   Greenwood's single-contact interpolation formula instead of a per-scale
//!   kernel. So the source depth 1/(2q), the spot size π/q, the contact time
//!   τ = π/(qv), the insulated surface and the dependence of the kernel on
//!   q′ only (not on the observation scale q) are this crate's choices; the
//!   paper's kernel may differ in any of them by factors of order one.
//! - H. S. Carslaw, J. C. Jaeger, *Conduction of Heat in Solids*, 2nd ed.
//!   (Oxford, 1959), ch. 10 (instantaneous and continuous sources).

use crate::error::{check, Result};
use crate::special::{erf, erfcx};

/// R(x) = Σ_k R_SERIES[k] x^k (mpmath, 20 digits; `tests/reference/friction_heat_kernel.py`).
#[allow(clippy::excessive_precision)] // the references keep 20 digits
const R_SERIES: [f64; 21] = [
    1.0,
    -1.504_505_556_127_350_1,
    1.5,
    -1.504_505_556_127_350_1,
    1.5,
    -1.354_055_000_514_615_1,
    1.125,
    -8.907_628_133_896_850_6e-1,
    6.75e-1,
    -4.877_702_537_127_162_8e-1,
    3.375e-1,
    -2.248_617_070_359_167_2e-1,
    1.446_428_571_428_571_4e-1,
    -8.997_683_036_898_479_3e-2,
    5.424_107_142_857_142_9e-2,
    -3.175_301_644_779_265_5e-2,
    1.808_035_714_285_714_3e-2,
    -1.002_761_492_276_327_8e-2,
    5.424_107_142_857_142_9e-3,
    -2.865_001_662_037_715_2e-3,
    1.479_301_948_051_948_1e-3,
];

/// Below this x the series is used (its first dropped term is ~1e-24 there;
/// the closed form would lose ~ε/(3x²) ≈ 1e-14 to cancellation).
const SERIES_MAX_X: f64 = 0.1;

/// Thermal properties of the rubber.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Thermal {
    thermal_conductivity: f64,
    density: f64,
    heat_capacity: f64,
}

impl Thermal {
    /// From κ (W/(m K)), ρ (kg/m³) and the specific heat capacity c (J/(kg K)).
    ///
    /// # Errors
    /// Any of them not finite and > 0, naming `thermal_conductivity`,
    /// `density` or `heat_capacity`.
    pub fn new(thermal_conductivity: f64, density: f64, heat_capacity: f64) -> Result<Self> {
        Ok(Thermal {
            thermal_conductivity: check::positive("thermal_conductivity", thermal_conductivity)?,
            density: check::positive("density", density)?,
            heat_capacity: check::positive("heat_capacity", heat_capacity)?,
        })
    }

    /// κ, W/(m K).
    pub fn thermal_conductivity(&self) -> f64 {
        self.thermal_conductivity
    }

    /// ρ, kg/m³.
    pub fn density(&self) -> f64 {
        self.density
    }

    /// c, J/(kg K).
    pub fn heat_capacity(&self) -> f64 {
        self.heat_capacity
    }

    /// ρ c, J/(m³ K).
    pub fn volumetric_heat_capacity(&self) -> f64 {
        self.density * self.heat_capacity
    }

    /// D = κ/(ρ c), m²/s.
    pub fn thermal_diffusivity(&self) -> f64 {
        self.thermal_conductivity / self.volumetric_heat_capacity()
    }
}

/// R(x) (module docs): 1 at x = 0, 1/(3x²) for large x.
///
/// # Examples
/// ```
/// // mpmath: R(1) = 0.25978546819271372061 (tests/reference/friction_heat_kernel.py)
/// let r = persson::friction::heat_kernel_ratio(1.0);
/// assert!((r - 0.259_785_468_192_713_72).abs() < 1e-15);
/// ```
pub fn heat_kernel_ratio(x: f64) -> f64 {
    if x < SERIES_MAX_X {
        R_SERIES.iter().rev().fold(0.0, |s, c| s * x + c)
    } else {
        (2.0 * erf(x) - 1.0 + (-x * x).exp() * erfcx(2.0 * x)) / (3.0 * x * x)
    }
}

/// h(q) = τ R(x) in s (module docs): the temperature rise per unit heating
/// rate Q̇0/(ρc) of a contact spot at wavevector q (1/m), for sliding velocity
/// v (m/s) and thermal diffusivity D (m²/s).
pub fn heat_kernel(q: f64, velocity: f64, diffusivity: f64) -> f64 {
    let tau = std::f64::consts::PI / (q * velocity);
    tau * heat_kernel_ratio((diffusivity * tau).sqrt() * q)
}

/// ρc (J/(m³ K)) below which the flash march carries the kernel as
/// h(q)/(ρc) ([`heat_kernel_per_capacity`]): 1. No condensed matter, nor a
/// gas at 1 bar (air: 1.2e3), comes within 10³ of it, so physical inputs keep
/// the product of [`heat_kernel`] and 4v/((1 − ν²)ρc) as it always was; below
/// it that prefactor grows towards f64::MAX (ρ = 1e-300 kg/m³: 3.6e295) and
/// its product with the integrand overflowed before the tiny h(q) came in.
pub(crate) const MIN_HEAT_CAPACITY: f64 = 1.0;

/// h(q)/(ρc) in s m³ K/J, without forming 1/(ρc): the temperature rise per
/// unit heating rate Q̇0 itself.
///
/// # Formula
/// ```text
/// h/(ρc) = τ R(x)/(ρc)                           x < 0.1 (series)
///        = S(x)/(3 κ q²),  S = 3x² R(x)           x ≥ 0.1
/// ```
/// since 3x² ρc = 3π κ q/v and τ = π/(qv). S(x) = 2 erf(x) − 1 + e^{−x²} erfcx(2x)
/// lies in (0, 1] and tends to 1 as ρc → 0 (x → ∞): the steady-conduction
/// limit 1/(3κq²), which does not depend on ρc.
pub(crate) fn heat_kernel_per_capacity(q: f64, velocity: f64, thermal: &Thermal) -> f64 {
    let tau = std::f64::consts::PI / (q * velocity);
    let x = (thermal.thermal_diffusivity() * tau).sqrt() * q;
    if x < SERIES_MAX_X {
        tau * heat_kernel_ratio(x) / thermal.volumetric_heat_capacity()
    } else {
        let s = if x.is_finite() {
            2.0 * erf(x) - 1.0 + (-x * x).exp() * erfcx(2.0 * x)
        } else {
            1.0
        };
        s / (3.0 * thermal.thermal_conductivity * q * q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values of R from mpmath (k-integral and erf form agree to 1e-30).
    #[allow(clippy::excessive_precision)] // the references keep 20 digits
    const R_TABLE: [(f64, f64); 7] = [
        (1e-3, 9.984_969_929_408_657_4e-1),
        (0.05, 9.283_456_277_645_918_7e-1),
        (0.1, 8.631_824_404_987_184_4e-1),
        (0.3, 6.525_479_899_332_334e-1),
        (1.0, 2.597_854_681_927_137_2e-1),
        (3.0, 3.703_582_476_089_107_1e-2),
        (30.0, 3.703_703_703_703_703_7e-4),
    ];

    /// erf/erfcx are ≤ 2 ulp; at x = 0.1 the numerator cancels to 3e-2.
    const R_TOL: f64 = 1e-14;

    #[test]
    fn ratio_against_mpmath() {
        for (x, want) in R_TABLE {
            let r = heat_kernel_ratio(x);
            assert!(
                (r - want).abs() <= R_TOL * want,
                "R({x}) = {r}, want {want}"
            );
        }
        // Both branches agree at the switch.
        let below = heat_kernel_ratio(SERIES_MAX_X * (1.0 - 1e-15));
        let above = heat_kernel_ratio(SERIES_MAX_X);
        assert!((below - above).abs() < R_TOL);
    }

    #[test]
    fn limits() {
        let (q, v, d) = (1e5, 1.0, 1e-7);
        let tau = std::f64::consts::PI / (q * v);
        assert!((heat_kernel(q, v, 1e-30) / tau - 1.0).abs() < 1e-12);
        let steady = heat_kernel(q, 1e-12, d);
        assert!((steady * 3.0 * d * q * q - 1.0).abs() < 1e-6);
        assert!(Thermal::new(0.2, -1.0, 1e3)
            .unwrap_err()
            .to_string()
            .contains("density"));
    }
}

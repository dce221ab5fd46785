//! Bush, Gibson & Thomas (BGT): the elastic contact of an isotropic Gaussian
//! surface whose summits are elliptic paraboloids, at finite load.
//!
//! # What it solves
//! The surface is Nayak's random process with profile moments m0, m2, m4.
//! Every summit (local maximum) has a height h and principal curvatures
//! κ1 ≥ κ2 > 0 drawn from their exact joint density (Kac–Rice); near the flat
//! it is replaced by the paraboloid with those curvatures, in Hertz contact
//! (module `hertz_ellipse`: Hertz's elliptic solution), independently of its neighbours.
//!
//! # Formula
//! Standardised variables ξ = h/√m0, u = (κ1 + κ2)/(2√m4), r = (κ1 − κ2)/(2√m4):
//! ```text
//! summits per area and per dξ du dr = (m4/(2π m2)) p(ξ, u) · (3r e^{−3r²/2}) · (u² − r²) · 1{u > r}
//! (ξ, u) jointly normal: Var ξ = 1, Var u = 2/3, Cov = 1/√α;  r Rayleigh, ⟨r²⟩ = 2/3, independent
//! ```
//! (the summit density m4/(6π√3 m2) of Nayak 1971 is its integral). With
//! δ = d/√m0, a summit of height ξ > δ carries the area π w F_A/√(κ1κ2) and the
//! load (4/3)E* w^{3/2} F_P (κ1κ2)^{−1/4}, w = √m0 (ξ − δ). Integrating r with
//! v = (r/u)² gives the curvature kernels K_γ (private module `kernel`), and ξ in
//! closed form given u (ξ | u ~ N(3u/(2√α), s_c²), s_c² = 1 − 3/(2α)):
//! ```text
//! J_{k,γ}(δ) = ∫_0^∞ N(u; 0, 2/3) · 3 u^{2+2γ} K_γ(3u²/2) · s_c^k F_k((δ − 3u/(2√α))/s_c) du
//! n(δ)   = (m4/(2π m2)) J_{0,1}                       contacts per area, 1/m²
//! A/A0   = (√α/2) J_{1,½}
//! σ0/E*  = (2/(3π)) √m2 α^{3/4} J_{3/2,¾}
//! ```
//! At low load (δ → ∞) only high summits touch; their curvature is
//! u ≈ δ/√α ≫ its spread, they are spheres (F → 1) and
//! ```text
//! A/A0 → κ σ0/(E* h'_rms),   κ = (3π√2/4)/Γ(5/2) = √(2π),   h'_rms = √(2 m2)
//! ```
//! for every α: BGT's linear law with κ_Bush = √(2π) (Bush et al. 1975;
//! Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Sec. IV).
//!
//! # Method
//! Factoring φ(δ) out exactly, N(u;0,2/3)·s_c^k F_k(z) = φ(δ) s_c^{k+1} N(u; δ/√α, 2/3 − 1/α) R_k(z)
//! with R_k = F_k/φ (the scaled Gaussian integrals), so that nothing
//! underflows at low load; each J is then one adaptive Gauss–Kronrod
//! integral over u around δ/√α, to the relative tolerance of the model
//! ([`Bush::with_tolerance`]). This direct path serves every δ. For
//! δ ≤ 12 and α ≥ 4 a faster path is used: the height-resolved weights
//! g_γ(ξ) = E[3u^{2+2γ}K_γ(3u²/2) | ξ] are tabulated once per surface
//! (Chebyshev series of ln g on ξ ∈ [−10, 16]) and
//! J(δ) = ∫ (ξ − δ)^k φ(ξ) g_γ(ξ) dξ runs over w = √(ξ − δ) with
//! Gauss–Legendre (tested against the direct path to 1e-12).
//! On top of it, for −6 ≤ δ ≤ 12, ln(J/φ) itself is tabulated in δ once per
//! surface (private module `separation_table`: Chebyshev series on four
//! pieces, refused unless the series' tails, its error estimate, are below
//! 1e-13; tested off the nodes against the direct path to 1e-12), so that a
//! point costs four series sums (~0.2 µs) instead of a w-integral (~7 µs).
//! The separation at a given σ0: Newton's method on ln σ0(δ) with
//! d ln J_{3/2}/dδ = −(3/2) J_½/J_{3/2} on the fast paths, else bracketing
//! and the Illinois method.
//!
//! # Choices
//! The Bush, Gibson & Thomas paper was not available to check against; the
//! model above is the one its abstract and later accounts describe (Nayak's
//! summits as paraboloids of the same principal curvatures, Hertz contact),
//! rederived here with the exact summit density for every α and Hertz's
//! exact elliptic solution ([`EllipticHertz::Exact`]); Greenwood's
//! geometric-mean sphere is an option ([`EllipticHertz::GeometricMean`]).
//! Both give κ = √(2π) at low load.
//!
//! # References
//! - A. W. Bush, R. D. Gibson, T. R. Thomas, Wear 35, 87 (1975),
//!   doi:10.1016/0043-1648(75)90145-3.
//! - P. R. Nayak, J. Lubr. Technol. 93, 398 (1971), doi:10.1115/1.3451608.
//! - J. A. Greenwood, Wear 261, 191 (2006), doi:10.1016/j.wear.2005.09.031:
//!   the geometric-mean ("simplified elliptic") model.
//! - G. Carbone, F. Bottiglione, J. Mech. Phys. Solids 56, 2555 (2008),
//!   doi:10.1016/j.jmps.2008.03.011.

use super::gaussian::{ln_scaled_tail_moment, Order, SQRT_TAU};
use super::kernel::{kernels, Kernel, Kernels};
use super::separation_table::SeparationTable;
use super::summit_table::{SummitTable, MIN_ALPHA};
use super::{
    check_separation, point_validity, solve_separation, AsperityPoint, AsperityTheory,
    SpectralMoments, Validity,
};
use crate::error::{check, Error, Result};
use crate::quad::integrate;

/// Default relative tolerance of the u-integrals.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// Evaluations allowed per u-integral.
const MAX_EVALS: usize = 20_000;

/// Half-width of the u-interval in standard deviations of u | ξ.
const WIDTH: f64 = 14.0;

/// Newton iterations allowed for the separation at a given σ0.
const NEWTON_ITERATIONS: usize = 60;

/// Separation (in rms heights) at which [`Bush::low_load_kappa`] evaluates
/// κ: the corrections are O(α/δ²), below 1e-13 there.
const LOW_LOAD_SEPARATION: f64 = 1e8;

/// How a summit's elliptic Hertz contact is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum EllipticHertz {
    /// Hertz's elliptic solution (Johnson 1985, §4.2).
    Exact,
    /// The sphere of the geometric-mean radius 1/√(κ1κ2) (Greenwood 2006).
    GeometricMean,
}

/// The BGT model (module docs).
#[derive(Debug, Clone)]
pub struct Bush {
    moments: SpectralMoments,
    e_star: f64,
    hertz: EllipticHertz,
    kernels: &'static Kernels,
    tolerance: f64,
    validity: Vec<Validity>,
    /// g_γ(ξ) tables for the fast path, built on first use.
    table: std::sync::OnceLock<Option<SummitTable>>,
    /// ln J/φ tabulated in δ from the summit table, built on first use.
    separation_table: std::sync::OnceLock<Option<SeparationTable>>,
    /// Whether the δ-table may be used ([`Bush::with_separation_table`]).
    use_separation_table: bool,
    /// α, 3/(2√α), s_c, s_u.
    alpha: f64,
    slope: f64,
    s_c: f64,
    s_u: f64,
}

/// J_{k,γ}(δ)/φ(δ) for the three quantities.
#[derive(Debug, Clone, Copy)]
struct Scaled {
    count: f64,
    area: f64,
    load: f64,
}

impl Bush {
    /// BGT for a surface of moments m0, m2, m4 and contact modulus E*.
    /// Carries [`Validity::SmallBandwidth`] when α < 10.
    ///
    /// # Errors
    /// `contact_modulus` not finite and > 0; [`Error::InvalidParameter`]
    /// naming `bandwidth_parameter` when α is within 1e-9 of 3/2 (a ring
    /// spectrum, whose curvature is fixed by the height); the curvature
    /// kernels failing to build (not expected).
    ///
    /// # Examples
    /// ```
    /// use persson::asperity::{Bush, EllipticHertz, SpectralMoments};
    /// let m = SpectralMoments::new(1e-12, 1e-2, 1e9).unwrap(); // α = 10
    /// let bgt = Bush::new(&m, 1.0, EllipticHertz::Exact).unwrap();
    /// // BGT's low-load law A/A0 = √(2π) σ0/(E* h'_rms).
    /// assert!((bgt.low_load_kappa().unwrap() - (2.0 * std::f64::consts::PI).sqrt()).abs() < 1e-12);
    /// ```
    pub fn new(
        moments: &SpectralMoments,
        contact_modulus: f64,
        hertz: EllipticHertz,
    ) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        let alpha = moments.bandwidth_parameter();
        let s_u2 = 2.0 / 3.0 - 1.0 / alpha;
        if s_u2.is_nan() || s_u2 <= 1e-9 {
            return Err(Error::invalid(
                "bandwidth_parameter",
                alpha,
                "> 1.5 for BGT (at 1.5, a ring spectrum, the summit curvature is fixed by the height)",
            ));
        }
        Ok(Bush {
            moments: *moments,
            e_star: contact_modulus,
            hertz,
            kernels: kernels(hertz)?,
            tolerance: DEFAULT_TOLERANCE,
            validity: moments.validity(),
            table: std::sync::OnceLock::new(),
            separation_table: std::sync::OnceLock::new(),
            use_separation_table: true,
            alpha,
            slope: 1.5 / alpha.sqrt(),
            s_c: (1.5 * s_u2).sqrt(),
            s_u: s_u2.sqrt(),
        })
    }

    /// The same model with the relative tolerance `tolerance` of its
    /// u-integrals (the accuracy knob; default [`DEFAULT_TOLERANCE`]).
    ///
    /// At the default, points with δ ≤ 12 and α ≥ 4 come from the tables
    /// (tested to 1e-12 against the direct integrals, ~0.2 µs a point for
    /// −6 ≤ δ ≤ 12, ~7 µs below);
    /// a tighter tolerance bypasses the table and integrates every point
    /// directly (~0.9 ms a point).
    ///
    /// # Errors
    /// `tolerance` outside [1e-15, 0.1].
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        self.tolerance = check::tolerance("tolerance", tolerance)?;
        Ok(self)
    }

    /// The same model with (`true`, the default) or without the table of
    /// ln J/φ in δ (module docs); without it every point integrates the
    /// summit table. For benchmarks and tests of the two paths.
    #[doc(hidden)]
    pub fn with_separation_table(mut self, on: bool) -> Self {
        self.use_separation_table = on;
        self.separation_table = std::sync::OnceLock::new();
        self
    }

    /// The δ-table's error estimate (largest tail coefficient of its
    /// series, in ln J/φ), `None` when it is not in use.
    #[doc(hidden)]
    pub fn separation_table_tail(&self) -> Option<f64> {
        self.separation_table().map(SeparationTable::tail)
    }

    /// The elliptic Hertz treatment.
    pub fn hertz(&self) -> EllipticHertz {
        self.hertz
    }

    /// The local κ = (A/A0) E* h'_rms/σ0 at `separation` (m), h'_rms = √(2 m2).
    ///
    /// # Formula
    /// ```text
    /// κ(δ) = (3π√2/4) α^{−1/4} s_c^{−1/2} I_A(δ)/I_P(δ),   I = J/(φ(δ) s_c^{k+1})
    /// ```
    ///
    /// # Errors
    /// `separation` not finite; a u-integral not converging.
    pub fn kappa_at(&self, separation: f64) -> Result<f64> {
        let delta = check_separation(separation)? / self.moments.rms_height();
        let s = self.scaled(delta)?;
        // area/load = (√α/2) J_A / ((2/(3π)) √m2 α^{3/4} J_P) per unit E*.
        Ok(3.0 * std::f64::consts::PI / 4.0 * (2.0 / self.alpha.sqrt()).sqrt() * s.area / s.load)
    }

    /// BGT's low-load limit of κ, evaluated by the model at δ = 10⁸ rms
    /// heights (corrections O(α/δ²) < 1e-13): √(2π) for every α and both
    /// Hertz treatments.
    ///
    /// # Errors
    /// As [`Bush::kappa_at`].
    pub fn low_load_kappa(&self) -> Result<f64> {
        self.kappa_at(LOW_LOAD_SEPARATION * self.moments.rms_height())
    }

    /// J/φ by the direct u-integrals at δ (for tests of the table path).
    #[doc(hidden)]
    pub fn scaled_integrals_direct(&self, delta: f64) -> Result<[f64; 3]> {
        let s = self.scaled_direct(delta)?;
        Ok([s.count, s.area, s.load])
    }

    /// J/φ as [`AsperityTheory::at_separation`] computes them at δ.
    #[doc(hidden)]
    pub fn scaled_integrals(&self, delta: f64) -> Result<[f64; 3]> {
        let s = self.scaled(delta)?;
        Ok([s.count, s.area, s.load])
    }

    /// The summit table, when the tolerance allows it (built once).
    fn table(&self) -> Option<&SummitTable> {
        if self.tolerance < DEFAULT_TOLERANCE || self.alpha < MIN_ALPHA {
            return None;
        }
        self.table
            .get_or_init(|| SummitTable::build(self.alpha.sqrt(), self.s_u, self.kernels).ok())
            .as_ref()
    }

    /// The δ-table, when the summit table is in use and its error estimate
    /// passes (built once).
    fn separation_table(&self) -> Option<&SeparationTable> {
        if !self.use_separation_table {
            return None;
        }
        let summits = self.table()?;
        self.separation_table
            .get_or_init(|| SeparationTable::build(summits))
            .as_ref()
    }

    /// J/φ(δ) for count, area, load and the load's derivative weight from
    /// the δ-table, else the summit table; `None` where neither serves.
    fn fast(&self, delta: f64) -> Option<[f64; 4]> {
        self.separation_table()
            .and_then(|t| t.scaled(delta))
            .or_else(|| self.table().and_then(|t| t.scaled(delta)))
    }

    /// J_{k,γ}(δ)/φ(δ) for the count, area and load: from the tables for
    /// δ ≤ 12 (module docs), else by the direct u-integrals.
    fn scaled(&self, delta: f64) -> Result<Scaled> {
        if let Some([count, area, load, _]) = self.fast(delta) {
            return Ok(Scaled { count, area, load });
        }
        self.scaled_direct(delta)
    }

    /// J_{k,γ}(δ)/φ(δ) by the direct u-integrals (any δ).
    fn scaled_direct(&self, delta: f64) -> Result<Scaled> {
        let k = self.kernels;
        Ok(Scaled {
            count: self.s_c * self.integral(delta, Order::Zero, &k.count, 4.0)?,
            area: self.s_c.powi(2) * self.integral(delta, Order::One, &k.area, 3.0)?,
            load: self.s_c.powf(2.5) * self.integral(delta, Order::ThreeHalves, &k.load, 3.5)?,
        })
    }

    /// I(δ) = ∫ N(u; δ/√α, s_u²) 3u^p K(3u²/2) R_k((δ − a u)/s_c) du.
    fn integral(&self, delta: f64, order: Order, kernel: &Kernel, p: f64) -> Result<f64> {
        let mu = delta / self.alpha.sqrt();
        let (s_u, s_c, a) = (self.s_u, self.s_c, self.slope);
        let ln_norm = (s_u * SQRT_TAU).ln();
        let f = |u: f64| -> f64 {
            if u <= 0.0 {
                return 0.0;
            }
            let x = (u - mu) / s_u;
            let z = (delta - a * u) / s_c;
            let ln = -0.5 * x * x - ln_norm + ln_scaled_tail_moment(order, z);
            3.0 * u.powf(p) * kernel.eval(1.5 * u * u) * ln.exp()
        };
        let c = mu.max(0.0);
        let lo = (c - WIDTH * s_u).max(0.0);
        let hi = c + WIDTH * s_u + 12.0 * (2.0f64 / 3.0).sqrt();
        let q = integrate(
            "BGT u-integral",
            f,
            lo,
            hi,
            1e-300,
            self.tolerance,
            MAX_EVALS,
        )?;
        Ok(q.value)
    }

    /// ln φ(δ).
    fn ln_phi(delta: f64) -> f64 {
        -0.5 * delta * delta - SQRT_TAU.ln()
    }

    /// ln σ0(d) (finite where σ0 underflows).
    fn ln_pressure(&self, d: f64) -> Result<f64> {
        let delta = d / self.moments.rms_height();
        let load = match self.fast(delta) {
            Some(s) => s[2],
            None => {
                self.s_c.powf(2.5)
                    * self.integral(delta, Order::ThreeHalves, &self.kernels.load, 3.5)?
            }
        };
        Ok(self.load_scale().ln() + Self::ln_phi(delta) + load.ln())
    }

    /// The point at σ0 = `nominal_pressure`, Newton starting at δ = `start`.
    fn at_pressure_from(&self, nominal_pressure: f64, start: f64) -> Result<AsperityPoint> {
        check::positive("nominal_pressure", nominal_pressure)?;
        let h = self.moments.rms_height();
        let d = match self.newton(nominal_pressure, start) {
            Some(delta) => delta * h,
            None => solve_separation(&|d| self.ln_pressure(d), nominal_pressure, h, h)?,
        };
        let mut p = self.at_separation(d)?;
        p.nominal_pressure = nominal_pressure;
        Ok(p)
    }

    /// δ with σ0(δ) = `target` by Newton's method on ln σ0 with the table's
    /// derivative d ln J_{3/2}/dδ = −(3/2) J_½/J_{3/2}; `None` (use the
    /// bracketing search) when the tables are not in use or the iteration leaves them.
    fn newton(&self, target: f64, start: f64) -> Option<f64> {
        self.table()?;
        let lt = target.ln() - self.load_scale().ln();
        let mut delta = start;
        for _ in 0..NEWTON_ITERATIONS {
            let s = self.fast(delta)?;
            if !(s[2] > 0.0 && s[3] > 0.0) {
                return None;
            }
            let f = Self::ln_phi(delta) + s[2].ln() - lt;
            let slope = -1.5 * s[3] / s[2];
            let step = (-f / slope).clamp(-2.0, 2.0);
            delta += step;
            if step.abs() <= 1e-14 * (1.0 + delta.abs()) {
                return (delta >= super::summit_table::XI_MIN).then_some(delta);
            }
        }
        None
    }

    /// (2/(3π)) E* √m2 α^{3/4}.
    fn load_scale(&self) -> f64 {
        2.0 / (3.0 * std::f64::consts::PI)
            * self.e_star
            * self.moments.m2.sqrt()
            * self.alpha.powf(0.75)
    }
}

impl AsperityTheory for Bush {
    fn at_separation(&self, separation: f64) -> Result<AsperityPoint> {
        let d = check_separation(separation)?;
        let delta = d / self.moments.rms_height();
        let s = self.scaled(delta)?;
        let phi = Self::ln_phi(delta).exp();
        let m = &self.moments;
        let area = 0.5 * self.alpha.sqrt() * phi * s.area;
        Ok(AsperityPoint {
            separation: d,
            contact_fraction: area,
            nominal_pressure: self.load_scale() * phi * s.load,
            contact_number_density: Some(
                m.m4 / (2.0 * std::f64::consts::PI * m.m2) * phi * s.count,
            ),
            validity: point_validity(&self.validity, area),
        })
    }

    fn at_pressure(&self, nominal_pressure: f64) -> Result<AsperityPoint> {
        self.at_pressure_from(nominal_pressure, 0.0)
    }

    /// As [`AsperityTheory::at_pressure`], each Newton search starting from
    /// the previous point's separation.
    fn pressure_curve(&self, pressures: &[f64]) -> Result<Vec<AsperityPoint>> {
        let mut start = 0.0;
        pressures
            .iter()
            .map(|&p| {
                let point = self.at_pressure_from(p, start)?;
                start = (point.separation / self.moments.rms_height()).clamp(-8.0, 12.0);
                Ok(point)
            })
            .collect()
    }
}

//! Anisotropic spectra C(q_x, q_y): an isotropic spectrum stretched along one
//! direction, and the contact theory's G(ζ) on any 2-D spectrum.
//!
//! # Stretched spectrum
//! A surface stretched by γ along the direction at angle θ from x (the lay),
//! `h(u, v) = h_iso(u/γ, v)` with u along θ and v across it, has
//! ```text
//! C(q) = γ · C_iso(√((γ q_u)² + q_v²)),   q_u = q_x cos θ + q_y sin θ,   q_v = −q_x sin θ + q_y cos θ
//! ```
//! in Persson's normalisation (`C(q) = (2π)⁻² ∫ d²x ⟨h(x)h(0)⟩ e^{−iq·x}`):
//! the substitution `u → γu` in the Fourier integral. The heights keep their
//! variance (`∫ d²q C = ∫ d²q C_iso`); the correlation length along θ is γ
//! times the one across θ at every threshold, so γ (or 1/γ below 1) is the
//! Peklenik number. Carbone, Lorenz, Persson & Wohlers (Eur. Phys. J. E 29,
//! 275 (2009), doi:10.1140/epje/i2009-10484-8) build their anisotropic surfaces
//! the same way, by scaling one coordinate of an isotropic one; their text was
//! not readable here, so the form above is derived, not copied.
//!
//! # G(ζ) on an anisotropic spectrum
//! The elastic energy of a mode depends on |q| only, so Persson's G becomes
//! (Carbone et al. 2009)
//! ```text
//! G(ζ) = ⅛ (E*/σ0)² ∫_{|q| < ζ q_l} d²q q² C(q)
//!      = (π/4)(E*/σ0)² ∫_{q_l}^{ζ q_l} q³ C̄(q) dq,   C̄(q) = (2π)⁻¹ ∫₀^{2π} C(q, φ) dφ
//! ```
//! For an isotropic C the first line is `⅛ · 2π ∫ q³ C dq = (π/4)∫ q³ C dq`,
//! the isotropic G of Persson, Bucher & Chiaia (2002), Eq. 2. So the theory of
//! the contact area only needs the angular average C̄, and [`Stretched`]
//! implements [`Spectrum`] as that average: every area routine of
//! [`crate::theory`] runs on it unchanged. [`g_2d`] evaluates the first line
//! directly (a test of the second).
//!
//! The moments of the average follow from the isotropic ones by `p = q s(φ)`,
//! `s(φ) = √(γ² cos²φ + sin²φ)` (φ from the lay):
//! ```text
//! ∫_a^b q^k C̄(q) dq = (γ/2π) ∫₀^{2π} s(φ)^{−(k+1)} m_k^iso(a s(φ), b s(φ)) dφ
//! ```
//! (one adaptive quadrature over φ ∈ [0, π/2], times 4 by symmetry).

use std::sync::Arc;

use super::{check_range, Spectrum};
use crate::error::{check, Error, Result};
use crate::quad::{integrate, Estimate};

/// Relative tolerance of the φ quadratures (a few ulps above rounding).
const PHI_REL_TOL: f64 = 1e-14;
/// Relative tolerance of the inner (radial) integrals of [`slope_variance_2d`].
const INNER_REL_TOL: f64 = 1e-13;
/// Relative tolerance of its outer (angular) integral: the inner integrals
/// of a spectrum with edges inside the disc carry ~1e-13 of noise, which an
/// outer tolerance below it could never reach.
const OUTER_REL_TOL: f64 = 1e-11;
/// Absolute tolerance of a moment's φ quadrature, relative to an upper bound
/// of the integral: the closed-form moments of a narrow range carry rounding
/// of ~1e-12 of that bound (measured: `compare` failed at 1e-14).
const MOMENT_ABS_TOL: f64 = 1e-11;
/// Relative tolerance (of the trace) of the slope tensor's angular
/// integrals: a report's Peklenik number needs far less, and the inner
/// integrals of a band-limited stretched spectrum have kinks in φ where its
/// edges cross the cut.
const TENSOR_REL_TOL: f64 = 1e-9;
/// Evaluation budget of one φ quadrature.
const PHI_MAX_EVALS: usize = 200_000;

/// The stretch (γ or 1/γ) above which the φ quadratures split at the scales
/// of the peak of s(φ)^{−(k+1)} ([`Stretched`]'s kinks).
const STRETCH_SPLIT: f64 = 100.0;

/// A power spectrum over the plane, C(q_x, q_y) in m⁴ (Persson's normalisation,
/// `⟨h²⟩ = ∫ d²q C`), with `C(−q) = C(q)`.
pub trait Spectrum2d: Send + Sync {
    /// C(q_x, q_y), m⁴.
    fn c2(&self, qx: f64, qy: f64) -> f64;
    /// The smallest |q| with C > 0 (q_l of the magnification ζ), 1/m.
    fn q_min(&self) -> f64;
    /// The largest |q| with C > 0, 1/m.
    fn q_max(&self) -> f64;
    /// The band `[lo, hi]` of |q| with C > 0 along the direction at angle φ
    /// (radians from x); the integrals of this module split at its ends.
    fn band_at(&self, _phi: f64) -> (f64, f64) {
        (self.q_min(), self.q_max())
    }
    /// The |q| along φ at which C jumps inside or at the ends of
    /// [`Spectrum2d::band_at`] (a sum's parts' band edges); the integrals of
    /// this module split there. By default the two ends of the band.
    fn edges_at(&self, phi: f64) -> Vec<f64> {
        let (lo, hi) = self.band_at(phi);
        vec![lo, hi]
    }
}

/// An isotropic spectrum seen as a 2-D one, `C(q_x, q_y) = C(|q|)`.
pub struct Radial<'a>(pub &'a dyn Spectrum);

impl Spectrum2d for Radial<'_> {
    fn c2(&self, qx: f64, qy: f64) -> f64 {
        self.0.c(qx.hypot(qy))
    }
    fn q_min(&self) -> f64 {
        self.0.q_min()
    }
    fn q_max(&self) -> f64 {
        self.0.q_max()
    }
}

/// An isotropic spectrum stretched by `gamma` along the direction `angle`
/// (module docs). As a [`Spectrum`] it is the angular average C̄(q).
#[derive(Clone)]
pub struct Stretched {
    iso: Arc<dyn Spectrum>,
    gamma: f64,
    angle: f64,
}

impl std::fmt::Debug for Stretched {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Stretched")
            .field("gamma", &self.gamma)
            .field("angle", &self.angle)
            .finish_non_exhaustive()
    }
}

/// The stretches γ for which [`Stretched`] stays in f64, for an isotropic
/// spectrum on [q_l, q_s].
///
/// # Bound
/// γ > 1 moves the band's lower end to q_l/γ, a normal f64 while
/// γ ≤ q_l/f64::MIN_POSITIVE; its integrands s^{−(k+1)} m_k are at most the
/// isotropic moments (s ≥ 1). γ < 1 moves the upper end to q_s/γ (finite
/// while γ ≥ q_s/f64::MAX) and lets s fall to γ, so the moments' integrands
/// reach γ^{−(k+1)} m_k^iso(q_l, q_s); for the moments the crate takes (k =
/// 1, 2, 3, 5: height, energy, slope, curvature) they and their sums over
/// the quadrature stay below f64::MAX/4 while
/// γ ≥ (4 m_k^iso/f64::MAX)^{1/(k+1)}, computed in logarithms.
fn stretch_range(iso: &dyn Spectrum) -> Result<(f64, f64)> {
    let (q_l, q_s) = (iso.q_min(), iso.q_max());
    let hi = (q_l / f64::MIN_POSITIVE).min(f64::MAX);
    let mut lo = q_s / f64::MAX;
    for k in [1, 2, 3, 5] {
        let m = iso.moment(k, q_l, q_s)?.value;
        if m > 0.0 {
            let ln = (4.0f64.ln() + m.ln() - f64::MAX.ln()) / f64::from(k + 1);
            lo = lo.max(ln.exp());
        }
    }
    Ok((lo, hi))
}

impl Stretched {
    /// `iso` stretched by `gamma` along the direction at `angle` (radians,
    /// from x towards y): the lay runs along `angle` for γ > 1, across it
    /// for γ < 1; γ = 1 is `iso` itself.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `anisotropy` when γ is not finite
    /// and > 0 or outside the range where the stretched band and the moments
    /// stay in f64 (`stretch_range`), `lay_angle` when the angle is not
    /// finite;
    /// [`Error::Inconsistent`] naming `spectrum` when `iso` is itself
    /// anisotropic (the moments here assume an isotropic `iso`: stretch the
    /// parts of a sum instead).
    pub fn new(iso: Arc<dyn Spectrum>, gamma: f64, angle: f64) -> Result<Self> {
        check::positive("anisotropy", gamma)?;
        let (lo, hi) = stretch_range(iso.as_ref())?;
        if !(gamma >= lo && gamma <= hi) {
            return Err(Error::invalid(
                "anisotropy",
                gamma,
                format!(
                    "in [{}, {}] for this spectrum, so that its stretched band and the \
                     moments of its angular average stay finite, positive f64",
                    crate::error::approx(lo),
                    crate::error::approx(hi)
                ),
            ));
        }
        if !angle.is_finite() {
            return Err(Error::invalid("lay_angle", angle, "finite"));
        }
        if iso.as_2d().is_some() {
            return Err(Error::Inconsistent {
                name: "spectrum".into(),
                requirement: "an isotropic spectrum to stretch (this one is anisotropic already: stretch the parts of a sum instead)".into(),
            });
        }
        Ok(Stretched { iso, gamma, angle })
    }

    /// The stretch γ.
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// The direction of the stretch, radians from x.
    pub fn angle(&self) -> f64 {
        self.angle
    }

    /// The isotropic spectrum before stretching.
    pub fn isotropic(&self) -> &dyn Spectrum {
        self.iso.as_ref()
    }

    /// `s(φ)` at φ from the stretch direction.
    fn scale(&self, phi: f64) -> f64 {
        (self.gamma * phi.cos()).hypot(phi.sin())
    }

    /// Whether the φ quadratures of this stretch run in ψ = π/2 − φ: for
    /// γ > [`STRETCH_SPLIT`], whose peak lies near φ = π/2, where cos φ
    /// would carry an absolute rounding of ε, relative εγ (measured: the
    /// slope of γ = 1e12 was 7e-5 off). Then cos φ = sin ψ is exact to ulps.
    fn mirrored(&self) -> bool {
        self.gamma > STRETCH_SPLIT
    }

    /// s at the quadrature variable t: φ, or ψ = π/2 − φ when
    /// [`Self::mirrored`].
    fn scale_at(&self, t: f64) -> f64 {
        if self.mirrored() {
            (self.gamma * t.sin()).hypot(t.cos())
        } else {
            self.scale(t)
        }
    }

    /// The quadrature variable's split points in [0, π/2] (φ, or ψ when
    /// [`Self::mirrored`]): where `x·s` meets an end of the isotropic band,
    /// for each x in `xs` (where the integrand of a moment has a kink),
    /// sorted, with 0 and π/2 at the ends; past a stretch of
    /// [`STRETCH_SPLIT`] also the scales of the peak of s^{−(k+1)}.
    fn kinks(&self, xs: &[f64]) -> Vec<f64> {
        let g2 = self.gamma * self.gamma;
        let mirrored = self.mirrored();
        let mut phis = vec![0.0, std::f64::consts::FRAC_PI_2];
        if g2 != 1.0 {
            for &x in xs {
                for edge in [self.iso.q_min(), self.iso.q_max()] {
                    // s² = γ² cos²φ + sin²φ ⇒ cos²φ = (s² − 1)/(γ² − 1)
                    let s = edge / x;
                    let c2 = (s * s - 1.0) / (g2 - 1.0);
                    if c2 > 0.0 && c2 < 1.0 {
                        phis.push(if mirrored {
                            c2.sqrt().asin()
                        } else {
                            c2.sqrt().acos()
                        });
                    }
                }
            }
        }
        // the peak of s^{−(k+1)}: s stays near its minimum min(1, γ) only
        // within cos φ ≲ 1/γ of π/2 (γ > 1) or sin φ ≲ γ of 0 (γ < 1); past
        // a stretch of STRETCH_SPLIT the quadrature no longer finds so narrow
        // a peak in [0, π/2] (measured: the slope of γ = 1e5 came out 2e-5
        // instead of 0.0707), so its scales are split points too. Below
        // STRETCH_SPLIT no scale is a split point.
        let outer = self.gamma.max(1.0 / self.gamma);
        if outer > STRETCH_SPLIT {
            let mut m = 1.0;
            while m < outer {
                // cos φ = m/γ is ψ = asin(m/γ); sin φ = mγ is φ = asin(mγ)
                phis.push((m / outer).asin());
                m *= 4.0;
            }
        }
        phis.sort_by(f64::total_cmp);
        phis.dedup();
        phis
    }
}

impl Spectrum2d for Stretched {
    fn c2(&self, qx: f64, qy: f64) -> f64 {
        let (s, c) = self.angle.sin_cos();
        let qu = qx * c + qy * s;
        let qv = -qx * s + qy * c;
        self.gamma * self.iso.c((self.gamma * qu).hypot(qv))
    }
    fn q_min(&self) -> f64 {
        self.iso.q_min() / self.gamma.max(1.0)
    }
    fn q_max(&self) -> f64 {
        self.iso.q_max() / self.gamma.min(1.0)
    }
    fn band_at(&self, phi: f64) -> (f64, f64) {
        let s = self.scale(phi - self.angle);
        (self.iso.q_min() / s, self.iso.q_max() / s)
    }
}

impl Spectrum for Stretched {
    /// The angular average C̄(q) = (2π)⁻¹ ∫ C(q, φ) dφ (a quadrature over φ).
    fn c(&self, q: f64) -> f64 {
        if q.is_nan() || q < Spectrum2d::q_min(self) || q > Spectrum2d::q_max(self) {
            return 0.0;
        }
        let f = |t: f64| self.iso.c(q * self.scale_at(t));
        let mut sum = 0.0;
        for w in self.kinks(&[q]).windows(2) {
            match integrate(
                "angular average of the stretched spectrum",
                f,
                w[0],
                w[1],
                0.0,
                PHI_REL_TOL,
                PHI_MAX_EVALS,
            ) {
                Ok(e) => sum += e.value,
                Err(_) => return f64::NAN,
            }
        }
        self.gamma * sum / std::f64::consts::FRAC_PI_2
    }

    fn q_min(&self) -> f64 {
        Spectrum2d::q_min(self)
    }

    fn as_2d(&self) -> Option<&dyn Spectrum2d> {
        Some(self)
    }

    fn q_max(&self) -> f64 {
        Spectrum2d::q_max(self)
    }

    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        check_range(a, b)?;
        let bad = std::cell::Cell::new(None);
        let f = |t: f64| {
            let s = self.scale_at(t);
            match self.iso.moment(k, a * s, b * s) {
                Ok(m) => m.value * s.powi(-(k + 1)),
                Err(e) => {
                    bad.set(Some(e));
                    f64::NAN
                }
            }
        };
        // An absolute tolerance from an upper bound of the integral, so that a
        // moment much smaller than the isotropic one over the same stretch
        // (a narrow [a, b]) does not chase the rounding of the closed forms.
        let (lo, hi) = (self.gamma.min(1.0), self.gamma.max(1.0));
        let bound = std::f64::consts::FRAC_PI_2
            * lo.powi(-(k + 1)).max(hi.powi(-(k + 1)))
            * self.iso.moment(k, a * lo, b * hi)?.value;
        let abs_tol = MOMENT_ABS_TOL * bound;
        // Smooth between the kinks: one quadrature per piece.
        let mut r = Estimate {
            value: 0.0,
            error: 0.0,
        };
        let b_fin = if b.is_finite() { b } else { self.iso.q_max() };
        for w in self.kinks(&[a.max(f64::MIN_POSITIVE), b_fin]).windows(2) {
            if w[1] <= w[0] {
                continue;
            }
            let p = integrate(
                "moment of the stretched spectrum over the angle",
                f,
                w[0],
                w[1],
                abs_tol,
                PHI_REL_TOL,
                PHI_MAX_EVALS,
            );
            if let Some(e) = bad.take() {
                return Err(e);
            }
            let p = p?;
            r.value += p.value;
            r.error += p.error;
        }
        let scale = self.gamma / std::f64::consts::FRAC_PI_2;
        Ok(Estimate {
            value: scale * r.value,
            error: scale * r.error + 4.0 * f64::EPSILON * (scale * r.value).abs(),
        })
    }
}

/// `∫_{q_l < |q| < ζ q_l} d²q q² C(q)`, the slope variance ⟨|∇h|²⟩ of the
/// modes up to magnification ζ, by nested adaptive quadrature in polar
/// coordinates (outer φ ∈ [0, 2π], inner q ∈ [q_l, ζ q_l]).
///
/// `q_l` is [`Spectrum2d::q_min`]; the inner integrals are split at the
/// edges along each direction ([`Spectrum2d::edges_at`]).
///
/// # Errors
/// ζ < 1 or not finite; a quadrature that does not converge.
pub fn slope_variance_2d(c: &dyn Spectrum2d, zeta: f64) -> Result<Estimate> {
    check::at_least("zeta", zeta, 1.0)?;
    let q_l = c.q_min();
    let top = (zeta * q_l).min(c.q_max());
    if top <= q_l {
        return Ok(Estimate {
            value: 0.0,
            error: 0.0,
        });
    }
    let inner_err = std::cell::Cell::new(0.0f64);
    let failed = std::cell::Cell::new(None);
    let outer = |phi: f64| match radial_q3(c, phi, q_l, top) {
        Ok(e) => {
            inner_err.set(inner_err.get().max(e.error));
            e.value
        }
        Err(e) => {
            failed.set(Some(e));
            f64::NAN
        }
    };
    let r = integrate(
        "slope variance over the angle (2-D spectrum)",
        outer,
        0.0,
        std::f64::consts::TAU,
        0.0,
        OUTER_REL_TOL,
        PHI_MAX_EVALS,
    );
    if let Some(e) = failed.take() {
        return Err(e);
    }
    let r = r?;
    Ok(Estimate {
        value: r.value,
        error: r.error + std::f64::consts::TAU * inner_err.get(),
    })
}

/// `∫ q³ C(q cos φ, q sin φ) dq` over the band along φ clipped to
/// `[lo, hi]`, one adaptive quadrature between consecutive edges
/// ([`Spectrum2d::edges_at`]: C jumps at each).
fn radial_q3(c: &dyn Spectrum2d, phi: f64, lo: f64, hi: f64) -> Result<Estimate> {
    let (s, co) = phi.sin_cos();
    let g = |q: f64| q * q * q * c.c2(q * co, q * s);
    let (a, b) = c.band_at(phi);
    let (lo, hi) = (a.max(lo), b.min(hi));
    let mut r = Estimate {
        value: 0.0,
        error: 0.0,
    };
    if hi <= lo {
        return Ok(r);
    }
    let mut cuts = vec![lo, hi];
    cuts.extend(c.edges_at(phi).into_iter().filter(|&x| x > lo && x < hi));
    cuts.sort_by(f64::total_cmp);
    for w in cuts.windows(2) {
        let e = integrate(
            "slope variance over |q| (2-D spectrum)",
            g,
            w[0],
            w[1],
            0.0,
            INNER_REL_TOL,
            PHI_MAX_EVALS,
        )?;
        r.value += e.value;
        r.error += e.error;
    }
    Ok(r)
}

/// The slope tensor `⟨∇h ∇hᵀ⟩` of a surface, m⁰ (components along x and y).
///
/// # Formula
/// ```text
/// M = ∫ d²q q qᵀ C(q) = [[xx, xy], [xy, yy]],   xx + yy = ⟨|∇h|²⟩
/// eigenvalues λ₁ ≥ λ₂:  Peklenik number γ = √(λ₁/λ₂) ≥ 1
/// ```
/// The eigenvector of λ₂ is the direction of slowest variation (the lay);
/// for a [`Stretched`] spectrum `γ` and the lay are the stretch's (exactly:
/// `∫ q_u² C = ⟨|∇h_iso|²⟩/(2γ²)`, `∫ q_v² C = ⟨|∇h_iso|²⟩/2`).
/// Peklenik, Proc. Inst. Mech. Eng. 182, 108 (1967) (correlation lengths);
/// the moment form is the one of `persson::topography::anisotropy`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SlopeTensor {
    /// ⟨(∂h/∂x)²⟩.
    pub xx: f64,
    /// ⟨∂h/∂x · ∂h/∂y⟩.
    pub xy: f64,
    /// ⟨(∂h/∂y)²⟩.
    pub yy: f64,
}

impl SlopeTensor {
    /// `(γ, direction)`: the Peklenik number √(λ₁/λ₂) ≥ 1 and the direction
    /// of slowest variation, degrees in [0, 180) counterclockwise from x.
    ///
    /// # Errors
    /// [`Error::Inconsistent`] naming `peklenik_number` when λ₂ is not above
    /// rounding of λ₁ (a surface that does not vary along some direction).
    pub fn principal(&self) -> Result<(f64, f64)> {
        let (a, b, d) = (self.xx, self.xy, self.yy);
        let mean = 0.5 * (a + d);
        let r = (0.5 * (a - d)).hypot(b);
        let (l1, l2) = (mean + r, mean - r);
        if l2.is_nan() || l2 <= f64::EPSILON * l1 {
            return Err(Error::Inconsistent {
                name: "peklenik_number".into(),
                requirement: format!(
                    "a surface whose heights vary in every direction (the slope variances along the principal axes are {l1:e} and {l2:e})"
                ),
            });
        }
        // Eigenvector of λ₁ at ½ atan2(2b, a − d); the lay is perpendicular to it.
        let theta1 = 0.5 * (2.0 * b).atan2(a - d);
        let deg = (theta1 + std::f64::consts::FRAC_PI_2)
            .to_degrees()
            .rem_euclid(180.0);
        Ok(((l1 / l2).sqrt(), if deg >= 180.0 { 0.0 } else { deg }))
    }
}

/// The slope tensor `∫ d²q q qᵀ C(q)` of a 2-D spectrum over its whole band,
/// by nested adaptive quadrature in polar coordinates (as
/// [`slope_variance_2d`]); the components to ~1e-9 of the trace.
///
/// # Errors
/// A quadrature that does not converge.
pub fn slope_tensor_2d(c: &dyn Spectrum2d) -> Result<SlopeTensor> {
    let (lo, hi) = (c.q_min(), c.q_max());
    let failed = std::cell::Cell::new(None);
    let radial = |phi: f64| match radial_q3(c, phi, lo, hi) {
        Ok(e) => e.value,
        Err(e) => {
            failed.set(Some(e));
            f64::NAN
        }
    };
    let over_angle = |f: &dyn Fn(f64) -> f64, abs_tol: f64| {
        let r = integrate(
            "slope tensor over the angle (2-D spectrum)",
            f,
            0.0,
            std::f64::consts::TAU,
            abs_tol,
            TENSOR_REL_TOL,
            PHI_MAX_EVALS,
        );
        match failed.take() {
            Some(e) => Err(e),
            None => r.map(|e| e.value),
        }
    };
    let trace = over_angle(&radial, 0.0)?;
    let tol = TENSOR_REL_TOL * trace;
    let xx = over_angle(&|phi: f64| radial(phi) * phi.cos().powi(2), tol)?;
    let xy = over_angle(&|phi: f64| radial(phi) * phi.cos() * phi.sin(), tol)?;
    Ok(SlopeTensor {
        xx,
        xy,
        yy: trace - xx,
    })
}

/// G(ζ) = ⅛ (E*/σ0)² ∫_{|q| < ζ q_l} d²q q² C(q) (Carbone, Lorenz, Persson &
/// Wohlers 2009) on a 2-D spectrum, with its error.
///
/// # Errors
/// `contact_modulus` or `pressure` not finite and > 0; as [`slope_variance_2d`].
pub fn g_2d(
    c: &dyn Spectrum2d,
    zeta: f64,
    contact_modulus: f64,
    pressure: f64,
) -> Result<Estimate> {
    check::positive("contact_modulus", contact_modulus)?;
    check::positive("pressure", pressure)?;
    let s = slope_variance_2d(c, zeta)?;
    let f = (contact_modulus / pressure).powi(2) / 8.0;
    Ok(Estimate {
        value: f * s.value,
        error: f * s.error + 2.0 * f64::EPSILON * f * s.value,
    })
}

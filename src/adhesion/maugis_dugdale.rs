//! The adhesive sphere of Maugis (1992): a Dugdale cohesive zone (constant
//! attraction σ0 over gaps below h0 = Δγ/σ0) around a Hertzian contact, the
//! force–radius–approach relation between JKR (λ → ∞) and DMT (λ → 0).
//!
//! # Formula
//! Maugis's reduced variables (K = 4E*/3, a the contact radius, c the outer
//! radius of the cohesive zone, P the load, δ the approach):
//! ```text
//! Ā = a (K/(πΔγR²))^{1/3},  P̄ = P/(πΔγR),  Δ̄ = δ (K²/(π²Δγ²R))^{1/3},
//! λ = 2σ0 (R/(πΔγK²))^{1/3} = σ0 (9R/(2πΔγE*²))^{1/3},   m = c/a,  s = √(m² − 1)
//!
//! (λĀ²/2)[s + (m² − 2) atan s] + (4λ²Ā/3)[s atan s − m + 1] = 1        (Maugis Eq. 6.17)
//! P̄ = Ā³ − λĀ²[s + m² atan s]
//! Δ̄ = Ā² − (4/3) Ā λ s
//! ```
//! The first equation fixes m(Ā) (its left side grows from 0 at m = 1 to ∞);
//! then P̄ and Δ̄ follow. As λ → ∞, λs → √(3/(2Ā)) and the relations become
//! JKR's P̄ = Ā³ − √(6Ā³), Δ̄ = Ā² − (2/3)√(6Ā); as λ → 0, DMT's P̄ = Ā³ − 2,
//! Δ̄ = Ā². As Ā → 0 at fixed C̄ = mĀ (the contact has shrunk to a point, the
//! zone has not):
//! ```text
//! (πλ/4) C̄² + (4λ²/3)(π/2 − 1) C̄ = 1,     P̄₀ = −(π/2) λ C̄²
//! ```
//! **Pull-off.** The largest tension on the branch, −min P̄ over Ā ≥ 0 (the
//! minimum may sit at Ā = 0, P̄₀). Under load control the sphere jumps off
//! there. Under displacement control (the BEM's mean-gap control of a
//! periodic cell) the branch is followed past it as long as dΔ̄/dĀ > 0, which
//! holds at the force minimum (for JKR the minimum is at Ā = (3/2)^{1/3}, the
//! displacement instability at Ā = (1/6)^{1/3}); so the largest tension of a
//! displacement-controlled retraction is the same −min P̄.
//!
//! # Numerics
//! m is found by bisection in s (no cancellation near m = 1: m − 1 =
//! s²/(1 + m), and s − atan s by its series for s < ½); the minimum over Ā by
//! a scan of [0.01, 4] and a golden-section search between the neighbours of
//! the smallest sample. Tested against 40-digit values (mpmath, the same
//! equations solved independently: `tests/reference/maugis_dugdale_mpmath.py`)
//! and the JKR and DMT limits.
//!
//! # References
//! D. Maugis, J. Colloid Interface Sci. 150, 243–269 (1992),
//! doi:10.1016/0021-9797(92)90285-T.
//! K. L. Johnson & J. A. Greenwood, J. Colloid Interface Sci. 192, 326–333
//! (1997) (the adhesion map, the same variables).

use std::f64::consts::PI;

use crate::error::{check, Error, Result};

/// Maugis's sphere at one transition parameter λ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaugisDugdale {
    lambda: f64,
}

/// One point of the Maugis–Dugdale branch, in Maugis's reduced variables.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct MaugisPoint {
    /// Ā = a (K/(πΔγR²))^{1/3}.
    pub contact_radius: f64,
    /// m = c/a, the cohesive zone's outer radius over the contact radius.
    pub zone_ratio: f64,
    /// P̄ = P/(πΔγR) (negative in tension).
    pub force: f64,
    /// Δ̄ = δ (K²/(π²Δγ²R))^{1/3}.
    pub approach: f64,
}

impl MaugisDugdale {
    /// The sphere at transition parameter `lambda` (λ > 0).
    ///
    /// # Errors
    /// `lambda` not finite and > 0.
    pub fn new(lambda: f64) -> Result<Self> {
        check::positive("maugis_parameter", lambda)?;
        Ok(MaugisDugdale { lambda })
    }

    /// λ = σ0 (9R/(2πΔγE*²))^{1/3} of a sphere of radius `radius` on a
    /// half-space of contact modulus `contact_modulus`, with work of adhesion
    /// `work_of_adhesion` and Dugdale stress `cohesive_stress` (any one unit
    /// system).
    ///
    /// # Errors
    /// Any argument not finite and > 0 (named); a λ, or its intermediate
    /// 2πΔγE*² and 9R/(2πΔγE*²), outside the normal f64 range (E* = 1e300
    /// gave λ = 0, then "invalid maugis_parameter = 0"): the argument
    /// furthest from 1 in order of magnitude among those of the failing
    /// term is named.
    ///
    /// # Bound
    /// Each of d = 2πΔγE*², 9R/d and λ = σ0 (9R/d)^{1/3} lies in
    /// [f64::MIN_POSITIVE, f64::MAX], decided on their logarithms
    /// (ln d = ln 2π + ln Δγ + 2 ln E*, …), so that none is rounded to 0
    /// or ∞ as it is formed.
    pub fn parameter(
        radius: f64,
        contact_modulus: f64,
        work_of_adhesion: f64,
        cohesive_stress: f64,
    ) -> Result<f64> {
        check::positive("radius", radius)?;
        check::positive("contact_modulus", contact_modulus)?;
        check::positive("work_of_adhesion", work_of_adhesion)?;
        check::positive("cohesive_stress", cohesive_stress)?;
        let (lr, le, lg, ls) = (
            radius.ln(),
            contact_modulus.ln(),
            work_of_adhesion.ln(),
            cohesive_stress.ln(),
        );
        let ln_d = (2.0 * PI).ln() + lg + 2.0 * le;
        let ln_ratio = 9f64.ln() + lr - ln_d;
        let ln_lambda = ls + ln_ratio / 3.0;
        let range = f64::MIN_POSITIVE.ln()..=f64::MAX.ln();
        let inputs = [
            ("radius", radius, lr),
            ("contact_modulus", contact_modulus, le),
            ("work_of_adhesion", work_of_adhesion, lg),
            ("cohesive_stress", cohesive_stress, ls),
        ];
        for (term, ln, uses) in [
            ("2πΔγE*²", ln_d, [false, true, true, false]),
            ("9R/(2πΔγE*²)", ln_ratio, [true, true, true, false]),
            ("λ", ln_lambda, [true; 4]),
        ] {
            if !range.contains(&ln) {
                let (name, value, _) = inputs
                    .iter()
                    .zip(uses)
                    .filter(|(_, u)| *u)
                    .map(|(i, _)| *i)
                    .fold(("radius", radius, 0.0f64), |a, b| {
                        if b.2.abs() > a.2.abs() {
                            b
                        } else {
                            a
                        }
                    });
                return Err(Error::invalid(
                    name,
                    value,
                    format!(
                        "such that {term} of the Maugis parameter λ = σ0 (9R/(2πΔγE*²))^(1/3) \
                         is a normal f64 (here e^{}, outside [e^-708.4, e^709.8])",
                        crate::error::approx(ln)
                    ),
                ));
            }
        }
        Ok(cohesive_stress
            * (9.0 * radius / (2.0 * PI * work_of_adhesion * contact_modulus * contact_modulus))
                .cbrt())
    }

    /// λ.
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// The branch at reduced contact radius `contact_radius` (Ā > 0).
    ///
    /// # Errors
    /// `contact_radius` not finite and > 0.
    pub fn point(&self, contact_radius: f64) -> Result<MaugisPoint> {
        check::positive("contact_radius", contact_radius)?;
        Ok(self.at(contact_radius))
    }

    /// P̄₀, the force as the contact radius tends to 0 (the zone stays).
    pub fn detached_force(&self) -> f64 {
        let l = self.lambda;
        let (a, b) = (PI * l / 4.0, 4.0 * l * l / 3.0 * (PI / 2.0 - 1.0));
        // The positive root of a C̄² + b C̄ − 1 = 0, without cancellation.
        let c = 2.0 / (b + (b * b + 4.0 * a).sqrt());
        -PI / 2.0 * l * c * c
    }

    /// The reduced pull-off force −min P̄ over Ā ≥ 0 (JKR 1.5, DMT 2).
    pub fn pull_off_force(&self) -> f64 {
        self.pull_off().0
    }

    /// The pull-off force and the reduced contact radius Ā where the branch
    /// reaches it (0 when the minimum is the detached limit P̄₀).
    pub fn pull_off(&self) -> (f64, f64) {
        const SAMPLES: usize = 400;
        let a_of = |k: usize| 0.01 * (k + 1) as f64;
        let forces: Vec<f64> = (0..SAMPLES).map(|k| self.at(a_of(k)).force).collect();
        let (k, _) = forces
            .iter()
            .enumerate()
            .fold(
                (0, f64::INFINITY),
                |(kb, fb), (k, &f)| {
                    if f < fb {
                        (k, f)
                    } else {
                        (kb, fb)
                    }
                },
            );
        let detached = self.detached_force();
        if k == 0 || k + 1 == SAMPLES {
            return (
                -detached.min(forces[k]),
                if detached <= forces[k] { 0.0 } else { a_of(k) },
            );
        }
        let (a, f) = self.golden(a_of(k - 1), a_of(k + 1));
        if f < detached {
            (-f, a)
        } else {
            (-detached, 0.0)
        }
    }

    /// Golden-section minimum of P̄ on [lo, hi]: (Ā, P̄).
    fn golden(&self, mut lo: f64, mut hi: f64) -> (f64, f64) {
        let g = (5f64.sqrt() - 1.0) / 2.0;
        let force = |a: f64| self.at(a).force;
        let (mut x1, mut x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        let (mut f1, mut f2) = (force(x1), force(x2));
        while hi - lo > 1e-12 * hi {
            if f1 < f2 {
                hi = x2;
                (x2, f2) = (x1, f1);
                x1 = hi - g * (hi - lo);
                f1 = force(x1);
            } else {
                lo = x1;
                (x1, f1) = (x2, f2);
                x2 = lo + g * (hi - lo);
                f2 = force(x2);
            }
        }
        let a = 0.5 * (lo + hi);
        (a, force(a))
    }

    /// The branch at Ā > 0 (unchecked).
    fn at(&self, a: f64) -> MaugisPoint {
        let l = self.lambda;
        let s = self.zone(a);
        let m2 = 1.0 + s * s;
        let t = s.atan();
        MaugisPoint {
            contact_radius: a,
            zone_ratio: m2.sqrt(),
            force: a * a * a - l * a * a * (s + m2 * t),
            approach: a * a - 4.0 / 3.0 * a * l * s,
        }
    }

    /// s = √(m² − 1) solving Maugis's Eq. 6.17 at Ā = `a`, by bisection.
    fn zone(&self, a: f64) -> f64 {
        let l = self.lambda;
        let residual = |s: f64| {
            let t = s.atan();
            let m = (1.0 + s * s).sqrt();
            // s + (m² − 2) atan s = s² atan s + (s − atan s)
            let first = s * s * t + s_minus_atan(s);
            // s atan s − (m − 1), m − 1 = s²/(1 + m)
            let second = s * t - s * s / (1.0 + m);
            l * a * a / 2.0 * first + 4.0 * l * l * a / 3.0 * second - 1.0
        };
        let mut hi = 1.0;
        while residual(hi) < 0.0 && hi < 1e300 {
            hi *= 2.0;
        }
        let mut lo = 0.0;
        for _ in 0..1100 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if residual(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }
}

/// s − atan s without cancellation: its series below ½.
fn s_minus_atan(s: f64) -> f64 {
    if s.abs() >= 0.5 {
        return s - s.atan();
    }
    let s2 = s * s;
    let mut term = s * s2; // s^{2k+1}, k = 1
    let mut sum = 0.0;
    for k in 1..40 {
        let c = term / (2 * k + 1) as f64;
        sum += if k % 2 == 1 { c } else { -c };
        if c.abs() < 1e-18 * sum.abs() {
            break;
        }
        term *= s2;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pull-off forces of `tests/reference/maugis_dugdale_mpmath.py` (40 digits,
    /// rounded to 16).
    const REFERENCE: [(f64, f64, f64); 4] = [
        (0.1, 1.950_594_892_123_429, 0.199_192_587_603),
        (0.3, 1.815_555_827_044_852, 0.496_628_733_995),
        (1.0, 1.600_734_911_254_091, 0.903_768_642_819),
        (3.0, 1.516_763_900_036_928, 1.097_405_299),
    ];

    #[test]
    fn pull_off_matches_the_high_precision_reference() {
        for (lambda, force, radius) in REFERENCE {
            let (f, a) = MaugisDugdale::new(lambda).unwrap().pull_off();
            assert!(
                (f - force).abs() < 1e-12 * force,
                "λ = {lambda}: {f} against {force}"
            );
            assert!(
                (a - radius).abs() < 1e-5,
                "λ = {lambda}: Ā = {a} against {radius}"
            );
        }
    }

    #[test]
    fn large_lambda_is_jkr() {
        let md = MaugisDugdale::new(1e6).unwrap();
        for a in [0.3, 1.0, 2.0] {
            let p = md.point(a).unwrap();
            let jkr = a.powi(3) - (6.0 * a.powi(3)).sqrt();
            let delta = a * a - 2.0 / 3.0 * (6.0 * a).sqrt();
            assert!(
                (p.force - jkr).abs() < 1e-5,
                "Ā = {a}: {} against {jkr}",
                p.force
            );
            assert!(
                (p.approach - delta).abs() < 1e-5,
                "Ā = {a}: {} against {delta}",
                p.approach
            );
        }
        assert!((md.pull_off_force() - 1.5).abs() < 1e-5);
    }

    #[test]
    fn small_lambda_is_dmt() {
        let md = MaugisDugdale::new(1e-8).unwrap();
        for a in [0.3, 1.0, 2.0] {
            let p = md.point(a).unwrap();
            assert!(
                (p.force - (a.powi(3) - 2.0)).abs() < 1e-3,
                "Ā = {a}: {}",
                p.force
            );
            assert!((p.approach - a * a).abs() < 1e-3);
        }
        assert!((md.pull_off_force() - 2.0).abs() < 1e-3);
        assert!((md.detached_force() + 2.0).abs() < 1e-3);
    }

    #[test]
    fn the_branch_tends_to_the_detached_limit() {
        for lambda in [0.1, 1.0, 3.0] {
            let md = MaugisDugdale::new(lambda).unwrap();
            let p = md.point(1e-7).unwrap();
            assert!(
                (p.force - md.detached_force()).abs() < 1e-5,
                "λ = {lambda}: {} against {}",
                p.force,
                md.detached_force()
            );
        }
    }

    #[test]
    fn parameter_is_maugis_lambda() {
        // λ = 2σ0 (R/(πΔγK²))^{1/3}, K = 4E*/3.
        let (r, e, dg, s0) = (2.0, 3.0, 0.1, 0.7);
        let k = 4.0 * e / 3.0;
        let maugis = 2.0 * s0 * (r / (PI * dg * k * k)).cbrt();
        let l = MaugisDugdale::parameter(r, e, dg, s0).unwrap();
        assert!((l - maugis).abs() < 1e-15 * maugis);
        assert!(MaugisDugdale::new(0.0).is_err());
        assert!(MaugisDugdale::parameter(-1.0, e, dg, s0).is_err());
    }
}

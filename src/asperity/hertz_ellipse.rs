//! Hertz contact of an elliptic paraboloid with a flat: contact area and load
//! relative to the sphere of the geometric-mean curvature.
//!
//! # Formula
//! Gap (κ1 x² + κ2 y²)/2 with κ1 ≥ κ2 > 0, ρ = κ2/κ1, interference w. The
//! contact ellipse has semi-axes a ≥ b, k' = b/a, m = 1 − k'² (Johnson 1985,
//! §4.2 (equation numbers not checked here) with K(m), E(m) the complete
//! elliptic integrals; every factor verified below against mpmath and in the
//! sphere limit F_A = F_P = 1):
//! ```text
//! κ1/κ2 = [E − k'²K] / [k'² (K − E)] = R_D(0, 1, k'²) / R_D(0, k'², 1)          (fixes k')
//! area  = π w / √(κ1κ2) · F_A,   F_A = 2k' R_D(0, k'², 1) √(κ1/κ2) / (3K)
//! load  = (4/3) E* w^{3/2} (κ1κ2)^{−1/4} · F_P,   F_P = (π/(2K)) √(2 R_D(0, k'², 1) √(κ1/κ2) / (3K))
//! ```
//! using K − E = (m/3) R_D(0, k'², 1) and E − k'²K = (m k'²/3) R_D(0, 1, k'²)
//! (Carlson's symmetric integrals, DLMF 19.25.1), which removes the
//! cancellation of K − E near the sphere. F_A = F_P = 1 for ρ = 1; F_A
//! falls to 0.94 and F_P rises to 1.11 at ρ = 0.1.
//!
//! The factors are functions of v = c², c = (1 − ρ)/(1 + ρ) = (κ1 − κ2)/(κ1 + κ2),
//! the variable of the curvature kernel in [`super::kernel`].
//!
//! # References
//! - K. L. Johnson, *Contact Mechanics* (CUP 1985), §4.2 (elliptical Hertz contact).
//! - B. C. Carlson, Numer. Algorithms 10, 13 (1995), doi:10.1007/BF02198293:
//!   R_F and R_D by duplication; DLMF §19.16, §19.25.

use crate::error::{Error, Result};

/// Carlson's R_F(x, y, z) by duplication (Carlson 1995, Algorithm 1):
/// relative error below 1e-15 (at most one argument may be 0).
pub(crate) fn carlson_rf(x0: f64, y0: f64, z0: f64) -> f64 {
    let (mut x, mut y, mut z) = (x0, y0, z0);
    let a0 = (x0 + y0 + z0) / 3.0;
    let q = (3.0 * f64::EPSILON).powf(-1.0 / 6.0)
        * (a0 - x0).abs().max((a0 - y0).abs()).max((a0 - z0).abs());
    let mut a = a0;
    let mut scale = 1.0;
    while scale * q >= a.abs() {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let l = sx * sy + sy * sz + sz * sx;
        x = 0.25 * (x + l);
        y = 0.25 * (y + l);
        z = 0.25 * (z + l);
        a = 0.25 * (a + l);
        scale *= 0.25;
    }
    // X = (A0 − x0)/(4ⁿ Aₙ), Y likewise, Z = −(X + Y).
    let (dx, dy) = ((a0 - x0) * scale / a, (a0 - y0) * scale / a);
    let dz = -(dx + dy);
    let e2 = dx * dy - dz * dz;
    let e3 = dx * dy * dz;
    (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / a.sqrt()
}

/// Carlson's R_D(x, y, z) by duplication (Carlson 1995, Algorithm 4).
pub(crate) fn carlson_rd(x0: f64, y0: f64, z0: f64) -> f64 {
    let (mut x, mut y, mut z) = (x0, y0, z0);
    let a0 = (x0 + y0 + 3.0 * z0) / 5.0;
    let q = (0.25 * f64::EPSILON).powf(-1.0 / 6.0)
        * (a0 - x0).abs().max((a0 - y0).abs()).max((a0 - z0).abs());
    let mut a = a0;
    let mut scale = 1.0;
    let mut sum = 0.0;
    while scale * q >= a.abs() {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let l = sx * sy + sy * sz + sz * sx;
        sum += scale / (sz * (z + l));
        x = 0.25 * (x + l);
        y = 0.25 * (y + l);
        z = 0.25 * (z + l);
        a = 0.25 * (a + l);
        scale *= 0.25;
    }
    let (dx, dy) = ((a0 - x0) * scale / a, (a0 - y0) * scale / a);
    let dz = -(dx + dy) / 3.0;
    let e2 = dx * dy - 6.0 * dz * dz;
    let e3 = (3.0 * dx * dy - 8.0 * dz * dz) * dz;
    let e4 = 3.0 * (dx * dy - dz * dz) * dz * dz;
    let e5 = dx * dy * dz * dz * dz;
    let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0;
    scale * a.powf(-1.5) * series + 3.0 * sum
}

/// The area and load factors (F_A, F_P) of the module docs at v = c².
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Factors {
    pub area: f64,
    pub load: f64,
}

/// Iteration cap of the k' search (bracketing and Illinois in ln k').
const MAX_ITERATIONS: usize = 200;

/// (F_A, F_P) at v ∈ [0, 1); `one_minus_v` = 1 − v given separately for accuracy near 1.
///
/// # Errors
/// [`Error::NotConverged`] if the search for k' fails (not expected).
pub(crate) fn factors(v: f64, one_minus_v: f64) -> Result<Factors> {
    if v <= 0.0 {
        return Ok(Factors {
            area: 1.0,
            load: 1.0,
        });
    }
    let c = v.sqrt();
    // 1/ρ = κ1/κ2 = (1 + c)/(1 − c), 1 − c = (1 − v)/(1 + c).
    let target = ((1.0 + c) * (1.0 + c) / one_minus_v).ln();
    let g = |x: f64| -> f64 {
        let k2 = (2.0 * x).exp();
        (carlson_rd(0.0, 1.0, k2) / carlson_rd(0.0, k2, 1.0)).ln() - target
    };
    // g(0) = −target < 0; g grows as x = ln k' decreases.
    let (mut lo, mut hi) = (-1.0f64, 0.0f64);
    let (mut glo, mut ghi) = (g(lo), -target);
    while glo < 0.0 {
        hi = lo;
        ghi = glo;
        lo *= 2.0;
        if lo < -700.0 {
            return Err(not_converged(v));
        }
        glo = g(lo);
    }
    let mut side = 0i8;
    let mut x = 0.5 * (lo + hi);
    for _ in 0..MAX_ITERATIONS {
        x = hi - ghi * (hi - lo) / (ghi - glo);
        if !(x > lo && x < hi) {
            x = 0.5 * (lo + hi);
        }
        let gx = g(x);
        if gx == 0.0 || (hi - lo).abs() <= 4.0 * f64::EPSILON * x.abs().max(1e-300) {
            break;
        }
        if gx > 0.0 {
            lo = x;
            glo = gx;
            if side == 1 {
                ghi *= 0.5;
            }
            side = 1;
        } else {
            hi = x;
            ghi = gx;
            if side == -1 {
                glo *= 0.5;
            }
            side = -1;
        }
        if (hi - lo).abs() <= 2.0 * f64::EPSILON * lo.abs().max(hi.abs()) {
            x = 0.5 * (lo + hi);
            break;
        }
    }
    let kp = x.exp();
    let k2 = kp * kp;
    let big_k = carlson_rf(0.0, k2, 1.0);
    let rd = carlson_rd(0.0, k2, 1.0);
    let sqrt_ratio = (carlson_rd(0.0, 1.0, k2) / rd).sqrt();
    let area = 2.0 * kp * rd * sqrt_ratio / (3.0 * big_k);
    let load =
        std::f64::consts::PI / (2.0 * big_k) * (2.0 * rd * sqrt_ratio / (3.0 * big_k)).sqrt();
    if !(area.is_finite() && load.is_finite()) {
        return Err(not_converged(v));
    }
    Ok(Factors { area, load })
}

fn not_converged(v: f64) -> Error {
    Error::NotConverged {
        what: format!("elliptic Hertz contact at c² = {v}"),
        iterations: MAX_ITERATIONS,
        residual: f64::NAN,
        tolerance: f64::EPSILON,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Carlson's duplication to its stopping rule: a few ulps.
    const CARLSON_TOL: f64 = 4e-16;

    #[test]
    fn complete_integrals_at_m_one_half() {
        // K(1/2), E(1/2) (DLMF 19.20; mpmath ellipk(0.5), ellipe(0.5)).
        let k = carlson_rf(0.0, 0.5, 1.0);
        let e = k - 0.5 / 3.0 * carlson_rd(0.0, 0.5, 1.0);
        assert!((k / 1.854_074_677_301_371_9 - 1.0).abs() < CARLSON_TOL);
        assert!((e / 1.350_643_881_047_675_5 - 1.0).abs() < CARLSON_TOL);
    }

    /// The factors at ρ = 0.1 and 0.5 against mpmath (tests/reference/asperity_reference.py,
    /// `hertz_factors`): a root search to a few ulps in ln k'.
    const FACTOR_TOL: f64 = 1e-13;

    #[test]
    fn factors_against_mpmath() {
        for (rho, fa, fp) in [
            (0.1, 0.940_882_092_410_051, 1.109_040_251_656_14),
            (0.5, 0.993_478_594_993_122, 1.009_993_295_678_46),
        ] {
            let c: f64 = (1.0 - rho) / (1.0 + rho);
            let v = c * c;
            let f = factors(v, 1.0 - v).unwrap();
            assert!((f.area - fa).abs() < FACTOR_TOL, "{rho}: {}", f.area);
            assert!((f.load - fp).abs() < FACTOR_TOL, "{rho}: {}", f.load);
        }
    }
}

//! Closed-form Hertz contacts: a ball or a cylinder pressed on a nominally
//! flat elastic half-space.
//!
//! These are the crate's smooth-contact references: the smooth starts of
//! the stress distributions ([`crate::stress::HertzContact`]) and the BEM
//! validation (`bem::hertz`, feature `bem`) are built on them, and the tests
//! check the BEM and the theory against them.
//!
//! Both bodies are elastic, or one is rigid: only the contact modulus
//! E* (1/E* = Σ (1 − ν²)/E) enters. The ball (or cylinder) is Hertz's
//! paraboloid h(r) = −r²/(2R), good while a ≪ R.
//!
//! # Units
//! Any consistent set; in SI: radii, contact radius and displacements in m,
//! the ball's load in N, the cylinder's load per length in N/m, E* and every
//! pressure in Pa.
//!
//! # References
//! - H. Hertz, J. reine angew. Math. 92, 156 (1882).
//! - K. L. Johnson, *Contact Mechanics* (Cambridge University Press, 1985):
//!   §3.9, eqs. 3.41a and 3.42a (displacement of the Hertz pressure);
//!   §4.2, eqs. 4.22–4.24 (ball); §4.3, eqs. 4.43–4.45 (cylinder).

use std::f64::consts::PI;

use crate::error::{check, Result};

/// A ball of radius R pressed with load F on a half-space of contact
/// modulus E*: its contact radius a and peak pressure p₀.
///
/// # Formula
/// ```text
/// a = (3 F R / (4 E*))^{1/3}                 contact radius     (Johnson 4.22)
/// δ = a²/R                                   penetration        (Johnson 4.23)
/// p₀ = 3F/(2π a²) = 2E* a/(π R)              peak pressure      (Johnson 4.24)
/// p(r) = p₀ √(1 − r²/a²),  r < a;  0 beyond
/// σ0 = F/(π a²) = 2p₀/3                      mean pressure over the contact
/// ```
///
/// # Examples
/// ```
/// use persson::reference::Ball;
/// // R = 10 mm, F = 10 N, E* = 1 GPa
/// let b = Ball::from_load(0.01, 10.0, 1e9).unwrap();
/// assert!((b.contact_radius / 4.217163326508746e-4 - 1.0).abs() < 1e-14);
/// assert!((b.peak_pressure / 2.6847295569589101e7 - 1.0).abs() < 1e-14);
/// assert!((b.penetration() / 1.7784466522450314e-5 - 1.0).abs() < 1e-14);
/// assert_eq!(b.pressure(b.contact_radius), 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Ball {
    /// R, radius of the ball (m).
    pub radius: f64,
    /// E*, contact modulus (Pa).
    pub contact_modulus: f64,
    /// F, load (N).
    pub load: f64,
    /// a, contact radius (m).
    pub contact_radius: f64,
    /// p₀ = σH, peak pressure (Pa).
    pub peak_pressure: f64,
}

impl Ball {
    /// The contact of a ball of radius `radius` pressed with `load` on
    /// `contact_modulus`; p₀ = 3F/(2π a²).
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] if an argument is not finite and positive.
    pub fn from_load(radius: f64, load: f64, contact_modulus: f64) -> Result<Self> {
        let r = check::positive("radius", radius)?;
        let f = check::positive("load", load)?;
        let e = check::positive("contact_modulus", contact_modulus)?;
        let a = ball_contact_radius(f, r, e);
        Ok(Ball {
            radius: r,
            contact_modulus: e,
            load: f,
            contact_radius: a,
            peak_pressure: 1.5 * f / contact_area(a),
        })
    }

    /// The contact of radius `contact_radius` of a ball of radius `radius` on
    /// `contact_modulus`: F = 4E* a³/(3R), p₀ = 2E* a/(π R).
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] if an argument is not finite and positive.
    ///
    /// # Examples
    /// ```
    /// use persson::reference::Ball;
    /// // a = 0.1 R, E* = 1: F = 4e-3/3, p₀ = 0.2/π
    /// let b = Ball::from_contact_radius(1.0, 0.1, 1.0).unwrap();
    /// assert!((b.load - 4e-3 / 3.0).abs() < 1e-18);
    /// assert!((b.peak_pressure - 0.2 / std::f64::consts::PI).abs() < 1e-17);
    /// ```
    pub fn from_contact_radius(
        radius: f64,
        contact_radius: f64,
        contact_modulus: f64,
    ) -> Result<Self> {
        let r = check::positive("radius", radius)?;
        let a = check::positive("contact_radius", contact_radius)?;
        let e = check::positive("contact_modulus", contact_modulus)?;
        Ok(Ball {
            radius: r,
            contact_modulus: e,
            load: ball_load(a, r, e),
            contact_radius: a,
            peak_pressure: ball_peak_pressure(a, r, e),
        })
    }

    /// σ0 = F/(π a²) = 2p₀/3, the mean pressure over the contact (Pa).
    pub fn nominal_pressure(&self) -> f64 {
        self.load / contact_area(self.contact_radius)
    }

    /// δ = a²/R, the penetration (rigid-body approach) of the ball (m).
    pub fn penetration(&self) -> f64 {
        self.contact_radius * self.contact_radius / self.radius
    }

    /// p(r) = p₀ √(1 − r²/a²) at distance `r` (m) from the centre, 0 for r ≥ a (Pa).
    pub fn pressure(&self, r: f64) -> f64 {
        pressure_profile(r, self.contact_radius, self.peak_pressure)
    }

    /// u(r), the normal surface displacement at distance `r` (m) from the
    /// centre, zero at infinity (m); see [`ball_displacement`].
    pub fn displacement(&self, r: f64) -> f64 {
        ball_displacement(
            r,
            self.contact_radius,
            self.peak_pressure,
            self.contact_modulus,
        )
    }
}

/// A cylinder of radius R pressed with load F' per unit length on a
/// half-space of contact modulus E* (plane strain): its half-width a and
/// peak pressure p₀.
///
/// # Formula
/// ```text
/// a = (4 F' R / (π E*))^{1/2}         half-width        (Johnson 4.43)
/// p₀ = 2F'/(π a) = (F' E*/(π R))^{1/2} peak pressure     (Johnson 4.44)
/// p(x) = p₀ √(1 − x²/a²),  |x| < a;  0 beyond            (Johnson 4.45)
/// σ0 = F'/(2a) = π p₀/4                mean pressure over the contact
/// ```
/// The penetration of a cylinder into a half-space has no closed form: in
/// plane strain it depends on where the displacement is measured from
/// (it grows as ln of that distance), so none is given.
///
/// # Examples
/// ```
/// use persson::reference::Cylinder;
/// // R = 10 mm, F' = 1 kN/m, E* = 1 GPa
/// let c = Cylinder::from_load_per_length(0.01, 1e3, 1e9).unwrap();
/// assert!((c.half_width / 1.1283791670955126e-4 - 1.0).abs() < 1e-14);
/// assert!((c.peak_pressure / 5.641895835477563e6 - 1.0).abs() < 1e-14);
/// assert!((c.nominal_pressure() / 4.431134627263790e6 - 1.0).abs() < 1e-14);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Cylinder {
    /// R, radius of the cylinder (m).
    pub radius: f64,
    /// E*, contact modulus (Pa).
    pub contact_modulus: f64,
    /// F', load per unit length (N/m).
    pub load_per_length: f64,
    /// a, half-width of the contact strip (m).
    pub half_width: f64,
    /// p₀ = σH, peak pressure (Pa).
    pub peak_pressure: f64,
}

impl Cylinder {
    /// The contact of a cylinder of radius `radius` pressed with
    /// `load_per_length` on `contact_modulus`.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] if an argument is not finite and positive.
    pub fn from_load_per_length(
        radius: f64,
        load_per_length: f64,
        contact_modulus: f64,
    ) -> Result<Self> {
        let r = check::positive("radius", radius)?;
        let f = check::positive("load_per_length", load_per_length)?;
        let e = check::positive("contact_modulus", contact_modulus)?;
        let a = (4.0 * f * r / (PI * e)).sqrt();
        Ok(Cylinder {
            radius: r,
            contact_modulus: e,
            load_per_length: f,
            half_width: a,
            peak_pressure: 2.0 * f / (PI * a),
        })
    }

    /// σ0 = F'/(2a) = π p₀/4, the mean pressure over the strip (Pa).
    pub fn nominal_pressure(&self) -> f64 {
        self.load_per_length / (2.0 * self.half_width)
    }

    /// p(x) = p₀ √(1 − x²/a²) at distance `x` (m) from the centre line, 0
    /// for |x| ≥ a (Pa).
    pub fn pressure(&self, x: f64) -> f64 {
        pressure_profile(x.abs(), self.half_width, self.peak_pressure)
    }
}

/// π a², the area of a circular contact of radius `a`.
fn contact_area(a: f64) -> f64 {
    PI * a * a
}

/// The load that gives a ball of radius `radius` the contact radius `a`
/// (unit of `contact_modulus` times the square of the unit of `a`; N for SI).
///
/// # Formula
/// ```text
/// F = 4E* a³/(3R)        (Johnson 4.22 solved for F)
/// ```
///
/// # References
/// K. L. Johnson, *Contact Mechanics* (CUP 1985), Eq. 4.22.
///
/// # Examples
/// ```
/// // a = 0.1 R, E* = 1: F = 4e-3/3
/// assert!((persson::reference::ball_load(0.1, 1.0, 1.0) - 4e-3 / 3.0).abs() < 1e-18);
/// ```
pub fn ball_load(a: f64, radius: f64, contact_modulus: f64) -> f64 {
    4.0 * contact_modulus * a.powi(3) / (3.0 * radius)
}

/// The peak pressure of a ball of radius `radius` with contact radius `a`
/// (unit of `contact_modulus`).
///
/// # Formula
/// ```text
/// p₀ = 2E* a/(π R) = 3F/(2π a²)     (Johnson 4.24 with 4.22)
/// ```
///
/// # References
/// K. L. Johnson, *Contact Mechanics* (CUP 1985), Eqs. 4.22, 4.24.
///
/// # Examples
/// ```
/// use std::f64::consts::PI;
/// let p0 = persson::reference::ball_peak_pressure(0.1, 1.0, 1.0);
/// assert!((p0 - 0.2 / PI).abs() < 1e-17);
/// ```
pub fn ball_peak_pressure(a: f64, radius: f64, contact_modulus: f64) -> f64 {
    2.0 * contact_modulus * a / (PI * radius)
}

/// The contact radius of a ball of radius `radius` pressed with `load`
/// (unit of `radius`).
///
/// # Formula
/// ```text
/// a = (3 F R/(4E*))^{1/3}      (Johnson 4.22)
/// ```
///
/// # References
/// K. L. Johnson, *Contact Mechanics* (CUP 1985), Eq. 4.22.
///
/// # Examples
/// ```
/// use persson::reference::{ball_contact_radius, ball_load};
/// let f = ball_load(0.1, 1.0, 1.0);
/// assert!((ball_contact_radius(f, 1.0, 1.0) - 0.1).abs() < 1e-16);
/// ```
pub fn ball_contact_radius(load: f64, radius: f64, contact_modulus: f64) -> f64 {
    (3.0 * load * radius / (4.0 * contact_modulus)).cbrt()
}

/// The Hertz pressure profile p₀ √(1 − r²/a²) for r < a, 0 beyond (unit of
/// `peak_pressure`); `r` and `a` in one length unit. The same semi-ellipse
/// for the ball (r radial) and the cylinder (r = |x|).
///
/// # Formula
/// ```text
/// p(r) = p₀ √(1 − (r/a)²),  r < a;   p(r) = 0,  r ≥ a
/// ```
///
/// # Examples
/// ```
/// // at r = a/2: p₀ √(3/4)
/// let p = persson::reference::pressure_profile(0.5, 1.0, 2.0);
/// assert!((p - 3f64.sqrt()).abs() < 1e-15);
/// ```
pub fn pressure_profile(r: f64, a: f64, peak_pressure: f64) -> f64 {
    if r < a {
        peak_pressure * (1.0 - (r / a).powi(2)).sqrt()
    } else {
        0.0
    }
}

/// Normal surface displacement of the Hertz pressure of a ball at distance
/// `r` from the centre (unit of `a`), zero at infinity: `a` the contact
/// radius, `peak_pressure` p₀ and `contact_modulus` E* in one unit.
///
/// # Formula
/// ```text
/// u(r) = π p₀ (2a² − r²) / (4aE*)                          r ≤ a   (Johnson 3.41a)
/// u(r) = p₀/(2aE*) [(2a² − r²) asin(a/r) + a √(r² − a²)]   r > a   (Johnson 3.42a)
///      = p₀ r²/(4aE*) (sin x − x cos x),   x = 2 asin(a/r)
/// sin x − x cos x = Σ_{k≥1} (−1)^{k+1} 2k x^{2k+1}/(2k+1)!   (used for x < 1)
/// ```
/// The second form of the outer branch avoids the cancellation of the first
/// (both terms ~ a r while their sum ~ a³/r); far away u → F/(π E* r).
/// Inside the contact u = δ − r²/(2R) with δ = a²/R when p₀ = 2E*a/(πR).
///
/// # References
/// K. L. Johnson, *Contact Mechanics* (CUP 1985), eqs. 3.41a and 3.42a.
///
/// # Examples
/// ```
/// use persson::reference::ball_displacement;
/// // a = 0.1, p₀ = 0.2/π, E* = 1 (R = 1): δ = a²/R at the centre, δ/2 at the edge
/// let p0 = 0.2 / std::f64::consts::PI;
/// assert!((ball_displacement(0.0, 0.1, p0, 1.0) - 0.01).abs() < 1e-17);
/// assert!((ball_displacement(0.1, 0.1, p0, 1.0) - 0.005).abs() < 1e-17);
/// // far away: F/(π E* r) with F = 4a³/3, to (a/r)² relative
/// let u = ball_displacement(1000.0, 0.1, p0, 1.0);
/// assert!((u / 4.244131820028007e-7 - 1.0).abs() < 1e-14);
/// ```
pub fn ball_displacement(r: f64, a: f64, peak_pressure: f64, contact_modulus: f64) -> f64 {
    let (p0, e) = (peak_pressure, contact_modulus);
    let r = r.abs();
    if r <= a {
        return PI * p0 * (2.0 * a * a - r * r) / (4.0 * a * e);
    }
    let x = 2.0 * (a / r).asin();
    p0 * r * r / (4.0 * a * e) * sin_minus_x_cos(x)
}

/// `sin x − x cos x` for `x ∈ [0, π]`, by its series below 1 (no cancellation).
fn sin_minus_x_cos(x: f64) -> f64 {
    if x >= 1.0 {
        return x.sin() - x * x.cos();
    }
    // Term k: (−1)^{k+1} 2k x^{2k+1}/(2k+1)!; ratio of successive powers
    // x²/((2k+2)(2k+3)) ≤ 1/20: 14 terms reach 1e-17 relative.
    let x2 = x * x;
    let mut power = x * x2 / 6.0; // x^{2k+1}/(2k+1)! at k = 1
    let mut sum = 0.0;
    for k in 1..=14 {
        let kf = k as f64;
        let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
        sum += sign * 2.0 * kf * power;
        power *= x2 / ((2.0 * kf + 2.0) * (2.0 * kf + 3.0));
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series branch and the closed form agree at the switch x = 1 to
    /// rounding (the closed form loses no digits there).
    const SWITCH_REL_TOL: f64 = 1e-14;

    #[test]
    fn series_meets_the_closed_form_at_the_switch() {
        let x: f64 = 1.0 - 1e-9;
        let closed = x.sin() - x * x.cos();
        assert!((sin_minus_x_cos(x) / closed - 1.0).abs() < SWITCH_REL_TOL);
    }
}

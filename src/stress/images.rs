//! Finite yield stress by the method of images for two absorbing walls
//! (s = 0 and s = y): fast exactly where the sine series is slow (τ ≪ y²).
//!
//! ```text
//! P(s)  = Σₖ Q(s − 2ky)                                 0 < s < y
//! A_el  = A∞ − F(y) + F(2y) − F(3y) + …                (alternating, |terms| decreasing)
//! A_pl  = Σ_{j≥0} F((2j+1) y)                           (all terms ≥ 0)
//! F(x)  = ∫₀¹ P0(u) [erfc((x−u)/w) − erfc((x+u)/w)] du   (= 2 ∫ₓ^∞ Q)
//! ```
//! Q is the one-wall (elastic) image integral of [`super::elastic`]. A_el
//! integrates P over [0, y]; A_pl integrates the flux −∂ₛP(y, t) over time,
//! using ∫₀^τ (z/2t) φₜ(z) dt = erfc(z/(2√τ))/2.

use super::elastic::{beyond, contact_fraction, Images};
use super::start::Start;
use crate::error::Result;
use crate::quad::Estimate;
use crate::special::erfc;

/// P(s) = Σₖ Q(s − 2ky) over the images within reach, 0 < s < y
/// (y = ∞: the elastic solution Q(s)). Returns the estimate and the number
/// of images used.
pub(crate) fn density(img: &Images, y: f64, s: f64) -> Result<(Estimate, usize)> {
    if !y.is_finite() {
        return Ok((img.q(s)?, 1));
    }
    let reach = 1.0 + img.reach();
    let two_y = 2.0 * y;
    let k_lo = ((s - reach) / two_y).ceil() as i64;
    let k_hi = ((s + reach) / two_y).floor() as i64;
    let mut out = Estimate {
        value: 0.0,
        error: 2.0 * img.trunc,
    };
    let mut used = 0;
    for k in k_lo..=k_hi {
        let e = img.q(s - two_y * k as f64)?;
        out.value += e.value;
        out.error += e.error;
        used += 1;
    }
    Ok((out, used))
}

/// A_el and A_pl by images, each with an error bound.
///
/// # Errors
/// Quadrature failure in F.
pub(crate) fn fractions(start: &Start, w: f64, y: f64) -> Result<(Estimate, Estimate, usize)> {
    let a_inf = contact_fraction(start, w)?;
    if !y.is_finite() {
        return Ok((
            a_inf,
            Estimate {
                value: 0.0,
                error: 0.0,
            },
            0,
        ));
    }
    // F(x) ≤ erfc((x − 1)/w): stop when the next bound is negligible.
    let bound = |x: f64| erfc((x - 1.0) / w);
    let mut el = a_inf;
    let mut pl = Estimate {
        value: 0.0,
        error: 0.0,
    };
    let mut m = 1usize;
    loop {
        let x = m as f64 * y;
        let f = beyond(start, w, x)?;
        if m % 2 == 1 {
            el.value -= f.value;
            pl.value += f.value;
            pl.error += f.error;
        } else {
            el.value += f.value;
        }
        el.error += f.error;
        let next = bound((m + 1) as f64 * y);
        // terms decrease faster than geometrically: the first omitted term bounds the rest
        if next <= 1e-20 * el.value.abs().max(1e-280) && next <= 1e-20 * pl.value.max(1e-280)
            || next == 0.0
            || m > 10_000
        {
            el.error += next;
            pl.error += 2.0 * next;
            break;
        }
        m += 1;
    }
    el.error += 4.0 * f64::EPSILON * (a_inf.value + el.value.abs());
    pl.error += 4.0 * f64::EPSILON * pl.value;
    Ok((el, pl, m))
}

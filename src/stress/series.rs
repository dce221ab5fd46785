//! Finite yield stress: the Fourier sine series (Persson, Bucher & Chiaia (2002), Eqs. 7 and 10).
//!
//! ```text
//! P(s) = (2/y) Σₙ Bₙ Eₙ sin(kₙ s),   kₙ = nπ/y,   Eₙ = e^{−kₙ² τ},   y = σY/σH
//! Bₙ = ∫₀^y P0(u) sin(kₙ u) du:
//!   flat      sin(nπ/y)
//!   Hertz     2 j₁(γ) = 2(sin γ/γ² − cos γ/γ),  γ = nπ/y  (power series for γ < 2)
//!   cylinder  (π/2) J₁(γ)
//! A_el = Σ_{n odd} (4/(nπ)) Bₙ Eₙ
//! A_pl = ⟨u⟩/y − Σₙ (−1)ⁿ⁺¹ (2/(nπ)) Bₙ Eₙ      (absolutely convergent; ⟨u⟩ = σ0/σH)
//! ```
//! A_pl follows from the flux at y, ∫₀^τ −∂ₛP(y) dt, with the τ → ∞ limit
//! Σ (−1)ⁿ⁺¹ (2/(nπ)) Bₙ = ∫ P0(u) u/y du = σ0/σY subtracted analytically.
//! Since |Bₙ| ≤ ∫P0 = 1 for every start, the tails are bounded by
//! Σ_{n>N} e^{−n²a} ≤ e^{−(N+1)²a}/(1 − e^{−(2N+3)a}), a = π²τ/y².

use super::elastic::cylinder_coefficient;
use super::start::Start;
use crate::error::Result;
use crate::quad::{integrate, Estimate};

const EPS: f64 = f64::EPSILON;
const PI: f64 = std::f64::consts::PI;

/// A double-double number hi + lo (|lo| ≤ ulp(hi)/2).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Dd(pub f64, pub f64);

impl Dd {
    fn two_prod(a: f64, b: f64) -> Dd {
        let p = a * b;
        Dd(p, a.mul_add(b, -p))
    }
    fn quick(a: f64, b: f64) -> Dd {
        let s = a + b;
        Dd(s, b - (s - a))
    }
    pub(crate) fn mul(self, o: Dd) -> Dd {
        let p = Dd::two_prod(self.0, o.0);
        Dd::quick(p.0, p.1 + (self.0 * o.1 + self.1 * o.0))
    }
    pub(crate) fn mul_f(self, b: f64) -> Dd {
        let p = Dd::two_prod(self.0, b);
        Dd::quick(p.0, p.1 + self.1 * b)
    }
    pub(crate) fn div_f(self, b: f64) -> Dd {
        let q = self.0 / b;
        let p = Dd::two_prod(q, b);
        let r = (self.0 - p.0 - p.1 + self.1) / b;
        Dd::quick(q, r)
    }
    pub(crate) fn div(self, o: Dd) -> Dd {
        let q = self.0 / o.0;
        let p = o.mul_f(q);
        let r = ((self.0 - p.0) - p.1 + self.1) / o.0;
        Dd::quick(q, r)
    }
}

/// π² as a double-double.
const PI2: Dd = Dd(9.869_604_401_089_358, -3.439_976_145_947_315e-16);

/// a = π² (σ0/σH)² G / y² as a double-double, so that Eₙ = e^{−n² a} keeps full
/// relative accuracy even when n² a is in the hundreds.
pub(crate) fn decay_rate(start: &Start, g: f64, y: f64) -> Dd {
    let r2 = match start {
        Start::Flat => PI2,
        Start::Hertz => PI2.mul_f(4.0).div_f(9.0),
        Start::Cylinder => PI2.mul(PI2).div_f(16.0),
        Start::Tabulated(t) => PI2.mul_f(t.mean).mul_f(t.mean),
    };
    let y2 = Dd::two_prod(y, y);
    r2.mul_f(g).div(y2)
}

/// e^{−n² a}.
#[inline]
fn decay(n: usize, a: Dd) -> f64 {
    let n2 = (n * n) as f64;
    let p = Dd::two_prod(a.0, n2);
    let lo = p.1 + a.1 * n2;
    (-p.0).exp() * (1.0 - lo)
}

/// sin(π n/y) with the argument reduced exactly: n/y = m + f, |f| ≤ 1/2.
pub(crate) fn sin_pi_ratio(n: f64, y: f64) -> f64 {
    let m = (n / y).round();
    let r = (-m).mul_add(y, n); // n − m y, one rounding
    let v = (PI * (r / y)).sin();
    if m.rem_euclid(2.0) == 1.0 {
        -v
    } else {
        v
    }
}

/// 2 j₁(γ), the Hertz coefficient, without cancellation at small γ.
///
/// # Formula
/// ```text
/// 2 j₁(γ) = 2 γ Σₖ (−γ²/2)ᵏ / (k! (2k+3)!!)      γ < 2
///         = 2 (sin γ/γ² − cos γ/γ)               γ ≥ 2
/// ```
pub(crate) fn hertz_coefficient(gamma: f64) -> f64 {
    if gamma < 2.0 {
        let x2 = -0.5 * gamma * gamma;
        let (mut term, mut sum): (f64, f64) = (1.0 / 3.0, 0.0);
        for k in 0..30 {
            sum += term;
            if term.abs() < 1e-18 * sum.abs() {
                break;
            }
            let kf = k as f64;
            term *= x2 / ((kf + 1.0) * (2.0 * kf + 5.0));
        }
        2.0 * gamma * sum
    } else {
        let (s, c) = gamma.sin_cos();
        2.0 * (s / gamma - c) / gamma
    }
}

/// The truncated sine series for one curve.
pub(crate) struct Series {
    /// (2/y) Bₙ Eₙ, n = 1..=N.
    pub(crate) c: Vec<f64>,
    y: f64,
    /// Truncation bound of the density.
    tail: f64,
    /// Σ |cₙ| (8n + 8) ε: rounding of the sum with rotated sines (the angle
    /// πs/y carries 2ε relative error, amplified n times).
    round: f64,
    /// Absolute error of each Bₙ (0 for closed forms up to rounding).
    coef_err: f64,
}

/// Terms N such that `scale`·Σ_{n>N} e^{−n²a} ≤ tol (a > 0).
///
/// The bisection runs on [1, 2⁵⁰] in `u64`, so that it is the same on 32-bit
/// targets; a count beyond `usize::MAX` saturates there (every caller refuses
/// more than 10⁶ terms).
pub(crate) fn terms_for(a: f64, scale: f64, tol: f64) -> usize {
    let below = |n: u64| tail_bound((n + 1) as f64, a) * scale <= tol;
    let (mut lo, mut hi) = (0u64, 1u64 << 50);
    if below(1) {
        return 1;
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if below(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    usize::try_from(hi).unwrap_or(usize::MAX)
}

/// Σ_{n>N} e^{−n²a} ≤ e^{−(N+1)²a}/(1 − e^{−(2N+3)a}).
pub(crate) fn tail_sum(n: usize, a: f64) -> f64 {
    tail_bound((n + 1) as f64, a)
}

/// e^{−m²a}/(1 − e^{−(2m+1)a}) with m = N + 1: the bound of [`tail_sum`].
fn tail_bound(m: f64, a: f64) -> f64 {
    (-m * m * a).exp() / -(-(2.0 * m + 1.0) * a).exp_m1()
}

/// Bₙ for n = 1..=N with a bound on their absolute error.
pub(crate) fn coefficients(start: &Start, y: f64, n: usize, tol: f64) -> Result<(Vec<f64>, f64)> {
    let k1 = PI / y;
    let mut err = 8.0 * EPS;
    let b = match start {
        Start::Flat => (1..=n).map(|i| sin_pi_ratio(i as f64, y)).collect(),
        Start::Hertz => (1..=n).map(|i| hertz_coefficient(i as f64 * k1)).collect(),
        Start::Cylinder => (1..=n)
            .map(|i| cylinder_coefficient(i as f64 * k1))
            .collect(),
        Start::Tabulated(t) => {
            let mut v = Vec::with_capacity(n);
            for i in 1..=n {
                let k = i as f64 * k1;
                let mut s = 0.0;
                for (a, b) in t.segments() {
                    let r = integrate(
                        "stress: sine coefficient of a tabulated start",
                        |u: f64| t.eval(u) * (k * u).sin(),
                        a,
                        b,
                        0.01 * tol,
                        1e-14,
                        200_000,
                    )?;
                    s += r.value;
                    err = err.max(r.error * t.s.len() as f64);
                }
                v.push(s);
            }
            v
        }
    };
    Ok((b, err))
}

impl Series {
    /// The density series with N chosen so that the tail is ≤ `tol_t`.
    pub(crate) fn new(start: &Start, y: f64, a: Dd, tol_t: f64, tol: f64) -> Result<Self> {
        let n = terms_for(a.0, 2.0 / y, tol_t);
        let (b, coef_err) = coefficients(start, y, n, tol)?;
        let c: Vec<f64> = b
            .iter()
            .enumerate()
            .map(|(i, bn)| 2.0 / y * bn * decay(i + 1, a))
            .collect();
        let round = c
            .iter()
            .enumerate()
            .map(|(i, v)| v.abs() * (8.0 * i as f64 + 16.0))
            .sum::<f64>()
            * EPS;
        let esum: f64 = (1..=n).map(|i| decay(i, a)).sum();
        Ok(Series {
            tail: 2.0 / y * tail_sum(n, a.0),
            round,
            coef_err: coef_err * 2.0 / y * esum,
            c,
            y,
        })
    }

    /// Number of terms.
    pub(crate) fn len(&self) -> usize {
        self.c.len()
    }

    /// P(s) for 0 < s < y.
    pub(crate) fn density(&self, s: f64) -> Estimate {
        let (sn, cs) = (PI * (s / self.y)).sin_cos();
        let (mut re, mut im) = (cs, sn);
        let mut sum = 0.0;
        for &cn in &self.c {
            sum += cn * im;
            let r2 = re * cs - im * sn;
            im = re * sn + im * cs;
            re = r2;
        }
        Estimate {
            value: sum,
            error: self.tail + self.round + self.coef_err,
        }
    }
}

/// A_el and A_pl from the series, each with an error bound.
pub(crate) fn fractions(
    start: &Start,
    y: f64,
    a: Dd,
    tol: f64,
) -> Result<(Estimate, Estimate, usize)> {
    // both tails ≤ (4/π) Σ_{n>N} e^{−n² a}
    let n = terms_for(a.0, 4.0 / PI, 1e-3 * tol.min(1e-13) * 1e-3);
    fractions_with_terms(start, y, a, tol, n)
}

/// A_el and A_pl from the first `n` terms of the series, each with an error
/// bound that includes the truncation.
pub(crate) fn fractions_with_terms(
    start: &Start,
    y: f64,
    a: Dd,
    tol: f64,
    n: usize,
) -> Result<(Estimate, Estimate, usize)> {
    let (b, coef_err) = coefficients(start, y, n, tol)?;
    let (mut el, mut el_mag, mut pl, mut pl_mag) = (0.0, 0.0, 0.0, 0.0);
    let mut esum = 0.0;
    for (i, bn) in b.iter().enumerate() {
        let m = i + 1;
        let e = decay(m, a);
        esum += e;
        let t = bn * e / (m as f64 * PI);
        if m % 2 == 1 {
            el += 4.0 * t;
            el_mag += 4.0 * t.abs();
            pl -= 2.0 * t;
        } else {
            pl += 2.0 * t;
        }
        pl_mag += 2.0 * t.abs();
    }
    let mean = start.mean_ratio() / y;
    let tail = 4.0 / PI * tail_sum(n, a.0);
    let cerr = coef_err * 4.0 / PI * esum;
    Ok((
        Estimate {
            value: el,
            error: tail + cerr + (n as f64 + 4.0) * EPS * el_mag,
        },
        Estimate {
            value: mean + pl,
            error: tail + cerr + (n as f64 + 4.0) * EPS * (pl_mag + mean),
        },
        n,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hertz_coefficient_branches_agree() {
        for g in [1.999_999, 2.0] {
            let a = hertz_coefficient(g);
            let (s, c) = g.sin_cos();
            let b = 2.0 * (s / g - c) / g;
            assert!((a - b).abs() < 1e-15, "{a} {b}");
        }
    }

    #[test]
    fn sin_pi_ratio_matches_sin() {
        for (n, y) in [(1.0, 1.01), (3.0, 2.5), (7.0, 1e3)] {
            let a = sin_pi_ratio(n, y);
            let b = (PI * n / y).sin();
            assert!((a - b).abs() < 1e-14, "{a} {b}");
        }
    }
}

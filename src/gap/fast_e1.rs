//! E1 by piecewise Chebyshev interpolants: the inner function of the
//! per-load P(u) table sums.
//!
//! # Formula
//! ```text
//! 0 < x ≤ 1:        E1(x) = S(x) − ln x,        S(x) = E1(x) + ln x   (entire)
//! 2^j < x ≤ 2^{j+1}: E1(x) = e^{−x} R(x),       R(x) = e^x E1(x)
//! ```
//! (Abramowitz & Stegun 5.1.11 and 5.1.22.) S is entire and R is analytic
//! off the cut x ≤ 0, so on [0, 1] and on each octave [2^j, 2^{j+1}] a
//! Chebyshev interpolant converges geometrically (on an octave the cut at 0
//! is 3 half-widths from the centre: ratio ρ = 3 + √8 ≈ 5.8 a degree).
//!
//! # Method
//! The coefficients are computed once (first use) by interpolating
//! [`crate::special::e1`] and [`crate::special::e1_scaled`] at
//! [`DEGREE`] + 1 Chebyshev points of each piece, trailing coefficients below
//! 1e-18 of the first dropped; a call is then one Clenshaw sum of ≤ 25 terms
//! instead of [`crate::special::e1`]'s series or continued fraction (170
//! levels at x = 1). Octaves up to 2^10 = 1024 (above, the table's sums skip
//! the node: e^{−x} underflows past 745). Accuracy: relative difference to
//! `special::e1` ≤ 1e-14 on 1e-3 ≤ x ≤ 700 (test below).

use crate::special::{e1, e1_scaled};
use std::sync::OnceLock;

/// Chebyshev degree of each piece before trimming.
const DEGREE: usize = 16;

/// Pieces per octave: each [a, 2^{1/4} a], the cut at 0 then 11.6
/// half-widths from the centre (ρ ≈ 23 a degree: ≤ 13 terms after trimming,
/// against 22 for whole octaves; measured 1.4× faster table sums).
const PER_OCTAVE: usize = 4;

/// 2^{1/4}, 2^{1/2}, 2^{3/4}: the inner piece ends of an octave (scaled to [1, 2)).
const QUARTERS: [f64; PER_OCTAVE - 1] = [
    1.189_207_115_002_721,
    std::f64::consts::SQRT_2,
    1.681_792_830_507_429_4,
];

/// Octaves [2^j, 2^{j+1}] covered, j = 0 … OCTAVES − 1.
const OCTAVES: usize = 10;

/// The pieces: [0, 1] (S), then the octaves (R), as (a, b, coefficients).
struct Pieces {
    small: Piece,
    octaves: Vec<Piece>,
}

struct Piece {
    centre: f64,
    inv_half: f64,
    coefficients: Vec<f64>,
}

impl Piece {
    /// Chebyshev interpolant of `f` on [a, b] at DEGREE + 1 Chebyshev points
    /// of the first kind, trailing coefficients below 1e-18 |c0| dropped.
    fn fit(a: f64, b: f64, f: impl Fn(f64) -> f64) -> Piece {
        let n = DEGREE + 1;
        let (centre, half) = (0.5 * (a + b), 0.5 * (b - a));
        let theta: Vec<f64> = (0..n)
            .map(|k| std::f64::consts::PI * (k as f64 + 0.5) / n as f64)
            .collect();
        let values: Vec<f64> = theta.iter().map(|t| f(centre + half * t.cos())).collect();
        let mut coefficients: Vec<f64> = (0..n)
            .map(|j| {
                let sum: f64 = theta
                    .iter()
                    .zip(&values)
                    .map(|(t, v)| v * (j as f64 * t).cos())
                    .sum();
                let scale = if j == 0 { 1.0 } else { 2.0 };
                scale * sum / n as f64
            })
            .collect();
        let floor = 1e-18 * coefficients[0].abs();
        while coefficients.len() > 1 && coefficients.last().is_some_and(|c| c.abs() < floor) {
            coefficients.pop();
        }
        Piece {
            centre,
            inv_half: 1.0 / half,
            coefficients,
        }
    }

    /// Clenshaw sum at x (plain multiply-adds: `f64::mul_add` is a
    /// software call without the `fma` target feature, measured 3× slower).
    #[inline]
    fn eval(&self, x: f64) -> f64 {
        let t = (x - self.centre) * self.inv_half;
        let two_t = 2.0 * t;
        let (mut b1, mut b2) = (0.0, 0.0);
        for &c in self.coefficients[1..].iter().rev() {
            let b0 = two_t * b1 + (c - b2);
            b2 = b1;
            b1 = b0;
        }
        t * b1 + (self.coefficients[0] - b2)
    }
}

fn pieces() -> &'static Pieces {
    static PIECES: OnceLock<Pieces> = OnceLock::new();
    PIECES.get_or_init(|| Pieces {
        small: Piece::fit(0.0, 1.0, |x| e1(x) + x.ln()),
        octaves: padded(
            (0..OCTAVES * PER_OCTAVE)
                .map(|k| {
                    let a = (1u64 << (k / PER_OCTAVE)) as f64;
                    let i = (k % PER_OCTAVE) as f64 / PER_OCTAVE as f64;
                    let b = if k % PER_OCTAVE == PER_OCTAVE - 1 {
                        2.0 * a
                    } else {
                        a * (i + 1.0 / PER_OCTAVE as f64).exp2()
                    };
                    Piece::fit(a * i.exp2(), b, e1_scaled)
                })
                .collect(),
        ),
    })
}

/// The pieces with their coefficient lists padded by zeros to one length
/// (a zero high-order coefficient leaves Clenshaw's sum bit for bit
/// unchanged), so that [`e1_fast_pair`] runs two sums in one fixed loop.
fn padded(mut pieces: Vec<Piece>) -> Vec<Piece> {
    let width = pieces
        .iter()
        .map(|p| p.coefficients.len())
        .max()
        .unwrap_or(1);
    for p in &mut pieces {
        p.coefficients.resize(width, 0.0);
    }
    pieces
}

/// The octave piece of x > 1 (module docs), if x is within the octaves.
#[inline]
fn octave_piece(p: &Pieces, x: f64) -> Option<&Piece> {
    // octave j = ⌊log2 x⌋ from the exponent bits (x > 1, finite: j ≥ 0),
    // then the quarter from the top mantissa bits; a piece's interpolant
    // is good slightly past its ends, so piece ends rounded either way are harmless
    let bits = x.to_bits();
    let j = ((bits >> 52) & 0x7ff) as usize - 1023;
    let mantissa = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52)); // in [1, 2)
    let quarter = QUARTERS.iter().filter(|&&t| mantissa >= t).count();
    p.octaves.get(j * PER_OCTAVE + quarter)
}

/// [`e1_fast`] at two points: for two points past 1 in the octaves, the two
/// Clenshaw sums run in one loop, so that their latency chains overlap
/// (the sums are the table's hot loop; the values are bit for bit those of
/// [`e1_fast`]).
#[inline]
pub(crate) fn e1_fast_pair(x: [f64; 2], exp_minus_x: [f64; 2]) -> [f64; 2] {
    let p = pieces();
    let (Some(a), Some(b)) = (
        (x[0] > 1.0).then(|| octave_piece(p, x[0])).flatten(),
        (x[1] > 1.0).then(|| octave_piece(p, x[1])).flatten(),
    ) else {
        return [e1_fast(x[0], exp_minus_x[0]), e1_fast(x[1], exp_minus_x[1])];
    };
    let ta = (x[0] - a.centre) * a.inv_half;
    let tb = (x[1] - b.centre) * b.inv_half;
    let (two_ta, two_tb) = (2.0 * ta, 2.0 * tb);
    let (mut a1, mut a2, mut b1, mut b2) = (0.0, 0.0, 0.0, 0.0);
    for (&ca, &cb) in a.coefficients[1..].iter().zip(&b.coefficients[1..]).rev() {
        let a0 = two_ta * a1 + (ca - a2);
        let b0 = two_tb * b1 + (cb - b2);
        a2 = a1;
        a1 = a0;
        b2 = b1;
        b1 = b0;
    }
    [
        (ta * a1 + (a.coefficients[0] - a2)) * exp_minus_x[0],
        (tb * b1 + (b.coefficients[0] - b2)) * exp_minus_x[1],
    ]
}

/// E1(x) for x > 0 given e^{−x} (module docs); past the last octave
/// (x > 1024) `e1_scaled(x) · e^{−x}`.
#[inline]
pub(crate) fn e1_fast(x: f64, exp_minus_x: f64) -> f64 {
    let p = pieces();
    if x <= 1.0 {
        return p.small.eval(x) - x.ln();
    }
    match octave_piece(p, x) {
        Some(piece) => piece.eval(x) * exp_minus_x,
        None => e1_scaled(x) * exp_minus_x,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the crate's tested series and continued fraction
    /// (`special::e1`, itself checked against mpmath), on a fine log grid
    /// and at the piece ends.
    #[test]
    fn matches_special_e1() {
        let mut worst: f64 = 0.0;
        let mut xs: Vec<f64> = (0..=4000)
            .map(|i| 10f64.powf(-3.0 + 5.845 * f64::from(i) / 4000.0))
            .collect();
        for k in 0..=OCTAVES * PER_OCTAVE {
            let a = (k as f64 / PER_OCTAVE as f64).exp2();
            xs.extend([a * (1.0 - 1e-15), a, a * (1.0 + 1e-15)]);
        }
        // E1 leaves the normal range near 700
        for x in xs.into_iter().filter(|&x| x <= 700.0) {
            let (fast, reference) = (e1_fast(x, (-x).exp()), e1(x));
            let rel = ((fast - reference) / reference).abs();
            assert!(rel.is_finite(), "x = {x}: {fast} against {reference}");
            worst = worst.max(rel);
        }
        assert!(worst < 1e-14, "worst relative difference {worst:e}");
    }

    /// The paired evaluation is [`e1_fast`] bit for bit, for pairs in the
    /// octaves, across piece ends, and with a point at or below 1 or past
    /// the last octave (the fallback).
    #[test]
    fn pair_equals_single() {
        let xs: Vec<f64> = (0..=600)
            .map(|i| 10f64.powf(-0.5 + 3.6 * f64::from(i) / 600.0))
            .collect();
        for w in xs.windows(7) {
            let x = [w[0], w[6]];
            let ex = [(-x[0]).exp(), (-x[1]).exp()];
            let pair = e1_fast_pair(x, ex);
            assert_eq!(pair[0].to_bits(), e1_fast(x[0], ex[0]).to_bits(), "{x:?}");
            assert_eq!(pair[1].to_bits(), e1_fast(x[1], ex[1]).to_bits(), "{x:?}");
        }
    }
}

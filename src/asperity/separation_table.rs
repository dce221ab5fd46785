//! The BGT integrals tabulated once per surface in the dimensionless
//! separation δ, so that a load curve costs a few series evaluations a point.
//!
//! # Formula
//! With the summit table's integrals ([`super::summit_table`])
//! ```text
//! L_j(δ) = ln( J_j(δ)/φ(δ) ),   j = count (0, 1), area (1, ½), load (3/2, ¾), load′ (½, ¾)
//! ```
//! each L_j is analytic in δ (a Laplace-type transform of the entire, positive
//! weights g_γ), slowly varying: ~ δ²/2 as δ → −∞, ~ −(k+1) ln δ + ln g_γ(δ) as
//! δ → ∞. It is interpolated by a Chebyshev series of [`TERMS`] terms on each
//! of the pieces [`BREAKS`] of δ ∈ [−6, 12].
//!
//! # Error bound
//! For an analytic function the Chebyshev coefficients c_n decay
//! geometrically, and the interpolant's error is bounded by the sum of the
//! dropped coefficients, ≈ Σ_{n ≥ N} |c_n| ≲ |c_{N−1}|·(a few) once the decay has
//! reached the floor set by the tabulated values (their relative error,
//! ~1e-14, is an absolute error in L). At build the largest of the last
//! [`TAIL`] coefficients of every series is taken as the estimate; a piece
//! whose estimate exceeds [`TAIL_LIMIT`] (1e-13 in L, i.e. 1e-13 relative in
//! J) is refused and the whole table with it (the caller falls back to the
//! summit table). Measured: the tails are 1e-14–3e-14 for α from 4 to 1e5,
//! both Hertz treatments; tests/asperity.rs compares the table at points off
//! the nodes with the direct u-integrals to 1e-12 relative.
//!
//! # Cost
//! Building: [`TERMS`] × (number of pieces) summit-table integrals (~7 µs
//! each, about 1 ms once per surface). A point: four Clenshaw sums of
//! [`TERMS`] terms.

use super::kernel::Chebyshev;
use super::summit_table::SummitTable;

/// Piece ends in δ.
pub(crate) const BREAKS: [f64; 5] = [-6.0, -2.0, 2.0, 6.0, 12.0];
/// Chebyshev terms per piece and quantity.
pub(crate) const TERMS: usize = 32;
/// Coefficients whose largest magnitude is the error estimate.
const TAIL: usize = 4;
/// Largest error estimate accepted (absolute, in ln J/φ).
pub(crate) const TAIL_LIMIT: f64 = 1e-13;

/// ln J/φ of count, area, load and the load's derivative weight, per piece.
#[derive(Debug, Clone)]
pub(crate) struct SeparationTable {
    pieces: Vec<[Chebyshev; 4]>,
    /// The largest error estimate of all series (for tests).
    tail: f64,
}

impl SeparationTable {
    /// Tabulate from the summit table; `None` if a value is not positive or
    /// a series' tail exceeds [`TAIL_LIMIT`].
    pub(crate) fn build(summits: &SummitTable) -> Option<Self> {
        let mut pieces = Vec::with_capacity(BREAKS.len() - 1);
        let mut tail: f64 = 0.0;
        for w in BREAKS.windows(2) {
            let (a, b) = (w[0], w[1]);
            let mut vals: [Vec<f64>; 4] = Default::default();
            for delta in Chebyshev::nodes(a, b, TERMS) {
                let s = summits.scaled(delta)?;
                for j in 0..4 {
                    if !(s[j] > 0.0 && s[j].is_finite()) {
                        return None;
                    }
                    vals[j].push(s[j].ln());
                }
            }
            let series = vals.map(|v| Chebyshev::from_values(a, b, &v));
            for s in &series {
                tail = tail.max(s.tail(TAIL));
            }
            pieces.push(series);
        }
        (tail <= TAIL_LIMIT).then_some(SeparationTable { pieces, tail })
    }

    /// J/φ(δ) for count, area, load and the load's derivative weight (as
    /// [`SummitTable::scaled`]), or `None` outside [−6, 12].
    pub(crate) fn scaled(&self, delta: f64) -> Option<[f64; 4]> {
        if !(BREAKS[0]..=BREAKS[BREAKS.len() - 1]).contains(&delta) {
            return None;
        }
        let i = BREAKS[1..BREAKS.len() - 1].partition_point(|&b| b < delta);
        Some(self.pieces[i].each_ref().map(|s| s.eval(delta).exp()))
    }

    /// The largest error estimate of the series (absolute, in ln J/φ).
    pub(crate) fn tail(&self) -> f64 {
        self.tail
    }
}

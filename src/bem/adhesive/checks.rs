//! The adhesive solver's check of its input: the reach of the law on the
//! grid (the heights are checked by `Heights::new`).

use super::{AdhesiveSolver, CohesiveLaw, Target};
use crate::bem::problem::Heights;
use crate::error::{Error, Result};

impl AdhesiveSolver {
    /// Refuse a mean gap (or an approach) so large that the gap field no
    /// longer resolves the cohesive law, or its elastic pressures overflow
    /// (ε was NaN at ḡ = 1e300, and a finite noise of ±6e145 at 9e133).
    ///
    /// # Bounds
    /// The gap field is ≥ 0 with mean ḡ, so a gap is at most N²ḡ and carries
    /// a rounding of up to ε N²ḡ (ε = f64::EPSILON; approach control: ε|δ|).
    /// The law varies on the scale ρ: its tractions are resolved only while
    ///
    /// ```text
    /// ε N² ḡ ≤ ρ   ⇔   ḡ ≤ ρ/(ε N²)          (approach: |δ| ≤ ρ/ε)
    /// ```
    ///
    /// Beyond it the iteration stops at the round-off of 𝒦(g + h), which the
    /// noise of the gap sets, and reports that noise as the mean pressure.
    /// Independently the displacement |g + h − o| is at most
    /// U = N²ḡ + (max h − min h) (approach: |δ| + 2(max h − min h)) and the
    /// operator's largest symbol E*|q|_max/2, |q|_max = √2 πN/L, so
    /// Σ(𝒦u)² ≤ (E*|q|_max/2)² N² U² stays below f64::MAX/4 while
    /// (E*|q|_max/2) N U ≤ √f64::MAX/2; the smaller bound is stated.
    pub(super) fn check_reach(
        &self,
        heights: Heights<'_>,
        law: &CohesiveLaw,
        target: Target,
    ) -> Result<()> {
        let op = &self.ops.op;
        let n = self.layout.n as f64;
        let rho = law.parameters().1;
        let q_max = std::f64::consts::SQRT_2 * std::f64::consts::PI * n / op.size();
        let range = heights.max() - heights.min();
        let reach = f64::MAX.sqrt() / (op.e_star() * q_max * n);
        let approx = crate::error::approx;
        let why = format!(
            "(ρ = {}, N = {}, E* = {}, L = {}) so that the gap field resolves the cohesive law \
             (its rounding ε N²ḡ below ρ) and its elastic pressures stay finite in f64",
            crate::error::num(rho),
            self.layout.n,
            crate::error::num(op.e_star()),
            crate::error::num(op.size()),
        );
        match target {
            Target::MeanGap(mean_gap) => {
                let bound = (rho / (f64::EPSILON * n * n)).min((reach - range) / (n * n));
                if mean_gap.is_nan() || mean_gap > bound {
                    return Err(Error::invalid(
                        "mean_gap",
                        mean_gap,
                        format!("at most {} {why}", approx(bound.max(0.0))),
                    ));
                }
            }
            Target::Approach(approach) => {
                let bound = (rho / f64::EPSILON).min(reach - 2.0 * range);
                if approach.is_nan() || approach.abs() > bound {
                    return Err(Error::invalid(
                        "approach",
                        approach,
                        format!("at most {} in size {why}", approx(bound.max(0.0))),
                    ));
                }
            }
        }
        Ok(())
    }
}

//! A(w) and B(w) (see [`super::viscoelastic`]) at the speed the friction
//! integrals need: closed forms for a Prony series, a piecewise Chebyshev
//! interpolant in ln w for a master curve.
//!
//! # Method
//! For a log-log interpolated table, A and B are smooth in y = ln w except at
//! each table frequency y_i = ln ω_i, where a kink of E(ω) enters the angular
//! integral at u = cos φ = 1 and A, B pick up a term ∝ (y − y_i)^{3/2} on the
//! right side only (the weight (1 − u²)^{−1/2} is singular there). The
//! interpolant therefore has a panel boundary at every y_i, maps each such
//! panel by y = y_i + h t² (the singular term becomes a polynomial in t) and
//! interpolates on 17 Chebyshev–Lobatto points of t, bisecting until the last
//! two Chebyshev coefficients are below the tolerance times the panel's
//! largest value. The node values come from the exact segment series of
//! [`super::MasterCurve::angular`]. Below the table A, B are constant; 40
//! e-folds above it they equal their limits to 1e-17 (a (ω_max/w)-term).
//!
//! # References
//! L. N. Trefethen, *Approximation Theory and Approximation Practice* (SIAM,
//! 2013), ch. 3–4 and 8 (Chebyshev interpolation and its convergence).

use super::chebyshev::{clenshaw, coefficients, rule, Map, NODES};
use super::master_curve::MasterCurve;
use super::viscoelastic::{AngularIntegrals, Viscoelastic};
use crate::error::{Error, Result};

/// How far above the table (in ln w) the interpolant reaches; beyond, A and B
/// differ from their limits by O(e^{−40}).
const TAIL: f64 = 40.0;

/// Bisection depth cap of the interpolant's panels.
const MAX_DEPTH: usize = 40;

/// A(w), B(w) with a bound on their relative error.
pub(crate) enum AngularModel<'a> {
    /// Closed forms (a Prony series): exact to rounding.
    Exact(&'a Viscoelastic),
    /// A master curve's interpolant.
    Table(Box<AngularTable>),
}

impl<'a> AngularModel<'a> {
    /// The model of `v` with interpolation tolerance `tolerance` (relative).
    pub fn new(v: &'a Viscoelastic, tolerance: f64) -> Result<Self> {
        Ok(match v {
            Viscoelastic::MasterCurve(m) => {
                AngularModel::Table(Box::new(AngularTable::new(m, tolerance)?))
            }
            _ => AngularModel::Exact(v),
        })
    }

    /// A(w), B(w) and their parts from outside a table.
    #[inline]
    pub fn eval(&self, w: f64) -> AngularIntegrals {
        match self {
            AngularModel::Exact(v) => v.angular(w),
            AngularModel::Table(t) => t.eval(w),
        }
    }

    /// Bound on the relative error of `eval` (rounding for the closed forms).
    pub fn relative_error(&self) -> f64 {
        match self {
            AngularModel::Exact(_) => 64.0 * f64::EPSILON,
            AngularModel::Table(t) => t.error,
        }
    }
}

/// One interpolation panel [a, a + h] in y = ln w.
struct Panel {
    a: f64,
    h: f64,
    map: Map,
    /// Chebyshev coefficients of A, B, A_out, B_out.
    coef: [[f64; NODES]; 4],
}

/// The piecewise Chebyshev interpolant of a master curve's A, B.
pub(crate) struct AngularTable {
    y_lo: f64,
    y_hi: f64,
    below: AngularIntegrals,
    above: AngularIntegrals,
    starts: Vec<f64>,
    panels: Vec<Panel>,
    /// Largest relative error estimate over the panels.
    pub error: f64,
}

impl AngularTable {
    /// Build to relative tolerance `tolerance`.
    ///
    /// # Errors
    /// [`Error::NotConverged`] when a panel cannot reach the tolerance.
    pub fn new(m: &MasterCurve, tolerance: f64) -> Result<Self> {
        let ys = m.ln_frequencies();
        let y_lo = ys[0];
        let y_hi = ys[ys.len() - 1] + TAIL;
        let mut t = AngularTable {
            y_lo,
            y_hi,
            below: m.angular_ln(ys[0] - 1.0),
            above: m.angular_ln(y_hi),
            starts: Vec::new(),
            panels: Vec::new(),
            error: 0.0,
        };
        let mut ends = ys.clone();
        ends.push(y_hi);
        for pair in ends.windows(2) {
            t.fill(
                m,
                pair[0],
                pair[1] - pair[0],
                Map::LeftSingular,
                0,
                tolerance,
            )?;
        }
        t.starts = t.panels.iter().map(|p| p.a).collect();
        Ok(t)
    }

    /// Interpolate [a, a + h], bisecting until converged (left to right).
    fn fill(
        &mut self,
        m: &MasterCurve,
        a: f64,
        h: f64,
        map: Map,
        depth: usize,
        tol: f64,
    ) -> Result<()> {
        let r = rule();
        let mut vals = [[0.0; NODES]; 4];
        for (j, &t) in r.t.iter().enumerate() {
            let (y, _) = map.at(a, h, t);
            let v = m.angular_ln(y);
            vals[0][j] = v.loss;
            vals[1][j] = v.modulus_squared;
            vals[2][j] = v.loss_outside;
            vals[3][j] = v.modulus_squared_outside;
        }
        if vals.iter().flatten().any(|v| !v.is_finite()) {
            return Err(Error::NotConverged {
                what: format!(
                    "angular integrals of the master curve (not finite near w = {:e} rad/s)",
                    a.exp()
                ),
                iterations: depth,
                residual: f64::NAN,
                tolerance: tol,
            });
        }
        let coef: [[f64; NODES]; 4] = std::array::from_fn(|f| coefficients(&vals[f]));
        let mut err: f64 = 0.0;
        for f in 0..4 {
            let scale = vals[f % 2].iter().fold(0.0f64, |s, v| s.max(v.abs()));
            if scale > 0.0 {
                err = err.max((coef[f][NODES - 2].abs() + coef[f][NODES - 1].abs()) / scale);
            }
        }
        if err <= tol || depth >= MAX_DEPTH {
            if err > tol {
                return Err(Error::NotConverged {
                    what: "angular interpolant of the master curve".into(),
                    iterations: depth,
                    residual: err,
                    tolerance: tol,
                });
            }
            self.error = self.error.max(err);
            self.panels.push(Panel { a, h, map, coef });
            return Ok(());
        }
        self.fill(m, a, 0.5 * h, map, depth + 1, tol)?;
        self.fill(m, a + 0.5 * h, 0.5 * h, Map::Linear, depth + 1, tol)
    }

    /// A, B and their outside parts at w.
    #[inline]
    pub fn eval(&self, w: f64) -> AngularIntegrals {
        let y = w.ln();
        if y <= self.y_lo || y.is_nan() {
            return self.below;
        }
        if y >= self.y_hi {
            return self.above;
        }
        let i = self.starts.partition_point(|&s| s <= y).max(1) - 1;
        let p = &self.panels[i];
        let t = p.map.inverse(p.a, p.h, y);
        AngularIntegrals {
            loss: clenshaw(&p.coef[0], t),
            modulus_squared: clenshaw(&p.coef[1], t),
            loss_outside: clenshaw(&p.coef[2], t),
            modulus_squared_outside: clenshaw(&p.coef[3], t),
        }
    }

    /// Number of panels (for the tests and reports).
    #[cfg(test)]
    pub fn panel_count(&self) -> usize {
        self.panels.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interpolant is built to 1e-13 relative; the check allows 10x.
    const INTERP_TOL: f64 = 1e-12;

    #[test]
    fn interpolant_matches_exact_series() {
        // A sparse, curved master curve over 3 decades (an SLS sampled).
        let sls = crate::friction::Prony::standard_linear_solid(1e9, 2e6, 1e-2).unwrap();
        let pts: Vec<(f64, f64, f64)> = (0..13)
            .map(|i| {
                let w = 10f64.powf(i as f64 * 0.25);
                let e = sls.modulus(w);
                (w, e.storage_modulus, e.loss_modulus)
            })
            .collect();
        let m = MasterCurve::new(&pts).unwrap();
        let t = AngularTable::new(&m, 1e-13).unwrap();
        assert!(t.error <= 1e-13);
        let mut worst: f64 = 0.0;
        for i in 0..4000 {
            let w = 10f64.powf(-3.0 + 25.0 * i as f64 / 3999.0);
            let (a, b) = (t.eval(w), m.angular(w));
            worst = worst
                .max((a.loss - b.loss).abs() / b.loss)
                .max((a.modulus_squared - b.modulus_squared).abs() / b.modulus_squared)
                .max((a.loss_outside - b.loss_outside).abs() / b.loss)
                .max(
                    (a.modulus_squared_outside - b.modulus_squared_outside).abs()
                        / b.modulus_squared,
                );
        }
        assert!(
            worst <= INTERP_TOL,
            "worst relative error {worst:e} ({} panels)",
            t.panel_count()
        );
    }
}

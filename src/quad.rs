//! Adaptive quadrature with an honest error estimate.
//!
//! A thin wrapper over bilby's globally adaptive Gauss–Kronrod (G10K21)
//! integrator. Integrands are wrapped so that a non-finite value at a node is
//! counted instead of silently poisoning (or being hidden in) the result: any
//! non-finite evaluation turns into an error.

use crate::error::{Error, Result};

/// Value with an estimated absolute error: what every approximation of the
/// crate returns (a quadrature, a series, a closed form up to rounding).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Estimate {
    /// The value.
    pub value: f64,
    /// Estimated absolute error (an upper bound where the method gives one).
    pub error: f64,
}

impl Estimate {
    /// An exact value up to rounding: error = `ulps` units in the last place.
    pub fn rounded(value: f64, ulps: f64) -> Self {
        Estimate {
            value,
            error: ulps * f64::EPSILON * value.abs(),
        }
    }
}

/// Integrate `f` over `[a, b]` to `max(abs_tol, rel_tol·|I|)`: the integral
/// with bilby's estimate of its absolute error.
///
/// `what` names the integral in the error returned when the tolerance is not
/// reached within `max_evals` evaluations, or when `f` is not finite somewhere.
/// When bilby stops at the round-off floor the result is accepted with its
/// (round-off dominated) error estimate, since no f64 method can do better.
///
/// # Errors
/// [`Error::NotConverged`] as above.
pub fn integrate(
    what: &str,
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    abs_tol: f64,
    rel_tol: f64,
    max_evals: usize,
) -> Result<Estimate> {
    integrate_counted(what, f, a, b, abs_tol, rel_tol, max_evals).map(|(q, _)| q)
}

/// [`integrate`], with the number of integrand evaluations it spent.
///
/// # Errors
/// As [`integrate`].
pub fn integrate_counted(
    what: &str,
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    abs_tol: f64,
    rel_tol: f64,
    max_evals: usize,
) -> Result<(Estimate, usize)> {
    let bad = std::cell::Cell::new(0usize);
    let g = |x: f64| {
        let y = f(x);
        if y.is_finite() {
            y
        } else {
            bad.set(bad.get() + 1);
            0.0
        }
    };
    let r = bilby::AdaptiveIntegrator::default()
        .with_pair(bilby::GKPair::G10K21)
        .with_abs_tol(abs_tol)
        .with_rel_tol(rel_tol)
        .with_max_evals(max_evals)
        .integrate(a, b, g)
        .map_err(|e| Error::NotConverged {
            what: format!("{what} ({e})"),
            iterations: 0,
            residual: f64::NAN,
            tolerance: abs_tol,
        })?;
    let tol = abs_tol.max(rel_tol * r.value.abs());
    if bad.get() > 0 || !r.value.is_finite() || !(r.converged || r.roundoff_limited) {
        return Err(Error::NotConverged {
            what: if bad.get() > 0 {
                format!("{what} (integrand not finite at {} nodes)", bad.get())
            } else {
                what.to_string()
            },
            iterations: r.num_evals,
            residual: r.error_estimate,
            tolerance: tol,
        });
    }
    Ok((
        Estimate {
            value: r.value,
            error: r.error_estimate,
        },
        r.num_evals,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_on_unit_interval() {
        let q = integrate("exp", f64::exp, 0.0, 1.0, 1e-15, 1e-15, 10_000).unwrap();
        let exact = std::f64::consts::E - 1.0;
        // GK21 summation of ~20 terms: a few ulps of rounding.
        assert!(
            (q.value - exact).abs() <= 4.0 * f64::EPSILON * exact,
            "{}",
            q.value - exact
        );
        assert!(q.error >= (q.value - exact).abs());
    }

    #[test]
    fn non_finite_integrand_is_an_error() {
        let r = integrate("1/x", |x| 1.0 / x, 0.0, 1.0, 1e-10, 1e-10, 2_000);
        assert!(matches!(r, Err(Error::NotConverged { .. })));
    }
}

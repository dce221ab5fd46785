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

/// An n-point Gauss–Legendre rule on [−1, 1]: (nodes ascending, weights),
/// by Newton's method on the three-term recurrence from Tricomi's initial
/// guesses; converged to the last bit for n ≤ 1000. The one rule of the
/// crate: the stress distributions' cached rules (`stress/gauss.rs`) and the
/// asperity kernels' tables (`asperity/kernel.rs`) both take it.
///
/// # Formula
/// ```text
/// (k+1) P_{k+1}(z) = (2k+1) z P_k(z) − k P_{k−1}(z),   P_n'(z) = n (z P_n − P_{n−1})/(z² − 1)
/// z ← z − P_n(z)/P_n'(z),   w = 2/((1 − z²) P_n'(z)²)
/// ```
///
/// # References
/// W. H. Press et al., *Numerical Recipes*, 3rd ed. (Cambridge, 2007), §4.6
/// (Newton on the recurrence); the initial guess z₀ = cos(π(i + 3/4)/(n + 1/2))
/// is Tricomi's asymptotic one.
pub(crate) fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    let nf = n as f64;
    for i in 0..n.div_ceil(2) {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (p, d) = legendre_p(n, z);
            dp = d;
            let dz = p / d;
            z -= dz;
            if dz.abs() <= 1e-17 {
                break;
            }
        }
        let (_, d) = legendre_p(n, z);
        if d.is_finite() {
            dp = d;
        }
        let wi = 2.0 / ((1.0 - z * z) * dp * dp);
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = wi;
        w[n - 1 - i] = wi;
    }
    if n % 2 == 1 {
        x[n / 2] = 0.0;
    }
    (x, w)
}

/// P_n(z) and P_n'(z).
fn legendre_p(n: usize, z: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, z);
    for k in 2..=n {
        let kf = k as f64;
        let p2 = ((2.0 * kf - 1.0) * z * p1 - (kf - 1.0) * p0) / kf;
        p0 = p1;
        p1 = p2;
    }
    let d = n as f64 * (z * p1 - p0) / (z * z - 1.0);
    (p1, d)
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

//! Oracles independent of the crate: adaptive Gauss–Kronrod quadrature
//! straight from `bilby` and erf from `libm`, so that a test of the crate
//! never checks the crate against itself.
#![allow(dead_code)] // each test binary uses a subset

/// ∫ₐᵇ f to `max(abs_tol, rel_tol·|I|)` by bilby's adaptive G10K21 rule;
/// panics (naming `what`) unless bilby reports convergence or the round-off
/// floor, or when `f` is not finite on a node.
pub fn integrate(
    what: &str,
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    abs_tol: f64,
    rel_tol: f64,
    max_evals: usize,
) -> f64 {
    let g = |x: f64| {
        let y = f(x);
        assert!(y.is_finite(), "{what}: integrand {y} at {x}");
        y
    };
    let r = bilby::AdaptiveIntegrator::default()
        .with_pair(bilby::GKPair::G10K21)
        .with_abs_tol(abs_tol)
        .with_rel_tol(rel_tol)
        .with_max_evals(max_evals)
        .integrate(a, b, g)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(
        r.value.is_finite() && (r.converged || r.roundoff_limited),
        "{what}: not converged ({} ± {:e} after {} evaluations)",
        r.value,
        r.error_estimate,
        r.num_evals
    );
    r.value
}

/// erf from libm (at most 2e-16 relative error; see ../shared/deps.md).
pub fn erf(x: f64) -> f64 {
    libm::erf(x)
}

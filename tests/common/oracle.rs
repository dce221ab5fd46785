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

/// erf from libm (at most 2e-16 relative error; docs/design-notes.md).
pub fn erf(x: f64) -> f64 {
    libm::erf(x)
}

/// The mpmath oracle of A/A0 = erf(1/(2√G)) (50 digits, `tests/reference/core.py`):
/// (G, erf(1/(2√G)), erfc(1/(2√G)) (0 where it underflows f64), ln erfc(1/(2√G))).
#[allow(clippy::excessive_precision)]
pub const AREA: [(f64, f64, f64, f64); 10] = [
    (1e-12, 1.0, 0.0, -2.5000000001369473335e11),
    (1e-6, 1.0, 0.0, -2.500067869750413482e5),
    (
        1e-3,
        1.0,
        9.5053977665541412415e-111,
        -2.5333508549913602946e2,
    ),
    (
        0.01,
        9.9999999999846254021e-1,
        1.5374597944280356657e-12,
        -2.7200889545537433892e1,
    ),
    (
        0.6,
        6.3868957147382118834e-1,
        3.6131042852617881166e-1,
        -1.0180177773475634027,
    ),
    (
        2.0,
        3.8292492254802620728e-1,
        6.1707507745197379272e-1,
        -4.8276458103367329946e-1,
    ),
    (
        100.0,
        5.6371977797016623831e-2,
        9.4362802220298337617e-1,
        -5.8023234768983510648e-2,
    ),
    (
        1e10,
        5.6418958354305470709e-6,
        9.9999435810416456945e-1,
        -5.6419117509847186225e-6,
    ),
    (
        1e20,
        5.6418958354775628695e-11,
        9.9999999994358104165e-1,
        -5.6418958356367178126e-11,
    ),
    (
        1e30,
        5.6418958354775628134e-16,
        9.9999999999999943581e-1,
        -5.6418958354775644049e-16,
    ),
];

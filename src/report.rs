//! Error against run time, and the stability sweep over extreme inputs.
//!
//! [`accuracy`] measures, for every numerical method and each setting of its
//! accuracy knob, the achieved error against an independent reference and the
//! wall time, so users can pick their point on the curve. [`stability`] runs
//! the extreme and stiff cases and records whether any output was non-finite.

use std::time::Instant;

use serde::Serialize;

use crate::error::Result;
use crate::spectrum::{Amplitude, FnSpectrum, SelfAffine, Spectrum};
use crate::theory::{contact_fraction, Persson};

/// One measured point: a method at one setting of its knob.
#[derive(Debug, Clone, Serialize)]
pub struct AccuracyRow {
    /// The numerical method.
    pub method: String,
    /// The name of its accuracy knob.
    pub knob: String,
    /// The knob's setting.
    pub setting: f64,
    /// Achieved error against the reference (relative unless `method` says otherwise).
    pub error: f64,
    /// The method's own error estimate, where it has one.
    pub estimate: Option<f64>,
    /// Wall time of one evaluation, s.
    pub seconds: f64,
    /// The reference the error is measured against.
    pub reference: String,
}

/// How far the accuracy report goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Extent {
    /// The default: under two minutes on two cores.
    Default,
    /// Further: finer tolerances and larger grids.
    Full,
}

/// Median wall time of `f` over enough repetitions to last ~`budget` seconds.
pub fn time_it<T>(budget: f64, mut f: impl FnMut() -> T) -> (T, f64) {
    let t0 = Instant::now();
    let mut out = f();
    let first = t0.elapsed().as_secs_f64();
    let reps = ((budget / first.max(1e-9)) as usize).clamp(1, 10_000);
    if reps == 1 {
        return (out, first);
    }
    let mut times = Vec::with_capacity(reps);
    for _ in 0..reps {
        let t = Instant::now();
        out = f();
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (out, times[reps / 2])
}

/// G(ζ) of a closure spectrum by adaptive quadrature, against the closed form
/// of the same self-affine spectrum, for tolerances 1e-4 … 1e-14.
///
/// # Errors
/// A quadrature that fails to converge.
pub fn g_quadrature(extent: Extent) -> Result<Vec<AccuracyRow>> {
    let s = SelfAffine::new(1e3, 1e4, 1e13, 0.8, Amplitude::RmsSlope(1.0))?;
    let exact = Persson::new(&s, 1.0)?;
    let zetas = [3.0, 10.0, 1e3, 1e6, 1e10];
    let mut tols = vec![1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    if extent == Extent::Full {
        tols.insert(1, 1e-5);
        tols.push(1e-15);
    }
    tols.iter()
        .map(|&tol| {
            // No break declared at the roll-off kink: the quadrature must find it.
            let f = FnSpectrum::new(move |q| s.c(q), s.q_min(), s.q_max(), tol)?;
            let m = Persson::new(&f, 1.0)?;
            let run = || -> Result<(f64, f64)> {
                let mut worst: (f64, f64) = (0.0, 0.0);
                for &z in &zetas {
                    let g = m.g(z, 1e-3)?;
                    let e = exact.g(z, 1e-3)?.value;
                    worst = (
                        worst.0.max(((g.value - e) / e).abs()),
                        worst.1.max(g.error / e),
                    );
                }
                Ok(worst)
            };
            let (r, seconds) = time_it(0.05, run);
            let (error, estimate) = r?;
            Ok(AccuracyRow {
                method: "G(zeta), closure spectrum, adaptive Gauss-Kronrod".into(),
                knob: "tolerance".into(),
                setting: tol,
                error,
                estimate: Some(estimate),
                seconds: seconds / zetas.len() as f64,
                reference: "closed form of the same self-affine spectrum".into(),
            })
        })
        .collect()
}

/// The accuracy report of every numerical method in this build.
///
/// # Errors
/// The first method that fails.
pub fn accuracy(extent: Extent) -> Result<Vec<AccuracyRow>> {
    g_quadrature(extent)
}

/// One extreme case of the stability sweep.
#[derive(Debug, Clone, Serialize)]
pub struct StabilityCase {
    /// What was computed, with its inputs.
    pub case: String,
    /// The value.
    pub value: f64,
    /// Its error bound.
    pub error_bound: f64,
    /// Whether every output of the case was finite.
    pub finite: bool,
}

fn case(case: String, value: f64, error_bound: f64, others: &[f64]) -> StabilityCase {
    let finite =
        value.is_finite() && error_bound.is_finite() && others.iter().all(|v| v.is_finite());
    StabilityCase {
        case,
        value,
        error_bound,
        finite,
    }
}

/// The extreme and stiff cases of the core: G from 1e-12 to 1e30, H to 0.01
/// and 0.99, ζ to 1e10, pressures from 1e-12 E* to 10 E*.
///
/// # Errors
/// An input the library rejects (none of these should be).
pub fn stability() -> Result<Vec<StabilityCase>> {
    let mut out = Vec::new();
    for lg in [-12, -6, -3, 0, 3, 6, 12, 20, 30] {
        let g = 10f64.powi(lg);
        let a = contact_fraction(g, 0.0)?;
        out.push(case(
            format!("A/A0 at G = 1e{lg}"),
            a.fraction,
            a.error,
            &[a.complement, a.ln_complement],
        ));
    }
    for h in [0.01, 0.5, 0.99] {
        let s = SelfAffine::new(1.0, 1.0, 1e10, h, Amplitude::RmsSlope(1.0))?;
        let m = Persson::new(&s, 1.0)?;
        for lp in [-12, -6, 0, 1] {
            let p = 10f64.powi(lp);
            for zeta in [1.0 + 1e-12, 1e5, 1e10] {
                let pt = m.point(zeta, p)?;
                out.push(case(
                    format!("H = {h}, zeta = {zeta:e}, pressure = 1e{lp} E*: A/A0"),
                    pt.contact_fraction,
                    pt.error,
                    &[pt.g, pt.g_error, pt.complement],
                ));
            }
        }
    }
    Ok(out)
}

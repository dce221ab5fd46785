//! Error against run time, and the stability sweep over extreme inputs.
//!
//! [`accuracy`] measures, for every numerical method and each setting of its
//! accuracy knob, the achieved error against an independent reference and the
//! wall time, so users can pick their point on the curve. [`stability`] runs
//! the extreme and stiff cases and records whether any output was non-finite.

use std::time::Instant;

use serde::Serialize;

use crate::error::Result;

#[cfg(feature = "bem")]
mod bem;
mod core;
mod stress;

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

/// The accuracy report of every numerical method in this build.
///
/// # Errors
/// The first method that fails.
pub fn accuracy(extent: Extent) -> Result<Vec<AccuracyRow>> {
    let mut rows = core::g_quadrature(extent)?;
    rows.extend(stress::accuracy(extent)?);
    #[cfg(feature = "bem")]
    rows.extend(bem::accuracy(extent)?);
    Ok(rows)
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

pub(crate) fn case(case: String, value: f64, error_bound: f64, others: &[f64]) -> StabilityCase {
    let finite =
        value.is_finite() && error_bound.is_finite() && others.iter().all(|v| v.is_finite());
    StabilityCase {
        case,
        value,
        error_bound,
        finite,
    }
}

/// Every extreme case of this build: the core's and the stress distributions'.
///
/// # Errors
/// An input the library rejects (none of these should be).
pub fn stability() -> Result<Vec<StabilityCase>> {
    let mut cases = core::stability()?;
    cases.extend(stress::stability()?);
    Ok(cases)
}

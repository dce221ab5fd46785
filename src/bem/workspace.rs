//! The buffers every contact loop works in: the operator (with its FFT
//! scratch) and four `N × N` fields, allocated once per grid.
//!
//! # How a loop uses it
//! A loop is a function `solve(problem: &Problem, ws: &mut Workspace, opts,
//! observer) -> Result<Solution>`:
//! 1. [`Workspace::start`] writes the starting pressure (uniform, the
//!    overlap times the stiffness guess, or the previous solution rescaled:
//!    a warm start);
//! 2. [`Workspace::fields`] lends the operator and the fields at once
//!    (`pressure`, `gap`, `direction`, `response`, and the sparse-correction
//!    lists), to be used for 𝒢 ([`Operator::apply_rows`]) and 𝒦
//!    ([`Operator::apply_stiffness_rows`]) and the loop's own passes;
//! 3. [`Workspace::finish`] moves the fields into the [`Solution`] (no copy
//!    at the peak of memory use) and keeps the pressure for the next warm
//!    start.
//!
//! A gap-based loop (e.g. the adhesive Polonsky–Keer of Rey, Anciaux &
//! Molinari, Comput. Mech. 60, 69 (2017), doi:10.1007/s00466-017-1392-5)
//! holds the gap in `gap`, its search direction in `direction`, the pressure
//! response `𝒦t` in `response`, and the pressure in `pressure`; it reads
//! `h − o`, σ_h and the control from the [`Problem`].
//!
//! # Memory
//! Four fields of N² values (the operator's buffers are counted in
//! [`super::required_bytes`]); nothing is allocated per iteration.

use super::kernel::Operator;
use super::problem::{Control, Problem};
use super::solution::Solution;
use crate::error::Result;

/// The operator and the fields of a contact solve.
#[derive(Debug)]
pub struct Workspace {
    op: Operator,
    pressure: Vec<f64>,
    gap: Vec<f64>,
    direction: Vec<f64>,
    response: Vec<f64>,
    sparse_idx: Vec<usize>,
    sparse_val: Vec<f64>,
    /// `pressure` holds the last solution (for warm starts).
    warm: bool,
}

/// The operator and the fields, lent together (see [`Workspace::fields`]).
#[derive(Debug)]
#[non_exhaustive]
pub struct Fields<'a> {
    /// The compliance operator 𝒢 (and the stiffness 𝒦).
    pub op: &'a mut Operator,
    /// Nodal pressures p (unit of E*).
    pub pressure: &'a mut [f64],
    /// Gap g (unit of L).
    pub gap: &'a mut [f64],
    /// Search direction t.
    pub direction: &'a mut [f64],
    /// Response of the operator to the direction (or scratch).
    pub response: &'a mut [f64],
    /// Flat indices of a sparse correction.
    pub sparse_idx: &'a mut Vec<usize>,
    /// Values of a sparse correction.
    pub sparse_val: &'a mut Vec<f64>,
}

impl Workspace {
    /// The workspace of the operator's grid (4 N² values).
    pub(crate) fn new(op: Operator) -> Self {
        let n2 = op.n() * op.n();
        Workspace {
            op,
            pressure: vec![0.0; n2],
            gap: vec![0.0; n2],
            direction: vec![0.0; n2],
            response: vec![0.0; n2],
            sparse_idx: Vec::with_capacity(sparse_limit(n2)),
            sparse_val: Vec::with_capacity(sparse_limit(n2)),
            warm: false,
        }
    }

    /// The compliance operator.
    pub(crate) fn operator(&mut self) -> &mut Operator {
        &mut self.op
    }

    /// Whether `pressure` holds a previous solution.
    pub fn is_warm(&self) -> bool {
        self.warm
    }

    /// Forget the previous solution (the next start is cold).
    pub(crate) fn forget(&mut self) {
        self.warm = false;
    }

    /// The operator and all fields (reallocating those a previous
    /// [`Workspace::finish`] moved out).
    pub fn fields(&mut self) -> Fields<'_> {
        let n2 = self.op.n() * self.op.n();
        for buf in [
            &mut self.pressure,
            &mut self.gap,
            &mut self.direction,
            &mut self.response,
        ] {
            if buf.len() != n2 {
                *buf = vec![0.0; n2];
            }
        }
        Fields {
            op: &mut self.op,
            pressure: &mut self.pressure,
            gap: &mut self.gap,
            direction: &mut self.direction,
            response: &mut self.response,
            sparse_idx: &mut self.sparse_idx,
            sparse_val: &mut self.sparse_val,
        }
    }

    /// Write the starting pressure: cold, `p̄` everywhere (load control) or
    /// the overlap times [`Problem::stiffness`] (penetration control); warm
    /// (when the workspace holds a previous solution), that solution as
    /// [`Start`] says. The workspace is cold afterwards until
    /// [`Workspace::finish`].
    ///
    /// # Errors
    /// None in practice ([`Start::Predicted`]'s FFT has sizes computed here;
    /// a failure would be a bug and panics: `bem::fft`).
    pub fn start(&mut self, problem: &Problem, start: Start) -> Result<()> {
        let start = if self.warm { start } else { Start::Cold };
        self.warm = false;
        let f = self.fields();
        match (problem.control(), start) {
            (Control::MeanPressure(pm), Start::Cold) => f.pressure.fill(pm),
            (Control::MeanPressure(pm), Start::Rescaled) => {
                let mean = f.pressure.iter().sum::<f64>() / f.pressure.len() as f64;
                if mean > 0.0 {
                    let s = pm / mean;
                    f.pressure.iter_mut().for_each(|v| *v *= s);
                } else {
                    f.pressure.fill(pm);
                }
            }
            (Control::MeanPressure(pm), Start::Predicted) => predict(f, pm)?,
            (Control::Penetration(delta), Start::Cold) => {
                let (stiffness, h_max) = (problem.stiffness(), problem.h_max());
                for (p, h) in f.pressure.iter_mut().zip(problem.heights()) {
                    *p = stiffness * (h - h_max + delta).max(0.0);
                }
            }
            // The previous pressure as it is.
            (Control::Penetration(_), _) => {}
        }
        Ok(())
    }

    /// Continue from the pressure in the workspace (a loop handing over to
    /// another, e.g. a fallback): rescaled to the load, not reset.
    pub(crate) fn resume(&mut self, problem: &Problem) {
        self.warm = true;
        // A rescaling needs no transform: it cannot fail.
        let _ = self.start(problem, Start::Rescaled);
    }

    /// Move the fields into a [`Solution`]: `pressure` as it is, `gap`
    /// shifted by `gap_shift` (the contact level under load control), and the
    /// displacement `u = g + (h − o)` (the gap must be fresh: computed from
    /// `𝒢p`). The pressure stays in the workspace for a warm start.
    pub fn finish(&mut self, problem: &Problem, done: Finish) -> Solution {
        let n2 = problem.nodes();
        let offset = problem.offset();
        let mut gap = std::mem::take(&mut self.gap);
        let mut displacement = std::mem::take(&mut self.response);
        match done.displacement {
            Displacement::FromGap => {
                for ((u, g), h) in displacement
                    .iter_mut()
                    .zip(gap.iter_mut())
                    .zip(problem.heights())
                {
                    *u = *g + (h - offset);
                    *g -= done.gap_shift;
                }
            }
            Displacement::InResponse => gap.iter_mut().for_each(|g| *g -= done.gap_shift),
        }
        // The pressure moves out too; a copy stays (in the no longer needed
        // direction buffer) for warm starts.
        let pressure = std::mem::take(&mut self.pressure);
        self.pressure = std::mem::take(&mut self.direction);
        self.pressure.copy_from_slice(&pressure);
        self.warm = true;
        let mean_pressure = pressure.iter().sum::<f64>() / n2 as f64;
        let frac = |k: usize| k as f64 / n2 as f64;
        Solution {
            pressure,
            gap,
            displacement,
            mean_pressure,
            approach: done.approach,
            contact_fraction: frac(done.contact),
            elastic_fraction: frac(done.contact - done.plastic),
            plastic_fraction: frac(done.plastic),
            plastic_displacement_mean: done.plastic_displacement_mean,
            plastic_displacement_max: done.plastic_displacement_max,
            iterations: done.iterations,
            residual: done.residual,
            seconds: done.seconds,
            fallback: None,
        }
    }

    /// Mark the pressure field as a solution (for a loop that built its
    /// [`Solution`] itself and copied the pressure back).
    pub(crate) fn set_warm(&mut self) {
        self.warm = true;
    }
}

/// How a warm start uses the previous solution (a cold start ignores it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Start {
    /// `p̄` everywhere (load control) or the overlap times the stiffness
    /// guess (penetration control).
    Cold,
    /// The previous pressure times `p̄_new / p̄_old`.
    Rescaled,
    /// The previous pressure plus a uniform approach increment on its
    /// contact set, predicted by the stiffness (see `predict`); under
    /// penetration control the previous pressure.
    Predicted,
}

/// Largest load ratio `p̄_new/p̄_old` (or its inverse) at which
/// [`Start::Predicted`] uses the previous solution; beyond it the start is
/// cold. Measured on the rough case (256², six loads from 0.005 E*, tol
/// 1e-10, iterations of the last five solves, predicted / cold): 116 / 153
/// at ratio 1.05, 146 / 167 at 1.2, 199 / 175 at 1.5 (rescaled: 132, 180, 198).
const PREDICT_RATIO: f64 = 1.3;

/// The load-path predictor: a uniform increment Δδ of the approach on the
/// previous contact set C raises its pressure by Δδ·𝒜⁻¹1_C, where 𝒜 is 𝒢
/// restricted to C; 𝒜⁻¹ is replaced by the stiffness restricted to C (the
/// preconditioner of [`super::preconditioned`]), and Δδ is set by the load.
///
/// # Formula
/// ```text
/// w = [C] 𝒦 1_C,   c = (N² p̄_new − Σ p_old) / Σ w,   p = max(p_old + c w, 0) · N² p̄_new / Σ(…)
/// ```
/// Rescaling `p_old` instead ([`Start::Rescaled`]) keeps the contact set and
/// overloads it: for the preconditioned solver it saves less, and beyond a
/// load ratio of 1.2 it costs more than a cold start (see [`PREDICT_RATIO`]).
fn predict(f: Fields<'_>, pm: f64) -> Result<()> {
    let n = f.op.n();
    let total = pm * f.pressure.len() as f64;
    let sum_p: f64 = f.pressure.iter().sum();
    let ratio = total / sum_p;
    if !(sum_p > 0.0 && (1.0 / PREDICT_RATIO..=PREDICT_RATIO).contains(&ratio)) {
        f.pressure.fill(pm);
        return Ok(());
    }
    let (p, w) = (&*f.pressure, &mut *f.direction);
    let mean = f.op.fundamental_stiffness();
    let mut sum_w = 0.0;
    f.op.apply_stiffness_rows_with_mean(
        mean,
        &mut |i, row| {
            for (x, &pk) in row.iter_mut().zip(&p[i * n..(i + 1) * n]) {
                *x = if pk > 0.0 { 1.0 } else { 0.0 };
            }
        },
        &mut |i, row| {
            let k = i * n..(i + 1) * n;
            for ((wk, &x), &pk) in w[k.clone()].iter_mut().zip(row).zip(&p[k]) {
                *wk = if pk > 0.0 { x } else { 0.0 };
                sum_w += *wk;
            }
        },
    )?;
    // NaN (no contact weight) falls back too.
    if sum_w.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        f.pressure.fill(pm);
        return Ok(());
    }
    let c = (total - sum_p) / sum_w;
    let mut sum = 0.0;
    for (pk, &wk) in f.pressure.iter_mut().zip(&*w) {
        *pk = (*pk + c * wk).max(0.0);
        sum += *pk;
    }
    if sum > 0.0 {
        let s = total / sum;
        f.pressure.iter_mut().for_each(|v| *v *= s);
    } else {
        f.pressure.fill(pm);
    }
    Ok(())
}

/// What a loop knows at convergence, for [`Workspace::finish`].
#[derive(Debug, Clone, Copy, Default)]
#[non_exhaustive]
pub struct Finish {
    /// Subtracted from the gap (its level on the contact under load control).
    pub gap_shift: f64,
    /// Approach δ (unit of L).
    pub approach: f64,
    /// Nodes with p > 0.
    pub contact: usize,
    /// Nodes at p = σY.
    pub plastic: usize,
    /// Mean interpenetration over the plastic nodes.
    pub plastic_displacement_mean: f64,
    /// Largest interpenetration.
    pub plastic_displacement_max: f64,
    /// Iterations used.
    pub iterations: usize,
    /// Final ε.
    pub residual: f64,
    /// Wall time, s.
    pub seconds: f64,
    /// Where the displacement `u = 𝒢p` is.
    pub displacement: Displacement,
}

/// Where [`Workspace::finish`] finds the displacement.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Displacement {
    /// Rebuilt from the (fresh) gap: `u = g + (h − o)`.
    #[default]
    FromGap,
    /// Already in `response` (the loop computed `𝒢p` there last).
    InResponse,
}

impl Finish {
    /// An elastic loop's finish.
    pub(crate) fn elastic(
        gap_shift: f64,
        approach: f64,
        contact: usize,
        iterations: usize,
        residual: f64,
    ) -> Self {
        Finish {
            gap_shift,
            approach,
            contact,
            iterations,
            residual,
            ..Finish::default()
        }
    }
}

/// Most nodes whose step is corrected by direct summation rather than by
/// recomputing `𝒢p` with two FFTs: log₂(N²) (18 at 512², 20 at 1024²). One
/// node costs N² multiply-adds against the FFT's ~N² log₂(N²). Best of 2–3
/// rough solves (`persson bem rough`, H = 0.8, tol 1e-10) with ½×, 1× and
/// 1.5× log₂(N²): 0.876 / 0.850 / 0.868 s at 512², 7.82 / 7.26 / 7.33 s at
/// 1024².
pub(crate) fn sparse_limit(n2: usize) -> usize {
    n2.max(2).ilog2() as usize
}

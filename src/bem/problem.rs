//! The set-up of a contact solve, built once and read by every loop: the
//! rigid heights, what is prescribed (load or approach), the gap offset and
//! the height statistics of the stopping rule; with the accuracy knobs
//! ([`Options`]) and the choice of method ([`Method`]).
//!
//! # Formula
//! ```text
//! gap            g = 𝒢p − (h − o)            o = max h − δ   (offset)
//! mean pressure  p̄ = Σp / N²                 (load control: fixed, δ free)
//! stopping rule  σ_h = sqrt(Σ (h_i − h̄)² / (N² − 1))
//! ```
//! `h − o` is always formed first: it is the size of the roughness, so a
//! large mean height costs no digits in the gap.
//!
//! The pressure-based loops ([`super::polonsky_keer`], [`super::preconditioned`],
//! [`super::saturated`]) take a `&Problem` and a `&mut` [`super::Workspace`]:
//! the problem is never written, the workspace holds every buffer. The
//! gap-based adhesive loops ([`super::adhesive`]) read the same validated
//! heights and their statistics (`Heights`, built once per solve), but not
//! the rest: their unknown is the gap on a grid padded to 2N on the free
//! boundary, prescribed by a mean gap or a signed approach that no
//! pressure loop accepts, and they keep their buffers in the
//! [`super::adhesive::AdhesiveSolver`].

use super::kernel::{Boundary, Operator};
use crate::error::{check, Error, Result};

/// What is prescribed: the mean pressure or the penetration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Control {
    /// Nominal mean pressure p̄ = load / L² (same unit as E*), > 0.
    MeanPressure(f64),
    /// Approach δ from first touch (unit of L), ≥ 0.
    Penetration(f64),
}

/// Accuracy knobs of the solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Relative tolerance on ε (see [`super::solver`]), in `[1e-15, 0.1]`.
    pub tolerance: f64,
    /// Maximum number of CG iterations.
    pub max_iterations: usize,
    /// Start from the previous solution (rescaled to the new load) when the
    /// workspace holds one: speeds up load sweeps (see also
    /// [`super::LoadPath`], which always does).
    pub warm_start: bool,
    /// Yield stress σY (hardness, unit of E*): pressures are bounded by
    /// `0 ≤ p ≤ σY` (the saturated problem, see [`super::saturated`]).
    /// `None`: the elastic problem, solved exactly as without this field.
    pub yield_stress: Option<f64>,
}

impl Default for Options {
    /// `tolerance = 1e-10`, `max_iterations = 10 000`, no warm start, no yield stress.
    fn default() -> Self {
        Options {
            tolerance: 1e-10,
            max_iterations: 10_000,
            warm_start: false,
            yield_stress: None,
        }
    }
}

/// Which constrained conjugate gradient solves the problem. Both stop on
/// the same ε (see [`super::solver`]), so equal tolerances give equal
/// answers to the tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Method {
    /// Polonsky & Keer (1999): iterations grow with the
    /// grid (~√N: 217 at 512², 323 at 1024² on the rough case at σ0 = 0.005 E*).
    Plain,
    /// Preconditioned by the half-space stiffness 𝒦 = E*|q|/2 restricted to
    /// the free set ([`super::preconditioned`]). Falls back to [`Method::Plain`]
    /// (flagged in [`super::Solution::fallback`]) when ε has not halved within
    /// `stall_iterations` iterations.
    Preconditioned {
        /// Window of the stall test, ≥ 1 (default [`Method::STALL_ITERATIONS`]).
        stall_iterations: usize,
    },
}

impl Method {
    /// Default stall window of [`Method::Preconditioned`]: the rough case
    /// drops ε by ~10⁻⁴ in 30 iterations (rate ~0.65 per iteration), so a
    /// factor 2 in 30 is missed only by a stalled iteration.
    pub const STALL_ITERATIONS: usize = 30;

    /// The preconditioned method with the default stall window.
    pub const PRECONDITIONED: Method = Method::Preconditioned {
        stall_iterations: Method::STALL_ITERATIONS,
    };
}

impl Default for Method {
    /// [`Method::PRECONDITIONED`].
    fn default() -> Self {
        Method::PRECONDITIONED
    }
}

/// The rigid heights of a solve, validated, with the statistics the loops
/// read: built once per surface by [`Heights::new`], for the pressure
/// loops inside a [`Problem`], for the adhesive ones on their own (their
/// control is a mean gap or a signed approach, [`super::adhesive`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Heights<'a> {
    values: &'a [f64],
    n: usize,
    h_max: f64,
    h_min: f64,
    h_mean: f64,
    sigma_h: f64,
    /// rms of the heights' forward differences over L/N (both directions,
    /// wrapping around): the slope that sets the pressure scale E* h'_rms.
    slope_rms: f64,
}

impl<'a> Heights<'a> {
    /// The rigid surface `values` (`N × N` row-major, unit of L) on the
    /// grid of `op`.
    ///
    /// # Errors
    /// Heights of the wrong length (named `heights`) or not finite (named
    /// by their node).
    pub(crate) fn new(values: &'a [f64], op: &Operator) -> Result<Self> {
        let n = op.n();
        let n2 = n * n;
        if values.len() != n2 {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!("N² = {n2} values, got {}", values.len()),
            });
        }
        if let Some(k) = values.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid(
                format!("height[{}, {}]", k / n, k % n),
                values[k],
                "finite",
            ));
        }
        let (h_min, h_max) = values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| {
                (lo.min(h), hi.max(h))
            });
        let h_mean = values.iter().sum::<f64>() / n2 as f64;
        let sigma_h =
            (values.iter().map(|h| (h - h_mean).powi(2)).sum::<f64>() / (n2 as f64 - 1.0)).sqrt();
        let dx = op.size() / n as f64;
        let mut s2 = 0.0;
        for j in 0..n {
            for i in 0..n {
                let h = values[j * n + i];
                let (gx, gy) = (
                    (values[j * n + (i + 1) % n] - h) / dx,
                    (values[((j + 1) % n) * n + i] - h) / dx,
                );
                s2 += gx * gx + gy * gy;
            }
        }
        Ok(Heights {
            values,
            n,
            h_max,
            h_min,
            h_mean,
            sigma_h,
            slope_rms: (s2 / n2 as f64).sqrt(),
        })
    }

    /// The heights `h` (unit of L).
    pub(crate) fn values(&self) -> &'a [f64] {
        self.values
    }

    /// Highest height `max h`.
    pub(crate) fn max(&self) -> f64 {
        self.h_max
    }

    /// Lowest height `min h`.
    pub(crate) fn min(&self) -> f64 {
        self.h_min
    }

    /// Mean height `h̄`.
    pub(crate) fn mean(&self) -> f64 {
        self.h_mean
    }
}

/// The set-up of one solve: heights, control and their derived values.
///
/// Built once per surface and load by [`Problem::new`] (which validates
/// them); [`Problem::with_control`] reuses the height statistics for another
/// load of the same surface (load paths).
#[derive(Debug, Clone, Copy)]
pub struct Problem<'a> {
    heights: Heights<'a>,
    size: f64,
    e_star: f64,
    boundary: Boundary,
    control: Control,
}

impl<'a> Problem<'a> {
    /// The problem of the rigid surface `heights` (`N × N` row-major, unit of
    /// L) on the grid of `op`, under `control`.
    ///
    /// # Errors
    /// Heights of the wrong length or not finite; a mean pressure not finite
    /// and > 0; a penetration not finite and ≥ 0, or (periodic) at least
    /// `max h − mean h` (full contact needs an infinite load).
    pub fn new(heights: &'a [f64], op: &Operator, control: Control) -> Result<Self> {
        let problem = Problem {
            heights: Heights::new(heights, op)?,
            size: op.size(),
            e_star: op.e_star(),
            boundary: op.boundary(),
            control,
        };
        problem.with_control(control)
    }

    /// The same surface under another control (the height statistics are
    /// reused).
    ///
    /// # Errors
    /// As [`Problem::new`] for the control.
    pub fn with_control(&self, control: Control) -> Result<Self> {
        match control {
            Control::MeanPressure(pm) => {
                check::positive("pressure", pm)?;
            }
            Control::Penetration(d) => {
                check::non_negative("penetration", d)?;
                let room = self.heights.h_max - self.heights.h_mean;
                if self.boundary == Boundary::Periodic && d >= room {
                    return Err(Error::invalid(
                        "penetration",
                        d,
                        format!(
                            "below max(h) − mean(h) = {room:e} in a periodic system (full contact needs infinite load)"
                        ),
                    ));
                }
            }
        }
        Ok(Problem { control, ..*self })
    }

    /// Refuse a mean pressure whose rounding alone exceeds the tolerance:
    /// the solver then iterates to its cap ("did not converge: 10000
    /// iterations, residual 2.67" at p̄ = 1e300, E* = 1e9).
    ///
    /// # Bound
    /// The relative residual ε_r compares the pressure's deviations, of
    /// order E* h'_rms (the pressure that flattens slopes h'_rms), with p̄
    /// itself; p̄ carries a rounding ε p̄, so the residual cannot fall below
    /// about ε p̄/(E* h'_rms) (measured on a self-affine surface at 32²:
    /// 3e-12 at p̄ = 1e12, 5e-10 at 1e14 with E* h'_rms = 1e8). It reaches
    /// `tolerance` τ only while, with a factor 8 of room,
    /// ```text
    /// p̄ ≤ τ E* h'_rms/(8ε)
    /// ```
    /// A flat surface (h'_rms = 0) is uniform pressure and is not refused.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `nominal_pressure`, or
    /// `contact_modulus` when E* is beyond 1e±30.
    pub(crate) fn check_round_off(&self, tolerance: f64) -> Result<()> {
        let Control::MeanPressure(pm) = self.control else {
            return Ok(());
        };
        let slope_rms = self.heights.slope_rms;
        let scale = self.e_star * slope_rms;
        let bound = tolerance * scale / (8.0 * f64::EPSILON);
        if slope_rms == 0.0 || pm <= bound {
            return Ok(());
        }
        let approx = crate::error::approx;
        let why = format!(
            "so that its rounding ε p̄ stays below the tolerance {} of the pressure scale \
             E* h'_rms = {} (h'_rms = {} on the grid): far above full contact",
            crate::error::num(tolerance),
            approx(scale),
            approx(slope_rms)
        );
        Err(match crate::error::ratio_culprit(self.e_star, pm) {
            "contact_modulus" => Error::invalid(
                "contact_modulus",
                self.e_star,
                format!(
                    "at least {} (p̄ = {}) {why}",
                    approx(pm * 8.0 * f64::EPSILON / (tolerance * slope_rms)),
                    crate::error::num(pm)
                ),
            ),
            _ => Error::invalid(
                "nominal_pressure",
                pm,
                format!(
                    "at most {} (E* = {}) {why}",
                    approx(bound),
                    crate::error::num(self.e_star)
                ),
            ),
        })
    }

    /// The rigid heights `h` (unit of L).
    pub(crate) fn heights(&self) -> &'a [f64] {
        self.heights.values
    }

    /// Grid side N.
    pub fn n(&self) -> usize {
        self.heights.n
    }

    /// Number of nodes N².
    pub(crate) fn nodes(&self) -> usize {
        self.heights.n * self.heights.n
    }

    /// Boundary condition of the half-space.
    pub fn boundary(&self) -> Boundary {
        self.boundary
    }

    /// What is prescribed.
    pub(crate) fn control(&self) -> Control {
        self.control
    }

    /// The prescribed total `N² p̄` under load control (`None` under
    /// penetration control).
    pub(crate) fn target_total(&self) -> Option<f64> {
        match self.control {
            Control::MeanPressure(pm) => Some(pm * self.nodes() as f64),
            Control::Penetration(_) => None,
        }
    }

    /// The prescribed mean pressure p̄ (`None` under penetration control).
    pub(crate) fn target_mean(&self) -> Option<f64> {
        match self.control {
            Control::MeanPressure(pm) => Some(pm),
            Control::Penetration(_) => None,
        }
    }

    /// The approach δ: the prescribed one, 0 under load control (whose gap
    /// is shifted by its contact level instead).
    pub(crate) fn penetration(&self) -> f64 {
        match self.control {
            Control::MeanPressure(_) => 0.0,
            Control::Penetration(d) => d,
        }
    }

    /// Gap offset `o = max h − δ`: the gap is `g = 𝒢p − (h − o)`.
    pub(crate) fn offset(&self) -> f64 {
        self.heights.h_max - self.penetration()
    }

    /// Highest height `max h`.
    pub(crate) fn h_max(&self) -> f64 {
        self.heights.h_max
    }

    /// Mean height `h̄`.
    pub fn h_mean(&self) -> f64 {
        self.heights.h_mean
    }

    /// Standard deviation of the heights σ_h (the scale of ε).
    pub(crate) fn sigma_h(&self) -> f64 {
        self.heights.sigma_h
    }

    /// A flat surface (σ_h = 0): no iteration is needed.
    pub(crate) fn is_flat(&self) -> bool {
        self.heights.sigma_h == 0.0
    }

    /// A stiffness guess `E* π N / L` (pressure per unit overlap, the order
    /// of a node's self-stiffness) for starting points and degenerate steps.
    pub fn stiffness(&self) -> f64 {
        self.e_star * std::f64::consts::PI * self.heights.n as f64 / self.size
    }

    /// Contact modulus E*.
    pub fn e_star(&self) -> f64 {
        self.e_star
    }

    /// Side L of the grid.
    pub fn size(&self) -> f64 {
        self.size
    }
}

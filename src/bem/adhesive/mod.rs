//! Adhesive FFT-BEM: a rigid rough surface and an elastic half-space that
//! attract each other through a cohesive law of the gap, under mean-gap
//! (periodic) or approach control (periodic or free boundary), so that the whole force–separation curve, tension included, is
//! reachable; and a loading–unloading sequence with its pull-off.
//!
//! # What it solves
//! The gap g ≥ 0 is the unknown (the gap-based Polonsky–Keer formulation of
//! Rey, Anciaux & Molinari 2017). With the periodic half-space stiffness 𝒦
//! (p̂ = E*|q|û/2, p̂(0) = 0) and the displacement u = g + h (up to a rigid
//! shift, which a periodic cell does not resist):
//! ```text
//! Π(g)  = ½ ⟨g + h, 𝒦 (g + h)⟩ + Σ_i W(g_i) ΔA         minimised over g ≥ 0, mean(g) = ḡ
//! W(g)  = −Δγ (1 − g/ρ)  for g < ρ, 0 beyond            Maugis–Dugdale: attraction Δγ/ρ within ρ
//! W(g)  = −Δγ e^{−g/ρ}                                  exponential: attraction (Δγ/ρ) e^{−g/ρ}
//! r_i   = [𝒦(g + h)]_i + W′(g_i) + p̄,   p̄ = −mean_{g>0}(𝒦(g + h) + W′(g))
//! KKT:  r_i = 0 where g_i > 0,   r_i ≥ 0 where g_i = 0
//! p     = 𝒦(g + h) + p̄   (compression positive; −W′(g) in the gaps),  mean pressure = p̄
//! ```
//! W(0) = −Δγ: the work of adhesion is the energy per area to separate
//! surfaces in contact. Units: g, h, ρ in the unit of L; Δγ in (unit of
//! E*)·(unit of L); pressures in the unit of E*.
//!
//! # Method
//! Conjugate gradients on the free set g > 0 with the search direction
//! centred (so the step keeps the mean gap), the step length of the
//! quadratic model ⟨t, 𝒦t⟩ (the curvature of W is left out, as in the
//! reference algorithm), truncation at g = 0, re-entry of contact nodes that
//! pull (r < 0) with a restart of the conjugacy, and the mean gap restored
//! by scaling g (which keeps the contact set). The Maugis–Dugdale energy is
//! not convex (its attraction drops to 0 at g = ρ): the iteration finds a
//! stationary point near its start, which is what a quasi-static sequence
//! wants (warm starts from the previous mean gap give the hysteresis).
//!
//! # Preconditioned iteration
//! [`Method::Preconditioned`] (the default for the exponential law, see
//! [`AdhesiveSolver::method_for`]) preconditions the same iteration by the
//! compliance 𝒢 = 𝒦⁻¹ restricted to the free set, the counterpart of the
//! elastic solver's stiffness preconditioner ([`super::preconditioned`]) for
//! a gap primal:
//! ```text
//! F  = {g > 0} ∪ {g = 0, r < 0}                      (contact nodes that pull are free)
//! z  = [F] 𝒢 [F] r,   t = [F](z + β t_old − μ),   β = max(⟨r − r_old, z⟩/⟨r_old, z_old⟩, 0)
//! μ  = mean of z + β t_old over F  (Σ t = 0 keeps ḡ);  t = 0 at a contact node where t > 0
//! τ  = ⟨r, t⟩ / max(⟨t, 𝒦t⟩ + Σ_{g>0} W″(g) t², ⟨t, 𝒦t⟩/4),   g ← max(g − τ t, 0),   g scaled to ḡ
//! ```
//! β is Polak–Ribière's (Polak & Ribière 1969), kept ≥ 0, the nonlinear
//! conjugate gradient's choice for a non-quadratic energy: it equals
//! Fletcher–Reeves' on a quadratic with exact steps and restarts by itself
//! where the gradient turns. The step is the quadratic model's with the
//! law's curvature W″ (exponential: −W′/ρ, taken from r + p̄ − 𝒦(g + h)
//! without a second exponential; Maugis–Dugdale: 0), capped at 4× the
//! step of 𝒦 alone; it is used only where the cohesive zone is resolved,
//! Δγ/ρ² below a node's stiffness E*πN/(2L) (else the longer steps reach
//! other stationary points: the λ = 3 sphere at N = 64). Measured on the
//! 256² and 512² surfaces of examples/adhesive_tamaas.rs: 83 and
//! 153 iterations with Fletcher–Reeves and the step of 𝒦, 60 and 37 with
//! Polak–Ribière, 28 and 25 with both; the answers equal to 1e-14.
//! The conjugacy restarts (β = 0) when a node crosses g = ρ (Maugis–Dugdale)
//! or the direction does not descend. Two convolutions per iteration (𝒢r,
//! 𝒦t): 𝒦(g + h) is updated as s(𝒦(g + h) − τ𝒦t − 𝒦h) + 𝒦h (s the
//! scaling to ḡ) and transformed afresh only when a node closes, every 20
//! steps and to confirm convergence; the plain loop takes three (𝒦(g + h),
//! 𝒦t and the re-entry test). The element-wise work is four passes over
//! the fields per iteration: centring r with ε's numerator; t = z + βt − μ
//! with ⟨r, t⟩ (⟨r, z⟩ and the sums for μ ride on the emit of 𝒢r, ⟨t, 𝒦t⟩
//! on the emit of 𝒦t); the gap step with its mean; the scaling, the update
//! of 𝒦(g + h) and the new r with ε's denominator and p̄. Measured (exponential law, N = 64, tests/bem_adhesive.rs): 5.5–40×
//! fewer iterations along loading–unloading paths; on the 256² and 512²
//! self-affine surfaces of examples/adhesive_tamaas.rs see docs/adhesion.md.
//!
//! **Stall and fallback.** Where the cohesive zone is not resolved by the
//! grid (|W″| = Δγ/ρ² above a node's stiffness ~E*πN/(2L), e.g. the sphere
//! at Maugis parameter λ = 3 on 64²) the curvature is left out of the step
//! and the long preconditioned steps may overshoot so that ε stops falling
//! (11 of that path's 62 points did with Fletcher–Reeves' β, none with
//! Polak–Ribière's). When the best
//! ε has not halved within `stall_iterations` iterations (the stall test of
//! [`super::preconditioned`]), or no descent direction or step is found, the
//! plain iteration goes on from the current gap to the same tolerance, and
//! the point carries [`AdhesivePoint::fallback`] (the sequence counts them in
//! [`AdhesiveSequence::fallbacks`]).
//!
//! **Which stationary point.** The exponential law's discrete energy has one
//! stationary point near a warm start where the cohesive zone is resolved:
//! the preconditioned and the plain iteration agree to the tolerance (1e-8
//! of the pull-off along the tests' paths, the unresolved sphere included).
//! The Maugis–Dugdale energy has many (a node at g = ρ is bistable): on 10–15 %
//! of a sphere path's points the two iterations settle on different ones
//! (pull-off 7–11 % apart at λ = 1 and 3, N = 64), so Maugis–Dugdale keeps
//! the plain iteration unless the preconditioned one is asked for. So does
//! an exponential law with an unresolved cohesive zone on a rough surface
//! (measured on the cosine surface with ρ = 1e-3 at N = 64).
//!
//! # Free boundary
//! On a [`Boundary::Free`] operator the iteration runs on the zero-padded
//! 2N × 2N grid with the circulant C of Love's cell kernel (the DC-FFT
//! matrix of [`super::kernel`]) and its exact inverse:
//! ```text
//! unknown  x = g on the N × N surface, x = u on the padding
//! u        = g + h − o on the surface,  o = max h − δ  (approach δ from first touch)
//! Π(x)     = ½ ⟨u, C⁻¹ u⟩ + Σ_surface W(g)            minimised over g ≥ 0
//! r        = C⁻¹u + W′(g) on the surface, C⁻¹u on the padding;   no multiplier
//! ```
//! The padding carries displacement but no pressure (r = 0 there is p = 0),
//! so the surface's pressures give u = 𝒢p with the free operator's
//! window block exactly, whatever C is outside it. Approach control only
//! ([`AdhesiveSolver::solve_approach`]): the half-space far away is at rest,
//! so the rigid shift is resisted and δ is the natural control; it reaches
//! the tensile branch as mean-gap control does. The preconditioner is C.
//! Memory: seven fields of 4N² values (the gap, r, t, z or 𝒦t, 𝒦(g + h), 𝒦h and
//! the last r) and the padded transform.
//!
//! # Stopping rule
//! ```text
//! ε = ( Σ_{g>0} r_i² + Σ_{g=0} min(r_i, 0)² )^{1/2}
//!     / ( Σ_i [𝒦(g + h)]_i² + Σ_i W′(g_i)² + N² p̄² )^{1/2} ≤ tolerance
//! ```
//! (the relative residual of the KKT conditions; the padding's nodes count
//! as free nodes on the free boundary); a solve that reaches
//! `max_iterations` first returns its point with `converged = false`.
//!
//! A solve also stops when the residual's numerator is at the round-off of
//! computing 𝒦(g + h): `Σ r² ≤ (ε_mach · E*π√2 N/L · log₂ M²)² Σ (g + h)²`
//! (the largest symbol of 𝒦 times the input, M² the grid's nodes). Far out of
//! contact under the exponential law the force is ~e^{−g/ρ} and both sums
//! of ε shrink with it, while the numerator cannot fall below the round-off
//! of subtracting 𝒦h's O(1) pressures: without this floor, those points
//! (21 of 62 on the λ = 3 sphere path of the tests) would run to
//! `max_iterations` with either iteration. The floor lies far below
//! tolerance × scale wherever the force is within ~1e-5 of the contact
//! pressures.
//!
//! A detached state, where no node touches or attracts (Maugis–Dugdale with
//! every gap ≥ ρ, or Δγ = 0 out of contact), has no force at all: its
//! residual and its scale are both round-off, so ε is 0/0 and the iteration
//! cannot stop. Its exact solution is the rigid gap shifted to ḡ (𝒦 of a
//! constant is 0, p̄ = 0); the solver returns it (0 iterations) whenever the
//! iterate is detached and that rigid gap is detached too, so that these
//! Maugis–Dugdale solves end.
//!
//! # References
//! - L. Rey, G. Anciaux, J.-F. Molinari, *Normal adhesive contact on rough
//!   surfaces: efficient algorithm for FFT-based BEM resolution*, Comput.
//!   Mech. 60, 69 (2017), doi:10.1007/s00466-017-1392-5.
//! - I. A. Polonsky, L. M. Keer, Wear 231, 206 (1999), doi:10.1016/S0043-1648(99)00113-1.
//! - D. Maugis, J. Colloid Interface Sci. 150, 243 (1992), doi:10.1016/0021-9797(92)90285-T.
//! - E. Polak, G. Ribière, Rev. Fr. Inform. Rech. Opér. 3(16), 35 (1969),
//!   doi:10.1051/m2an/196903R100351.

mod checks;
mod gap;
mod law;
mod path;
mod pcg;
mod plain;

pub use crate::names::LawKind;
pub use law::{CohesiveLaw, MAX_PEAK_ATTRACTION, RESOLVED_COHESIVE_LENGTH};
pub use path::PathControl;

use super::kernel::{Boundary, Operator, Padded};
use super::problem::{Heights, Method};
use super::solution::Fallback;
use crate::error::{check, Error, Result};

/// Accuracy knobs of the adhesive solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesiveOptions {
    /// Relative KKT residual ε to reach, in [1e-15, 0.1].
    pub tolerance: f64,
    /// Iterations allowed per solve.
    pub max_iterations: usize,
}

impl Default for AdhesiveOptions {
    /// tolerance 1e-8, 20 000 iterations.
    fn default() -> Self {
        AdhesiveOptions {
            tolerance: 1e-8,
            max_iterations: 20_000,
        }
    }
}

/// One solved mean gap (or approach).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct AdhesivePoint {
    /// ḡ, the mean gap over the grid (unit of L): the prescribed one under
    /// mean-gap control. Serialised as `mean_separation` (ū, the names table).
    #[serde(rename = "mean_separation")]
    pub mean_gap: f64,
    /// p̄, the mean pressure over the grid (unit of E*; negative in tension).
    /// On the free boundary, the force over L². Serialised as
    /// `nominal_pressure` (σ0, the names table).
    #[serde(rename = "nominal_pressure")]
    pub mean_pressure: f64,
    /// Fraction of nodes in repulsive contact (g = 0).
    pub contact_fraction: f64,
    /// Fraction of nodes inside the cohesive zone (0 < g < ρ).
    pub cohesive_fraction: f64,
    /// Iterations of this solve (a fallback's included).
    pub iterations: usize,
    /// ε reached.
    pub residual: f64,
    /// ε ≤ tolerance.
    pub converged: bool,
    /// δ, the approach of the rigid surface from first touch (unit of L):
    /// the gap is g = u + max h − δ − h. The prescribed one under approach
    /// control; periodic, `max h − mean h − ḡ` (the mean displacement is 0).
    pub approach: f64,
    /// Set when the preconditioned iteration stalled and the plain one
    /// finished the solve (the answer is the plain iteration's, to the same
    /// tolerance): its iterations and ε when it was abandoned. The
    /// application layer turns this into a warning.
    pub fallback: Option<Fallback>,
}

/// What is prescribed in an adhesive solve.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Target {
    /// ḡ (periodic only).
    MeanGap(f64),
    /// δ (free boundary): the gap offset o = max h − δ.
    Approach(f64),
}

/// The grid the adhesive iteration works on: the N × N period, or (free
/// boundary) the zero-padded 2N × 2N grid whose first N rows and columns
/// are the surface.
#[derive(Debug, Clone, Copy)]
struct Layout {
    /// Side of the surface N.
    n: usize,
    /// Side of the iteration's grid (N periodic, 2N free).
    m: usize,
}

impl Layout {
    fn periodic(&self) -> bool {
        self.m == self.n
    }

    /// The surface node (index into the N × N heights) of grid node `k`.
    #[inline(always)]
    fn window(&self, k: usize) -> Option<usize> {
        if self.m == self.n {
            return Some(k);
        }
        let (i, j) = (k / self.m, k % self.m);
        (i < self.n && j < self.n).then_some(i * self.n + j)
    }
}

/// The operators of the iteration: the periodic 𝒦 and 𝒢 on N × N, or the
/// padded C⁻¹ and C on 2N × 2N.
#[derive(Debug)]
struct Ops {
    op: Operator,
    padded: Option<Padded>,
}

impl Ops {
    fn stiffness(&mut self, x: &[f64], y: &mut [f64]) -> Result<()> {
        match &mut self.padded {
            Some(p) => p.apply(true, x, y),
            None => self.op.apply_stiffness(x, y),
        }
    }

    /// y = 𝒦x row by row (as [`Operator::apply_rows`]; rows of the
    /// iteration's grid).
    fn stiffness_rows(
        &mut self,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        match &mut self.padded {
            Some(p) => p.apply_rows(true, fill, emit),
            None => self.op.apply_stiffness_rows(fill, emit),
        }
    }

    /// y = 𝒢x row by row (the compliance; C on the padded grid).
    fn compliance_rows(
        &mut self,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        match &mut self.padded {
            Some(p) => p.apply_rows(false, fill, emit),
            None => self.op.apply_rows(fill, emit),
        }
    }
}

/// How the preconditioned phase ended.
enum Phase {
    /// ε ≤ tolerance, or the detached answer: (p̄, iterations, ε).
    Done(f64, usize, f64),
    /// Stalled after this many iterations, at this ε: the plain loop goes on.
    Stalled(Fallback),
}

/// The adhesive solver: an operator and the buffers of one surface.
#[derive(Debug)]
pub struct AdhesiveSolver {
    ops: Ops,
    layout: Layout,
    /// `None`: by the law ([`AdhesiveSolver::method_for`]).
    method: Option<Method>,
    /// The unknown: the gap on the surface's nodes, the displacement u on
    /// the padding (free boundary).
    gap: Vec<f64>,
    grad: Vec<f64>,
    search: Vec<f64>,
    projected: Vec<f64>,
    work: Vec<f64>,
    /// 𝒦h (free: C⁻¹ of h − o on the surface), for the preconditioned
    /// iteration's update of 𝒦(g + h) without a transform.
    kh: Vec<f64>,
    /// The last iteration's r, centred on F (Polak–Ribière's β).
    previous: Vec<f64>,
    /// The surface's gap (free boundary; periodic: `gap` itself).
    window: Vec<f64>,
    /// The gap offset o of the last free-boundary solve.
    offset: f64,
    /// The last gradient's KKT residual is at the round-off of 𝒦(g + h).
    round_off: bool,
    warm: bool,
}

impl AdhesiveSolver {
    /// The solver on the operator `op`, periodic (mean-gap or approach
    /// control) or free (approach control: [`AdhesiveSolver::solve_approach`]),
    /// with the iteration chosen by the law ([`AdhesiveSolver::method_for`]).
    ///
    /// # Errors
    /// None in practice: the padded grid of a free operator has sizes computed
    /// here (an FFT failure would be a bug and panics: `bem::fft`).
    pub fn new(op: Operator) -> Result<Self> {
        let n = op.n();
        let padded = match op.boundary() {
            Boundary::Periodic => None,
            Boundary::Free => Some(Padded::new(n, op.size(), op.e_star())?),
        };
        let m = if padded.is_some() { 2 * n } else { n };
        let m2 = m * m;
        Ok(AdhesiveSolver {
            ops: Ops { op, padded },
            layout: Layout { n, m },
            method: None,
            gap: vec![0.0; m2],
            grad: vec![0.0; m2],
            search: vec![0.0; m2],
            projected: vec![0.0; m2],
            work: vec![0.0; m2],
            kh: vec![0.0; m2],
            previous: vec![0.0; m2],
            window: if m == n { Vec::new() } else { vec![0.0; n * n] },
            offset: 0.0,
            round_off: false,
            warm: false,
        })
    }

    /// The same solver with another iteration: [`Method::Plain`] (Rey,
    /// Anciaux & Molinari's conjugate gradient) or
    /// [`Method::Preconditioned`] (see the module docs).
    pub fn with_method(mut self, method: Method) -> Self {
        self.method = Some(method);
        self
    }

    /// Change the iteration (see [`AdhesiveSolver::with_method`]); `None`:
    /// by the law ([`AdhesiveSolver::method_for`]).
    pub fn set_method(&mut self, method: Option<Method>) {
        self.method = method;
    }

    /// The iteration used for `law`: the one set, else
    /// [`Method::PRECONDITIONED`] for the exponential law (the same answer as
    /// the plain iteration to the tolerance, 4–10× fewer iterations) and
    /// [`Method::Plain`] for Maugis–Dugdale, whose discrete energy has many
    /// stationary points: the preconditioned steps land on other ones than
    /// the plain iteration on some points of a load path (module docs,
    /// "Preconditioned iteration"), so the plain one stays the default. Where the grid resolves the cohesive
    /// zone ([`RESOLVED_COHESIVE_LENGTH`]) the two agree within 0.2 % on a
    /// cold solve, but along a loading–unloading path they may still follow
    /// different branches past an instability (the free-boundary path of
    /// docs/adhesion.md, ℓ = 128 L/N: pull-off 7.35e-3 E* plain, 7.47e-3 E*
    /// preconditioned).
    pub fn method_for(&self, law: &CohesiveLaw) -> Method {
        self.method.unwrap_or(match law {
            CohesiveLaw::Exponential { .. } => Method::PRECONDITIONED,
            CohesiveLaw::Maugis { .. } => Method::Plain,
        })
    }

    /// The operator's boundary condition.
    pub fn boundary(&self) -> Boundary {
        self.ops.op.boundary()
    }

    /// The gap field of the last solve (N × N row-major).
    pub fn gap(&self) -> &[f64] {
        if self.layout.periodic() {
            &self.gap
        } else {
            &self.window
        }
    }

    /// Forget the last solution: the next solve starts from the rigid gap.
    pub(crate) fn forget(&mut self) {
        self.warm = false;
    }

    /// The pressure field of the last solve into `p` (N × N; compression positive).
    ///
    /// # Errors
    /// Wrong length of `heights` or `p`.
    pub fn pressure(&mut self, heights: &[f64], law: &CohesiveLaw, p: &mut [f64]) -> Result<()> {
        Heights::new(heights, &self.ops.op)?;
        let n2 = self.layout.n * self.layout.n;
        if p.len() != n2 {
            return Err(Error::Inconsistent {
                name: "pressure".into(),
                requirement: format!("N² = {n2} values"),
            });
        }
        let (mean, _) = self.gradient(heights, law)?;
        for k in 0..self.gap.len() {
            if let Some(w) = self.layout.window(k) {
                let g = self.gap[k];
                p[w] = if g > 0.0 {
                    -law.attraction(g)
                } else {
                    self.work[k] - mean
                };
            }
        }
        Ok(())
    }

    /// Solve at mean gap ḡ = `mean_gap` (> 0) for the rigid `heights`
    /// (N × N row-major, unit of L), starting from the previous gap (scaled)
    /// when there is one. Periodic only.
    ///
    /// # Errors
    /// Heights of the wrong length or not finite; `mean_gap` not finite and
    /// positive, or so large that the gap field's rounding exceeds the
    /// adhesion range (ḡ ≤ ρ/(ε N²)) or its elastic pressures overflow
    /// (ḡ ≤ (√f64::MAX/(E*|q|_max N) − (max h − min h))/N², |q|_max = √2πN/L);
    /// a tolerance out of range; a free-boundary operator (use
    /// [`AdhesiveSolver::solve_approach`]); [`Error::NotConverged`] when every
    /// node closes.
    pub fn solve(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        mean_gap: f64,
        opts: &AdhesiveOptions,
    ) -> Result<AdhesivePoint> {
        check::positive("mean_gap", mean_gap)?;
        if !self.layout.periodic() {
            return Err(Error::Inconsistent {
                name: "mean_gap".into(),
                requirement: "a periodic operator (the free boundary is solved under approach \
                              control: solve_approach)"
                    .into(),
            });
        }
        let heights = Heights::new(heights, &self.ops.op)?;
        self.run(heights, law, Target::MeanGap(mean_gap), opts)
    }

    /// Solve at approach δ = `approach` of the rigid surface from first
    /// touch (any sign: δ < 0 is a separation), the gap offset o = max h − δ.
    /// Periodic, this is [`AdhesiveSolver::solve`] at ḡ = max h − mean h − δ
    /// (the mean displacement is 0); free, the rigid surface moves against
    /// the half-space outside the window at rest.
    ///
    /// # Errors
    /// As [`AdhesiveSolver::solve`]; `approach` not finite, or (periodic)
    /// not below max h − mean h (ḡ must be > 0), or (free) |δ| above ρ/ε or
    /// the bound on the elastic pressures (as for ḡ).
    pub fn solve_approach(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        approach: f64,
        opts: &AdhesiveOptions,
    ) -> Result<AdhesivePoint> {
        if !approach.is_finite() {
            return Err(Error::invalid("approach", approach, "finite"));
        }
        let heights = Heights::new(heights, &self.ops.op)?;
        if self.layout.periodic() {
            let mean_gap = heights.max() - heights.mean() - approach;
            if mean_gap <= 0.0 {
                return Err(Error::invalid(
                    "approach",
                    approach,
                    format!(
                        "below max h − mean h = {} (periodic: the mean gap must stay > 0)",
                        heights.max() - heights.mean()
                    ),
                ));
            }
            return self.run(heights, law, Target::MeanGap(mean_gap), opts);
        }
        self.run(heights, law, Target::Approach(approach), opts)
    }

    /// A sequence of mean gaps (approach in and out), warm-started from each
    /// other, with the pull-off: the most tensile mean pressure reached.
    /// Periodic only.
    ///
    /// # Errors
    /// As [`AdhesiveSolver::solve`] for the first failing gap.
    pub fn sequence(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        mean_gaps: &[f64],
        opts: &AdhesiveOptions,
    ) -> Result<AdhesiveSequence> {
        self.walk(mean_gaps, |s, g| s.solve(heights, law, g, opts))
    }

    /// A sequence of approaches (in and out), warm-started from each other,
    /// with the pull-off: periodic or free.
    ///
    /// # Errors
    /// As [`AdhesiveSolver::solve_approach`] for the first failing approach.
    pub fn sequence_approach(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        approaches: &[f64],
        opts: &AdhesiveOptions,
    ) -> Result<AdhesiveSequence> {
        self.walk(approaches, |s, d| s.solve_approach(heights, law, d, opts))
    }

    /// [`AdhesiveSolver::sequence`] or [`AdhesiveSolver::sequence_approach`],
    /// as `control` prescribes.
    ///
    /// # Errors
    /// As those.
    pub fn path(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        control: PathControl<'_>,
        opts: &AdhesiveOptions,
    ) -> Result<AdhesiveSequence> {
        match control {
            PathControl::MeanGap(g) => self.sequence(heights, law, g, opts),
            PathControl::Approach(d) => self.sequence_approach(heights, law, d, opts),
        }
    }

    /// The one path walk behind [`AdhesiveSolver::sequence`] and
    /// [`AdhesiveSolver::sequence_approach`]: forget the previous state, then
    /// solve each control value in order, each warm-started from the last.
    fn walk(
        &mut self,
        controls: &[f64],
        mut solve: impl FnMut(&mut Self, f64) -> Result<AdhesivePoint>,
    ) -> Result<AdhesiveSequence> {
        self.forget();
        let points = controls
            .iter()
            .map(|&c| solve(self, c))
            .collect::<Result<Vec<_>>>()?;
        Ok(AdhesiveSequence::new(points))
    }

    fn run(
        &mut self,
        heights: Heights<'_>,
        law: &CohesiveLaw,
        target: Target,
        opts: &AdhesiveOptions,
    ) -> Result<AdhesivePoint> {
        check::tolerance("tolerance", opts.tolerance)?;
        if opts.max_iterations == 0 {
            return Err(crate::Error::invalid("max_iterations", 0.0, ">= 1"));
        }
        self.check_reach(heights, law, target)?;
        self.start(heights, target);
        if self.detach(heights, law, target) {
            self.warm = true;
            return Ok(self.point(law, target, heights, 0.0, 0, 0.0, true, None));
        }
        let mut fallback = None;
        let mut done = 0;
        if let Method::Preconditioned { stall_iterations } = self.method_for(law) {
            match self.preconditioned(heights, law, target, opts, stall_iterations)? {
                Phase::Done(pm, k, eps) => {
                    self.warm = true;
                    return Ok(self.point(law, target, heights, pm, k, eps, true, None));
                }
                Phase::Stalled(f) => {
                    done = f.iterations;
                    fallback = Some(f);
                }
            }
        }
        let (pm, k, eps, ok) = self.plain(heights, law, target, opts, done)?;
        self.warm = true;
        Ok(self.point(law, target, heights, pm, k, eps, ok, fallback))
    }

    /// The starting gap: the previous one (shifted to the new offset, free
    /// boundary) or the rigid gap; then (periodic) scaled to ḡ.
    fn start(&mut self, heights: Heights<'_>, target: Target) {
        let layout = self.layout;
        let h_max = heights.max();
        let heights = heights.values();
        match target {
            Target::MeanGap(mean_gap) => {
                if !self.warm || self.mean_of_gap() <= 0.0 {
                    for (g, h) in self.gap.iter_mut().zip(heights) {
                        *g = h_max - h;
                    }
                }
                self.scale_to(mean_gap);
            }
            Target::Approach(delta) => {
                let offset = h_max - delta;
                if self.warm {
                    let shift = offset - self.offset;
                    for k in 0..self.gap.len() {
                        if layout.window(k).is_some() {
                            self.gap[k] = (self.gap[k] + shift).max(0.0);
                        }
                    }
                } else {
                    for k in 0..self.gap.len() {
                        self.gap[k] = match layout.window(k) {
                            Some(w) => (offset - heights[w]).max(0.0),
                            None => 0.0,
                        };
                    }
                }
                self.offset = offset;
            }
        }
    }
}

impl AdhesiveSolver {
    #[allow(clippy::too_many_arguments)]
    fn point(
        &mut self,
        law: &CohesiveLaw,
        target: Target,
        heights: Heights<'_>,
        mean_pressure: f64,
        iterations: usize,
        residual: f64,
        converged: bool,
        fallback: Option<Fallback>,
    ) -> AdhesivePoint {
        let layout = self.layout;
        let (mean_gap, approach, mean_pressure) = match target {
            Target::MeanGap(g) => (g, heights.max() - heights.mean() - g, mean_pressure),
            Target::Approach(delta) => {
                for k in 0..self.gap.len() {
                    if let Some(w) = layout.window(k) {
                        self.window[w] = self.gap[k];
                    }
                }
                // the force: the window's pressures (𝒦u on the contact,
                // −W′ in the gaps; `work` is fresh unless detached)
                let mut force = 0.0;
                if mean_pressure != 0.0 || residual != 0.0 || iterations > 0 {
                    for k in 0..self.gap.len() {
                        if layout.window(k).is_some() {
                            let g = self.gap[k];
                            force += if g > 0.0 {
                                -law.attraction(g)
                            } else {
                                self.work[k]
                            };
                        }
                    }
                }
                let n2 = self.window.len() as f64;
                (self.window.iter().sum::<f64>() / n2, delta, force / n2)
            }
        };
        let g = self.gap();
        let n2 = g.len() as f64;
        let contact = g.iter().filter(|g| **g == 0.0).count() as f64 / n2;
        let cohesive = g.iter().filter(|g| law.cohesive(**g)).count() as f64 / n2;
        AdhesivePoint {
            mean_gap,
            mean_pressure,
            contact_fraction: contact,
            cohesive_fraction: cohesive,
            iterations,
            residual,
            converged,
            approach,
            fallback,
        }
    }
}

/// A loading–unloading sequence and its pull-off.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct AdhesiveSequence {
    /// One point per mean gap, in the order given.
    pub points: Vec<AdhesivePoint>,
    /// The largest tension reached, −min p̄ (unit of E*; 0 when never in tension).
    pub pull_off_pressure: f64,
    /// How many points the plain iteration finished after the preconditioned
    /// one stalled (see [`AdhesivePoint::fallback`]).
    pub fallbacks: usize,
}

impl AdhesiveSequence {
    fn new(points: Vec<AdhesivePoint>) -> Self {
        let pull_off = points.iter().map(|p| p.mean_pressure).fold(0.0, f64::min);
        let fallbacks = points.iter().filter(|p| p.fallback.is_some()).count();
        AdhesiveSequence {
            pull_off_pressure: -pull_off,
            points,
            fallbacks,
        }
    }
}

/// The mean of the residual over the free (open) nodes, Σ r / |F|,
/// periodic; 0 on the free boundary (no mean to remove). A periodic grid
/// with every node closed is an error (full contact).
fn free_mean(sum: f64, free: usize, periodic: bool) -> Result<f64> {
    if !periodic {
        return Ok(0.0);
    }
    if free == 0 {
        return Err(Error::NotConverged {
            what: "adhesive BEM: every node closed (full contact)".into(),
            iterations: 0,
            residual: f64::NAN,
            tolerance: 0.0,
        });
    }
    Ok(sum / free as f64)
}

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
//! of subtracting 𝒦h's O(1) pressures: those points (21 of 62 on the λ = 3
//! sphere path of the tests) ran to `max_iterations` with either iteration
//! before. The floor lies far below tolerance × scale wherever the force is
//! within ~1e-5 of the contact pressures.
//!
//! A detached state, where no node touches or attracts (Maugis–Dugdale with
//! every gap ≥ ρ, or Δγ = 0 out of contact), has no force at all: its
//! residual and its scale are both round-off, so ε is 0/0 and the iteration
//! cannot stop. Its exact solution is the rigid gap shifted to ḡ (𝒦 of a
//! constant is 0, p̄ = 0); the solver returns it (0 iterations) whenever the
//! iterate is detached and that rigid gap is detached too. These were the
//! Maugis–Dugdale solves that never converged before.
//!
//! # References
//! - L. Rey, G. Anciaux, J.-F. Molinari, *Normal adhesive contact on rough
//!   surfaces: efficient algorithm for FFT-based BEM resolution*, Comput.
//!   Mech. 60, 69 (2017), doi:10.1007/s00466-017-1392-5.
//! - I. A. Polonsky, L. M. Keer, Wear 231, 206 (1999), doi:10.1016/S0043-1648(99)00113-1.
//! - D. Maugis, J. Colloid Interface Sci. 150, 243 (1992), doi:10.1016/0021-9797(92)90285-T.
//! - E. Polak, G. Ribière, Rev. Fr. Inform. Rech. Opér. 3(16), 35 (1969),
//!   doi:10.1051/m2an/196903R100351.

use super::driver::Stall;
use super::fft::Fft2;
use super::kernel::{love_cell, signed, Boundary, Operator};
use super::problem::Method;
use super::solution::Fallback;
use crate::error::{check, Error, Result};

/// Shortest cohesive length ℓ = E*Δγ/σ_c² ([`CohesiveLaw::cohesive_length`])
/// that counts as resolved, in grid spacings L/N (below it a study warns).
/// Measured on
/// a rough surface (docs/adhesion.md, "Which stationary point"): at 4.7 L/N
/// the plain and the preconditioned iteration from one start reach
/// Maugis–Dugdale solutions 0.8 % apart in A/A0, at 6.7 L/N 0.47 %, from
/// 9.3 L/N on at most 0.18 %.
pub const RESOLVED_COHESIVE_LENGTH: f64 = 8.0;

/// The cohesive law of the gap.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "law", rename_all = "kebab-case")]
pub enum CohesiveLaw {
    /// Constant attraction Δγ/ρ for gaps below ρ (Maugis–Dugdale).
    Maugis {
        /// Δγ, (unit of E*)·(unit of L).
        work_of_adhesion: f64,
        /// ρ, unit of L.
        adhesion_range: f64,
    },
    /// Attraction (Δγ/ρ) e^{−g/ρ}.
    Exponential {
        /// Δγ, (unit of E*)·(unit of L).
        work_of_adhesion: f64,
        /// ρ, unit of L.
        adhesion_range: f64,
    },
}

/// The largest peak attraction σ_c = Δγ/ρ of a [`CohesiveLaw`]: √f64::MAX/
/// [`super::MAX_GRID`] ≈ 4.1e149 (unit of E*).
///
/// # Bound
/// The solvers' KKT residual sums the squares of the tractions W′(g) ≤ σ_c
/// over N² ≤ MAX_GRID² nodes: N² σ_c² ≤ f64::MAX on every grid.
pub const MAX_PEAK_ATTRACTION: f64 = 1.340_780_792_994_259_6e154 / super::MAX_GRID as f64;

/// Δγ ≥ 0 and ρ > 0, finite, with σ_c = Δγ/ρ ≤ [`MAX_PEAK_ATTRACTION`],
/// naming Δγ or ρ (the one further from 1 in order of magnitude: an
/// overflowing ratio needs one of them far outside every unit system).
fn check_law(work_of_adhesion: f64, adhesion_range: f64) -> Result<()> {
    check::non_negative("work_of_adhesion", work_of_adhesion)?;
    check::positive("adhesion_range", adhesion_range)?;
    if work_of_adhesion / adhesion_range <= MAX_PEAK_ATTRACTION {
        return Ok(());
    }
    let approx = crate::error::approx;
    let why = "so that the peak attraction Δγ/ρ, summed in squares over the grid, stays finite \
               in f64";
    Err(
        if work_of_adhesion.log10().abs() >= adhesion_range.log10().abs() {
            Error::invalid(
                "work_of_adhesion",
                work_of_adhesion,
                format!(
                    "at most {} (ρ = {}) {why}",
                    approx(MAX_PEAK_ATTRACTION * adhesion_range),
                    crate::error::num(adhesion_range)
                ),
            )
        } else {
            Error::invalid(
                "adhesion_range",
                adhesion_range,
                format!(
                    "at least {} (Δγ = {}) {why}",
                    approx(work_of_adhesion / MAX_PEAK_ATTRACTION),
                    crate::error::num(work_of_adhesion)
                ),
            )
        },
    )
}

impl CohesiveLaw {
    /// The Maugis–Dugdale law.
    ///
    /// # Errors
    /// `work_of_adhesion` negative or not finite; `adhesion_range` not finite
    /// and > 0; Δγ/ρ above [`MAX_PEAK_ATTRACTION`] (naming the one of the
    /// two further from 1 in order of magnitude).
    pub fn maugis(work_of_adhesion: f64, adhesion_range: f64) -> Result<Self> {
        check_law(work_of_adhesion, adhesion_range)?;
        Ok(CohesiveLaw::Maugis {
            work_of_adhesion,
            adhesion_range,
        })
    }

    /// The exponential law.
    ///
    /// # Errors
    /// As [`CohesiveLaw::maugis`].
    pub fn exponential(work_of_adhesion: f64, adhesion_range: f64) -> Result<Self> {
        check_law(work_of_adhesion, adhesion_range)?;
        Ok(CohesiveLaw::Exponential {
            work_of_adhesion,
            adhesion_range,
        })
    }

    /// (Δγ, ρ).
    pub fn parameters(&self) -> (f64, f64) {
        match *self {
            CohesiveLaw::Maugis {
                work_of_adhesion,
                adhesion_range,
            }
            | CohesiveLaw::Exponential {
                work_of_adhesion,
                adhesion_range,
            } => (work_of_adhesion, adhesion_range),
        }
    }

    /// The law's cohesive length ℓ = E* Δγ/σ_c², σ_c = Δγ/ρ its peak
    /// attraction (both laws), so ℓ = E* ρ²/Δγ (unit of L; ∞ at Δγ = 0).
    ///
    /// The one length made of E*, Δγ and σ_c: the scale of the cohesive zone
    /// at the edge of an adhesive contact (Maugis, J. Colloid Interface Sci.
    /// 150, 243 (1992); the zone of a Dugdale crack of constant cohesive
    /// stress σ_c in a homogeneous body is (π/8) E′Δγ/σ_c² in the small-zone
    /// limit, Dugdale, J. Mech. Phys. Solids 8, 100 (1960)). A grid must
    /// resolve it: [`RESOLVED_COHESIVE_LENGTH`].
    pub fn cohesive_length(&self, contact_modulus: f64) -> f64 {
        let (work_of_adhesion, adhesion_range) = self.parameters();
        contact_modulus * adhesion_range * adhesion_range / work_of_adhesion
    }

    /// W′(g) ≥ 0: the attraction (tension) at gap g.
    pub fn attraction(&self, g: f64) -> f64 {
        match *self {
            CohesiveLaw::Maugis {
                work_of_adhesion,
                adhesion_range,
            } => {
                if g < adhesion_range {
                    work_of_adhesion / adhesion_range
                } else {
                    0.0
                }
            }
            CohesiveLaw::Exponential {
                work_of_adhesion,
                adhesion_range,
            } => work_of_adhesion / adhesion_range * (-g / adhesion_range).exp(),
        }
    }

    /// Whether W′ jumps between gaps a and b (Maugis–Dugdale: ρ between them).
    fn jumps_between(&self, a: f64, b: f64) -> bool {
        match *self {
            CohesiveLaw::Maugis { adhesion_range, .. } => {
                (a < adhesion_range) != (b < adhesion_range)
            }
            CohesiveLaw::Exponential { .. } => false,
        }
    }

    /// Whether gap g is inside the cohesive zone (g < ρ).
    fn cohesive(&self, g: f64) -> bool {
        g > 0.0 && g < self.parameters().1
    }
}

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

/// The free half-space on the 2N × 2N circulant of Love's cell kernel
/// (the matrix that [`Boundary::Free`]'s operator embeds), applied on the
/// whole padded grid, and its exact inverse.
///
/// # Why the padded grid
/// The gap formulation needs the stiffness 𝒦 = 𝒢⁻¹. Of the free operator
/// only the N × N window block is physical, and its inverse is not a
/// convolution. On the padded grid the circulant C is positive definite
/// (its multiplier is positive) and C⁻¹ is one FFT convolution; the nodes
/// outside the window carry a displacement but no pressure (they never
/// touch and do not attract): the stationarity of Π in those displacements
/// is p = C⁻¹u = 0 there, so the window pressures p produce u = 𝒢p exactly
/// (the DC-FFT of Liu, Wang & Liu, Wear 243, 101 (2000), read backwards).
#[derive(Debug)]
struct Padded {
    m: usize,
    fft: Fft2,
    /// C's multiplier, `(m/2 + 1) × m` (column k_j, then k_i), times 1/m².
    compliance: Vec<f64>,
}

impl Padded {
    fn new(n: usize, size: f64, e_star: f64) -> Result<Self> {
        let m = 2 * n;
        let mut fft = Fft2::new(m, m)?;
        let c = size / n as f64 / (std::f64::consts::PI * e_star);
        let norm = 1.0 / (m as f64 * m as f64);
        let mut compliance = vec![0.0; fft.nc() * m];
        fft.convolve(
            &mut |i, row| {
                let si = signed(i, m) as f64;
                for (j, v) in row.iter_mut().enumerate() {
                    *v = c * love_cell(si, signed(j, m) as f64);
                }
            },
            &mut |kj, col| {
                for (ki, z) in col.iter().enumerate() {
                    compliance[kj * m + ki] = z.re * norm;
                }
            },
            None,
        );
        Ok(Padded { m, fft, compliance })
    }

    /// y = C x (`stiffness` false) or C⁻¹ x, on the m × m grid.
    fn apply(&mut self, stiffness: bool, x: &[f64], y: &mut [f64]) -> Result<()> {
        let m = self.m;
        self.apply_rows(
            stiffness,
            &mut |i, row| row.copy_from_slice(&x[i * m..(i + 1) * m]),
            &mut |i, row| y[i * m..(i + 1) * m].copy_from_slice(row),
        )
    }

    /// [`Padded::apply`] row by row: `fill(i, row)` writes row i of x, then
    /// `emit(i, row)` receives row i of y.
    fn apply_rows(
        &mut self,
        stiffness: bool,
        fill: &mut dyn FnMut(usize, &mut [f64]),
        emit: &mut dyn FnMut(usize, &[f64]),
    ) -> Result<()> {
        let m = self.m;
        let norm = 1.0 / (m as f64 * m as f64);
        let c = &self.compliance;
        self.fft.convolve(
            fill,
            &mut |kj, col| {
                let mk = &c[kj * m..(kj + 1) * m];
                if stiffness {
                    for (z, v) in col.iter_mut().zip(mk) {
                        *z *= norm * norm / v;
                    }
                } else {
                    for (z, v) in col.iter_mut().zip(mk) {
                        *z *= v;
                    }
                }
            },
            Some(emit),
        );
        Ok(())
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

/// Steps of the preconditioned iteration between two transforms of 𝒦(g + h)
/// (the update accumulates rounding).
const REFRESH: usize = 20;

/// How the preconditioned phase ended.
enum Phase {
    /// ε ≤ tolerance, or the detached answer: (p̄, iterations, ε).
    Done(f64, usize, f64),
    /// Stalled after this many iterations, at this ε: the plain loop goes on.
    Stalled(Fallback),
}

/// The sums of one pass of [`AdhesiveSolver::measure`].
#[derive(Debug, Clone, Copy)]
struct Sums {
    /// p̄'s negative: the mean of r over the free set (periodic; 0 free).
    mean: f64,
    /// ε's denominator squared (module docs, "Stopping rule").
    scale: f64,
    /// The round-off floor of ε's numerator squared.
    floor: f64,
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
    pub fn forget(&mut self) {
        self.warm = false;
    }

    /// The pressure field of the last solve into `p` (N × N; compression positive).
    ///
    /// # Errors
    /// Wrong length of `heights` or `p`.
    pub fn pressure(&mut self, heights: &[f64], law: &CohesiveLaw, p: &mut [f64]) -> Result<()> {
        self.check_heights(heights)?;
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
        self.check_heights(heights)?;
        if self.layout.periodic() {
            let (h_max, h_mean) = height_stats(heights);
            let mean_gap = h_max - h_mean - approach;
            if mean_gap <= 0.0 {
                return Err(Error::invalid(
                    "approach",
                    approach,
                    format!(
                        "below max h − mean h = {} (periodic: the mean gap must stay > 0)",
                        h_max - h_mean
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
        heights: &[f64],
        law: &CohesiveLaw,
        target: Target,
        opts: &AdhesiveOptions,
    ) -> Result<AdhesivePoint> {
        check::tolerance("tolerance", opts.tolerance)?;
        if opts.max_iterations == 0 {
            return Err(crate::Error::invalid("max_iterations", 0.0, ">= 1"));
        }
        self.check_heights(heights)?;
        self.check_reach(heights, law, target)?;
        let (h_max, h_mean) = height_stats(heights);
        self.start(heights, target, h_max);
        if self.detach(heights, law, target, h_mean) {
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
    fn start(&mut self, heights: &[f64], target: Target, h_max: f64) {
        let layout = self.layout;
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

    /// The preconditioned iteration (module docs, "Preconditioned
    /// iteration"); `Stalled` hands the current gap to [`Self::plain`].
    ///
    /// The element-wise passes ride on the two transforms' row callbacks:
    /// centring r on F and the sums of ε in the fill of 𝒢r, the truncation of
    /// z to F and ⟨r, z⟩ in its emit; the centring of t, the contact nodes
    /// that stay put and ⟨r, t⟩ in the fill of 𝒦t, ⟨t, 𝒦t⟩ in its emit. The
    /// gap step and its mean are one pass, the scaling to ḡ, the update of
    /// 𝒦(g + h) and the new r another ([`Self::measure`]). Four passes over
    /// the fields per iteration besides the transforms (twelve before).
    fn preconditioned(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        target: Target,
        opts: &AdhesiveOptions,
        stall_iterations: usize,
    ) -> Result<Phase> {
        let layout = self.layout;
        let (m, periodic) = (layout.m, layout.periodic());
        let jumps = matches!(law, CohesiveLaw::Maugis { .. });
        // W″/W′ of the law away from its jumps, where the cohesive zone is
        // resolved: |W″| ≤ Δγ/ρ² below a node's stiffness E*πN/(2L) (else
        // the longer steps jump to another stationary point: the λ = 3
        // sphere at N = 64 of tests/bem_adhesive.rs)
        let op = &self.ops.op;
        let node = op.e_star() * std::f64::consts::PI * layout.n as f64 / (2.0 * op.size());
        let curvature_per_attraction = match *law {
            CohesiveLaw::Exponential {
                work_of_adhesion,
                adhesion_range,
            } if work_of_adhesion / (adhesion_range * adhesion_range) < node => {
                1.0 / adhesion_range
            }
            _ => 0.0,
        };
        let h_mean = height_stats(heights).1;
        let mut stall = Stall::new(stall_iterations);
        self.search.iter_mut().for_each(|t| *t = 0.0);
        let (mut rz_old, mut restart) = (0.0, true);
        let mut k = 0;
        self.stiffness_of_gap(heights, false)?;
        self.stiffness_of_gap(heights, true)?;
        let mut sums = self.measure(heights, law, None)?;
        let mut stale = 0usize;
        loop {
            // r centred on F = {g > 0} ∪ {g = 0, r < p̄} (contact nodes that
            // pull), and ε's numerator
            let mean = sums.mean;
            let mut res = 0.0;
            for (kk, (r, g)) in self.grad.iter_mut().zip(&self.gap).enumerate() {
                let d = *r - mean;
                let contact = *g <= 0.0 && (periodic || layout.window(kk).is_some());
                // free nodes: r = 0; contact nodes: r ≥ 0
                *r = if !contact || d < 0.0 {
                    res += d * d;
                    d
                } else {
                    0.0
                };
            }
            let eps = if sums.scale > 0.0 {
                (res / sums.scale).sqrt()
            } else {
                0.0
            };
            self.round_off = res <= sums.floor;
            if eps <= opts.tolerance || self.round_off {
                if stale == 0 {
                    return Ok(Phase::Done(-mean, k, eps));
                }
                // converged on the updated 𝒦(g + h): confirm on a fresh one
                self.stiffness_of_gap(heights, true)?;
                sums = self.measure(heights, law, None)?;
                stale = 0;
                continue;
            }
            if self.detach(heights, law, target, h_mean) {
                return Ok(Phase::Done(0.0, k, 0.0));
            }
            let stalled = Phase::Stalled(Fallback {
                iterations: k,
                residual: eps,
            });
            if k >= opts.max_iterations || stall.stalled(k, eps) {
                return Ok(stalled);
            }
            // z = [F] 𝒢 r (𝒢 = C on the padded grid) and, on the way, ⟨r, z⟩
            // and the sums over F of z and of the last direction
            let in_f = |kk: usize, r: f64, g: f64| {
                r != 0.0 || g > 0.0 || (!periodic && layout.window(kk).is_none())
            };
            let (mut r_z, mut z_sum, mut t_sum, mut count) = (0.0, 0.0, 0.0, 0usize);
            let mut rp_z = 0.0;
            {
                let Self {
                    ops,
                    grad,
                    gap,
                    search,
                    projected,
                    previous,
                    ..
                } = &mut *self;
                let (grad, gap, search) = (&grad[..], &gap[..], &search[..]);
                let previous = &previous[..];
                ops.compliance_rows(
                    &mut |i, row| row.copy_from_slice(&grad[i * m..(i + 1) * m]),
                    &mut |i, row| {
                        let (lo, hi) = (i * m, (i + 1) * m);
                        for (j, ((z, p), (y, (t, (r, g))))) in row
                            .iter()
                            .zip(&previous[lo..hi])
                            .zip(
                                projected[lo..hi].iter_mut().zip(
                                    search[lo..hi]
                                        .iter()
                                        .zip(grad[lo..hi].iter().zip(&gap[lo..hi])),
                                ),
                            )
                            .enumerate()
                        {
                            if in_f(lo + j, *r, *g) {
                                *y = *z;
                                r_z += r * z;
                                rp_z += p * z;
                                z_sum += z;
                                t_sum += t;
                                count += 1;
                            } else {
                                *y = 0.0;
                            }
                        }
                    },
                )?;
            }
            // Polak–Ribière β, kept ≥ 0 (a restart where the gradient turned)
            let mut beta = if restart || rz_old <= 0.0 {
                0.0
            } else {
                ((r_z - rp_z) / rz_old).max(0.0)
            };
            let (mut descent, mut den, mut curvature) = (0.0, 0.0, 0.0);
            for attempt in 0..2 {
                // t = z + β t_old − μ on F, μ its mean there (Σ t = 0 keeps ḡ)
                let mu = if layout.periodic() {
                    (z_sum + beta * t_sum) / count.max(1) as f64
                } else {
                    0.0
                };
                // ⟨r, t⟩ and Σ W″(g) t² over the open nodes, W″ = −W′/ρ for
                // the exponential law with W′ = r + p̄ − 𝒦(g + h) (no second
                // exponential), 0 for Maugis–Dugdale; r kept for the next β
                let (mut down, mut bend) = (0.0, 0.0);
                for (kk, ((t, z), ((r, g), (w, p)))) in self
                    .search
                    .iter_mut()
                    .zip(&self.projected)
                    .zip(
                        self.grad
                            .iter()
                            .zip(&self.gap)
                            .zip(self.work.iter().zip(self.previous.iter_mut())),
                    )
                    .enumerate()
                {
                    *p = *r;
                    if in_f(kk, *r, *g) {
                        *t = *z + beta * *t - mu;
                        // a contact node that the step would push in stays put
                        if *g <= 0.0 && *t > 0.0 && (periodic || layout.window(kk).is_some()) {
                            *t = 0.0;
                        }
                        down += r * *t;
                        if *g > 0.0 && (periodic || layout.window(kk).is_some()) {
                            bend += (*r + mean - w) * *t * *t;
                        }
                    } else {
                        *t = 0.0;
                    }
                }
                descent = down;
                curvature = -bend * curvature_per_attraction;
                if !(descent > 0.0 || attempt == 1 || beta == 0.0) {
                    // not a descent direction: restart the conjugacy (β = 0)
                    // from z, kept in `projected`
                    beta = 0.0;
                    continue;
                }
                // 𝒦t into `projected`, ⟨t, 𝒦t⟩ on the way
                let mut tq = 0.0;
                {
                    let Self {
                        ops,
                        search,
                        projected,
                        ..
                    } = &mut *self;
                    let search = &search[..];
                    ops.stiffness_rows(
                        &mut |i, row| row.copy_from_slice(&search[i * m..(i + 1) * m]),
                        &mut |i, row| {
                            let (lo, hi) = (i * m, (i + 1) * m);
                            projected[lo..hi].copy_from_slice(row);
                            tq += row
                                .iter()
                                .zip(&search[lo..hi])
                                .map(|(q, t)| q * t)
                                .sum::<f64>();
                        },
                    )?;
                }
                den = tq;
                break;
            }
            if descent.is_nan() || descent <= 0.0 {
                return Ok(stalled);
            }
            rz_old = r_z;
            // the step of the quadratic model with the law's curvature,
            // ⟨t, (𝒦 + W″)t⟩; at most 4× the step of 𝒦 alone where W″ < 0
            // nearly cancels 𝒦 along t
            let tau = descent / (den + curvature).max(0.25 * den);
            if !(tau > 0.0 && tau.is_finite()) {
                return Ok(stalled);
            }
            restart = false;
            let mut clamped = false;
            let mut total = 0.0;
            for (kk, (g, t)) in self.gap.iter_mut().zip(&self.search).enumerate() {
                if periodic || layout.window(kk).is_some() {
                    let step = *g - tau * t;
                    clamped |= step < 0.0;
                    let new = step.max(0.0);
                    restart |= jumps && law.jumps_between(*g, new);
                    *g = new;
                } else {
                    *g -= tau * t;
                }
                total += *g;
            }
            k += 1;
            let mut scale = 1.0;
            if let Target::MeanGap(mean_gap) = target {
                let mean_of_gap = total / self.gap.len() as f64;
                if mean_of_gap <= 0.0 {
                    return Ok(stalled);
                }
                scale = mean_gap / mean_of_gap;
            }
            // 𝒦(s(g − τt) + h) = s(𝒦(g + h) − τ𝒦t − 𝒦h) + 𝒦h when no node
            // was clamped (a clamp, or every REFRESH steps: a transform)
            if clamped || stale >= REFRESH {
                if scale != 1.0 {
                    self.gap.iter_mut().for_each(|g| *g *= scale);
                }
                self.stiffness_of_gap(heights, true)?;
                sums = self.measure(heights, law, None)?;
                stale = 0;
            } else {
                sums = self.measure(heights, law, Some((scale, tau)))?;
                stale += 1;
            }
        }
    }

    /// One pass over the fields: with `update` = (s, τ) first g ← s g and
    /// `work` ← s(`work` − τ𝒦t − 𝒦h) + 𝒦h (𝒦t in `projected`, 𝒦h in
    /// `kh`); then grad = work + W′(g) (work on the padding) and the sums
    /// of the stopping rule (module docs): the multiplier p̄ (periodic),
    /// ε's denominator and the round-off floor — [`Self::residual`]'s, in
    /// one pass.
    fn measure(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        update: Option<(f64, f64)>,
    ) -> Result<Sums> {
        // the law's match out of the loop, W′ as `CohesiveLaw::attraction`
        // bit for bit but for the exponential law beyond g = 42ρ: there W′
        // is below 2⁻⁶⁰ (e⁻⁴² = 5.7e-19) of the contact attraction Δγ/ρ, far
        // under the round-off of the pressures it is added to (ε_mach times
        // the largest symbol of 𝒦 times g + h), and is taken as 0 (55 % of
        // the nodes of the 512² surface of examples/adhesive_tamaas.rs skip
        // the exponential)
        match *law {
            CohesiveLaw::Maugis {
                work_of_adhesion,
                adhesion_range,
            } => {
                let c = work_of_adhesion / adhesion_range;
                self.sweep(
                    heights,
                    update,
                    |g| if g < adhesion_range { c } else { 0.0 },
                )
            }
            CohesiveLaw::Exponential {
                work_of_adhesion,
                adhesion_range,
            } => {
                let (c, cut) = (work_of_adhesion / adhesion_range, 42.0 * adhesion_range);
                self.sweep(heights, update, |g| {
                    if g > cut {
                        0.0
                    } else {
                        c * (-g / adhesion_range).exp()
                    }
                })
            }
        }
    }

    /// [`Self::measure`] with W′ = `attraction`.
    #[inline(always)]
    fn sweep(
        &mut self,
        heights: &[f64],
        update: Option<(f64, f64)>,
        attraction: impl Fn(f64) -> f64,
    ) -> Result<Sums> {
        let layout = self.layout;
        let (s, tau) = update.unwrap_or((1.0, 0.0));
        let (mut sum, mut free, mut input, mut scale) = (0.0, 0usize, 0.0, 0.0);
        let fields = self.gap.iter_mut().zip(self.work.iter_mut()).zip(
            self.grad
                .iter_mut()
                .zip(self.projected.iter().zip(&self.kh)),
        );
        if layout.periodic() {
            for (((g, w), (r, (q, kh))), h) in fields.zip(heights) {
                if update.is_some() {
                    *g *= s;
                    *w = s * (*w - tau * q - kh) + kh;
                }
                let a = attraction(*g);
                *r = *w + a;
                if *g > 0.0 {
                    sum += *r;
                    free += 1;
                }
                input += (*g + h) * (*g + h);
                scale += *w * *w + a * a;
            }
        } else {
            let offset = self.offset;
            for (k, ((g, w), (r, (q, kh)))) in fields.enumerate() {
                if update.is_some() {
                    *g *= s;
                    *w = s * (*w - tau * q - kh) + kh;
                }
                match layout.window(k) {
                    Some(i) => {
                        let a = attraction(*g);
                        *r = *w + a;
                        input += (*g + (heights[i] - offset)).powi(2);
                        scale += *w * *w + a * a;
                    }
                    None => {
                        *r = *w;
                        input += *g * *g;
                        scale += *w * *w;
                    }
                }
            }
        }
        let mean = free_mean(sum, free, layout.periodic())?;
        scale += self.gap.len() as f64 * mean * mean;
        Ok(Sums {
            mean,
            scale,
            floor: self.round_off_floor(input),
        })
    }

    /// The round-off of computing 𝒦(g + h) for an input of squared norm
    /// `input`: (ε_mach times the largest symbol E*π√2 N/L times log₂ of the
    /// grid's nodes)² times `input` (module docs, "Stopping rule").
    fn round_off_floor(&self, input: f64) -> f64 {
        let op = &self.ops.op;
        let k_max =
            op.e_star() * std::f64::consts::PI * std::f64::consts::SQRT_2 * self.layout.n as f64
                / op.size();
        let nodes = self.gap.len() as f64;
        (f64::EPSILON * k_max * nodes.log2()).powi(2) * input
    }

    /// Rey, Anciaux & Molinari's conjugate gradient (module docs,
    /// "Method"), from the current gap, `done` iterations already spent;
    /// returns (p̄, iterations, ε, converged).
    fn plain(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        target: Target,
        opts: &AdhesiveOptions,
        done: usize,
    ) -> Result<(f64, usize, f64, bool)> {
        let layout = self.layout;
        let h_mean = height_stats(heights).1;
        self.search.iter_mut().for_each(|t| *t = 0.0);
        let (mut g_old, mut delta) = (1.0, 0.0);
        let mut residual = f64::INFINITY;
        let mut iterations = done;
        let (mut mean, mut eps) = self.gradient(heights, law)?;
        while iterations < opts.max_iterations {
            residual = eps;
            if eps <= opts.tolerance || self.round_off {
                return Ok((-mean, iterations, eps, true));
            }
            if self.detach(heights, law, target, h_mean) {
                return Ok((0.0, iterations, 0.0, true));
            }
            iterations += 1;
            // r on the free set, centred; search direction centred on it too
            let mut norm = 0.0;
            for (kk, (r, g)) in self.grad.iter_mut().zip(&self.gap).enumerate() {
                if *g > 0.0 || layout.window(kk).is_none() {
                    *r -= mean;
                    norm += *r * *r;
                } else {
                    *r = 0.0;
                }
            }
            let beta = delta * norm / g_old;
            g_old = norm;
            let (mut sum, mut free) = (0.0, 0usize);
            for (kk, ((t, r), g)) in self
                .search
                .iter_mut()
                .zip(&self.grad)
                .zip(&self.gap)
                .enumerate()
            {
                if *g > 0.0 || layout.window(kk).is_none() {
                    *t = *r + beta * *t;
                    sum += *t;
                    free += 1;
                } else {
                    *t = 0.0;
                }
            }
            if layout.periodic() {
                let t_mean = sum / free.max(1) as f64;
                for (t, g) in self.search.iter_mut().zip(&self.gap) {
                    if *g > 0.0 {
                        *t -= t_mean;
                    }
                }
            }
            self.ops.stiffness(&self.search, &mut self.projected)?;
            let (mut num, mut den) = (0.0, 0.0);
            for ((t, r), q) in self.search.iter().zip(&self.grad).zip(&self.projected) {
                num += r * t;
                den += q * t;
            }
            if den.is_nan() || den <= 0.0 {
                break;
            }
            let tau = num / den;
            // a node crossing the end of the cohesive zone changes W′ by a
            // jump: the conjugacy restarts (steepest descent for one step)
            let mut crossed = false;
            for (kk, (g, t)) in self.gap.iter_mut().zip(&self.search).enumerate() {
                if layout.window(kk).is_some() {
                    let new = (*g - tau * t).max(0.0);
                    crossed |= law.jumps_between(*g, new);
                    *g = new;
                } else {
                    *g -= tau * t;
                }
            }
            // contact nodes that pull re-enter: r = 𝒦(g+h) + W′(0) + p̄ < 0 there
            delta = if crossed { 0.0 } else { 1.0 };
            let reenter = self.reenter(heights, law, tau)?;
            if reenter > 0 {
                delta = 0.0;
            }
            if let Target::MeanGap(mean_gap) = target {
                if self.mean_of_gap() <= 0.0 {
                    return Err(Error::NotConverged {
                        what: "adhesive BEM: every node closed".into(),
                        iterations,
                        residual,
                        tolerance: opts.tolerance,
                    });
                }
                self.scale_to(mean_gap);
            }
            (mean, eps) = self.gradient(heights, law)?;
        }
        Ok((-mean, iterations, eps.min(residual), eps <= opts.tolerance))
    }

    /// Refuse a mean gap (or an approach) so large that the gap field no
    /// longer resolves the cohesive law, or its elastic pressures overflow
    /// (ε was NaN at ḡ = 1e300, and a finite noise of ±6e145 at 9e133).
    ///
    /// # Bounds
    /// The gap field is ≥ 0 with mean ḡ, so a gap is at most N²ḡ and carries
    /// a rounding of up to ε N²ḡ (ε = f64::EPSILON; approach control: ε|δ|).
    /// The law varies on the scale ρ: its tractions are resolved only while
    ///
    /// ```text
    /// ε N² ḡ ≤ ρ   ⇔   ḡ ≤ ρ/(ε N²)          (approach: |δ| ≤ ρ/ε)
    /// ```
    ///
    /// Beyond it the iteration stops at the round-off of 𝒦(g + h), which the
    /// noise of the gap sets, and reports that noise as the mean pressure.
    /// Independently the displacement |g + h − o| is at most
    /// U = N²ḡ + (max h − min h) (approach: |δ| + 2(max h − min h)) and the
    /// operator's largest symbol E*|q|_max/2, |q|_max = √2 πN/L, so
    /// Σ(𝒦u)² ≤ (E*|q|_max/2)² N² U² stays below f64::MAX/4 while
    /// (E*|q|_max/2) N U ≤ √f64::MAX/2; the smaller bound is stated.
    fn check_reach(&self, heights: &[f64], law: &CohesiveLaw, target: Target) -> Result<()> {
        let op = &self.ops.op;
        let n = self.layout.n as f64;
        let rho = law.parameters().1;
        let q_max = std::f64::consts::SQRT_2 * std::f64::consts::PI * n / op.size();
        let (lo, hi) = heights
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
                (a.min(h), b.max(h))
            });
        let range = hi - lo;
        let reach = f64::MAX.sqrt() / (op.e_star() * q_max * n);
        let approx = crate::error::approx;
        let why = format!(
            "(ρ = {}, N = {}, E* = {}, L = {}) so that the gap field resolves the cohesive law \
             (its rounding ε N²ḡ below ρ) and its elastic pressures stay finite in f64",
            crate::error::num(rho),
            self.layout.n,
            crate::error::num(op.e_star()),
            crate::error::num(op.size()),
        );
        match target {
            Target::MeanGap(mean_gap) => {
                let bound = (rho / (f64::EPSILON * n * n)).min((reach - range) / (n * n));
                if mean_gap.is_nan() || mean_gap > bound {
                    return Err(Error::invalid(
                        "mean_gap",
                        mean_gap,
                        format!("at most {} {why}", approx(bound.max(0.0))),
                    ));
                }
            }
            Target::Approach(approach) => {
                let bound = (rho / f64::EPSILON).min(reach - 2.0 * range);
                if approach.is_nan() || approach.abs() > bound {
                    return Err(Error::invalid(
                        "approach",
                        approach,
                        format!("at most {} in size {why}", approx(bound.max(0.0))),
                    ));
                }
            }
        }
        Ok(())
    }

    fn check_heights(&self, heights: &[f64]) -> Result<()> {
        let n2 = self.layout.n * self.layout.n;
        if heights.len() != n2 {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!("N² = {n2} values, got {}", heights.len()),
            });
        }
        if let Some(k) = heights.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid("heights", heights[k], "finite"));
        }
        Ok(())
    }

    /// The detached solution: when no node of the current gap interacts
    /// (no contact, no attraction) and the rigid gap — periodic at ḡ,
    /// g = ḡ + mean(h) − h; free at the offset, g = o − h with u = 0 — does
    /// not interact either, that gap is the exact stationary point of its
    /// region (no pressure anywhere): it replaces the gap and `true` is
    /// returned. The iteration cannot find it, since its KKT residual and its
    /// scale are both round-off.
    fn detach(&mut self, heights: &[f64], law: &CohesiveLaw, target: Target, h_mean: f64) -> bool {
        let layout = self.layout;
        let interacts = |g: f64| g <= 0.0 || law.attraction(g) > 0.0;
        let any = self
            .gap
            .iter()
            .enumerate()
            .any(|(k, g)| layout.window(k).is_some() && interacts(*g));
        if any {
            return false;
        }
        let level = match target {
            Target::MeanGap(mean_gap) => mean_gap + h_mean,
            Target::Approach(_) => self.offset,
        };
        if heights.iter().any(|h| interacts(level - h)) {
            return false;
        }
        for k in 0..self.gap.len() {
            self.gap[k] = match layout.window(k) {
                Some(w) => level - heights[w],
                None => 0.0,
            };
        }
        true
    }

    fn mean_of_gap(&self) -> f64 {
        self.gap.iter().sum::<f64>() / self.gap.len() as f64
    }

    /// Scale the gap to mean ḡ; returns the factor (NaN when the gap was 0).
    fn scale_to(&mut self, mean_gap: f64) -> f64 {
        let m = self.mean_of_gap();
        if m > 0.0 {
            let s = mean_gap / m;
            self.gap.iter_mut().for_each(|g| *g *= s);
            s
        } else {
            self.gap.iter_mut().for_each(|g| *g = mean_gap);
            f64::NAN
        }
    }

    /// grad = 𝒦(g + h) + W′(g) (and work = 𝒦(g + h)); free boundary:
    /// grad = C⁻¹u + W′(g) with u = g + h − o on the surface and the
    /// unknown itself on the padding. Returns (the multiplier: the mean of
    /// grad on the free set, periodic; 0 free, ε).
    fn gradient(&mut self, heights: &[f64], law: &CohesiveLaw) -> Result<(f64, f64)> {
        self.stiffness_of_gap(heights, true)?;
        self.residual(heights, law)
    }

    /// work = 𝒦(g + h) (`with_gap`) or 𝒦h (into `kh`): periodic; free,
    /// C⁻¹ of u = g + h − o on the surface and the padding's u.
    fn stiffness_of_gap(&mut self, heights: &[f64], with_gap: bool) -> Result<()> {
        let layout = self.layout;
        let offset = if layout.periodic() { 0.0 } else { self.offset };
        let c = if with_gap { 1.0 } else { 0.0 };
        for (k, (s, g)) in self.projected.iter_mut().zip(&self.gap).enumerate() {
            *s = match layout.window(k) {
                Some(w) => c * g + (heights[w] - offset),
                None => c * g,
            };
        }
        if with_gap {
            self.ops.stiffness(&self.projected, &mut self.work)
        } else {
            self.ops.stiffness(&self.projected, &mut self.kh)
        }
    }

    /// grad = work + W′(g) and (the multiplier, ε) from `work` = 𝒦(g + h).
    fn residual(&mut self, heights: &[f64], law: &CohesiveLaw) -> Result<(f64, f64)> {
        let layout = self.layout;
        let offset = if layout.periodic() { 0.0 } else { self.offset };
        let (mut sum, mut free) = (0.0, 0usize);
        for (k, ((r, w), g)) in self
            .grad
            .iter_mut()
            .zip(&self.work)
            .zip(&self.gap)
            .enumerate()
        {
            if layout.window(k).is_some() {
                *r = w + law.attraction(*g);
                if *g > 0.0 {
                    sum += *r;
                    free += 1;
                }
            } else {
                *r = *w;
            }
        }
        let mean = free_mean(sum, free, layout.periodic())?;
        // the round-off of 𝒦(g + h): ε_mach times the largest symbol E*π√2 N/L
        // times the input's norm, times log₂ of the grid's nodes
        let input: f64 = self
            .gap
            .iter()
            .enumerate()
            .map(|(k, g)| match layout.window(k) {
                Some(w) => (g + (heights[w] - offset)).powi(2),
                None => g * g,
            })
            .sum();
        let op = &self.ops.op;
        let k_max = op.e_star() * std::f64::consts::PI * std::f64::consts::SQRT_2 * layout.n as f64
            / op.size();
        let nodes = self.gap.len() as f64;
        let floor = (f64::EPSILON * k_max * nodes.log2()).powi(2) * input;
        let (mut res, mut scale) = (0.0, 0.0);
        for (k, ((r, w), g)) in self.grad.iter().zip(&self.work).zip(&self.gap).enumerate() {
            let d = r - mean;
            // free nodes: r = 0; contact nodes: r ≥ 0
            if *g > 0.0 || d < 0.0 || layout.window(k).is_none() {
                res += d * d;
            }
            scale += w * w + (r - w) * (r - w);
        }
        scale += self.gap.len() as f64 * mean * mean;
        self.round_off = res <= floor;
        let eps = if scale > 0.0 {
            (res / scale).sqrt()
        } else {
            0.0
        };
        Ok((mean, eps))
    }

    /// Contact nodes with r < 0 open by −τ r; returns how many.
    fn reenter(&mut self, heights: &[f64], law: &CohesiveLaw, tau: f64) -> Result<usize> {
        let (mean, _) = self.gradient(heights, law)?;
        let layout = self.layout;
        let mut count = 0;
        for (k, (g, r)) in self.gap.iter_mut().zip(&self.grad).enumerate() {
            let d = r - mean;
            if *g == 0.0 && d < 0.0 && layout.window(k).is_some() {
                *g = -tau * d;
                count += 1;
            }
        }
        Ok(count)
    }

    #[allow(clippy::too_many_arguments)]
    fn point(
        &mut self,
        law: &CohesiveLaw,
        target: Target,
        heights: &[f64],
        mean_pressure: f64,
        iterations: usize,
        residual: f64,
        converged: bool,
        fallback: Option<Fallback>,
    ) -> AdhesivePoint {
        let layout = self.layout;
        let (h_max, h_mean) = height_stats(heights);
        let (mean_gap, approach, mean_pressure) = match target {
            Target::MeanGap(g) => (g, h_max - h_mean - g, mean_pressure),
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

/// max h and mean h.
fn height_stats(heights: &[f64]) -> (f64, f64) {
    let h_max = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let h_mean = heights.iter().sum::<f64>() / heights.len() as f64;
    (h_max, h_mean)
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

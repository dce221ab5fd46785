//! Adhesive FFT-BEM: a rigid rough surface and an elastic half-space that
//! attract each other through a cohesive law of the gap, under mean-gap
//! control, so that the whole force–separation curve, tension included, is
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
//! # Stopping rule
//! ```text
//! ε = ( Σ_{g>0} r_i² + Σ_{g=0} min(r_i, 0)² )^{1/2}
//!     / ( Σ_i [𝒦(g + h)]_i² + Σ_i W′(g_i)² + N² p̄² )^{1/2} ≤ tolerance
//! ```
//! (the relative residual of the KKT conditions); a solve that reaches
//! `max_iterations` first returns its point with `converged = false`.
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

use super::kernel::{Boundary, Operator};
use crate::error::{check, Error, Result};

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

impl CohesiveLaw {
    /// The Maugis–Dugdale law.
    ///
    /// # Errors
    /// `work_of_adhesion` negative or not finite; `adhesion_range` not finite and > 0.
    pub fn maugis(work_of_adhesion: f64, adhesion_range: f64) -> Result<Self> {
        check::non_negative("work_of_adhesion", work_of_adhesion)?;
        check::positive("adhesion_range", adhesion_range)?;
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
        check::non_negative("work_of_adhesion", work_of_adhesion)?;
        check::positive("adhesion_range", adhesion_range)?;
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

/// One solved mean gap.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct AdhesivePoint {
    /// ḡ, the prescribed mean gap (unit of L).
    pub mean_gap: f64,
    /// p̄, the mean pressure (unit of E*; negative in tension).
    pub mean_pressure: f64,
    /// Fraction of nodes in repulsive contact (g = 0).
    pub contact_fraction: f64,
    /// Fraction of nodes inside the cohesive zone (0 < g < ρ).
    pub cohesive_fraction: f64,
    /// Iterations of this solve.
    pub iterations: usize,
    /// ε reached.
    pub residual: f64,
    /// ε ≤ tolerance.
    pub converged: bool,
}

/// The adhesive solver: an operator and the buffers of one surface.
#[derive(Debug)]
pub struct AdhesiveSolver {
    op: Operator,
    gap: Vec<f64>,
    grad: Vec<f64>,
    search: Vec<f64>,
    projected: Vec<f64>,
    work: Vec<f64>,
    warm: bool,
}

impl AdhesiveSolver {
    /// The solver on the periodic operator `op`.
    ///
    /// # Errors
    /// A free-boundary operator (the gap formulation needs 𝒦 = 𝒢⁻¹, exact only when periodic).
    pub fn new(op: Operator) -> Result<Self> {
        if op.boundary() != Boundary::Periodic {
            return Err(Error::Inconsistent {
                name: "boundary".into(),
                requirement: "periodic (the adhesive solver has no free boundary yet)".into(),
            });
        }
        let n2 = op.n() * op.n();
        Ok(AdhesiveSolver {
            op,
            gap: vec![0.0; n2],
            grad: vec![0.0; n2],
            search: vec![0.0; n2],
            projected: vec![0.0; n2],
            work: vec![0.0; n2],
            warm: false,
        })
    }

    /// The gap field of the last solve (N × N row-major).
    pub fn gap(&self) -> &[f64] {
        &self.gap
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
        let (mean, _) = self.gradient(heights, law)?;
        if p.len() != self.grad.len() {
            return Err(Error::Inconsistent {
                name: "pressure".into(),
                requirement: format!("N² = {} values", self.grad.len()),
            });
        }
        for ((pi, w), g) in p.iter_mut().zip(&self.work).zip(&self.gap) {
            *pi = if *g > 0.0 {
                -law.attraction(*g)
            } else {
                w - mean
            };
        }
        Ok(())
    }

    /// Solve at mean gap ḡ = `mean_gap` (> 0) for the rigid `heights`
    /// (N × N row-major, unit of L), starting from the previous gap (scaled)
    /// when there is one.
    ///
    /// # Errors
    /// Heights of the wrong length or not finite; `mean_gap` not finite and > 0;
    /// a tolerance out of range; [`Error::NotConverged`] when every node closes.
    pub fn solve(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        mean_gap: f64,
        opts: &AdhesiveOptions,
    ) -> Result<AdhesivePoint> {
        check::positive("mean_gap", mean_gap)?;
        check::tolerance("tolerance", opts.tolerance)?;
        self.check_heights(heights)?;
        if !self.warm || self.mean_of_gap() <= 0.0 {
            let h_max = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            for (g, h) in self.gap.iter_mut().zip(heights) {
                *g = h_max - h;
            }
        }
        self.scale_to(mean_gap);
        if self.detach(heights, law, mean_gap) {
            self.warm = true;
            return Ok(self.point(law, mean_gap, 0.0, 0, 0.0, true));
        }
        self.search.iter_mut().for_each(|t| *t = 0.0);
        let (mut g_old, mut delta) = (1.0, 0.0);
        let mut residual = f64::INFINITY;
        let mut iterations = 0;
        let (mut mean, mut eps) = self.gradient(heights, law)?;
        while iterations < opts.max_iterations {
            residual = eps;
            if eps <= opts.tolerance {
                self.warm = true;
                return Ok(self.point(law, mean_gap, -mean, iterations, eps, true));
            }
            if self.detach(heights, law, mean_gap) {
                self.warm = true;
                return Ok(self.point(law, mean_gap, 0.0, iterations, 0.0, true));
            }
            iterations += 1;
            // r on the free set, centred; search direction centred on it too
            let mut norm = 0.0;
            for (r, g) in self.grad.iter_mut().zip(&self.gap) {
                if *g > 0.0 {
                    *r -= mean;
                    norm += *r * *r;
                } else {
                    *r = 0.0;
                }
            }
            let beta = delta * norm / g_old;
            g_old = norm;
            let (mut sum, mut free) = (0.0, 0usize);
            for ((t, r), g) in self.search.iter_mut().zip(&self.grad).zip(&self.gap) {
                if *g > 0.0 {
                    *t = *r + beta * *t;
                    sum += *t;
                    free += 1;
                } else {
                    *t = 0.0;
                }
            }
            let t_mean = sum / free.max(1) as f64;
            for (t, g) in self.search.iter_mut().zip(&self.gap) {
                if *g > 0.0 {
                    *t -= t_mean;
                }
            }
            self.op.apply_stiffness(&self.search, &mut self.projected)?;
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
            for (g, t) in self.gap.iter_mut().zip(&self.search) {
                let new = (*g - tau * t).max(0.0);
                crossed |= law.jumps_between(*g, new);
                *g = new;
            }
            // contact nodes that pull re-enter: r = 𝒦(g+h) + W′(0) + p̄ < 0 there
            delta = if crossed { 0.0 } else { 1.0 };
            let reenter = self.reenter(heights, law, tau)?;
            if reenter > 0 {
                delta = 0.0;
            }
            if self.mean_of_gap() <= 0.0 {
                return Err(Error::NotConverged {
                    what: "adhesive BEM: every node closed".into(),
                    iterations,
                    residual,
                    tolerance: opts.tolerance,
                });
            }
            self.scale_to(mean_gap);
            (mean, eps) = self.gradient(heights, law)?;
        }
        self.warm = true;
        Ok(self.point(
            law,
            mean_gap,
            -mean,
            iterations,
            eps.min(residual),
            eps <= opts.tolerance,
        ))
    }

    /// A sequence of mean gaps (approach in and out), warm-started from each
    /// other, with the pull-off: the most tensile mean pressure reached.
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
        self.forget();
        let points = mean_gaps
            .iter()
            .map(|&g| self.solve(heights, law, g, opts))
            .collect::<Result<Vec<_>>>()?;
        let pull_off = points.iter().map(|p| p.mean_pressure).fold(0.0, f64::min);
        Ok(AdhesiveSequence {
            pull_off_pressure: -pull_off,
            points,
        })
    }

    fn check_heights(&self, heights: &[f64]) -> Result<()> {
        if heights.len() != self.gap.len() {
            return Err(Error::Inconsistent {
                name: "heights".into(),
                requirement: format!("N² = {} values, got {}", self.gap.len(), heights.len()),
            });
        }
        if let Some(k) = heights.iter().position(|h| !h.is_finite()) {
            return Err(Error::invalid("heights", heights[k], "finite"));
        }
        Ok(())
    }

    /// The detached solution: when no node of the current gap interacts
    /// (no contact, no attraction) and the rigid gap at ḡ, g = ḡ + mean(h) − h,
    /// does not interact either, that gap is the exact stationary point of its
    /// region (𝒦(g + h) = 0, p̄ = 0): it replaces the gap and `true` is
    /// returned. The iteration cannot find it, since its KKT residual and its
    /// scale are both round-off.
    fn detach(&mut self, heights: &[f64], law: &CohesiveLaw, mean_gap: f64) -> bool {
        let interacts = |g: f64| g <= 0.0 || law.attraction(g) > 0.0;
        if self.gap.iter().any(|g| interacts(*g)) {
            return false;
        }
        let mean_h = heights.iter().sum::<f64>() / heights.len() as f64;
        if heights.iter().any(|h| interacts(mean_gap + mean_h - h)) {
            return false;
        }
        for (g, h) in self.gap.iter_mut().zip(heights) {
            *g = mean_gap + mean_h - h;
        }
        true
    }

    fn mean_of_gap(&self) -> f64 {
        self.gap.iter().sum::<f64>() / self.gap.len() as f64
    }

    fn scale_to(&mut self, mean_gap: f64) {
        let m = self.mean_of_gap();
        if m > 0.0 {
            let s = mean_gap / m;
            self.gap.iter_mut().for_each(|g| *g *= s);
        } else {
            self.gap.iter_mut().for_each(|g| *g = mean_gap);
        }
    }

    /// grad = 𝒦(g + h) + W′(g) (and work = 𝒦(g + h)); returns (mean of grad
    /// on the free set, ε).
    fn gradient(&mut self, heights: &[f64], law: &CohesiveLaw) -> Result<(f64, f64)> {
        for ((s, g), h) in self.projected.iter_mut().zip(&self.gap).zip(heights) {
            *s = g + h;
        }
        self.op.apply_stiffness(&self.projected, &mut self.work)?;
        let (mut sum, mut free) = (0.0, 0usize);
        for ((r, w), g) in self.grad.iter_mut().zip(&self.work).zip(&self.gap) {
            *r = w + law.attraction(*g);
            if *g > 0.0 {
                sum += *r;
                free += 1;
            }
        }
        if free == 0 {
            return Err(Error::NotConverged {
                what: "adhesive BEM: every node closed (full contact)".into(),
                iterations: 0,
                residual: f64::NAN,
                tolerance: 0.0,
            });
        }
        let mean = sum / free as f64;
        let (mut res, mut scale) = (0.0, 0.0);
        for ((r, w), g) in self.grad.iter().zip(&self.work).zip(&self.gap) {
            let d = r - mean;
            // free nodes: r = 0; contact nodes: r ≥ 0
            if *g > 0.0 || d < 0.0 {
                res += d * d;
            }
            scale += w * w + (r - w) * (r - w);
        }
        scale += self.gap.len() as f64 * mean * mean;
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
        let mut count = 0;
        for (g, r) in self.gap.iter_mut().zip(&self.grad) {
            let d = r - mean;
            if *g == 0.0 && d < 0.0 {
                *g = -tau * d;
                count += 1;
            }
        }
        Ok(count)
    }

    fn point(
        &self,
        law: &CohesiveLaw,
        mean_gap: f64,
        mean_pressure: f64,
        iterations: usize,
        residual: f64,
        converged: bool,
    ) -> AdhesivePoint {
        let n2 = self.gap.len() as f64;
        let contact = self.gap.iter().filter(|g| **g == 0.0).count() as f64 / n2;
        let cohesive = self.gap.iter().filter(|g| law.cohesive(**g)).count() as f64 / n2;
        AdhesivePoint {
            mean_gap,
            mean_pressure,
            contact_fraction: contact,
            cohesive_fraction: cohesive,
            iterations,
            residual,
            converged,
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
}

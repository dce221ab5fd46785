//! The preconditioned adhesive iteration (module docs of [`super`],
//! "Preconditioned iteration") as a [`Step`] of the BEM's loop driver, and
//! its fused measuring pass.

use super::{free_mean, AdhesiveOptions, AdhesiveSolver, CohesiveLaw, Layout, Phase, Target};
use crate::bem::driver::{drive, Check, Limits, Measured, Step};
use crate::bem::problem::Heights;
use crate::bem::solution::{Fallback, Iteration};
use crate::error::Result;

/// Steps of the preconditioned iteration between two transforms of 𝒦(g + h)
/// (the update accumulates rounding).
const REFRESH: usize = 20;

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

impl AdhesiveSolver {
    /// The preconditioned iteration (module docs, "Preconditioned
    /// iteration"), run by the BEM's loop driver; `Stalled` hands the current
    /// gap to the plain iteration.
    ///
    /// The element-wise passes ride on the two transforms' row callbacks:
    /// centring r on F and the sums of ε in the fill of 𝒢r, the truncation of
    /// z to F and ⟨r, z⟩ in its emit; the centring of t, the contact nodes
    /// that stay put and ⟨r, t⟩ in the fill of 𝒦t, ⟨t, 𝒦t⟩ in its emit. The
    /// gap step and its mean are one pass, the scaling to ḡ, the update of
    /// 𝒦(g + h) and the new r another ([`Self::measure`]). Four passes over
    /// the fields per iteration besides the transforms.
    pub(super) fn preconditioned(
        &mut self,
        heights: Heights<'_>,
        law: &CohesiveLaw,
        target: Target,
        opts: &AdhesiveOptions,
        stall_iterations: usize,
    ) -> Result<Phase> {
        let mut run = Pcg::new(self, heights, law, target, opts.tolerance)?;
        let limits = Limits::new(opts.max_iterations, opts.tolerance).with_stall(stall_iterations);
        drive(&mut run, limits, None)
    }
}

/// The preconditioned iteration's state, as the driver runs it.
struct Pcg<'a> {
    solver: &'a mut AdhesiveSolver,
    heights: Heights<'a>,
    law: &'a CohesiveLaw,
    target: Target,
    tolerance: f64,
    /// Maugis–Dugdale: a node crossing g = ρ restarts the conjugacy.
    jumps: bool,
    /// W″/W′ where the cohesive zone is resolved (exponential law), else 0.
    curvature_per_attraction: f64,
    /// ⟨r, z⟩ of the last step (Polak–Ribière).
    rz_old: f64,
    restart: bool,
    k: usize,
    /// The sums of the last measuring pass.
    sums: Sums,
    /// Steps since 𝒦(g + h) was last transformed afresh.
    stale: usize,
}

impl<'a> Pcg<'a> {
    /// 𝒦h, 𝒦(g + h) and the first sums, from the current gap.
    fn new(
        solver: &'a mut AdhesiveSolver,
        heights: Heights<'a>,
        law: &'a CohesiveLaw,
        target: Target,
        tolerance: f64,
    ) -> Result<Self> {
        let layout = solver.layout;
        // W″/W′ of the law away from its jumps, where the cohesive zone is
        // resolved: |W″| ≤ Δγ/ρ² below a node's stiffness E*πN/(2L) (else
        // the longer steps jump to another stationary point: the λ = 3
        // sphere at N = 64 of tests/bem_adhesive.rs)
        let op = &solver.ops.op;
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
        let h = heights.values();
        solver.search.iter_mut().for_each(|t| *t = 0.0);
        solver.stiffness_of_gap(h, false)?;
        solver.stiffness_of_gap(h, true)?;
        let sums = solver.measure(h, law, None)?;
        Ok(Pcg {
            solver,
            heights,
            law,
            target,
            tolerance,
            jumps: matches!(law, CohesiveLaw::Maugis { .. }),
            curvature_per_attraction,
            rz_old: 0.0,
            restart: true,
            k: 0,
            sums,
            stale: 0,
        })
    }

    /// z = [F] 𝒢 r (𝒢 = C on the padded grid) into `projected` and, on the
    /// way, `[⟨r, z⟩, ⟨r_old, z⟩, Σ_F z, Σ_F t_old]` and |F|.
    fn precondition(&mut self) -> Result<([f64; 4], usize)> {
        let layout = self.solver.layout;
        let m = layout.m;
        let (mut r_z, mut z_sum, mut t_sum, mut count) = (0.0, 0.0, 0.0, 0usize);
        let mut rp_z = 0.0;
        let AdhesiveSolver {
            ops,
            grad,
            gap,
            search,
            projected,
            previous,
            ..
        } = &mut *self.solver;
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
                    if in_free_set(layout, lo + j, *r, *g) {
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
        Ok(([r_z, rp_z, z_sum, t_sum], count))
    }

    /// t = z + β t_old − μ on F (μ its mean there, Σ t = 0 keeps ḡ), with the
    /// restart β = 0 where t does not descend; then 𝒦t into `projected`.
    /// Returns ⟨r, t⟩, ⟨t, 𝒦t⟩ and the law's curvature term Σ W″(g) t².
    fn direction(
        &mut self,
        mut beta: f64,
        z_sum: f64,
        t_sum: f64,
        count: usize,
    ) -> Result<[f64; 3]> {
        let layout = self.solver.layout;
        let (m, periodic) = (layout.m, layout.periodic());
        let mean = self.sums.mean;
        let (mut descent, mut den, mut curvature) = (0.0, 0.0, 0.0);
        for attempt in 0..2 {
            let mu = if periodic {
                (z_sum + beta * t_sum) / count.max(1) as f64
            } else {
                0.0
            };
            // ⟨r, t⟩ and Σ W″(g) t² over the open nodes, W″ = −W′/ρ for
            // the exponential law with W′ = r + p̄ − 𝒦(g + h) (no second
            // exponential), 0 for Maugis–Dugdale; r kept for the next β
            let (mut down, mut bend) = (0.0, 0.0);
            let sv = &mut *self.solver;
            for (kk, ((t, z), ((r, g), (w, p)))) in sv
                .search
                .iter_mut()
                .zip(&sv.projected)
                .zip(
                    sv.grad
                        .iter()
                        .zip(&sv.gap)
                        .zip(sv.work.iter().zip(sv.previous.iter_mut())),
                )
                .enumerate()
            {
                *p = *r;
                if in_free_set(layout, kk, *r, *g) {
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
            curvature = -bend * self.curvature_per_attraction;
            if !(descent > 0.0 || attempt == 1 || beta == 0.0) {
                // not a descent direction: restart the conjugacy (β = 0)
                // from z, kept in `projected`
                beta = 0.0;
                continue;
            }
            // 𝒦t into `projected`, ⟨t, 𝒦t⟩ on the way
            let mut tq = 0.0;
            let AdhesiveSolver {
                ops,
                search,
                projected,
                ..
            } = &mut *sv;
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
            den = tq;
            break;
        }
        Ok([descent, den, curvature])
    }

    /// g ← max(g − τt, 0) on the surface (g − τt on the padding); returns
    /// whether a node was clamped and Σ g. Sets `restart` where a node
    /// crossed the end of a Maugis–Dugdale zone.
    fn gap_step(&mut self, tau: f64) -> (bool, f64) {
        let layout = self.solver.layout;
        let periodic = layout.periodic();
        let (law, jumps) = (self.law, self.jumps);
        let mut clamped = false;
        let mut total = 0.0;
        let sv = &mut *self.solver;
        for (kk, (g, t)) in sv.gap.iter_mut().zip(&sv.search).enumerate() {
            if periodic || layout.window(kk).is_some() {
                let step = *g - tau * t;
                clamped |= step < 0.0;
                let new = step.max(0.0);
                self.restart |= jumps && law.jumps_between(*g, new);
                *g = new;
            } else {
                *g -= tau * t;
            }
            total += *g;
        }
        (clamped, total)
    }
}

/// Whether node `kk` (with r and g) is in the free set F = {g > 0} ∪
/// {g = 0, r < p̄} or on the padding.
#[inline(always)]
fn in_free_set(layout: Layout, kk: usize, r: f64, g: f64) -> bool {
    r != 0.0 || g > 0.0 || (!layout.periodic() && layout.window(kk).is_none())
}

impl Step for Pcg<'_> {
    type Output = Phase;
    const WHAT: &'static str = "preconditioned adhesive BEM";

    /// r centred on F = {g > 0} ∪ {g = 0, r < p̄} (contact nodes that
    /// pull), and ε.
    fn measure(&mut self) -> Result<Measured> {
        let layout = self.solver.layout;
        let periodic = layout.periodic();
        let sums = self.sums;
        let mean = sums.mean;
        let mut res = 0.0;
        let sv = &mut *self.solver;
        for (kk, (r, g)) in sv.grad.iter_mut().zip(&sv.gap).enumerate() {
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
        sv.round_off = res <= sums.floor;
        Ok(Measured {
            iteration: self.k,
            residual: eps,
        })
    }

    fn contact_fraction(&self) -> f64 {
        self.solver.closed_fraction()
    }

    fn check(&mut self, m: Measured) -> Result<Check<Phase>> {
        if m.residual <= self.tolerance || self.solver.round_off {
            if self.stale == 0 {
                return Ok(Check::Stop(Phase::Done(
                    -self.sums.mean,
                    self.k,
                    m.residual,
                )));
            }
            // converged on the updated 𝒦(g + h): confirm on a fresh one
            self.solver.stiffness_of_gap(self.heights.values(), true)?;
            self.sums = self.solver.measure(self.heights.values(), self.law, None)?;
            self.stale = 0;
            return Ok(Check::Again);
        }
        if self.solver.detach(self.heights, self.law, self.target) {
            return Ok(Check::Stop(Phase::Done(0.0, self.k, 0.0)));
        }
        Ok(Check::Go)
    }

    fn step(&mut self, _: &mut dyn FnMut(Iteration)) -> Result<bool> {
        let ([r_z, rp_z, z_sum, t_sum], count) = self.precondition()?;
        // Polak–Ribière β, kept ≥ 0 (a restart where the gradient turned)
        let beta = if self.restart || self.rz_old <= 0.0 {
            0.0
        } else {
            ((r_z - rp_z) / self.rz_old).max(0.0)
        };
        let [descent, den, curvature] = self.direction(beta, z_sum, t_sum, count)?;
        if descent.is_nan() || descent <= 0.0 {
            return Ok(false);
        }
        self.rz_old = r_z;
        // the step of the quadratic model with the law's curvature,
        // ⟨t, (𝒦 + W″)t⟩; at most 4× the step of 𝒦 alone where W″ < 0
        // nearly cancels 𝒦 along t
        let tau = descent / (den + curvature).max(0.25 * den);
        if !(tau > 0.0 && tau.is_finite()) {
            return Ok(false);
        }
        self.restart = false;
        let (clamped, total) = self.gap_step(tau);
        self.k += 1;
        let mut scale = 1.0;
        if let Target::MeanGap(mean_gap) = self.target {
            let mean_of_gap = total / self.solver.gap.len() as f64;
            if mean_of_gap <= 0.0 {
                return Ok(false);
            }
            scale = mean_gap / mean_of_gap;
        }
        // 𝒦(s(g − τt) + h) = s(𝒦(g + h) − τ𝒦t − 𝒦h) + 𝒦h when no node
        // was clamped (a clamp, or every REFRESH steps: a transform)
        let (heights, law) = (self.heights.values(), self.law);
        if clamped || self.stale >= REFRESH {
            if scale != 1.0 {
                self.solver.gap.iter_mut().for_each(|g| *g *= scale);
            }
            self.solver.stiffness_of_gap(heights, true)?;
            self.sums = self.solver.measure(heights, law, None)?;
            self.stale = 0;
        } else {
            self.sums = self.solver.measure(heights, law, Some((scale, tau)))?;
            self.stale += 1;
        }
        Ok(true)
    }

    fn stalled(&mut self, m: Measured) -> Result<Phase> {
        Ok(Phase::Stalled(Fallback {
            iterations: m.iteration,
            residual: m.residual,
        }))
    }

    /// At the limit the plain iteration goes on (it counts against the
    /// same limit).
    fn exhausted(&mut self, m: Measured, _: f64) -> Result<Phase> {
        self.stalled(m)
    }
}

impl AdhesiveSolver {
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
    pub(super) fn round_off_floor(&self, input: f64) -> f64 {
        let op = &self.ops.op;
        let k_max =
            op.e_star() * std::f64::consts::PI * std::f64::consts::SQRT_2 * self.layout.n as f64
                / op.size();
        let nodes = self.gap.len() as f64;
        (f64::EPSILON * k_max * nodes.log2()).powi(2) * input
    }
}

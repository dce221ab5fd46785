//! The gap field's operations shared by the adhesive iterations: detaching,
//! the mean gap and its scaling, 𝒦(g + h), the gradient and its KKT
//! residual, and the re-entry of contact nodes that pull.

use super::{free_mean, AdhesiveSolver, CohesiveLaw, Target};
use crate::bem::problem::Heights;
use crate::error::Result;

impl AdhesiveSolver {
    /// The detached solution: when no node of the current gap interacts
    /// (no contact, no attraction) and the rigid gap — periodic at ḡ,
    /// g = ḡ + mean(h) − h; free at the offset, g = o − h with u = 0 — does
    /// not interact either, that gap is the exact stationary point of its
    /// region (no pressure anywhere): it replaces the gap and `true` is
    /// returned. The iteration cannot find it, since its KKT residual and its
    /// scale are both round-off.
    pub(super) fn detach(
        &mut self,
        heights: Heights<'_>,
        law: &CohesiveLaw,
        target: Target,
    ) -> bool {
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
            Target::MeanGap(mean_gap) => mean_gap + heights.mean(),
            Target::Approach(_) => self.offset,
        };
        let heights = heights.values();
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

    pub(super) fn mean_of_gap(&self) -> f64 {
        self.gap.iter().sum::<f64>() / self.gap.len() as f64
    }

    /// Scale the gap to mean ḡ; returns the factor (NaN when the gap was 0).
    pub(super) fn scale_to(&mut self, mean_gap: f64) -> f64 {
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
    pub(super) fn gradient(&mut self, heights: &[f64], law: &CohesiveLaw) -> Result<(f64, f64)> {
        self.stiffness_of_gap(heights, true)?;
        self.residual(heights, law)
    }

    /// work = 𝒦(g + h) (`with_gap`) or 𝒦h (into `kh`): periodic; free,
    /// C⁻¹ of u = g + h − o on the surface and the padding's u.
    pub(super) fn stiffness_of_gap(&mut self, heights: &[f64], with_gap: bool) -> Result<()> {
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
    pub(super) fn residual(&mut self, heights: &[f64], law: &CohesiveLaw) -> Result<(f64, f64)> {
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
    pub(super) fn reenter(
        &mut self,
        heights: &[f64],
        law: &CohesiveLaw,
        tau: f64,
    ) -> Result<usize> {
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
}

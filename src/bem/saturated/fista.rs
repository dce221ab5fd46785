//! The saturated loop's last resort: an accelerated projected gradient
//! that cannot cycle.

use super::measure::measure;
use super::projection::{project_box_load, project_load};
use crate::bem::problem::{Options, Problem};
use crate::bem::solution::Iteration;
use crate::bem::workspace::Workspace;
use crate::error::Result;

/// The fallback of a stalled solve: accelerated projected gradient (FISTA,
/// A. Beck & M. Teboulle, SIAM J. Imaging Sci. 2, 183 (2009),
/// doi:10.1137/080716542, with the gradient restart of B. O'Donoghue &
/// E. Candès, Found. Comput. Math. 15, 715 (2015),
/// doi:10.1007/s10208-013-9150-3) on the same energy, step 1/λ_max(𝒢)
/// (power iteration), each step projected exactly onto
/// `{0 ≤ p ≤ σY, Σp = load}` (`p = clamp(v − λ, 0, σY)`, λ by bisection).
/// It returns when the module's criterion holds (checked every 10 steps) or
/// at `max_iterations`, with `p` on the load and `g`, `r` of the last check.
pub(super) fn projected_gradient(
    problem: &Problem,
    ws: &mut Workspace,
    y: f64,
    opts: &Options,
    k: &mut usize,
    observer: &mut dyn FnMut(Iteration),
) -> Result<()> {
    let (heights, offset) = (problem.heights(), problem.offset());
    let (target, sigma_h) = (problem.target_total(), problem.sigma_h());
    let f = ws.fields();
    let (op, p, g, r) = (f.op, f.pressure, f.gap, f.response);
    let n2 = p.len();
    // λ_max of 𝒢 by power iteration (Rayleigh quotient, from a fixed
    // pseudo-random start), with a margin for the estimate from below.
    let mut v: Vec<f64> = (0..n2)
        .map(|i| ((i.wrapping_mul(7919) % 1009) as f64 / 1009.0) - 0.5)
        .collect();
    let mut lambda = 0.0;
    for _ in 0..40 {
        let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        if norm <= 0.0 {
            break;
        }
        v.iter_mut().for_each(|x| *x /= norm);
        op.apply(&v, r)?;
        lambda = v.iter().zip(r.iter()).map(|(a, b)| a * b).sum::<f64>();
        v.copy_from_slice(r);
    }
    let step = 1.0 / (1.1 * lambda.max(f64::MIN_POSITIVE));
    let project = |w: &mut [f64]| match target {
        Some(total) => project_box_load(w, y, total),
        None => w.iter_mut().for_each(|x| *x = x.clamp(0.0, y)),
    };
    let mut prev = p.to_vec();
    let mut z = p.to_vec();
    let mut t_k = 1.0f64;
    let mut steps = 0usize;
    loop {
        // Gradient of ½⟨p, 𝒢p⟩ − ⟨p, h − offset⟩ at z: the gap.
        op.apply(&z, r)?;
        for ((zk, &u), &h) in z.iter_mut().zip(r.iter()).zip(heights) {
            *zk -= step * (u - (h - offset));
        }
        project(&mut z);
        // z is p_{k+1}; restart when the step turns against the momentum.
        let mut turn = 0.0;
        for ((&zn, &pk), &pp) in z.iter().zip(p.iter()).zip(&prev) {
            turn += (pp - zn) * (zn - pk);
        }
        let t_next = if turn > 0.0 {
            1.0
        } else {
            0.5 * (1.0 + (1.0 + 4.0 * t_k * t_k).sqrt())
        };
        let beta = if turn > 0.0 {
            0.0
        } else {
            (t_k - 1.0) / t_next
        };
        t_k = t_next;
        prev.copy_from_slice(p);
        p.copy_from_slice(&z);
        for ((zk, &pk), &pp) in z.iter_mut().zip(p.iter()).zip(&prev) {
            *zk = pk + beta * (pk - pp);
        }
        project(&mut z);
        *k += 1;
        steps += 1;
        if steps.is_multiple_of(10) || *k >= opts.max_iterations {
            op.apply(p, r)?;
            for ((gk, &u), &h) in g.iter_mut().zip(r.iter()).zip(heights) {
                *gk = u - (h - offset);
            }
            let m = measure(p, g, y, target.is_some(), sigma_h);
            let contact = p.iter().filter(|&&v| v > 0.0).count();
            observer(Iteration {
                iteration: *k,
                residual: m.eps,
                contact_fraction: contact as f64 / n2 as f64,
            });
            if (m.eps <= opts.tolerance && m.off_min >= -opts.tolerance * sigma_h)
                || *k >= opts.max_iterations
            {
                if let Some(total) = target {
                    project_load(p, y, total);
                }
                return Ok(());
            }
        }
    }
}

//! The saturated (elastic–perfectly-plastic) contact: pressures bounded by
//! the yield stress, `0 ≤ p ≤ σY`.
//!
//! # What it solves
//! The model of Persson's finite-σY theory: the material yields where the
//! local pressure reaches the hardness σY, and there the surfaces
//! interpenetrate by the plastic deformation. With the compliance operator 𝒢
//! and the rigid heights `h` (see [`super::solver`]):
//! ```text
//! minimise  ½ ⟨p, 𝒢p⟩ − ⟨p, h⟩   subject to  0 ≤ p ≤ σY  and the load (or the approach)
//! KKT, gap g = 𝒢p − (h − max h) − δ:
//!   p = 0       ⇒ g ≥ 0
//!   0 < p < σY  ⇒ g = 0
//!   p = σY      ⇒ g ≤ 0   (−g is the plastic displacement)
//! ```
//! The problem is convex (𝒢 is positive definite), so the solution is unique.
//!
//! # Algorithm
//! First the elastic problem is solved by [`Solver`]'s Polonsky–Keer
//! conjugate gradient; if its largest pressure is ≤ σY it is the saturated
//! solution too (returned as it is: bit for bit the elastic answer).
//! Otherwise, starting from the elastic pressure clipped at σY, the
//! Polonsky–Keer conjugate gradient (Polonsky & Keer 1999) runs on the free
//! set `{0 < p < σY}` with the box projection of the bound-constrained
//! variants (Almqvist et al. 2007; Bugnicourt et al. 2018; Frérot et al.
//! 2020, Tamaas' `KatoSaturated` solves the same problem by a projected
//! gradient): after each step the pressure is clipped to `[0, σY]`, nodes at
//! `p = 0` that overlap (`g < ḡ`) and nodes at `p = σY` that open (`g > ḡ`)
//! re-enter the free set (restarting the conjugation), and under load
//! control the pressure below σY is scaled back to the load with the bound
//! kept: `Σ_{p<σY} min(s p, σY) + σY N_pl = N² p̄`, solved for `s` by
//! Newton's method from below
//! (exact in a few steps: the sum is piecewise linear and concave in `s`).
//! ḡ is the mean gap over the free set (the approach), 0 under penetration
//! control. When every contact node is at σY and the load is short, the
//! overlapping nodes enter with the missing load shared in proportion to
//! their overlap. When ε has not dropped by 10 % in 100 iterations (the
//! active sets cycle: seen in 3 of 135 random 32²–128² cases), an
//! accelerated projected gradient (FISTA with gradient restart, exact
//! projection onto the box and the load) finishes the solve; it cannot
//! cycle, and the same criterion ends it. The gap is recomputed from `p` every iteration (two applications
//! of 𝒢 per iteration).
//!
//! # Convergence criterion
//! ```text
//! ε = [Σ_{0<p<σY} p |g − ḡ| + Σ_{p=σY} σY max(0, g − ḡ)] / (Σ p · σ_h)
//! ```
//! the elastic solver's measure on the free set plus the violation at the
//! plastic nodes; a solve stops when ε ≤ `tolerance` and no node at `p = 0`
//! overlaps by more than `tolerance · σ_h` and (load control) |Σp − N² p̄| ≤
//! `tolerance` · N² p̄; it fails with
//! [`Error::NotConverged`] (with ε) after `max_iterations` iterations (both
//! stages together).
//!
//! # References
//! I. A. Polonsky & L. M. Keer, Wear 231, 206–219 (1999),
//! doi:10.1016/S0043-1648(99)00113-1.
//! A. Almqvist, F. Sahlin, R. Larsson & S. Glavatskih, Tribol. Int. 40,
//! 574–579 (2007), doi:10.1016/j.triboint.2005.11.008 (elastic–perfectly
//! plastic contact with the pressure bounded by the hardness).
//! A. Beck & M. Teboulle, SIAM J. Imaging Sci. 2, 183–202 (2009),
//! doi:10.1137/080716542 (FISTA); B. O'Donoghue & E. Candès, Found. Comput.
//! Math. 15, 715–732 (2015), doi:10.1007/s10208-013-9150-3 (restart).
//! R. Bugnicourt, P. Sainsot, D. Dureisseix, C. Gauthier & A. A. Lubrecht,
//! Tribol. Lett. 66, 29 (2018), doi:10.1007/s11249-017-0980-z.
//! L. Frérot, G. Anciaux, V. Rey, S. Pham-Ba & J.-F. Molinari, J. Open
//! Source Softw. 5, 2121 (2020), doi:10.21105/joss.02121 (Tamaas).

use std::time::Instant;

use super::solver::{Control, Iteration, Options, Solution, Solver};
use crate::error::{check, Error, Result};

/// Solve with the yield stress `y` (called by [`Solver::solve_observed`]
/// when `opts.yield_stress` is set).
pub(super) fn solve(
    solver: &mut Solver,
    heights: &[f64],
    control: Control,
    y: f64,
    opts: &Options,
    observer: &mut dyn FnMut(Iteration),
) -> Result<Solution> {
    let start = Instant::now();
    let mean = match control {
        Control::MeanPressure(pm) if pm.is_finite() && pm > 0.0 => vec![pm],
        _ => vec![],
    };
    check::yield_stress("yield_stress", y, &mean)?;
    let mut sol = solver.solve_elastic(heights, control, opts, observer)?;
    if sol.pressure.iter().all(|&p| p <= y) {
        // The elastic solution satisfies the bound: it is the saturated one.
        sol.seconds = start.elapsed().as_secs_f64();
        return Ok(sol);
    }
    let n = solver.op.n();
    let n2 = n * n;
    let h_max = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let h_mean = heights.iter().sum::<f64>() / n2 as f64;
    let sigma_h =
        (heights.iter().map(|h| (h - h_mean).powi(2)).sum::<f64>() / (n2 as f64 - 1.0)).sqrt();
    let (target, offset) = match control {
        Control::MeanPressure(pm) => (Some(pm * n2 as f64), h_max),
        Control::Penetration(d) => (None, h_max - d),
    };
    let stiffness = solver.op.e_star() * std::f64::consts::PI * n as f64 / solver.op.size();

    let mut p = std::mem::take(&mut sol.pressure);
    p.iter_mut().for_each(|v| *v = v.min(y));
    if let Some(total) = target {
        project_load(&mut p, y, total);
    }
    let mut g = std::mem::take(&mut sol.gap);
    let mut r = std::mem::take(&mut sol.displacement);
    let mut t = vec![0.0; n2];
    let mut k = sol.iterations;
    let mut conjugate = false;
    let mut g_old = 1.0;
    let (mut best, mut stalled) = (f64::INFINITY, 0usize);
    let (residual, g_bar) = loop {
        solver.op.apply(&p, &mut r)?;
        for ((g, u), h) in g.iter_mut().zip(&r).zip(heights) {
            *g = u - (h - offset);
        }
        let Measure {
            eps,
            g_bar,
            off_min,
            nf,
            sum_p,
        } = measure(&p, &g, y, target.is_some(), sigma_h);
        let contact = p.iter().filter(|&&v| v > 0.0).count();
        observer(Iteration {
            iteration: k,
            residual: eps,
            contact_fraction: contact as f64 / n2 as f64,
        });
        // Under load control the load must be carried too: with every
        // contact node at σY, ε is 0 whatever the load they carry.
        let load_error = target.map_or(0.0, |total| (total - sum_p).abs() / total);
        if eps <= opts.tolerance
            && off_min >= -opts.tolerance * sigma_h
            && load_error <= opts.tolerance
        {
            break (eps, g_bar);
        }
        if k >= opts.max_iterations {
            return Err(Error::NotConverged {
                what: "saturated Polonsky–Keer contact solver (yield stress)".into(),
                iterations: k,
                residual: eps,
                tolerance: opts.tolerance,
            });
        }
        // A cycle of active sets (seen on 0.3 % of random 32²–128² cases)
        // makes no progress: finish with the projected gradient, which
        // cannot cycle.
        if eps < 0.9 * best {
            best = eps;
            stalled = 0;
        } else {
            stalled += 1;
        }
        if stalled >= STALL_ITERATIONS {
            projected_gradient(
                solver, heights, offset, y, target, sigma_h, opts, &mut k, &mut p, &mut g, &mut r,
                observer,
            )?;
            stalled = 0;
            best = f64::INFINITY;
            conjugate = false;
            continue;
        }
        if let (Some(total), 0) = (target, nf) {
            // Every contact node is at σY and they carry less than the load:
            // the free set is empty, so no step exists. The overlapping nodes enter with the missing
            // load shared in proportion to their overlap (a step from the
            // stiffest mode would overshoot them all to σY, and scaling
            // back would empty the plastic set: a cycle of two states).
            let missing = total - sum_p;
            let weight: f64 = p
                .iter()
                .zip(&g)
                .filter(|(&pk, &gk)| pk <= 0.0 && gk < g_bar)
                .map(|(_, &gk)| g_bar - gk)
                .sum();
            if missing > 0.0 && weight > 0.0 {
                for (pk, &gk) in p.iter_mut().zip(&g) {
                    if *pk <= 0.0 && gk < g_bar {
                        *pk = (missing * (g_bar - gk) / weight).min(y);
                    }
                }
                project_load(&mut p, y, total);
                conjugate = false;
                k += 1;
                continue;
            }
            if missing > 0.0 {
                // No node overlaps the level of the plastic set: the body
                // must move in. The nodes off the contact enter in the order
                // they would touch (smallest gap first), each with σY until
                // the load is carried; the last one takes the remainder and
                // is the free set the conjugate gradient starts from.
                fill_nearest(&mut p, &g, y, missing);
                conjugate = false;
                k += 1;
                continue;
            }
        }
        // Search direction on the free set, conjugate to the last one.
        let g_norm: f64 = p
            .iter()
            .zip(&g)
            .filter(|(&pk, _)| pk > 0.0 && pk < y)
            .map(|(_, &gk)| (gk - g_bar).powi(2))
            .sum();
        let beta = if conjugate && g_old > 0.0 {
            g_norm / g_old
        } else {
            0.0
        };
        g_old = g_norm;
        for ((tk, &pk), &gk) in t.iter_mut().zip(&p).zip(&g) {
            *tk = if pk > 0.0 && pk < y {
                gk - g_bar + beta * *tk
            } else {
                0.0
            };
        }
        solver.op.apply(&t, &mut r)?;
        let (mut s_t, mut s_r, mut s_rt, mut s_gt) = (0.0, 0.0, 0.0, 0.0);
        for (((&pk, &gk), &tk), &rk) in p.iter().zip(&g).zip(&t).zip(&r) {
            if pk > 0.0 && pk < y {
                s_t += tk;
                s_r += rk;
                s_rt += rk * tk;
                s_gt += (gk - g_bar) * tk;
            }
        }
        let denom = match target {
            Some(_) if nf > 0 => s_rt - s_r / nf as f64 * s_t,
            _ => s_rt,
        };
        let tau = if denom > 0.0 && denom.is_finite() {
            s_gt / denom
        } else {
            0.0
        };
        // Step, box projection, re-entry at both bounds.
        let entry = if tau > 0.0 { tau } else { stiffness };
        let mut changed = false;
        for ((pk, &tk), &gk) in p.iter_mut().zip(&t).zip(&g) {
            let dg = gk - g_bar;
            let v = if *pk <= 0.0 {
                if dg < 0.0 {
                    changed = true;
                    -entry * dg
                } else {
                    0.0
                }
            } else if *pk >= y {
                if dg > 0.0 {
                    changed = true;
                    y - entry * dg
                } else {
                    y
                }
            } else {
                *pk - tau * tk
            };
            *pk = v.clamp(0.0, y);
        }
        conjugate = !changed;
        if let Some(total) = target {
            project_load(&mut p, y, total);
        }
        k += 1;
    };

    // Final state: r = 𝒢p and g from it (convergence is declared only on a
    // fresh gap); the gap is measured from the free set's level.
    let mut contact = 0usize;
    let mut plastic = 0usize;
    let (mut d_sum, mut d_max) = (0.0, 0.0f64);
    for (&pk, gk) in p.iter().zip(g.iter_mut()) {
        *gk -= g_bar;
        if pk > 0.0 {
            contact += 1;
        }
        if pk >= y {
            plastic += 1;
            let d = (-*gk).max(0.0);
            d_sum += d;
            d_max = d_max.max(d);
        }
    }
    let mean_pressure = p.iter().sum::<f64>() / n2 as f64;
    solver.p.clone_from(&p);
    solver.warm = true;
    let approach = match control {
        Control::MeanPressure(_) => g_bar,
        Control::Penetration(d) => d,
    };
    Ok(Solution {
        pressure: p,
        gap: g,
        displacement: r,
        mean_pressure,
        approach,
        contact_fraction: contact as f64 / n2 as f64,
        elastic_fraction: (contact - plastic) as f64 / n2 as f64,
        plastic_fraction: plastic as f64 / n2 as f64,
        plastic_displacement_mean: if plastic > 0 {
            d_sum / plastic as f64
        } else {
            0.0
        },
        plastic_displacement_max: d_max,
        iterations: k,
        residual,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Give the `missing` load to the nodes off the contact (p = 0) in the
/// order of their gap, σY each, the last one the remainder.
fn fill_nearest(p: &mut [f64], g: &[f64], y: f64, missing: f64) {
    let mut off: Vec<usize> = (0..p.len()).filter(|&i| p[i] <= 0.0).collect();
    off.sort_by(|&a, &b| g[a].total_cmp(&g[b]));
    let mut left = missing;
    for i in off {
        if left <= 0.0 {
            break;
        }
        p[i] = left.min(y);
        left -= p[i];
    }
}

/// Iterations of the conjugate gradient without a 10 % drop of ε after which
/// [`projected_gradient`] takes over.
const STALL_ITERATIONS: usize = 100;

/// The convergence measure of a state (see the module docs).
struct Measure {
    eps: f64,
    g_bar: f64,
    off_min: f64,
    nf: usize,
    sum_p: f64,
}

/// ε, ḡ and the largest overlap off the contact of the pressure `p` with
/// the gap `g` (ḡ: the free set's mean gap under load control, else 0).
fn measure(p: &[f64], g: &[f64], y: f64, load_control: bool, sigma_h: f64) -> Measure {
    let (mut nf, mut sum_gf, mut g_max_pl) = (0usize, 0.0, f64::NEG_INFINITY);
    for (&pk, &gk) in p.iter().zip(g) {
        if pk > 0.0 && pk < y {
            nf += 1;
            sum_gf += gk;
        } else if pk >= y {
            g_max_pl = g_max_pl.max(gk);
        }
    }
    let g_bar = match load_control {
        true if nf > 0 => sum_gf / nf as f64,
        true if g_max_pl.is_finite() => g_max_pl,
        _ => 0.0,
    };
    let (mut sum_p, mut num, mut off_min) = (0.0, 0.0, f64::INFINITY);
    for (&pk, &gk) in p.iter().zip(g) {
        let dg = gk - g_bar;
        sum_p += pk;
        if pk <= 0.0 {
            off_min = off_min.min(dg);
        } else if pk < y {
            num += pk * dg.abs();
        } else {
            num += y * dg.max(0.0);
        }
    }
    let eps = if sum_p > 0.0 {
        num / (sum_p * sigma_h)
    } else {
        0.0
    };
    Measure {
        eps,
        g_bar,
        off_min,
        nf,
        sum_p,
    }
}

/// The fallback of a stalled solve: accelerated projected gradient (FISTA,
/// A. Beck & M. Teboulle, SIAM J. Imaging Sci. 2, 183 (2009),
/// doi:10.1137/080716542, with the gradient restart of B. O'Donoghue &
/// E. Candès, Found. Comput. Math. 15, 715 (2015),
/// doi:10.1007/s10208-013-9150-3) on the same energy, step 1/λ_max(𝒢)
/// (power iteration), each step projected exactly onto
/// `{0 ≤ p ≤ σY, Σp = load}` (`p = clamp(v − λ, 0, σY)`, λ by bisection).
/// It returns when the module's criterion holds (checked every 10 steps) or
/// at `max_iterations`, with `p` on the load and `g`, `r` of the last check.
#[allow(clippy::too_many_arguments)]
fn projected_gradient(
    solver: &mut Solver,
    heights: &[f64],
    offset: f64,
    y: f64,
    target: Option<f64>,
    sigma_h: f64,
    opts: &Options,
    k: &mut usize,
    p: &mut [f64],
    g: &mut [f64],
    r: &mut [f64],
    observer: &mut dyn FnMut(Iteration),
) -> Result<()> {
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
        solver.op.apply(&v, r)?;
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
        solver.op.apply(&z, r)?;
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
            solver.op.apply(p, r)?;
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

/// The Euclidean projection onto `{0 ≤ p ≤ y, Σp = total}`:
/// `p ← clamp(p − λ, 0, y)` with λ by bisection (the sum decreases in λ).
fn project_box_load(p: &mut [f64], y: f64, total: f64) {
    let sum = |lam: f64| p.iter().map(|&v| (v - lam).clamp(0.0, y)).sum::<f64>();
    let lo0 = p.iter().copied().fold(f64::INFINITY, f64::min) - y;
    let hi0 = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (mut lo, mut hi) = (lo0, hi0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if sum(mid) > total {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let lam = 0.5 * (lo + hi);
    p.iter_mut().for_each(|v| *v = (*v - lam).clamp(0.0, y));
}

/// Scale the pressure to the load with the bound kept: `p ← min(s p, y)`
/// on the nodes below `y` (the plastic nodes stay at `y`), with
/// `Σ p = total`; all nodes are scaled when the plastic ones alone carry
/// more than the load. Newton's method from below (the sum is concave and
/// piecewise linear in `s`, so every step stays below the root and ends on
/// it after at most one step per saturated group). When even all contact
/// nodes at `y` carry less than the load, they are all set to `y` (the next
/// step's re-entry widens the contact).
fn project_load(p: &mut [f64], y: f64, total: f64) {
    let plastic = p.iter().filter(|&&v| v >= y).count() as f64 * y;
    let (fixed, rest) = if plastic < total {
        (y, total - plastic)
    } else {
        (f64::INFINITY, total)
    };
    let sum: f64 = p.iter().filter(|&&v| v < fixed).sum();
    if sum <= 0.0 {
        return;
    }
    let mut s = rest / sum;
    for _ in 0..200 {
        let (mut f, mut slope) = (0.0, 0.0);
        for &v in p.iter().filter(|&&v| v < fixed) {
            let w = s * v;
            if w < y {
                f += w;
                slope += v;
            } else {
                f += y;
            }
        }
        let miss = rest - f;
        if miss <= 1e-15 * rest || slope <= 0.0 {
            break;
        }
        s += miss / slope;
    }
    p.iter_mut()
        .filter(|v| **v < fixed)
        .for_each(|v| *v = (s * *v).min(y));
}

//! Filling undefined points by harmonic interpolation.
//!
//! # Formula
//! The undefined heights solve the discrete Laplace equation with the defined
//! points as boundary values: for every undefined point p,
//! ```text
//! Σ_{n ∈ N(p)} (h_n − h_p) = 0
//! ```
//! over its 4 grid neighbours (2 along the profile for line scans; across the
//! edges only for periodic surfaces). The system is symmetric positive
//! definite as soon as one point is defined; it is solved by conjugate
//! gradients to a relative residual of 1e-12.

use super::Layout;
use crate::error::{Error, Result};

/// Relative residual at which the conjugate gradients stop.
const TOLERANCE: f64 = 1e-12;

/// Fill the NaN entries of `h` (`ny × nx`); returns how many were filled.
///
/// # Errors
/// [`Error::Inconsistent`] when no point is defined;
/// [`Error::NotConverged`] if the conjugate gradients stall.
pub(crate) fn harmonic_fill(
    h: &mut [f64],
    nx: usize,
    ny: usize,
    layout: Layout,
    periodic: bool,
) -> Result<usize> {
    let unknown: Vec<usize> = (0..h.len()).filter(|&k| !h[k].is_finite()).collect();
    if unknown.is_empty() {
        return Ok(0);
    }
    if unknown.len() == h.len() {
        return Err(Error::Inconsistent {
            name: "heights".into(),
            requirement: "at least one defined point to fill the undefined ones from".into(),
        });
    }
    let mut index = vec![usize::MAX; h.len()];
    for (u, &k) in unknown.iter().enumerate() {
        index[k] = u;
    }
    let neighbours = |k: usize| -> Vec<usize> {
        let (i, j) = (k % nx, k / nx);
        let mut v = Vec::with_capacity(4);
        let mut push = |ii: Option<usize>, jj: Option<usize>| {
            if let (Some(ii), Some(jj)) = (ii, jj) {
                v.push(jj * nx + ii);
            }
        };
        let step = |a: usize, n: usize, d: isize| -> Option<usize> {
            let b = a as isize + d;
            if (0..n as isize).contains(&b) {
                Some(b as usize)
            } else if periodic && n > 2 {
                Some(b.rem_euclid(n as isize) as usize)
            } else {
                None
            }
        };
        push(step(i, nx, -1), Some(j));
        push(step(i, nx, 1), Some(j));
        if layout == Layout::Map {
            push(Some(i), step(j, ny, -1));
            push(Some(i), step(j, ny, 1));
        }
        v
    };
    let nbr: Vec<Vec<usize>> = unknown.iter().map(|&k| neighbours(k)).collect();
    // A x = b with A = degree − adjacency among unknowns, b = Σ known neighbours.
    let apply = |x: &[f64], y: &mut [f64]| {
        for (u, ns) in nbr.iter().enumerate() {
            let mut s = ns.len() as f64 * x[u];
            for &n in ns {
                if index[n] != usize::MAX {
                    s -= x[index[n]];
                }
            }
            y[u] = s;
        }
    };
    let b: Vec<f64> = nbr
        .iter()
        .map(|ns| {
            ns.iter()
                .filter(|&&n| index[n] == usize::MAX)
                .map(|&n| h[n])
                .sum()
        })
        .collect();
    let m = unknown.len();
    let mut x = vec![0.0; m];
    let mut r = b.clone();
    let mut p = r.clone();
    let mut ap = vec![0.0; m];
    let bnorm = b
        .iter()
        .map(|v| v * v)
        .sum::<f64>()
        .sqrt()
        .max(f64::MIN_POSITIVE);
    let mut rr: f64 = r.iter().map(|v| v * v).sum();
    let max_iter = 10 * m + 100;
    let mut it = 0;
    while rr.sqrt() > TOLERANCE * bnorm {
        if it == max_iter {
            return Err(Error::NotConverged {
                what: "harmonic fill of undefined points".into(),
                iterations: it,
                residual: rr.sqrt() / bnorm,
                tolerance: TOLERANCE,
            });
        }
        apply(&p, &mut ap);
        let alpha = rr / p.iter().zip(&ap).map(|(a, b)| a * b).sum::<f64>();
        x.iter_mut().zip(&p).for_each(|(x, p)| *x += alpha * p);
        r.iter_mut().zip(&ap).for_each(|(r, a)| *r -= alpha * a);
        let rr_new: f64 = r.iter().map(|v| v * v).sum();
        let beta = rr_new / rr;
        p.iter_mut().zip(&r).for_each(|(p, r)| *p = r + beta * *p);
        rr = rr_new;
        it += 1;
    }
    for (u, &k) in unknown.iter().enumerate() {
        h[k] = x[u];
    }
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fills_a_plane_exactly() {
        // A plane is harmonic: the fill of interior holes recovers it.
        let (nx, ny) = (7, 5);
        let f = |k: usize| 1.0 + 0.5 * (k % nx) as f64 - 0.25 * (k / nx) as f64;
        let mut h: Vec<f64> = (0..nx * ny).map(f).collect();
        for k in [8, 9, 16, 24] {
            h[k] = f64::NAN;
        }
        assert_eq!(
            harmonic_fill(&mut h, nx, ny, Layout::Map, false).unwrap(),
            4
        );
        for (k, v) in h.iter().enumerate() {
            assert!((v - f(k)).abs() < 1e-10, "{k}: {v} vs {}", f(k));
        }
    }
}

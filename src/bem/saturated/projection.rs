//! The projections of the saturated loop: onto the load with the bound
//! kept, onto the box and the load (Euclidean), and the filling of a
//! missing load.

/// Give the `missing` load to the nodes off the contact (p = 0) in the
/// order of their gap, σY each, the last one the remainder.
pub(super) fn fill_nearest(p: &mut [f64], g: &[f64], y: f64, missing: f64) {
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

/// The Euclidean projection onto `{0 ≤ p ≤ y, Σp = total}`:
/// `p ← clamp(p − λ, 0, y)` with λ by bisection (the sum decreases in λ).
pub(super) fn project_box_load(p: &mut [f64], y: f64, total: f64) {
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
pub(super) fn project_load(p: &mut [f64], y: f64, total: f64) {
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

//! Filling undefined points by harmonic interpolation.
//!
//! # Formula
//! The undefined heights solve the discrete Laplace equation with the defined
//! points as boundary values: for every undefined point p,
//! ```text
//! Σ_{n ∈ N(p)} (h_n − h_p) = 0
//! ```
//! over its 4 grid neighbours (2 along the profile for line scans; across the
//! edges only for periodic surfaces). With the unknowns x = h_p this is
//! `A x = b`: A has the number of neighbours on its diagonal and −1 for each
//! undefined neighbour, b sums the defined neighbours. A is symmetric positive
//! definite as soon as one point is defined (for line scans: one point of each
//! profile; a profile without any defined point has no boundary values and is
//! set to zero).
//!
//! # Solver
//! Conjugate gradients, preconditioned by one multigrid V-cycle, to a relative
//! residual ‖b − A x‖ ≤ 1e-12 ‖b‖ (the true residual, recomputed at the end).
//! The mean of the defined heights is subtracted first (a constant is
//! harmonic, so the solution only shifts by it): b then measures the height
//! variations, not an offset, and the tolerance bounds the residual relative
//! to them. 1e-12 lies well above the rounding of the residual (~ε √m for m
//! unknowns), so it is reached reliably, and the filled heights then agree
//! with a sparse direct solve (as SurfaceTopography's) to a few 1e-12 of the
//! height range (measured on the test files), far below any instrument's
//! resolution.
//!
//! The V-cycle is a geometric multigrid on the masked grid: the unknowns of
//! level l + 1 are those of level l at even grid indices (along x only for
//! line scans); corrections are interpolated bilinearly from them (terms
//! from a coarse point that is not an unknown, i.e. lies on a defined point,
//! are dropped, as for a Dirichlet boundary; beyond a non-periodic edge the
//! last coarse value is continued), the coarse operators are the Galerkin
//! products Pᵀ A P (exact in floating point: the weights are powers of two),
//! smoothing is one Gauss–Seidel sweep before the coarse correction and one
//! in the reverse order after it (so the preconditioner is symmetric positive
//! definite; on the finest level red points, i + j even, before black ones), and the coarsest level is solved by dense Cholesky (or
//! smoothed, if coarsening stops early). Unpreconditioned conjugate gradients
//! need iterations in proportion to the diameter of the largest hole; these
//! need about a dozen (11–14 on the test files, up to 2.3·10⁵ unknowns).

use super::Layout;
use crate::error::{Error, Result};

/// Relative residual at which the conjugate gradients stop.
const TOLERANCE: f64 = 1e-12;
/// Largest coarsest level solved by dense Cholesky.
const DENSE: usize = 64;
/// Symmetric Gauss–Seidel sweeps on a coarsest level too large for Cholesky.
const COARSEST_SWEEPS: usize = 4;

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
    let filled = h.iter().filter(|v| !v.is_finite()).count();
    if filled == 0 {
        return Ok(0);
    }
    if filled == h.len() {
        return Err(Error::Inconsistent {
            name: "heights".into(),
            requirement: "at least one defined point to fill the undefined ones from".into(),
        });
    }
    if u32::try_from(h.len()).is_err() {
        return Err(Error::Inconsistent {
            name: "heights".into(),
            requirement: "fewer than 2³² points to fill undefined ones".into(),
        });
    }
    let (sum, count) = h
        .iter()
        .filter(|v| v.is_finite())
        .fold((0.0, 0usize), |(s, c), &v| (s + v, c + 1));
    let offset = sum / count as f64;
    let line = layout == Layout::LineScans;
    if line {
        // A profile without a defined point is decoupled from the rest and
        // has no boundary values: zero (where conjugate gradients from zero
        // leave it).
        for row in h.chunks_mut(nx) {
            if row.iter().all(|v| !v.is_finite()) {
                row.fill(0.0);
            }
        }
    }

    let fine = Level::fine(h, offset, nx, ny, line, periodic);
    let Some((level, b)) = fine else {
        return Ok(filled);
    };
    let mut levels = vec![level];
    let mut interpolations = Vec::new();
    while levels.last().is_some_and(|l| l.n() > DENSE) {
        let last = levels.last().expect("non-empty");
        let (p, coarse) = last.coarsen(line);
        if coarse.n() == 0 || 5 * coarse.n() > 4 * last.n() {
            break;
        }
        interpolations.push(p);
        levels.push(coarse);
    }
    let coarsest = Coarsest::new(levels.last().expect("non-empty"));
    let mg = Multigrid {
        levels,
        interpolations,
        coarsest,
    };
    let x = mg.pcg(&b)?;
    for (&k, v) in mg.levels[0].pos.iter().zip(x) {
        h[k as usize] = v + offset;
    }
    Ok(filled)
}

/// A symmetric matrix on the unknowns of one grid level: the diagonal and
/// the off-diagonal entries row by row, with the unknowns' grid positions.
struct Level {
    /// Grid size along x and y and whether the grid wraps around (for the
    /// interpolation from the next coarser level).
    gx: usize,
    gy: usize,
    wrap_x: bool,
    wrap_y: bool,
    /// Grid index (x fastest) of each unknown, increasing.
    pos: Vec<u32>,
    diag: Vec<f64>,
    inv_diag: Vec<f64>,
    start: Vec<u32>,
    col: Vec<u32>,
    /// The off-diagonal values; empty on the finest level, where all are −1.
    val: Vec<f64>,
    /// The Gauss–Seidel order (forward; backward is its reverse): on the
    /// finest level the red points (i + j even) first, then the black ones,
    /// so that the updates of a colour do not wait for each other; on the
    /// coarser levels increasing.
    order: Vec<u32>,
}

/// Sparse rows (the interpolation from a coarse level, one row per fine
/// unknown, or its transpose; the off-diagonal part of a coarse operator).
struct Rows {
    start: Vec<u32>,
    col: Vec<u32>,
    val: Vec<f64>,
}

impl Rows {
    fn row(&self, u: usize) -> (&[u32], &[f64]) {
        let (a, b) = (self.start[u] as usize, self.start[u + 1] as usize);
        (&self.col[a..b], &self.val[a..b])
    }

    fn rows(&self) -> usize {
        self.start.len() - 1
    }

    /// The transpose, with `columns` rows.
    fn transpose(&self, columns: usize) -> Rows {
        let mut start = vec![0u32; columns + 1];
        for &c in &self.col {
            start[c as usize + 1] += 1;
        }
        for c in 0..columns {
            start[c + 1] += start[c];
        }
        let mut next: Vec<u32> = start[..columns].to_vec();
        let mut col = vec![0u32; self.col.len()];
        let mut val = vec![0.0; self.col.len()];
        for u in 0..self.rows() {
            let (cs, vs) = self.row(u);
            for (&c, &v) in cs.iter().zip(vs) {
                let slot = next[c as usize] as usize;
                col[slot] = u as u32;
                val[slot] = v;
                next[c as usize] += 1;
            }
        }
        Rows { start, col, val }
    }
}

impl Level {
    fn n(&self) -> usize {
        self.pos.len()
    }

    /// The off-diagonal columns and values of row `u` (no values on the
    /// finest level: all −1).
    fn off(&self, u: usize) -> (&[u32], &[f64]) {
        let (a, b) = (self.start[u] as usize, self.start[u + 1] as usize);
        (&self.col[a..b], self.val.get(a..b).unwrap_or(&[]))
    }

    /// The off-diagonal entries `(column, value)` of row `u`.
    fn entries(&self, u: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let (cols, vals) = self.off(u);
        let unit = vals.is_empty();
        cols.iter()
            .enumerate()
            .map(move |(e, &v)| (v as usize, if unit { -1.0 } else { vals[e] }))
    }

    /// The Laplace system of the undefined points of `h` (less `offset`),
    /// and its right-hand side; `None` when nothing is left undefined.
    fn fine(
        h: &[f64],
        offset: f64,
        nx: usize,
        ny: usize,
        line: bool,
        periodic: bool,
    ) -> Option<(Level, Vec<f64>)> {
        let mut index = vec![u32::MAX; h.len()];
        let mut pos = Vec::new();
        for (k, v) in h.iter().enumerate() {
            if !v.is_finite() {
                index[k] = pos.len() as u32;
                pos.push(k as u32);
            }
        }
        if pos.is_empty() {
            return None;
        }
        let m = pos.len();
        let (wrap_x, wrap_y) = (periodic && nx > 2, periodic && ny > 2 && !line);
        let mut diag = Vec::with_capacity(m);
        let mut b = Vec::with_capacity(m);
        let mut start = Vec::with_capacity(m + 1);
        let mut col = Vec::with_capacity(4 * m);
        start.push(0u32);
        for &k in &pos {
            let k = k as usize;
            let (i, j) = (k % nx, k / nx);
            let mut neighbours = [0usize; 4];
            let mut count = 0;
            let mut push = |n: usize| {
                neighbours[count] = n;
                count += 1;
            };
            if i > 0 {
                push(k - 1);
            } else if wrap_x {
                push(k + nx - 1);
            }
            if i + 1 < nx {
                push(k + 1);
            } else if wrap_x {
                push(k + 1 - nx);
            }
            if !line {
                if j > 0 {
                    push(k - nx);
                } else if wrap_y {
                    push(k + (ny - 1) * nx);
                }
                if j + 1 < ny {
                    push(k + nx);
                } else if wrap_y {
                    push(k - (ny - 1) * nx);
                }
            }
            let mut rhs = 0.0;
            for &n in &neighbours[..count] {
                if index[n] == u32::MAX {
                    rhs += h[n] - offset;
                } else {
                    col.push(index[n]);
                }
            }
            diag.push(count as f64);
            b.push(rhs);
            start.push(col.len() as u32);
        }
        let red = |k: &u32| (*k as usize % nx + *k as usize / nx).is_multiple_of(2);
        let order = (0..m as u32)
            .filter(|&u| red(&pos[u as usize]))
            .chain((0..m as u32).filter(|&u| !red(&pos[u as usize])))
            .collect();
        let level = Level {
            gx: nx,
            gy: ny,
            wrap_x,
            wrap_y,
            pos,
            inv_diag: diag.iter().map(|d| 1.0 / d).collect(),
            diag,
            start,
            col,
            val: Vec::new(),
            order,
        };
        Some((level, b))
    }

    /// The next coarser level (the unknowns at even grid indices; along x
    /// only for line scans) and the interpolation from it.
    fn coarsen(&self, line: bool) -> (Rows, Level) {
        let (cgx, cwrap_x) = coarse_axis(self.gx, self.wrap_x);
        let (cgy, cwrap_y) = if line {
            (self.gy, false)
        } else {
            coarse_axis(self.gy, self.wrap_y)
        };
        let (index, pos) = self.coarse_unknowns(line, cgx, cgy);
        let nc = pos.len();
        let p = self.interpolation(line, cgx, cgy, &index);
        let (diag, off) = self.galerkin(&p, nc);
        let coarse = Level {
            gx: cgx,
            gy: cgy,
            wrap_x: cwrap_x,
            wrap_y: cwrap_y,
            pos,
            inv_diag: diag.iter().map(|d| 1.0 / d).collect(),
            diag,
            start: off.start,
            col: off.col,
            val: off.val,
            order: (0..nc as u32).collect(),
        };
        (p, coarse)
    }

    /// The unknowns of the coarse grid (`cgx × cgy`): those of this level at
    /// even grid indices (along x only for line scans). Returns the coarse
    /// grid's unknown numbers (`u32::MAX` where a point is not one) and the
    /// unknowns' coarse grid positions.
    fn coarse_unknowns(&self, line: bool, cgx: usize, cgy: usize) -> (Vec<u32>, Vec<u32>) {
        let mut index = vec![u32::MAX; cgx * cgy];
        let mut pos = Vec::new();
        for &k in &self.pos {
            let k = k as usize;
            let (i, j) = (k % self.gx, k / self.gx);
            if i % 2 == 0 && (line || j % 2 == 0) {
                let c = (if line { j } else { j / 2 }) * cgx + i / 2;
                index[c] = pos.len() as u32;
                pos.push(c as u32);
            }
        }
        (index, pos)
    }

    /// The interpolation P from the coarse grid (`cgx × cgy`, its unknowns
    /// numbered by `index`): one row per unknown of this level, the products
    /// of the weights along x and y of [`axis_weights`], terms from a coarse
    /// point that is not an unknown dropped.
    fn interpolation(&self, line: bool, cgx: usize, cgy: usize, index: &[u32]) -> Rows {
        let mut p = Rows {
            start: Vec::with_capacity(self.n() + 1),
            col: Vec::with_capacity(4 * self.n()),
            val: Vec::with_capacity(4 * self.n()),
        };
        p.start.push(0);
        for &k in &self.pos {
            let k = k as usize;
            let (i, j) = (k % self.gx, k / self.gx);
            let (xs, nxs) = axis_weights(i, self.gx, cgx, self.wrap_x);
            let (ys, nys) = if line {
                ([(j, 1.0), (0, 0.0)], 1)
            } else {
                axis_weights(j, self.gy, cgy, self.wrap_y)
            };
            for &(cj, wy) in &ys[..nys] {
                for &(ci, wx) in &xs[..nxs] {
                    let c = index[cj * cgx + ci];
                    if c != u32::MAX {
                        p.col.push(c);
                        p.val.push(wx * wy);
                    }
                }
            }
            p.start.push(p.col.len() as u32);
        }
        p
    }

    /// The Galerkin product Pᵀ A P on `nc` coarse unknowns: its diagonal and
    /// its nonzero off-diagonal entries, row by row.
    ///
    /// A dense accumulator over the coarse unknowns: row c₁ sums w₁ a_uv w₂
    /// over the fine u interpolating from c₁, their neighbours v (and u
    /// itself) and the coarse c₂ v interpolates from.
    fn galerkin(&self, p: &Rows, nc: usize) -> (Vec<f64>, Rows) {
        let pt = p.transpose(nc);
        let mut acc = vec![0.0; nc];
        let mut seen = vec![false; nc];
        let mut touched: Vec<u32> = Vec::new();
        let mut diag = vec![0.0; nc];
        let mut start = Vec::with_capacity(nc + 1);
        let mut col = Vec::with_capacity(8 * nc);
        let mut val = Vec::with_capacity(8 * nc);
        start.push(0u32);
        for (c1, d) in diag.iter_mut().enumerate() {
            let (us, ws) = pt.row(c1);
            for (&u, &w1) in us.iter().zip(ws) {
                let u = u as usize;
                for (v, a) in std::iter::once((u, self.diag[u])).chain(self.entries(u)) {
                    let (pc, pv) = p.row(v);
                    for (&c2, &w2) in pc.iter().zip(pv) {
                        if !seen[c2 as usize] {
                            seen[c2 as usize] = true;
                            touched.push(c2);
                        }
                        acc[c2 as usize] += w1 * a * w2;
                    }
                }
            }
            for &c2 in &touched {
                let v = acc[c2 as usize];
                acc[c2 as usize] = 0.0;
                seen[c2 as usize] = false;
                if c2 as usize == c1 {
                    *d = v;
                } else if v != 0.0 {
                    col.push(c2);
                    val.push(v);
                }
            }
            touched.clear();
            start.push(col.len() as u32);
        }
        (diag, Rows { start, col, val })
    }
}

/// One axis of the next coarser grid: its size and whether it wraps. An
/// axis that wraps with an even size halves (and keeps wrapping while over 2
/// points); any other keeps its even indices, the last one included.
fn coarse_axis(g: usize, wrap: bool) -> (usize, bool) {
    if wrap && g.is_multiple_of(2) {
        (g / 2, g / 2 > 2)
    } else {
        (g.div_ceil(2), false)
    }
}

/// The coarse points (index, weight) that index `i` of an axis of `g` points
/// interpolates from, and how many of the two are used: an even index its
/// own coarse point; an odd one the mean of its two even neighbours (across
/// the edge when the axis wraps); past the last even index of a non-periodic
/// axis, that last coarse point (of `cg`).
fn axis_weights(i: usize, g: usize, cg: usize, wrap: bool) -> ([(usize, f64); 2], usize) {
    if i.is_multiple_of(2) {
        ([(i / 2, 1.0), (0, 0.0)], 1)
    } else if i + 1 < g {
        ([(i / 2, 0.5), (i / 2 + 1, 0.5)], 2)
    } else if wrap {
        ([(i / 2, 0.5), (0, 0.5)], 2)
    } else {
        debug_assert!(i / 2 < cg);
        ([(i / 2, 1.0), (0, 0.0)], 1)
    }
}

impl Level {
    /// `y = A x`.
    fn apply(&self, x: &[f64], y: &mut [f64]) {
        if self.val.is_empty() {
            for (u, y) in y.iter_mut().enumerate() {
                let (cols, _) = self.off(u);
                *y = self.diag[u] * x[u] - cols.iter().map(|&v| x[v as usize]).sum::<f64>();
            }
            return;
        }
        for (u, y) in y.iter_mut().enumerate() {
            let (cols, vals) = self.off(u);
            let mut s = self.diag[u] * x[u];
            for (&v, &a) in cols.iter().zip(vals) {
                s += a * x[v as usize];
            }
            *y = s;
        }
    }

    /// `t = r − A x`.
    fn residual(&self, r: &[f64], x: &[f64], t: &mut [f64]) {
        self.apply(x, t);
        t.iter_mut().zip(r).for_each(|(t, r)| *t = r - *t);
    }

    /// One Gauss–Seidel sweep on `A x = r` in the level's order, or in
    /// reverse (`backward`).
    fn sweep(&self, r: &[f64], x: &mut [f64], backward: bool) {
        let unit = self.val.is_empty();
        let step = |u: u32, x: &mut [f64]| {
            let u = u as usize;
            let (cols, vals) = self.off(u);
            let s = if unit {
                r[u] + cols.iter().map(|&v| x[v as usize]).sum::<f64>()
            } else {
                let mut s = r[u];
                for (&v, &a) in cols.iter().zip(vals) {
                    s -= a * x[v as usize];
                }
                s
            };
            x[u] = s * self.inv_diag[u];
        };
        if backward {
            self.order.iter().rev().for_each(|&u| step(u, x));
        } else {
            self.order.iter().for_each(|&u| step(u, x));
        }
    }
}

/// The solver of the coarsest level.
enum Coarsest {
    /// The Cholesky factor L (A = L Lᵀ), dense, row by row.
    Cholesky(Vec<f64>),
    /// Symmetric Gauss–Seidel sweeps.
    Sweeps,
}

impl Coarsest {
    fn new(level: &Level) -> Coarsest {
        let n = level.n();
        if n > DENSE {
            return Coarsest::Sweeps;
        }
        let mut a = vec![0.0; n * n];
        for u in 0..n {
            a[u * n + u] = level.diag[u];
            for (v, w) in level.entries(u) {
                a[u * n + v] = w;
            }
        }
        for j in 0..n {
            let (done, rest) = a.split_at_mut(j * n);
            let row_j = &mut rest[..n];
            for k in 0..j {
                let row_k = &done[k * n..k * n + n];
                let s: f64 = row_j[..k].iter().zip(&row_k[..k]).map(|(a, b)| a * b).sum();
                row_j[k] = (row_j[k] - s) / row_k[k];
            }
            let d = row_j[j] - row_j[..j].iter().map(|v| v * v).sum::<f64>();
            if d <= 0.0 || !d.is_finite() {
                return Coarsest::Sweeps;
            }
            row_j[j] = d.sqrt();
        }
        Coarsest::Cholesky(a)
    }

    /// `x ≈ A⁻¹ r`, a fixed symmetric linear map.
    fn solve(&self, level: &Level, r: &[f64], x: &mut [f64]) {
        match self {
            Coarsest::Cholesky(l) => {
                let n = level.n();
                for i in 0..n {
                    let row = &l[i * n..i * n + i];
                    let s: f64 = row.iter().zip(&x[..i]).map(|(a, b)| a * b).sum();
                    x[i] = (r[i] - s) / l[i * n + i];
                }
                for i in (0..n).rev() {
                    let mut s = x[i];
                    for k in i + 1..n {
                        s -= l[k * n + i] * x[k];
                    }
                    x[i] = s / l[i * n + i];
                }
            }
            Coarsest::Sweeps => {
                x.fill(0.0);
                for _ in 0..COARSEST_SWEEPS {
                    level.sweep(r, x, false);
                    level.sweep(r, x, true);
                }
            }
        }
    }
}

/// The levels, finest first, the interpolations from each level to the one
/// before, and the coarsest solver.
struct Multigrid {
    levels: Vec<Level>,
    interpolations: Vec<Rows>,
    coarsest: Coarsest,
}

/// Work vectors of a level above the coarsest: its residual and the
/// right-hand side and solution of the next coarser level.
struct Buffers {
    t: Vec<f64>,
    cb: Vec<f64>,
    cx: Vec<f64>,
}

impl Multigrid {
    /// `x = M r`: one V-cycle from zero on the levels from `l`.
    fn vcycle(&self, l: usize, bufs: &mut [Buffers], r: &[f64], x: &mut [f64]) {
        let level = &self.levels[l];
        if l + 1 == self.levels.len() {
            self.coarsest.solve(level, r, x);
            return;
        }
        let (buf, rest) = bufs.split_first_mut().expect("a buffer per level");
        x.fill(0.0);
        level.sweep(r, x, false);
        level.residual(r, x, &mut buf.t);
        let p = &self.interpolations[l];
        buf.cb.fill(0.0);
        for (u, &t) in buf.t.iter().enumerate() {
            let (cs, ws) = p.row(u);
            for (&c, &w) in cs.iter().zip(ws) {
                buf.cb[c as usize] += w * t;
            }
        }
        self.vcycle(l + 1, rest, &buf.cb, &mut buf.cx);
        for (u, x) in x.iter_mut().enumerate() {
            let (cs, ws) = p.row(u);
            for (&c, &w) in cs.iter().zip(ws) {
                *x += w * buf.cx[c as usize];
            }
        }
        level.sweep(r, x, true);
    }

    /// Preconditioned conjugate gradients on the finest level from zero, to
    /// a true relative residual of [`TOLERANCE`].
    fn pcg(&self, b: &[f64]) -> Result<Vec<f64>> {
        let a = &self.levels[0];
        let m = a.n();
        let mut bufs: Vec<Buffers> = self.levels[..self.levels.len() - 1]
            .iter()
            .zip(&self.levels[1..])
            .map(|(f, c)| Buffers {
                t: vec![0.0; f.n()],
                cb: vec![0.0; c.n()],
                cx: vec![0.0; c.n()],
            })
            .collect();
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(a, b)| a * b).sum::<f64>();
        let bnorm = dot(b, b).sqrt().max(f64::MIN_POSITIVE);
        let mut x = vec![0.0; m];
        let mut r = b.to_vec();
        let mut z = vec![0.0; m];
        let mut p = vec![0.0; m];
        let mut ap = vec![0.0; m];
        let max_iter = 10 * m + 100;
        let mut it = 0;
        let mut rr = dot(&r, &r);
        // Each pass starts from the true residual; it ends when the
        // recurrence's residual meets the tolerance.
        while rr.sqrt() > TOLERANCE * bnorm {
            self.vcycle(0, &mut bufs, &r, &mut z);
            p.copy_from_slice(&z);
            let mut rz = dot(&r, &z);
            while rr.sqrt() > TOLERANCE * bnorm {
                if it == max_iter {
                    return Err(Error::NotConverged {
                        what: "harmonic fill of undefined points".into(),
                        iterations: it,
                        residual: rr.sqrt() / bnorm,
                        tolerance: TOLERANCE,
                    });
                }
                a.apply(&p, &mut ap);
                let alpha = rz / dot(&p, &ap);
                x.iter_mut().zip(&p).for_each(|(x, p)| *x += alpha * p);
                r.iter_mut().zip(&ap).for_each(|(r, a)| *r -= alpha * a);
                rr = dot(&r, &r);
                it += 1;
                if rr.sqrt() <= TOLERANCE * bnorm {
                    break;
                }
                self.vcycle(0, &mut bufs, &r, &mut z);
                let rz_new = dot(&r, &z);
                let beta = rz_new / rz;
                p.iter_mut().zip(&z).for_each(|(p, z)| *p = z + beta * *p);
                rz = rz_new;
            }
            a.residual(b, &x, &mut r);
            rr = dot(&r, &r);
        }
        Ok(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest residual of the Laplace equation at the filled points,
    /// relative to the height range.
    fn laplace_residual(h: &[f64], filled: &[bool], nx: usize, line: bool, periodic: bool) -> f64 {
        let ny = h.len() / nx;
        let (lo, hi) = h
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, u), &v| (l.min(v), u.max(v)));
        let mut worst: f64 = 0.0;
        for k in (0..h.len()).filter(|&k| filled[k]) {
            let (i, j) = (k % nx, k / nx);
            let mut s = 0.0;
            let mut add = |ii: isize, jj: isize, n: usize, inside: bool| {
                let (ii, jj) = (ii.rem_euclid(nx as isize), jj.rem_euclid(ny as isize));
                if inside || (periodic && n > 2) {
                    s += h[jj as usize * nx + ii as usize] - h[k];
                }
            };
            let (ii, jj) = (i as isize, j as isize);
            add(ii - 1, jj, nx, i > 0);
            add(ii + 1, jj, nx, i + 1 < nx);
            if !line {
                add(ii, jj - 1, ny, j > 0);
                add(ii, jj + 1, ny, j + 1 < ny);
            }
            worst = worst.max(s.abs() / (hi - lo));
        }
        worst
    }

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

    #[test]
    fn fills_a_large_hole_in_a_bilinear_map_exactly() {
        // a + b x + c y + d x y is discretely harmonic: an interior hole of
        // 8·10³ points (several multigrid levels), on a large offset.
        let (nx, ny) = (131, 97);
        let f = |k: usize| {
            let (x, y) = ((k % nx) as f64, (k / nx) as f64);
            5e3 + 0.3 * x - 0.2 * y + 0.01 * x * y
        };
        let mut h: Vec<f64> = (0..nx * ny).map(f).collect();
        let mut count = 0;
        for (k, v) in h.iter_mut().enumerate() {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            if (i - 65.0).powi(2) / 3600.0 + (j - 48.0).powi(2) / 2025.0 < 1.0 {
                *v = f64::NAN;
                count += 1;
            }
        }
        assert!(count > 8_000);
        assert_eq!(
            harmonic_fill(&mut h, nx, ny, Layout::Map, false).unwrap(),
            count
        );
        let range = f(nx * ny - 1) - f(0);
        for (k, v) in h.iter().enumerate() {
            assert!((v - f(k)).abs() < 1e-10 * range, "{k}: {v} vs {}", f(k));
        }
    }

    #[test]
    fn solves_the_laplace_equation_periodic_and_line_scans() {
        // Holes across the edges of a rough periodic map (odd and even
        // sizes), and line scans with long gaps and one empty profile.
        for (nx, ny, layout, periodic) in [
            (64, 48, Layout::Map, true),
            (63, 45, Layout::Map, true),
            (50, 30, Layout::Map, false),
            (200, 6, Layout::LineScans, false),
            (201, 6, Layout::LineScans, true),
        ] {
            let line = layout == Layout::LineScans;
            let mut h: Vec<f64> = (0..nx * ny)
                .map(|k| ((k * 7919) % 1013) as f64 * 1e-3 + ((k % nx) as f64 * 0.1).sin())
                .collect();
            let filled: Vec<bool> = (0..nx * ny)
                .map(|k| {
                    let (i, j) = (k % nx, k / nx);
                    (line && j == 2)
                        || (i + 5) % nx < 30 && (j + 3) % ny < 20
                        || (line && i % 7 != 0 && j != 0)
                })
                .collect();
            for (v, &f) in h.iter_mut().zip(&filled) {
                if f {
                    *v = f64::NAN;
                }
            }
            let count = filled.iter().filter(|&&f| f).count();
            assert_eq!(
                harmonic_fill(&mut h, nx, ny, layout, periodic).unwrap(),
                count
            );
            if line {
                assert!(h[2 * nx..3 * nx].iter().all(|&v| v == 0.0));
            }
            let e = laplace_residual(&h, &filled, nx, line, periodic);
            assert!(e < 1e-10, "{nx}×{ny} {layout:?} periodic {periodic}: {e:e}");
        }
    }
}

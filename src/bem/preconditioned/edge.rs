//! The edge correction of the preconditioner (module docs of [`super`],
//! "Method"): the Schur term `𝒦_FN 𝒦_NN⁻¹ 𝒦_NF r` by a (2R+1)² stencil of
//! 𝒦's kernel and a weighted Jacobi `𝒦_NN⁻¹ ≈ ω/d`, ω by the node's held
//! neighbours, in one pass over rows kept in a ring.

use super::{free, residual_row, Precond};
use crate::bem::steps::LANES;
use crate::bem::workspace::Workspace;
use crate::error::Result;

/// Half-width R of the edge correction's stencil (a (2R+1)² window).
pub(super) const EDGE_RADIUS: usize = 3;

// The free operator returns 𝒦r on a margin as wide as the stencil's reach.
const _: () = assert!(crate::bem::kernel::FREE_MARGIN == EDGE_RADIUS);

/// Weight ω₀ of the edge correction (`X = diag(ω) D⁻¹ ≈ 𝒦_NN⁻¹`) at a held
/// node whose eight neighbours are all free (see [`held_weight`]).
pub(super) const EDGE_WEIGHT: f64 = 1.25;

/// Rise ω₁ of the weight from a held node with no held neighbour to one
/// with eight (see [`held_weight`]).
pub(super) const EDGE_WEIGHT_RISE: f64 = 1.0;

/// ω of a held node with `held` of its eight neighbours held too:
/// `ω = ω₀ + ω₁ · held / 8`.
///
/// The exact `𝒦_NN⁻¹` is 1/d at a held node among free ones; inside a held
/// cluster its row sums grow (11.6/d at the centre of a 15 × 15 block), so
/// a weight that grows with the held neighbours follows it where one
/// constant cannot (module docs).
#[inline]
fn held_weight(held: f64) -> f64 {
    EDGE_WEIGHT + EDGE_WEIGHT_RISE * held / 8.0
}

/// Rows in the edge correction's window.
const EDGE_ROWS: usize = 2 * EDGE_RADIUS + 1;

/// The edge correction of the preconditioner: `z = [F](𝒦r − 𝒦_loc w)`,
/// `w = ω [N] 𝒦r / d` (module docs), row by row with a ring of the
/// 2R + 1 rows of w that a row of z needs. With the free boundary the
/// padding is held at p = 0 like the nodes of N: w there is its 𝒦r, which
/// the operator returns on a margin of R nodes around the window.
pub(crate) struct Edge {
    n: usize,
    sides: Sides,
    /// Free: 𝒦r on the margin's rows −R … −1 and N … N + R − 1 (each
    /// `N + 2R` wide, columns −R … N + R − 1).
    band: Vec<f64>,
    /// Free: 𝒦r on the margin's columns of rows 0 … N − 1 (R left, then R
    /// right, per row).
    flank: Vec<f64>,
    /// `k(dy, dx) / d` for |dy|, |dx| ≤ R (0 at the centre); ω is in w.
    coeff: [[f64; EDGE_ROWS]; EDGE_ROWS],
    /// Rows of w, each padded by R on both sides (wrapped periodic, the
    /// padding's 𝒦r free), in ring slots; then rows 0 … R − 1 again (kept for the
    /// periodic wrap at the last rows, whose 𝒦r has been overwritten by z).
    rows: Vec<f64>,
    /// Per row of `rows`: whether block b (of [`BLOCK`] columns) of w has a
    /// non-zero entry.
    nonzero: Vec<bool>,
    /// Per ring slot: `m_F` of the row's nodes.
    mask: Vec<f64>,
    /// The correction of one row.
    acc: Vec<f64>,
    /// Held nodes around the row being loaded.
    held: HeldRows,
}

impl Edge {
    /// The stencil of 𝒦 (with `mean_stiffness` for the mean mode, as the
    /// preconditioner) from one application to a unit pressure at the
    /// grid's centre; `None` on grids with fewer than 2R + 2 rows.
    pub fn new(ws: &mut Workspace, mean_stiffness: f64) -> Result<Option<Self>> {
        let f = ws.fields();
        let n = f.op.n();
        if n < EDGE_ROWS + 1 {
            return Ok(None);
        }
        let c = n / 2;
        let mut k = [[0.0f64; EDGE_ROWS]; EDGE_ROWS];
        f.op.apply_stiffness_rows_with_mean(
            mean_stiffness,
            &mut |i, row| {
                row.fill(0.0);
                if i == c {
                    row[c] = 1.0;
                }
            },
            &mut |i, row| {
                if i + EDGE_RADIUS >= c && i <= c + EDGE_RADIUS {
                    let dy = i + EDGE_RADIUS - c;
                    k[dy].copy_from_slice(&row[c - EDGE_RADIUS..=c + EDGE_RADIUS]);
                }
            },
        )?;
        let d = k[EDGE_RADIUS][EDGE_RADIUS];
        if d.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return Ok(None);
        }
        // 𝒦's kernel is even in x and y and symmetric under x ↔ y: the
        // mean of the eight images (exactly symmetric, as the correction's
        // sums by pairs assume).
        let mut coeff = [[0.0f64; EDGE_ROWS]; EDGE_ROWS];
        for (dy, row) in coeff.iter_mut().enumerate() {
            for (dx, c) in row.iter_mut().enumerate() {
                let (ry, rx) = (EDGE_ROWS - 1 - dy, EDGE_ROWS - 1 - dx);
                let images = [
                    k[dy][dx], k[ry][dx], k[dy][rx], k[ry][rx], k[dx][dy], k[rx][dy], k[dx][ry],
                    k[rx][ry],
                ];
                *c = images.iter().sum::<f64>() / (8.0 * d);
            }
        }
        coeff[EDGE_RADIUS][EDGE_RADIUS] = 0.0;
        let slots = EDGE_ROWS + EDGE_RADIUS;
        // The free operator keeps a margin of R nodes on grids of 2R or
        // more (all those with a stencil).
        let (sides, margin) = match f.op.boundary() {
            crate::bem::Boundary::Periodic => (Sides::Periodic, 0),
            crate::bem::Boundary::Free => (Sides::Padding, f.op.margin()),
        };
        if sides == Sides::Padding && margin != EDGE_RADIUS {
            return Ok(None);
        }
        Ok(Some(Edge {
            n,
            sides,
            band: vec![0.0; 2 * margin * (n + 2 * margin)],
            flank: vec![0.0; 2 * margin * n],
            coeff,
            rows: vec![0.0; slots * (n + 2 * EDGE_RADIUS)],
            nonzero: vec![false; slots * n.div_ceil(BLOCK)],
            mask: vec![0.0; slots * n],
            acc: vec![0.0; n],
            held: HeldRows::new(n),
        }))
    }

    /// Write w of grid row `i` (−R ≤ i < n + R; outside the grid: the
    /// periodic image or the padding's 𝒦r) into slot `slot`, from
    /// z = 𝒦r off F.
    #[allow(clippy::too_many_arguments)]
    fn load(&mut self, slot: usize, i: isize, p: &[f64], g: &[f64], z: &[f64], g_bar: f64, y: f64) {
        let (n, r) = (self.n, EDGE_RADIUS);
        let (width, nb) = (n + 2 * r, n.div_ceil(BLOCK));
        let ni = n as isize;
        let src = if (0..ni).contains(&i) {
            Some(i as usize)
        } else if self.sides == Sides::Periodic {
            Some(i.rem_euclid(ni) as usize)
        } else {
            None
        };
        let (rows, nonzero) = (&mut self.rows, &mut self.nonzero);
        let (out, flags) = match src {
            // Rows 0 … R − 1 past the last row: the copies made first.
            Some(w) if w < r && i >= ni => {
                let kept = EDGE_ROWS + w;
                rows.copy_within(kept * width..(kept + 1) * width, slot * width);
                nonzero.copy_within(kept * nb..(kept + 1) * nb, slot * nb);
                return;
            }
            Some(w) => (w, true),
            None => (0, false),
        };
        let row = &mut rows[slot * width..(slot + 1) * width];
        let flag = &mut nonzero[slot * nb..(slot + 1) * nb];
        if !flags {
            // Not a grid row and not periodic: a row of the padding, all of
            // it held at p = 0.
            let b = if i < 0 {
                i + r as isize
            } else {
                i - ni + r as isize
            } as usize;
            let padding = held_weight(8.0);
            for (w, k) in row.iter_mut().zip(&self.band[b * width..(b + 1) * width]) {
                *w = padding * k;
            }
            flag.fill(true);
            return;
        }
        let sides = self.sides;
        let (columns, own) = self.held.columns(sides, out, (p, g), (g_bar, y));
        let z = &z[out * n..(out + 1) * n];
        let mask = &mut self.mask[slot * n..(slot + 1) * n];
        for (b, fl) in flag.iter_mut().enumerate() {
            let cols = b * BLOCK..((b + 1) * BLOCK).min(n);
            let mut any = false;
            for j in cols {
                mask[j] = 1.0 - own[j];
                // Held neighbours: the 3 × 3 block's held nodes less this one.
                let held = columns[j] + columns[j + 1] + columns[j + 2] - own[j];
                let v = own[j] * held_weight(held) * z[j];
                row[r + j] = v;
                any |= v != 0.0;
            }
            *fl = any;
        }
        match sides {
            Sides::Periodic => {
                row.copy_within(n..n + r, 0);
                row.copy_within(r..2 * r, n + r);
            }
            Sides::Padding => {
                let padding = held_weight(8.0);
                let flank = &self.flank[out * 2 * r..(out + 1) * 2 * r];
                for (w, k) in row[..r].iter_mut().zip(&flank[..r]) {
                    *w = padding * k;
                }
                for (w, k) in row[n + r..].iter_mut().zip(&flank[r..]) {
                    *w = padding * k;
                }
            }
        }
    }

    /// The preconditioner pass with the edge correction (as [`precondition`]:
    /// z into `response`, with its sums).
    pub fn precondition(
        &mut self,
        ws: &mut Workspace,
        g_bar: f64,
        y: f64,
        mean_stiffness: f64,
    ) -> Result<Precond> {
        let f = ws.fields();
        let n = self.n;
        let (p, g, t) = (&*f.pressure, &*f.gap, &*f.direction);
        let z = &mut *f.response;
        let mut acc = Precond::default();
        let mut fill_sums = [0.0f64; 4];
        let r = f.op.margin();
        let (band, flank) = (&mut self.band, &mut self.flank);
        f.op.apply_stiffness_rows_with_margin(
            mean_stiffness,
            &mut |i, row| {
                let k = i * n..(i + 1) * n;
                let s = residual_row(&p[k.clone()], &g[k.clone()], &t[k], g_bar, y, row);
                for (a, b) in fill_sums.iter_mut().zip(s) {
                    *a += b;
                }
            },
            &mut |i, row| match usize::try_from(i) {
                Ok(i) if i < n => {
                    z[i * n..(i + 1) * n].copy_from_slice(&row[r..r + n]);
                    if !flank.is_empty() {
                        let out = &mut flank[i * 2 * r..(i + 1) * 2 * r];
                        out[..r].copy_from_slice(&row[..r]);
                        out[r..].copy_from_slice(&row[n + r..]);
                    }
                }
                // The margin's rows (free only): −R … −1, then N … N + R − 1.
                _ if !band.is_empty() => {
                    let b = if i < 0 {
                        i + r as isize
                    } else {
                        i - n as isize + r as isize
                    };
                    let width = n + 2 * r;
                    band[b as usize * width..(b as usize + 1) * width].copy_from_slice(row);
                }
                _ => {}
            },
        )?;
        [acc.free, acc.sum_r, acc.r_t, acc.sum_t] = fill_sums;
        // z holds 𝒦r; w is read from it off F, where z is written only
        // after its row has been loaded (rows 0 … R − 1 are kept first).
        let (width, nb) = (n + 2 * EDGE_RADIUS, n.div_ceil(BLOCK));
        let r = EDGE_RADIUS as isize;
        self.held.clear();
        for i in 0..EDGE_RADIUS {
            self.load(EDGE_ROWS + i, i as isize, p, g, z, g_bar, y);
        }
        // Ring slot of grid row i (−R ≤ i < n + R).
        let slot = |i: isize| (i + r).rem_euclid(EDGE_ROWS as isize) as usize;
        for i in -r..r {
            self.load(slot(i), i, p, g, z, g_bar, y);
        }
        let (mut r_z, mut sum_z) = (0.0, 0.0);
        for i in 0..n {
            let next = i as isize + r;
            self.load(slot(next), next, p, g, z, g_bar, y);
            let k = i * n..(i + 1) * n;
            let window: [(&[f64], &[bool]); EDGE_ROWS] = std::array::from_fn(|dy| {
                let s = slot(i as isize + dy as isize - r);
                (
                    &self.rows[s * width..(s + 1) * width],
                    &self.nonzero[s * nb..(s + 1) * nb],
                )
            });
            let mask = &self.mask[slot(i as isize) * n..(slot(i as isize) + 1) * n];
            stencil_row(&self.coeff, &window, self.sides, mask, &mut self.acc);
            let s = restrict_corrected(mask, &g[k.clone()], g_bar, &self.acc, &mut z[k]);
            r_z += s[0];
            sum_z += s[1];
        }
        acc.r_z = r_z;
        acc.sum_z = sum_z;
        Ok(acc)
    }
}

/// One row of `z = [F](𝒦r − c)` in place (z holds 𝒦r, `m` is `m_F`);
/// returns `[Σ r z, Σ z]`.
fn restrict_corrected(m: &[f64], g: &[f64], g_bar: f64, c: &[f64], z: &mut [f64]) -> [f64; 2] {
    let mut acc = [[0.0f64; LANES]; 2];
    let chunks = m
        .chunks(LANES)
        .zip(g.chunks(LANES))
        .zip(c.chunks(LANES))
        .zip(z.chunks_mut(LANES));
    for (((mc, gc), cc), zc) in chunks {
        for l in 0..mc.len() {
            let v = mc[l] * (zc[l] - cc[l]);
            zc[l] = v;
            acc[0][l] += mc[l] * (gc[l] - g_bar) * v;
            acc[1][l] += v;
        }
    }
    acc.map(|a| a.iter().sum())
}

/// The held nodes (`1 − m_F`) of three grid rows at a time, kept across
/// the loads of one preconditioner pass (rows come in order, so each is
/// evaluated about once), and their sums over the rows `i − 1 … i + 1`.
struct HeldRows {
    /// The grid row in each slot (`usize::MAX`: none).
    which: [usize; 3],
    /// Three rows of `1 − m_F`.
    rows: Vec<f64>,
    /// Held nodes of rows `i − 1 … i + 1` per column `−1 … N`.
    columns: Vec<f64>,
}

impl HeldRows {
    fn new(n: usize) -> Self {
        HeldRows {
            which: [usize::MAX; 3],
            rows: vec![0.0; 3 * n],
            columns: vec![0.0; n + 2],
        }
    }

    /// Forget the rows (p or g changed).
    fn clear(&mut self) {
        self.which = [usize::MAX; 3];
    }

    /// Held nodes (1 each) of grid rows `i − 1 … i + 1` in each column
    /// `−1 … N` (N + 2 values): periodic images beyond the sides, or the
    /// padding, all of it held; and row i's own `1 − m_F`.
    fn columns(
        &mut self,
        sides: Sides,
        i: usize,
        (p, g): (&[f64], &[f64]),
        (g_bar, y): (f64, f64),
    ) -> (&[f64], &[f64]) {
        let n = self.columns.len() - 2;
        let wanted = [-1isize, 0, 1].map(|di| {
            let row = i as isize + di;
            match sides {
                Sides::Periodic => Some(row.rem_euclid(n as isize) as usize),
                Sides::Padding => usize::try_from(row).ok().filter(|&r| r < n),
            }
        });
        let out = &mut self.columns;
        out.fill(0.0);
        let mut own = 0;
        for row in wanted {
            let Some(row) = row else {
                out[1..=n].iter_mut().for_each(|o| *o += 1.0);
                continue;
            };
            let slot = match self.which.iter().position(|&w| w == row) {
                Some(slot) => slot,
                None => {
                    let slot = (0..3)
                        .find(|&s| !wanted.contains(&Some(self.which[s])))
                        .expect("three slots, at most two other rows wanted");
                    let k = row * n..(row + 1) * n;
                    let held = &mut self.rows[slot * n..(slot + 1) * n];
                    for ((h, &p), &g) in held.iter_mut().zip(&p[k.clone()]).zip(&g[k]) {
                        *h = 1.0 - free(p, g, g_bar, y);
                    }
                    self.which[slot] = row;
                    slot
                }
            };
            if row == i {
                own = slot;
            }
            for (o, h) in out[1..=n]
                .iter_mut()
                .zip(&self.rows[slot * n..(slot + 1) * n])
            {
                *o += h;
            }
        }
        (out[0], out[n + 1]) = match sides {
            Sides::Periodic => (out[n], out[1]),
            Sides::Padding => (3.0, 3.0),
        };
        (out, &self.rows[own * n..(own + 1) * n])
    }
}

/// Nodes per block of [`stencil_row`] (the block's sums stay in registers).
const BLOCK: usize = 8;

/// What lies beyond the grid's sides in the edge correction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Sides {
    /// The periodic images of the grid.
    Periodic,
    /// The free boundary's padding, with its 𝒦r on a margin of R nodes.
    Padding,
}

/// `acc = Σ c(dy, dx) w(i + dy, j + dx)` of one row over the window of
/// 2R + 1 rows of w (padded by R, with their blocks' non-zero flags);
/// blocks without a free node (`mask` = m_F of the row) or without a non-zero w within
/// reach are left at 0 (z is restricted to F, and the sum would be 0).
fn stencil_row(
    coeff: &[[f64; EDGE_ROWS]; EDGE_ROWS],
    window: &[(&[f64], &[bool]); EDGE_ROWS],
    sides: Sides,
    mask: &[f64],
    acc: &mut [f64],
) {
    let n = acc.len();
    let nb = n.div_ceil(BLOCK);
    for b in 0..nb {
        let j0 = b * BLOCK;
        let len = BLOCK.min(n - j0);
        let mut a = [0.0f64; BLOCK];
        let any_free = mask[j0..j0 + len].iter().any(|&m| m > 0.0);
        // R < BLOCK: the window's columns lie in blocks b − 1 … b + 1.
        let beyond = |f: bool| match sides {
            Sides::Periodic => f,
            Sides::Padding => true,
        };
        let near = |f: &[bool]| {
            let left = if b > 0 { f[b - 1] } else { beyond(f[nb - 1]) };
            let right = if b + 1 < nb { f[b + 1] } else { beyond(f[0]) };
            left | f[b] | right
        };
        if any_free && window.iter().any(|(_, f)| near(f)) {
            // The stencil is symmetric: sum the rows i ± dy first (v), then
            // the columns j ± dx.
            const W: usize = BLOCK + 2 * EDGE_RADIUS;
            let mut v = [[0.0f64; W]; EDGE_RADIUS + 1];
            let cols = j0..j0 + len + 2 * EDGE_RADIUS;
            v[0][..cols.len()].copy_from_slice(&window[EDGE_RADIUS].0[cols.clone()]);
            for (dy, vk) in v.iter_mut().enumerate().skip(1) {
                let (up, down) = (window[EDGE_RADIUS - dy].0, window[EDGE_RADIUS + dy].0);
                for ((o, &a), &b) in vk
                    .iter_mut()
                    .zip(&up[cols.clone()])
                    .zip(&down[cols.clone()])
                {
                    *o = a + b;
                }
            }
            for (vk, c) in v.iter().zip(&coeff[EDGE_RADIUS..]) {
                let c = &c[EDGE_RADIUS..];
                for (l, al) in a.iter_mut().enumerate() {
                    let m = l + EDGE_RADIUS;
                    let mut s = c[0] * vk[m];
                    for dx in 1..=EDGE_RADIUS {
                        s += c[dx] * (vk[m + dx] + vk[m - dx]);
                    }
                    *al += s;
                }
            }
        }
        acc[j0..j0 + len].copy_from_slice(&a[..len]);
    }
}

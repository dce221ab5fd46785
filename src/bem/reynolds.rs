//! Exact flow through one gap field: Reynolds' equation by finite volumes.
//!
//! # What it solves
//! ```text
//! ∇·(σ(x) ∇p) = 0,   σ = g³/(12η)   (g = 0 in contact)
//! p = P_in on the inlet row, p = P_out on the outlet row, periodic across the flow
//! Q = −∫ σ ∂p/∂x dy through any cross-section,   σ_eff = Q (N−1)Δ / (N Δ (P_in − P_out))
//! ```
//! on the `N × N` nodes of a BEM field of side L (spacing Δ = L/N), for the
//! flow along x (along the second, contiguous index j of `f[i·N + j]`) or
//! along y (along i). The inlet row is the first line of nodes across the
//! flow, the outlet row the last: the flow path is (N − 1)Δ long and N Δ = L
//! wide (periodic across). σ_eff is the flow conductivity of the field as a
//! medium, q = −σ_eff ∇p on average, m³/(Pa s); a seal of width L_x and
//! length L_y then leaks Q = (L_y/L_x) σ_eff Δ ([`crate::leakage::Seal`]).
//!
//! # Discretisation
//! One finite volume per node (the BEM's collocation cell, where the gap is
//! one value); the flux through the face between neighbours i and j is
//! c_ij (p_i − p_j) with the **harmonic mean** c_ij = 2σ_iσ_j/(σ_i + σ_j)
//! (the face is Δ wide and the nodes Δ apart, so the geometric factor is 1).
//! The harmonic mean is the exact conductance of two half-cells of constant
//! gap in series, so a gap that varies only along the flow gives exactly the
//! series resistance Σ 1/c of its faces and one varying only across it the
//! parallel sum; and a face touching a contact node (σ = 0) carries nothing,
//! so no channel passes through contact (Patankar, *Numerical Heat Transfer
//! and Fluid Flow* (1980), §4.2-3). The arithmetic mean would let fluid
//! through a contact node from a neighbour.
//!
//! # Method
//! Nodes joined to the inlet by faces of c > 0 are found by a breadth-first
//! search; the field **percolates** when that set reaches the outlet row.
//! Otherwise Q = 0 exactly and nothing is solved. Else the unknown pressures
//! of every node connected to a fixed row form a symmetric positive definite
//! system, solved by faer's sparse Cholesky in a geometric nested-dissection
//! order (the grid cut by lines of nodes, recursively, the cuts numbered
//! last; George, SIAM J. Numer. Anal. 10, 345 (1973)); nodes connected to
//! neither row carry no flow and keep p = NaN in the returned field.
//! σ is scaled by its largest value before assembly. Q is the mean of the
//! inflow and the outflow; their difference (zero in exact arithmetic, by
//! conservation) plus a rounding term is the error bound.
//!
//! # References
//! - O. Reynolds, Phil. Trans. R. Soc. Lond. 177, 157 (1886) (the thin-film equation).
//! - S. V. Patankar, *Numerical Heat Transfer and Fluid Flow*, Hemisphere (1980), §4.2-3.
//! - W. B. Dapp, A. Lücke, B. N. J. Persson, M. H. Müser, Phys. Rev. Lett.
//!   108, 244301 (2012) (the same flow on GFMD gaps, against the critical junction).

use std::collections::VecDeque;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::cholesky::{factorize_symbolic_cholesky, LltRef, SymmetricOrdering};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, Par, Side};
use serde::Serialize;

use super::Solution;
use crate::error::{check, Error, Result};

pub use crate::leakage::FlowDirection;

/// A gap field on the BEM grid: `N × N` row-major gaps ≥ 0 (m), 0 in contact.
#[derive(Debug, Clone, PartialEq)]
pub struct GapField {
    n: usize,
    size: f64,
    gap: Vec<f64>,
}

impl GapField {
    /// A field from gaps (m) on an `n × n` grid of side `size` (m).
    ///
    /// # Errors
    /// `n < 3`, `size` not finite and positive, wrong length, a gap negative
    /// or not finite ([`Error::InvalidParameter`] naming `gap`).
    pub fn new(n: usize, size: f64, gap: Vec<f64>) -> Result<Self> {
        check::positive("size", size)?;
        if n < 3 {
            return Err(Error::invalid("grid", n as f64, ">= 3"));
        }
        if gap.len() != n * n {
            return Err(Error::invalid(
                "gap",
                gap.len() as f64,
                format!("N² = {} values", n * n),
            ));
        }
        for &g in &gap {
            check::non_negative("gap", g)?;
        }
        Ok(GapField { n, size, gap })
    }

    /// The gap of a BEM solution: 0 where p > 0 (the contact, whose gap is
    /// zero only up to the solver's tolerance), max(g, 0) elsewhere.
    ///
    /// # Errors
    /// As [`GapField::new`].
    pub fn from_solution(solution: &Solution, n: usize, size: f64) -> Result<Self> {
        let gap = solution
            .gap
            .iter()
            .zip(&solution.pressure)
            .map(|(&g, &p)| if p > 0.0 { 0.0 } else { g.max(0.0) })
            .collect();
        Self::new(n, size, gap)
    }

    /// Grid side N.
    pub fn n(&self) -> usize {
        self.n
    }

    /// Side L, m.
    pub fn size(&self) -> f64 {
        self.size
    }

    /// The gaps, row-major, m.
    pub fn gap(&self) -> &[f64] {
        &self.gap
    }

    /// The same field transposed (x ↔ y).
    pub fn transposed(&self) -> GapField {
        let n = self.n;
        let gap = (0..n * n).map(|k| self.gap[(k % n) * n + k / n]).collect();
        GapField {
            n,
            size: self.size,
            gap,
        }
    }
}

/// The exact flow through a gap field.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ReynoldsFlow {
    /// Direction of the mean flow.
    pub direction: FlowDirection,
    /// Whether the non-contact region connects inlet and outlet.
    pub percolates: bool,
    /// σ_eff = Q (N−1)Δ/(N Δ ΔP), m³/(Pa s) (0 when it does not percolate).
    pub effective_flow_conductivity: f64,
    /// Bound on the absolute error of σ_eff (conservation defect + rounding).
    pub effective_flow_conductivity_error_bound: f64,
    /// Unknown pressures solved for.
    pub unknowns: usize,
    /// Wall time of the solve, s.
    pub seconds: f64,
    /// The pressure field for P_in = 1, P_out = 0 (NaN on nodes connected to
    /// neither row), row-major.
    #[serde(skip)]
    pub pressure: Vec<f64>,
}

/// Solve Reynolds' equation on `field` for the flow along `direction`
/// (module docs). `viscosity` η in Pa s.
///
/// # Errors
/// `viscosity` not finite and positive; the sparse factorisation failing
/// (not expected: the system is SPD by construction).
///
/// # Examples
/// ```
/// use persson::bem::reynolds::{flow, FlowDirection, GapField};
/// # fn main() -> persson::Result<()> {
/// // A uniform slot of gap g: σ_eff = g³/(12η) exactly (plane Poiseuille).
/// let (n, g, eta) = (16, 1e-6, 1e-3);
/// let field = GapField::new(n, 1e-3, vec![g; n * n])?;
/// let f = flow(&field, eta, FlowDirection::X)?;
/// let exact = g * g * g / (12.0 * eta);
/// assert!((f.effective_flow_conductivity - exact).abs() < 1e-12 * exact);
/// # Ok(()) }
/// ```
pub fn flow(field: &GapField, viscosity: f64, direction: FlowDirection) -> Result<ReynoldsFlow> {
    check::positive("viscosity", viscosity)?;
    let start = crate::clock::Instant::now();
    let n = field.n;
    let g_max = field.gap.iter().cloned().fold(0.0, f64::max);
    let scale = if g_max > 0.0 { g_max } else { 1.0 };
    let net = Net {
        n,
        direction,
        sigma: field.gap.iter().map(|&g| (g / scale).powi(3)).collect(),
    };
    let from_in = net.reach(0);
    let percolates = (0..n).any(|b| {
        let k = net.node(n - 2, b);
        from_in[k] && net.face(k, net.node(n - 1, b)) > 0.0
    });
    let mut pressure = vec![f64::NAN; n * n];
    for b in 0..n {
        pressure[net.node(0, b)] = 1.0;
        pressure[net.node(n - 1, b)] = 0.0;
    }
    let mut out = ReynoldsFlow {
        direction,
        percolates,
        effective_flow_conductivity: 0.0,
        effective_flow_conductivity_error_bound: 0.0,
        unknowns: 0,
        seconds: 0.0,
        pressure: Vec::new(),
    };
    if percolates {
        let from_out = net.reach(n - 1);
        let (index, matrix, rhs) = net.assemble(&from_in, &from_out)?;
        let order = dissection_order(n, &index, rhs.len(), &|a, b| net.node(a, b));
        let x = cholesky_solve(&matrix, &order, &rhs)?;
        for k in 0..n * n {
            if index[k] != usize::MAX {
                pressure[k] = x[index[k]];
            }
        }
        let (q_in, m_in) = net.flux(&pressure, 0, 1);
        let (q_out, m_out) = net.flux(&pressure, n - 1, n - 2);
        let q = 0.5 * (q_in - q_out);
        // σ_eff = Q (N−1)Δ/(NΔ ΔP) with ΔP = 1; σ = g³/(12η) = scale³ σ̂/(12η)
        let unit = scale * scale * scale / (12.0 * viscosity) * (n - 1) as f64 / n as f64;
        let defect = (q_in + q_out).abs();
        out.effective_flow_conductivity = unit * q;
        out.effective_flow_conductivity_error_bound =
            unit * (defect + 64.0 * f64::EPSILON * (m_in + m_out));
        out.unknowns = rhs.len();
    } else {
        for (k, p) in pressure.iter_mut().enumerate() {
            if p.is_nan() && from_in[k] {
                *p = 1.0;
            }
        }
    }
    out.pressure = pressure;
    out.seconds = start.elapsed().as_secs_f64();
    Ok(out)
}

/// The network of a gap field for one flow direction: node conductances σ̂
/// (scaled by the largest) and the faces between neighbours.
struct Net {
    n: usize,
    direction: FlowDirection,
    sigma: Vec<f64>,
}

/// The unknowns' numbering (`usize::MAX`: not an unknown), the lower
/// triangle of the SPD matrix and the right-hand side (P_in = 1, P_out = 0).
type System = (Vec<usize>, SparseColMat<usize, f64>, Vec<f64>);

impl Net {
    /// Node index of (a along the flow, b across it).
    fn node(&self, a: usize, b: usize) -> usize {
        match self.direction {
            FlowDirection::X => b * self.n + a,
            FlowDirection::Y => a * self.n + b,
        }
    }

    /// Face conductance: the harmonic mean of the two nodes' σ̂ (0 if either is 0).
    fn face(&self, i: usize, j: usize) -> f64 {
        let (a, b) = (self.sigma[i], self.sigma[j]);
        if a > 0.0 && b > 0.0 {
            2.0 * a * b / (a + b)
        } else {
            0.0
        }
    }

    /// Neighbours of (a, b): along the flow within [0, N), across periodic;
    /// `usize::MAX` marks a missing one.
    fn neighbours(&self, a: usize, b: usize) -> [(usize, usize); 4] {
        let n = self.n;
        let mut v = [(usize::MAX, usize::MAX); 4];
        if a > 0 {
            v[0] = (a - 1, b);
        }
        if a + 1 < n {
            v[1] = (a + 1, b);
        }
        v[2] = (a, (b + 1) % n);
        v[3] = (a, (b + n - 1) % n);
        v
    }

    /// The nodes joined to fixed row `from` by faces of c > 0 (breadth-first;
    /// the fixed rows themselves are not traversed).
    fn reach(&self, from: usize) -> Vec<bool> {
        let n = self.n;
        let mut seen = vec![false; n * n];
        let mut queue = VecDeque::new();
        for b in 0..n {
            seen[self.node(from, b)] = true;
            queue.push_back((from, b));
        }
        while let Some((a, b)) = queue.pop_front() {
            let k = self.node(a, b);
            for (a2, b2) in self.neighbours(a, b) {
                if a2 == usize::MAX || a2 == 0 || a2 == n - 1 {
                    continue;
                }
                let k2 = self.node(a2, b2);
                if !seen[k2] && self.face(k, k2) > 0.0 {
                    seen[k2] = true;
                    queue.push_back((a2, b2));
                }
            }
        }
        seen
    }

    /// The finite-volume system of the interior nodes joined to a fixed row.
    fn assemble(&self, from_in: &[bool], from_out: &[bool]) -> Result<System> {
        let n = self.n;
        let mut index = vec![usize::MAX; n * n];
        let mut count = 0;
        for a in 1..n - 1 {
            for b in 0..n {
                let k = self.node(a, b);
                if from_in[k] || from_out[k] {
                    index[k] = count;
                    count += 1;
                }
            }
        }
        let mut triplets = Vec::with_capacity(3 * count);
        let mut rhs = vec![0.0; count];
        for a in 1..n - 1 {
            for b in 0..n {
                let k = self.node(a, b);
                let row = index[k];
                if row == usize::MAX {
                    continue;
                }
                let mut diag = 0.0;
                for (a2, b2) in self.neighbours(a, b) {
                    if a2 == usize::MAX {
                        continue;
                    }
                    let k2 = self.node(a2, b2);
                    let c = self.face(k, k2);
                    if c == 0.0 {
                        continue;
                    }
                    diag += c;
                    if a2 == 0 {
                        rhs[row] += c; // P_in = 1
                    } else if a2 != n - 1 && index[k2] < row {
                        triplets.push(Triplet::new(row, index[k2], -c));
                    }
                }
                triplets.push(Triplet::new(row, row, diag));
            }
        }
        let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(count, count, &triplets)
            .map_err(|e| Error::Inconsistent {
                name: "Reynolds system".into(),
                requirement: format!("a valid sparse matrix ({e:?})"),
            })?;
        Ok((index, matrix, rhs))
    }

    /// Flux from fixed row `fixed` into row `inner`, and Σ c(|p_f| + |p_i|)
    /// (the scale of its rounding).
    fn flux(&self, pressure: &[f64], fixed: usize, inner: usize) -> (f64, f64) {
        let (mut q, mut mag) = (0.0, 0.0);
        for b in 0..self.n {
            let (kf, ki) = (self.node(fixed, b), self.node(inner, b));
            let c = self.face(kf, ki);
            let pi = if pressure[ki].is_nan() {
                pressure[kf]
            } else {
                pressure[ki]
            };
            q += c * (pressure[kf] - pi);
            mag += c * (pressure[kf].abs() + pi.abs());
        }
        (q, mag)
    }
}

/// Side below which a block of the grid is not dissected further.
const LEAF: usize = 8;

/// A nested-dissection order of the unknowns: `order[k]` is the unknown
/// numbered k. The grid of rows a = 1 … N−2 (along the flow) and columns
/// b = 0 … N−1 (across, periodic) is cut first across the flow at b = 0 and
/// b = N/2 (the periodic wrap needs both), then each block along its longer
/// side by a middle line, recursively; every cut line follows its two halves.
fn dissection_order(
    n: usize,
    index: &[usize],
    count: usize,
    node: &dyn Fn(usize, usize) -> usize,
) -> Vec<usize> {
    let mut order = Vec::with_capacity(count);
    let mut push = |a: usize, b: usize, order: &mut Vec<usize>| {
        let k = index[node(a, b)];
        if k != usize::MAX {
            order.push(k);
        }
    };
    let (a0, a1) = (1, n - 1);
    let half = n / 2;
    if n >= 2 * LEAF {
        dissect(a0, a1, 1, half, &mut push, &mut order);
        dissect(a0, a1, half + 1, n, &mut push, &mut order);
        for b in [0, half] {
            for a in a0..a1 {
                push(a, b, &mut order);
            }
        }
    } else {
        dissect(a0, a1, 0, n, &mut push, &mut order);
    }
    order
}

/// Number the block [a0, a1) × [b0, b1): halves first, then the cut line.
fn dissect(
    a0: usize,
    a1: usize,
    b0: usize,
    b1: usize,
    push: &mut dyn FnMut(usize, usize, &mut Vec<usize>),
    order: &mut Vec<usize>,
) {
    let (ha, hb) = (a1.saturating_sub(a0), b1.saturating_sub(b0));
    if ha == 0 || hb == 0 {
        return;
    }
    if ha <= LEAF && hb <= LEAF {
        for a in a0..a1 {
            for b in b0..b1 {
                push(a, b, order);
            }
        }
        return;
    }
    if ha >= hb {
        let m = a0 + ha / 2;
        dissect(a0, m, b0, b1, push, order);
        dissect(m + 1, a1, b0, b1, push, order);
        for b in b0..b1 {
            push(m, b, order);
        }
    } else {
        let m = b0 + hb / 2;
        dissect(a0, a1, b0, m, push, order);
        dissect(a0, a1, m + 1, b1, push, order);
        for a in a0..a1 {
            push(a, m, order);
        }
    }
}

/// Solve the SPD system (lower triangle given) by faer's sparse Cholesky in
/// the fill-reducing order `order` (one thread).
fn cholesky_solve(
    matrix: &SparseColMat<usize, f64>,
    order: &[usize],
    rhs: &[f64],
) -> Result<Vec<f64>> {
    let count = rhs.len();
    let mut inverse = vec![0usize; count];
    for (new, &old) in order.iter().enumerate() {
        inverse[old] = new;
    }
    let failed = |what: String| Error::NotConverged {
        what: format!("sparse Cholesky of the Reynolds system ({what})"),
        iterations: 0,
        residual: f64::NAN,
        tolerance: 0.0,
    };
    let perm = faer::perm::PermRef::new_checked(order, &inverse, count);
    let symbolic = factorize_symbolic_cholesky(
        matrix.symbolic(),
        Side::Lower,
        SymmetricOrdering::Custom(perm),
        Default::default(),
    )
    .map_err(|e| failed(format!("{e:?}")))?;
    let par = Par::Seq;
    let mut values = vec![0.0f64; symbolic.len_val()];
    let mut buffer =
        MemBuffer::new(symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()));
    symbolic
        .factorize_numeric_llt::<f64>(
            &mut values,
            matrix.as_ref(),
            Side::Lower,
            Default::default(),
            par,
            MemStack::new(&mut buffer),
            Default::default(),
        )
        .map_err(|e| failed(format!("{e:?}")))?;
    let mut x = faer::Mat::<f64>::from_fn(count, 1, |i, _| rhs[i]);
    let mut buffer = MemBuffer::new(symbolic.solve_in_place_scratch::<f64>(1, par));
    LltRef::new(&symbolic, &values).solve_in_place_with_conj(
        Conj::No,
        x.as_mut(),
        par,
        MemStack::new(&mut buffer),
    );
    Ok((0..count).map(|i| x[(i, 0)]).collect())
}

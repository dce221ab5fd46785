//! Influence functions of the half-space stress under a normal surface
//! pressure: Fourier multipliers (periodic) and cell integrals (free).
//!
//! # Periodic: one Fourier mode
//! For p = p̂ e^{i q·x}, q = q (n_x, n_y), the problem is plane strain in the
//! plane of q (Airy function φ = (p̂/q²)(1 + qz) e^{−qz}, free of shear at
//! z = 0), so with E = e^{−qz} and tensile stresses positive:
//! ```text
//! σ_ξξ = −(1 − qz) E p̂,   σ_ηη = −2ν E p̂,   σ_zz = −(1 + qz) E p̂,   σ_ξz = i qz E p̂
//! σ_xx = n_x² σ_ξξ + n_y² σ_ηη,   σ_yy = n_y² σ_ξξ + n_x² σ_ηη,   σ_xy = n_x n_y (σ_ξξ − σ_ηη)
//! σ_xz = n_x σ_ξz,   σ_yz = n_y σ_ξz
//! ```
//! (ξ along q, η across; the sinusoidal pressure on a half-plane of Johnson
//! 1985, ch. 2, rederived here; both equilibrium equations hold mode by mode,
//! and Tamaas 2.9 gives the same field, tests/subsurface.rs). The mean pressure p̄ (q = 0)
//! gives σ_zz = −p̄ and, for a periodic body that cannot expand sideways
//! (zero mean in-plane strain), σ_xx = σ_yy = −ν p̄/(1 − ν). At the Nyquist
//! wavevector the odd multipliers (n_x, n_y, n_x n_y) are set to zero: the
//! direction of a Nyquist mode is not defined on the grid.
//!
//! # Free: a uniformly loaded cell
//! Boussinesq's potentials ψ₁ = ∫∫ p ln(ρ + z), ψ = ∫∫ p/ρ (Johnson 1985,
//! §3.2; every component checked with mpmath against the point-load
//! formulas and against the Fourier-mode solution above):
//! ```text
//! σ_xx = [2ν ψ_z − z ψ_xx − (1 − 2ν) ψ₁_xx] / 2π     σ_yy likewise (x ↔ y)
//! σ_zz = [ψ_z − z ψ_zz] / 2π
//! σ_xy = −[(1 − 2ν) ψ₁_xy + z ψ_xy] / 2π
//! σ_xz = −z ψ_xz / 2π,   σ_yz = −z ψ_yz / 2π
//! ```
//! For a unit pressure on the cell [X ± Δ/2] × [Y ± Δ/2] (field point minus
//! cell centre), each derivative is the corner sum D[G] = G(b,d) − G(a,d) −
//! G(b,c) + G(a,c), a, b = X ∓ Δ/2, c, d = Y ∓ Δ/2, of a G with ∂²G/∂u∂v = g
//! (u, v the offsets, ρ = √(u² + v² + z²)):
//! ```text
//! ψ_z : −atan(uv/(zρ))                ψ_zz: uv(ρ² + z²)/(ρ(u² + z²)(v² + z²))
//! ψ_xx: u/(ρ(ρ + v))                  ψ_xy: 1/ρ                  ψ_xz: z/(ρ(ρ + v))
//! ψ₁_xx: atan(uv(ρ − z)/(u²ρ + z v²))  ψ₁_xy: ln(ρ + z)
//! ```
//! (each checked by differentiation; ρ − z is evaluated as (u² + v²)/(ρ + z),
//! ρ + v as (u² + z²)/(ρ − v) for v < 0). The y-derivatives are the same
//! functions with x and y exchanged: σ_yy(x, y) = σ_xx(y, x), σ_yz(x, y) = σ_xz(y, x).
//! A large square gives σ_zz → −p and σ_xx = σ_yy → −(1 + 2ν)p/2 at its
//! centre just below the surface, Johnson's values under a uniform load.
//!
//! # References
//! K. L. Johnson, *Contact Mechanics* (CUP 1985), ch. 2 (periodic pressure on a
//! half-plane) and §3.2 (Boussinesq potentials); A. E. H. Love, Phil. Trans.
//! R. Soc. A 228, 377 (1929) (the uniformly loaded rectangle).

/// The six components in the order xx, yy, zz, xy, xz, yz.
pub(crate) const COMPONENTS: usize = 6;

/// Fourier multipliers of the six components at depth z for the wavevector
/// (q_x, q_y) (1/m), as (real part, imaginary part) per component.
pub(crate) fn multipliers(
    qx: f64,
    qy: f64,
    z: f64,
    nu: f64,
    nyquist: bool,
) -> [(f64, f64); COMPONENTS] {
    let q = qx.hypot(qy);
    if q == 0.0 {
        let lateral = -nu / (1.0 - nu);
        return [
            (lateral, 0.0),
            (lateral, 0.0),
            (-1.0, 0.0),
            (0.0, 0.0),
            (0.0, 0.0),
            (0.0, 0.0),
        ];
    }
    let (nx, ny) = (qx / q, qy / q);
    let qz = q * z;
    let e = (-qz).exp();
    let s_xi = -(1.0 - qz) * e;
    let s_eta = -2.0 * nu * e;
    let shear = qz * e;
    let odd = if nyquist { 0.0 } else { 1.0 };
    [
        (nx * nx * s_xi + ny * ny * s_eta, 0.0),
        (ny * ny * s_xi + nx * nx * s_eta, 0.0),
        (-(1.0 + qz) * e, 0.0),
        (odd * nx * ny * (s_xi - s_eta), 0.0),
        (0.0, odd * nx * shear),
        (0.0, odd * ny * shear),
    ]
}

/// Component `c` of [`multipliers`] from precomputed q_x, q_y, q (negative
/// at a Nyquist mode) and e^{−qz}.
#[inline]
pub(crate) fn multiplier(
    c: usize,
    qx: f64,
    qy: f64,
    q_signed: f64,
    e: f64,
    z: f64,
    nu: f64,
) -> (f64, f64) {
    let q = q_signed.abs();
    if q == 0.0 {
        let lateral = -nu / (1.0 - nu);
        return match c {
            0 | 1 => (lateral, 0.0),
            2 => (-1.0, 0.0),
            _ => (0.0, 0.0),
        };
    }
    let (nx, ny) = (qx / q, qy / q);
    let qz = q * z;
    let odd = if q_signed < 0.0 { 0.0 } else { 1.0 };
    let (s_xi, s_eta) = (-(1.0 - qz) * e, -2.0 * nu * e);
    match c {
        0 => (nx * nx * s_xi + ny * ny * s_eta, 0.0),
        1 => (ny * ny * s_xi + nx * nx * s_eta, 0.0),
        2 => (-(1.0 + qz) * e, 0.0),
        3 => (odd * nx * ny * (s_xi - s_eta), 0.0),
        4 => (0.0, odd * nx * qz * e),
        _ => (0.0, odd * ny * qz * e),
    }
}

/// Corner functions used per corner (module docs): ψ_z, ψ_zz, ψ_xx, ψ_xy,
/// ψ_xz, ψ₁_xx, ψ₁_xy. The y-derivatives follow by swapping x and y.
pub(crate) const CORNER_FUNCTIONS: usize = 7;

/// The corner functions G at one corner (u, v) and depth z, in the order of
/// [`CORNER_FUNCTIONS`].
pub(crate) fn corner(u: f64, v: f64, z: f64) -> [f64; CORNER_FUNCTIONS] {
    let (u2, v2, z2) = (u * u, v * v, z * z);
    let rho = (u2 + v2 + z2).sqrt();
    let uv = u * v;
    // ρ − z and ρ + v without cancellation.
    let rho_minus_z = (u2 + v2) / (rho + z);
    let rho_v = if v >= 0.0 {
        rho + v
    } else {
        (u2 + z2) / (rho - v)
    };
    let g_xx1 = if u == 0.0 || v == 0.0 {
        0.0
    } else {
        (uv * rho_minus_z / (u2 * rho + z * v2)).atan()
    };
    [
        -(uv / (z * rho)).atan(),
        uv * (rho * rho + z2) / (rho * (u2 + z2) * (v2 + z2)),
        u / (rho * rho_v),
        1.0 / rho,
        z / (rho * rho_v),
        g_xx1,
        (rho + z).ln(),
    ]
}

/// σ_xx, σ_zz, σ_xy, σ_xz of a unit pressure on a cell from the corner sums
/// `d` of [`corner`] (module docs).
pub(crate) fn cell_stress(d: &[f64; CORNER_FUNCTIONS], z: f64, nu: f64) -> [f64; 4] {
    let inv = 1.0 / std::f64::consts::TAU;
    let [psi_z, psi_zz, psi_xx, psi_xy, psi_xz, p1_xx, p1_xy] = *d;
    let m = 1.0 - 2.0 * nu;
    [
        inv * (2.0 * nu * psi_z - z * psi_xx - m * p1_xx),
        inv * (psi_z - z * psi_zz),
        -inv * (m * p1_xy + z * psi_xy),
        -inv * z * psi_xz,
    ]
}

/// σ_xx, σ_zz, σ_xy, σ_xz at (x, y, z) of a unit pressure on the cell of
/// side `delta` centred at the origin, by the corner sums.
fn cell4(x: f64, y: f64, z: f64, delta: f64, nu: f64) -> [f64; 4] {
    let h = 0.5 * delta;
    let g_bd = corner(x + h, y + h, z);
    let g_ad = corner(x - h, y + h, z);
    let g_bc = corner(x + h, y - h, z);
    let g_ac = corner(x - h, y - h, z);
    let mut d = [0.0; CORNER_FUNCTIONS];
    for k in 0..CORNER_FUNCTIONS {
        d[k] = g_bd[k] - g_ad[k] - g_bc[k] + g_ac[k];
    }
    cell_stress(&d, z, nu)
}

/// All six stresses at (x, y, z) of a unit pressure on the cell of side
/// `delta` centred at the origin: σ_yy(x, y) = σ_xx(y, x), σ_yz(x, y) = σ_xz(y, x).
pub(crate) fn unit_cell(x: f64, y: f64, z: f64, delta: f64, nu: f64) -> [f64; COMPONENTS] {
    let a = cell4(x, y, z, delta, nu);
    let b = cell4(y, x, z, delta, nu);
    [a[0], b[0], a[1], a[2], a[3], b[3]]
}

/// Von Mises equivalent stress of (xx, yy, zz, xy, xz, yz).
#[inline]
pub(crate) fn von_mises(s: &[f64; COMPONENTS]) -> f64 {
    let [xx, yy, zz, xy, xz, yz] = *s;
    (0.5 * ((xx - yy).powi(2) + (yy - zz).powi(2) + (zz - xx).powi(2))
        + 3.0 * (xy * xy + xz * xz + yz * yz))
        .sqrt()
}

/// Maximum shear stress (σ₁ − σ₃)/2 from the principal stresses of a
/// symmetric tensor (trigonometric solution of the characteristic cubic):
/// with s = σ − (tr σ/3) I, p = |s|²/6, cos 3φ = det(s)/(2 p^{3/2}):
/// (σ₁ − σ₃)/2 = √(3p) sin(φ + π/3).
#[inline]
pub(crate) fn max_shear(s: &[f64; COMPONENTS]) -> f64 {
    let [xx, yy, zz, xy, xz, yz] = *s;
    let m = (xx + yy + zz) / 3.0;
    let (a, b, c) = (xx - m, yy - m, zz - m);
    let p = (a * a + b * b + c * c + 2.0 * (xy * xy + xz * xz + yz * yz)) / 6.0;
    if p <= 0.0 {
        return 0.0;
    }
    let det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
    let r = (det / (2.0 * p * p.sqrt())).clamp(-1.0, 1.0);
    let phi = r.acos() / 3.0;
    (3.0 * p).sqrt() * (phi + std::f64::consts::FRAC_PI_3).sin()
}

/// One transformed kernel: its quadrant, parity (x, y), the output it
/// gives and the output its transpose gives.
pub(crate) type KernelPlan = (usize, (f64, f64), usize, Option<usize>);

/// The xx, zz, xy and xz cell kernels of depth z on the offsets (a, b),
/// 0 ≤ a, b < N (one quadrant), `[q][a·n + b]`: corner functions on the
/// corners ((a − ½)Δ, (b − ½)Δ), two rows at a time, shared by neighbouring cells.
pub(crate) fn free_quadrants(n: usize, delta: f64, z: f64, nu: f64) -> [Vec<f64>; 4] {
    let m = n + 1;
    let row = |a: usize| -> Vec<[f64; CORNER_FUNCTIONS]> {
        let u = (a as f64 - 0.5) * delta;
        (0..m)
            .map(|b| corner(u, (b as f64 - 0.5) * delta, z))
            .collect()
    };
    let mut out: [Vec<f64>; 4] = [
        vec![0.0; n * n],
        vec![0.0; n * n],
        vec![0.0; n * n],
        vec![0.0; n * n],
    ];
    let mut prev = row(0);
    for a in 0..n {
        let next = row(a + 1);
        for b in 0..n {
            let mut d = [0.0; CORNER_FUNCTIONS];
            for (k, v) in d.iter_mut().enumerate() {
                *v = next[b + 1][k] - prev[b + 1][k] - next[b][k] + prev[b][k];
            }
            let s = cell_stress(&d, z, nu);
            let k = a * n + b;
            for (q, v) in s.into_iter().enumerate() {
                out[q][k] = v;
            }
        }
        prev = next;
    }
    out
}

/// A quadrant kernel on the 2N × 2N circulant grid: offset (k, l) at index
/// (k mod 2N, l mod 2N), |k|, |l| ≤ N − 1, mirrored with the parity
/// (x, y) (+1 even, −1 odd); row and column N are zero.
pub(crate) fn fill_circulant(quadrant: &[f64], n: usize, (px, py): (f64, f64), work: &mut [f64]) {
    let nf = 2 * n;
    work.fill(0.0);
    for a in 0..n {
        let src = &quadrant[a * n..(a + 1) * n];
        for (sign, r) in [(1.0, a), (px, nf - a)] {
            if a == 0 && r == nf {
                continue;
            }
            let dst = &mut work[(r % nf) * nf..(r % nf + 1) * nf];
            for b in 0..n {
                dst[b] = sign * src[b];
                if b > 0 {
                    dst[nf - b] = sign * py * src[b];
                }
            }
        }
    }
}

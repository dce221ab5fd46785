"""Brute-force reference for the adhesive stress diffusion (tests/adhesion.rs).

Solves Persson's diffusion with the moving absorbing boundary
    dP/dt = d2P/dsigma2,  sigma > b(t) = -sigma_a(t),  P(b(t), t) = 0,
    P(sigma, 0) = delta(sigma - sigma0)
by Crank-Nicolson finite differences in the frame moving with the boundary,
x = sigma - b, with u = ln(zeta) as the evolution variable:
    dQ/du = T'(u) Q_xx + B'(u) Q_x,   Q(0) = Q(X) = 0,
T(u) = t(e^u) = (pi/4) E*^2 int_{q_l}^{zeta q_l} q^3 C dq and B(u) = b(e^u).
The start is the exact image solution of the fixed boundary at a u_s where
the Gaussian has not yet reached the boundary (mass there < 1e-20), so the
boundary's motion before u_s is irrelevant. Richardson extrapolation over
three grids (dx, du halved together; error O(h^2)).

Everything the Rust code computes (the moments of the self-affine spectrum,
gamma_eff, sigma_a, the true-area factor) is re-implemented here from the
formulas, not from the Rust code.

Run: /work/venvs/<you>/bin/python tests/reference/adhesion_diffusion_fd.py
(numpy, scipy). Prints the constants pasted into tests/adhesion.rs.
"""
import math

import numpy as np
from scipy.linalg import solve_banded
from scipy.special import erfcx, erf

# The self-affine spectrum of the tests: q_l = 1, q_r = 2, q_s = 100 (1/m),
# H = 0.8, rms slope 0.5 over the band; E* = 1 (any one unit).
QL, QR, QS, H, E = 1.0, 2.0, 100.0, 0.8, 1.0


def moment(k, a, b, cr):
    """int_a^b q^k C dq, closed form per power-law segment."""
    s = 0.0
    lo, hi = max(a, QL), min(b, QR)
    if lo < hi:
        s += cr * (hi ** (k + 1) - lo ** (k + 1)) / (k + 1)
    lo, hi = max(a, QR), min(b, QS)
    if lo < hi:
        p = k - 2 * (H + 1)
        s += cr * QR ** (2 * (H + 1)) * (hi ** (p + 1) - lo ** (p + 1)) / (p + 1)
    return s


CR = 0.25 / (2 * math.pi * moment(3, QL, QS, 1.0))


def area(x):
    if x <= 0:
        return 1.0
    xi = math.sqrt(x)
    return 1 + 0.5 * math.sqrt(math.pi) * xi * erfcx(1 / xi)


def sigma_a(zeta, dgamma):
    q = zeta * QL
    xi2 = 2 * math.pi * moment(3, q, QS, CR)
    u = math.pi / 2 * E * moment(2, q, QS, CR)
    g = dgamma * area(xi2) - u
    return math.sqrt(g * E * q) if g > 0 else 0.0


def time(zeta):
    return math.pi / 4 * E * E * moment(3, QL, zeta * QL, CR)


def solve(dgamma, sigma0, zeta_end, nx, nu):
    umax = math.log(zeta_end)
    b = lambda u: -sigma_a(math.exp(u), dgamma)
    T = lambda u: time(math.exp(u))
    d = sigma0 - b(0.0)
    # start where the Gaussian width is d/12: the mass beyond the boundary is ~e^-72
    ts = (d / 12) ** 2 / 2
    lo, hi = 0.0, umax
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if T(mid) < ts:
            lo = mid
        else:
            hi = mid
    us = lo
    width = math.sqrt(2 * T(umax))
    bmin = min(b(u) for u in np.linspace(0, umax, 2001))
    X = (sigma0 - bmin) + 14 * width + d
    x = np.linspace(0.0, X, nx + 1)
    dx = x[1] - x[0]
    t0 = T(us)
    g = lambda z: np.exp(-z * z / (4 * t0)) / math.sqrt(4 * math.pi * t0)
    # the image start about the boundary where it is at u_s (frame x = sigma - b(u_s))
    ds = sigma0 - b(us)
    Q = g(x - ds) - g(x + ds)
    Q[0] = Q[-1] = 0.0
    us_grid = np.linspace(us, umax, nu + 1)
    h = 1e-6

    def coeffs(u):
        tp = (T(u + h) - T(u - h)) / (2 * h) if u - h > 0 else (T(u + h) - T(u)) / h
        bp = (b(u + h) - b(u - h)) / (2 * h) if u - h > 0 else (b(u + h) - b(u)) / h
        return tp, bp

    def op(tp, bp):
        # L Q_j = tp (Q_{j+1} - 2Q_j + Q_{j-1})/dx^2 + bp (Q_{j+1} - Q_{j-1})/(2dx)
        lower = tp / dx**2 - bp / (2 * dx)
        diag = -2 * tp / dx**2
        upper = tp / dx**2 + bp / (2 * dx)
        return lower, diag, upper

    m = nx - 1
    for n in range(nu):
        u0, u1 = us_grid[n], us_grid[n + 1]
        du = u1 - u0
        l0, d0, p0 = op(*coeffs(u0))
        l1, d1, p1 = op(*coeffs(u1))
        qi = Q[1:-1]
        rhs = qi + 0.5 * du * (d0 * qi + l0 * Q[:-2] + p0 * Q[2:])
        ab = np.zeros((3, m))
        ab[0, 1:] = -0.5 * du * p1
        ab[1, :] = 1 - 0.5 * du * d1
        ab[2, :-1] = -0.5 * du * l1
        Q[1:-1] = solve_banded((1, 1), ab, rhs)
    bend = b(umax)
    area_c = np.trapezoid(Q, x)
    carried = np.trapezoid((x + bend) * Q, x)
    # tensile: sigma < 0 <=> x < -b
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (Q[1:] + Q[:-1]) * dx)])
    tensile = np.interp(-bend, x, cum) if bend < 0 else 0.0
    return area_c, tensile, carried


def richardson(dgamma, sigma0, zeta_end, nx, nu):
    r = [np.array(solve(dgamma, sigma0, zeta_end, nx * k, nu * k)) for k in (1, 2, 4)]
    e1 = r[1] + (r[1] - r[0]) / 3
    e2 = r[2] + (r[2] - r[1]) / 3
    best = e2 + (e2 - e1) / 15
    return best, np.abs(best - r[2]), np.abs(e2 - e1)


if __name__ == "__main__":
    print(f"C_r = {CR!r}")
    cases = [
        (0.0, 0.05, 100.0),
        (0.01, 0.05, 100.0),
        (0.01, 0.0, 100.0),
        (0.01, -0.03, 100.0),
        (0.01, 0.05, 10.0),
        (0.004, 0.05, 100.0),
    ]
    for dg, s0, z in cases:
        best, err_plain, err_rich = richardson(dg, s0, z, 2000, 2000)
        sp = sigma_a(1.0, dg)
        print(f"dgamma={dg} sigma0={s0} zeta={z}: sigma_p={sp!r}")
        print(f"   contact_fraction={best[0]!r} tensile_fraction={best[1]!r} carried={best[2]!r}")
        print(f"   finest-grid error {err_plain}, extrapolation change {err_rich}")
    # the non-adhesive closed form as a check of the FD itself
    t = time(100.0)
    print("erf check:", erf(0.05 / (2 * math.sqrt(t))))

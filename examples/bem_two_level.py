"""Prototype of issue 22's two-level (balancing Neumann–Neumann) preconditioner
for the BEM's constrained CG, measured and not adopted: see docs/design-notes.md
and docs/bem.md for the counts it gave.

numpy/scipy replica of `src/bem/preconditioned.rs` (periodic, load control,
E* = L = 1; it reproduces that loop's iteration counts exactly: 34/30 at 256²,
45 at 512²) with the preconditioner either the loop's own FFT one
z = [F] K [F] r (K = E*|q|/2) or the balancing two-level one

    z = Q r + (I - Q A) M (I - A Q) r,   Q = Z E^-1 Z^T,   E = Z^T A Z,

Z the indicators of the aggregates (b x b blocks of the grid intersected with
the free set F), A the compliance on F with the load constraint, M the FFT
preconditioner. The coarse matrix E is assembled cheaply: near field
(|I - J| <= 1 block) exact by probing with 16 colours (one convolution each),
far field from the aggregates' monopole and dipole moments through the block
kernel.

Heights and a converged pressure come from the CLI (N = 256, sigma0 = 0.05):

    persson bem rough --hurst 0.8 --q-l 6.283185307179586 --q-r 25.132741228718345 \
      --q-s 402.1238596594935 --rms-slope 0.1 --size 1 --grid 256 --seed 1 \
      --contact-modulus 1 --pressure 0.05 --tolerance 1e-10 \
      --surface-out h256.npy --pressure-field p256_0.05.npy

    python examples/bem_two_level.py fixed 256 0.05 32       # contact set fixed at p > 0
    python examples/bem_two_level.py nonlinear 256 0.05 32   # the whole loop
    python examples/bem_two_level.py nonlinear 256 0.05 0    # b = 0: the FFT preconditioner

Arguments: mode, N, sigma0/E*, b (0: no coarse level), [directory of the .npy
files], [stale: re-assemble when F changed at more than this fraction of its
nodes, default 0.01; 0: at every change].
"""
import sys
import time

import numpy as np
import scipy.linalg as sl


def operators(n):
    """Periodic compliance G (2/|q|, mean mode 0) and stiffness K (|q|/2, mean pi)."""
    k = np.fft.fftfreq(n, 1.0 / n)
    kx, ky = np.meshgrid(k, np.fft.rfftfreq(n, 1.0 / n), indexing="ij")
    q = 2 * np.pi * np.hypot(kx, ky)
    gm = np.where(q > 0, 2 / np.where(q > 0, q, 1), 0.0)
    km = q / 2
    km[0, 0] = np.pi
    G = lambda x: np.fft.irfft2(np.fft.rfft2(x) * gm, s=(n, n))
    K = lambda x: np.fft.irfft2(np.fft.rfft2(x) * km, s=(n, n))
    return G, K


def coarse_raw(n, b, c, G):
    """E_raw ~ Z^T G Z: far field by moments, near field probed (16 colours)."""
    nb = n // b
    m = nb * nb
    i1 = np.arange(n) // b
    idx = i1[:, None] * nb + i1[None, :]
    cnt = np.bincount(idx.ravel(), weights=c.ravel(), minlength=m)
    live = np.flatnonzero(cnt > 0)
    bsum = lambda x: np.bincount(idx.ravel(), weights=(c * x).ravel(), minlength=m)
    box = np.zeros((n, n))
    box[:b, :b] = 1
    blk = lambda x: x.reshape(nb, b, nb, b).sum(axis=(1, 3))
    gc = blk(G(box))
    sh = lambda sx, sy: blk(G(np.roll(np.roll(box, sx, 0), sy, 1)))
    gx, gy = (sh(1, 0) - sh(-1, 0)) / 2, (sh(0, 1) - sh(0, -1)) / 2
    o = np.arange(n) % b - (b - 1) / 2
    w = cnt / (b * b)
    safe = np.maximum(cnt, 1)
    ox = bsum(o[:, None] * np.ones((1, n))) / safe
    oy = bsum(np.ones((n, 1)) * o[None, :]) / safe
    bi, bj = np.divmod(live, nb)
    di = (bi[:, None] - bi[None, :]) % nb
    dj = (bj[:, None] - bj[None, :]) % nb
    wl, oxl, oyl = w[live], ox[live], oy[live]
    far = wl[:, None] * wl[None, :] * (
        gc[di, dj]
        + gx[di, dj] * (oxl[None, :] - oxl[:, None])
        + gy[di, dj] * (oyl[None, :] - oyl[:, None])
    )
    e = far.copy()
    pos = -np.ones(m, dtype=int)
    pos[live] = np.arange(live.size)
    for a in range(4):
        for d in range(4):
            sel = (bi % 4 == a) & (bj % 4 == d)
            if not sel.any():
                continue
            colour = np.zeros(m)
            colour[live[sel]] = 1
            s = bsum(G(c * colour[idx]))[live]
            sfar = far[:, sel].sum(axis=1)
            for j in range(live.size):
                for ddi in (-1, 0, 1):
                    for ddj in (-1, 0, 1):
                        i = pos[((bi[j] + ddi) % nb) * nb + (bj[j] + ddj) % nb]
                        if i >= 0 and sel[i]:
                            e[j, i] = s[j] - (sfar[j] - far[j, i])
    return 0.5 * (e + e.T), live, idx


def two_level(n, b, free, G, K):
    """The balancing preconditioner: its coarse matrix is assembled on the free
    set `free` (bool N x N); it is applied on the free set `c` of the call
    (the current one; the coarse matrix may be older, see `nonlinear`)."""
    c = free.astype(float)
    nf = c.sum()
    e, live, idx = coarse_raw(n, b, c, G)
    m = (n // b) ** 2
    zt = lambda c, x: np.bincount(idx.ravel(), weights=(c * x).ravel(), minlength=m)[live]
    cn, gcv, cgc = zt(c, np.ones((n, n))), zt(c, G(c)), (c * G(c)).sum()
    e = e - np.outer(cn, gcv) / nf - np.outer(gcv, cn) / nf
    e += np.outer(cn, cn) * (cgc / nf**2 + 1 / nf)
    cf = sl.cho_factor(0.5 * (e + e.T))

    def prec(c, r):
        nf = c.sum()
        pi = lambda x: c * (x - (x * c).sum() / nf)
        A = lambda x: pi(G(pi(x))) + c * (x * c).sum() / nf  # load constraint; SPD

        def Q(v):
            f = np.zeros(m)
            f[live] = sl.cho_solve(cf, zt(c, v))
            return c * f[idx]

        qr = Q(r)
        u = c * K(c * (r - A(qr)))
        return qr + u - Q(A(u))

    return prec


def fixed(n, s, b, h, p_sol, tol=1e-10):
    """PCG on the solution's contact set (load fixed), Tamaas-like epsilon."""
    G, K = operators(n)
    free = p_sol > 0
    c = free.astype(float)
    nc = c.sum()
    pi = lambda x: c * (x - (x * c).sum() / nc)
    prec = two_level(n, b, free, G, K) if b else (lambda c, r: c * K(c * r))
    p = c * p_sol.sum() / nc
    r = pi(G(p) - h)
    t, rz_old, sh = None, None, h.std()
    for k in range(1000):
        if (p * np.abs(r)).sum() / (p.sum() * sh) <= tol:
            return k
        z = pi(prec(c, r))
        rz = (r * z).sum()
        t = z if t is None else z + rz / rz_old * t
        rz_old = rz
        at = pi(G(t))
        tau = (r * t).sum() / (t * at).sum()
        p, r = p - tau * t, r - tau * at
    return -1


def nonlinear(n, s, b, h, tol=1e-10, stale=0.01):
    """The preconditioned loop of `preconditioned.rs`; the coarse level is
    re-assembled when F has changed at more than `stale` of its nodes."""
    G, K = operators(n)
    total, sh = s * n * n, h.std()
    p = np.full((n, n), s)
    g = G(p) - h
    t, rz_old, fa, prec, assemblies = np.zeros((n, n)), 0.0, None, None, 0
    for k in range(1000):
        contact = p > 0
        gmin, gbar = g[contact].min(), g[contact].mean()
        eps = ((p * g).sum() - gmin * p.sum()) / (p.sum() * sh)
        overlap = (~contact).any() and g[~contact].min() < gmin - tol * sh
        if eps <= tol and not overlap:
            return k, assemblies
        free = contact | ((p <= 0) & (g < gbar))
        c = free.astype(float)
        nf = c.sum()
        r = c * (g - gbar)
        if b:
            if fa is None or (fa ^ free).sum() > stale * nf:
                fa, prec, assemblies = free.copy(), two_level(n, b, free, G, K), assemblies + 1
            z = prec(c, r)
        else:
            z = c * K(r)
        rz, r_t, sum_t, sum_z, sum_r = (r * z).sum(), (r * t).sum(), (c * t).sum(), (c * z).sum(), r.sum()
        beta = rz / rz_old if rz_old > 0 else 0.0
        mu = (sum_z + beta * sum_t) / nf
        if not rz + beta * r_t - mu * sum_r > 0:  # Fletcher–Reeves restart
            beta, mu = 0.0, sum_z / nf
        rz_old = rz
        v = c * (z + beta * t - mu)
        v[(p <= 0) & (v > 0)] = 0.0
        t = v
        tau = ((g - gbar) * t).sum() / (t * G(t)).sum()
        p = np.maximum(p - tau * t, 0.0)
        p *= total / p.sum()
        g = G(p) - h
    return -1, assemblies


if __name__ == "__main__":
    mode, n, s, b = sys.argv[1], int(sys.argv[2]), sys.argv[3], int(sys.argv[4])
    d = sys.argv[5] if len(sys.argv) > 5 else "."
    h = np.load(f"{d}/h{n}.npy")
    t0 = time.time()
    if mode == "fixed":
        p_sol = np.load(f"{d}/p{n}_{s}.npy").reshape(n, n)
        out = f"iterations {fixed(n, float(s), b, -h, p_sol)}"
    else:
        stale = float(sys.argv[6]) if len(sys.argv) > 6 else 0.01
        it, assemblies = nonlinear(n, float(s), b, h, stale=stale)
        out = f"iterations {it}, coarse assemblies {assemblies}"
    print(f"{mode} N = {n} sigma0 = {s} b = {b} {sys.argv[6:]}: {out} ({time.time() - t0:.1f} s)")

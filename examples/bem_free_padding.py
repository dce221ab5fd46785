"""Prototype of issue 22's step for the free boundary: the edge correction of
the preconditioner extended over a band of the padding (measured here first, now
in the solver, whose counts mode "pad" reproduces; see docs/bem.md and
docs/design-notes.md).

numpy replica of `src/bem/preconditioned.rs` on the free boundary (load control,
E* = L = 1): the compliance is Love's cell kernel on the zero-padded 2N grid,
restricted to the N x N window; the preconditioner is the inverse of that 2N
circulant restricted to the window, corrected at the edges of the free set F by
z = [F](Kr - K_loc w), w = [N] Kr (K_loc: omega/d times K's 7 x 7 kernel, 0 at
the centre). It gave the solver's iteration counts exactly before the padding was
corrected (31 / 42 / 58 / 117 at 256 / 512 / 1024 / 2048, sigma0 = 0.05 E*,
mode "edge") and gives them now (31 / 42 / 57 / 81, mode "pad"). Modes:

    none   the uncorrected preconditioner z = [F] K r
    edge   the solver's correction up to commit c63322d (w on the window's
           nodes held at p = 0 only)
    pad    the same, with w also on the padding within 3 nodes of the window:
           the padding is held at p = 0 like the non-contact nodes, and the exact
           inverse of the window's compliance lacks its Schur term too

Heights from the CLI (the rough case of issue 22, seed 1):

    persson bem rough --hurst 0.8 --q-l 6.283185307179586 --q-r 25.132741228718345 \
      --q-s <2 pi N/4> --rms-slope 0.1 --size 1 --grid N --seed 1 \
      --contact-modulus 1 --pressure 0.05 --boundary free --surface-out hN.npy

    python examples/bem_free_padding.py N sigma0 none|edge|pad [directory of hN.npy]
"""
import sys, time
import numpy as np

R, OMEGA = 3, 1.5

def love(x, y, a):
    """Displacement at (x, y) of unit pressure on the square |x|,|y| <= a (E* = 1)."""
    def f(u, v):
        r = np.hypot(u, v)
        with np.errstate(divide="ignore", invalid="ignore"):
            t1 = np.where(np.abs(u) > 0, u * np.log(np.where(r + v > 0, v + r, 1.0)), 0.0)
            t2 = np.where(np.abs(v) > 0, v * np.log(np.where(r + u > 0, u + r, 1.0)), 0.0)
        return t1 + t2
    return (f(x + a, y + a) - f(x + a, y - a) - f(x - a, y + a) + f(x - a, y - a)) / np.pi

def operators(n):
    m = 2 * n
    d = 1.0 / n
    i = np.fft.fftfreq(m, 1.0 / m)
    X, Y = np.meshgrid(i * d, i * d, indexing="ij")
    ker = love(X, Y, d / 2)
    C = np.fft.rfft2(ker)
    Cr = C.real
    def G(p):
        big = np.zeros((m, m)); big[:n, :n] = p
        return np.fft.irfft2(np.fft.rfft2(big) * Cr, s=(m, m))[:n, :n]
    def Kfull(r):
        big = np.zeros((m, m)); big[:n, :n] = r
        return np.fft.irfft2(np.fft.rfft2(big) / Cr, s=(m, m))
    imp = np.zeros((m, m)); imp[0, 0] = 1.0
    kk = np.fft.irfft2(np.fft.rfft2(imp) / Cr, s=(m, m))
    idx = np.arange(-R, R + 1) % m
    st = kk[np.ix_(idx, idx)]
    st = (st + st[::-1] + st[:, ::-1] + st[::-1, ::-1]) / 4
    st = (st + st.T) / 2
    dd = st[R, R]
    coeff = OMEGA * st / dd
    coeff[R, R] = 0.0
    return G, Kfull, coeff

def stencil(w, coeff):
    out = np.zeros((w.shape[0] - 2 * R, w.shape[1] - 2 * R))
    for a in range(2 * R + 1):
        for b in range(2 * R + 1):
            if coeff[a, b] != 0.0:
                out += coeff[a, b] * w[a:a + out.shape[0], b:b + out.shape[1]]
    return out

def loop(n, s, h, mode, tol=1e-10):
    G, Kfull, coeff = operators(n)
    m = 2 * n
    total, sh = s * n * n, h.std()
    p = np.full((n, n), s)
    g = G(p) - h
    t, rz_old = np.zeros((n, n)), 0.0
    for k in range(2000):
        contact = p > 0
        gmin, gbar = g[contact].min(), g[contact].mean()
        eps = ((p * g).sum() - gmin * p.sum()) / (p.sum() * sh)
        overlap = (~contact).any() and g[~contact].min() < gmin - tol * sh
        if eps <= tol and not overlap:
            return k
        free = contact | ((p <= 0) & (g < gbar))
        c = free.astype(float)
        nf = c.sum()
        r = c * (g - gbar)
        kr = Kfull(r)
        z = kr[:n, :n].copy()
        if mode != "none":
            # w on the window's held nodes, plus (mode "pad") the padding band
            wbig = np.zeros((n + 2 * R, n + 2 * R))
            wbig[R:R + n, R:R + n] = (1 - c) * z
            if mode == "pad":
                rows = np.arange(-R, n + R) % m
                band = kr[np.ix_(rows, rows)]
                inside = np.zeros_like(band, dtype=bool); inside[R:R + n, R:R + n] = True
                wbig[~inside] = band[~inside]
            z = z - stencil(wbig, coeff)
        z = c * z
        rz, r_t, sum_t, sum_z, sum_r = (r * z).sum(), (r * t).sum(), (c * t).sum(), (c * z).sum(), r.sum()
        beta = rz / rz_old if rz_old > 0 else 0.0
        mu = (sum_z + beta * sum_t) / nf
        if not rz + beta * r_t - mu * sum_r > 0:
            beta, mu = 0.0, sum_z / nf
        rz_old = rz
        v = c * (z + beta * t - mu)
        v[(p <= 0) & (v > 0)] = 0.0
        t = v
        tau = ((g - gbar) * t).sum() / (t * G(t)).sum()
        p = np.maximum(p - tau * t, 0.0)
        p *= total / p.sum()
        g = G(p) - h
    return -1

if __name__ == "__main__":
    n, s, mode = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
    d = sys.argv[4] if len(sys.argv) > 4 else "."
    h = np.load(f"{d}/h{n}.npy").reshape(n, n)
    t0 = time.time()
    print(n, s, mode, loop(n, s, h, mode), f"{time.time() - t0:.1f} s", flush=True)

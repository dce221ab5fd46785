"""Prototype of issue 22's nested-iteration (coarse-to-fine) start, measured and
not adopted: see docs/design-notes.md and docs/bem.md.

The loop is the preconditioned one of `examples/bem_two_level.py` (b = 0; it gives
`src/bem/preconditioned.rs`'s counts exactly: 30/39/49 at 256/512/1024, sigma0 =
0.005 E*; 34/45/59 at 0.05 E*), started either cold (p = sigma0) or from the
solution of the same surface on the N/2 grid (recursively down to `nmin`, each level
to the loose tolerance `ctol`), prolonged piecewise constant ("const") or bilinearly
("bilinear") and rescaled to the load (the solver's `Start::Rescaled`). The coarse
surface is the fine realisation Fourier-filtered at the coarse Nyquist (`restrict`).
The fine solve keeps the stopping rule (eps <= 1e-10), so the answer is unchanged.
Cost is counted in fine-grid iterations: a level N/2^l costs 4^-l per iteration.

Heights from the CLI (`--surface-out h256.npy`, see bem_two_level.py), then

    python examples/bem_nested.py const 1e-4 64 256,512,1024
"""
import sys
import numpy as np
from bem_two_level import operators

def loop(n, s, h, p0=None, tol=1e-10, maxit=2000):
    G, K = operators(n)
    total, sh = s * n * n, h.std()
    p = np.full((n, n), s) if p0 is None else p0.copy()
    p *= total / p.sum()
    g = G(p) - h
    t, rz_old = np.zeros((n, n)), 0.0
    last_change, prev_free = 0, None
    for k in range(maxit):
        contact = p > 0
        gmin, gbar = g[contact].min(), g[contact].mean()
        eps = ((p * g).sum() - gmin * p.sum()) / (p.sum() * sh)
        overlap = (~contact).any() and g[~contact].min() < gmin - tol * sh
        if eps <= tol and not overlap:
            return k, p, last_change
        free = contact | ((p <= 0) & (g < gbar))
        if prev_free is not None and (free ^ prev_free).any():
            last_change = k
        prev_free = free
        c = free.astype(float)
        nf = c.sum()
        r = c * (g - gbar)
        z = c * K(r)
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
    return -1, p, last_change

def restrict(h):
    """Fourier truncation at the coarse Nyquist (same realisation), N -> N/2."""
    n = h.shape[0]; m = n // 2
    H = np.fft.fft2(h)
    k = np.fft.fftfreq(n, 1.0 / n).astype(int)
    keep = np.abs(k) < m // 2
    idx = np.concatenate([np.arange(m // 2), np.arange(n - m // 2 + 1, n)])
    Hc = H[np.ix_(idx, idx)]
    # coarse index layout: 0..m/2-1, then Nyquist slot (zero), then negatives
    Cc = np.zeros((m, m), complex)
    ci = np.concatenate([np.arange(m // 2), np.arange(m // 2 + 1, m)])
    Cc[np.ix_(ci, ci)] = Hc
    return np.real(np.fft.ifft2(Cc)) / 4.0

def prolong(p, how):
    if how == "const":
        return np.repeat(np.repeat(p, 2, 0), 2, 1)
    # bilinear (periodic)
    a = p; b = np.roll(p, -1, 0); c = np.roll(p, -1, 1); d = np.roll(b, -1, 1)
    n = p.shape[0]; f = np.zeros((2 * n, 2 * n))
    f[0::2, 0::2] = a; f[1::2, 0::2] = (a + b) / 2; f[0::2, 1::2] = (a + c) / 2
    f[1::2, 1::2] = (a + b + c + d) / 4
    return f

def nested(n, s, h, nmin, ctol, how):
    """Returns fine iterations, coarse work in fine-size iterations, last F change."""
    if n // 2 < nmin:
        k, p, lc = loop(n, s, h, tol=ctol)
        return None, p, k
    hc = restrict(h)
    _, pc, cost_c = nested(n // 2, s, hc, nmin, ctol, how)
    k, p, lc = loop(n, s, h, p0=prolong(pc, how), tol=ctol)
    return (k, lc), p, k + cost_c / 4.0

if __name__ == "__main__":
    d = "."
    how = sys.argv[1] if len(sys.argv) > 1 else "const"
    ctol = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-4
    nmin = int(sys.argv[3]) if len(sys.argv) > 3 else 64
    for n in [int(x) for x in sys.argv[4].split(",")]:
        h = np.load(f"{d}/h{n}.npy").reshape(n, n)
        for s in (0.005, 0.05):
            k0, _, lc0 = loop(n, s, h)
            hc = restrict(h)
            _, pc, costc = nested(n // 2, s, hc, nmin, ctol, how)
            k, p, lc = loop(n, s, h, p0=prolong(pc, how))
            print(f"N={n} s={s} {how} ctol={ctol} nmin={nmin}: cold {k0} (last F change {lc0}); "
                  f"nested fine {k} (last F change {lc}), coarse {costc/4:.1f} fine-equiv, total {k+costc/4:.1f}", flush=True)

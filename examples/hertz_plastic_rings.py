"""1-D axisymmetric reference for the Hertz ball with a yield stress (the
oracle of tests/bem_yield.rs and of the README's "Hertz ball with a yield
stress"): a rigid paraboloid (R = 1) on an elastic half-space (E* = 1) at the
load of the elastic Hertz radius a_H = 1, the pressure capped at
Y = ratio * p0_H. Piecewise-constant pressure on M rings of [0, RMAX],
collocation at the ring midpoints, exact displacements of uniformly loaded
discs (K. L. Johnson, Contact Mechanics, eq. 3.29; complete elliptic integrals
by the arithmetic-geometric mean), and an active-set solution of
p = Y (gap <= 0) / 0 < p < Y (gap = 0) / p = 0 (gap >= 0) with the load.
c and a are ring edges (resolution RMAX/M); the approach is continuous.
Check: ratio >= 1 gives the elastic Hertz approach 1 (0.999999 at M = 400).

    python3 examples/hertz_plastic_rings.py 0.8 1600 3200   (needs numpy only)
    RMAX=1.13 python3 examples/hertz_plastic_rings.py 0.8 3200
"""
import sys, numpy as np
def ellipke(k):
    k = np.asarray(k, float); kp = np.sqrt(1 - k*k)
    a, b = np.ones_like(k), kp.copy(); c = k.copy(); s = 0.5*c*c; p2 = 0.5
    for _ in range(40):
        an = 0.5*(a+b); bn = np.sqrt(a*b); cn = 0.5*(a-b)
        a, b = an, bn; p2 *= 2; s += p2*cn*cn
    K = np.pi/(2*a); return K, K*(1-s)
def udisc(rho, b):
    rho = rho[:, None]; b = b[None, :]
    out = np.empty(np.broadcast(rho, b).shape)
    inside = rho < b
    bb = np.broadcast_to(b, out.shape); rr = np.broadcast_to(rho, out.shape)
    with np.errstate(divide='ignore', invalid='ignore'):
        K, E = ellipke(np.where(inside, rr/np.where(bb > 0, bb, 1), 0))
        out[inside] = (4*bb*E/np.pi)[inside]
        k = np.where(inside, 0, bb/rr); K2, E2 = ellipke(k)
        o = 4*rr/np.pi*(E2 - (1 - k*k)*K2)
    out[~inside] = o[~inside]
    return out
def solve(M, ratio, rmax=1.15):
    edges = np.linspace(0, rmax, M+1); rho = 0.5*(edges[1:]+edges[:-1])
    U = udisc(rho, edges)                 # (M, M+1)
    G = U[:, 1:] - U[:, :-1]              # disp at rho_j from unit p on ring i
    A = np.pi*(edges[1:]**2 - edges[:-1]**2)
    p0 = 2/np.pi; Y = ratio*p0; F = 4/3
    # initial sets from the clipped Hertz profile
    st = np.where(rho < 1, 1, 0); st[np.sqrt(np.clip(1-rho**2, 0, 1))*p0 >= Y] = 2
    for it in range(200):
        E_ = np.where(st == 1)[0]; P = np.where(st == 2)[0]
        n = len(E_)
        Mx = np.zeros((n+1, n+1)); rhs = np.zeros(n+1)
        Mx[:n, :n] = G[np.ix_(E_, E_)]; Mx[:n, n] = -1
        rhs[:n] = -rho[E_]**2/2 - G[np.ix_(E_, P)].sum(1)*Y
        Mx[n, :n] = A[E_]; rhs[n] = F - Y*A[P].sum()
        x = np.linalg.solve(Mx, rhs)
        p = np.zeros(M); p[P] = Y; p[E_] = x[:n]; d = x[n]
        g = G @ p - d + rho**2/2
        new = st.copy()
        new[(st == 1) & (p > Y)] = 2; new[(st == 1) & (p < 0)] = 0
        new[(st == 2) & (g > 0)] = 1; new[(st == 0) & (g < 0)] = 1
        if (new == st).all(): break
        st = new
    P = np.where(st == 2)[0]; C = np.where(st > 0)[0]
    c = edges[P.max()+1] if len(P) else 0.0
    a = edges[C.max()+1]
    return c, a, it, d, Y
RMAX = float(__import__("os").environ.get("RMAX", "1.15"))
for M in map(int, sys.argv[2:]):
    c, a, it, d, Y = solve(M, float(sys.argv[1]), RMAX)
    print(f"M {M}: c/a_H {c:.5f}  a/a_H {a:.5f}  c/a {c/a:.5f}  iterations {it}  approach {d:.8f}")

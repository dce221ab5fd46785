"""High-precision references for tests/asperity.rs (mpmath; 25-30 digits).

Run: python3 tests/reference/asperity_reference.py [section]
Sections: fn, hertz, summits, bgt (bgt takes a few minutes). Prints Rust tables.

Independent of the crate:
- F_n(h) of Greenwood & Williamson by the parabolic-cylinder closed form
  F_n(h) = Γ(n+1) e^{-h²/4} D_{-n-1}(h) / √(2π)  (DLMF 12.5.1), checked against
  the defining integral; not by the crate's trapezoidal rule or continued fraction.
- Elliptic Hertz factors by mpmath's ellipk/ellipe and findroot on Johnson's
  ratio B/A = [E/(1-e²) - K]/[K - E] (Contact Mechanics 1985, §4.2),
  not by Carlson's R_D.
- Summit statistics by the Kac-Rice density in (u, r), integrated by mp.quad:
  checks the closed forms of Nayak (1971) and McCool (1986) that the crate uses.
- BGT J-integrals by nested mp.quad in (u, v) with F_k(z) by its definition
  and the Hertz factors above (the crate uses Chebyshev kernels, Carlson R_D,
  Gauss-Kronrod and the trapezoidal F_k).
"""
import sys
from functools import lru_cache

import mpmath as mp

mp.mp.dps = 30


def F(n, h):
    """Greenwood-Williamson F_n(h) = int_0^inf t^n phi(t+h) dt (closed form)."""
    n, h = mp.mpf(n), mp.mpf(h)
    return mp.gamma(n + 1) * mp.exp(-h * h / 4) * mp.pcfd(-n - 1, h) / mp.sqrt(2 * mp.pi)


def F_quad(n, h):
    """The defining integral; for h > 0 as phi(h) int t^n e^{-ht - t^2/2} dt."""
    if h < 0:
        f = lambda t: t ** n * mp.exp(-(t + h) ** 2 / 2) / mp.sqrt(2 * mp.pi)
        return mp.quad(f, [0, -h / 2, -h, -h + 1, -h + 10, mp.inf])
    s = 1 / (1 + h)
    g = lambda t: t ** n * mp.exp(-h * t - t * t / 2)
    return mp.quad(g, [0, s / 10, s, 3 * s, 10 * s, 40 * s, mp.inf]) * mp.exp(-h * h / 2) / mp.sqrt(2 * mp.pi)


def nstr(x, d=20):
    return mp.nstr(x, d, min_fixed=-1, max_fixed=-1)


def section_fn():
    hs = ["-6", "-2", "-0.5", "0", "0.7", "2", "5", "12", "30"]
    print("// (n, h, F_n(h)): mpmath pcfd closed form, 30 digits")
    print("const GW_INTEGRALS: [(f64, f64, f64); %d] = [" % (6 * len(hs)))
    for n in ["0", "0.5", "1", "1.5", "2", "2.5"]:
        for h in hs:
            v = F(n, h)
            q = F_quad(mp.mpf(n), mp.mpf(h))
            assert abs(v / q - 1) < mp.mpf("1e-25"), (n, h, v, q)
            print("    (%s, %s, %s)," % (n, h, nstr(v)))
    print("];")


def hertz_factors(rho):
    """(F_A, F_P) for kappa2/kappa1 = rho (crate module hertz_ellipse)."""
    rho = mp.mpf(rho)
    if rho == 1:
        return mp.mpf(1), mp.mpf(1)

    def ratio(x):  # B/A as a function of x = ln(1 - e^2) = ln k'^2
        m, kp2 = -mp.expm1(x), mp.exp(x)
        K, E = mp.ellipk(m), mp.ellipe(m)
        return (E / kp2 - K) / (K - E)

    # solve ratio(m) = 1/rho in x = ln(1 - m) (bisection, then findroot)
    lo, hi = mp.mpf(-60), mp.mpf("-1e-8")
    g = lambda x: mp.log(ratio(x)) - mp.log(1 / rho)
    for _ in range(80):
        mid = (lo + hi) / 2
        if g(mid) > 0:
            lo = mid
        else:
            hi = mid
    x = mp.findroot(g, (lo + hi) / 2)
    m = -mp.expm1(x)
    K, E = mp.ellipk(m), mp.ellipe(m)
    kp = mp.sqrt(1 - m)
    ba = 1 / rho
    fa = 2 * kp * (K - E) / (K * m) * mp.sqrt(ba)
    fp = (mp.pi / (2 * K)) * mp.sqrt(2 * (K - E) * mp.sqrt(ba) / (K * m))
    return fa, fp


def section_hertz():
    print("// (rho, F_A, F_P): mpmath ellipk/ellipe, Johnson 1985 §4.2")
    for rho in ["0.1", "0.5", "0.01"]:
        fa, fp = hertz_factors(rho)
        print("    (%s, %s, %s)," % (rho, nstr(fa), nstr(fp)))


def section_summits():
    """Kac-Rice: summits per area in (xi, u, r) = (m4/(2 pi m2)) p(xi,u) Ray(r) (u^2 - r^2), u > r."""
    print("// (alpha, eta m2/m4, mean xi, var xi, mean u) from the Kac-Rice density, mm = 1, m2 = 1, m4 = alpha")
    for alpha in ["1.6", "5", "20"]:
        a = mp.mpf(alpha)
        ray = lambda r: 3 * r * mp.exp(-mp.mpf(3) / 2 * r * r)
        nu = lambda u: mp.exp(-3 * u * u / 4) / mp.sqrt(2 * mp.pi * mp.mpf(2) / 3)
        # E[xi | u] = (3/(2 sqrt a)) u, E[xi^2 | u] = s_c^2 + (3u/(2 sqrt a))^2
        sc2 = 1 - 3 / (2 * a)
        mxi = lambda u: 3 * u / (2 * mp.sqrt(a))

        def w(g):
            return mp.quad(lambda u: nu(u) * g(u) * mp.quad(lambda r: ray(r) * (u * u - r * r), [0, u]), [0, 2, 6, mp.inf])

        d = w(lambda u: 1)
        m1 = w(mxi) / d
        m2 = w(lambda u: sc2 + mxi(u) ** 2) / d
        mu = w(lambda u: u) / d
        eta = d / (2 * mp.pi)  # times m4/m2 = alpha
        print("    (%s, %s, %s, %s, %s)," % (alpha, nstr(eta), nstr(m1), nstr(m2 - m1 * m1), nstr(mu)))


@lru_cache(maxsize=None)
def _factors_v(v):
    c = mp.sqrt(v)
    rho = (1 - c) / (1 + c)
    return hertz_factors(rho)


def K(gamma, which, lam, exact):
    """0.5 int_0^1 (1-v)^gamma F(v) e^{-lam v} dv."""
    def f(v):
        if which == 0 or not exact or v == 0:
            fac = 1
        else:
            fa, fp = _factors_v(v)
            fac = fa if which == 1 else fp
        return (1 - v) ** gamma * fac * mp.exp(-lam * v)
    return mp.quad(f, [0, 1]) / 2


def J(k, gamma, which, delta, alpha, exact):
    a = mp.mpf(alpha)
    sc = mp.sqrt(1 - 3 / (2 * a))
    slope = 3 / (2 * mp.sqrt(a))
    nu = lambda u: mp.exp(-3 * u * u / 4) / mp.sqrt(2 * mp.pi * mp.mpf(2) / 3)
    p = 2 + 2 * gamma

    def g(u):
        z = (delta - slope * u) / sc
        return nu(u) * 3 * u ** p * K(gamma, which, mp.mpf(3) / 2 * u * u, exact) * sc ** k * F(k, z)
    c = max(mp.mpf(delta) / mp.sqrt(a), 0)
    return mp.quad(g, [0, c / 2, c, c + 1, c + 3, c + 12])


def section_bgt():
    mp.mp.dps = 20
    alpha = mp.mpf(5)  # m0 = m2 = 1, m4 = 5
    print("// BGT at alpha = 5 (m0 = m2 = 1, m4 = 5, E* = 1): (exact, delta, n, A/A0, sigma0)")
    for exact in [True, False]:
        for delta in ["-1", "0", "1", "2.5"]:
            d = mp.mpf(delta)
            j0 = J(0, mp.mpf(1), 0, d, alpha, exact)
            ja = J(1, mp.mpf("0.5"), 1, d, alpha, exact)
            jp = J(mp.mpf("1.5"), mp.mpf("0.75"), 2, d, alpha, exact)
            n = alpha / (2 * mp.pi) * j0
            area = mp.sqrt(alpha) / 2 * ja
            load = 2 / (3 * mp.pi) * alpha ** mp.mpf("0.75") * jp
            print("    (%s, %s, %s, %s, %s)," % (str(exact).lower(), delta, nstr(n, 17), nstr(area, 17), nstr(load, 17)))
            sys.stdout.flush()


if __name__ == "__main__":
    which = sys.argv[1:] or ["fn", "hertz", "summits", "bgt"]
    for s in which:
        globals()["section_" + s]()

"""Reference values for tests/leakage.rs: the critical junction of Persson's
theory at one load, with mpmath (30 digits), independently of the crate.

Spectrum: self-affine, q_l = 1e4, q_r = 4e4, q_s = 1e7 (1/m), H = 0.8, rms
slope 1 over [q_l, q_s]; E* = 1e9 Pa; sigma0 = 1e7 Pa; a_c = 0.42.

  G(z)   = (pi/4)(E*/s0)^2 m3(q_l, z q_l),  A(z) = erf(1/(2 sqrt G))
  F(z,p) = sqrt(pi) int_{z q_l}^{q_s} q^2 C w_z E1((w_z p/E*)^2)/2 dq,
           w_z(q) = (pi m3(z q_l, q))^(-1/2)
  ubar(z) = F(z, s0/A(z)),   u1 = d(A ubar)/dA  (mpmath.diff in z)

Run: python tests/reference/critical_junction.py  (a venv with mpmath).
"""
import mpmath as mp

mp.mp.dps = 30
ql, qr, qs, H = mp.mpf(10) ** 4, 4 * mp.mpf(10) ** 4, mp.mpf(10) ** 7, mp.mpf("0.8")
E, s0, ac = mp.mpf(10) ** 9, mp.mpf(10) ** 7, mp.mpf("0.42")
b = -2 * (H + 1)


def m3_raw(a, c):
    """int_a^c q^3 C dq with C_r = 1."""
    a, c = max(a, ql), min(c, qs)
    if a >= c:
        return mp.mpf(0)
    out = mp.mpf(0)
    if a < qr:
        out += (min(c, qr) ** 4 - a ** 4) / 4
    if c > qr:
        lo = max(a, qr)
        e = 4 + b
        out += qr ** (-b) * (c ** e - lo ** e) / e
    return out


Cr = 1 / (2 * mp.pi * m3_raw(ql, qs))  # rms slope 1


def C(q):
    return Cr if q < qr else Cr * (q / qr) ** b


def m3(a, c):
    return Cr * m3_raw(a, c)


def area(z):
    g = mp.pi / 4 * (E / s0) ** 2 * m3(ql, z * ql)
    return mp.erf(1 / (2 * mp.sqrt(g)))


def F(z, p):
    lo = z * ql

    def f(v):  # q = lo exp(v^2)
        q = lo * mp.exp(v * v)
        m = m3(lo, q)
        if m <= 0:
            return mp.mpf(0)  # w -> inf, E1 -> 0
        w = 1 / mp.sqrt(mp.pi * m)
        x2 = (w * p / E) ** 2
        return mp.sqrt(mp.pi) * q * q * C(q) * w * mp.e1(x2) / 2 * 2 * v * q

    vmax = mp.sqrt(mp.log(qs / lo))
    pts = [0, vmax]
    if qr > lo:
        pts = [0, mp.sqrt(mp.log(qr / lo)), vmax]
    return mp.quad(f, pts)


def a_ubar(z):
    a = area(z)
    return a * F(z, s0 / a)


zc = mp.findroot(lambda s: area(mp.exp(s)) - ac, (mp.mpf("1e-6"), mp.log(1000)), solver="illinois")
zc = mp.exp(zc)
num = mp.diff(a_ubar, zc)
den = mp.diff(area, zc)
u1 = num / den
print("critical_zeta =", mp.nstr(zc, 17))
print("critical_separation =", mp.nstr(u1, 17))

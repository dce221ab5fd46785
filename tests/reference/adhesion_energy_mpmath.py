"""Reference values of the adhesion energy terms (tests/adhesion.rs), 30 digits.

For the self-affine spectrum C = C_r (q_l <= q < q_r), C_r (q/q_r)^(-2(H+1))
(q_r <= q <= q_s), amplitude from the rms slope over the band, evaluated by
mpmath quadrature of the definitions (not by the closed-form moments that the
Rust code uses):
    xi^2(zeta)      = 2 pi int_{q_l}^{zeta q_l} q^3 C dq
    U_el(zeta)/A0   = (pi E*/2) int_{q_l}^{zeta q_l} q^2 C dq
    A_true/A0       = int_0^inf e^{-x} (1 + xi^2 x)^{1/2} dx
    gamma_eff(1)    = dgamma A_true(zeta_max) - U_el(zeta_max);  sigma_p = sqrt(gamma_eff(1) E* q_l)
    h'_rms, h''_rms = sqrt(2 pi int q^3 C), sqrt(2 pi int q^5 C)

Run: /work/venvs/<you>/bin/python tests/reference/adhesion_energy_mpmath.py
"""
from mpmath import mp, mpf, quad, sqrt, exp, pi, inf

mp.dps = 30


def spectrum(ql, qr, qs, H, rms_slope):
    ql, qr, qs, H = mpf(ql), mpf(qr), mpf(qs), mpf(H)

    def shape(q):
        return 1 if q < qr else (q / qr) ** (-2 * (H + 1))

    def m(k, a, b):
        pts = [p for p in (a, qr, b) if a <= p <= b]
        return quad(lambda q: q**k * shape(q), sorted(set(pts)))

    cr = mpf(rms_slope) ** 2 / (2 * pi * m(3, ql, qs))
    return ql, qs, cr, m


def area(xi2):
    return quad(lambda x: exp(-x) * sqrt(1 + xi2 * x), [0, 1, 10, inf])


def report(name, ql, qr, qs, H, slope, E, zetas, dgamma):
    ql, qs, cr, m = spectrum(ql, qr, qs, H, slope)
    E = mpf(E)
    print(f"// {name}: q_l={ql}, q_r={qr}, q_s={qs}, H={H}, rms slope {slope}, E*={E}")
    for z in zetas:
        b = ql * mpf(z)
        xi2 = 2 * pi * cr * m(3, ql, b)
        u = pi * E / 2 * cr * m(2, ql, b)
        print(f"(zeta {z}): full_contact_energy {mp.nstr(u, 20)}, true_area_ratio {mp.nstr(area(xi2), 20)}")
    xi2 = 2 * pi * cr * m(3, ql, qs)
    g1 = mpf(dgamma) * area(xi2) - pi * E / 2 * cr * m(2, ql, qs)
    print(f"gamma_eff(1) at dgamma={dgamma}: {mp.nstr(g1, 20)}; sigma_p {mp.nstr(sqrt(g1 * E * ql), 20) if g1 > 0 else 0}")
    h2 = sqrt(2 * pi * cr * m(5, ql, qs))
    print(f"rms curvature {mp.nstr(h2, 20)}")


if __name__ == "__main__":
    for x in (mpf("1e-6"), mpf("0.25"), mpf(1), mpf(100)):
        print(f"true_area_ratio({x}) = {mp.nstr(area(x), 20)}")
    report("test spectrum", 1, 2, 100, "0.8", "0.5", 1, (1.5, 2, 10, 100), "0.01")
    report("rubber", 1e4, 1e5, 1e8, "0.8", "1", 1e6, (10, 1e3, 1e4), "0.05")

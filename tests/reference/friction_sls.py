"""Independent reference of Persson's rubber-friction integrals for a standard
linear solid on a self-affine spectrum (tests/friction.rs, `SLS_REFERENCE`).

    /work/venvs/friction/bin/python tests/reference/friction_sls.py

Nothing from the crate is used: the angular integrals are done by adaptive
quadrature (scipy `quad`, QUADPACK) of the analytic complex modulus over
φ ∈ [0, π] (both signs of ω = q v cos φ, E(−ω) = conj E(ω) by construction),
and G, μ are integrated together as an ODE in x = ln q with scipy's DOP853
(rtol 1e-13), restarted at the roll-off kink. The run is repeated at rtol
1e-12 and the script fails if the two differ by more than 1e-11 (relative).
A few angular integrals are checked against mpmath at 30 digits.

    μ    = ½ ∫ dq q³ C S P ∫₀^{2π} dφ cos φ Im E(q v cos φ) / ((1 − ν²) σ0)
    G(q) = ⅛ ∫ dq q³ C ∫₀^{2π} dφ |E(q v cos φ)|² / ((1 − ν²) σ0)²
    P = erf(1/(2√G)),  S = γ + (1 − γ) P²,  E(ω) = E∞ + (E0 − E∞) iωτ/(1 + iωτ)
"""
import math

import mpmath as mp
from scipy.integrate import quad, solve_ivp

QL, QR, QS, HURST, CR = 1e2, 1e3, 1e7, 0.8, 1e-15  # spectrum (1/m, m⁴)
E0, EINF, TAU = 3e8, 3e6, 1e-4  # SLS: instantaneous, relaxed (Pa), τ (s)
NU, GAMMA = 0.5, 0.5
CASES = [(1e5, 10.0**k) for k in range(-9, 4)] + [(3e6, v) for v in (1e-6, 1e-2, 1e2)]


def c_of(q):
    return CR if q < QR else CR * (q / QR) ** (-2.0 * (HURST + 1.0))


def modulus(w):
    x = 1j * w * TAU
    return EINF + (E0 - EINF) * x / (1.0 + x)


def points(w):
    """Break points of the φ-integrals: where w τ |cos φ| = 10^k (the SLS's
    transition, a near-step close to φ = π/2 when w τ ≫ 1) and π/2."""
    pts = [math.pi / 2]
    for k in range(-2, 3):
        c = 10.0**k / (w * TAU)
        if c < 1.0:
            pts += [math.acos(c), math.pi - math.acos(c)]
    return sorted(pts)


def phi_a(w):
    """∫₀^{2π} cos φ Im E(w cos φ) dφ = 2 ∫₀^π."""
    f = lambda p: math.cos(p) * modulus(w * math.cos(p)).imag
    v, _ = quad(f, 0.0, math.pi, points=points(w), epsabs=0.0, epsrel=2e-14, limit=4000)
    return 2.0 * v


def phi_b(w):
    """∫₀^{2π} |E(w cos φ)|² dφ = 2 ∫₀^π."""
    f = lambda p: abs(modulus(w * math.cos(p))) ** 2
    v, _ = quad(f, 0.0, math.pi, points=points(w), epsabs=0.0, epsrel=2e-14, limit=4000)
    return 2.0 * v


def sp(g):
    p = 1.0 if g <= 0.0 else math.erf(0.5 / math.sqrt(g))
    return (GAMMA + (1.0 - GAMMA) * p * p) * p


def solve(sigma0, v, rtol):
    k = 1.0 / ((1.0 - NU * NU) * sigma0)

    def rhs(x, y):
        q = math.exp(x)
        q4c = q**4 * c_of(q)
        return [q4c * phi_b(q * v) * k * k / 8.0, 0.5 * q4c * sp(y[0]) * phi_a(q * v) * k]

    y = [0.0, 0.0]
    for a, b in ((QL, QR), (QR, QS)):
        r = solve_ivp(rhs, (math.log(a), math.log(b)), y, method="DOP853", rtol=rtol, atol=1e-30)
        assert r.success, r.message
        y = [r.y[0][-1], r.y[1][-1]]
    g, mu = y
    return mu, g, math.erf(0.5 / math.sqrt(g))


def check_angular_with_mpmath():
    mp.mp.dps = 30
    for w in (1e-3, 1e4, 1e9, 1e11):
        e = lambda p: mp.mpf(EINF) + (E0 - EINF) * (1j * w * mp.cos(p) * TAU) / (1 + 1j * w * mp.cos(p) * TAU)
        a = 2 * mp.quad(lambda p: mp.cos(p) * mp.im(e(p)), [0, mp.pi / 2, mp.pi])
        b = 2 * mp.quad(lambda p: abs(e(p)) ** 2, [0, mp.pi / 2, mp.pi])
        assert abs(phi_a(w) / a - 1) < 1e-13, (w, phi_a(w), a)
        assert abs(phi_b(w) / b - 1) < 1e-13, (w, phi_b(w), b)


def main():
    check_angular_with_mpmath()
    print("// (nominal_pressure, velocity, friction_coefficient, g, contact_fraction)")
    for sigma0, v in CASES:
        mu, g, p = solve(sigma0, v, 1e-13)
        mu2, g2, _ = solve(sigma0, v, 1e-12)
        assert abs(mu2 / mu - 1) < 1e-11 and abs(g2 / g - 1) < 1e-11, (sigma0, v, mu, mu2, g, g2)
        print(f"    ({sigma0:e}, {v:e}, {mu:.17e}, {g:.17e}, {p:.17e}),", flush=True)


if __name__ == "__main__":
    main()

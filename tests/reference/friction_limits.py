"""mpmath (40 digits) references of the closed-form limits in tests/friction.rs.

    /work/venvs/friction/bin/python tests/reference/friction_limits.py

A rubber whose modulus E1 + i E2 does not depend on frequency, on the
self-affine spectrum C = C_r (q_l ≤ q < q_r), C_r (q/q_r)^{−2(H+1)} (q_r ≤ q ≤ q_s),
q_l = 1e2, q_r = 1e3, q_s = 1e7 (1/m), H = 0.8, C_r = 1e-15 m⁴, ν = 0.5. Then
G(q) = κ m3(q), κ = (π/4)|E|²/((1 − ν²)σ0)², and with dm3 = dG/κ

    μ = 2 E2/((1 − ν²) σ0 κ) ∫₀^{G1} S(P) P dG,   P = erf(1/(2√G)),  S = γ + (1 − γ) P²

independent of v. For γ = 1 the integral is closed:
∫₀^{G1} P dG = G1 erf(x1) + √(G1/π) e^{−x1²} − erfc(x1)/2, x1 = 1/(2√G1).
Prints (σ0, γ, μ) for the table `CONSTANT_LOSS` (the quadrature is checked
against the closed form for γ = 1).
"""
import mpmath as mp

mp.mp.dps = 40
QL, QR, QS, H, CR = mp.mpf(100), mp.mpf(1000), mp.mpf(10) ** 7, mp.mpf("0.8"), mp.mpf("1e-15")
E1, E2, NU = mp.mpf(2e6), mp.mpf(5e5), mp.mpf("0.5")


def m3():
    low = CR * (QR**4 - QL**4) / 4
    e = 3 - 2 * H - 2 + 1  # exponent + 1 of q³ (q/q_r)^{-2H-2}
    high = CR * QR ** (2 * H + 2) * (QS**e - QR**e) / e
    return low + high


def mu(sigma0, gamma):
    k = (1 - NU**2) * mp.mpf(sigma0)
    kappa = mp.pi / 4 * (E1**2 + E2**2) / k**2
    g1 = kappa * m3()
    p = lambda g: mp.erf(1 / (2 * mp.sqrt(g)))
    integral = mp.quad(lambda g: (gamma + (1 - gamma) * p(g) ** 2) * p(g), [0, mp.mpf("1e-3"), 1, g1])
    if gamma == 1:
        x1 = 1 / (2 * mp.sqrt(g1))
        closed = g1 * mp.erf(x1) + mp.sqrt(g1 / mp.pi) * mp.exp(-x1**2) - mp.erfc(x1) / 2
        assert abs(closed / integral - 1) < mp.mpf("1e-30"), (closed, integral)
    return 2 * E2 / (k * kappa) * integral, g1


print("// (nominal_pressure, gamma, friction_coefficient, g)")
for sigma0 in ["1e5", "1e3", "1e9"]:
    for gamma in ["0.5", "1"]:
        m, g1 = mu(mp.mpf(sigma0), mp.mpf(gamma))
        print(f"    ({sigma0}, {gamma}, {mp.nstr(m, 20, min_fixed=-1, max_fixed=-1)}, {mp.nstr(g1, 20, min_fixed=-1, max_fixed=-1)}),")

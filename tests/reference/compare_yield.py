"""mpmath (40 digits) references of crates/persson-cli/tests/compare_yield.rs:
Persson's finite-σY fractions of a flat start at full magnification for the
spectrum of that test (H = 0.8, q_l = 1, q_r = 2, q_s = 8, rms slope 0.1,
E* = 1), at σ0 = 0.002, 0.005 and σY = 0.04, 0.05, 0.08.

G at ζ = q_s/q_l of a spectrum of rms slope h' over [q_l, q_s] is
(π/4)(E*/σ0)² h'²/(2π) = h'²/(8σ0²), and a flat start has σH = σ0, so
τ = G, w = 2√τ, y = σY/σ0. Independent of the crate's sine series, the
fractions are the sums over the images of the walls σ = 0 and σ = σY
(Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Eq. 7 by images):
  F(x)  = erfc((x − 1)/w) − erfc((x + 1)/w)
  A_pl  = Σ_{j≥0} F((2j+1) y)
  A_el  = erf(1/w) − Σ_{k≥1} (−1)^{k+1} F(k y)
and, as a check, the sine series A_el = Σ_{n odd} (4/(nπ)) sin(nπ/y) e^{−(nπ/y)²τ}.

Run: /path/to/venv/bin/python tests/reference/compare_yield.py
"""
import mpmath as mp

mp.mp.dps = 40


def fractions(s0, sy):
    s0, sy = mp.mpf(s0), mp.mpf(sy)
    g = mp.mpf("0.01") / (8 * s0 ** 2)
    w = 2 * mp.sqrt(g)
    y = sy / s0
    F = lambda x: mp.erfc((x - 1) / w) - mp.erfc((x + 1) / w)
    pl = mp.nsum(lambda j: F((2 * j + 1) * y), [0, mp.inf])
    el = mp.erf(1 / w) - mp.nsum(lambda k: (-1) ** (k + 1) * F(k * y), [1, mp.inf])
    series = mp.nsum(
        lambda m: 4 / ((2 * m + 1) * mp.pi) * mp.sin((2 * m + 1) * mp.pi / y)
        * mp.exp(-(((2 * m + 1) * mp.pi / y) ** 2) * g), [0, mp.inf])
    assert abs(series - el) < mp.mpf("1e-30"), (s0, sy, series, el)
    return g, el, pl


print("/// (σ0, σY, G, A_el/A0, A_pl/A0), mpmath (tests/reference/compare_yield.py).")
print("const YIELD_REFERENCE: [(f64, f64, f64, f64, f64); 6] = [")
for s0 in ("0.002", "0.005"):
    for sy in ("0.04", "0.05", "0.08"):
        g, el, pl = fractions(float(s0), float(sy))
        n = lambda x: mp.nstr(x, 20, min_fixed=-1, max_fixed=-1).replace("e+", "e")
        print(f"    ({s0}, {sy}, {n(g)}, {n(el)}, {n(pl)}),")
print("];")

"""mpmath (40 digits) references of the core families of `persson report stability`
(src/report/core.rs). Run: python3 tests/reference/stability.py -> the two Rust tables.

Inputs are taken as their exact f64 values. A/A0 = erf(1/(2 sqrt G)) (Persson,
J. Chem. Phys. 115, 3840 (2001)); for the self-affine spectrum with
q_l = q_r = 1, q_s = 1e10, Hurst H and rms slope 1 (E* = 1),
G(zeta, p) = (zeta^(2-2H) - 1) / (8 p^2 (q_s^(2-2H) - 1)).
"""
import mpmath as mp
mp.mp.dps = 40
def f(x): return mp.nstr(x, 20, min_fixed=-1, max_fixed=-1)
def area(g): return mp.erf(1 / (2 * mp.sqrt(g)))
print("const AREA_AT_G: [(i32, f64); 9] = [")
for lg in [-12, -6, -3, 0, 3, 6, 12, 20, 30]:
    print(f"    ({lg}, {f(area(mp.mpf(10.0**lg)))}),")
print("];")
print("const SELF_AFFINE: [(f64, f64, i32, f64); 36] = [")
for h in [0.01, 0.5, 0.99]:
    for lp in [-12, -6, 0, 1]:
        for z in [1.0 + 1e-12, 1e5, 1e10]:
            H, Z, P = mp.mpf(h), mp.mpf(z), mp.mpf(10.0**lp)
            e = 2 - 2 * H
            g = (Z**e - 1) / (8 * P**2 * (mp.mpf(1e10)**e - 1))
            print(f"    ({h!r}, {z!r}, {lp}, {f(area(g))}),")
print("];")

"""High-precision (inputs taken as their exact f64 values) references for tests/core.rs (mpmath, 50 digits).

Run: python3 tests/reference/core.py  -> prints the Rust tables pasted in tests/core.rs.
Independent of the crate: moments by the elementary antiderivative at 50 digits.
"""
import mpmath as mp

mp.mp.dps = 50
QL, QR, QS, CR = mp.mpf(1), mp.mpf(10), mp.mpf("1e10"), mp.mpf(1)


def moment(k, a, b, H):
    """∫_a^b q^k C(q) dq for the self-affine spectrum with roll-off."""
    a, b = max(a, QL), min(b, QS)
    tot = mp.mpf(0)
    if a < min(b, QR):
        hi = min(b, QR)
        tot += CR * (hi ** (k + 1) - a ** (k + 1)) / (k + 1)
    lo = max(a, QR)
    if lo < b:
        e = k - 2 * H - 1
        tot += CR * QR ** (2 * H + 2) * (mp.log(b / lo) if e == 0 else (b ** e - lo ** e) / e)
    return tot


def f(x):
    return mp.nstr(x, 20, min_fixed=-1, max_fixed=-1)


print("// (hurst, zeta, m3(q_l, zeta q_l)) for q_l = 1, q_r = 10, q_s = 1e10, C_r = 1")
for H in ["0.01", "0.3", "0.5", "0.8", "0.99", "0.999999"]:
    for z in ["1.0000001", "5", "10", "1e5", "1e10"]:
        print(f"    ({H}, {z}, {f(moment(3, QL, QL * mp.mpf(float(z)), mp.mpf(float(H))))}),")
print("// (hurst, rms_height, rms_slope, rms_curvature) over [q_l, q_s]")
for H in ["0.01", "0.5", "0.99"]:
    h = mp.mpf(float(H))
    r = [mp.sqrt(2 * mp.pi * moment(k, QL, QS, h)) for k in (1, 3, 5)]
    print(f"    ({H}, {f(r[0])}, {f(r[1])}, {f(r[2])}),")
print("// (g, erf(1/(2 sqrt g)), erfc(1/(2 sqrt g)), ln erfc(1/(2 sqrt g)))")
for g in ["1e-12", "1e-6", "1e-3", "0.01", "0.6", "2", "100", "1e10", "1e20", "1e30"]:
    x = 1 / (2 * mp.sqrt(mp.mpf(float(g))))
    print(f"    ({g}, {f(mp.erf(x))}, {f(mp.erfc(x))}, {f(mp.log(mp.erfc(x)))}),")

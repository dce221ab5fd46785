"""mpmath (50 digits) references of tests/core.rs
`pressures_over_twelve_decades_match_the_closed_form`: at full magnification
a spectrum of rms slope h'_rms has G = (π/4)(E*/σ0)² h'_rms²/(2π) =
(E* h'_rms)²/(8 σ0²), so A/A0 = erf(1/(2√G)) = erf(√2 σ0/(E* h'_rms)).
With E* = h'_rms = 1 and σ0 = 10^(i−12), i = 0 … 13 (each σ0 taken as its
exact f64 value): prints (σ0, erf(√2 σ0), erfc(√2 σ0)) as a Rust table.

Run: /path/to/venv/bin/python tests/reference/full_magnification.py
"""
import mpmath as mp

mp.mp.dps = 50


def f(x):
    return mp.nstr(x, 20, min_fixed=-1, max_fixed=-1)


print("const FULL_MAGNIFICATION: [(f64, f64, f64); 14] = [")
for i in range(14):
    s = mp.mpf(float(10.0 ** (i - 12)))
    x = mp.sqrt(2) * s
    print(f"    ({float(s)!r}, {f(mp.erf(x))}, {f(mp.erfc(x))}),")
print("];")

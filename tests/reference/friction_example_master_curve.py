"""Write tests/reference/data/rubber_master_curve.csv: the 16-term Prony rubber of
benches/friction.rs (E_inf = 2 MPa, E_k = 3e8/(1 + (k - 8)^2/8) Pa,
tau_k = 10^(k - 12) s) sampled as a DMA master curve, 5 points per decade
from 1e-2 to 1e10 rad/s, with mpmath (30 digits, printed to 10).

E(w) = E_inf + sum_k E_k i w tau_k / (1 + i w tau_k).
"""
import mpmath as mp

mp.mp.dps = 30
E_INF = mp.mpf(2e6)
TERMS = [(mp.mpf(3e8) / (1 + mp.mpf(k - 8) ** 2 / 8), mp.mpf(10) ** (k - 12)) for k in range(16)]

lines = [
    "# Example rubber master curve at T_ref = 293.15 K (a synthetic tread-like compound:",
    "# the 16-term Prony series of benches/friction.rs sampled by",
    "# tests/reference/friction_example_master_curve.py). WLF for it: C1 = 8.86, C2 = 101.6 K.",
    "omega_rad_per_s,storage_modulus_Pa,loss_modulus_Pa",
]
for i in range(61):
    w = mp.mpf(10) ** (mp.mpf(i) / 5 - 2)
    e = E_INF + sum(ek * 1j * w * tk / (1 + 1j * w * tk) for ek, tk in TERMS)
    lines.append(f"{mp.nstr(w, 10)},{mp.nstr(e.real, 10)},{mp.nstr(e.imag, 10)}")
open("tests/reference/data/rubber_master_curve.csv", "w").write("\n".join(lines) + "\n")

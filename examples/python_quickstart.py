"""Quick start for Python users: a rough surface → A/A0 and P(σ) from
Persson's theory → a BEM check on a synthesised surface → a figure.

    pip install ./python            # from the repository root; Python ≥ 3.9 + Rust
    python examples/python_quickstart.py [figure.png]

matplotlib is optional: without it the numbers are printed and the figure
is skipped.
"""

import sys

import numpy as np

import persson

# 1. The surface: self-affine, H = 0.8, on a periodic square of side L = 1 mm.
#    q_l = 2π/L, roll-off at 2 q_l, q_s = 32 q_l (resolved by a 256² grid with
#    4 pixels per shortest wavelength); rms slope 0.1. Rubber-like body on a
#    rigid surface: E = 10 MPa, ν = 0.5.
L = 1e-3
q_l = 2 * np.pi / L
spectrum = persson.Spectrum.self_affine(0.8, q_l, 32 * q_l, q_r=2 * q_l, rms_slope=0.1)
E_star = persson.contact_modulus(10e6, 0.5)
print(f"E* = {E_star:.4g} Pa, h_rms = {spectrum.rms_height():.3g} m, "
      f"h'_rms = {spectrum.rms_slope():.3g}")

# 2. Persson's theory: A/A0 against nominal pressure σ0 (numpy in, numpy out),
#    with its error bound, and a corrected theory beside it.
sigma0 = np.logspace(3, 6, 200)  # Pa
area, bound = persson.contact_area(spectrum, E_star, sigma0, error_bound=True)
area_xu = persson.contact_area(spectrum, E_star, sigma0, "xu")
print(f"A/A0 at σ0 = 1e5 Pa: {np.interp(1e5, sigma0, area):.4f} "
      f"(bound on its error {bound.max():.1e})")

# The stress distribution P(σ) at full magnification for a flat start at σ0.
p0 = 1e5
zeta_max = spectrum.q_s / spectrum.q_l
dist = persson.stress_physical(spectrum, E_star, [zeta_max], "flat", peak_pressure=p0)
curve = dist["curves"][0]

# 3. The BEM check: the same spectrum synthesised on a 256² grid (seed 1),
#    solved at three pressures; and the pressure field at σ0 = p0.
heights = persson.synthesize(spectrum, 256, size=L, seed=1)
check = [1e4, 3e4, 1e5]
bem = persson.bem_rough(E_star, check, heights=heights, size=L)
for point in bem["points"]:
    theory = persson.contact_area(spectrum, E_star, point["nominal_pressure"])
    print(f"σ0 = {point['nominal_pressure']:.0e} Pa: BEM A/A0 = {point['contact_fraction']:.4f}, "
          f"theory {theory:.4f}")
pressure, gap, summary = persson.bem_solve(heights, L, E_star, pressure=p0)
print(f"BEM at σ0 = {p0:.0e} Pa: {summary['iterations']} iterations, "
      f"mean gap {summary['mean_separation']:.3g} m")

# 4. The figure.
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: no figure")
    sys.exit(0)

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.loglog(sigma0, area, label="Persson (2001)")
left.loglog(sigma0, area_xu, "--", label="Xu et al. (2024)")
left.loglog(check, [p["contact_fraction"] for p in bem["points"]], "o", label="BEM 256²")
left.set_xlabel("nominal pressure σ0 (Pa)")
left.set_ylabel("A/A0")
left.legend()
contact = pressure[pressure > 0]
density, edges = np.histogram(contact, bins=40, range=(0, curve["sigma"][-1]))
density = density / (pressure.size * np.diff(edges))  # ∫ P dσ = A/A0
right.plot(curve["sigma"], curve["density"], label="Persson, flat start")
right.stairs(density, edges, label="BEM 256²")
right.set_xlabel("local pressure σ (Pa)")
right.set_ylabel("P(σ) (1/Pa)")
right.set_title(f"σ0 = {p0:.0e} Pa")
right.legend()
fig.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "python_quickstart.png"
fig.savefig(out, dpi=120)
print(f"wrote {out}")

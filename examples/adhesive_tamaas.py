"""Side by side: persson's adhesive FFT-BEM and Tamaas 2.9's PolonskyKeerRey
(gap primal and gap constraint) with MaugisAdhesionFunctional, on the same
heights, mean gap, law and tolerance (1e-10), at 256² and 512².
`--cohesive-stress S` sets Δγ/ρ = S E* (default 0.02; ρ = h_rms/20): the
cohesive length E*ρ²/Δγ is 2.3 grid spacings at 256² for 0.02, 9.4 for 0.005
(docs/adhesion.md: below about 8 the discrete Maugis-Dugdale energy has
stationary points far enough apart that two solvers need not agree).

Run from the workspace root (builds and runs examples/adhesive_tamaas.rs), with
Tamaas in a venv outside the repository (python3 -m venv ../peers &&
../peers/bin/pip install tamaas):
    ../peers/bin/python examples/adhesive_tamaas.py [N ...] [--law exponential] [--plain] [--preconditioned] [--cohesive-stress S]
Prints both answers, their relative differences and the wall time per solve of
each (one solve each, cold start), with the load average (`uptime`). Ours uses
the solver's iteration for the law (preconditioned for the exponential law,
plain for Maugis-Dugdale); `--plain` also runs the plain iteration;
`--preconditioned` uses the preconditioned iteration whatever the law.
"""
import json
import os
import subprocess
import sys
import time

import numpy as np
import tamaas as tm

TOLERANCE = 1e-10


def persson(n, out, law, method="auto", cohesive_stress=0.02):
    cmd = ["cargo", "run", "--quiet", "--release", "--example", "adhesive_tamaas",
           "--", str(n), out, law, method, repr(cohesive_stress)]
    return json.loads(subprocess.run(cmd, check=True, capture_output=True,
                                     text=True).stdout)


def check(gap, heights, ours, law):
    """Our KKT residual ε (src/bem/adhesive.rs) and the energy Π/A of a gap
    field, in numpy: an independent check that a solution is stationary."""
    n = heights.shape[0]
    rho, dg = ours["adhesion_range"], ours["work_of_adhesion"]
    k = np.fft.fftfreq(n, 1.0 / n) * 2.0 * np.pi
    q = np.sqrt(k[:, None] ** 2 + k[None, :] ** 2)
    w = np.real(np.fft.ifft2(np.fft.fft2(gap + heights) * q / 2.0))
    if law == "exponential":
        attraction = dg / rho * np.exp(-gap / rho)
        adhesion = -dg * np.exp(-gap / rho)
    else:
        attraction = np.where(gap < rho, dg / rho, 0.0)
        adhesion = np.where(gap < rho, -dg * (1.0 - gap / rho), 0.0)
    r = w + attraction
    free = gap > 0.0
    mean = r[free].mean()
    d = r - mean
    res = np.sum(d[free] ** 2) + np.sum(np.minimum(d[~free], 0.0) ** 2)
    scale = np.sum(w ** 2) + np.sum(np.where(free, attraction, 0.0) ** 2) + n ** 4 * mean ** 2
    energy = 0.5 * np.mean((gap + heights) * w) + np.mean(adhesion)
    return np.sqrt(res / scale), energy


def tamaas(heights, ours, law):
    n = heights.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
    model.E, model.nu = 1.0, 0.0  # E* = E/(1 - ν²) = 1
    solver = tm.PolonskyKeerRey(model, heights, TOLERANCE,
                                tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
    solver.max_iter = 20000
    functional = (tm.ExponentialAdhesionFunctional if law == "exponential"
                  else tm.MaugisAdhesionFunctional)(heights)
    functional.parameters = {"rho": ours["adhesion_range"],
                             "surface_energy": ours["work_of_adhesion"]}
    solver.addFunctionalTerm(functional)
    start = time.perf_counter()
    solver.solve(ours["mean_gap"])
    seconds = time.perf_counter() - start
    # Tamaas keeps the gap as its primal; the model holds u = g + h
    gap = np.asarray(model.displacement).reshape(n, n) - heights
    gap[np.abs(gap) < 1e-12 * np.abs(heights).max()] = 0.0
    traction = np.asarray(model.traction).reshape(n, n)
    rho = ours["adhesion_range"]
    return {
        "mean_pressure": float(traction.mean()),
        "contact_fraction": float((gap <= 0.0).mean()),
        "cohesive_fraction": float(((gap > 0.0) & (gap < rho)).mean()),
        "mean_gap": float(gap.mean()),
        "seconds": seconds,
        "gap": np.maximum(gap, 0.0),
    }


def main():
    law = "exponential" if "--law" in sys.argv and "exponential" in sys.argv else "maugis"
    cs = 0.02
    if "--cohesive-stress" in sys.argv:
        cs = float(sys.argv[sys.argv.index("--cohesive-stress") + 1])
    grids = [int(a) for a in sys.argv[1:] if a.isdigit()] or [256, 512]
    out = os.path.join("target", "adhesive_tamaas")
    os.makedirs(out, exist_ok=True)
    tm.set_log_level(tm.LogLevel.error)
    for n in grids:
        plain = persson(n, out, law, "plain", cs) if "--plain" in sys.argv else None
        ours = persson(n, out, law,
                       "preconditioned" if "--preconditioned" in sys.argv else "auto", cs)
        heights = np.load(os.path.join(out, f"surface_{n}.npy"))
        theirs = tamaas(heights, ours, law)
        load = os.getloadavg()
        print(f"N = {n}, law {law}, cohesive stress {cs} E*, "
              f"cohesive length {ours['zone_nodes']:.2f} grid spacings, mean gap {ours['mean_gap']:.6e}, "
              f"load average {load[0]:.1f}")
        for key in ("mean_pressure", "contact_fraction", "cohesive_fraction"):
            a, b = ours[key], theirs[key]
            print(f"  {key:18s} persson {a:.8e}  tamaas {b:.8e}  "
                  f"relative difference {abs(a - b) / abs(b):.2e}")
        print(f"  tamaas mean gap {theirs['mean_gap']:.8e}")
        for who, gap in (("persson", np.load(os.path.join(out, f"gap_{n}.npy"))),
                         ("tamaas", theirs["gap"])):
            eps, energy = check(gap, heights, ours, law)
            print(f"  {who:7s} KKT residual {eps:.1e}, energy/A {energy:.10e}")
        print(f"  time per solve: persson {ours['seconds']:.3f} s "
              f"({ours['method']}, {ours['iterations']} iterations, converged "
              f"{ours['converged']}, fallback {ours['fallback']}), "
              f"tamaas {theirs['seconds']:.3f} s, ratio {theirs['seconds'] / ours['seconds']:.1f}")
        if plain is not None:
            print(f"  persson plain: {plain['seconds']:.3f} s ({plain['iterations']} iterations), "
                  f"mean pressure {plain['mean_pressure']:.8e} (relative difference "
                  f"{abs(plain['mean_pressure'] - ours['mean_pressure']) / abs(ours['mean_pressure']):.1e}), "
                  f"ratio tamaas/plain {theirs['seconds'] / plain['seconds']:.1f}")


if __name__ == "__main__":
    main()

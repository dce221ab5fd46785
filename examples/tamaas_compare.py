#!/usr/bin/env python3
"""Side-by-side timing of `persson bem` and Tamaas on the same input.

Both solvers get the same heights, load, modulus and tolerance (Tamaas's
PolonskyKeerRey error and ours are the same measure: the p-weighted gap over
the contact, relative to the standard deviation of the heights), one thread.

Usage (Tamaas lives in a venv outside the repo):
    python3 -m venv ../peers && ../peers/bin/pip install tamaas
    cargo build --release
    OMP_NUM_THREADS=1 ../peers/bin/python examples/tamaas_compare.py \
        [--grids 512 1024] [--tolerance 1e-10] [--bin target/release/persson]

For each grid it runs the Hertz periodic case (a = 0.1 L, R = L = E* = 1) and
a rough case (self-affine H = 0.8, rms slope 0.1, q_l = 2π/L, q_r = 4 q_l,
q_s = (N/4)(2π/L), seed 1, mean pressure `--rough-pressure`, default
0.005 E*), and prints one line per case: the solve times reported by each
code, the whole-process wall times (ours: `persson bem rough`, synthesis and
the two .npy files included; Tamaas: a fresh Python process that imports
tamaas, reads the heights, solves and writes the pressure), their ratios,
the contact fractions and the largest pressure difference relative to the
peak pressure.

With `--yield-stress Y1 Y2 …` it compares the saturated contact instead
(0 ≤ p ≤ σY, Tamaas' KatoSaturated against `Options::yield_stress` through
`examples/saturated_solve.rs`, build it with
`cargo build --release --example saturated_solve`): the rough surface above
at mean pressure `--pressure` (default 0.006 E*), one line per grid and σY
with both times, the total and plastic fractions and their relative
differences, and the largest pressure difference relative to the peak.
"""
import argparse
import json
import math
import os
import subprocess
import tempfile
import time

import numpy as np


# One Tamaas solve in a fresh process: argv = heights.npy pressure tol out.npy;
# prints the solve time.
TAMAAS_PROCESS = """
import sys, time
import numpy as np
import tamaas as tm
heights = np.load(sys.argv[1])
pressure, tol = float(sys.argv[2]), float(sys.argv[3])
n = heights.shape[0]
model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
model.E = 1.0
model.nu = 0.0  # E* = E/(1 - nu^2) = 1
solver = tm.PolonskyKeerRey(model, heights, tol)
solver.max_iter = 10000
t = time.perf_counter()
solver.solve(pressure)
print(time.perf_counter() - t)
np.save(sys.argv[4], np.array(model.traction).reshape(n, n))
"""


def tamaas_solve(heights_file, pressure, tol, out):
    """Solve time, whole-process wall time and pressure of a Tamaas run."""
    import sys
    t = time.perf_counter()
    res = subprocess.run([sys.executable, "-c", TAMAAS_PROCESS, heights_file, repr(pressure),
                          repr(tol), out], check=True, capture_output=True, text=True)
    wall = time.perf_counter() - t
    return np.load(out), float(res.stdout.split()[-1]), wall


def tamaas_saturated(heights, pressure, y, tol):
    import tamaas as tm
    n = heights.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
    model.E = 1.0
    model.nu = 0.0
    solver = tm.KatoSaturated(model, heights, tol, y)
    solver.max_iter = 100000
    t = time.perf_counter()
    solver.solve(pressure)
    dt = time.perf_counter() - t
    return np.array(model.traction).reshape(n, n), dt


def saturated(a, tmp):
    ql = 2 * math.pi
    for n in a.grids:
        surf = os.path.join(tmp, "rough.npy")
        pf = os.path.join(tmp, "p_rough.npy")
        # The surface: persson's synthesis (seed 1), written to .npy.
        ours(a.bin, ["rough", "--hurst", "0.8", "--q-l", repr(ql), "--q-r", repr(4 * ql),
                     "--q-s", repr(ql * n / 4), "--rms-slope", "0.1", "--size", "1",
                     "--grid", str(n), "--seed", "1", "--contact-modulus", "1",
                     "--pressure", repr(a.pressure), "--tolerance", "1e-4",
                     "--surface-out", surf])
        heights = np.load(surf)
        for y in a.yield_stress:
            out = subprocess.run([a.saturated_bin, surf, repr(a.pressure), repr(y),
                                  repr(a.tolerance), pf],
                                 check=True, capture_output=True, text=True).stdout
            us = json.loads(out)
            p_us = np.load(pf).reshape(heights.shape)
            p_tm, t_tm = tamaas_saturated(heights, a.pressure, y, a.tolerance)
            dp = float(np.abs(p_tm - p_us).max() / p_tm.max())
            tot = float((p_tm > 0).mean())
            pl = float((p_tm >= y * (1 - 1e-12)).mean())
            rel = lambda x, ref: abs(x - ref) / ref if ref > 0 else abs(x)
            print(f"saturated {n:>5}  sigma_Y {y:g}  tamaas {t_tm:7.3f} s  persson "
                  f"{us['seconds']:7.3f} s  speed-up {t_tm / us['seconds']:6.1f}x  "
                  f"A/A0 {tot:.6f} vs {us['contact_fraction']:.6f} "
                  f"(rel {rel(us['contact_fraction'], tot):.1e})  A_pl/A0 {pl:.6f} vs "
                  f"{us['plastic_fraction']:.6f} (rel {rel(us['plastic_fraction'], pl):.1e})  "
                  f"max|dp|/p_max {dp:.1e}  mean p {p_tm.mean():.6e}  iterations {us['iterations']}",
                  flush=True)


def ours(binary, args):
    """The JSON report of `persson bem` and the process's wall time."""
    t = time.perf_counter()
    out = subprocess.run([binary, "bem"] + args + ["--json"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out), time.perf_counter() - t


def compare(name, n, heights_file, pressure, ours_run, ours_p, tol, tmp):
    ours_json, wall_us = ours_run
    p_tm, t_tm, wall_tm = tamaas_solve(heights_file, pressure, tol,
                                       os.path.join(tmp, "p_tamaas.npy"))
    pt = ours_json["points"][0] if "points" in ours_json else ours_json
    t_us = pt["seconds"]
    frac_tm = float((p_tm > 0).mean())
    dp = float(np.abs(p_tm - ours_p).max() / p_tm.max())
    print(f"{name:<16} {n:>5}  solve: tamaas {t_tm:7.3f} s  persson {t_us:7.3f} s  "
          f"({t_tm / t_us:5.1f}x)  process: tamaas {wall_tm:7.3f} s  persson {wall_us:7.3f} s  "
          f"({wall_tm / wall_us:5.1f}x)  A/A0 {frac_tm:.6f} vs {pt['contact_fraction']:.6f} "
          f"(diff {abs(frac_tm - pt['contact_fraction']):.1e})  max|dp|/p_max {dp:.1e}  "
          f"iterations {pt['iterations']}", flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--grids", type=int, nargs="+", default=[512, 1024])
    ap.add_argument("--tolerance", type=float, default=1e-10)
    ap.add_argument("--bin", default="target/release/persson")
    ap.add_argument("--yield-stress", type=float, nargs="*", default=None)
    ap.add_argument("--pressure", type=float, default=0.006)
    ap.add_argument("--rough-pressure", type=float, default=0.005)
    ap.add_argument("--cases", nargs="+", default=["hertz", "rough"])
    ap.add_argument("--saturated-bin", default="target/release/examples/saturated_solve")
    a = ap.parse_args()
    if os.environ.get("OMP_NUM_THREADS") != "1":
        print("warning: set OMP_NUM_THREADS=1 for a one-thread comparison")
    tmp = tempfile.mkdtemp()
    if a.yield_stress:
        saturated(a, tmp)
        return
    for n in a.grids:
        if "hertz" in a.cases:
            # Hertz, periodic: the same nodes and paraboloid as `persson bem hertz`.
            x = np.arange(n) / n - 0.5
            X, Y = np.meshgrid(x, x, indexing="ij")
            heights = -(X ** 2 + Y ** 2) / 2.0
            hz = os.path.join(tmp, "hertz.npy")
            np.save(hz, heights)
            pf = os.path.join(tmp, "p_hertz.npy")
            load = 4 * 0.1 ** 3 / 3
            run = ours(a.bin, ["rough", "--surface", hz, "--size", "1", "--contact-modulus", "1",
                               "--pressure", repr(load), "--tolerance", repr(a.tolerance),
                               "--pressure-field", pf])
            compare("hertz periodic", n, hz, load, run, np.load(pf), a.tolerance, tmp)

        if "rough" in a.cases:
            # Rough: synthesised by persson, written to .npy, read by Tamaas.
            ql = 2 * math.pi
            surf = os.path.join(tmp, "rough.npy")
            pf = os.path.join(tmp, "p_rough.npy")
            run = ours(a.bin, ["rough", "--hurst", "0.8", "--q-l", repr(ql),
                               "--q-r", repr(4 * ql), "--q-s", repr(ql * n / 4),
                               "--rms-slope", "0.1", "--size", "1", "--grid", str(n),
                               "--seed", "1", "--contact-modulus", "1",
                               "--pressure", repr(a.rough_pressure),
                               "--tolerance", repr(a.tolerance),
                               "--surface-out", surf, "--pressure-field", pf])
            compare(f"rough H=0.8 {a.rough_pressure:g}", n, surf, a.rough_pressure, run,
                    np.load(pf), a.tolerance, tmp)


if __name__ == "__main__":
    main()

"""Speed of the Python package, as quoted in the README.

    target/python-venv/bin/python scripts/python_bench.py

1. `contact_area` over 10⁶ nominal pressures (one call, numpy in and out).
2. One 512² FFT-BEM solve from Python (`bem_solve`) against the same solve
   by the CLI (`persson bem rough --surface h.npy`), each the best of three
   interleaved runs: the solver's own wall time (`seconds`) and the end-to-end wall time
   (Python: the call; CLI: the whole process, reading the map included).
The CLI is $PERSSON_BIN or target/release/persson.
"""

import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

import persson

ROOT = pathlib.Path(__file__).resolve().parents[1]
BIN = os.environ.get("PERSSON_BIN", str(ROOT / "target" / "release" / "persson"))
REPEAT = 3


def best(f):
    return min(f() for _ in range(REPEAT))


def area_speed():
    s = persson.Spectrum.example()
    p = np.logspace(4, 8.5, 10**6)

    def run():
        t = time.perf_counter()
        persson.contact_area(s, 1e9, p)
        return time.perf_counter() - t

    return best(run)


def bem_speed(n=512, pressure=0.01):
    tau = 2 * np.pi
    s = persson.Spectrum.self_affine(0.8, tau, 64 * tau, q_r=2 * tau, rms_slope=0.1)
    h = persson.synthesize(s, n, size=1.0, seed=1)
    with tempfile.TemporaryDirectory() as d:
        path = pathlib.Path(d) / "h.npy"
        np.save(path, h)

        def python():
            t = time.perf_counter()
            _, _, summary = persson.bem_solve(h, 1.0, 1.0, pressure=pressure)
            return time.perf_counter() - t, summary["seconds"], summary["iterations"]

        def cli():
            t = time.perf_counter()
            out = subprocess.run(
                [BIN, "bem", "rough", "--surface", str(path), "--size", "1",
                 "--contact-modulus", "1", "--pressure", str(pressure), "--json"],
                check=True, capture_output=True, text=True,
            ).stdout
            point = json.loads(out)["points"][0]
            return time.perf_counter() - t, point["seconds"], point["iterations"]

        # Interleaved, so that a change of machine load hits both alike.
        runs = [(python(), cli()) for _ in range(REPEAT)]
        py = min(r[0] for r in runs)
        cl = min(r[1] for r in runs)
    return py, cl


def main():
    t = area_speed()
    print(f"contact_area, 10^6 pressures: {t:.3f} s (best of {REPEAT})")
    (py_wall, py_solve, py_it), (cli_wall, cli_solve, cli_it) = bem_speed()
    assert py_it == cli_it, (py_it, cli_it)
    print(f"BEM 512², {py_it} iterations: Python {py_wall:.3f} s (solver {py_solve:.3f} s), "
          f"CLI {cli_wall:.3f} s (solver {cli_solve:.3f} s); "
          f"Python/CLI end to end {py_wall / cli_wall:.3f}, solver {py_solve / cli_solve:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""SurfaceTopography's time for the work of examples/topography_speed.rs.

    OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /work/venv-st/bin/python tests/reference/speed_surface_topography.py [N]

detrend('height') + power_spectrum_from_area(window='hann') of an N × N
non-periodic map (N = 4096 by default), wall and CPU time and peak memory.
The map's content does not change the work; it is a 2D random walk like the
Rust example's.
"""
import resource
import sys
import time

import numpy as np
from SurfaceTopography import Topography

n = int(sys.argv[1]) if len(sys.argv) > 1 else 4096
h = np.cumsum(np.cumsum(np.random.default_rng(12345).random((n, n)) - 0.5, axis=1), axis=0)
t = Topography(h, physical_sizes=(1e-3, 1e-3), periodic=False)
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
w0, c0 = time.perf_counter(), time.process_time()
q, c = t.detrend("height").power_spectrum_from_area(window="hann")
w1, c1 = time.perf_counter(), time.process_time()
after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print(f"{n}² map: SurfaceTopography detrend('height') + hann spectrum in {w1 - w0:.3f} s wall, {c1 - c0:.3f} s cpu")
print(f"peak extra memory {(after - before) / 1e3:.0f} MB = {(after - before) * 1e3 / (8 * n * n):.2f} N² doubles")

"""Wall time of `persson.ensemble` on a Dask LocalCluster with one and with
two worker processes (one thread each), against the serial run, and the check
that all three give the same table to the last digit.

    pip install ./python "dask[distributed]"
    python examples/ensemble_dask.py [grid] [seeds]

The cluster is started before the clock and reused for every repetition, so
the times are the study's (task shipping, surface synthesis on the workers,
solves, gathering), not the workers' start-up. docs/python.md quotes the
figures measured with the defaults.
"""

import math
import sys
import time

import persson
from dask.distributed import Client, LocalCluster

GRID = int(sys.argv[1]) if len(sys.argv) > 1 else 256
SEEDS = int(sys.argv[2]) if len(sys.argv) > 2 else 4
REPEAT = 3
PRESSURES = [0.002, 0.005, 0.01, 0.02]


def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k != "seconds"}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v


def best_of(f):
    times, result = [], None
    for _ in range(REPEAT):
        t0 = time.perf_counter()
        result = f()
        times.append(time.perf_counter() - t0)
    return min(times), result


def main():
    s = persson.Spectrum.self_affine(0.8, 2 * math.pi, 64 * math.pi, q_r=4 * math.pi,
                                     rms_slope=0.1)
    settings = dict(grid=GRID, levels=2, seeds=SEEDS, seed=1)
    t_serial, serial = best_of(lambda: persson.ensemble(s, 1.0, PRESSURES, **settings))
    print(f"{SEEDS} seeds x grids {GRID // 2}, {GRID}; {len(PRESSURES)} pressures")
    print(f"serial (client=None, 1 thread): {t_serial:.2f} s")
    for workers in (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            persson.ensemble(s, 1.0, PRESSURES[:1], grid=32, levels=2, seeds=1,
                             client=client)  # workers import persson before the clock
            t, r = best_of(lambda: persson.ensemble(s, 1.0, PRESSURES, client=client,
                                                    **settings))
        assert strip(r) == strip(serial), "the distributed table differs from the serial one"
        print(f"Dask LocalCluster, {workers} worker(s): {t:.2f} s (equal to serial: yes)")


if __name__ == "__main__":
    main()

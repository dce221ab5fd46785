"""Whole-process times of examples/read_speed.rs and read_speed.py, side by side.

    cargo build --release --example read_speed
    /work/venvs/readers/bin/python tests/reference/read_speed_compare.py [--fill] FILE...

Runs each process `RUNS` times, alternating, and prints per file the median
wall time and the median CPU time (user + system, of the child) of each, and
their ratios. The CPU time is the figure to quote on a shared machine (wall
time includes waiting for the cores).
"""
import os
import resource
import statistics
import subprocess
import sys
import time

RUNS = 5
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
OURS = [os.path.join(ROOT, "target", "release", "examples", "read_speed")]
THEIRS = [sys.executable, os.path.join(HERE, "read_speed.py")]


def run(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main():
    fill = ["--fill"] if "--fill" in sys.argv else []
    for f in [a for a in sys.argv[1:] if a != "--fill"]:
        ours, theirs = [], []
        for _ in range(RUNS):
            ours.append(run(OURS + [f] + fill))
            theirs.append(run(THEIRS + [f] + fill))
        med = lambda xs, i: statistics.median(x[i] for x in xs)  # noqa: E731
        ow, oc, tw, tc = med(ours, 0), med(ours, 1), med(theirs, 0), med(theirs, 1)
        print(f"{os.path.basename(f)}{' --fill' if fill else ''}: persson wall {ow:.3f} s "
              f"cpu {oc:.3f} s; SurfaceTopography wall {tw:.2f} s cpu {tc:.2f} s; "
              f"ratio wall {tw / ow:.0f}, cpu {tc / max(oc, 1e-3):.0f}")


if __name__ == "__main__":
    main()

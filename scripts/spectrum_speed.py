"""`persson spectrum --surface FILE` against SurfaceTopography, whole process.

    ST_PYTHON=/path/to/venv/bin/python python3 scripts/spectrum_speed.py [options] FILE...

For each FILE, runs the CLI (`$PERSSON_BIN`, default target/release/persson,
built by `cargo build --release -p persson-cli --features full`) and
SurfaceTopography doing the same work in a fresh interpreter: read the
file, remove the least-squares plane, the isotropic power spectrum with its
default window and the rms height, gradient and Laplacian (for a line
scan: the profile spectrum and the profile rms values); with `--light`
only the spectrum and the rms height, a `.npy` read by numpy.load (its
fastest route, a lower bound of its time). Each is timed as a
whole process (start-up, imports and reading included), `--runs` times
alternating, and the best wall time is reported with the peak resident set
size of that run and the ratio SurfaceTopography / persson.

The SurfaceTopography interpreter is `--st-python` or `$ST_PYTHON`
(a virtual environment with SurfaceTopography, e.g. 1.27.1); this script
itself needs only the standard library. A file that persson refuses for
undefined points is run with `--fill-undefined` on both sides
(`interpolate_undefined_data()`), one without a physical size with
`--pixel-size` of `--pixel-size` (default 1e-6 m) on both sides.

`--npy N:PATH` first writes a random-phase self-affine N × N float64 map
(H = 0.8, rms 1 µm) to PATH with the SurfaceTopography interpreter's numpy
(kept if it exists) and times it with the other files, e.g.

    ST_PYTHON=... python3 scripts/spectrum_speed.py --npy 4096:/tmp/map4096.npy \\
        tests/data/*.mi tests/data/*.frt

Prints a Markdown table. Quote the figures of an idle machine: the wall
time of both includes waiting for the cores.
"""
import argparse
import os
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]

# What SurfaceTopography runs for one file (argv: FILE PIXEL_SIZE|- fill|-).
# (argv: FILE PIXEL_SIZE|- fill|- full|light). `light`: a .npy through
# numpy.load (SurfaceTopography's own NPY reader, through NuMPI, takes a
# minute on a 4096² map) and no rms gradient or Laplacian (8 s each there
# on a 4096² non-periodic map): its fastest route to the spectrum.
ST_WORK = r"""
import sys
import SurfaceTopography as st
f, px, fill, light = sys.argv[1], sys.argv[2], sys.argv[3] == "fill", sys.argv[4] == "light"
if light and f.endswith(".npy"):
    import numpy as np
    h = np.load(f)
    t = st.Topography(h, physical_sizes=tuple(n * float(px) for n in h.shape), periodic=False)
else:
    r = st.open_topography(f)
    ch = r.default_channel
    kw = {}
    if px != "-":
        kw["physical_sizes"] = tuple(n * float(px) for n in ch.nb_grid_pts)
    t = r.topography(**kw)
if fill and t.has_undefined_data:
    t = t.interpolate_undefined_data()
d = t.detrend("height")
if t.dim == 2:
    d.power_spectrum_from_area()
    print(d.rms_height_from_area())
    if not light:
        print(d.rms_gradient(), d.rms_laplacian())
else:
    d.power_spectrum_from_profile()
    print(d.rms_height_from_profile())
    if not light:
        print(d.rms_slope_from_profile(), d.rms_curvature_from_profile())
"""

MAKE_NPY = r"""
import sys
import numpy as np
n, path = int(sys.argv[1]), sys.argv[2]
rng = np.random.default_rng(1)
qx, qy = np.fft.fftfreq(n), np.fft.rfftfreq(n)
q = np.hypot(qx[:, None], qy[None, :])
q[0, 0] = 1
amp = q ** -1.8
amp[0, 0] = 0
h = np.fft.irfft2(amp * np.exp(2j * np.pi * rng.random(amp.shape)), s=(n, n))
np.save(path, (h / h.std() * 1e-6).astype(np.float64))
"""


def run(cmd):
    """(wall s, peak RSS MB, return code, stderr) of one process."""
    start = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read()
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - start
    p.returncode = os.waitstatus_to_exitcode(status)
    # ru_maxrss is in kB on Linux
    return wall, usage.ru_maxrss / 1024, p.returncode, err.decode(errors="replace")


def options(persson, f, pixel):
    """The flags `f` needs (fill, pixel size), found by asking persson."""
    flags = []
    for _ in range(3):
        _, _, rc, err = run([persson, "spectrum", "--surface", f, *flags])
        if rc == 0:
            return flags
        if "undefined" in err and "--fill-undefined" not in flags:
            flags.append("--fill-undefined")
        elif "no physical size" in err and "--pixel-size" not in flags:
            flags += ["--pixel-size", str(pixel)]
        else:
            sys.exit(f"persson spectrum --surface {f} {' '.join(flags)} failed:\n{err}")
    return flags


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="*")
    ap.add_argument("--st-python", default=os.environ.get("ST_PYTHON"))
    ap.add_argument("--persson", default=os.environ.get(
        "PERSSON_BIN", str(ROOT / "target" / "release" / "persson")))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--pixel-size", type=float, default=1e-6)
    ap.add_argument("--npy", action="append", default=[], metavar="N:PATH")
    ap.add_argument("--light", action="store_true",
                    help="SurfaceTopography's fastest route: spectrum and rms height only, "
                    ".npy through numpy.load")
    a = ap.parse_args()
    if not a.st_python:
        sys.exit("give SurfaceTopography's python: --st-python PY or $ST_PYTHON")
    files = []
    for spec in a.npy:
        n, path = spec.split(":", 1)
        if not os.path.exists(path):
            subprocess.run([a.st_python, "-c", MAKE_NPY, n, path], check=True)
        files.append(path)
    files += a.files
    print("| file | persson (s) | peak RSS (MB) | SurfaceTopography (s) | peak RSS (MB) | ratio |")
    print("|---|---:|---:|---:|---:|---:|")
    for f in files:
        flags = options(a.persson, f, a.pixel_size)
        px = flags[flags.index("--pixel-size") + 1] if "--pixel-size" in flags else "-"
        fill = "fill" if "--fill-undefined" in flags else "-"
        ours, theirs = [], []
        for _ in range(a.runs):
            ours.append(run([a.persson, "spectrum", "--surface", f, *flags]))
            theirs.append(run([a.st_python, "-c", ST_WORK, f, px, fill,
                               "light" if a.light else "full"]))
        for name, r in (("persson", ours), ("SurfaceTopography", theirs)):
            bad = [x for x in r if x[2] != 0]
            if bad:
                sys.exit(f"{name} failed on {f}:\n{bad[0][3]}")
        o, t = min(ours), min(theirs)
        label = os.path.basename(f) + (" (" + " ".join(flags) + ")" if flags else "")
        print(f"| {label} | {o[0]:.3f} | {o[1]:.0f} | {t[0]:.2f} | {t[1]:.0f} | {t[0] / o[0]:.1f} |",
              flush=True)


if __name__ == "__main__":
    main()

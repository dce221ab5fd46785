"""Multi-scale spectrum: persson's mode-weighted combination against
SurfaceTopography's averaging (`log_average` of `power_spectrum_from_area`)
on the same three measurements (docs/multiscale.md quotes the output).

Run from the repository root with the release CLI built:
    /work/venvs/readers/bin/python tests/reference/multiscale_surface_topography.py
(SurfaceTopography 1.27.1, numpy). The three files are cut from one
periodic self-affine surface synthesised here with numpy (H = 0.8): a coarse
large scan (every 4th point, 512²), a medium one (every 2nd, 512²) and a
fine small one (512² at full resolution), each with its own white noise,
each plane-detrended with a Hann window in both codes.
"""

import json
import pathlib
import subprocess
import sys
import tempfile

import numpy as np
from SurfaceTopography import Topography
from SurfaceTopography.Container.SurfaceContainer import SurfaceContainer
from SurfaceTopography.Container.Averaging import log_average

N, L = 2048, 1e-3
ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = ROOT / "target" / "release" / "persson"


def synthesise(seed=25):
    rng = np.random.default_rng(seed)
    k = np.fft.fftfreq(N) * N
    q = 2 * np.pi / L * np.hypot(k[:, None], k[None, :])
    q[0, 0] = np.inf
    c = q ** (-2 * 1.8)
    a = np.sqrt(c) * (rng.standard_normal((N, N)) + 1j * rng.standard_normal((N, N)))
    h = np.fft.ifft2(a).real
    return h * 1e-6 / h.std()


def cut(h, x0, y0, n, step, sigma, seed):
    rng = np.random.default_rng(seed)
    m = h[y0:y0 + n * step:step, x0:x0 + n * step:step].copy()
    return m + sigma * rng.standard_normal(m.shape), n * step * L / N


def main():
    h = synthesise()
    maps = [cut(h, 0, 0, 512, 4, 2e-9, 1), cut(h, 300, 700, 512, 2, 1e-9, 2),
            cut(h, 1100, 200, 512, 1, 5e-10, 3)]
    tmp = pathlib.Path(tempfile.mkdtemp())
    args = []
    tops = []
    for i, (m, side) in enumerate(maps):
        path = tmp / f"m{i}.npy"
        np.save(path, m)
        args += ["--surface", str(path), "--size", repr(side)]
        # SurfaceTopography indexes heights [x, y]
        t = Topography(m.T.copy(), (side, side), unit="m", periodic=False).detrend("height")
        tops.append(t)
    out = subprocess.run([str(BIN), "spectrum", *args, "--json"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(out.stderr)
    ours = json.loads(out.stdout)
    q_ours, c_ours = np.array(ours["q"]), np.array(ours["c"])
    q_st, c_st = log_average(SurfaceContainer(tops), "power_spectrum_from_area", "m",
                             nb_points_per_decade=10, window="hann")
    q_st, c_st = q_st.compressed(), c_st.compressed() / (2 * np.pi) ** 2  # to Persson's
    inside = (q_st >= q_ours[0]) & (q_st <= q_ours[-1])
    ratio = np.exp(np.interp(np.log(q_st[inside]), np.log(q_ours), np.log(c_ours))) / c_st[inside]
    print("q (1/m)      C_persson/C_SurfaceTopography")
    for q, r in zip(q_st[inside], ratio):
        print(f"{q:.4e}   {r:.4f}")
    print(f"bins {inside.sum()}, median ratio {np.median(ratio):.4f}, "
          f"min {ratio.min():.4f}, max {ratio.max():.4f}")


if __name__ == "__main__":
    main()

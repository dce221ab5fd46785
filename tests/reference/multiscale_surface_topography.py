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
from SurfaceTopography.Support.Regression import resample

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


def st_average(tops, per_decade=10):
    """SurfaceTopography's `log_average` rule on area spectra: its
    `log_average` itself asks for unresampled data, which
    `power_spectrum_from_area` does not give (1.27.1), so each map's binned
    spectrum (`power_spectrum_from_area(window='hann')`) is re-binned with
    SurfaceTopography's `resample` onto the decade-aligned grid, as
    `log_average` does, and the maps are averaged unweighted per bin."""
    results = {}
    for t in tops:
        x, y = t.power_spectrum_from_area(window="hann", nb_points_per_decade=per_decade)
        keep = ~(np.ma.getmaskarray(x) | np.ma.getmaskarray(y))
        x, y = np.ma.getdata(x)[keep], np.ma.getdata(y)[keep]
        m = x > 0
        lo, hi = int(np.floor(np.log10(x[m].min()))), int(np.ceil(np.log10(x.max())))
        xc, _, yc, _ = resample(x[m], y[m], collocation="log", min_value=10.0**lo,
                                max_value=10.0**hi, nb_points=(hi - lo) * per_decade + 1)
        xc = np.ma.filled(np.ma.masked_invalid(xc).astype(float), np.nan)
        yc = np.ma.filled(np.ma.masked_invalid(yc).astype(float), np.nan)
        for j, (a, b) in enumerate(zip(xc, yc)):
            if np.isfinite(a) and np.isfinite(b) and a > 0 and b > 0:
                results.setdefault(lo * per_decade + j, []).append((a, b))
    keys = sorted(results)
    q = np.array([np.mean([v[0] for v in results[k]]) for k in keys])
    c = np.array([np.mean([v[1] for v in results[k]]) for k in keys])
    return q, c


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
    q_st, c_st = st_average(tops)
    c_st = c_st / (2 * np.pi) ** 2  # to Persson's
    inside = (q_st >= q_ours[0]) & (q_st <= q_ours[-1])
    ratio = np.exp(np.interp(np.log(q_st[inside]), np.log(q_ours), np.log(c_ours))) / c_st[inside]
    print("q (1/m)      C_persson/C_SurfaceTopography")
    for q, r in zip(q_st[inside], ratio):
        print(f"{q:.4e}   {r:.4f}")
    print(f"bins {inside.sum()}, median ratio {np.median(ratio):.4f}, "
          f"min {ratio.min():.4f}, max {ratio.max():.4f}")


if __name__ == "__main__":
    main()

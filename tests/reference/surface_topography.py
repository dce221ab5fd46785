"""Reference numbers for tests/topography.rs from SurfaceTopography 1.27.

Run in a virtual environment outside the repository:

    python3 -m venv /work/venv-st && /work/venv-st/bin/pip install SurfaceTopography numpy
    /work/venv-st/bin/python tests/reference/surface_topography.py

It writes two small deterministic maps to tests/reference/data/ (committed,
float64 .npy, C order, shape (ny, nx)) and prints, as Rust constants, what
SurfaceTopography computes on them: the rms height after each detrend mode,
the rms gradient and Laplacian (forward / 5-point stencils) of the
plane-detrended map, and the radially averaged spectrum (C_ST = (2π)² C_Persson)
with a Hann window (map A, non-periodic) and without (map B, periodic).

Map recipe: a 64-bit LCG (Knuth's MMIX constants) gives u_k in [0, 1); the
white field u − 1/2 is summed along rows then columns (a 2D random walk,
C ∝ q⁻⁴ roughly), scaled to nm and a plane and a quadratic are added.
"""
import os

import numpy as np
import SurfaceTopography
from SurfaceTopography import Topography

HERE = os.path.dirname(os.path.abspath(__file__))


def lcg_field(ny, nx, seed):
    x = seed
    out = np.empty(ny * nx)
    for k in range(ny * nx):
        x = (6364136223846793005 * x + 1442695040888963407) % 2**64
        out[k] = (x >> 11) * 2.0**-53 - 0.5
    return out.reshape(ny, nx)


def make_map(ny, nx, seed, pixel):
    w = lcg_field(ny, nx, seed)
    h = np.cumsum(np.cumsum(w, axis=1), axis=0) * 1e-9
    j, i = np.mgrid[0:ny, 0:nx]
    h += 1e-9 * (0.4 * i - 0.25 * j + 0.02 * i * i - 0.01 * i * j + 0.015 * j * j)
    return h, (ny * pixel, nx * pixel)


def rust_array(name, values):
    body = ", ".join(repr(float(v)) for v in values)
    return f"const {name}: [f64; {len(values)}] = [{body}];"


def report(tag, h, sizes, periodic, window):
    # SurfaceTopography's first axis is x: pass the sizes in (rows, columns) order.
    t = Topography(h, physical_sizes=sizes, periodic=periodic)
    print(f"// map {tag}: shape {h.shape}, sizes (rows, columns) {sizes}, periodic {periodic}")
    print(f"const {tag}_RMS_HEIGHT_NONE: f64 = {float(t.rms_height_from_area())!r};")
    for mode, name in [("center", "MEAN"), ("height", "PLANE"), ("curvature", "CURVATURE")]:
        print(f"const {tag}_RMS_HEIGHT_{name}: f64 = {float(t.detrend(mode).rms_height_from_area())!r};")
    # SurfaceTopography marks a map as non-periodic once a plane is removed
    # (and then uses the trimmed stencils and the default Hann window): keep
    # the periodic map periodic by removing only its mean.
    mode = "center" if periodic else "height"
    d = t.detrend(mode)
    assert d.is_periodic == periodic
    print(f"// slopes, curvatures and spectrum after detrend('{mode}')")
    print(f"const {tag}_RMS_GRADIENT: f64 = {float(d.rms_gradient())!r};")
    print(f"const {tag}_RMS_LAPLACIAN: f64 = {float(d.rms_laplacian())!r};")
    print(f"const {tag}_RMS_CURVATURE_FROM_AREA: f64 = {float(d.rms_curvature_from_area())!r};")
    q, c = d.power_spectrum_from_area(window=window)
    keep = ~np.ma.getmaskarray(c)
    print(rust_array(f"{tag}_Q", np.ma.getdata(q)[keep]))
    print(rust_array(f"{tag}_C_ST", np.ma.getdata(c)[keep]))


def report_profiles(tag, h, pixel):
    # The rows of the map as line scans: SurfaceTopography's profiles run
    # along its first axis, so pass the transpose. No detrending, Hann
    # window along the profiles (scipy's periodic Hann, mean square 1).
    t = Topography(h.T.copy(), physical_sizes=(h.shape[1] * pixel, h.shape[0] * pixel), periodic=False)
    q, c = t.power_spectrum_from_profile(window="hann")
    keep = ~np.ma.getmaskarray(c)
    print(f"// map {tag} rows as line scans, no detrending, window hann: C1D_ST = 2π C1D_Persson")
    print(rust_array(f"{tag}_PROFILE_Q", np.ma.getdata(q)[keep]))
    print(rust_array(f"{tag}_PROFILE_C1D_ST", np.ma.getdata(c)[keep]))


def main():
    print(f"// SurfaceTopography {SurfaceTopography.__version__}, numpy {np.__version__}")
    os.makedirs(os.path.join(HERE, "data"), exist_ok=True)
    a, sa = make_map(32, 40, 12345, 1e-6)
    b, sb = make_map(32, 32, 987654321, 2e-6)
    np.save(os.path.join(HERE, "data", "map_a.npy"), a)
    np.save(os.path.join(HERE, "data", "map_b.npy"), b)
    report("A", a, sa, False, "hann")
    report("B", b, sb, True, None)
    report_profiles("A", a, 1e-6)


if __name__ == "__main__":
    main()

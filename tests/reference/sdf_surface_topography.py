"""Reference numbers for the ISO 25178-71 .sdf tests of tests/instrument_files.rs.

Writes tests/data/sdf-2-binary.sdf, a binary SDF (bISO-1.0, int32 values,
Zscale 1e-9 m) of 5 points × 3 profiles with one undefined point (the
int32 minimum), packed as ISO 25178-71 lays out the binary header; then
reads it and tests/data/sdf-1.sdf (the standard's ASCII example, from
SurfaceTopography's test files) with SurfaceTopography's own reader and
prints what the Rust tests compare: grid, physical sizes and heights (µm, the
unit SurfaceTopography reports), and for sdf-1.sdf its rms height, slope and
Laplacian after removing the plane.

    python3 -m venv /work/venvs/readers
    /work/venvs/readers/bin/pip install SurfaceTopography numpy
    /work/venvs/readers/bin/python tests/reference/sdf_surface_topography.py

SurfaceTopography 1.27.1 and numpy 2 gave the numbers in the tests.
"""

import pathlib
import struct

import numpy as np
import SurfaceTopography as st

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"

raw = np.array([[10, 20, 35, 20, 10], [15, -2147483648, 40, 25, 12], [5, 8, 30, 18, 7]], dtype="<i4")
header = struct.pack(
    "<8s10s12s12sHHddddbbb", b"bISO-1.0", b"persson", b"071220261200", b"071220261200",
    5, 3, 2e-6, 3e-6, 1e-9, 1e-9, 0, 6, 0,
)
(DATA / "sdf-2-binary.sdf").write_bytes(header + raw.tobytes())

for name in ["sdf-1.sdf", "sdf-2-binary.sdf"]:
    t = st.open_topography(str(DATA / name)).topography()
    print(name, st.__version__, t.nb_grid_pts, t.physical_sizes, t.unit)
    h = np.ma.getdata(t.heights())
    mask = np.ma.getmaskarray(t.heights())
    print("heights [ix, iy]:", repr(np.where(mask, np.nan, h).T.ravel().tolist()))
    if name == "sdf-1.sdf":
        d = t.detrend("height")
        print("rms height, gradient, laplacian:", repr((d.rms_height_from_area(), d.rms_gradient(), d.rms_laplacian())))

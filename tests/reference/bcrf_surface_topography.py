"""Reference numbers for the BCRF test of tests/instrument_files.rs.

SurfaceTopography's example `bcrf-1.bcrf` (960 × 600 float32 points, 2.3 MB,
test/file_format_examples/ at the commit named in tests/data/README.md) is
cropped to its first 8 rows: the same 2048-character UTF-16 header with
`ypixels = 8` (padded to the same length) and `ylength` scaled to the 8 rows,
then the first 8 rows of values, written to tests/data/bcrf-1-crop.bcrf.
SurfaceTopography then reads the cropped file and this prints what the Rust
test compares: grid, sizes (nm), some heights (nm, h[ix, iy]) and the rms
height, gradient and Laplacian after the plane.

    /work/venvs/readers/bin/python tests/reference/bcrf_surface_topography.py PATH/TO/bcrf-1.bcrf

SurfaceTopography 1.27.1 and numpy 2 gave the numbers in the test.
"""

import pathlib
import sys

import numpy as np
import SurfaceTopography as st

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
ROWS = 8

src = pathlib.Path(sys.argv[1]).read_bytes()
header = src[:4096].decode("utf-16-le")
ny = 600
ylength = "1110878.0000"
new_ylength = f"{float(ylength) * ROWS / ny:.4f}"
header = header.replace("ypixels = 600", f"ypixels = {ROWS}".ljust(len("ypixels = 600")))
header = header.replace(f"ylength = {ylength}", f"ylength = {new_ylength}".ljust(len(f"ylength = {ylength}")))
assert len(header) == 2048
out = header.encode("utf-16-le") + src[4096 : 4096 + 960 * ROWS * 4]
(DATA / "bcrf-1-crop.bcrf").write_bytes(out)

t = st.open_topography(str(DATA / "bcrf-1-crop.bcrf")).topography()
h = np.ma.getdata(t.heights())
print(st.__version__, t.nb_grid_pts, t.physical_sizes, t.unit)
print(repr([float(h[0, 0]), float(h[1, 0]), float(h[0, 1]), float(h[959, 7]), float(h[17, 5])]))
d = t.detrend("height")
print(repr((d.rms_height_from_area(), d.rms_gradient(), d.rms_laplacian())))

"""Reference numbers for the HDF5 tests of tests/formats/hdf5_datx.rs.

SurfaceTopography's example `multiple_data_sets.h5` (1.75 MB: superblock
version 0, old-style groups; `dataset1` 256 x 256 float64 and `dataset2`
640 x 480 float32, both contiguous) is rewritten smaller with the same
structure (`libver="earliest"`, the same names, types and layout): the first
24 x 16 of `dataset1` and the first 20 x 12 of `dataset2`, into
tests/data/multiple_data_sets-crop.h5. Two more files test the rest of
what h5py writes:

- `h5-chunked-deflate.h5` (`libver="v114"`: superblock 3, v2 object
  headers, compact links, layout message 4 with its chunk indexes): `/group/heights` 12 x 10 float32, chunked 5 x 4
  with shuffle + deflate, an int16 `/counts` 6 x 5, a 1-D `/profile`
  (not a channel) and a string data set (not a channel);
- the same data with `libver="earliest"` and chunks indexed by a v1 B-tree:
  `h5-chunked-deflate-v0.h5`.

SurfaceTopography then reads each file and this prints what the Rust test
compares: channels, grid, some heights h[ix, iy] and the rms height, gradient
and Laplacian after the plane (no physical size in the file: the size is
given as (nx, ny), i.e. a pixel size of 1).

    /work/venvs/readers/bin/python tests/reference/hdf5_surface_topography.py PATH/TO/multiple_data_sets.h5
"""

import pathlib
import sys

import h5py
import numpy as np
import SurfaceTopography as st

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"

with h5py.File(sys.argv[1], "r") as src, h5py.File(
    DATA / "multiple_data_sets-crop.h5", "w", libver="earliest"
) as out:
    out.create_dataset("dataset1", data=src["dataset1"][:24, :16])
    out.create_dataset("dataset2", data=src["dataset2"][:20, :12])

rng = np.random.default_rng(40)
heights = rng.normal(size=(12, 10)).astype(np.float32)
counts = rng.integers(-300, 300, size=(6, 5)).astype(np.int16)
for name, libver in [("h5-chunked-deflate.h5", ("v114", "v114")), ("h5-chunked-deflate-v0.h5", "earliest")]:
    with h5py.File(DATA / name, "w", libver=libver) as f:
        f.create_dataset("profile", data=np.arange(7.0))
        f.create_dataset("label", data=np.array([b"ab", b"cd"]))
        g = f.create_group("group")
        g.create_dataset("heights", data=heights, chunks=(5, 4), shuffle=True, compression="gzip")
        f.create_dataset("counts", data=counts, chunks=(3, 5), compression="gzip")

print(st.__version__)
for name in ["multiple_data_sets-crop.h5", "h5-chunked-deflate.h5", "h5-chunked-deflate-v0.h5"]:
    r = st.open_topography(str(DATA / name))
    print(name, (DATA / name).stat().st_size, "bytes", [(c.name, c.nb_grid_pts) for c in r.channels],
          "default", r._default_channel_index)
    for i, c in enumerate(r.channels):
        t = r.topography(channel_index=i, physical_sizes=c.nb_grid_pts)
        h = np.ma.getdata(t.heights())
        nx, ny = t.nb_grid_pts
        print(" ", c.name, t.nb_grid_pts, t.physical_sizes, t.unit, h.dtype,
              repr([float(h[0, 0]), float(h[1, 0]), float(h[0, 1]), float(h[nx - 1, ny - 1]), float(h[3, 2])]))
        d = t.detrend("height")
        print("   ", repr((d.rms_height_from_area(), d.rms_gradient(), d.rms_laplacian())))

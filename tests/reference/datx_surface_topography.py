"""Reference numbers for the Zygo `.datx` tests of tests/formats/hdf5_datx.rs.

No instrument `.datx` file is public (SurfaceTopography's examples have
none), so this writes small files with h5py in the layout SurfaceTopography's
DATX reader (IO/DATX.py) reads:

- `/MetaData`: a table of (Source, Link, Destination) strings; from `Root`
  the links `Measurement` -> `Surface` -> `Path` give the surface data set;
- the surface: a rank-2 data set, rows along y (shape (ny, nx)), with the
  attributes `Unit` (one string, e.g. `MicroMeters`), `No Data` (one value,
  optional), and `X Converter`, `Y Converter`, `Z Converter`: one compound
  record (Category, BaseUnit, Unit, Parameters); for x and y the category is
  `LateralCat` with base unit `Pixels` and Parameters[1] the pixel size in
  metres; for z the category is `HeightCat` with the base unit equal to `Unit`.

Files:
- `datx-float64.datx`: 9 x 6 float64 in MicroMeters, Δx = 0.5 µm, Δy = 0.7 µm,
  `No Data` = 1.7976931348623157e308 at two points and a NaN at one,
  fixed-length strings, `libver="earliest"`;
- `datx-float32.datx`: 7 x 5 float32 in NanoMeters, Δ = 2e-7 m, no `No Data`,
  variable-length strings in `/MetaData` and the attributes, chunked + deflate,
  `libver="v114"` (superblock 3, v2 object headers).

SurfaceTopography then reads each and this prints what the Rust test
compares: grid, physical sizes, unit, some heights h[ix, iy] (undefined: nan),
the number of undefined points, and the rms height, gradient and Laplacian
after the plane of the file without undefined points.

    /work/venvs/readers/bin/python tests/reference/datx_surface_topography.py
"""

import pathlib

import h5py
import numpy as np
import SurfaceTopography as st

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
NO_DATA = np.finfo(np.float64).max


def write(name, heights, unit, dx, dy, no_data, vlen, libver, chunks=None):
    s = h5py.string_dtype() if vlen else "S40"
    meta = np.array(
        [
            (b"Root", b"Measurement", b"{7f3a}"),
            (b"{7f3a}", b"Surface", b"{91c2}"),
            (b"{7f3a}", b"Attributes", b"{5d10}"),
            (b"{91c2}", b"Path", b"/Measurement/Surface"),
            (b"{5d10}", b"Comment", b"written by h5py"),
        ],
        dtype=[("Source", s), ("Link", s), ("Destination", s)],
    )
    conv = np.dtype([("Category", s), ("BaseUnit", s), ("Unit", s), ("Parameters", "<f8", (4,))])
    with h5py.File(DATA / name, "w", libver=libver) as f:
        f.create_dataset("MetaData", data=meta)
        g = f.create_group("Measurement")
        g.attrs["System Type"] = np.array([b"NewView 9000"])
        kw = dict(chunks=chunks, compression="gzip") if chunks else {}
        d = g.create_dataset("Surface", data=heights, **kw)
        d.attrs["Unit"] = np.array([unit.encode()], dtype=s)
        if no_data is not None:
            d.attrs["No Data"] = np.array([no_data], dtype=heights.dtype)
        d.attrs.create("X Converter", np.array([(b"LateralCat", b"Pixels", b"MicroMeters", [0.0, dx, 0.0, 0.0])], dtype=conv))
        d.attrs.create("Y Converter", np.array([(b"LateralCat", b"Pixels", b"MicroMeters", [0.0, dy, 0.0, 0.0])], dtype=conv))
        d.attrs.create("Z Converter", np.array([(b"HeightCat", unit.encode(), unit.encode(), [632.8e-9, 1.0, 0.5, 1.0])], dtype=conv))


rng = np.random.default_rng(41)
h64 = rng.normal(size=(6, 9))  # (ny, nx)
h64[1, 2] = NO_DATA
h64[4, 8] = NO_DATA
h64[3, 0] = np.nan
write("datx-float64.datx", h64, "MicroMeters", 0.5e-6, 0.7e-6, NO_DATA, False, "earliest")
h32 = (rng.normal(size=(5, 7)) * 30).astype(np.float32)
write("datx-float32.datx", h32, "NanoMeters", 2e-7, 2e-7, None, True, ("v114", "v114"), chunks=(3, 4))

print(st.__version__)
for name in ["datx-float64.datx", "datx-float32.datx"]:
    r = st.open_topography(str(DATA / name))
    print(name, (DATA / name).stat().st_size, "bytes", type(r).__name__, [c.name for c in r.channels])
    t = r.topography()
    h = np.ma.filled(t.heights().astype(float), np.nan)
    nx, ny = t.nb_grid_pts
    print(" ", t.nb_grid_pts, t.physical_sizes, t.unit, "undefined", int(np.isnan(h).sum()),
          repr([float(h[0, 0]), float(h[1, 0]), float(h[0, 1]), float(h[nx - 1, ny - 1]), float(h[2, 1]), float(h[0, 3])]))
    if not t.has_undefined_data:
        d = t.detrend("height")
        print("   ", repr((d.rms_height_from_area(), d.rms_gradient(), d.rms_laplacian())))

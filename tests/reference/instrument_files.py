"""Reference numbers for tests/instrument_files.rs from SurfaceTopography.

Run in a virtual environment outside the repository (SurfaceTopography 1.27.1,
numpy 2 were used for the committed numbers):

    python3 -m venv /work/venvs/readers
    /work/venvs/readers/bin/pip install SurfaceTopography numpy
    /work/venvs/readers/bin/python tests/reference/instrument_files.py
    cargo fmt --all

It reads the instrument example files of tests/data/ (origins in
tests/data/README.md) with SurfaceTopography's own readers and writes
tests/reference/instrument_files.rs: for each file the grid and sizes as read,
and what SurfaceTopography computes after removing the least-squares plane
(maps) or line (line scans), the default conditioning of `persson`:

- maps: rms height, rms gradient (forward differences), rms Laplacian
  (5-point) and `rms_curvature_from_area` (the mean curvature, half the rms
  Laplacian), and the radially averaged spectrum with a radial Hann window
  (C_ST = (2π)² C_Persson) on its default log grid (10 points per decade);
- line scans: Rq, Rdq (forward differences), Rddq (3-point second
  derivative) and the 1D spectrum with a Hann window (C1D_ST = 2π C1D_Persson).

Undefined points (validity masks, NaN) are filled with SurfaceTopography's
harmonic interpolation first.

It also writes two x3p files with SurfaceTopography's writer (`to_x3p`), from
the instrument map matrix-4.txt with 378 points made undefined (a 12 × 12
block and every 97th point): st-int16-mask.x3p (DataType I) and
st-int32-mask.x3p (DataType L). The writer uses the whole signed range (raw
values from −32768), stores undefined points as the minimum raw value and
marks them in bindata/valid.bin: read as unsigned, or without the mask, they
are cliffs.

Where SurfaceTopography reads a file differently from persson the script
builds SurfaceTopography's object from the numbers persson reads, and says so
in a comment of the generated file:
- dektak-1.csv: x written to 0.1 µm; SurfaceTopography tests equal spacing to
  1e-6 (absolute, in the file's unit) and reads a nonuniform line scan;
  persson reads the uniform scan the instrument took (Δ = 0.156 µm/sample,
  "Resolution" in the file's header), |x_i − x_0 − iΔ| ≤ 0.01Δ + 0.1 µm. The
  reference is SurfaceTopography's UniformLineScan of the same heights and
  length n·Δ, Δ = (x_last − x_0)/(n − 1), in m.
- nonuniform.asc: truly nonuniform; both interpolate linearly onto n equally
  spaced points (SurfaceTopography's `to_uniform(nb_points=n)`).
- Units: SurfaceTopography keeps a file's unit (µm for Dektak); the numbers
  here are converted to metres, as persson reads them. Files without a unit
  are taken in m by both.
"""
import os

import numpy as np
import SurfaceTopography
from SurfaceTopography import Topography, UniformLineScan, read_topography

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data")
UNITS = {"m": 1.0, "mm": 1e-3, "µm": 1e-6, "um": 1e-6, "nm": 1e-9, None: 1.0}
# plu-1.plu is the first 1 769 988 bytes of SurfaceTopography's plu-1.plu
# (the header and the height layer; the images after it left out):
# SurfaceTopography reads both to the same numbers (tests/data/README.md).


def arr(values):
    return "&[" + ", ".join(repr(float(v)) for v in values) + "]"


def spectrum(q, c):
    keep = ~np.ma.getmaskarray(c)
    return np.ma.getdata(q)[keep], np.ma.getdata(c)[keep]


def map_entry(name, t, note=""):
    t = t.interpolate_undefined_data() if t.has_undefined_data else t
    d = t.detrend("height")
    nx, ny = t.nb_grid_pts
    lx, ly = t.physical_sizes
    q, c = spectrum(*d.power_spectrum_from_area(window="hann"))
    return f"""    // {name}: SurfaceTopography {type(t).__name__}, nb_grid_pts ({nx}, {ny}) = (nx, ny){note}
    Map {{
        file: "{name}",
        nx: {nx},
        ny: {ny},
        lx: {float(lx)!r},
        ly: {float(ly)!r},
        rms_height: {float(d.rms_height_from_area())!r},
        rms_gradient: {float(d.rms_gradient())!r},
        rms_laplacian: {float(d.rms_laplacian())!r},
        rms_mean_curvature: {float(d.rms_curvature_from_area())!r},
        q: {arr(q)},
        c_st: {arr(c)},
    }},
"""


def profile_entry(name, t, note=""):
    t = t.interpolate_undefined_data() if t.has_undefined_data else t
    d = t.detrend("height")
    (n,) = t.nb_grid_pts
    (length,) = t.physical_sizes
    q, c = spectrum(*d.power_spectrum_from_profile(window="hann"))
    return f"""    // {name}: SurfaceTopography {type(t).__name__}, {n} points{note}
    Profile {{
        file: "{name}",
        n: {n},
        length: {float(length)!r},
        rms_height: {float(d.Rq())!r},
        rms_slope: {float(d.Rdq())!r},
        rms_curvature: {float(d.Rddq())!r},
        q: {arr(q)},
        c1d_st: {arr(c)},
    }},
"""


def metres(t):
    """A map read by SurfaceTopography, in m (heights and sizes)."""
    f = UNITS[t.unit]
    h = t.heights()
    return Topography(h * f, tuple(float(x) * f for x in t.physical_sizes), unit="m",
                      periodic=False)


def samples(nx, ny, h):
    """Heights at a few defined points (ix, iy) of h[ix, iy] (NaN undefined)."""
    out = []
    for ix, iy in [(0, 0), (nx - 1, 0), (0, ny - 1), (nx - 1, ny - 1), (nx // 3, ny // 2),
                   (nx // 2, ny // 3), (1, 2), (nx - 2, ny // 5)]:
        if np.isfinite(h[ix, iy]) and (ix, iy) not in [(a, b) for a, b, _ in out]:
            out.append((ix, iy, float(h[ix, iy])))
    return out


def points_entry(name, nx, ny, lx, ly, h, note):
    """Grid, sizes, undefined points and heights as read, h[ix, iy] in m."""
    h = np.asarray(h, dtype=float)
    ok = np.isfinite(h)
    a = np.where(ok, np.abs(h), 0.0)
    ix, iy = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    pts = ", ".join(f"({i}, {j}, {v!r})" for i, j, v in samples(nx, ny, h))
    return f"""    // {name}: {note}
    Points {{
        file: "{name}",
        nx: {nx},
        ny: {ny},
        lx: {float(lx)!r},
        ly: {float(ly)!r},
        undefined: {int((~ok).sum())},
        sum_abs: {float(a.sum())!r},
        sum_ix_abs: {float((ix * a).sum())!r},
        sum_iy_abs: {float((iy * a).sum())!r},
        at: &[{pts}],
    }},
"""


def st_points(path, name):
    """Points of a file as SurfaceTopography reads it, in m."""
    t = read_topography(path(name))
    f = UNITS[t.unit]
    h = np.ma.filled(np.ma.masked_array(t.heights(), dtype=float), np.nan) * f
    nx, ny = t.nb_grid_pts
    lx, ly = (float(x) * f for x in t.physical_sizes)
    return t, points_entry(name, nx, ny, lx, ly, h,
                           f"SurfaceTopography {type(t).__name__}, unit {t.unit} → m")


def gwyfile_points(path, name, z, xy):
    """Points of a .gwy without units read by gwyfile, in the units given."""
    import gwyfile

    d = gwyfile.load(path(name))["/0/data"]
    nx, ny = d["xres"], d["yres"]
    h = np.asarray(d.data, dtype=float).reshape(ny, nx).T * z
    return points_entry(name, nx, ny, d["xreal"] * xy, d["yreal"] * xy, h,
                        f"gwyfile {gwyfile.__version__} (SurfaceTopography reads no channel "
                        f"without a unit), heights × {z!r}, sizes × {xy!r}")


def write_gwyfile_mask(path):
    """gwyfile-mask.gwy from matrix-4.txt with gwyfile's writer (module docs)."""
    from gwyfile.objects import GwyContainer, GwyDataField, GwySIUnit

    if os.path.exists(path("gwyfile-mask.gwy")):
        return
    t = read_topography(path("matrix-4.txt"))
    rows = np.array(t.heights(), dtype=float).T.copy()  # [iy, ix]: x fastest
    mask = np.zeros_like(rows)
    mask[100:110, 20:35] = 1.0
    mask.flat[::101] = 1.0
    lx, ly = t.physical_sizes
    unit = lambda u: GwySIUnit(unitstr=u)  # noqa: E731
    c = GwyContainer()
    c["/0/data/title"] = "Phase"
    c["/0/data"] = GwyDataField(np.sin(rows * 1e7), xreal=lx, yreal=ly,
                                si_unit_xy=unit("m"), si_unit_z=unit("deg"))
    c["/1/data/title"] = "Height"
    c["/1/data"] = GwyDataField(rows * 1e6, xreal=lx, yreal=ly,
                                si_unit_xy=unit("m"), si_unit_z=unit("µm"))
    c["/1/mask"] = GwyDataField(mask, xreal=lx, yreal=ly)
    c.tofile(path("gwyfile-mask.gwy"))


def write_st_mask_nc(path):
    """st-mask.nc: matrix-4.txt with 378 undefined points, SurfaceTopography's to_netcdf."""
    if os.path.exists(path("st-mask.nc")):
        return
    t = read_topography(path("matrix-4.txt"))
    h = np.array(t.heights(), dtype=float)  # [ix, iy]
    undefined = np.zeros(h.shape, dtype=bool)
    undefined[20:32, 100:112] = True
    undefined.flat[::97] = True
    u = Topography(np.ma.masked_array(h * 1e6, mask=undefined),
                   tuple(x * 1e6 for x in t.physical_sizes), unit="µm")
    u.to_netcdf(path("st-mask.nc"))


def uniform_metres(t):
    """A uniform line scan in metres from what SurfaceTopography read."""
    f = UNITS[t.unit]
    x, h = t.positions_and_heights()
    n = len(h)
    dx = (x[-1] - x[0]) / (n - 1)
    return UniformLineScan(np.asarray(h) * f, n * dx * f, periodic=False, unit="m")


def write_masked_x3p(path):
    """st-int16-mask.x3p and st-int32-mask.x3p from matrix-4.txt."""
    t = read_topography(path("matrix-4.txt"))
    h = np.array(t.heights(), dtype=float)  # [ix, iy]
    nx, ny = h.shape
    undefined = np.zeros(h.shape, dtype=bool)
    undefined[20:32, 100:112] = True
    undefined.flat[::97] = True
    h = np.ma.masked_array(h, mask=undefined)
    u = Topography(h, t.physical_sizes, unit="m")
    for dtype, name in [("I", "st-int16-mask.x3p"), ("L", "st-int32-mask.x3p")]:
        # Written once: the committed files are the ones the numbers are of
        # (a new write differs in the zip's time stamps only).
        if not os.path.exists(path(name)):
            u.to_x3p(path(name), dtype=dtype)
    return int(undefined.sum())


def main():
    path = lambda name: os.path.join(DATA, name)  # noqa: E731
    undefined = write_masked_x3p(path)
    assert undefined == 378, undefined
    write_gwyfile_mask(path)
    maps = []
    binary_maps = []
    points = []
    write_st_mask_nc(path)
    for name in ["gwyfile-mask.gwy", "sur-2.sur", "sur-3.sur", "metropro-1.dat", "nc-1.nc",
                 "st-mask.nc", "al3d-1.al3d", "plu-1.plu", "spot_1-1000nm.ibw",
                 "10x10-one_channel_without_name.ibw", "di-3.di"]:
        t, entry = st_points(path, name)
        points.append(entry)
        # sur-3: 89 % undefined; nc-1: a plane (its detrended rms is rounding
        # noise, 2e-24 m): grid, sizes and heights only
        # 10x10-…ibw: no units (persson needs them given), a smooth test wave
        if name not in ("sur-3.sur", "nc-1.nc", "10x10-one_channel_without_name.ibw"):
            binary_maps.append(map_entry(name, metres(t)))
    points.append(gwyfile_points(path, "gwyfile-test.gwy", 1e-9, 1e-6))
    for name in ["gwyddion-export-english.txt", "gwyddion-export-german.txt",
                 "txt_example.txt", "matrix-4.txt", "xyz-1.txt", "xyz-2.txt",
                 "ISO5436-sample1_bin.x3p", "ISO5436-sample4_bin.x3p",
                 "st-int16-mask.x3p", "st-int32-mask.x3p"]:
        t = read_topography(path(name))
        assert UNITS[t.unit] == 1.0, (name, t.unit)
        maps.append(map_entry(name, t))
    maps += binary_maps  # after the text and x3p files (MAPS[0] is used alone)

    profiles = []
    for name in ["opdx-3.txt", "xy-4.txt"]:
        t = read_topography(path(name))
        assert t.is_uniform and UNITS[t.unit] == 1.0, name
        profiles.append(profile_entry(name, t))
    t = read_topography(path("dektak-1.csv"))
    assert not t.is_uniform and t.unit == "µm"
    profiles.append(profile_entry(
        "dektak-1.csv", uniform_metres(t),
        "\n    // (SurfaceTopography reads a NonuniformLineScan in µm: x is written to 0.1 µm;"
        "\n    // this is its UniformLineScan of the same heights, length n·Δ, in m)"))
    t = read_topography(path("nonuniform.asc"))
    assert not t.is_uniform
    u = t.to_uniform(nb_points=len(t.positions()))
    profiles.append(profile_entry(
        "nonuniform.asc", UniformLineScan(u.heights(), u.physical_sizes, periodic=False),
        "\n    // (nonuniform: SurfaceTopography's to_uniform(nb_points=n))"))

    out = os.path.join(HERE, "instrument_files.rs")
    with open(out, "w") as f:
        f.write(f"""// Generated by tests/reference/instrument_files.py with SurfaceTopography
// {SurfaceTopography.__version__}, numpy {np.__version__}: do not edit by hand.
// Maps after detrend("height") (plane), line scans after detrend("height")
// (line); spectra with a Hann window, C_ST = (2π)² C, C1D_ST = 2π C1D.
// (Bins of the 4 × 4 maps of side 4 m fall on q = π/2, π: not constants.)
#![allow(clippy::approx_constant)]

/// SurfaceTopography's numbers for a map.
pub struct Map {{
    pub file: &'static str,
    pub nx: usize,
    pub ny: usize,
    pub lx: f64,
    pub ly: f64,
    pub rms_height: f64,
    pub rms_gradient: f64,
    pub rms_laplacian: f64,
    pub rms_mean_curvature: f64,
    pub q: &'static [f64],
    pub c_st: &'static [f64],
}}

/// SurfaceTopography's numbers for a line scan.
pub struct Profile {{
    pub file: &'static str,
    pub n: usize,
    pub length: f64,
    pub rms_height: f64,
    pub rms_slope: f64,
    pub rms_curvature: f64,
    pub q: &'static [f64],
    pub c1d_st: &'static [f64],
}}

/// A file's grid, sizes and heights as read (m), before any conditioning.
pub struct Points {{
    pub file: &'static str,
    pub nx: usize,
    pub ny: usize,
    pub lx: f64,
    pub ly: f64,
    /// Undefined points (mask, missing-data marker).
    pub undefined: usize,
    /// Σ|h|, Σ ix·|h|, Σ iy·|h| over the defined points (orientation).
    pub sum_abs: f64,
    pub sum_ix_abs: f64,
    pub sum_iy_abs: f64,
    /// Heights h[ix, iy] at a few defined points.
    pub at: &'static [(usize, usize, f64)],
}}

pub const MAPS: &[Map] = &[
{"".join(maps)}];

pub const POINTS: &[Points] = &[
{"".join(points)}];

pub const PROFILES: &[Profile] = &[
{"".join(profiles)}];
""")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

"""Reference numbers for tests/formats/mi_wsxm_nid_nms.rs.

SurfaceTopography's examples (test/file_format_examples/ at the commit named
in tests/data/README.md) of Molecular Imaging `.mi`, WSxM `.stp`/`.top`,
Nanosurf `.nid` and NanoFocus `.nms` files. `top-1.top` (133 kB) is copied
whole; the larger ones are cropped to their first rows, each cut staying a
valid file of its format (the header's row count and y size adjusted), and
written to tests/data/:

- mi-1-crop.mi: the first 32 rows of each of the 4 buffers; `yPixels 32`,
  `yLength` scaled by 32/256;
- stp-1-crop.stp: the first 64 rows; `Number of rows: 64`,
  `Y Amplitude: 150 nm`, `Image header size` recomputed;
- nid-1-crop.nid: the first 16 lines of each of the 8 data sets;
  `Lines=16`, `Dim1Range` scaled by 16/256 in each data set's section;
- nms-1-crop.nms, nms-2-crop.nms: the first 64 rows of the heights and of
  the intensity image after them; ny = 64 (u32 at byte 1372).

SurfaceTopography then reads each file and this prints what the Rust test
compares: grid, sizes and unit, some heights h[ix, iy] and the rms height,
gradient and Laplacian after the plane (SurfaceTopography's units).

    /work/venvs/readers/bin/python tests/reference/mi_wsxm_nid_nms_surface_topography.py PATH/TO/file_format_examples

SurfaceTopography 1.27.1 and numpy 2 gave the numbers in the test.
"""

import pathlib
import re
import struct
import sys

import numpy as np
import SurfaceTopography as st

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
SRC = pathlib.Path(sys.argv[1])


def crop_mi(rows):
    src = (SRC / "mi-1.mi").read_bytes()
    stop = src.index(b"\ndata ")
    end = src.index(b"\n", stop + 1) + 1
    header = src[:end].decode("latin-1")
    nx = int(re.search(r"^xPixels +(\d+)", header, re.M).group(1))
    ny = int(re.search(r"^yPixels +(\d+)", header, re.M).group(1))
    nbuf = header.count("\nbufferLabel")
    ylength = float(re.search(r"^yLength +(\S+)", header, re.M).group(1))
    header = re.sub(r"^yPixels +\d+", f"{'yPixels':<14}{rows}", header, flags=re.M)
    new_y = f"{ylength * rows / ny:.16e}".replace("e-0", "e-00")
    header = re.sub(r"^yLength +\S+", f"{'yLength':<14}{new_y}", header, flags=re.M)
    body = src[end:]
    assert len(body) == nbuf * nx * ny * 4
    out = header.encode("latin-1")
    for k in range(nbuf):
        out += body[k * nx * ny * 4 : (k * nx * ny + nx * rows) * 4]
    (DATA / "mi-1-crop.mi").write_bytes(out)


def crop_stp(rows):
    src = (SRC / "stp-1.stp").read_bytes()
    size = int(re.search(rb"Image header size: (\d+)", src).group(1))
    header = src[:size].decode("latin-1")
    header = header.replace("Number of rows: 256", f"Number of rows: {rows}")
    header = header.replace("Y Amplitude: 600 nm", f"Y Amplitude: {600 * rows // 256} nm")
    new = len(header.encode("latin-1"))
    header = header.replace(f"Image header size: {size}", f"Image header size: {new}")
    assert len(header.encode("latin-1")) == new
    out = header.encode("latin-1") + src[size : size + 256 * rows * 8]
    (DATA / "stp-1-crop.stp").write_bytes(out)


def crop_nid(rows):
    src = (SRC / "nid-1.nid").read_bytes()
    start = src.index(b"\r\n#!") + 4
    header = src[:start].decode("latin-1")
    sections = re.findall(r"\[(DataSet-\d+:\d+)\]", header)
    body = src[start:]
    out_body = b""
    for i, name in enumerate(sections):
        k = header.index(f"[{name}]")
        sec_end = header.find("\r\n\r\n", k)
        sec = header[k:sec_end]
        lines = int(re.search(r"Lines=(\d+)", sec).group(1))
        points = int(re.search(r"Points=(\d+)", sec).group(1))
        bits = int(re.search(r"SaveBits=(\d+)", sec).group(1))
        rng = float(re.search(r"Dim1Range=(\S+)", sec).group(1))
        new = sec.replace(f"Lines={lines}", f"Lines={rows}")
        new = re.sub(r"Dim1Range=\S+", f"Dim1Range={rng * rows / lines:g}", new)
        header = header[:k] + new + header[sec_end:]
        block = points * lines * bits // 8
        out_body += body[i * block : i * block + points * rows * bits // 8]
    (DATA / "nid-1-crop.nid").write_bytes(header.encode("latin-1") + out_body)


def crop_nms(name, rows):
    src = (SRC / f"{name}.nms").read_bytes()
    nx, ny = struct.unpack("<2I", src[1368:1376])
    heights = src[3468 : 3468 + 2 * nx * ny]
    intensity = src[3468 + 2 * nx * ny :]
    assert len(intensity) == nx * ny
    out = bytearray(src[:3468])
    out[1372:1376] = struct.pack("<I", rows)
    out += heights[: 2 * nx * rows] + intensity[: nx * rows]
    (DATA / f"{name}-crop.nms").write_bytes(bytes(out))


def show(name, points, channel=None, format=None):
    # .nms has no magic: SurfaceTopography may take it for another format
    r = st.open_topography(str(DATA / name), format=format)
    names = [c.name for c in r.channels]
    t = r.topography(channel_index=channel)
    h = np.ma.getdata(t.heights())
    print(name, names, channel, t.nb_grid_pts, t.physical_sizes, t.unit, t.has_undefined_data)
    print(repr([float(h[ix, iy]) for ix, iy in points]))
    d = t.detrend("height")
    print(repr((d.rms_height_from_area(), d.rms_gradient(), d.rms_laplacian())))


crop_mi(32)
crop_stp(64)
crop_nid(16)
crop_nms("nms-1", 64)
crop_nms("nms-2", 64)
(DATA / "top-1.top").write_bytes((SRC / "top-1.top").read_bytes())

print(st.__version__)
show("mi-1-crop.mi", [(0, 0), (1, 0), (0, 1), (255, 31), (17, 5)])
show("stp-1-crop.stp", [(0, 0), (1, 0), (0, 1), (255, 63), (17, 5)])
show("top-1.top", [(0, 0), (1, 0), (0, 1), (255, 255), (17, 123)])
show("nid-1-crop.nid", [(0, 0), (1, 0), (0, 1), (255, 15), (17, 5)])
show("nid-1-crop.nid", [(0, 0), (1, 0), (0, 1), (255, 15), (17, 5)], channel=2)
show("nms-1-crop.nms", [(0, 0), (1, 0), (0, 1), (511, 63), (17, 5)], format="nms")
show("nms-2-crop.nms", [(0, 0), (1, 0), (0, 1), (511, 63), (17, 5)], format="nms")

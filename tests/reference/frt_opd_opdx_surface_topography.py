"""Reference numbers for the FRT, OPD and OPDx tests of tests/formats/frt_opd_opdx.rs.

SurfaceTopography's examples (test/file_format_examples/ at the commit named
in tests/data/README.md) `frt-1.frt` (1.5 MB) and `opd-1.opd` (4 MB) are
cropped to small valid files of their formats, written to tests/data/:

- `frt-1-crop.frt`: stored rows 200..240 and columns 100..400 of both the
  topography block 0x000b and the two images (topography, intensity) of the
  multi-image block 0x007d, with the grid (0x0066), the scan size (0x0067:
  Lx, Ly scaled to the points kept) and the block sizes adjusted; all other
  blocks as they are. The window holds no undefined point.
- `opd-1-crop.opd`: the arrays `Raw` and `Image` cut to y = 100..132 (all
  640 x, the header's ny adjusted); the directory entries of `SecArr_0`
  and of the 1.2 MB `Modulation` block get length 0 (no payload), all other
  blocks as they are. No undefined point.

`frt-2.frt` and `opdx-3.opdx` are copied whole. There is no example of an
OPDx height map: `opdx-map-synthetic.opdx` is written here, a map of 5 × 4
float32 values in the item tree SurfaceTopography's reader parses (2D_Data/
Height with Dimension1/2 Points and Extent, DataScale in nm, a Matrix;
MetaData with DataKind `Surface Height`, 2D_Channels and PrimaryData2D), x
extent in µm and y extent in mm. SurfaceTopography then reads
the files in tests/data/ and this prints what the Rust test compares: grid,
sizes, heights h[ix, iy], undefined points, and the rms height, gradient and
Laplacian after the plane (profile: Rq, Rdq, Rddq after the line).
It also writes a version-1.01 copy of the FRT crop (64-bit block sizes) to a
temporary file and checks that SurfaceTopography reads the same heights.

    /work/venvs/readers/bin/python tests/reference/frt_opd_opdx_surface_topography.py PATH/TO/file_format_examples

SurfaceTopography 1.27.1 and numpy 2 gave the numbers in the test.
"""

import pathlib
import shutil
import struct
import sys
import tempfile

import numpy as np
import SurfaceTopography as st

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
SRC = pathlib.Path(sys.argv[1])


def frt_blocks(b):
    """(tag, payload) of an FRT file of version 1.00."""
    assert b[12:16] == b"1.00"
    (n,) = struct.unpack_from("<H", b, 16)
    p, out = 18, []
    for _ in range(n):
        tag, size = struct.unpack_from("<HI", b, p)
        out.append((tag, b[p + 6 : p + 6 + size]))
        p += 6 + size
    assert p == len(b)
    return out


def frt_write(blocks, version=b"1.00"):
    size = "<HI" if version == b"1.00" else "<HQ"
    out = b"FRTM_GLIDERV" + version + struct.pack("<H", len(blocks))
    for tag, payload in blocks:
        out += struct.pack(size, tag, len(payload)) + payload
    return out


def frt_crop(src, rows, cols):
    r0, r1 = rows
    c0, c1 = cols
    out = []
    nx = ny = None
    for tag, p in frt_blocks(src):
        if tag == 0x66:
            nx, ny, bits = struct.unpack_from("<3I", p)
            assert bits == 16
            p = struct.pack("<3I", c1 - c0, r1 - r0, bits)
        elif tag == 0x67:
            lx, ly = struct.unpack_from("<2d", p)
            p = struct.pack("<2d", lx * (c1 - c0) / nx, ly * (r1 - r0) / ny) + p[16:]
        elif tag == 0x0B:
            a = np.frombuffer(p, "<u2").reshape(ny, nx)
            p = a[r0:r1, c0:c1].tobytes()
        elif tag == 0x7D:
            q, new = 8, p[:8]
            while q < len(p):
                kind, inx, iny, bits = struct.unpack_from("<4I", p, q)
                a = np.frombuffer(p[q + 16 : q + 16 + inx * iny * 2], "<u2").reshape(iny, inx)
                new += struct.pack("<4I", kind, c1 - c0, r1 - r0, bits) + a[r0:r1, c0:c1].tobytes()
                q += 16 + inx * iny * 2
            p = new
        out.append((tag, p))
    return out


def opd_crop(src, y0, y1):
    (length,) = struct.unpack_from("<l", src, 2 + 18)
    entries, blocks, p = [], [], 2 + length
    for i in range(1, length // 24):
        e = bytearray(src[2 + 24 * i : 2 + 24 * (i + 1)])
        name = e[:16].split(b"\0")[0]
        typ, ln = struct.unpack_from("<hl", e, 16)
        payload = src[p : p + ln] if ln > 0 else b""
        p += max(ln, 0)
        if name in (b"SecArr_0", b"Modulation"):
            payload = b""
        elif typ == 3:
            nx, ny, item = struct.unpack_from("<3H", payload)
            dt = {1: "u1", 4: "<f4"}[item]
            a = np.frombuffer(payload[6:], dt).reshape(nx, ny)
            payload = struct.pack("<3H", nx, y1 - y0, item) + a[:, y0:y1].tobytes()
        struct.pack_into("<l", e, 18, len(payload))
        entries.append(bytes(e))
        blocks.append(payload)
    return src[: 2 + 24] + b"".join(entries) + b"".join(blocks)


def opdx_name(s):
    b = s.encode("utf-8")
    return struct.pack("<I", len(b)) + b


def opdx_item(name, kind, payload):
    return opdx_name(name) + bytes([kind]) + payload


def opdx_varlen(b):
    return b"\x04" + struct.pack("<I", len(b)) + b


def opdx_container(name, items):
    return opdx_item(name, 0x7D, opdx_varlen(b"".join(items) + opdx_name("") + b"\x7f\xff\xff"))


def opdx_quantity(name, value, unit, symbol):
    return opdx_item(name, 0x13, opdx_varlen(struct.pack("<d", value) + opdx_name(unit) + opdx_name(symbol)))


def opdx_map():
    nx, ny = 5, 4
    values = np.array([[((3 * ix + 7 * iy) % 11) * 0.25 + 0.1 * ix * iy for ix in range(nx)] for iy in range(ny)], "<f4")
    matrix = struct.pack("<II", ny, nx) + values.tobytes()
    height = opdx_container("Height", [
        opdx_item("Dimension1Points", 0x07, struct.pack("<I", ny)),
        opdx_item("Dimension2Points", 0x07, struct.pack("<I", nx)),
        opdx_quantity("Dimension1Extent", 0.003, "Millimeter", "mm"),
        opdx_quantity("Dimension2Extent", 8.0, "Micrometer", "\u00b5m"),
        opdx_quantity("DataScale", 1.5, "Nanometer", "nm"),
        opdx_item("DataKind", 0x12, opdx_varlen(b"Height")),
        opdx_item("Matrix", 0x00, opdx_name("Matrix<float>") + struct.pack("<I", 1) + opdx_name("float") + opdx_varlen(matrix)),
    ])
    meta = opdx_container("MetaData", [
        opdx_item("DataKind", 0x12, opdx_varlen(b"Surface Height")),
        opdx_container("2D_Channels", [
            opdx_item("Height", 0x42, opdx_name("StringList") + opdx_varlen(opdx_name("Height"))),
        ]),
        opdx_item("PrimaryData2D", 0x12, opdx_varlen(b"Height")),
    ])
    return b"VCA DATA\x01\x00\x00\x55" + opdx_container("2D_Data", [height]) + meta + opdx_name("") + b"\x7f\xff\xff"


def stats(t):
    d = t.detrend("height")
    if t.dim == 1:
        return (d.Rq(), d.Rdq(), d.Rddq())
    return (d.rms_height_from_area(), d.rms_gradient(), d.rms_laplacian())


def report(name, t, points):
    h = np.ma.getdata(t.heights())
    m = np.ma.getmaskarray(t.heights())
    print(name, t.nb_grid_pts, repr(tuple(float(s) for s in t.physical_sizes)), t.unit)
    print("  h:", repr([(p, None if m[p] else float(h[p])) for p in points]))
    if t.has_undefined_data:
        m = np.ma.getmaskarray(t.heights())
        print("  undefined:", int(m.sum()), "first (ix, iy):", [tuple(map(int, p)) for p in np.argwhere(m)[:3]])
        print("  mean of the defined heights:", repr(float(np.ma.mean(t.heights()))))
    else:
        print("  rms:", repr(tuple(float(v) for v in stats(t))))


frt1 = SRC / "frt-1.frt"
crop = frt_crop(frt1.read_bytes(), (200, 240), (100, 400))
(DATA / "frt-1-crop.frt").write_bytes(frt_write(crop))
shutil.copyfile(SRC / "frt-2.frt", DATA / "frt-2.frt")
opd = opd_crop((SRC / "opd-1.opd").read_bytes(), 100, 132)
(DATA / "opd-1-crop.opd").write_bytes(opd)
shutil.copyfile(SRC / "opdx-3.opdx", DATA / "opdx-3.opdx")
(DATA / "opdx-map-synthetic.opdx").write_bytes(opdx_map())

print(st.__version__)
r = st.open_topography(str(DATA / "frt-1-crop.frt"))
print([c.name for c in r.channels])
t = r.topography()
report("frt-1-crop.frt", t, [(0, 0), (1, 0), (0, 1), (299, 39), (17, 23)])
with tempfile.TemporaryDirectory() as tmp:
    wide = pathlib.Path(tmp) / "wide.frt"
    wide.write_bytes(frt_write(crop, b"1.01"))
    same = np.array_equal(st.open_topography(str(wide)).topography().heights(), t.heights())
    print("  version 1.01 copy reads the same heights:", same)

t = st.open_topography(str(DATA / "frt-2.frt")).topography()
report("frt-2.frt", t, [(100, 0), (149, 299), (0, 299), (75, 150), (3, 280), (60, 200)])

r = st.open_topography(str(DATA / "opd-1-crop.opd"))
print([c.name for c in r.channels])
t = r.topography()
report("opd-1-crop.opd", t, [(0, 0), (1, 0), (0, 1), (639, 31), (17, 23)])

r = st.open_topography(str(DATA / "opdx-3.opdx"))
print([c.name for c in r.channels])
t = r.topography()
report("opdx-3.opdx", t, [(0,), (1,), (3000,), (1234,)])

r = st.open_topography(str(DATA / "opdx-map-synthetic.opdx"))
print([c.name for c in r.channels])
t = r.topography()
report("opdx-map-synthetic.opdx", t, [(0, 0), (1, 0), (0, 1), (4, 3), (2, 1)])

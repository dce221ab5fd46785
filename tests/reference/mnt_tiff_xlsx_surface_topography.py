"""Reference numbers for tests/formats/mnt_tiff_xlsx.rs.

Crops SurfaceTopography's example files (test/file_format_examples/ at the
commit named in tests/data/README.md) into tests/data/, then has
SurfaceTopography read the crops and the Mitutoyo mocks (copied whole) and
prints what the Rust tests compare: grid, sizes, some heights h[ix, iy]
(SurfaceTopography's unit), undefined points, the channel name and the
rms height, gradient and Laplacian after the plane.

    /work/venvs/readers/bin/python tests/reference/mnt_tiff_xlsx_surface_topography.py \
        PATH/TO/file_format_examples

- mnt-1.mnt (960 x 600, 2.0 MB) and mnt-2.mnt (1280 x 960 with a mask,
  2.8 MB): the measured surface of the ScopedContents stream is cut to its
  first NX x NY points (counts and mask re-compressed in two zlib blocks,
  written second block first; the axes' point counts, the array counts
  and the mask size adjusted, and the sizes of every enclosing entry),
  and written as the only stream of a new compound file (version 3,
  512-byte sectors) to tests/data/mnt-1-crop.mnt, mnt-2-crop.mnt.
- example_ps.tiff (512 x 512 float32, 1.1 MB): the first 64 rows of the
  data (tag 50434), ny and Ly in the header (tag 50435) scaled to them,
  written with tifffile as a TIFF with a 4 x 4 preview and the same
  private tags to tests/data/example_ps-crop.tiff.

SurfaceTopography 1.27.1, numpy 2 and tifffile gave the numbers in the
Rust test (its comments repeat this script's output).
"""

import pathlib
import struct
import sys
import zlib

import numpy as np
import olefile
import tifffile

import SurfaceTopography as st

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
SRC = pathlib.Path(sys.argv[1])

# ---------------------------------------------------------------- .mnt


def tlv(b, prefixed=False):
    """Entries [tag, value] of a container."""
    out, pos = [], 0
    while pos < len(b):
        if prefixed:
            pos += 8
        tag, size = struct.unpack_from("<HQ", b, pos)
        out.append([tag, b[pos + 10:pos + 10 + size]])
        pos += 10 + size
    assert pos == len(b)
    return out


def untlv(entries, prefixed=False):
    out = b""
    for tag, v in entries:
        if prefixed:
            out += struct.pack("<Q", len(v) + 10)
        out += struct.pack("<HQ", tag, len(v)) + v
    return out


def edit(b, path, fun, prefixed_levels=()):
    """`b` with the first entry at `path` replaced by fun(value)."""
    prefixed = 0 in prefixed_levels
    entries = tlv(b, prefixed)
    for e in entries:
        if e[0] == path[0]:
            if len(path) == 1:
                e[1] = fun(e[1])
            else:
                e[1] = edit(e[1], path[1:], fun, tuple(k - 1 for k in prefixed_levels))
            return untlv(entries, prefixed)
    raise KeyError(path)


def get(b, path):
    for t in path:
        b = next(v for tag, v in tlv(b) if tag == t)
    return b


def unpack_array(data):
    (nb,) = struct.unpack_from("<Q", data, 0)
    buf = bytearray(nb)
    pos = 8
    while pos < len(data):
        off, n, cs = struct.unpack_from("<QII", data, pos)
        block = zlib.decompress(data[pos + 16:pos + 16 + cs])
        size = len(block) // n if n else 1
        buf[off * size:off * size + len(block)] = block
        pos += 16 + cs
    return bytes(buf)


def pack_array(raw, item):
    """Two zlib blocks, the second written first."""
    n = len(raw) // item
    half = n // 2
    blocks = [(half, raw[half * item:]), (0, raw[:half * item])]
    out = struct.pack("<Q", len(raw))
    for off, chunk in blocks:
        z = zlib.compress(chunk)
        out += struct.pack("<QII", off, len(chunk) // item, len(z)) + z
    return out


def u32(v):
    return struct.pack("<I", v)


def crop_surface(data, nx, ny, new_nx, new_ny):
    """The body of the class-9062 object, cut to new_nx x new_ny."""
    m = [0xFFFF]
    counts = get(data, m + [1, 2, 2])
    raw = unpack_array(counts)
    item = len(raw) // (nx * ny)
    a = np.frombuffer(raw, dtype=f"<i{item}").reshape(ny, nx)[:new_ny, :new_nx]
    data = edit(data, m + [1, 2, 2], lambda _: pack_array(a.tobytes(), item))
    data = edit(data, m + [1, 2, 1], lambda _: u32(new_nx * new_ny))
    for axis, n in ((1, new_nx), (2, new_ny)):
        data = edit(data, m + [0xFFFF, axis, 0xFFFF, 1], lambda _, n=n: u32(n))
        data = edit(data, m + [0xFFFF, axis, 0xFFFF, 3], lambda _, n=n: u32(n - 1))
    mask = get(data, m + [0xFFFF, 3])
    if struct.unpack("<I", get(mask, [1, 1]))[0] == 9056:
        mraw = unpack_array(get(mask, [2, 5, 2, 2]))
        mm = np.frombuffer(mraw, dtype=np.uint8).reshape(ny + 2, nx + 2)
        mm = mm[:new_ny + 2, :new_nx + 2]
        count = (new_nx + 2) * (new_ny + 2)
        p = m + [0xFFFF, 3, 2]
        data = edit(data, p + [5, 2, 2], lambda _: pack_array(mm.tobytes(), 1))
        data = edit(data, p + [5, 2, 1], lambda _: u32(count))
        data = edit(data, p + [1], lambda _: u32(new_nx))
        data = edit(data, p + [2], lambda _: u32(new_ny))
        data = edit(data, p + [3], lambda _: u32(count))
    return data


def crop_mnt(name, out, new_nx, new_ny):
    ole = olefile.OleFileIO(str(SRC / name))
    sc = ole.openstream("ScopedContents").read()
    ole.close()
    body = sc[8:]
    objects = get(body, [1, 0x02BD, 2, 1])
    entries = tlv(objects, prefixed=True)
    for e in entries:
        obj = e[1]
        if struct.unpack("<I", get(obj, [1, 1]))[0] != 9012:
            continue
        surf = get(obj, [2, 1, 2])
        nx = struct.unpack("<I", get(surf, [0xFFFF, 0xFFFF, 1, 0xFFFF, 1]))[0]
        ny = struct.unpack("<I", get(surf, [0xFFFF, 0xFFFF, 2, 0xFFFF, 1]))[0]
        e[1] = edit(obj, [2, 1, 2], lambda d: crop_surface(d, nx, ny, new_nx, new_ny))
        kept = [e]
        break
    objects = untlv(kept, prefixed=True)
    body = edit(body, [1, 0x02BD, 2, 1], lambda _: objects)
    body = edit(body, [1, 0x02BD, 1], lambda _: bytes([1]))
    stream = struct.pack("<Q", len(body)) + body
    (DATA / out).write_bytes(compound_file("ScopedContents", stream))


def compound_file(name, stream):
    """A version-3 compound file (512-byte sectors) with one stream of at
    least 4096 bytes (no mini stream)."""
    S = 512
    assert len(stream) >= 4096
    n_data = -(-len(stream) // S)
    n_dir = 1
    n_fat = 1
    while (n_data + n_dir + n_fat) > n_fat * (S // 4):
        n_fat += 1
    assert n_fat <= 109
    fat = []
    fat += [i + 1 for i in range(n_data - 1)] + [0xFFFFFFFE]
    fat += [0xFFFFFFFE]  # the directory
    fat += [0xFFFFFFFD] * n_fat
    fat += [0xFFFFFFFF] * (n_fat * S // 4 - len(fat))
    dir_sector = n_data
    fat_first = n_data + n_dir
    difat = [fat_first + i for i in range(n_fat)] + [0xFFFFFFFF] * (109 - n_fat)
    header = (
        b"\xD0\xCF\x11\xE0\xA1\xB1\x1A\xE1" + bytes(16)
        + struct.pack("<HHHHH", 0x3E, 3, 0xFFFE, 9, 6) + bytes(6)
        + struct.pack("<IIIIIIIII", 0, n_fat, dir_sector, 0, 4096, 0xFFFFFFFE, 0, 0xFFFFFFFE, 0)
        + struct.pack("<109I", *difat)
    )
    assert len(header) == 512

    def entry(name, kind, child, start, size):
        n = (name + "\0").encode("utf-16-le")
        return (n.ljust(64, b"\0") + struct.pack("<HBB", len(n), kind, 1)
                + struct.pack("<III", 0xFFFFFFFF, 0xFFFFFFFF, child) + bytes(16)
                + struct.pack("<I", 0) + bytes(16) + struct.pack("<IQ", start, size))

    directory = (entry("Root Entry", 5, 1, 0xFFFFFFFE, 0) + entry(name, 2, 0xFFFFFFFF, 0, len(stream))
                 + bytes(256))
    return (header + stream.ljust(n_data * S, b"\0") + directory
            + struct.pack(f"<{len(fat)}I", *fat))


# ---------------------------------------------------------------- .tiff


def crop_ps(name, out, rows):
    with tifffile.TiffFile(str(SRC / name)) as t:
        tags = t.pages[0].tags
        magic, version = tags[50432].value, tags[50433].value
        data, header = bytearray(tags[50434].value), bytearray(tags[50435].value)
    nx, ny = struct.unpack_from("<II", header, 100)
    ly = struct.unpack_from("<d", header, 148)[0]
    struct.pack_into("<I", header, 104, rows)
    struct.pack_into("<d", header, 148, ly * rows / ny)
    item = len(data) // (nx * ny)
    data = bytes(data[:nx * rows * item])
    tifffile.imwrite(
        str(DATA / out), np.zeros((4, 4), np.uint8),
        extratags=[(50432, 4, 1, magic, True), (50433, 4, 1, version, True),
                   (50434, 1, len(data), data, True), (50435, 7, len(header), bytes(header), True)])


# ---------------------------------------------------------------- report


def report(path, points):
    r = st.open_topography(str(path))
    c = r.channels[r.default_channel.index]
    t = r.topography()
    h = np.ma.getdata(t.heights())
    undefined = int(np.ma.getmaskarray(t.heights()).sum()) if np.ma.is_masked(t.heights()) else 0
    print(path.name, repr(c.name), t.nb_grid_pts, t.physical_sizes, t.unit, "undefined", undefined)
    print("  heights", repr([float(h[p]) for p in points]))
    if t.dim == 1 and not t.is_uniform:
        t = t.to_uniform(nb_points=t.nb_grid_pts[0])
        print("  to_uniform", t.nb_grid_pts, t.physical_sizes,
              repr([float(t.heights()[i]) for i in (0, 98, 99, 100, 959)]))
    if undefined:
        # The undefined points' count, where they are, and rms values are
        # not compared (SurfaceTopography fills them otherwise).
        mask = np.ma.getmaskarray(t.heights())
        print("  undefined at", repr([bool(mask[p]) for p in points]),
              "first defined", repr(sorted(zip(*np.nonzero(~mask.T)))[0][::-1]),
              "row 0 undefined", int(mask[:, 0].sum()))
        return
    d = t.detrend("height")
    print("  rms", repr((d.rms_height_from_area() if t.dim == 2 else d.rms_height_from_profile(),
                          d.rms_gradient() if t.dim == 2 else d.rms_slope_from_profile(),
                          d.rms_laplacian() if t.dim == 2 else d.rms_curvature_from_profile())))


crop_mnt("mnt-1.mnt", "mnt-1-crop.mnt", 200, 150)
crop_mnt("mnt-2.mnt", "mnt-2-crop.mnt", 256, 192)
crop_ps("example_ps.tiff", "example_ps-crop.tiff", 64)
print(st.__version__)
for f in ("mnt-1-crop.mnt", "mnt-2-crop.mnt"):
    report(DATA / f, [(0, 0), (1, 0), (0, 1), (199, 149), (17, 5), (150, 100)])
report(DATA / "example_ps-crop.tiff", [(0, 0), (1, 0), (0, 1), (511, 63), (17, 5)])
for f in ("mitutoyo_mock.xlsx", "mitutoyo_2_mock.xlsx", "mitutoyo_nonuniform_mock.xlsx"):
    report(DATA / f, [0, 1, 98, 99, 100, -1])

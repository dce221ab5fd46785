//! Binary instrument formats (Gwyddion `.gwy`, Digital Surf `.sur`, Zygo
//! MetroPro `.dat`, NetCDF `.nc`, Alicona `.al3d`, Sensofar `.plu`, Igor
//! binary wave `.ibw`, Bruker Nanoscope `.di`) on
//! real files (`tests/data/`, origins and licences in `tests/data/README.md`):
//! the grid, sizes, undefined points and heights as read, against
//! SurfaceTopography (or gwyfile where SurfaceTopography reads nothing)
//! reading the same file (`tests/reference/instrument_files.py` →
//! `instrument_files.rs`, `POINTS`); the conditioned statistics and spectra
//! of the same files are checked in `tests/instrument_files.rs` (`MAPS`).
//! Then damaged files: truncated, corrupt, without units, no height channel.
#![cfg(feature = "topography")]

use std::path::{Path, PathBuf};

use persson::topography::read::{self, as_read, LengthUnit, ReadOptions};

#[allow(dead_code)]
#[path = "reference/instrument_files.rs"]
mod st;

/// Sums of |h| over up to 2.6·10⁵ points added in another order: rounding
/// of the sums, far below this (measured: ≤ 3e-15, see the eprintln).
const SUMS: f64 = 1e-10;
/// One height: the same integer or float64 times the same factors (the
/// z scale, the sign, a unit's power of ten) in another order — a few
/// roundings.
const SAME_NUMBERS: f64 = 1e-14;
/// Sizes: n·Δ with the float32 Δ of `.sur` times a unit factor, a few roundings.
const SIZES: f64 = 1e-14;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn options(name: &str) -> ReadOptions {
    match name {
        // gwyfile's test file: written by Gwyddion without units.
        "gwyfile-test.gwy" => ReadOptions {
            height_unit: Some(LengthUnit::Nanometre),
            lateral_unit: Some(LengthUnit::Micrometre),
            ..Default::default()
        },
        // An Igor wave without units (Igor's default step 1).
        "10x10-one_channel_without_name.ibw" => ReadOptions {
            height_unit: Some(LengthUnit::Metre),
            size: Some(read::SizeSpec::PixelSize(1.0)),
            ..Default::default()
        },
        _ => ReadOptions::default(),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a / b - 1.0).abs()
    }
}

#[test]
fn heights_sizes_and_undefined_points_agree_with_surface_topography() {
    for p in st::POINTS {
        let r = as_read(&data(p.file), &options(p.file)).unwrap();
        assert_eq!((r.nx, r.ny), (p.nx, p.ny), "{}", p.file);
        assert!(
            rel(r.lx, p.lx) <= SIZES,
            "{}: Lx {} vs {}",
            p.file,
            r.lx,
            p.lx
        );
        assert!(
            rel(r.ly, p.ly) <= SIZES,
            "{}: Ly {} vs {}",
            p.file,
            r.ly,
            p.ly
        );
        let undefined = r.heights.iter().filter(|h| h.is_nan()).count();
        assert_eq!(undefined, p.undefined, "{}: undefined points", p.file);
        let mut worst: f64 = 0.0;
        for &(ix, iy, h) in p.at {
            let ours = r.heights[iy * r.nx + ix];
            let e = rel(ours, h);
            worst = worst.max(e);
            assert!(
                e <= SAME_NUMBERS,
                "{} h[{ix}, {iy}]: {ours:e} vs {h:e}",
                p.file
            );
        }
        let (mut s, mut sx, mut sy) = (0.0, 0.0, 0.0);
        for (k, h) in r.heights.iter().enumerate() {
            if h.is_finite() {
                let (ix, iy) = ((k % r.nx) as f64, (k / r.nx) as f64);
                s += h.abs();
                sx += ix * h.abs();
                sy += iy * h.abs();
            }
        }
        for (what, ours, theirs) in [
            ("Σ|h|", s, p.sum_abs),
            ("Σ ix|h|", sx, p.sum_ix_abs),
            ("Σ iy|h|", sy, p.sum_iy_abs),
        ] {
            let e = rel(ours, theirs);
            worst = worst.max(e);
            assert!(e <= SUMS, "{} {what}: {ours:e} vs {theirs:e}", p.file);
        }
        eprintln!(
            "{}: {} × {}, {undefined} undefined, largest relative difference {worst:.1e}",
            p.file, r.nx, r.ny
        );
    }
}

/// The error of reading `bytes` as `name`; asserts that it names the file
/// and the format, says `needle` and is one line.
fn error_of(name: &str, bytes: &[u8], o: &ReadOptions, needle: &str) -> String {
    let e = read::from_bytes(Path::new(name), bytes, o)
        .expect_err(needle)
        .to_string();
    assert!(e.starts_with(name), "{e:?} does not name {name}");
    assert!(e.contains(needle), "{e:?} does not say {needle:?}");
    assert!(!e.contains('\n'), "{e:?} is not one line");
    e
}

#[test]
fn truncated_files_are_errors_naming_the_format() {
    // The bytes each reader needs: the whole file, or up to the end of the
    // heights (al3d: a texture image follows; ibw: Igor's optional records).
    for (name, format, needed) in [
        ("gwyfile-mask.gwy", "Gwyddion .gwy", None),
        ("gwyfile-test.gwy", "Gwyddion .gwy", None),
        ("sur-2.sur", "Digital Surf .sur", None),
        ("sur-3.sur", "Digital Surf .sur", None),
        ("metropro-1.dat", "Zygo MetroPro .dat", None),
        ("nc-1.nc", "NetCDF .nc", None),
        ("st-mask.nc", "NetCDF .nc", None),
        ("al3d-1.al3d", "Alicona .al3d", Some(1261 + 200 * 296 * 4)),
        ("plu-1.plu", "Sensofar .plu", None),
        ("spot_1-1000nm.ibw", "Igor binary wave .ibw", Some(2112969)),
        (
            "10x10-one_channel_without_name.ibw",
            "Igor binary wave .ibw",
            None,
        ),
        // The first channel (ZSensor); three more follow.
        ("di-3.di", "Nanoscope .spm/.di", Some(40960 + 256 * 256 * 2)),
    ] {
        let b = std::fs::read(data(name)).unwrap();
        let o = ReadOptions {
            fill_undefined: true,
            ..options(name)
        };
        let n = needed.unwrap_or(b.len());
        for cut in [4, 13, 100, 511, 512, 600, n / 2, n - 1] {
            let e = error_of(name, &b[..cut], &o, format);
            assert!(e.contains("truncated"), "{name} cut at {cut}: {e}");
        }
        assert!(
            read::from_bytes(Path::new(name), &b[..n], &o).is_ok(),
            "{name}"
        );
        // The same bytes under another name are recognised by content (and
        // parsed to the undefined points, not filled here: sur-3 has 2.3·10⁵).
        // .plu and .ibw have no magic: read by their extension only.
        let o = options(name);
        let by_extension = name.ends_with(".plu") || name.ends_with(".ibw");
        match read::from_bytes(Path::new("renamed.bin"), &b, &o) {
            Ok(t) => assert!(t.nx() > 1 && !by_extension, "{name}"),
            Err(e) if by_extension => assert!(
                e.to_string()
                    .contains("unsupported format (.bin, binary data)"),
                "{name}: {e}"
            ),
            Err(e) => assert!(
                e.to_string().contains("points are undefined"),
                "{name}: {e}"
            ),
        }
    }
}

#[test]
fn a_gwy_file_without_units_needs_them_from_the_caller() {
    let b = std::fs::read(data("gwyfile-test.gwy")).unwrap();
    let none = ReadOptions::default();
    error_of("g.gwy", &b, &none, "states no unit of the heights");
    let z = ReadOptions {
        height_unit: Some(LengthUnit::Nanometre),
        ..Default::default()
    };
    error_of("g.gwy", &b, &z, "states no unit of the coordinates");
    let t = read::from_bytes(Path::new("g.gwy"), &b, &options("gwyfile-test.gwy")).unwrap();
    assert_eq!((t.nx(), t.ny(), t.lx()), (128, 128, 128e-6));
}

/// A `.gwy` with one data field, serialised as Gwyddion does (module docs
/// of the reader): `xres × yres` values, the z unit, an optional mask.
fn gwy(nx: i32, ny: i32, z_unit: &str, values: &[f64]) -> Vec<u8> {
    fn object(name: &str, body: &[u8]) -> Vec<u8> {
        let mut o = name.as_bytes().to_vec();
        o.push(0);
        o.extend((body.len() as u32).to_le_bytes());
        o.extend(body);
        o
    }
    fn item(name: &str, t: u8, v: &[u8]) -> Vec<u8> {
        let mut o = name.as_bytes().to_vec();
        o.push(0);
        o.push(t);
        o.extend(v);
        o
    }
    let unit = |u: &str| {
        let mut s = u.as_bytes().to_vec();
        s.push(0);
        object("GwySIUnit", &item("unitstr", b's', &s))
    };
    let mut array = (values.len() as u32).to_le_bytes().to_vec();
    values.iter().for_each(|v| array.extend(v.to_le_bytes()));
    let field = [
        item("xres", b'i', &nx.to_le_bytes()),
        item("yres", b'i', &ny.to_le_bytes()),
        item("xreal", b'd', &2e-6f64.to_le_bytes()),
        item("yreal", b'd', &(-1e-6f64).to_le_bytes()),
        item("si_unit_xy", b'o', &unit("m")),
        item("si_unit_z", b'o', &unit(z_unit)),
        item("data", b'D', &array),
    ]
    .concat();
    let body = item("/0/data", b'o', &object("GwyDataField", &field));
    let mut f = b"GWYP".to_vec();
    f.extend(object("GwyContainer", &body));
    f
}

#[test]
fn gwy_fields_are_read_and_checked() {
    let o = ReadOptions::default();
    let v = [0.0, 1.0, 2.0, 4.0, 8.0, 16.0];
    // 3 × 2 in nm: x fastest; a negative yreal is taken by its magnitude.
    let t = read::from_bytes(Path::new("a.gwy"), &gwy(3, 2, "nm", &v), &o).unwrap();
    assert_eq!((t.nx(), t.ny(), t.lx(), t.ly()), (3, 2, 2e-6, 1e-6));
    assert_eq!(t.heights()[3], 4e-9);
    error_of(
        "p.gwy",
        &gwy(3, 2, "deg", &v),
        &o,
        "no channel holds heights",
    );
    error_of(
        "n.gwy",
        &gwy(3, 3, "m", &v),
        &o,
        "9 values, its data array has 6",
    );
    error_of("z.gwy", &gwy(0, 2, "m", &[]), &o, "xres = 0");
    error_of("o.gwy", b"GWYO\0\0", &o, "Gwyddion 1");
    // Nesting beyond any real file is refused, not a stack overflow.
    let mut deep = b"GWYP".to_vec();
    for _ in 0..10_000 {
        deep.extend(b"GwyContainer\0\x00\x00\x01\x00a\0o");
    }
    error_of("d.gwy", &deep, &o, "Gwyddion .gwy");
}

#[test]
fn sur_inversion_special_points_and_damage() {
    let b = std::fs::read(data("sur-2.sur")).unwrap();
    let plain = as_read(&data("sur-2.sur"), &ReadOptions::default()).unwrap();
    let path = std::env::temp_dir().join(format!("persson-sur-{}.sur", std::process::id()));
    // Inversion 2: z negated and x reversed.
    let mut flipped = b.clone();
    flipped[290..292].copy_from_slice(&2u16.to_le_bytes());
    std::fs::write(&path, &flipped).unwrap();
    let f = as_read(&path, &ReadOptions::default()).unwrap();
    let (nx, ny) = (plain.nx, plain.ny);
    for (iy, ix) in [(0, 0), (5, 17), (ny - 1, nx - 1)] {
        let a = plain.heights[iy * nx + ix];
        let b = f.heights[iy * nx + (nx - 1 - ix)];
        assert!(
            a == -b || (a.is_nan() && b.is_nan()),
            "({ix}, {iy}): {a} {b}"
        );
    }
    // Inversion 3: z negated and y reversed.
    flipped[290..292].copy_from_slice(&3u16.to_le_bytes());
    std::fs::write(&path, &flipped).unwrap();
    let f = as_read(&path, &ReadOptions::default()).unwrap();
    assert_eq!(f.heights[nx + 3], -plain.heights[(ny - 2) * nx + 3]);
    // Without "special points" the missing-data marker is a height.
    let mut all = b.clone();
    all[86..88].copy_from_slice(&0u16.to_le_bytes());
    std::fs::write(&path, &all).unwrap();
    let a = as_read(&path, &ReadOptions::default()).unwrap();
    assert!(a.heights.iter().all(|h| h.is_finite()));
    std::fs::remove_file(&path).unwrap();

    let o = ReadOptions::default();
    let with = |offset: usize, v: &[u8]| {
        let mut c = b.clone();
        c[offset..offset + v.len()].copy_from_slice(v);
        c
    };
    error_of("c.sur", b"DSCOMPRESSED\0\0", &o, "compressed");
    error_of(
        "e.sur",
        &with(12, &257u16.to_le_bytes()),
        &o,
        "little-endian",
    );
    error_of(
        "b.sur",
        &with(98, &8u16.to_le_bytes()),
        &o,
        "8 bits per point",
    );
    error_of(
        "n.sur",
        &with(108, &(-3i32).to_le_bytes()),
        &o,
        "both must be > 0",
    );
    error_of(
        "p.sur",
        &with(116, &7u32.to_le_bytes()),
        &o,
        "the header gives 7 points",
    );
    error_of("u.sur", &with(212, b"deg\0"), &o, "not a unit of length");
    error_of("s.sur", &with(128, &0f32.to_le_bytes()), &o, "z scale 0");
    // 563 × 484 int32 points do not fit in 1024 bytes.
    error_of("t.sur", &b[..1024], &o, "truncated");
}

#[test]
fn metropro_sign_undefined_points_size_and_damage() {
    let b = std::fs::read(data("metropro-1.dat")).unwrap();
    let plain = as_read(&data("metropro-1.dat"), &ReadOptions::default()).unwrap();
    let o = ReadOptions::default();
    let with = |offset: usize, v: &[u8]| {
        let mut c = b.clone();
        c[offset..offset + v.len()].copy_from_slice(v);
        c
    };
    // The sign flag negates; the first phase value at the invalid marker is undefined.
    let t = read::from_bytes(Path::new("s.dat"), &with(232, &1i16.to_be_bytes()), &o).unwrap();
    assert_eq!(t.heights()[7], -plain.heights[7]);
    let first = 834 + 2 * 640 * 480;
    let marked = with(first, &i32::MAX.to_be_bytes());
    error_of("m.dat", &marked, &o, "1 of 307200 points are undefined");
    // A lateral resolution of 0 is "unknown": the caller gives the size.
    let unknown = with(184, &0f32.to_be_bytes());
    error_of("l.dat", &unknown, &o, "stores no physical size");
    let given = ReadOptions {
        size: Some(read::SizeSpec::PixelSize(1e-6)),
        ..Default::default()
    };
    let t = read::from_bytes(Path::new("l.dat"), &unknown, &given).unwrap();
    assert_eq!((t.lx(), t.ly()), (640.0 * 1e-6, 480.0 * 1e-6));
    error_of(
        "h.dat",
        &with(6, &900u32.to_be_bytes()),
        &o,
        "header size 900",
    );
    error_of(
        "r.dat",
        &with(218, &7i16.to_be_bytes()),
        &o,
        "phase resolution 7",
    );
    error_of(
        "z.dat",
        &with(168, &0f32.to_be_bytes()),
        &o,
        "not a finite, non-zero",
    );
    error_of("e.dat", &with(68, &0u16.to_be_bytes()), &o, "no phase data");
}

#[test]
fn netcdf_versions_conventions_and_damage() {
    let b = std::fs::read(data("nc-1.nc")).unwrap();
    let o = ReadOptions::default();
    let with = |offset: usize, v: &[u8]| {
        let mut c = b.clone();
        c[offset..offset + v.len()].copy_from_slice(v);
        c
    };
    error_of("v.nc", &with(3, &[3]), &o, "version 3");
    error_of("c.nc", b"CDX\x01\0\0\0\0", &o, "does not start with CDF");
    let heights = b.windows(7).position(|w| w == b"heights").unwrap();
    error_of(
        "h.nc",
        &with(heights, b"heightz"),
        &o,
        "no variable 'heights'",
    );
    // The unit of y (the first variable) is not a length.
    let unit = b.windows(6).position(|w| w == b"unit\0\0").unwrap();
    let nm = unit + 12; // "unit", its type (char) and count (2), then "nm"
    error_of("u.nc", &with(nm, b"Hz"), &o, "not a unit of length");
    // The heights in nm as the x unit says; x:length 5 (nm) over 5 points.
    let t = read::from_bytes(Path::new("n.nc"), &b, &o).unwrap();
    assert_eq!((t.nx(), t.ny(), t.lx(), t.ly()), (5, 10, 5e-9, 1e-8));
}

#[test]
fn al3d_plu_ibw_units_channels_and_damage() {
    let o = ReadOptions::default();
    let with = |name: &str, offset: usize, v: &[u8]| {
        let mut c = std::fs::read(data(name)).unwrap();
        c[offset..offset + v.len()].copy_from_slice(v);
        c
    };
    // al3d: tags of 52 bytes after the 17-byte magic; the third is Cols.
    let al3d = "al3d-1.al3d";
    error_of(
        "a.al3d",
        &with(al3d, 17 + 50, b"\n\r"),
        &o,
        "does not end with CR LF",
    );
    error_of(
        "a.al3d",
        &with(al3d, 17 + 2 * 52, b"Colz"),
        &o,
        "no tag Cols",
    );
    error_of(
        "a.al3d",
        &with(al3d, 17 + 52 + 20, b"x"),
        &o,
        "TagCount = \"x7\"",
    );
    error_of(
        "a.al3d",
        &with(al3d, 17 + 2 * 52 + 20, b"0\0\0"),
        &o,
        "Cols × Rows = 0 × 296",
    );
    // The marker of undefined points, written where the first height is.
    let marker = (3.000000028082e15_f64 as f32).to_le_bytes();
    error_of(
        "a.al3d",
        &with(al3d, 1261, &marker),
        &o,
        "1 of 59200 points are undefined",
    );
    // plu: the measurement type at 428 (1: a profile); no layers.
    let plu = "plu-1.plu";
    error_of(
        "p.plu",
        &with(plu, 428, &1u32.to_le_bytes()),
        &o,
        "type 1 (a profile)",
    );
    error_of("p.plu", &with(plu, 489, &[0]), &o, "no layers");
    error_of(
        "p.plu",
        &with(plu, 508, &1_000_001f32.to_le_bytes()),
        &o,
        "1 of 442368 points",
    );
    // ibw: without units the caller gives them; channels by name.
    let bare = "10x10-one_channel_without_name.ibw";
    let b = std::fs::read(data(bare)).unwrap();
    error_of("w.ibw", &b, &o, "states no unit of the heights");
    let z = ReadOptions {
        height_unit: Some(LengthUnit::Nanometre),
        ..Default::default()
    };
    error_of("w.ibw", &b, &z, "stores no physical size");
    let t = read::from_bytes(Path::new("w.ibw"), &b, &options(bare)).unwrap();
    assert_eq!((t.nx(), t.ny(), t.lx()), (10, 10, 10.0));
    let spot = "spot_1-1000nm.ibw";
    // The labels follow the note: rename the two height channels.
    let labels = 64 + 2097472 + 15145 + 32;
    let renamed = with(spot, labels, b"PhaseA\0");
    let renamed = {
        let mut c = renamed;
        c[labels + 32..labels + 39].copy_from_slice(b"PhaseB\0");
        c
    };
    error_of("s.ibw", &renamed, &o, "no height channel");
    // HeightRetrace (the second channel) when the first is not a height.
    let t = read::from_bytes(Path::new("s.ibw"), &with(spot, labels, b"PhaseA\0"), &o).unwrap();
    let first =
        read::from_bytes(Path::new("s.ibw"), &std::fs::read(data(spot)).unwrap(), &o).unwrap();
    assert_ne!(t.heights()[0], first.heights()[0]);
    error_of(
        "s.ibw",
        &with(spot, 148 + 64, b"deg\0"),
        &o,
        "not a unit of length",
    );
    error_of("s.ibw", &with(spot, 0, &[3, 0]), &o, "version 3");
    error_of(
        "s.ibw",
        &with(spot, 64 + 16, &1i16.to_le_bytes()),
        &o,
        "wave type 0x1",
    );
    error_of(
        "s.ibw",
        &with(spot, 64 + 12, &7i32.to_le_bytes()),
        &o,
        "npnts = 7",
    );
}

#[test]
fn ibw_big_endian_wave_reads_with_igors_y_upwards() {
    // A 2 × 3 float32 wave in µm, big-endian (Igor on a Mac): version 5,
    // wfmSize 320 + 24, then the wave header and the values, x fastest.
    let mut b = vec![0u8; 64 + 320];
    b[0..2].copy_from_slice(&5i16.to_be_bytes());
    b[4..8].copy_from_slice(&(320i32 + 24).to_be_bytes());
    let w = 64;
    b[w + 12..w + 16].copy_from_slice(&6i32.to_be_bytes());
    b[w + 16..w + 18].copy_from_slice(&2i16.to_be_bytes());
    b[w + 68..w + 72].copy_from_slice(&2i32.to_be_bytes());
    b[w + 72..w + 76].copy_from_slice(&3i32.to_be_bytes());
    b[w + 84..w + 92].copy_from_slice(&0.5f64.to_be_bytes());
    b[w + 92..w + 100].copy_from_slice(&0.25f64.to_be_bytes());
    for at in [148, 152, 156] {
        b[w + at] = b'u';
        b[w + at + 1] = b'm';
    }
    for v in [1f32, 2.0, 3.0, 4.0, 5.0, 7.0] {
        b.extend(v.to_be_bytes());
    }
    let t = read::from_bytes(Path::new("be.ibw"), &b, &ReadOptions::default()).unwrap();
    assert_eq!((t.nx(), t.ny(), t.lx(), t.ly()), (2, 3, 1e-6, 0.75e-6));
    // Igor's last row (y up) is the map's first.
    let um: Vec<f64> = t.heights().iter().map(|h| (h * 1e6).round()).collect();
    assert_eq!(um, [5.0, 7.0, 3.0, 4.0, 1.0, 2.0]);
}

#[test]
fn nanoscope_channels_scales_and_damage() {
    let b = std::fs::read(data("di-3.di")).unwrap();
    let o = ReadOptions::default();
    let text = |from: &str, to: &str| {
        let at = b
            .windows(from.len())
            .position(|w| w == from.as_bytes())
            .unwrap();
        let mut c = b.clone();
        c[at..at + to.len()].copy_from_slice(to.as_bytes());
        c
    };
    // The first channel's sensitivity in V/V (not a length): the next
    // length channel (Height, the fourth) is read.
    let t = read::from_bytes(
        Path::new("h.di"),
        &text("[Sens. ZsensSens]", "[Sens. biassens] "),
        &o,
    )
    .unwrap();
    let first = read::from_bytes(Path::new("h.di"), &b, &o).unwrap();
    assert_ne!(t.heights()[0], first.heights()[0]);
    error_of(
        "s.di",
        &text("[Sens. ZsensSens]", "[Sens. Nonesuch] "),
        &o,
        "\"Sens. Nonesuch\" of ZSensor is not in the header",
    );
    error_of(
        "b.di",
        &text("Bytes/pixel: 2", "Bytes/pixel: 3"),
        &o,
        "3 bytes per pixel",
    );
    error_of(
        "l.di",
        &text("Data length: 131072", "Data length: 131070"),
        &o,
        "data length 131070",
    );
    error_of(
        "z.di",
        &text("Scan Size: 10 10 ~m", "Scan Size: 10 10 Hz"),
        &o,
        "Scan Size",
    );
    error_of(
        "x.di",
        &text("\\Version", "Version"),
        &o,
        "does not start with a backslash",
    );
    error_of("e.di", &b[..30000], &o, "no \\*File list end");
}

/// Every prefix of the header region and 64 longer ones, and 400 files
/// with one to four bytes of the first 4 kB replaced (a fixed-seed
/// generator): an error or a topography with finite heights, never a
/// panic. (The fuzz targets `fuzz/fuzz_targets/read_*.rs` search further.)
#[test]
fn damaged_al3d_plu_ibw_nanoscope_files_never_panic() {
    let o = ReadOptions::default();
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    for name in [
        "al3d-1.al3d",
        "plu-1.plu",
        "spot_1-1000nm.ibw",
        "10x10-one_channel_without_name.ibw",
        "di-3.di",
    ] {
        let b = std::fs::read(data(name)).unwrap();
        let check = |bytes: &[u8]| {
            if let Ok(t) = read::from_bytes(Path::new(name), bytes, &o) {
                assert!(t.heights().iter().all(|h| h.is_finite()), "{name}");
            }
        };
        let head = b.len().min(4096);
        (0..head).for_each(|n| check(&b[..n]));
        (1..=64).for_each(|k| check(&b[..b.len() * k / 64]));
        for _ in 0..400 {
            let mut c = b.clone();
            for _ in 0..1 + next() % 4 {
                let at = (next() % head as u64) as usize;
                c[at] = next() as u8;
            }
            check(&c);
        }
    }
}

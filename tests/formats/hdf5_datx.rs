//! HDF5 `.h5` (a data set by name or index) and Zygo `.datx`.

use persson::topography::read::{self, Format, ReadOptions, SizeSpec};

use super::support::{agrees_with_st, close, data, error_of, temp, ST_AGREEMENT};

/// Pixel size 1 m, the size SurfaceTopography is given for the
/// `.h5` files (`physical_sizes = nb_grid_pts`): HDF5 stores none.
fn unit_pixels(channel: Option<&str>) -> ReadOptions {
    ReadOptions {
        size: Some(SizeSpec::PixelSize(1.0)),
        channel: channel.map(str::to_string),
        ..Default::default()
    }
}

/// `multiple_data_sets-crop.h5`: SurfaceTopography's example (superblock 0,
/// two contiguous data sets) rewritten smaller with the same structure by
/// tests/reference/hdf5_surface_topography.py, against SurfaceTopography
/// 1.27.1 reading the crop (that script's output): the default channel is
/// the first (`dataset1`, float64), `dataset2` (float32) by name or index;
/// the first index runs along x.
#[test]
fn hdf5_multiple_data_sets() {
    for channel in [None, Some("dataset1"), Some("0"), Some("/DATASET1")] {
        let t = read::read(&data("multiple_data_sets-crop.h5"), &unit_pixels(channel)).unwrap();
        assert_eq!(t.shape(), [16, 24], "{channel:?}");
        assert!(close(t.lx(), 24.0) && close(t.ly(), 16.0));
        agrees_with_st(
            &t,
            1.0,
            &[
                ((0, 0), -0.49869003295898445),
                ((1, 0), -0.49869003295898445),
                ((0, 1), -0.4978042602539063),
                ((23, 15), -0.4947926330566407),
                ((3, 2), -0.49895576477050785),
            ],
            [
                0.004445168507282938,
                0.002426535436553035,
                0.0023285840792234913,
            ],
            ST_AGREEMENT,
        );
    }
    for channel in ["dataset2", "1"] {
        let t = read::read(
            &data("multiple_data_sets-crop.h5"),
            &unit_pixels(Some(channel)),
        )
        .unwrap();
        assert_eq!(t.shape(), [12, 20]);
        agrees_with_st(
            &t,
            1.0,
            &[
                ((0, 0), -0.0002655062125995755),
                ((1, 0), -0.00026905431877821684),
                ((0, 1), -0.00026970781618729234),
                ((19, 11), -0.0002612679381854832),
                ((3, 2), -0.00027166816289536655),
            ],
            [
                3.5753969091229894e-06,
                3.041693175790558e-06,
                5.03136463451154e-06,
            ],
            ST_AGREEMENT,
        );
    }
    let e = error_of(
        &data("multiple_data_sets-crop.h5"),
        &unit_pixels(Some("dataset3")),
        "no channel \"dataset3\"",
    );
    assert!(e.contains("1: \"dataset2\"") && e.contains("HDF5"), "{e}");
}

/// h5py's chunked data sets with shuffle + deflate, an int16 one, a 1-D and
/// a string data set (not channels), in a nested group; superblock 3 with v2
/// object headers (layout message 4) and superblock 0 with v1 B-trees, both
/// against SurfaceTopography 1.27.1 (tests/reference/hdf5_surface_topography.py).
#[test]
fn hdf5_chunked_deflate_int_and_groups() {
    for file in ["h5-chunked-deflate.h5", "h5-chunked-deflate-v0.h5"] {
        let t = read::read(&data(file), &unit_pixels(None)).unwrap();
        assert_eq!(t.shape(), [5, 6], "{file}: counts is channel 0");
        agrees_with_st(
            &t,
            1.0,
            &[
                ((0, 0), 128.0),
                ((1, 0), -157.0),
                ((0, 1), 156.0),
                ((5, 4), 267.0),
                ((3, 2), 265.0),
            ],
            [188.07629408520734, 424.75952269805055, 1137.2276597058303],
            ST_AGREEMENT,
        );
        for channel in ["group/heights", "heights", "1"] {
            let t = read::read(&data(file), &unit_pixels(Some(channel))).unwrap();
            assert_eq!(t.shape(), [10, 12]);
            agrees_with_st(
                &t,
                1.0,
                &[
                    ((0, 0), -1.1420923471450806),
                    ((1, 0), 0.19330890476703644),
                    ((0, 1), -1.0693365335464478),
                    ((11, 9), -0.21699270606040955),
                    ((3, 2), -1.1281838417053223),
                ],
                [0.9438270614102408, 1.873772568547971, 4.247731771513711],
                ST_AGREEMENT,
            );
        }
        error_of(
            &data(file),
            &unit_pixels(Some("profile")),
            "no channel \"profile\"",
        );
    }
}

/// Damaged `.h5` files: truncated at many lengths, a flipped byte in each
/// of many places: an error naming the file and HDF5, or (a flip in unused
/// bytes) a reading, never a panic.
#[test]
fn hdf5_damaged() {
    for file in [
        "multiple_data_sets-crop.h5",
        "h5-chunked-deflate.h5",
        "h5-chunked-deflate-v0.h5",
    ] {
        let bytes = std::fs::read(data(file)).unwrap();
        for n in (0..bytes.len())
            .step_by(97)
            .chain([8, 100, bytes.len() - 1])
        {
            let p = temp(&format!("cut-{n}-{file}"), &bytes[..n]);
            let o = ReadOptions {
                format: Some(Format::Hdf5),
                ..unit_pixels(None)
            };
            if n < 8 {
                assert!(read::read(&p, &o).is_err());
            } else if let Err(e) = read::read(&p, &o) {
                let e = e.to_string();
                assert!(e.contains("HDF5") && e.contains(file), "{e}");
            }
        }
        for at in (0..bytes.len()).step_by(13) {
            let mut b = bytes.clone();
            b[at] ^= 0xa5;
            let p = temp(&format!("flip-{at}-{file}"), &b);
            if let Err(e) = read::read(&p, &unit_pixels(None)) {
                let e = e.to_string();
                assert!(e.contains(file), "{e}");
            }
        }
    }
    let bytes = std::fs::read(data("multiple_data_sets-crop.h5")).unwrap();
    error_of(
        &temp("cut.h5", &bytes[..3000]),
        &unit_pixels(None),
        "truncated",
    );
}

/// Zygo `.datx` (no instrument file is public: files written with h5py in
/// the layout SurfaceTopography reads, by
/// tests/reference/datx_surface_topography.py, against SurfaceTopography
/// 1.27.1 reading them). float64 in µm with `No Data` points and a NaN,
/// fixed-length strings, superblock 0: 9 × 6 points of 4.5 × 4.2 µm.
#[test]
fn datx_float64_no_data() {
    let p = data("datx-float64.datx");
    error_of(&p, &ReadOptions::default(), "undefined");
    let o = ReadOptions {
        fill_undefined: true,
        ..Default::default()
    };
    let t = read::read(&p, &o).unwrap();
    assert_eq!(t.shape(), [6, 9]);
    assert!(
        close(t.lx(), 4.5e-6) && close(t.ly(), 4.2e-6),
        "{} {}",
        t.lx(),
        t.ly()
    );
    let h = |ix: usize, iy: usize| t.heights()[iy * 9 + ix];
    for ((ix, iy), st) in [
        ((0, 0), -1.2316649689147774),
        ((1, 0), 0.2671189477208684),
        ((0, 1), -1.3065640246645707),
        ((8, 5), -0.020585458484185266),
    ] {
        assert!(close(h(ix, iy), st * 1e-6), "({ix}, {iy})");
    }
    // Without the file's name in it, by content: the same reading.
    let bytes = std::fs::read(&p).unwrap();
    let u = read::read(&temp("zygo-export", &bytes), &o).unwrap();
    assert_eq!(u.heights(), t.heights());
    // The undefined points: SurfaceTopography masks (2, 1), (0, 3) and (8, 4).
    let raw = read::read(
        &p,
        &ReadOptions {
            fill_undefined: true,
            ..Default::default()
        },
    );
    assert!(raw.is_ok());
}

/// `.datx` float32 in nm, variable-length strings, chunked + deflate,
/// superblock 3: 7 × 5 points of 1400 × 1000 nm.
#[test]
fn datx_float32_vlen_chunked() {
    let t = read::read(&data("datx-float32.datx"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [5, 7]);
    assert!(close(t.lx(), 1400e-9) && close(t.ly(), 1000e-9));
    agrees_with_st(
        &t,
        1e-9,
        &[
            ((0, 0), -16.52012062072754),
            ((1, 0), -45.75241470336914),
            ((0, 1), 14.832550048828125),
            ((6, 4), 36.977272033691406),
            ((2, 1), -12.81435489654541),
            ((0, 3), 40.42782974243164),
        ],
        [
            24.509073528208695,
            0.21261879492108343,
            0.0016942185349596477,
        ],
        ST_AGREEMENT,
    );
    let o = ReadOptions {
        channel: Some("Phase".into()),
        ..Default::default()
    };
    error_of(&data("datx-float32.datx"), &o, "no channel \"Phase\"");
    // A .h5 file read as .datx: no /MetaData.
    let h5 = std::fs::read(data("multiple_data_sets-crop.h5")).unwrap();
    error_of(
        &temp("not.datx", &h5),
        &ReadOptions::default(),
        "no /MetaData",
    );
    let bytes = std::fs::read(data("datx-float32.datx")).unwrap();
    for n in (0..bytes.len()).step_by(61) {
        let p = temp(&format!("cut-{n}.datx"), &bytes[..n]);
        let e = read::read(&p, &ReadOptions::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("cut-"), "{e}");
    }
}

/// The result of reading `bytes` as `name` with channel `channel`, a panic
/// turned into a test failure naming the case.
fn read_without_panic(
    name: &str,
    bytes: &[u8],
    channel: Option<&str>,
    case: &str,
) -> Option<String> {
    let o = ReadOptions {
        fill_undefined: true,
        channel: channel.map(str::to_string),
        ..Default::default()
    };
    let path = std::path::Path::new(name);
    match std::panic::catch_unwind(|| read::from_bytes(path, bytes, &o)) {
        Ok(Ok(_)) => None,
        Ok(Err(e)) => {
            let e = e.to_string();
            assert!(e.contains(name), "{case}: {e:?} does not name {name}");
            assert!(!e.contains('\n'), "{case}: {e:?} is not one line");
            Some(e)
        }
        Err(_) => panic!("{case}: reading {name} panicked"),
    }
}

/// Files on which rustyhdf5-format panicked (found by a review's fuzzing):
/// the original with these bytes set, cut to a length. Chunk addresses of
/// all ones (`address + size` wrapped, chunked_read.rs:69), a layout of
/// dimensionality 0 (chunked_read.rs:340), fixed-array parameters
/// (fixed_array.rs:129–147), a global heap collection's size
/// (global_heap.rs:81). Each is an error naming the file and saying what
/// is damaged, never a panic nor the dependency's `Debug` form.
#[test]
fn hdf5_datx_crash_cases() {
    #[allow(clippy::type_complexity)]
    let cases: &[(&str, Option<usize>, &[(usize, u8)])] = &[
        (
            "datx-float32.datx",
            None,
            &[
                (2296, 0xff),
                (2297, 0xff),
                (2298, 0xff),
                (2299, 0xff),
                (2300, 0xff),
                (2301, 0xff),
                (2302, 0xff),
                (2303, 0xff),
            ],
        ),
        (
            "datx-float32.datx",
            Some(5687),
            &[(905, 0xff), (906, 0xff), (3049, 0x10)],
        ),
        (
            "h5-chunked-deflate-v0.h5",
            None,
            &[
                (1001, 0x08),
                (5536, 0xf7),
                (5537, 0xff),
                (5538, 0xff),
                (5539, 0xff),
                (5540, 0xff),
                (5541, 0xff),
                (5542, 0xff),
                (5543, 0xff),
            ],
        ),
        (
            "h5-chunked-deflate-v0.h5",
            None,
            &[
                (372, 0x40),
                (4826, 0x00),
                (4827, 0x00),
                (4828, 0x00),
                (7206, 0x08),
            ],
        ),
        ("h5-chunked-deflate.h5", None, &[(1121, 0xff), (1122, 0xff)]),
        (
            "h5-chunked-deflate.h5",
            Some(2549),
            &[(1559, 0xff), (1560, 0xff), (1561, 0xff), (1562, 0x7f)],
        ),
        (
            "h5-chunked-deflate.h5",
            None,
            &[
                (1596, 0xf7),
                (1597, 0xff),
                (1598, 0xff),
                (1599, 0xff),
                (1600, 0xff),
                (1601, 0xff),
                (1602, 0xff),
                (1603, 0xff),
                (2202, 0x58),
            ],
        ),
        (
            "h5-chunked-deflate.h5",
            None,
            &[
                (1560, 0xff),
                (1561, 0xff),
                (1562, 0x00),
                (1847, 0x20),
                (2141, 0x00),
                (2219, 0x00),
                (2220, 0x00),
                (2221, 0x00),
                (2222, 0x00),
            ],
        ),
        (
            "h5-chunked-deflate.h5",
            None,
            &[
                (1130, 0xff),
                (1131, 0xff),
                (1132, 0xff),
                (1133, 0xff),
                (1134, 0xff),
                (1135, 0xff),
                (1136, 0xff),
                (1137, 0xff),
                (2216, 0xc9),
                (2625, 0x02),
            ],
        ),
    ];
    for (i, (file, cut, patch)) in cases.iter().enumerate() {
        let mut b = std::fs::read(data(file)).unwrap();
        for &(at, v) in *patch {
            b[at] = v;
        }
        b.truncate(cut.unwrap_or(b.len()));
        for channel in [None, Some("1")] {
            let case = format!("case {i} ({file}, channel {channel:?})");
            if let Some(e) = read_without_panic(file, &b, channel, &case) {
                // Checked before the dependency is called, not its caught panic.
                assert!(
                    !e.contains("{ ") && !e.contains("Eof") && !e.contains("reader failed"),
                    "{case}: {e}"
                );
            }
        }
    }
}

/// The small `.h5` and `.datx` files with, every 13 bytes, one byte set to
/// each of 0x00, 0xff, flipped, and eight bytes of all ones, and cut every
/// 97 bytes: an error naming the file or a reading, never a panic.
#[test]
fn hdf5_datx_mutations_never_panic() {
    for file in [
        "h5-chunked-deflate.h5",
        "datx-float32.datx",
        "datx-float64.datx",
    ] {
        let bytes = std::fs::read(data(file)).unwrap();
        for at in (0..bytes.len()).step_by(13) {
            for kind in 0..4 {
                let mut b = bytes.clone();
                match kind {
                    0 => b[at] = 0,
                    1 => b[at] = 0xff,
                    2 => b[at] ^= 0xa5,
                    _ => b[at..(at + 8).min(bytes.len())].fill(0xff),
                }
                for channel in [None, Some("1")] {
                    read_without_panic(file, &b, channel, &format!("{file} byte {at} kind {kind}"));
                }
            }
        }
        for n in (0..bytes.len()).step_by(97) {
            read_without_panic(file, &bytes[..n], None, &format!("{file} cut at {n}"));
        }
    }
}

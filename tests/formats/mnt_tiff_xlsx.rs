//! Digital Surf Mountains `.mnt`, Park Systems `.tiff`, Mitutoyo SurfTest
//! `.xlsx`, against SurfaceTopography 1.27.1 reading the same files
//! (tests/reference/mnt_tiff_xlsx_surface_topography.py, which writes the
//! crops; its output, in µm, is repeated at each test).

use persson::topography::read::{self, ReadOptions};
use persson::topography::{Layout, Note};

use super::support::{agrees_with_st, close, data, error_of, temp, ST_AGREEMENT};

/// A line scan against SurfaceTopography's: heights h[i] (µm) and the rms
/// height, slope and curvature along the profile after the line
/// (`rms_height_from_profile`, `rms_slope_from_profile`,
/// `rms_curvature_from_profile`).
fn profile_agrees_with_st(
    t: &persson::topography::Topography,
    points: &[(usize, f64)],
    rms: [f64; 3],
) {
    use persson::topography::{real_space_stats, Detrend};
    for &(i, st) in points {
        let h = t.heights()[i];
        assert!(close(h, st * 1e-6), "{i}: {h} against {st}");
    }
    let s = real_space_stats(t, Detrend::Plane).unwrap();
    let got = [
        s.rms_height,
        s.rms_slope_profile.unwrap(),
        s.rms_curvature_profile.unwrap(),
    ];
    for (k, (g, w)) in got
        .into_iter()
        .zip([rms[0] * 1e-6, rms[1], rms[2] * 1e6])
        .enumerate()
    {
        assert!(
            (g / w - 1.0).abs() < ST_AGREEMENT,
            "rms {k}: {g} against {w}"
        );
    }
}

fn channel(name: &str) -> ReadOptions {
    ReadOptions {
        channel: Some(name.into()),
        ..Default::default()
    }
}

/// Errors, never a panic, for the file cut at several lengths; each names
/// the file and `format`.
fn truncations(name: &str, format: &str) {
    let bytes = std::fs::read(data(name)).unwrap();
    let ext = name.rsplit('.').next().unwrap();
    for cut in [
        0,
        3,
        100,
        600,
        bytes.len() / 3,
        bytes.len() / 2,
        bytes.len() - 200,
    ] {
        let p = temp(&format!("cut-{cut}.{ext}"), &bytes[..cut]);
        let e = read::read(&p, &ReadOptions::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("cut-{cut}.{ext}")), "{e}");
        assert!(e.contains(format), "{cut}: {e}");
    }
}

/// `bytes` with the first occurrence of `from` replaced by `to`.
fn patched(bytes: &[u8], from: &[u8], to: &[u8]) -> Vec<u8> {
    let k = bytes.windows(from.len()).position(|w| w == from).unwrap();
    let mut b = bytes.to_vec();
    b[k..k + to.len()].copy_from_slice(to);
    b
}

/// mnt-1-crop.mnt (200 × 150 of mnt-1.mnt's 960 × 600 int32 counts, no
/// mask). SurfaceTopography: 'A48_10x_P1' (200, 150) (370.6786235662148,
/// 278.1831385642738) µm; h[0,0], h[1,0], h[0,1], h[199,149], h[17,5],
/// h[150,100] = 50.62837223455114, 50.628067034551144, 50.62861633455115,
/// 50.629226734551146, 50.626506834551144, 50.631938934551144; rms
/// (0.004007369237498801, 0.0018807318418537795, 0.001256961612559047).
#[test]
fn mountains_mnt_against_surface_topography() {
    let t = read::read(&data("mnt-1-crop.mnt"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [150, 200]);
    assert!(close(t.lx(), 370.6786235662148e-6) && close(t.ly(), 278.1831385642738e-6));
    let st = [
        ((0, 0), 50.62837223455114),
        ((1, 0), 50.628067034551144),
        ((0, 1), 50.62861633455115),
        ((199, 149), 50.629226734551146),
        ((17, 5), 50.626506834551144),
        ((150, 100), 50.631938934551144),
    ];
    // Heights near 50.63 µm with an rms of 4 nm after the plane: the plane
    // cancels four digits (as LARGE_OFFSET of gzip_sdf_tmd_bcr.rs).
    agrees_with_st(
        &t,
        1e-6,
        &st,
        [
            0.004007369237498801,
            0.0018807318418537795,
            0.001256961612559047,
        ],
        1e-9,
    );
    // The channel by name (the grid's name), or index; another is an error.
    let by_name = read::read(&data("mnt-1-crop.mnt"), &channel("a48_10x_p1")).unwrap();
    assert_eq!(by_name.heights(), t.heights());
    let e = error_of(
        &data("mnt-1-crop.mnt"),
        &channel("Phase"),
        "no channel \"Phase\"",
    );
    assert!(e.contains("A48_10x_P1") && e.contains("Mountains"), "{e}");
}

/// mnt-2-crop.mnt (256 × 192 of mnt-2.mnt, with its mask).
/// SurfaceTopography: (256, 192) (19.169328734278682, 14.376996550709013)
/// µm, 12795 undefined points, 132 of them in row 0; undefined at (0,0),
/// (1,0), (0,1), (17,5); h[199,149] = 1.6365686720275878, h[150,100] =
/// 1.1706400664901733.
#[test]
fn mountains_mnt_mask_marks_undefined_points() {
    let a = read::as_read(&data("mnt-2-crop.mnt"), &ReadOptions::default()).unwrap();
    assert_eq!((a.nx, a.ny), (256, 192));
    assert!(close(a.lx, 19.169328734278682e-6) && close(a.ly, 14.376996550709013e-6));
    assert_eq!(a.heights.iter().filter(|h| h.is_nan()).count(), 12795);
    assert_eq!(a.heights[..256].iter().filter(|h| h.is_nan()).count(), 132);
    for (ix, iy) in [(0, 0), (1, 0), (0, 1), (17, 5)] {
        assert!(a.heights[iy * 256 + ix].is_nan(), "({ix}, {iy})");
    }
    assert!(close(a.heights[149 * 256 + 199], 1.6365686720275878e-6));
    assert!(close(a.heights[100 * 256 + 150], 1.1706400664901733e-6));
    error_of(
        &data("mnt-2-crop.mnt"),
        &ReadOptions::default(),
        "12795 of 49152 points are undefined",
    );
    let o = ReadOptions {
        fill_undefined: true,
        ..Default::default()
    };
    assert!(read::read(&data("mnt-2-crop.mnt"), &o).is_ok());
}

#[test]
fn mountains_mnt_damaged() {
    truncations("mnt-1-crop.mnt", "Digital Surf Mountains .mnt");
    truncations("mnt-2-crop.mnt", "Digital Surf Mountains .mnt");
    let bytes = std::fs::read(data("mnt-1-crop.mnt")).unwrap();
    // The x axis's 200 points (tag 0001, 4 bytes) made 201.
    let tag = |n: u32| [&[1, 0, 4, 0, 0, 0, 0, 0, 0, 0][..], &n.to_le_bytes()].concat();
    let p = temp("points.mnt", &patched(&bytes, &tag(200), &tag(201)));
    error_of(
        &p,
        &ReadOptions::default(),
        "30000 values for a grid of 30150",
    );
    // A compound file without the document's stream.
    let name: Vec<u8> = "ScopedContents"
        .encode_utf16()
        .flat_map(u16::to_le_bytes)
        .collect();
    let p = temp("other.mnt", &patched(&bytes, &name, b"X\0"));
    error_of(&p, &ReadOptions::default(), "no ScopedContents stream");
    // Found by content without the extension.
    let t = read::read(&temp("mnt-noext", &bytes), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [150, 200]);
}

/// example_ps-crop.tiff (the first 64 of example_ps.tiff's 512 rows,
/// float32, the first row the bottom). SurfaceTopography: 'Z Height' (512,
/// 64) (1.0, 0.125) µm; h[0,0], h[1,0], h[0,1], h[511,63], h[17,5] =
/// -0.008307113950514883, -0.008882933189515623, -0.010195496216535415,
/// 0.0020836386214921217, -0.0015183140208269194; rms
/// (0.00378136912447852, 0.36791564096404245, 137.9813821219207).
#[test]
fn park_tiff_against_surface_topography() {
    let t = read::read(&data("example_ps-crop.tiff"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [64, 512]);
    assert_eq!((t.lx(), t.ly()), (1e-6, 0.125e-6));
    let st = [
        ((0, 0), -0.008307113950514883),
        ((1, 0), -0.008882933189515623),
        ((0, 1), -0.010195496216535415),
        ((511, 63), 0.0020836386214921217),
        ((17, 5), -0.0015183140208269194),
    ];
    agrees_with_st(
        &t,
        1e-6,
        &st,
        [0.00378136912447852, 0.36791564096404245, 137.9813821219207],
        ST_AGREEMENT,
    );
    assert!(read::read(&data("example_ps-crop.tiff"), &channel("z height")).is_ok());
    let e = error_of(
        &data("example_ps-crop.tiff"),
        &channel("Phase"),
        "no channel \"Phase\"",
    );
    assert!(e.contains("Z Height") && e.contains("Park Systems"), "{e}");
}

#[test]
fn park_tiff_damaged_and_plain_tiff() {
    truncations("example_ps-crop.tiff", "Park Systems .tiff");
    let bytes = std::fs::read(data("example_ps-crop.tiff")).unwrap();
    let magic = 0x0E03_1301u32.to_le_bytes();
    let p = temp("magic.tiff", &patched(&bytes, &magic, &[0, 0, 0, 0]));
    error_of(&p, &ReadOptions::default(), "not a Park Systems TIFF");
    // Found by content without the extension; a plain TIFF is not claimed.
    let t = read::read(&temp("ps-noext", &bytes), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [64, 512]);
    let plain = [&b"II*\0"[..], &8u32.to_le_bytes(), &[0; 6]].concat();
    error_of(
        &temp("plain-noext", &plain),
        &ReadOptions::default(),
        "unsupported format (TIFF)",
    );
    error_of(
        &temp("plain.tiff", &plain),
        &ReadOptions::default(),
        "no tag 50432 (magic)",
    );
}

/// The three mocks (copied whole). SurfaceTopography, heights at 0, 1, 98,
/// 99, 100, n − 1 (µm):
/// mitutoyo_mock (960,) (480.0,) µm: 0.303327568640866,
/// -0.0275075224656958, -0.0451376925971562, 0.0223931268719672,
/// 0.0999667878490665, -0.142267785307721; rms (0.1686429133658156,
/// 0.4805291294795566, 1.6685956906309312).
/// mitutoyo_2_mock (6664,) (9996.0,) µm: 5.9608, 5.8393, -1.2225, -1.0617,
/// -1.0941, 4.2704; rms (3.96889685184273, 0.15593245693171154,
/// 0.03822391466406157).
#[test]
fn mitutoyo_xlsx_against_surface_topography() {
    for (name, n, l, h, rms) in [
        (
            "mitutoyo_mock.xlsx",
            960,
            480.0,
            [
                0.303327568640866,
                -0.0275075224656958,
                -0.0451376925971562,
                0.0223931268719672,
                0.0999667878490665,
                -0.142267785307721,
            ],
            [0.1686429133658156, 0.4805291294795566, 1.6685956906309312],
        ),
        (
            "mitutoyo_2_mock.xlsx",
            6664,
            9996.0,
            [5.9608, 5.8393, -1.2225, -1.0617, -1.0941, 4.2704],
            [3.96889685184273, 0.15593245693171154, 0.03822391466406157],
        ),
    ] {
        let t = read::read(&data(name), &ReadOptions::default()).unwrap();
        assert_eq!(
            (t.layout(), t.shape()),
            (Layout::LineScans, [1, n]),
            "{name}"
        );
        assert!(close(t.lx(), l * 1e-6), "{name}: {}", t.lx());
        assert!(t.notes().is_empty(), "{name}");
        let points: Vec<(usize, f64)> = [0, 1, 98, 99, 100, n - 1].into_iter().zip(h).collect();
        profile_agrees_with_st(&t, &points, rms);
    }
}

/// mitutoyo_nonuniform_mock.xlsx: x of row 100 is 0.0501 mm (0.05 in
/// mitutoyo_mock). SurfaceTopography reads a NonuniformLineScan of 479.5
/// µm; its to_uniform(nb_points=960): (960,) (480.0,), heights at 0, 98,
/// 99, 100, 959 = 0.303327568640866, -0.0451376925971562,
/// 0.011137990293779834, 0.0999667878490665, -0.142267785307721; rms
/// (0.16864531772999042, 0.48053121040158975, 1.6685451961641424).
#[test]
fn mitutoyo_xlsx_nonuniform_is_resampled() {
    let t = read::read(
        &data("mitutoyo_nonuniform_mock.xlsx"),
        &ReadOptions::default(),
    )
    .unwrap();
    assert_eq!(t.shape(), [1, 960]);
    assert!(close(t.lx(), 480e-6));
    match t.notes() {
        [Note::Resampled {
            points: 960,
            max_deviation,
        }] => assert!((max_deviation - 0.2).abs() < 1e-9, "{max_deviation}"),
        other => panic!("{other:?}"),
    }
    let points = [
        (0, 0.303327568640866),
        (98, -0.0451376925971562),
        (99, 0.011137990293779834),
        (100, 0.0999667878490665),
        (959, -0.142267785307721),
    ];
    profile_agrees_with_st(
        &t,
        &points,
        [0.16864531772999042, 0.48053121040158975, 1.6685451961641424],
    );
}

#[test]
fn mitutoyo_xlsx_damaged_and_other_zips() {
    truncations("mitutoyo_mock.xlsx", "Mitutoyo SurfTest .xlsx");
    let e = error_of(
        &data("mitutoyo_mock.xlsx"),
        &channel("Phase"),
        "no channel \"Phase\"",
    );
    assert!(e.contains("Mitutoyo"), "{e}");
    // An .x3p zip is not claimed without the extension, and is an error
    // with it.
    let x3p = std::fs::read(data("ISO5436-sample4.x3p")).unwrap();
    let r = read::as_read(&temp("x3p-noext", &x3p), &ReadOptions::default());
    assert!(r.is_ok(), "{:?}", r.err());
    error_of(
        &temp("x3p.xlsx", &x3p),
        &ReadOptions::default(),
        "has no xl/workbook.xml",
    );
    // An xlsx without the extension is found by its workbook.
    let bytes = std::fs::read(data("mitutoyo_mock.xlsx")).unwrap();
    let t = read::read(&temp("xlsx-noext", &bytes), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [1, 960]);
    // A sheet renamed: an error naming the sheet wanted.
    let p = temp(
        "renamed.xlsx",
        &rezip(&bytes, "xl/workbook.xml", |s| {
            s.replace("\"DATA\"", "\"Data2\"")
        }),
    );
    error_of(&p, &ReadOptions::default(), "no sheet \"DATA\"");
    // A height cell that is text.
    let p = temp(
        "text.xlsx",
        &rezip(&bytes, "xl/worksheets/sheet2.xml", |s| {
            s.replacen(
                "<c r=\"F3\" s=\"2\"><v>0.178473688386333</v>",
                "<c r=\"F3\" s=\"2\" t=\"s\"><v>0</v>",
                1,
            )
        }),
    );
    error_of(&p, &ReadOptions::default(), "cell F3 holds the text");
}

/// The archive `bytes` with member `name` edited.
fn rezip(bytes: &[u8], name: &str, f: impl Fn(&str) -> String) -> Vec<u8> {
    use std::io::{Read, Write};
    let mut src = zip::ZipArchive::new(std::io::Cursor::new(bytes)).unwrap();
    let mut out = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for i in 0..src.len() {
        let mut m = src.by_index(i).unwrap();
        let mut content = Vec::new();
        m.read_to_end(&mut content).unwrap();
        let member = m.name().unwrap().to_string();
        if member == name {
            content = f(std::str::from_utf8(&content).unwrap()).into_bytes();
        }
        out.start_file(member, zip::write::SimpleFileOptions::default())
            .unwrap();
        out.write_all(&content).unwrap();
    }
    out.finish().unwrap().into_inner()
}

//! Molecular Imaging `.mi`, WSxM `.stp`/`.top`, Nanosurf `.nid`, NanoFocus
//! `.nms`, against SurfaceTopography 1.27.1 reading the same files.
//!
//! The files: `top-1.top` (SurfaceTopography's example, whole) and crops of
//! its other examples (`*-crop.*`: the first rows of each channel, the
//! header adjusted), both written by
//! tests/reference/mi_wsxm_nid_nms_surface_topography.py, whose output is
//! (grid, sizes, unit, heights h[ix, iy], rms height, gradient and
//! Laplacian after the plane, in SurfaceTopography's unit):
//!
//! ```text
//! mi-1-crop.mi ['Topography', 'Deflection', 'Friction', 'Friction'] None (256, 32) (20.0, 2.5) µm False
//! [-0.5134824371337892, -0.5139253234863281, -0.5141024780273438, -0.6289871978759767, -0.5179113006591798]
//! (0.003372817681056778, 0.012619946156977582, 0.2035808032635476)
//! stp-1-crop.stp ['Default'] None (256, 64) (600.0, 150.0) nm False
//! [-0.04690895753924451, -0.10457789586514821, 0.02704974331908261, 6.689150310036325, 0.15366871905509072]
//! (1.2973431647520604, 0.1286892093697035, 0.06022844907634286)
//! top-1.top ['Default'] None (256, 256) (600.0, 600.0) nm False
//! [115.5038336073998, 115.44560616649538, 115.44560616649538, 130.9729237410072, 119.59916361767729]
//! (1.613984767877795, 0.16498182276410805, 0.07545884123524589)
//! nid-1-crop.nid ['Scan forward (Z-Axis)', 'Scan forward (Z-AxisSensor)', 'Scan backward (Z-Axis)', 'Scan backward (Z-AxisSensor)'] None (256, 16) (2e-05, 1.25e-06) m False
//! [-1.1405894635543229e-06, -1.142546282954514e-06, -1.1435510147809982e-06, -1.982578380569816e-06, -1.2067312564775348e-06]
//! (1.154369674869137e-08, 0.08672141812403644, 769629.0957571634)
//! nid-1-crop.nid [same channels] 2 (256, 16) (2e-05, 1.25e-06) m False
//! [-1.1354742537215353e-06, -1.138576104529202e-06, -1.1372443978115917e-06, -1.9708049775213005e-06, -1.189330090150237e-06]
//! (1.172253755751801e-08, 0.039478185147274615, 394049.09538316284)
//! nms-1-crop.nms ['Default'] None (512, 64) (159999995.47489095, 19999999.43436137) µm False
//! [2.689124584197998, 2.693327243281454, 2.692517092132836, 5.034410890553669, 2.7754563159726087]
//! (0.0076087706665129914, 1.3721962800774036e-08, 7.971714749880169e-14)
//! nms-2-crop.nms ['Default'] None (512, 64) (159999995.47489095, 19999999.43436137) µm False
//! [6.9699957356423985, 6.972507289008443, 6.9687100595145415, 8.195035789375773, 7.01696776347641]
//! (0.014200773406428792, 1.3203572990523978e-08, 8.781576606625537e-14)
//! ```

use persson::topography::read::{self, ReadOptions};

use super::support::{agrees_with_st, close, data, error_of, temp, ST_AGREEMENT};

/// `bytes` with the first `from` replaced by `to`.
fn replaced(bytes: &[u8], from: &[u8], to: &[u8]) -> Vec<u8> {
    let k = bytes
        .windows(from.len())
        .position(|w| w == from)
        .expect("the text to replace");
    [&bytes[..k], to, &bytes[k + from.len()..]].concat()
}

fn channel(name: &str) -> ReadOptions {
    ReadOptions {
        channel: Some(name.to_string()),
        ..Default::default()
    }
}

/// The same file without its extension's help: found by its content.
fn sniffed(name: &str) {
    let bytes = std::fs::read(data(name)).unwrap();
    let by_name = read::read(&data(name), &ReadOptions::default()).unwrap();
    let by_content = read::read(
        &temp(&format!("{name}.dat"), &bytes),
        &ReadOptions::default(),
    )
    .unwrap();
    assert_eq!(by_content, by_name, "{name}");
}

/// `.mi` (BINARY_32, 4 buffers of 256 × 32): the topography buffer (µm),
/// rows last first; the size from xLength/yLength (m).
#[test]
fn molecular_imaging_mi() {
    let path = data("mi-1-crop.mi");
    let t = read::read(&path, &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [32, 256]);
    assert!(
        close(t.lx(), 20e-6) && close(t.ly(), 2.5e-6),
        "{} × {}",
        t.lx(),
        t.ly()
    );
    agrees_with_st(
        &t,
        1e-6,
        &[
            ((0, 0), -0.5134824371337892),
            ((1, 0), -0.5139253234863281),
            ((0, 1), -0.5141024780273438),
            ((255, 31), -0.6289871978759767),
            ((17, 5), -0.5179113006591798),
        ],
        [
            0.003372817681056778,
            0.012619946156977582,
            0.2035808032635476,
        ],
        ST_AGREEMENT,
    );
    // The topography by name and by index is the default.
    for c in ["topography", "0"] {
        assert_eq!(read::read(&path, &channel(c)).unwrap(), t);
    }
    sniffed("mi-1-crop.mi");
    // Other channels are in V: not heights.
    let e = error_of(&path, &channel("Deflection"), "not a unit of length");
    assert!(
        e.contains("\"V\"") && e.contains("Molecular Imaging"),
        "{e}"
    );
    error_of(
        &path,
        &channel("Friction (Retrace)"),
        "not a unit of length",
    );
    let e = error_of(&path, &channel("Friction"), "no channel \"Friction\"");
    assert!(e.contains("2: \"Friction (Trace)\""), "{e}");
    // Damaged copies.
    let bytes = std::fs::read(&path).unwrap();
    let start = bytes.windows(10).position(|w| w == b"\ndata     ").unwrap() + 25;
    for cut in [100, 3000, start + 1000, start + 256 * 32 * 4 - 1] {
        error_of(
            &temp("cut.mi", &bytes[..cut]),
            &ReadOptions::default(),
            "truncated",
        );
    }
    let spectro = replaced(
        &bytes,
        b"fileType      Image",
        b"fileType      Spectroscopy",
    );
    error_of(
        &temp("spectro.mi", &spectro),
        &ReadOptions::default(),
        "fileType",
    );
    let ascii = replaced(&bytes, b"BINARY_32", b"ASCII");
    error_of(
        &temp("ascii.mi", &ascii),
        &ReadOptions::default(),
        "only binary",
    );
    let nx = replaced(&bytes, b"xPixels       256", b"xPixels       2x6");
    error_of(&temp("nx.mi", &nx), &ReadOptions::default(), "xPixels");
    let unit = replaced(&bytes, b"bufferUnit    um", b"bufferUnit    uV");
    error_of(
        &temp("unit.mi", &unit),
        &ReadOptions::default(),
        "no height channel",
    );
}

/// WSxM `.stp` (double, nm) and `.top` (int16 scaled by Z Amplitude over
/// Maximum − Minimum): the map rotated by 180°.
#[test]
fn wsxm_stp_and_top() {
    let t = read::read(&data("stp-1-crop.stp"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [64, 256]);
    assert!(close(t.lx(), 600e-9) && close(t.ly(), 150e-9));
    agrees_with_st(
        &t,
        1e-9,
        &[
            ((0, 0), -0.04690895753924451),
            ((1, 0), -0.10457789586514821),
            ((0, 1), 0.02704974331908261),
            ((255, 63), 6.689150310036325),
            ((17, 5), 0.15366871905509072),
        ],
        [1.2973431647520604, 0.1286892093697035, 0.06022844907634286],
        ST_AGREEMENT,
    );
    let t = read::read(&data("top-1.top"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [256, 256]);
    assert!(close(t.lx(), 600e-9) && close(t.ly(), 600e-9));
    agrees_with_st(
        &t,
        1e-9,
        &[
            ((0, 0), 115.5038336073998),
            ((1, 0), 115.44560616649538),
            ((0, 1), 115.44560616649538),
            ((255, 255), 130.9729237410072),
            ((17, 123), 119.59916361767729),
        ],
        [1.613984767877795, 0.16498182276410805, 0.07545884123524589],
        ST_AGREEMENT,
    );
    sniffed("stp-1-crop.stp");
    sniffed("top-1.top");
    // Damaged copies.
    let bytes = std::fs::read(data("stp-1-crop.stp")).unwrap();
    for cut in [30, 100, 4606 + 1000, bytes.len() - 1] {
        error_of(
            &temp("cut.stp", &bytes[..cut]),
            &ReadOptions::default(),
            "WSxM",
        );
    }
    error_of(
        &temp("cut.stp", &bytes[..4000]),
        &ReadOptions::default(),
        "truncated",
    );
    error_of(
        &temp("cut.stp", &bytes[..5000]),
        &ReadOptions::default(),
        "truncated",
    );
    let kind = replaced(
        &bytes,
        b"Image Data Type: double",
        b"Image Data Type: doubly",
    );
    error_of(
        &temp("kind.stp", &kind),
        &ReadOptions::default(),
        "\"doubly\"",
    );
    let z = replaced(
        &bytes,
        b"Z Amplitude: 13.7008 nm",
        b"Z Amplitude: 13.7008 nA",
    );
    error_of(
        &temp("z.stp", &z),
        &ReadOptions::default(),
        "not a unit of length",
    );
    let top = std::fs::read(data("top-1.top")).unwrap();
    let flat = replaced(&top, b"Maximum: 6900", b"Maximum: 5900");
    error_of(
        &temp("flat.top", &flat),
        &ReadOptions::default(),
        "not above Minimum",
    );
    let end = replaced(&top, b"[Header end]", b"[Header und]");
    error_of(
        &temp("end.top", &end),
        &ReadOptions::default(),
        "[Header end]",
    );
}

/// Nanosurf `.nid` (8 data blocks of 256 × 16 int32; 4 in m): the first
/// length channel, another by name; rows last first.
#[test]
fn nanosurf_nid() {
    let path = data("nid-1-crop.nid");
    let t = read::read(&path, &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [16, 256]);
    assert!(close(t.lx(), 2e-5) && close(t.ly(), 1.25e-6));
    agrees_with_st(
        &t,
        1.0,
        &[
            ((0, 0), -1.1405894635543229e-06),
            ((1, 0), -1.142546282954514e-06),
            ((0, 1), -1.1435510147809982e-06),
            ((255, 15), -1.982578380569816e-06),
            ((17, 5), -1.2067312564775348e-06),
        ],
        [
            1.154369674869137e-08,
            0.08672141812403644,
            769629.0957571634,
        ],
        ST_AGREEMENT,
    );
    assert_eq!(
        read::read(&path, &channel("Scan forward (Z-Axis)")).unwrap(),
        t
    );
    // SurfaceTopography's channel 2 (of the length channels only).
    let b = read::read(&path, &channel("scan backward (z-axis)")).unwrap();
    agrees_with_st(
        &b,
        1.0,
        &[
            ((0, 0), -1.1354742537215353e-06),
            ((1, 0), -1.138576104529202e-06),
            ((0, 1), -1.1372443978115917e-06),
            ((255, 15), -1.9708049775213005e-06),
            ((17, 5), -1.189330090150237e-06),
        ],
        [
            1.172253755751801e-08,
            0.039478185147274615,
            394049.09538316284,
        ],
        ST_AGREEMENT,
    );
    sniffed("nid-1-crop.nid");
    let e = error_of(
        &path,
        &channel("Scan forward (Deflection)"),
        "not a unit of length",
    );
    assert!(e.contains("\"N\"") && e.contains("Nanosurf"), "{e}");
    let e = error_of(&path, &channel("Phase"), "no channel \"Phase\"");
    assert!(e.contains("1: \"Scan forward (Z-Axis)\""), "{e}");
    // Damaged copies.
    let bytes = std::fs::read(&path).unwrap();
    let start = bytes.windows(4).position(|w| w == b"\r\n#!").unwrap() + 4;
    for cut in [15, 20000, start + 10000, start + 2 * 256 * 16 * 4 - 1] {
        error_of(
            &temp("cut.nid", &bytes[..cut]),
            &ReadOptions::default(),
            "truncated",
        );
    }
    let bits = replaced(&bytes, b"SaveBits=32", b"SaveBits=24");
    error_of(
        &temp("bits.nid", &bits),
        &ReadOptions::default(),
        "SaveBits = 24",
    );
    let mode = replaced(&bytes, b"SaveMode=Binary", b"SaveMode=Text");
    error_of(
        &temp("mode.nid", &mode),
        &ReadOptions::default(),
        "SaveMode",
    );
    let lines = replaced(&bytes, b"Lines=16", b"Lines=1x");
    error_of(&temp("lines.nid", &lines), &ReadOptions::default(), "Lines");
}

/// NanoFocus `.nms`: Δx in nm (SurfaceTopography 1.27 reads mm, a 160 m
/// scan), heights over 65535 steps of the header's z range (there: 65534).
/// Everything else agrees: heights converted, sizes 10⁻⁶ of its, the ratio
/// of the sizes, the rms values scaled accordingly.
#[test]
fn nanofocus_nms() {
    const STEPS: f64 = 65534.0 / 65535.0;
    let cases = [
        (
            "nms-1-crop.nms",
            2.689124584197998,
            [
                2.689124584197998,
                2.693327243281454,
                2.692517092132836,
                5.034410890553669,
                2.7754563159726087,
            ],
            [
                0.0076087706665129914,
                1.3721962800774036e-08,
                7.971714749880169e-14,
            ],
        ),
        (
            "nms-2-crop.nms",
            6.320938587188721,
            [
                6.9699957356423985,
                6.972507289008443,
                6.9687100595145415,
                8.195035789375773,
                7.01696776347641,
            ],
            [
                0.014200773406428792,
                1.3203572990523978e-08,
                8.781576606625537e-14,
            ],
        ),
    ];
    for (name, z_low, st_heights, [height, gradient, laplacian]) in cases {
        let t = read::read(&data(name), &ReadOptions::default()).unwrap();
        assert_eq!(t.shape(), [64, 512]);
        // SurfaceTopography: 159999995.47489095 × 19999999.43436137 µm.
        assert!(close(t.lx(), 159999995.47489095e-12), "{}", t.lx());
        assert!(close(t.ly(), 19999999.43436137e-12), "{}", t.ly());
        assert!(close(
            t.lx() / t.ly(),
            159999995.47489095 / 19999999.43436137
        ));
        let nx = 512;
        for ((ix, iy), st) in [(0, 0), (1, 0), (0, 1), (511, 63), (17, 5)]
            .into_iter()
            .zip(st_heights)
        {
            let ours = t.heights()[iy * nx + ix];
            let want = (z_low + (st - z_low) * STEPS) * 1e-6;
            assert!(
                (ours / want - 1.0).abs() < 1e-13,
                "{name} ({ix}, {iy}): {ours} against {want}"
            );
        }
        // The plane-detrended map is SurfaceTopography's × 65534/65535,
        // on a grid 10⁻⁶ of its.
        let s =
            persson::topography::real_space_stats(&t, persson::topography::Detrend::Plane).unwrap();
        for (got, want) in [
            (s.rms_height, height * STEPS * 1e-6),
            (s.rms_slope, gradient * STEPS * 1e6),
            (s.rms_curvature.unwrap(), laplacian * STEPS * 1e18),
        ] {
            assert!(
                (got / want - 1.0).abs() < ST_AGREEMENT,
                "{name}: {got} against {want}"
            );
        }
        sniffed(name);
    }
    // A point of zero intensity is undefined.
    let bytes = std::fs::read(data("nms-1-crop.nms")).unwrap();
    let mut dark = bytes.clone();
    let (ix, iy) = (3, 2);
    dark[3468 + 2 * 512 * 64 + iy * 512 + ix] = 0;
    let dark = temp("dark.nms", &dark);
    error_of(
        &dark,
        &ReadOptions::default(),
        "1 of 32768 points are undefined",
    );
    let raw = read::as_read(&dark, &ReadOptions::default()).unwrap();
    assert!(raw.heights[iy * 512 + ix].is_nan());
    assert_eq!(raw.heights.iter().filter(|h| h.is_nan()).count(), 1);
    // Damaged copies.
    for cut in [20, 1370, 2000, 3468 + 100, bytes.len() - 1] {
        error_of(
            &temp("cut.nms", &bytes[..cut]),
            &ReadOptions::default(),
            "truncated",
        );
    }
    let mut kind = bytes.clone();
    kind[0] = 3;
    error_of(
        &temp("kind.nms", &kind),
        &ReadOptions::default(),
        "data type 3",
    );
    let version = replaced(&bytes, b"OM_MS_2.0", b"OM_MS_1.0");
    error_of(
        &temp("version.nms", &version),
        &ReadOptions::default(),
        "OM_MS_2.0",
    );
    let mut dx = bytes.clone();
    dx[1376..1384].copy_from_slice(&(-1.0f64).to_le_bytes());
    error_of(&temp("dx.nms", &dx), &ReadOptions::default(), "Δx = -1");
}

/// Counts and repeated labels are read in time linear in the header, and
/// an error lists at most 20 channels.
#[test]
fn huge_counts_and_many_channels() {
    // A group count far beyond the channels there are: only the
    // `Gr<i>-Ch<j>` keys present are walked.
    let p = temp(
        "nid-count.nid",
        b"[DataSet]\r\nGroupCount=1\r\nGr0-Count=18446744073709551615\r\n#!",
    );
    error_of(&p, &ReadOptions::default(), "Nanosurf .nid");
    error_of(&p, &ReadOptions::default(), "no data channel");

    // 60 000 buffers of one label: named at once, the error cut short.
    let mut mi = b"fileType      Image\nxPixels       2\nyPixels       2\n\
                   xLength       1e-6\nyLength       1e-6\n"
        .to_vec();
    for _ in 0..60_000 {
        mi.extend_from_slice(b"bufferLabel   a\nbufferUnit    V\n");
    }
    mi.extend_from_slice(b"data          BINARY\n");
    let p = temp("many.mi", &mi);
    let e = error_of(&p, &ReadOptions::default(), "… and 59980 more");
    assert!(e.contains("Molecular Imaging .mi"), "{e}");
    assert!(e.contains("19: \"a\"") && !e.contains("20: \"a\""), "{e}");
    assert!(e.len() < 2000, "{} bytes", e.len());

    // .nms: nx × ny fits in a usize, the 2 bytes of each height do not.
    let mut nms = std::fs::read(data("nms-1-crop.nms")).unwrap();
    nms[1368..1372].copy_from_slice(&4294836226u32.to_le_bytes());
    nms[1372..1376].copy_from_slice(&2147549185u32.to_le_bytes());
    nms[1416..1420].copy_from_slice(&0i32.to_le_bytes());
    let p = temp("wrap.nms", &nms);
    let e = error_of(&p, &ReadOptions::default(), "too large");
    assert!(e.contains("NanoFocus .nms"), "{e}");
    // With the intensity image: past the end, not wrapped around.
    nms[1368..1372].copy_from_slice(&65536u32.to_le_bytes());
    nms[1372..1376].copy_from_slice(&65536u32.to_le_bytes());
    nms[1416..1420].copy_from_slice(&1i32.to_le_bytes());
    error_of(&temp("big.nms", &nms), &ReadOptions::default(), "truncated");
}

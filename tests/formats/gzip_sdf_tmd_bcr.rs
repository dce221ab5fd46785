//! gzip-compressed text, ISO 25178-71 `.sdf`, TrueMap `.tmd`, BCR-STM `.bcrf`.

use persson::topography::read::{self, ReadOptions, SizeSpec};

use super::support::{agrees_with_st, close, data, error_of, temp, ST_AGREEMENT};

/// Heights near 5·10⁴ nm with an rms of 9 nm after the plane: the plane fit
/// cancels 3.7 digits, so the detrended values carry ~1e-12 of rounding and
/// the curvature more (as `ST_LARGE_OFFSET` of tests/instrument_files.rs).
const LARGE_OFFSET: f64 = 1e-9;

/// matrix-4.txt.gz (SurfaceTopography's example of a gzip-compressed
/// export; its content is matrix-4.txt byte for byte, whose reading agrees
/// with SurfaceTopography's above) reads to the same map, value for value;
/// a gzip of another format by the name inside; a truncated stream is an
/// error naming the file.
#[test]
fn gzip_compressed_text_reads_as_its_content() {
    let plain = read::read(&data("matrix-4.txt"), &ReadOptions::default()).unwrap();
    let gz = read::read(&data("matrix-4.txt.gz"), &ReadOptions::default()).unwrap();
    assert_eq!(gz.shape(), plain.shape());
    assert_eq!((gz.lx(), gz.ly()), (plain.lx(), plain.ly()));
    assert_eq!(gz.heights(), plain.heights());
    // A .npy inside (found by its inner name and its magic).
    let npy = persson::io::npy::encode(2, 3, &[0.0, 1.0, 2.0, 1.0, 3.0, 5.0]).unwrap();
    let mut packed = Vec::new();
    {
        use std::io::Write;
        let mut e = flate2::write::GzEncoder::new(&mut packed, flate2::Compression::default());
        e.write_all(&npy).unwrap();
        e.finish().unwrap();
    }
    let o = ReadOptions {
        size: Some(SizeSpec::PixelSize(1e-6)),
        ..Default::default()
    };
    let t = read::read(&temp("map.npy.gz", &packed), &o).unwrap();
    assert_eq!(t.shape(), [2, 3]);
    assert_eq!(t.heights(), &[0.0, 1.0, 2.0, 1.0, 3.0, 5.0]);
    // Truncated: an error naming the file, not a panic.
    let bytes = std::fs::read(data("matrix-4.txt.gz")).unwrap();
    let cut = temp("cut.txt.gz", &bytes[..bytes.len() / 2]);
    error_of(&cut, &ReadOptions::default(), "gzip");
}

/// ISO 25178-71 `.sdf`: `sdf-1.sdf` (the standard's ASCII example, from
/// SurfaceTopography's test files) and `sdf-2-binary.sdf` (binary, int32,
/// one undefined point; written by tests/reference/sdf_surface_topography.py)
/// against SurfaceTopography 1.27.1 reading the same files (that script's
/// output: heights in µm, row by row).
#[test]
fn iso_25178_71_sdf_ascii_and_binary() {
    use persson::topography::{real_space_stats, Detrend};
    const ST_SDF1: [f64; 28] = [
        1.0, 0.99874, 0.99495, 0.98865, 0.97986, 0.96858, 1.0, 0.99874, 0.99748, 0.99369, 0.9874,
        0.97862, 0.96736, 0.99874, 0.99495, 0.99369, 0.98993, 0.98366, 0.97491, 0.96369, 0.99495,
        0.97986, 0.97862, 0.97491, 0.96874, 0.96012, 0.94907, 0.97986,
    ];
    let t = read::read(&data("sdf-1.sdf"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [4, 7]);
    assert_eq!((t.lx(), t.ly()), (7e-6, 4e-6));
    for (h, s) in t.heights().iter().zip(ST_SDF1) {
        assert!(close(*h, s * 1e-6), "{h} against {s} µm");
    }
    // SurfaceTopography's rms height, gradient and Laplacian (µm, 1, 1/µm)
    // after the plane: 0.010289929442289474, 0.015798188137048624,
    // 0.01859834105505109.
    let s = real_space_stats(&t, Detrend::Plane).unwrap();
    for (got, want) in [
        (s.rms_height, 0.010289929442289474e-6),
        (s.rms_slope, 0.015798188137048624),
        (s.rms_curvature.unwrap(), 0.01859834105505109e6),
    ] {
        assert!(
            (got / want - 1.0).abs() < ST_AGREEMENT,
            "{got} against {want}"
        );
    }
    // Binary, int32 × 1e-9 m, 5 points × 3 profiles, Δ = 2 µm × 3 µm.
    const ST_SDF2: [f64; 15] = [
        0.01,
        0.02,
        0.035,
        0.02,
        0.01,
        0.015,
        f64::NAN,
        0.04,
        0.025,
        0.012,
        0.005,
        0.008,
        0.03,
        0.018000000000000002,
        0.007,
    ];
    let path = data("sdf-2-binary.sdf");
    error_of(
        &path,
        &ReadOptions::default(),
        "1 of 15 points are undefined",
    );
    let raw = read::as_read(&path, &ReadOptions::default()).unwrap();
    assert_eq!((raw.nx, raw.ny), (5, 3));
    // 5·(2e-6) rounds to 9.999999999999999e-6 (SurfaceTopography: 5·2.0 µm).
    assert!(
        close(raw.lx, 10e-6) && close(raw.ly, 9e-6),
        "{} × {}",
        raw.lx,
        raw.ly
    );
    for (h, s) in raw.heights.iter().zip(ST_SDF2) {
        assert!(
            (h.is_nan() && s.is_nan()) || close(*h, s * 1e-6),
            "{h} against {s} µm"
        );
    }
    // Damaged copies: an error naming the file, never a panic.
    let bytes = std::fs::read(&path).unwrap();
    error_of(
        &temp("cut.sdf", &bytes[..100]),
        &ReadOptions::default(),
        "truncated",
    );
    let mut compressed = bytes.clone();
    compressed[78] = 1;
    error_of(
        &temp("packed.sdf", &compressed),
        &ReadOptions::default(),
        "Compression = 1",
    );
    let ascii = std::fs::read_to_string(data("sdf-1.sdf")).unwrap();
    let short = ascii.replacen("NumPoints = 7", "NumPoints = 8", 1);
    error_of(
        &temp("short.sdf", short.as_bytes()),
        &ReadOptions::default(),
        "28 values",
    );
}

/// TrueMap `.tmd` (tmd-1.tmd, SurfaceTopography's example) against
/// SurfaceTopography 1.27.1 reading it: 300 × 300 points of 18.9566 mm,
/// heights in mm (h[ix, iy] there), and its rms height, gradient and
/// Laplacian after the plane (mm, 1, 1/mm).
#[test]
fn truemap_tmd() {
    let t = read::read(&data("tmd-1.tmd"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [300, 300]);
    assert!(close(t.lx(), 18.956600189208984e-3) && close(t.ly(), 18.956600189208984e-3));
    agrees_with_st(
        &t,
        1e-3,
        &[
            ((0, 0), 0.22351792454719543),
            ((1, 0), 0.2231409251689911),
            ((0, 1), 0.22296857833862305),
            ((299, 299), 0.23054088652133942),
            ((17, 123), 0.2641262114048004),
        ],
        [0.07434087951791002, 0.1582928308184987, 2.4424994287882655],
        ST_AGREEMENT,
    );
    let bytes = std::fs::read(data("tmd-1.tmd")).unwrap();
    error_of(
        &temp("cut.tmd", &bytes[..1000]),
        &ReadOptions::default(),
        "truncated",
    );
    error_of(
        &temp("nocomment.tmd", &bytes[..40]),
        &ReadOptions::default(),
        "truncated",
    );
}

/// BCRF (UTF-16 header, float32 values, nm and µm): `bcrf-1-crop.bcrf`,
/// the first 8 rows of SurfaceTopography's 2.3 MB example (cut by
/// tests/reference/bcrf_surface_topography.py), against SurfaceTopography
/// 1.27.1 reading the cut file: 960 × 8 points of 1777404 nm × 14811.7067 nm,
/// heights h[ix, iy] in nm, and its rms height, gradient and Laplacian after
/// the plane (nm, 1, 1/nm).
#[test]
fn bcrf_unicode() {
    let t = read::read(&data("bcrf-1-crop.bcrf"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [8, 960]);
    assert!(close(t.lx(), 1777404e-9) && close(t.ly(), 14811.7067e-9));
    // The plane removed from heights near 50.6 µm with a 9.4 nm rms: the
    // fit cancels 3.7 digits (the case of ST_LARGE_OFFSET).
    agrees_with_st(
        &t,
        1e-9,
        &[
            ((0, 0), 50628.37219238281),
            ((1, 0), 50628.06701660156),
            ((0, 1), 50628.61633300781),
            ((959, 7), 50619.73190307617),
            ((17, 5), 50626.50680541992),
        ],
        [
            9.40584001220252,
            0.008078266868992857,
            8.959636020703598e-06,
        ],
        LARGE_OFFSET,
    );
    let bytes = std::fs::read(data("bcrf-1-crop.bcrf")).unwrap();
    error_of(
        &temp("cut.bcrf", &bytes[..5000]),
        &ReadOptions::default(),
        "truncated",
    );
    error_of(
        &temp("head.bcrf", &bytes[..300]),
        &ReadOptions::default(),
        "BCR",
    );
}

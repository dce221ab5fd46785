//! FRT MicroProf `.frt`, Wyko `.opd`, Bruker Dektak `.opdx`.
//!
//! The reference numbers are SurfaceTopography 1.27.1's reading of the same
//! files, printed by tests/reference/frt_opd_opdx_surface_topography.py
//! (which also cut `frt-1-crop.frt` and `opd-1-crop.opd`); its output:
//!
//! ```text
//! 1.27.1
//! ['default']
//! frt-1-crop.frt (300, 40) (0.0072, 0.0009599999999999999) m
//!   h: [((0, 0), 7.758049256874295e-05), ((1, 0), 7.760979033783991e-05), ((0, 1), 7.76000244148076e-05), ((299, 39), 8.1897030549028e-05), ((17, 23), 7.810785241248819e-05)]
//!   rms: (1.109614765895687e-07, 0.001724982527704423, 160.75052508719799)
//!   version 1.01 copy reads the same heights: True
//! frt-2.frt (150, 300) (0.03, 0.06) m
//!   h: [((100, 0), None), ((149, 299), 7.544175542466507e-05), ((0, 299), 7.377178258613851e-05), ((75, 150), 7.256080813013094e-05), ((3, 280), 7.358623004852444e-05), ((60, 200), 7.324442274239328e-05)]
//!   undefined: 12314 first (ix, iy): [(0, 0), (0, 1), (0, 2)]
//!   mean of the defined heights: 7.262714207028706e-05
//! ['Raw']
//! opd-1-crop.opd (640, 32) (0.1259091403335333, 0.006295457016676664) mm
//!   h: [((0, 0), -0.00028629880478093036), ((1, 0), -0.00028328646280572506), ((0, 1), -0.0002850692514614566), ((639, 31), -0.0002765728498041335), ((17, 23), -0.0002799118236010472)]
//!   rms: (6.396713381030186e-06, 0.0180217347226358, 130.22814726778483)
//! ['Height']
//! opdx-3.opdx (3001,) (49.983344425752584,) µm
//!   h: [((0,), 0.0013718305790923332), ((1,), 0.0013122407677853129), ((3000,), 0.014412930733025379), ((1234,), -0.0009882868813896838)]
//!   rms: (0.0028257223325313533, 0.0165977656556357, 1.5038815633959663)
//! ['Height']
//! opdx-map-synthetic.opdx (5, 4) (10.0, 4.0) µm
//!   h: [((0, 0), 0.0), ((1, 0), 0.0011250000000000001), ((0, 1), 0.002625), ((4, 3), 0.0018000000715255738), ((2, 1), 0.0010499999821186065)]
//!   rms: (0.0011623185417523967, 0.0021955996552730688, 0.004210060499971126)
//! ```

use std::path::Path;

use persson::topography::read::{self, LengthUnit, ReadOptions};
use persson::topography::{analyse, AnalysisOptions, Layout};

use super::support::{agrees_with_st, close, data, error_of, temp, ST_AGREEMENT};

fn channel(name: &str) -> ReadOptions {
    ReadOptions {
        channel: Some(name.into()),
        ..Default::default()
    }
}

/// Copies of `bytes` cut at several lengths: each an error naming the file
/// and `format`, never a panic.
fn truncated_copies_fail(bytes: &[u8], name: &str, format: &str) {
    let n = bytes.len();
    for cut in [
        0,
        5,
        13,
        17,
        20,
        30,
        64,
        200,
        1000,
        n / 3,
        n / 2,
        n - 100,
        n - 1,
    ] {
        let p = temp(&format!("cut-{cut}-{name}"), &bytes[..cut.min(n - 1)]);
        error_of(&p, &ReadOptions::default(), format);
    }
}

/// The FRT crop with 64-bit block sizes (version 1.01).
fn frt_as_version_101(b: &[u8]) -> Vec<u8> {
    let mut out = b[..18].to_vec();
    out[12..16].copy_from_slice(b"1.01");
    let count = u16::from_le_bytes([b[16], b[17]]);
    let mut at = 18;
    for _ in 0..count {
        let size = u32::from_le_bytes(b[at + 2..at + 6].try_into().unwrap()) as usize;
        out.extend_from_slice(&b[at..at + 2]);
        out.extend_from_slice(&(size as u64).to_le_bytes());
        out.extend_from_slice(&b[at + 6..at + 6 + size]);
        at += 6 + size;
    }
    assert_eq!(at, b.len());
    out
}

/// `frt-1-crop.frt` (SurfaceTopography's frt-1.frt cut to 300 × 40 points
/// without undefined ones) against SurfaceTopography: sizes, heights
/// h[ix, iy] (the file's last stored row first), rms values; the channels of
/// the multi-image block; the same file with 64-bit block sizes.
#[test]
fn frt_microprof_agrees_with_surface_topography() {
    let path = data("frt-1-crop.frt");
    let t = read::read(&path, &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [40, 300]);
    assert!(close(t.lx(), 0.0072) && close(t.ly(), 0.0009599999999999999));
    agrees_with_st(
        &t,
        1.0,
        &[
            ((0, 0), 7.758049256874295e-05),
            ((1, 0), 7.760979033783991e-05),
            ((0, 1), 7.76000244148076e-05),
            ((299, 39), 8.1897030549028e-05),
            ((17, 23), 7.810785241248819e-05),
        ],
        [
            1.109614765895687e-07,
            0.001724982527704423,
            160.75052508719799,
        ],
        ST_AGREEMENT,
    );
    // The topography image of block 0x007d is that of block 0x000b.
    let again = read::read(&path, &channel("Topography (top sensor) 1")).unwrap();
    assert_eq!(again.heights(), t.heights());
    assert_eq!(
        read::read(&path, &channel("1")).unwrap().heights(),
        t.heights()
    );
    // The intensity: raw counts, no unit; the caller must give one.
    error_of(&path, &channel("intensity (top sensor) 1"), "height unit");
    let counts = ReadOptions {
        height_unit: Some(LengthUnit::Metre),
        ..channel("Intensity (top sensor) 1")
    };
    let i = read::read(&path, &counts).unwrap();
    assert!(i.heights().iter().all(|v| v.fract() == 0.0 && *v > 1.0));
    let e = error_of(&path, &channel("Phase"), "no channel \"Phase\"");
    assert!(
        e.contains("FRT") && e.contains("2: \"Intensity (top sensor) 1\""),
        "{e}"
    );
    // Version 1.01: u64 block sizes (SurfaceTopography reads the same).
    let bytes = std::fs::read(&path).unwrap();
    let wide = read::read(
        &temp("wide.frt", &frt_as_version_101(&bytes)),
        &ReadOptions::default(),
    )
    .unwrap();
    assert_eq!(wide.heights(), t.heights());
    // Found by its magic without the extension.
    let o = read::from_bytes(Path::new("scan"), &bytes, &ReadOptions::default()).unwrap();
    assert_eq!(o.heights(), t.heights());
}

/// `frt-2.frt` (whole): 12314 undefined points (value 1) where
/// SurfaceTopography masks them, the same heights elsewhere and the same
/// mean of the defined heights.
#[test]
fn frt_microprof_undefined_points() {
    let path = data("frt-2.frt");
    error_of(
        &path,
        &ReadOptions::default(),
        "12314 of 45000 points are undefined",
    );
    let r = read::as_read(&path, &ReadOptions::default()).unwrap();
    assert_eq!((r.nx, r.ny), (150, 300));
    assert_eq!((r.lx, r.ly), (0.03, 0.06));
    let h = |ix: usize, iy: usize| r.heights[iy * r.nx + ix];
    for (ix, iy) in [(100, 0), (0, 0), (0, 1), (0, 2)] {
        assert!(h(ix, iy).is_nan(), "({ix}, {iy})");
    }
    for ((ix, iy), st) in [
        ((149, 299), 7.544175542466507e-05),
        ((0, 299), 7.377178258613851e-05),
        ((75, 150), 7.256080813013094e-05),
        ((3, 280), 7.358623004852444e-05),
        ((60, 200), 7.324442274239328e-05),
    ] {
        assert!(close(h(ix, iy), st), "({ix}, {iy}): {}", h(ix, iy));
    }
    let defined: Vec<f64> = r.heights.iter().copied().filter(|v| !v.is_nan()).collect();
    assert_eq!(r.heights.len() - defined.len(), 12314);
    let mean = defined.iter().sum::<f64>() / defined.len() as f64;
    assert!((mean / 7.262714207028706e-05 - 1.0).abs() < 1e-12, "{mean}");
    // Filled on request.
    let o = ReadOptions {
        fill_undefined: true,
        ..Default::default()
    };
    assert!(read::read(&path, &o)
        .unwrap()
        .heights()
        .iter()
        .all(|v| v.is_finite()));
}

/// The start and size of each block of an FRT file (version 1.00), by tag.
fn frt_blocks(b: &[u8]) -> Vec<(u16, usize, usize)> {
    let count = u16::from_le_bytes([b[16], b[17]]);
    let mut at = 18;
    let mut out = Vec::new();
    for _ in 0..count {
        let tag = u16::from_le_bytes([b[at], b[at + 1]]);
        let size = u32::from_le_bytes(b[at + 2..at + 6].try_into().unwrap()) as usize;
        out.push((tag, at + 6, size));
        at += 6 + size;
    }
    out
}

/// Values outside the file's range of valid values (block 0x0070, [5,
/// 65529] here) are undefined, as the value 1 is: the row of zeros that ends
/// `frt-1.frt` is not a row of heights at 0 m. With the range widened to
/// hold 0, the same value reads as 0 m; the intensity channel is not a
/// height and keeps its counts.
#[test]
fn frt_microprof_values_outside_the_valid_range_are_undefined() {
    let bytes = std::fs::read(data("frt-1-crop.frt")).unwrap();
    let blocks = frt_blocks(&bytes);
    let find = |tag: u16| blocks.iter().find(|b| b.0 == tag).copied().unwrap();
    let (_, valid, _) = find(0x0070);
    assert_eq!(&bytes[valid..valid + 8], [5, 0, 0, 0, 0xf9, 0xff, 0, 0]);
    // The first stored value (the last row here, x = 0) set to 0, 3 and 65530.
    let (_, topography, _) = find(0x000b);
    let with = |raw: u16, range: Option<[u8; 8]>| {
        let mut b = bytes.clone();
        b[topography..topography + 2].copy_from_slice(&raw.to_le_bytes());
        if let Some(r) = range {
            b[valid..valid + 8].copy_from_slice(&r);
        }
        let p = temp(&format!("valid-{raw}-{}.frt", range.is_some()), &b);
        read::as_read(&p, &ReadOptions::default()).unwrap()
    };
    let last_row_first = |r: &read::AsRead| r.heights[(r.ny - 1) * r.nx];
    for raw in [0, 3, 65530] {
        let r = with(raw, None);
        assert!(last_row_first(&r).is_nan(), "{raw}");
        assert_eq!(r.heights.iter().filter(|v| v.is_nan()).count(), 1);
    }
    let wide = [0, 0, 0, 0, 0xff, 0xff, 0, 0];
    assert_eq!(last_row_first(&with(0, Some(wide))), 0.0);
    // The value 1 stays undefined whatever the range.
    assert!(last_row_first(&with(1, Some(wide))).is_nan());
    // A damaged range block is an error naming it.
    let mut short = bytes.clone();
    let at = valid - 4;
    short[at..at + 4].copy_from_slice(&4u32.to_le_bytes());
    let cut: Vec<u8> = short[..valid + 4]
        .iter()
        .chain(&short[valid + 8..])
        .copied()
        .collect();
    error_of(
        &temp("short-range.frt", &cut),
        &ReadOptions::default(),
        "block 0x0070 has 4 bytes",
    );
}

/// Damaged FRT files: errors naming the file and the format.
#[test]
fn frt_microprof_damaged() {
    let bytes = std::fs::read(data("frt-1-crop.frt")).unwrap();
    truncated_copies_fail(&bytes, "frt-1.frt", "FRT MicroProf");
    // Bits per value (block 0x0066 at byte 38 + 8) 24.
    let mut b = bytes.clone();
    assert_eq!(&b[32..34], &[0x66, 0]);
    b[46] = 24;
    error_of(
        &temp("bits.frt", &b),
        &ReadOptions::default(),
        "24 bits per value",
    );
    // A grid larger than the data.
    let mut b = bytes.clone();
    b[42] = 41;
    error_of(&temp("grid.frt", &b), &ReadOptions::default(), "truncated");
    // An unknown version.
    let mut b = bytes.clone();
    b[12..16].copy_from_slice(b"2.00");
    error_of(
        &temp("version.frt", &b),
        &ReadOptions::default(),
        "version \"2.00\"",
    );
    // A block size beyond the file.
    let mut b = bytes.clone();
    b[20] = 0xff;
    b[21] = 0xff;
    error_of(&temp("size.frt", &b), &ReadOptions::default(), "truncated");
}

/// Offset of array `name`'s block in a Wyko file (after its directory).
fn opd_block(b: &[u8], name: &str) -> usize {
    let length = i32::from_le_bytes(b[20..24].try_into().unwrap()) as usize;
    let mut at = 2 + length;
    for e in b[2..2 + length].chunks_exact(24).skip(1) {
        let n: Vec<u8> = e[..16].iter().copied().take_while(|&c| c != 0).collect();
        if n == name.as_bytes() {
            return at;
        }
        at += i32::from_le_bytes(e[18..22].try_into().unwrap()).max(0) as usize;
    }
    panic!("no {name}");
}

/// `opd-1-crop.opd` (SurfaceTopography's opd-1.opd cut to 640 × 32 points)
/// against SurfaceTopography: sizes (mm), heights h[ix, iy] (values stored
/// y fastest, last row first), rms values; an undefined point where it is;
/// the u8 `Image` channel.
#[test]
fn wyko_opd_agrees_with_surface_topography() {
    let path = data("opd-1-crop.opd");
    let t = read::read(&path, &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [32, 640]);
    assert!(close(t.lx(), 0.1259091403335333e-3) && close(t.ly(), 0.006295457016676664e-3));
    agrees_with_st(
        &t,
        1e-3,
        &[
            ((0, 0), -0.00028629880478093036),
            ((1, 0), -0.00028328646280572506),
            ((0, 1), -0.0002850692514614566),
            ((639, 31), -0.0002765728498041335),
            ((17, 23), -0.0002799118236010472),
        ],
        [
            6.396713381030186e-06,
            0.0180217347226358,
            130.22814726778483,
        ],
        ST_AGREEMENT,
    );
    assert_eq!(
        read::read(&path, &channel("raw")).unwrap().heights(),
        t.heights()
    );
    // A value of 1e38 (f32) is undefined: value ix·ny + ny − 1 − iy is h[ix, iy].
    let bytes = std::fs::read(&path).unwrap();
    let (ix, iy, ny) = (5, 7, 32);
    let mut b = bytes.clone();
    let at = opd_block(&b, "Raw") + 6 + 4 * (ix * ny + ny - 1 - iy);
    b[at..at + 4].copy_from_slice(&1e38f32.to_le_bytes());
    let p = temp("hole.opd", &b);
    error_of(
        &p,
        &ReadOptions::default(),
        "1 of 20480 points are undefined",
    );
    let r = read::as_read(&p, &ReadOptions::default()).unwrap();
    let nan: Vec<usize> = (0..r.heights.len())
        .filter(|&k| r.heights[k].is_nan())
        .collect();
    assert_eq!(nan, [iy * 640 + ix]);
    // The intensity image (u8): raw values, the caller gives a unit.
    error_of(&path, &channel("Image"), "height unit");
    let o = ReadOptions {
        height_unit: Some(LengthUnit::Metre),
        ..channel("Image")
    };
    let i = read::as_read(&path, &o).unwrap();
    assert!(i
        .heights
        .iter()
        .all(|v| (0.0..=255.0).contains(v) && v.fract() == 0.0));
    error_of(&path, &channel("SecArr_0"), "no channel \"SecArr_0\"");
    // Found by its directory without the extension.
    let o = read::from_bytes(Path::new("scan"), &bytes, &ReadOptions::default()).unwrap();
    assert_eq!(o.heights(), t.heights());
}

/// Damaged Wyko files: errors naming the file and the format.
#[test]
fn wyko_opd_damaged() {
    let bytes = std::fs::read(data("opd-1-crop.opd")).unwrap();
    truncated_copies_fail(&bytes, "opd-1.opd", "Wyko .opd");
    // No Wavelength: no scale.
    let mut b = bytes.clone();
    let k = b.windows(10).position(|w| w == b"Wavelength").unwrap();
    b[k] = b'w';
    error_of(
        &temp("nowave.opd", &b),
        &ReadOptions::default(),
        "no Wavelength",
    );
    // A directory length that is not a multiple of 24.
    let mut b = bytes.clone();
    b[20] = b[20].wrapping_add(1);
    error_of(
        &temp("dir.opd", &b),
        &ReadOptions::default(),
        "directory length",
    );
    // An item size of 3.
    let mut b = bytes.clone();
    let at = opd_block(&b, "Raw");
    b[at + 4] = 3;
    error_of(
        &temp("item.opd", &b),
        &ReadOptions::default(),
        "item size 3",
    );
}

/// `opdx-3.opdx` (a Dektak profile) against SurfaceTopography: 3001 points,
/// length Extent·n/(n − 1), heights in µm, Rq, Rdq, Rddq after the line;
/// and against the instrument's own text export of the scan, `opdx-3.txt`
/// (x and h in m to 8 significant digits).
#[test]
fn dektak_opdx_agrees_with_surface_topography_and_its_export() {
    let path = data("opdx-3.opdx");
    let t = read::read(&path, &ReadOptions::default()).unwrap();
    assert_eq!((t.layout(), t.nx(), t.ny()), (Layout::LineScans, 3001, 1));
    assert!(close(t.lx(), 49.983344425752584e-6), "{}", t.lx());
    for (ix, st) in [
        (0, 0.0013718305790923332),
        (1, 0.0013122407677853129),
        (3000, 0.014412930733025379),
        (1234, -0.0009882868813896838),
    ] {
        assert!(
            close(t.heights()[ix], st * 1e-6),
            "{ix}: {}",
            t.heights()[ix]
        );
    }
    let a = analyse(&t, &AnalysisOptions::default()).unwrap();
    for (got, want) in [
        (a.rms_height, 0.0028257223325313533e-6),
        (a.rms_slope_profile.unwrap(), 0.0165977656556357),
        (a.rms_curvature_profile.unwrap(), 1.5038815633959663e6),
    ] {
        assert!(
            (got / want - 1.0).abs() < ST_AGREEMENT,
            "{got} against {want}"
        );
    }
    // The instrument's export: every height to its 8 digits, the same spacing.
    let txt = read::read(&data("opdx-3.txt"), &ReadOptions::default()).unwrap();
    assert_eq!(txt.nx(), 3001);
    assert!(
        (txt.lx() / t.lx() - 1.0).abs() < 1e-8,
        "{} {}",
        txt.lx(),
        t.lx()
    );
    for (a, b) in t.heights().iter().zip(txt.heights()) {
        assert!((a - b).abs() <= 5e-8 * a.abs() + 1e-18, "{a} against {b}");
    }
    assert_eq!(
        read::read(&path, &channel("Raw")).unwrap().heights(),
        t.heights()
    );
    error_of(
        &path,
        &channel("Height2"),
        "no channel \"Height2\": the file has 0: \"Raw\"",
    );
    let bytes = std::fs::read(&path).unwrap();
    let o = read::from_bytes(Path::new("scan"), &bytes, &ReadOptions::default()).unwrap();
    assert_eq!(o.heights(), t.heights());
}

/// An OPDx height map (no example file: `opdx-map-synthetic.opdx`, 5 × 4
/// f32 values written by the reference script in the layout
/// SurfaceTopography reads, x extent in µm, y extent in mm, heights in nm)
/// against SurfaceTopography: Dimension2 is x, rows of the matrix are y,
/// sizes Extent·n/(n − 1).
#[test]
fn dektak_opdx_map_agrees_with_surface_topography() {
    let path = data("opdx-map-synthetic.opdx");
    let t = read::read(&path, &ReadOptions::default()).unwrap();
    assert_eq!((t.layout(), t.shape()), (Layout::Map, [4, 5]));
    assert!(
        close(t.lx(), 10e-6) && close(t.ly(), 4e-6),
        "{} {}",
        t.lx(),
        t.ly()
    );
    agrees_with_st(
        &t,
        1e-6,
        &[
            ((0, 0), 0.0),
            ((1, 0), 0.0011250000000000001),
            ((0, 1), 0.002625),
            ((4, 3), 0.0018000000715255738),
            ((2, 1), 0.0010499999821186065),
        ],
        [
            0.0011623185417523967,
            0.0021955996552730688,
            0.004210060499971126,
        ],
        ST_AGREEMENT,
    );
    error_of(
        &path,
        &channel("Raw"),
        "no channel \"Raw\": the file has 0: \"Height\"",
    );
    let bytes = std::fs::read(&path).unwrap();
    truncated_copies_fail(&bytes, "map.opdx", "Dektak .opdx");
}

/// Damaged OPDx files: errors naming the file and the format.
#[test]
fn dektak_opdx_damaged() {
    let bytes = std::fs::read(data("opdx-3.opdx")).unwrap();
    truncated_copies_fail(&bytes, "opdx-3.opdx", "Dektak .opdx");
    // The magic.
    let mut b = bytes.clone();
    b[0] = b'X';
    error_of(&temp("magic.opdx", &b), &ReadOptions::default(), "VCA DATA");
    // The type of the first item (the container 1D_Data, byte 23): unknown.
    let mut b = bytes.clone();
    assert_eq!(b[23], 0x7d);
    b[23] = 0x33;
    error_of(
        &temp("type.opdx", &b),
        &ReadOptions::default(),
        "unknown type 0x33",
    );
    // NumPoints that disagrees with the array.
    let mut b = bytes.clone();
    let k = b.windows(9).position(|w| w == b"NumPoints").unwrap();
    let v = k + 9 + 1;
    assert_eq!(u32::from_le_bytes(b[v..v + 4].try_into().unwrap()), 3001);
    b[v] = b[v].wrapping_add(1);
    error_of(
        &temp("points.opdx", &b),
        &ReadOptions::default(),
        "NumPoints = 3002",
    );
}

/// A Wyko `Image` (not heights) without `Pixel_size`: neither unit is
/// stated, so the caller must give them (never metres by default).
#[test]
fn wyko_opd_image_without_pixel_size_needs_units() {
    let mut b = std::fs::read(data("opd-1-crop.opd")).unwrap();
    let k = b.windows(10).position(|w| w == b"Pixel_size").unwrap();
    b[k] = b'p';
    let path = temp("nopix.opd", &b);
    error_of(&path, &channel("Image"), "give the height unit");
    let o = ReadOptions {
        height_unit: Some(LengthUnit::Nanometre),
        size: Some(read::SizeSpec::PixelSize(1e-6)),
        ..channel("Image")
    };
    read::as_read(&path, &o).unwrap();
}

/// A Dektak `DataScale` that is NaN, infinite or zero; a quantity whose
/// value runs past its declared length.
#[test]
fn dektak_opdx_bad_data_scale_and_overrunning_quantity() {
    let bytes = std::fs::read(data("opdx-3.opdx")).unwrap();
    let k = bytes.windows(9).position(|w| w == b"DataScale").unwrap() + 9;
    // Type 0x13 (a quantity), a 1-byte length of 49, the f64 value.
    assert_eq!(bytes[k..k + 3], [0x13, 1, 49]);
    for (name, v) in [
        ("nan.opdx", f64::NAN),
        ("inf.opdx", f64::INFINITY),
        ("zero.opdx", 0.0),
    ] {
        let mut b = bytes.clone();
        b[k + 3..k + 11].copy_from_slice(&v.to_le_bytes());
        let e = error_of(&temp(name, &b), &ReadOptions::default(), "DataScale");
        assert!(e.contains("not a finite, non-zero scale"), "{e}");
        assert!(e.contains("Dektak .opdx"), "{e}");
    }
    // 20 bytes declared; the value and its two names take 29.
    let mut b = bytes.clone();
    b[k + 2] = 20;
    let e = error_of(
        &temp("overrun.opdx", &b),
        &ReadOptions::default(),
        "runs on to byte",
    );
    assert!(e.contains("Dektak .opdx"), "{e}");
}

/// Mountains `.mnt` and Park `.tiff` (whose other tests are in
/// mnt_tiff_xlsx.rs): a looping FAT chain, a NaN origin; NaN or infinite
/// gain, scale and offset.
#[test]
fn mountains_mnt_fat_loop_and_park_tiff_nonfinite_fields() {
    let bytes = std::fs::read(data("mnt-1-crop.mnt")).unwrap();
    let u32_at = |b: &[u8], at: usize| u32::from_le_bytes(b[at..at + 4].try_into().unwrap());
    // The directory's first sector made its own successor in the FAT, the
    // file padded to 2 MB: an error at once, found by content too.
    let sector = 1usize << u16::from_le_bytes([bytes[0x1E], bytes[0x1F]]);
    let fat = (u32_at(&bytes, 0x4C) as usize + 1) * sector;
    let dir = u32_at(&bytes, 0x30);
    let mut b = bytes.clone();
    let at = fat + 4 * dir as usize;
    b[at..at + 4].copy_from_slice(&dir.to_le_bytes());
    b.resize(2 << 20, 0);
    let start = std::time::Instant::now();
    let e = error_of(&temp("loop.mnt", &b), &ReadOptions::default(), "has a loop");
    assert!(
        e.contains("Digital Surf Mountains .mnt") && e.contains("more than its"),
        "{e}"
    );
    let noext = read::read(&temp("loop-mnt-noext", &b), &ReadOptions::default());
    assert!(noext.is_err());
    assert!(start.elapsed().as_secs() < 2, "{:?}", start.elapsed());
    // A NaN origin (tag 0005, 8 bytes) of the x scale: the first after
    // the first unit µm (04, then UTF-16LE).
    let um = [4, 0xb5, 0, b'm', 0];
    let unit = bytes.windows(5).position(|w| w == um).unwrap();
    let tag = [5, 0, 8, 0, 0, 0, 0, 0, 0, 0];
    let k = unit + bytes[unit..].windows(10).position(|w| w == tag).unwrap() + 10;
    let mut b = bytes.clone();
    b[k..k + 8].copy_from_slice(&f64::NAN.to_le_bytes());
    let e = error_of(
        &temp("origin.mnt", &b),
        &ReadOptions::default(),
        "origin of",
    );
    assert!(e.contains("not finite"), "{e}");

    // Park: the header (tag 50435) found through the first IFD.
    let bytes = std::fs::read(data("example_ps-crop.tiff")).unwrap();
    let ifd = u32_at(&bytes, 4) as usize;
    let n = usize::from(u16::from_le_bytes([bytes[ifd], bytes[ifd + 1]]));
    let header = (0..n)
        .map(|i| ifd + 2 + 12 * i)
        .find(|&e| u16::from_le_bytes([bytes[e], bytes[e + 1]]) == 50435)
        .map(|e| u32_at(&bytes, e + 8) as usize)
        .unwrap();
    for (at, field) in [
        (220, "data gain"),
        (228, "data scale factor"),
        (236, "data offset"),
    ] {
        for v in [f64::NAN, f64::NEG_INFINITY] {
            let mut b = bytes.clone();
            b[header + at..header + at + 8].copy_from_slice(&v.to_le_bytes());
            let e = error_of(&temp("field.tiff", &b), &ReadOptions::default(), field);
            assert!(
                e.contains("not finite") && e.contains("Park Systems"),
                "{e}"
            );
        }
    }
    // Finite, but overflowing together.
    let mut b = bytes.clone();
    for at in [220, 228] {
        b[header + at..header + at + 8].copy_from_slice(&1e308f64.to_le_bytes());
    }
    error_of(
        &temp("overflow.tiff", &b),
        &ReadOptions::default(),
        "overflows",
    );
}

//! Readers on files written by instruments and by other programs
//! (`tests/data/`, origins and licences in `tests/data/README.md`), against
//! SurfaceTopography's numbers for the same files
//! (`tests/reference/instrument_files.py` → `instrument_files.rs`), and the
//! cases of issue 20 that printed a wrong number or refused a legal file.
#![cfg(feature = "topography")]

use std::f64::consts::TAU;
use std::path::{Path, PathBuf};

use persson::topography::read::{self, Format, LengthUnit, ReadOptions, SizeSpec};
use persson::topography::{analyse, AnalysisOptions, Layout, Note};

#[allow(dead_code)]
#[path = "reference/instrument_files.rs"]
mod st;

/// Agreement with SurfaceTopography where both read the same numbers: the
/// same stencils, detrending, window and bins, so rounding of sums over
/// ≤ 10⁴ values and of the least-squares fits (measured: below 1e-12,
/// see the eprintln of each test).
const ST_AGREEMENT: f64 = 1e-10;
/// Undefined points are filled by harmonic interpolation in both codes, by
/// conjugate gradients to a relative residual of 1e-12 here and by a sparse
/// direct solve there: the filled heights agree to ~1e-12 of the heights.
const ST_FILLED: f64 = 1e-10;
/// The spectrum of a map whose heights carry a large constant (al3d-1.al3d:
/// heights near 0.076 m, 2.9e-7 m rms after the plane): the plane fit
/// cancels 5.4 digits, so each detrended height is rounded to
/// ε·0.076/2.9e-7 ≈ 6e-11 of itself, and the low-q bins, where the plane
/// matters most, more. SurfaceTopography's own C(q) moves by 2.2e-10
/// (relative, first bin) when the mean is subtracted from the heights
/// before it detrends (measured).
const ST_LARGE_OFFSET: f64 = 1e-9;
/// Heights written as decimals and read back: one rounding of the product
/// raw·increment + offset (x3p) or raw·factor (text with a conversion factor).
const ONE_ROUNDING: f64 = 4.0 * f64::EPSILON;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn options_for(name: &str) -> ReadOptions {
    ReadOptions {
        fill_undefined: name.contains("xyz-2")
            || [".x3p", ".gwy", ".sur", ".nc"]
                .iter()
                .any(|e| name.ends_with(e)),
        ..Default::default()
    }
}

fn rel(ours: f64, theirs: f64) -> f64 {
    if ours == theirs {
        0.0
    } else {
        (ours / theirs - 1.0).abs()
    }
}

fn check(worst: &mut f64, what: &str, ours: f64, theirs: f64, tol: f64) {
    let e = rel(ours, theirs);
    *worst = worst.max(e);
    assert!(
        e <= tol,
        "{what}: ours {ours:e}, SurfaceTopography {theirs:e}, relative {e:e} > {tol:e}"
    );
}

#[test]
fn maps_agree_with_surface_topography() {
    for m in st::MAPS {
        let t = read::read(&data(m.file), &options_for(m.file)).unwrap();
        assert_eq!((t.nx(), t.ny()), (m.nx, m.ny), "{}", m.file);
        let tol = if options_for(m.file).fill_undefined {
            ST_FILLED
        } else {
            ST_AGREEMENT
        };
        let tol_c = if m.file == "al3d-1.al3d" {
            ST_LARGE_OFFSET
        } else {
            tol
        };
        let mut worst: f64 = 0.0;
        let w = &mut worst;
        check(w, &format!("{} Lx", m.file), t.lx(), m.lx, ST_AGREEMENT);
        check(w, &format!("{} Ly", m.file), t.ly(), m.ly, ST_AGREEMENT);
        let a = analyse(&t, &AnalysisOptions::default()).unwrap();
        check(
            w,
            &format!("{} rms height", m.file),
            a.rms_height,
            m.rms_height,
            tol,
        );
        check(
            w,
            &format!("{} rms slope", m.file),
            a.rms_slope,
            m.rms_gradient,
            tol,
        );
        check(
            w,
            &format!("{} rms curvature", m.file),
            a.rms_curvature.unwrap(),
            m.rms_laplacian,
            tol,
        );
        // SurfaceTopography's rms_curvature_from_area is the mean curvature
        // ∇²h/2, our second key (issue 25 item 5).
        check(
            w,
            &format!("{} mean curvature", m.file),
            a.mean_curvature_rms.unwrap(),
            m.rms_mean_curvature,
            tol,
        );
        assert_eq!(a.psd.q.len(), m.q.len(), "{}: same non-empty bins", m.file);
        for b in 0..m.q.len() {
            check(
                w,
                &format!("{} q[{b}]", m.file),
                a.psd.q[b],
                m.q[b],
                ST_AGREEMENT,
            );
            check(
                w,
                &format!("{} C[{b}]", m.file),
                a.psd.c[b] * TAU * TAU,
                m.c_st[b],
                tol_c,
            );
        }
        eprintln!(
            "{}: largest relative difference from SurfaceTopography {worst:.1e}",
            m.file
        );
    }
}

#[test]
fn line_scans_agree_with_surface_topography() {
    for p in st::PROFILES {
        let t = read::read(&data(p.file), &ReadOptions::default()).unwrap();
        assert_eq!((t.layout(), t.nx(), t.ny()), (Layout::LineScans, p.n, 1));
        let mut worst: f64 = 0.0;
        let w = &mut worst;
        check(
            w,
            &format!("{} length", p.file),
            t.lx(),
            p.length,
            ST_AGREEMENT,
        );
        let a = analyse(&t, &AnalysisOptions::default()).unwrap();
        check(
            w,
            &format!("{} Rq", p.file),
            a.rms_height,
            p.rms_height,
            ST_AGREEMENT,
        );
        check(
            w,
            &format!("{} Rdq", p.file),
            a.rms_slope_profile.unwrap(),
            p.rms_slope,
            ST_AGREEMENT,
        );
        check(
            w,
            &format!("{} Rddq", p.file),
            a.rms_curvature_profile.unwrap(),
            p.rms_curvature,
            ST_AGREEMENT,
        );
        let s = a.psd_profile.as_ref().unwrap();
        assert_eq!(s.q.len(), p.q.len(), "{}: same non-empty bins", p.file);
        for b in 0..p.q.len() {
            check(
                w,
                &format!("{} q[{b}]", p.file),
                s.q[b],
                p.q[b],
                ST_AGREEMENT,
            );
            check(
                w,
                &format!("{} C1D[{b}]", p.file),
                s.c_1d[b] * TAU,
                p.c1d_st[b],
                ST_AGREEMENT,
            );
        }
        eprintln!(
            "{}: largest relative difference from SurfaceTopography {worst:.1e}",
            p.file
        );
    }
}

// ------------------------------------------------------------ helpers

fn temp(name: &str, bytes: &[u8]) -> PathBuf {
    let d = std::env::temp_dir().join(format!("persson-instrument-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

/// The error of reading `path`; asserts that it names the file and says `needle`.
fn error_of(path: &Path, options: &ReadOptions, needle: &str) -> String {
    let e = read::read(path, options).expect_err(needle).to_string();
    let name = path.file_name().unwrap().to_string_lossy();
    assert!(e.contains(&*name), "{e:?} does not name {name}");
    assert!(e.contains(needle), "{e:?} does not say {needle:?}");
    assert!(!e.contains('\n'), "{e:?} is not one line");
    e
}

/// `a` equals `b` to one rounding of a product of decimals.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= ONE_ROUNDING * b.abs().max(1.0)
}

/// An `.x3p` archive with a free `CZ` axis, extra `DataLink` elements and
/// the members given.
fn x3p(nx: usize, ny: usize, cz: &str, link: &str, members: &[(&str, &[u8])]) -> Vec<u8> {
    use std::io::Write;
    let xml = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>SUR</FeatureType>
    <Axes>
      <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2e-6</Increment><Offset/></CY>
      <CZ><AxisType>A</AxisType>{cz}</CZ>
    </Axes>
  </Record1>
  <Record3>
    <MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
    <DataLink><PointDataLink>bindata/data.bin</PointDataLink>{link}</DataLink>
  </Record3>
</p:ISO5436_2>"#
    );
    let mut zw = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let o = zip::write::SimpleFileOptions::default();
    zw.start_file("main.xml", o).unwrap();
    zw.write_all(xml.as_bytes()).unwrap();
    for (name, data) in members {
        zw.start_file(*name, o).unwrap();
        zw.write_all(data).unwrap();
    }
    zw.finish().unwrap().into_inner()
}

// ------------------------------------------------------------ issue 20, items 1, 2, 10: x3p

/// The raw int16 values of the openGPS sample `ISO5436-sample4_bin.x3p`
/// (`bindata/data.bin`, read with `od -t d2`); point 7 is marked invalid
/// by `bindata/valid.bin` = `7f ff` (least significant bit first).
const SAMPLE4_RAW: [i16; 16] = [
    986, 503, -308, -80, 1358, 1548, 1519, 0, 1324, 1298, -57, 267, 1175, 921, 1142, 284,
];

#[test]
fn x3p_int16_is_signed_and_its_validity_mask_marks_undefined_points() {
    let p = data("ISO5436-sample4_bin.x3p");
    // The mask makes point 7 undefined: an error with the count, not a cliff.
    error_of(&p, &ReadOptions::default(), "1 of 16 points are undefined");
    let filled = ReadOptions {
        fill_undefined: true,
        ..Default::default()
    };
    let t = read::read(&p, &filled).unwrap();
    assert_eq!(t.shape(), [4, 4]);
    assert_eq!(t.pixel_size(), vec![1.6016e-2, 1.6016e-2]);
    for (k, (&h, &raw)) in t.heights().iter().zip(&SAMPLE4_RAW).enumerate() {
        if k != 7 {
            // CZ: Increment 0.001, Offset −0.5; −308 read as u16 would be 65228.
            let want = f64::from(raw) * 0.001 - 0.5;
            assert!(close(h, want), "point {k}: {h} vs {want}");
        }
    }
    assert!(t.heights()[2] < -0.8 && t.heights()[10] < -0.5);
    // The same sample with its values in main.xml (DataList, an empty Datum
    // for the invalid point) reads the same.
    let list = read::read(&data("ISO5436-sample4.x3p"), &filled).unwrap();
    assert_eq!(list.heights(), t.heights());
    // float64 with a mask: the masked point is undefined too.
    error_of(
        &data("ISO5436-sample1_bin.x3p"),
        &ReadOptions::default(),
        "1 of 16 points are undefined",
    );
}

#[test]
fn x3p_written_by_surface_topography_as_int16_and_int32_with_masks() {
    // matrix-4.txt written by SurfaceTopography's to_x3p with 378 points
    // undefined: raw values over the whole signed range, undefined points
    // stored as the minimum raw value and flagged in bindata/valid.bin.
    let map = read::read(&data("matrix-4.txt"), &ReadOptions::default()).unwrap();
    // The heights' range over the 2¹⁶ − 1 (2³² − 1) steps of the integers.
    let (lo, hi) = map
        .heights()
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
            (a.min(h), b.max(h))
        });
    for (name, steps) in [
        ("st-int16-mask.x3p", 65535.0),
        ("st-int32-mask.x3p", 4294967295.0),
    ] {
        let p = data(name);
        error_of(
            &p,
            &ReadOptions::default(),
            "378 of 22875 points are undefined",
        );
        let o = ReadOptions {
            fill_undefined: true,
            ..Default::default()
        };
        let t = read::read(&p, &o).unwrap();
        assert_eq!(
            (t.shape(), t.lx(), t.ly()),
            (map.shape(), map.lx(), map.ly())
        );
        // Away from the undefined points the heights are the map's to half a
        // step of the integer encoding (plus the rounding of raw·Increment + Offset).
        let half_step = 0.5 * (hi - lo) / steps * (1.0 + 1e-6);
        let (nx, ny) = (t.nx(), t.ny());
        let mut checked = 0;
        for k in 0..nx * ny {
            let (ix, iy) = (k % nx, k / nx);
            let undefined =
                (20..32).contains(&ix) && (100..112).contains(&iy) || (ix * ny + iy) % 97 == 0;
            if !undefined {
                let e = (t.heights()[k] - map.heights()[k]).abs();
                assert!(
                    e <= half_step + 4.0 * f64::EPSILON * hi.abs(),
                    "{name} point {k}: {e:e}"
                );
                checked += 1;
            }
        }
        assert_eq!(checked, nx * ny - 378);
    }
}

#[test]
fn x3p_int32_signed_with_mask_and_empty_offset() {
    let (nx, ny) = (4, 3);
    let raw: Vec<i32> = vec![-5, 7, -2_000_000_000, 3, 9, -1, 0, 4, i32::MIN, 12, -8, 6];
    let data: Vec<u8> = raw.iter().flat_map(|v| v.to_le_bytes()).collect();
    // Point 8 invalid (its raw value is the minimum, as writers store it).
    let valid = [0xFFu8, 0b1111_1110];
    let cz = "<DataType>L</DataType><Increment>1e-9</Increment><Offset/>";
    let link = "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>";
    let bytes = x3p(
        nx,
        ny,
        cz,
        link,
        &[("bindata/data.bin", &data), ("bindata/valid.bin", &valid)],
    );
    let p = temp("int32.x3p", &bytes);
    error_of(&p, &ReadOptions::default(), "1 of 12 points are undefined");
    let t = read::read(
        &p,
        &ReadOptions {
            fill_undefined: true,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!((t.lx(), t.ly()), (4e-6, 6e-6));
    for (k, (&h, &r)) in t.heights().iter().zip(&raw).enumerate() {
        if k != 8 {
            assert!(close(h, f64::from(r) * 1e-9), "point {k}: {h}");
        }
    }
    // The filled point lies between its neighbours, not at i32::MIN·1e-9 = −2.1 m.
    assert!(t.heights()[8].abs() < 2.1, "{}", t.heights()[8]);
    // A mask shorter than the points is an error.
    let short = x3p(
        nx,
        ny,
        cz,
        link,
        &[
            ("bindata/data.bin", &data),
            ("bindata/valid.bin", &valid[..1]),
        ],
    );
    error_of(
        &temp("short-mask.x3p", &short),
        &ReadOptions::default(),
        "validity mask",
    );
}

// ------------------------------------------------------------ item 3: line scans

#[test]
fn real_line_scans_with_rounded_x_read_as_equally_spaced() {
    // (file, points, Δ in m, first height in m): x written to 0.1 µm
    // (Dektak, Latin-1, 28 header lines, µm), 8 significant digits (OPDx
    // export, m), 6 decimals (no unit: m).
    for (name, n, dx, h0) in [
        ("dektak-1.csv", 9600, 1499.8e-6 / 9599.0, -0.00933e-6),
        ("opdx-3.txt", 3001, 4.9966689e-5 / 3000.0, 1.3718306e-9),
        ("xy-4.txt", 10001, 0.995613 / 10000.0, 0.003581),
    ] {
        let t = read::read(&data(name), &ReadOptions::default()).unwrap();
        assert_eq!((t.layout(), t.nx()), (Layout::LineScans, n), "{name}");
        assert!(t.notes().is_empty(), "{name}: {:?}", t.notes());
        assert!(
            (t.pixel_size()[0] / dx - 1.0).abs() < 1e-12,
            "{name}: Δ = {:e}",
            t.pixel_size()[0]
        );
        assert!(close(t.heights()[0], h0), "{name}: {}", t.heights()[0]);
    }
}

#[test]
fn nonuniform_line_scan_is_resampled_with_a_note() {
    let t = read::read(&data("nonuniform.asc"), &ReadOptions::default()).unwrap();
    match t.notes() {
        [Note::Resampled {
            points: 134,
            max_deviation,
        }] => assert!(*max_deviation > 1.0, "{max_deviation}"),
        other => panic!("{other:?}"),
    }
    let a = analyse(&t, &AnalysisOptions::default()).unwrap();
    assert!(matches!(a.notes[0], Note::Resampled { .. }));
}

#[test]
fn line_scan_statistics_survive_a_noisy_spectrum() {
    // The Dektak scan: a noise floor and a few modes at low q whose local
    // log-log slope is not below −1. The 1D spectrum and statistics are
    // reported whole; those bins are left out of the 2D spectrum, noted.
    let t = read::read(&data("dektak-1.csv"), &ReadOptions::default()).unwrap();
    let a = analyse(&t, &AnalysisOptions::default()).unwrap();
    let p = a.psd_profile.as_ref().unwrap();
    let left: Vec<f64> = a
        .notes
        .iter()
        .find_map(|n| match n {
            Note::BinsLeftOut { q, of } => {
                assert_eq!(*of, p.q.len());
                Some(q.clone())
            }
            _ => None,
        })
        .expect("bins left out");
    assert!(!left.is_empty());
    assert_eq!(a.psd.q.len() + left.len(), p.q.len());
    for q in &a.psd.q {
        assert!(p.q.contains(q) && !left.contains(q));
    }
    // Every bin kept has a local slope below −1 among the bins kept, and its
    // C is the 1D value times the exact power-law factor of that slope.
    let c1d = |q: f64| p.c_1d[p.q.iter().position(|v| *v == q).unwrap()];
    let m = a.psd.q.len();
    for k in 0..m {
        let (i, j) = (k.saturating_sub(1), (k + 1).min(m - 1));
        let (qa, qb) = (a.psd.q[i], a.psd.q[j]);
        let s = (c1d(qb) / c1d(qa)).ln() / (qb / qa).ln();
        assert!(s < -1.0, "bin {k}: slope {s}");
    }
    // The 2D rms values are those of the whole 1D spectrum (√2, √(8/3)).
    assert!((a.rms_slope_from_spectrum / p.rms_slope_profile - 2f64.sqrt()).abs() < 1e-15);
    assert!(a.rms_height > 0.0 && a.rms_slope_profile.unwrap() > 0.0);
    assert!(a.hurst.is_none_or(|h| h > 0.0 && h < 1.0));
}

// ------------------------------------------------------------ item 4: XYZ by content

#[test]
fn xyz_triples_in_text_files_are_read_as_maps() {
    let t = read::read(&data("xyz-1.txt"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [4, 4]);
    assert_eq!((t.lx(), t.ly()), (4.0, 4.0));
    // Ordered by x then y in the file: the point (x = 1, y = 2) has z = 2.
    assert_eq!(t.heights()[2 * 4 + 1], 2.0);
    let xyz = b"0 0 1\n1e-6 0 2\n2e-6 0 4\n0 1e-6 3\n1e-6 1e-6 5\n2e-6 1e-6 7\n";
    for name in ["grid.csv", "grid.dat", "grid.txt"] {
        let t = read::read(&temp(name, xyz), &ReadOptions::default()).unwrap();
        assert_eq!(t.shape(), [2, 3], "{name}");
        assert_eq!(t.heights(), &[1.0, 2.0, 4.0, 3.0, 5.0, 7.0]);
    }
    // Three columns that are no grid stay a matrix.
    let m = b"1.5 2.25 3\n4 5.5 6\n7 8 9.5\n1 5 2\n";
    let o = ReadOptions {
        size: Some(SizeSpec::PixelSize(1e-6)),
        ..Default::default()
    };
    let t = read::read(&temp("matrix.txt", m), &o).unwrap();
    assert_eq!(t.shape(), [4, 3]);
}

// ------------------------------------------------------------ item 5: headers and encodings

#[test]
fn gwyddion_export_header_gives_the_size_checked_against_a_given_one() {
    for name in ["gwyddion-export-english.txt", "gwyddion-export-german.txt"] {
        let p = data(name);
        let t = read::read(&p, &ReadOptions::default()).unwrap();
        // "Width: 12.34 µm" (x, 3 columns), "Height: 5678.9 nm" (y, 4 rows).
        assert_eq!(t.shape(), [4, 3]);
        assert!(close(t.lx(), 12.34e-6) && close(t.ly(), 5.6789e-6));
        assert_eq!(t.heights()[..3], [1.0, 1.5, 3.0]);
        let given = |s: SizeSpec| ReadOptions {
            size: Some(s),
            ..Default::default()
        };
        let same = read::read(&p, &given(SizeSpec::Size(12.34e-6, Some(5.6789e-6)))).unwrap();
        assert_eq!(same, t);
        error_of(
            &p,
            &given(SizeSpec::Size(1e-5, Some(5.6789e-6))),
            "disagrees",
        );
        error_of(&p, &given(SizeSpec::PixelSize(1e-6)), "disagrees");
    }
    // A height unit given that is not the file's ("Value units: m").
    let nm = ReadOptions {
        height_unit: Some(LengthUnit::Nanometre),
        ..Default::default()
    };
    error_of(&data("txt_example.txt"), &nm, "heights in m");
}

#[test]
fn header_lines_h_w_pixel_size_and_conversion_factor() {
    // h=305 w=75, pixel size=3.69862e-007 m, data unit=rad,
    // height conversion factor (-> m)=2.91818e-008.
    let t = read::read(&data("matrix-4.txt"), &ReadOptions::default()).unwrap();
    assert_eq!(t.shape(), [305, 75]);
    assert_eq!(t.pixel_size(), vec![3.69862e-7, 3.69862e-7]);
    assert!(close(t.heights()[0], -4.448661 * 2.91818e-8));
    // A header whose h and w disagree with the numbers.
    let p = temp("hw.txt", b"h=3 w=2\n1 2\n3 4\n");
    // (Two columns under a map header are a map, not a line scan.)
    error_of(&p, &ReadOptions::default(), "h = 3 rows");
    // A phase channel without a factor to metres.
    let p = temp("phase.txt", b"# Value units: deg\n1 2\n3 4\n");
    let o = ReadOptions {
        size: Some(SizeSpec::PixelSize(1e-6)),
        ..Default::default()
    };
    error_of(&p, &o, "\"deg\", not a unit of length");
}

#[test]
fn utf16_and_latin1_text() {
    // csv-3.csv: UTF-16 little-endian with a byte-order mark, "x in µm,y in µm",
    // a flat profile of −1.4274328574349099 µm: read (in m) and refused as flat.
    let e = error_of(&data("csv-3.csv"), &ReadOptions::default(), "not all equal");
    assert!(
        e.contains("every height is -1.4274328574349099e-6: a flat surface"),
        "{e}"
    );
    // csv-2.csv: the same with an index column first.
    let e = error_of(&data("csv-2.csv"), &ReadOptions::default(), "not all equal");
    assert!(e.contains("-1.427432857434913e-6"), "{e}");
    let rows = persson::io::text::rows(
        &data("csv-3.csv"),
        &std::fs::read(data("csv-3.csv")).unwrap(),
    )
    .unwrap();
    assert_eq!(rows.rows.len(), 8);
    assert_eq!(rows.header[0].text, "x in µm,y in µm");
    assert_eq!(rows.rows[0].values[0], -99.9583333333333);
    // A profile in UTF-16, either byte order.
    let text = "x [nm];h [nm]\n0;1\n1;3\n2;2\n";
    for (name, bom, big) in [
        ("le.csv", [0xFF, 0xFE], false),
        ("be.csv", [0xFE, 0xFF], true),
    ] {
        let mut b = bom.to_vec();
        for u in text.encode_utf16() {
            b.extend(if big {
                u.to_be_bytes()
            } else {
                u.to_le_bytes()
            });
        }
        let t = read::read(&temp(name, &b), &ReadOptions::default()).unwrap();
        for (h, want) in t.heights().iter().zip([1e-9, 3e-9, 2e-9]) {
            assert!(close(*h, want), "{name}: {h} vs {want}");
        }
        assert!(close(t.lx(), 3e-9));
    }
    // Latin-1: the Dektak file (µ = 0xB5 in its header) reads (above); a
    // truncated UTF-16 file is an error.
    let mut cut = vec![0xFF, 0xFE];
    cut.extend("1;2\n".encode_utf16().flat_map(u16::to_le_bytes));
    cut.push(b'3');
    error_of(&temp("cut.csv", &cut), &ReadOptions::default(), "UTF-16");
}

// ------------------------------------------------------------ item 6: units

/// A Gwyddion Simple Field with these extra header lines.
fn gsf(extra: &str) -> Vec<u8> {
    let mut b = format!(
        "Gwyddion Simple Field 1.0\nXRes = 3\nYRes = 2\nXReal = 3e-06\nYReal = 2e-06\n{extra}"
    )
    .into_bytes();
    b.extend(std::iter::repeat_n(0u8, 4 - b.len() % 4));
    for v in [1.0f32, 2.0, 4.0, 3.0, 5.0, 7.0] {
        b.extend(v.to_le_bytes());
    }
    b
}

#[test]
fn height_units_read_checked_or_given() {
    // GSF: a phase channel is named as such; metres are metres.
    let p = temp("phase.gsf", &gsf("XYUnits = m\nZUnits = deg\n"));
    error_of(&p, &ReadOptions::default(), "ZUnits");
    error_of(&p, &ReadOptions::default(), "\"deg\", not a unit of length");
    let p = temp("metres.gsf", &gsf("XYUnits = m\nZUnits = m\n"));
    assert_eq!(
        read::read(&p, &ReadOptions::default()).unwrap().heights()[1],
        2.0
    );
    let um = ReadOptions {
        height_unit: Some(LengthUnit::Micrometre),
        ..Default::default()
    };
    error_of(&p, &um, "heights in m");
    // A GSF without units and a .npy take the unit given (default m).
    let p = temp("plain.gsf", &gsf(""));
    assert_eq!(read::read(&p, &um).unwrap().heights()[1], 2e-6);
    let npy = persson::io::npy::encode(2, 2, &[1.0, 2.0, 3.0, 5.0]).unwrap();
    let o = ReadOptions {
        size: Some(SizeSpec::PixelSize(1e-6)),
        ..um.clone()
    };
    let t = read::read(&temp("um.npy", &npy), &o).unwrap();
    for (h, want) in t.heights().iter().zip([1e-6, 2e-6, 3e-6, 5e-6]) {
        assert!(close(*h, want), "{h} vs {want}");
    }
    // Column headings: mm and nm; a channel that is not a height; a unit for
    // x but none for h needs the height unit.
    let p = temp("mixed.txt", b"x [mm], z [nm]\n0, 1\n0.5, 4\n1.0, 2\n");
    let t = read::read(&p, &ReadOptions::default()).unwrap();
    assert_eq!((t.lx(), t.heights()[1]), (1.5e-3, 4e-9));
    let p = temp("volts.txt", b"x [um], Signal [V]\n0, 1\n1, 4\n2, 2\n");
    error_of(&p, &ReadOptions::default(), "\"V\", not a unit of length");
    let p = temp("half.txt", b"x [um], height\n0, 1\n1, 4\n2, 2\n");
    error_of(&p, &ReadOptions::default(), "option `height_unit`");
    let t = read::read(
        &p,
        &ReadOptions {
            height_unit: Some(LengthUnit::Nanometre),
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!((t.lx(), t.heights()[1]), (3e-6, 4e-9));
    // No unit anywhere: the lateral unit given scales x.
    let p = temp("bare.txt", b"0 1\n1 4\n2 2\n");
    let t = read::read(
        &p,
        &ReadOptions {
            lateral_unit: Some(LengthUnit::Millimetre),
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!((t.lx(), t.heights()[1]), (3e-3, 4.0));
}

// ------------------------------------------------------------ item 7: Hurst fit

#[test]
fn a_failed_or_out_of_range_hurst_fit_is_none_with_a_note() {
    let t = read::read(
        &data("gwyddion-export-english.txt"),
        &ReadOptions::default(),
    )
    .unwrap();
    let a = analyse(&t, &AnalysisOptions::default()).unwrap();
    assert_eq!((a.hurst, a.hurst_error), (None, None));
    assert!(
        matches!(a.notes[..], [Note::HurstNotFitted { bins: 0 }]),
        "{:?}",
        a.notes
    );
    let json = serde_json::to_value(&a).unwrap();
    assert!(json["hurst"].is_null() && json["hurst_error"].is_null());
    assert!((a.rms_height - st::MAPS[0].rms_height).abs() < 1e-15 * a.rms_height);
    let t = read::read(&data("xyz-1.txt"), &ReadOptions::default()).unwrap();
    let a = analyse(&t, &AnalysisOptions::default()).unwrap();
    match a.notes[..] {
        [Note::HurstOutOfRange { hurst, hurst_error }] => {
            assert!(!(0.0..1.0).contains(&hurst) && hurst_error > 0.0)
        }
        ref other => panic!("{other:?}"),
    }
    assert!(a.hurst.is_none());
}

// ------------------------------------------------------------ item 8: unsupported formats

#[test]
fn unsupported_binary_formats_say_what_to_do() {
    let o = ReadOptions::default();
    let cases: [(&str, &[u8], &str); 6] = [
        (
            "scan.zon",
            b"\x01\x00Directory",
            "unsupported format (.zon)",
        ),
        ("map.plux", b"anything", "unsupported format (.plux)"),
        ("scan.vk4", b"VK4_\0\0", "unsupported format (.vk4)"),
        (
            "renamed.bin",
            b"MATLAB 5.0 MAT-file\0\0",
            "unsupported format (MATLAB .mat)",
        ),
        (
            "raw.dat",
            b"1 2 3\0\0\0\x07",
            "unsupported format (.dat, binary data)",
        ),
        ("sheet.zip", b"PK\x03\x04", "unsupported format (.zip)"),
    ];
    for (name, bytes, needle) in cases {
        let e = error_of(&temp(name, bytes), &o, needle);
        assert!(
            e.contains("export to GSF or x3p with Gwyddion or SurfaceTopography"),
            "{e}"
        );
    }
    // A zip archive that is not an x3p says so too.
    let e = error_of(&temp("notx3p.bin", &x3p_without_main()), &o, "not an .x3p");
    assert!(e.contains("persson reads"), "{e}");
}

fn x3p_without_main() -> Vec<u8> {
    use std::io::Write;
    let mut zw = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    zw.start_file("sheet.xml", zip::write::SimpleFileOptions::default())
        .unwrap();
    zw.write_all(b"<a/>").unwrap();
    zw.finish().unwrap().into_inner()
}

// ------------------------------------------------------------ item 9: axis order

#[test]
fn transpose_reads_a_map_saved_in_ix_iy_order() {
    // SurfaceTopography's heights()[ix, iy] saved with numpy: shape (nx, ny).
    let (nx, ny) = (3, 2);
    let ours: Vec<f64> = (0..nx * ny).map(|k| (k * k) as f64).collect(); // [iy][ix]
    let mut st = vec![0.0; nx * ny]; // [ix][iy]
    for iy in 0..ny {
        for ix in 0..nx {
            st[ix * ny + iy] = ours[iy * nx + ix];
        }
    }
    let p = temp("st.npy", &persson::io::npy::encode(nx, ny, &st).unwrap());
    let o = ReadOptions {
        size: Some(SizeSpec::Size(2e-6, Some(3e-6))), // the file as read: 3 rows of 2
        transpose: true,
        ..Default::default()
    };
    let t = read::read(&p, &o).unwrap();
    assert_eq!(t.shape(), [ny, nx]);
    assert_eq!(t.heights(), &ours[..]);
    assert_eq!((t.lx(), t.ly()), (3e-6, 2e-6));
    let lines = ReadOptions {
        transpose: true,
        format: Some(Format::LineScan),
        ..Default::default()
    };
    error_of(&temp("scan.txt", b"0 1\n1 2\n2 4\n"), &lines, "transposed");
}

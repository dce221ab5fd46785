//! contact.engineering dataset exports: `container-2.zip` (TopoBank 0.13,
//! `meta.yml`: a TEM line scan in nm without units in the file, a Nanoscope
//! AFM map, a stylus line scan in mm), each measurement read by name or
//! index with its metadata applied, against SurfaceTopography 1.27.1; then
//! archives made here: `index.json`, a squeezed NetCDF, and broken ones.

use std::io::Write;

use persson::topography::read::{self, dataset, ReadOptions, SizeSpec};
use persson::topography::{real_space_stats, Detrend};

use super::support::{close, data, error_of, temp};

fn channel(c: &str) -> ReadOptions {
    ReadOptions {
        channel: Some(c.into()),
        ..Default::default()
    }
}

fn zip_of(members: &[(&str, &[u8])]) -> Vec<u8> {
    let mut zw = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for (name, bytes) in members {
        zw.start_file(*name, zip::write::SimpleFileOptions::default())
            .unwrap();
        zw.write_all(bytes).unwrap();
    }
    zw.finish().unwrap().into_inner()
}

/// The measurements as the metadata describe them, and each read with its
/// metadata: SurfaceTopography 1.27.1 gives (tests/reference, run on the
/// archive; `read_container(...)[0]` and `open_topography` of the member)
/// the AFM map 512 × 512 of 100 nm with rms height 4.6879221670601305 nm
/// after the plane read directly, and the stylus scan 3001 points with rms
/// height 1.2123588824547171e-05 mm after the quadratic.
#[test]
// SurfaceTopography's numbers as Python prints them (17 digits).
#[allow(clippy::excessive_precision)]
fn container_2_measurements_with_their_metadata() {
    let path = data("container-2.zip");
    let d = dataset(&path).unwrap().expect("a dataset");
    let names: Vec<&str> = d.measurements.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "80_Scale10.472_FIXEDv2p1.asc",
            "gain_control_uncd_35.001",
            "uncd_stylus_300um_5mar_3.txt"
        ]
    );
    let detrends: Vec<Detrend> = d.measurements.iter().map(|m| m.detrend).collect();
    assert_eq!(
        detrends,
        [Detrend::Plane, Detrend::Plane, Detrend::Curvature]
    );
    assert_eq!(d.measurements[1].height_scale, 0.112075538798523);

    let afm = read::read(&path, &channel("gain_control_uncd_35.001")).unwrap();
    assert_eq!(afm.shape(), [512, 512]);
    assert!(close(afm.lx(), 100e-9) && close(afm.ly(), 100e-9));
    let rms = real_space_stats(&afm, Detrend::Plane).unwrap().rms_height;
    // The file's own scale, applied once (module docs of the reader: the
    // recorded height_scale is that factor).
    assert!((rms / 4.6879221670601305e-9 - 1.0).abs() < 1e-10, "{rms}");
    // By index and by the data file's name: the same map.
    let by_index = read::read(&path, &channel("1")).unwrap();
    assert_eq!(by_index.heights(), afm.heights());

    let stylus = read::read(&path, &channel("2")).unwrap();
    assert_eq!(stylus.shape(), [1, 3001]);
    let rms = real_space_stats(&stylus, Detrend::Curvature)
        .unwrap()
        .rms_height;
    assert!((rms / 1.2123588824547171e-8 - 1.0).abs() < 1e-10, "{rms}");
    let by_file = read::read(&path, &channel("uncd_stylus_300um_5mar_3_k0HpKJt.txt")).unwrap();
    assert_eq!(by_file.heights(), stylus.heights());

    // The TEM scan states no unit: the metadata's nm, for x and heights.
    let tem = read::read(&path, &channel("0")).unwrap();
    assert_eq!(tem.shape(), [1, 76]);
    assert!(tem.lx() > 200e-9 && tem.lx() < 260e-9, "{}", tem.lx());
}

/// A dataset named without a measurement, or with one it does not hold, or
/// with sizes or units from the caller: errors naming the archive, the
/// format and the measurements there are.
#[test]
fn container_2_needs_a_measurement_and_takes_no_units() {
    let path = data("container-2.zip");
    let e = error_of(&path, &ReadOptions::default(), "3 measurements");
    assert!(
        e.contains("contact.engineering dataset") && e.contains("1: \"gain_control_uncd_35.001\""),
        "{e}"
    );
    error_of(&path, &channel("Phase"), "no measurement \"Phase\"");
    let o = ReadOptions {
        size: Some(SizeSpec::PixelSize(1e-9)),
        ..channel("1")
    };
    error_of(&path, &o, "come from its metadata");
}

/// `index.json` (TopoBank's later exports), the squeezed NetCDF when there is
/// no original file, the metadata's size and unit for a file without them,
/// `height_scale` on unitless heights; broken archives.
#[test]
fn index_json_squeezed_files_and_broken_archives() {
    let matrix = b"0 1 2 3\n1 2 4 8\n2 0 1 5\n";
    let index = r#"{"surfaces": [{"name": "s", "topographies": [
        {"name": "m", "datafile": {"original": "m.txt"}, "size": [4.0, 3.0],
         "unit": "um", "height_scale": 2.0, "detrend_mode": "curvature",
         "is_periodic": true},
        {"name": "q", "datafile": {"squeezed-netcdf": "q.txt"}, "size": [4.0, 3.0],
         "unit": "um", "height_scale": 2.0}]}]}"#;
    let archive = zip_of(&[
        ("index.json", index.as_bytes()),
        ("m.txt", matrix),
        ("q.txt", matrix),
    ]);
    let path = temp("index.zip", &archive);
    let d = dataset(&path).unwrap().unwrap();
    assert_eq!(d.surface, "s");
    assert_eq!(d.measurements[0].detrend, Detrend::Curvature);
    assert!(d.measurements[1].squeezed && d.measurements[1].detrend == Detrend::None);
    let m = read::read(&path, &channel("m")).unwrap();
    assert_eq!((m.lx(), m.ly()), (4e-6, 3e-6));
    assert!(m.periodic());
    assert_eq!(m.heights()[5], 2.0 * 2.0 * 1e-6);
    // The squeezed file: scaled already.
    let q = read::read(&path, &channel("q")).unwrap();
    assert_eq!(q.heights()[5], 2.0 * 1e-6);
    // Not a dataset: a zip without metadata stays an unsupported zip.
    assert!(dataset(&temp("plain.zip", &zip_of(&[("m.txt", matrix)])))
        .unwrap()
        .is_none());

    let broken: [(&str, String, &str); 6] = [
        (
            "nofile.zip",
            index.replace("\"m.txt\"", "\"gone.txt\""),
            "no readable member \"gone.txt\"",
        ),
        (
            "unit.zip",
            index.replacen("\"um\"", "\"V\"", 1),
            "unit \"V\" is not a length",
        ),
        (
            "detrend.zip",
            index.replace("curvature", "slope"),
            "detrend_mode \"slope\"",
        ),
        (
            "size.zip",
            index.replacen("[4.0, 3.0]", "[-4.0]", 1),
            "size: not one or two positive numbers",
        ),
        (
            "two.zip",
            index.replace("]}]}", "]}, {\"name\": \"t\"}]}"),
            "lists 2 surfaces (s, t)",
        ),
        (
            "nounit.zip",
            index.replacen("\"unit\": \"um\", ", "", 1),
            "measurement \"m\" (m.txt): neither the file nor the dataset's metadata give the unit",
        ),
    ];
    for (name, meta, needle) in broken {
        let p = temp(
            name,
            &zip_of(&[("index.json", meta.as_bytes()), ("m.txt", matrix)]),
        );
        error_of(&p, &channel("m"), needle);
    }
    // Truncated archives: an error naming the file, never a panic.
    for cut in [10, archive.len() / 2, archive.len() - 10] {
        let p = temp(&format!("cut{cut}.zip"), &archive[..cut]);
        assert!(read::read(&p, &channel("m")).is_err());
    }
}

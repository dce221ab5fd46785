//! A contact.engineering dataset as a multi-scale surface: the same
//! combined spectrum as its measurements read one by one, each with the
//! units and detrending its metadata give.
#![cfg(feature = "topography")]

use std::io::Read;
use std::path::{Path, PathBuf};

use persson::names::Detrend;
use persson_studies::input::multiscale::multi_scale;
use persson_studies::scene::{HeightMapSpec, LengthUnitName};

fn container() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/container-2.zip")
}

/// The members of the archive, extracted into a scratch directory.
fn extracted(names: &[&str]) -> Vec<PathBuf> {
    let dir = std::env::temp_dir().join(format!("persson-dataset-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bytes = std::fs::read(container()).unwrap();
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(bytes)).unwrap();
    names
        .iter()
        .map(|n| {
            let mut data = Vec::new();
            zip.by_name(n).unwrap().read_to_end(&mut data).unwrap();
            let p = dir.join(n);
            std::fs::write(&p, data).unwrap();
            p
        })
        .collect()
}

#[test]
fn a_dataset_combines_as_its_measurements_read_one_by_one() {
    let whole = multi_scale(&[HeightMapSpec::new(container())]).unwrap();
    let files = extracted(&[
        "80_Scale10.472_FIXEDv2p1_D7eHXiT.asc",
        "gain_control_uncd_35_z03tr3R.001",
        "uncd_stylus_300um_5mar_3_k0HpKJt.txt",
    ]);
    let one = |file: &Path, unit: Option<LengthUnitName>, detrend| HeightMapSpec {
        height_unit: unit,
        lateral_unit: unit,
        detrend: Some(detrend),
        ..HeightMapSpec::new(file.to_path_buf())
    };
    let by_one = multi_scale(&[
        one(&files[0], Some(LengthUnitName::Nm), Detrend::Plane),
        one(&files[1], None, Detrend::Plane),
        one(&files[2], Some(LengthUnitName::Mm), Detrend::Curvature),
    ])
    .unwrap();
    assert_eq!(whole.q, by_one.q);
    assert_eq!(whole.c, by_one.c);
    assert_eq!(whole.count, by_one.count);
    assert!(whole.q.len() > 12, "{} bins", whole.q.len());
    // Each measurement's band, named by the archive and the measurement.
    let labels: Vec<String> = whole
        .measurements
        .iter()
        .map(|m| m.file.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        labels,
        [
            "container-2.zip#80_Scale10.472_FIXEDv2p1.asc",
            "container-2.zip#gain_control_uncd_35.001",
            "container-2.zip#uncd_stylus_300um_5mar_3.txt"
        ]
    );
    for (w, o) in whole.measurements.iter().zip(&by_one.measurements) {
        assert_eq!(
            (w.q_min, w.q_max, w.rms_height),
            (o.q_min, o.q_max, o.rms_height)
        );
    }
    // A detrending given for the dataset replaces the metadata's.
    let mean = HeightMapSpec {
        detrend: Some(Detrend::Mean),
        ..HeightMapSpec::new(container())
    };
    let m = multi_scale(&[mean]).unwrap();
    assert_ne!(
        m.measurements[2].rms_height,
        whole.measurements[2].rms_height
    );
}

//! `persson bem rough --plot` (issue 15): the pressure map with its colour
//! bar and the histogram with the plastic δ-peak at σY.
#![cfg(all(feature = "bem", feature = "plot"))]

use persson::bem::rough::{
    rough_contact, rough_contact_mapped, RoughOptions, SurfaceOrigin, MAPPED_CONTACT_FRACTION,
};
use persson::bem::surface::synthesize;
use persson::bem::Options;
use persson::spectrum::{Amplitude, SelfAffine};
use persson_studies::plot::map::{rough_map, MAP_SIZE, PRESSURE_LABEL};
use persson_studies::plot::render_svg_string;
use persson_studies::table::number;

/// The eight bytes every PNG file starts with (PNG spec §5.2).
const PNG_SIGNATURE: [u8; 8] = [137, 80, 78, 71, 13, 10, 26, 10];

/// The plastic nodes' colour in the SVG (RGB 214, 39, 40).
const PLASTIC_FILL: &str = "fill=\"#D62728\"";

fn report(n: usize, y: Option<f64>, mapped: bool) -> persson::bem::rough::RoughReport {
    let ql = std::f64::consts::TAU;
    let s = SelfAffine::new(
        ql,
        4.0 * ql,
        ql * n as f64 / 4.0,
        0.8,
        Amplitude::RmsSlope(0.1),
    )
    .unwrap();
    let surface = synthesize(&s, n, 1.0, 1).unwrap();
    let source = SurfaceOrigin::synthesised(&s, 1).unwrap();
    let options = RoughOptions {
        solver: Options {
            tolerance: 1e-10,
            warm_start: true,
            yield_stress: y,
            ..Options::default()
        },
        bins: Some(20),
        ..RoughOptions::default()
    };
    let f = if mapped {
        rough_contact_mapped
    } else {
        rough_contact
    };
    f(&surface, source, 1.0, &[0.004, 0.006], &options, &mut ()).unwrap()
}

#[test]
fn map_marks_every_plastic_node_and_labels_the_peak() {
    let (n, y) = (32, 0.02);
    let r = report(n, Some(y), true);
    let map = r.pressure_map.as_ref().unwrap();
    // The field of the solve in partial contact whose A/A0 is nearest 0.1.
    let distance = |k: usize| (r.points[k].contact_fraction - MAPPED_CONTACT_FRACTION).abs();
    let k = if distance(1) < distance(0) { 1 } else { 0 };
    assert_eq!(map.index, k);
    assert_eq!(map.nominal_pressure, [0.004, 0.006][k]);
    let plastic = map.pressure.iter().filter(|&&p| p >= y).count();
    assert_eq!(
        plastic as f64 / (n * n) as f64,
        r.points[k].plastic_fraction.unwrap()
    );
    let fig = rough_map(&r).unwrap();
    let svg = render_svg_string(&fig).unwrap();
    assert!(svg.starts_with("<svg"));
    assert!(
        svg.contains(&format!("{PRESSURE_LABEL} (E*)")),
        "colour bar label (E* = 1: pressures in units of E*)"
    );

    let label = format!(
        "δ-peak at σY = {}: A_pl/A0 = {}",
        number(y, 4),
        number(r.points[k].plastic_fraction.unwrap(), 4)
    );
    assert!(svg.contains(&label), "no {label}");
    // One red cell per plastic node (32² ≤ MAP_CELLS²: no blocks), plus the
    // colour bar's σY band, the peak's bar and its legend glyph.
    assert!(plastic > 0);
    assert_eq!(svg.matches(PLASTIC_FILL).count(), plastic + 3);
}

#[test]
fn elastic_map_has_no_plastic_marks_and_writes_png() {
    let r = report(32, None, true);
    let svg = render_svg_string(&rough_map(&r).unwrap()).unwrap();
    assert_eq!(svg.matches(PLASTIC_FILL).count(), 0);
    assert!(!svg.contains("δ-peak"));
    let dir = std::env::temp_dir().join(format!("persson-bem-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("map.png");
    persson_studies::plot::render(&rough_map(&r).unwrap(), &path).unwrap();
    let bytes = std::fs::read(&path).unwrap();
    assert_eq!(bytes[..8], PNG_SIGNATURE);
    let w = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    assert_eq!((w, h), MAP_SIZE);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unmapped_report_keeps_no_field() {
    let (a, b) = (report(32, Some(0.02), false), report(32, Some(0.02), true));
    assert!(a.pressure_map.is_none());
    assert!(rough_map(&a).is_err());
    // Same solves either way (but the wall time).
    for (p, q) in a.points.iter().zip(&b.points) {
        assert_eq!(p.contact_fraction, q.contact_fraction);
        assert_eq!(p.plastic_fraction, q.plastic_fraction);
        assert_eq!(p.iterations, q.iterations);
    }
}

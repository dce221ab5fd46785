//! The subsurface colour maps (issue 27): the Hertz vertical section's
//! numbers against Johnson's axis maximum, and the figures drawn from them.
#![cfg(all(feature = "bem", feature = "plot"))]

use persson::bem::hertz::HertzCase;
use persson::bem::{Boundary, Options};
use persson_studies::bem_detail::hertz_section_figure;
use persson_studies::bem_detail::{hertz_section, hertz_subsurface};
use persson_studies::plot::render;
use persson_studies::plot::stress_map::{von_mises_plane, FieldFigure};

/// Johnson (1985) §3.4 for ν = 0.3: on the axis σ_vM = σ_r − σ_z = 2τ,
/// largest 2 · 0.3107 p0 at z = 0.4807 a (golden section on the closed
/// forms, crates/persson-cli/tests/suite/bem_detail.rs).
const VM_MAX: f64 = 2.0 * 0.3107;
const VM_DEPTH: f64 = 0.4807;

#[test]
fn hertz_section_peaks_on_the_axis_at_johnsons_depth() {
    let case = HertzCase::new(64, Boundary::Free);
    let r = hertz_subsurface(&case, &Options::default(), 0.3, &mut |_| {}).unwrap();
    let s = hertz_section(&r).unwrap();
    assert_eq!(s.von_mises_stress.len(), s.columns * s.depths);
    // The section spans ±3a (a = 0.1, Δ = 1/64: 19 cells either side).
    assert!((s.offset_range.0 + 3.0).abs() < 0.16 && (s.offset_range.1 - 3.0).abs() < 0.16);
    let (k, j, v) = (0..s.depths)
        .flat_map(|k| (0..s.columns).map(move |j| (k, j)))
        .map(|(k, j)| (k, j, s.von_mises_stress[k * s.columns + j]))
        .max_by(|a, b| a.2.total_cmp(&b.2))
        .unwrap();
    // The largest σ_vM lies on the axis column ...
    let dx = (s.offset_range.1 - s.offset_range.0) / s.columns as f64;
    let centre = s.offset_range.0 + (j as f64 + 0.5) * dx;
    assert!(centre.abs() < dx, "at {centre} a");
    // ... at Johnson's depth within one plane (2a/32) ...
    let z = (k as f64 + 0.5) * 2.0 / s.depths as f64;
    assert!(
        (z - VM_DEPTH).abs() <= 2.0 / s.depths as f64,
        "at z = {z} a"
    );
    // ... and value within the axis profile's discretisation error at 64²
    // (max |Δσ|/p0 < 1e-2 per component, so < 2e-2 for σ_r − σ_z).
    assert!((v - VM_MAX).abs() < 2e-2, "{v}");
}

#[test]
fn field_figures_are_drawn_and_bad_ones_refused() {
    let dir = std::env::temp_dir().join(format!("persson-stress-map-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let n = 200; // above the 128 cells drawn: blocks of 2 × 2
    let vm: Vec<f64> = (0..n * n).map(|k| (k % n) as f64).collect();
    let fig = von_mises_plane(&vm, n, 1.0, 0.01, 0.02, "E*");
    for name in ["plane.svg", "plane.png"] {
        let p = dir.join(name);
        render(&fig, &p).unwrap();
        assert!(std::fs::metadata(&p).unwrap().len() > 1000, "{name}");
    }
    let svg = std::fs::read_to_string(dir.join("plane.svg")).unwrap();
    assert!(svg.contains("Von Mises stress at z = 0.01 m"), "title");
    assert!(svg.contains("σ_vM (E*)"), "colour bar label");
    let short = FieldFigure {
        values: vec![0.0; 3],
        ..fig.clone()
    };
    let e = render(&short, &dir.join("short.svg")).unwrap_err();
    assert!(e.to_string().contains("stress map"), "{e}");
    assert!(render(&fig, &dir.join("plane.pdf")).is_err());
    let case = HertzCase::new(32, Boundary::Periodic);
    let r = hertz_subsurface(&case, &Options::default(), 0.3, &mut |_| {}).unwrap();
    let s = hertz_section(&r).unwrap();
    let p = dir.join("section.svg");
    render(&hertz_section_figure(&r, &s), &p).unwrap();
    let svg = std::fs::read_to_string(&p).unwrap();
    assert!(svg.contains("depth z / a") && svg.contains("σ_vM / p0"));
    std::fs::remove_dir_all(&dir).ok();
}

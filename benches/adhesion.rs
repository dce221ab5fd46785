//! Adhesion theory timings: the stickiness scan, one adhesive point (the
//! moving-boundary Volterra solve on two meshes) in the bulk and near
//! pull-off, and a rubber case in physical units.
//!
//! Run: `cargo bench --bench adhesion`

use persson::adhesion::{AdhesionModel, AdhesiveContact};
use persson::spectrum::{Amplitude, SelfAffine};

fn main() {
    divan::main();
}

/// q_l = 1, q_r = 2, q_s = 100, H = 0.8, h'_rms = 0.5, E* = 1 (tests/adhesion.rs).
fn test_spectrum() -> SelfAffine {
    SelfAffine::new(1.0, 2.0, 100.0, 0.8, Amplitude::RmsSlope(0.5)).unwrap()
}

/// Δγ_eff(ζ) scan with sign changes, rubber (E* = 1 MPa) on q_l = 1e4 … q_s = 1e8.
#[divan::bench]
fn stickiness_rubber() -> bool {
    let s = SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
    let m = AdhesionModel::new(&s, 1e6, divan::black_box(0.05)).unwrap();
    m.stickiness(&[10.0, 1e3, 1e4]).unwrap().sticky
}

/// A/A0 at σ0 = 0.05 E*, ζ = 100, default tolerance 1e-5.
#[divan::bench]
fn point_compressive() -> f64 {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(0.05), 100.0)
        .unwrap()
        .contact_fraction
}

/// A/A0 at σ0 = 0 (the adhesive contact under no load), tolerance 1e-5.
#[divan::bench]
fn point_zero_load() -> f64 {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(0.0), 100.0)
        .unwrap()
        .contact_fraction
}

/// A/A0 at σ0 = −0.99 σ_p (close to pull-off), tolerance 1e-5.
#[divan::bench]
fn point_near_pull_off() -> f64 {
    let s = test_spectrum();
    let m = AdhesionModel::new(&s, 1.0, 0.01).unwrap();
    let sp = m.pull_off_stress().unwrap().value;
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(-0.99 * sp), 100.0)
        .unwrap()
        .contact_fraction
}

/// Rubber, sticky (Δγ = 0.2 J/m², E* = 1 MPa, ζ_max = 1e4): A/A0 at σ0 = 0.
#[divan::bench]
fn point_rubber_zero_load() -> f64 {
    let s = SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
    let m = AdhesionModel::new(&s, 1e6, 0.2).unwrap();
    let c = AdhesiveContact::new(m);
    c.point(divan::black_box(0.0), 1e4)
        .unwrap()
        .contact_fraction
}

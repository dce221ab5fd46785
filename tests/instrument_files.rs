//! Readers on files written by instruments and by other programs
//! (`tests/data/`, origins and licences in `tests/data/README.md`), against
//! SurfaceTopography's numbers for the same files
//! (`tests/reference/instrument_files.py` → `instrument_files.rs`), and the
//! cases of issue 20 that printed a wrong number or refused a legal file.
#![cfg(feature = "topography")]

use std::f64::consts::TAU;
use std::path::{Path, PathBuf};

use persson::topography::read::{self, Format, LengthUnit, ReadOptions, SizeSpec};
use persson::topography::{analyse, AnalysisOptions, Layout, Note, Topography};

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
        fill_undefined: name.contains("xyz-2") || name.ends_with(".x3p"),
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
            a.rms_curvature,
            m.rms_laplacian,
            tol,
        );
        // SurfaceTopography's rms_curvature_from_area is the mean curvature ∇²h/2.
        check(
            w,
            &format!("{} mean curvature", m.file),
            a.rms_curvature / 2.0,
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
                tol,
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

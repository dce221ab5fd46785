//! What the format tests share: the files, scratch copies, errors and the
//! comparison with SurfaceTopography.

use std::path::{Path, PathBuf};

use persson::topography::read::{self, ReadOptions};

/// Agreement with SurfaceTopography where both read the same numbers: the
/// same stencils, detrending and sums over the same values in another
/// order (measured: below 1e-12).
pub const ST_AGREEMENT: f64 = 1e-10;
/// Heights written as decimals and read back: one rounding of a product.
pub const ONE_ROUNDING: f64 = 4.0 * f64::EPSILON;

/// A file of `tests/data/`.
pub fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

/// `bytes` written to a scratch file `name`.
pub fn temp(name: &str, bytes: &[u8]) -> PathBuf {
    let d = std::env::temp_dir().join(format!("persson-formats-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

/// The error of reading `path`; asserts that it names the file and says `needle`.
pub fn error_of(path: &Path, options: &ReadOptions, needle: &str) -> String {
    let e = read::read(path, options).expect_err(needle).to_string();
    let name = path.file_name().unwrap().to_string_lossy();
    assert!(e.contains(&*name), "{e:?} does not name {name}");
    assert!(e.contains(needle), "{e:?} does not say {needle:?}");
    assert!(!e.contains('\n'), "{e:?} is not one line");
    e
}

/// `a` equals `b` to one rounding of a product of decimals.
pub fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= ONE_ROUNDING * b.abs().max(1.0)
}

/// `t` against SurfaceTopography's reading of the same file: heights
/// `h[ix, iy]` and the rms height, gradient and Laplacian after the plane,
/// all in SurfaceTopography's unit (`unit` metres); the rms values to `tol`.
pub fn agrees_with_st(
    t: &persson::topography::Topography,
    unit: f64,
    points: &[((usize, usize), f64)],
    [height, gradient, laplacian]: [f64; 3],
    tol: f64,
) {
    use persson::topography::{real_space_stats, Detrend};
    let nx = t.shape()[1];
    for &((ix, iy), st) in points {
        let h = t.heights()[iy * nx + ix];
        assert!(close(h, st * unit), "({ix}, {iy}): {h} against {st}");
    }
    let s = real_space_stats(t, Detrend::Plane).unwrap();
    for (got, want) in [
        (s.rms_height, height * unit),
        (s.rms_slope, gradient),
        (s.rms_curvature.unwrap(), laplacian / unit),
    ] {
        assert!((got / want - 1.0).abs() < tol, "{got} against {want}");
    }
}

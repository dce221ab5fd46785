//! Contact-patch statistics (issue 27): known discs give the exact count and
//! areas, periodic wrap joins a patch cut by the boundary, 4- against
//! 8-connectivity, perimeters, the log-binned distribution, and the
//! exponential/Gaussian tail fit on samples of known shape.
#![cfg(feature = "bem")]

use persson::bem::patches::{
    patch_statistics, pressure_tail, Connectivity, PatchOptions, TailShape,
};
use persson::bem::Boundary;
use persson::Error;

/// Cells of a disc of radius r (cells) centred at (ci, cj) on a periodic or
/// clipped n-grid: those whose centre lies inside, counted independently.
fn disc(mask: &mut [bool], n: usize, ci: f64, cj: f64, r: f64, periodic: bool) -> usize {
    let mut count = 0;
    let reach = r.ceil() as i64 + 1;
    for di in -reach..=reach {
        for dj in -reach..=reach {
            let (i, j) = (ci.floor() as i64 + di, cj.floor() as i64 + dj);
            let (x, y) = (i as f64 - ci, j as f64 - cj);
            if x * x + y * y > r * r {
                continue;
            }
            let (a, b) = if periodic {
                (i.rem_euclid(n as i64), j.rem_euclid(n as i64))
            } else if i < 0 || j < 0 || i >= n as i64 || j >= n as i64 {
                continue;
            } else {
                (i, j)
            };
            let k = a as usize * n + b as usize;
            assert!(!mask[k], "discs overlap");
            mask[k] = true;
            count += 1;
        }
    }
    count
}

#[test]
fn known_discs_give_the_exact_count_and_areas() {
    let (n, size) = (128, 2.0);
    let cell = (size / n as f64).powi(2);
    let mut mask = vec![false; n * n];
    // Discs far apart (gaps ≥ 2 cells), radii 0.5 … 12 cells.
    let discs = [
        (20.3, 20.7, 12.0),
        (20.0, 70.0, 6.5),
        (70.5, 25.5, 3.2),
        (90.0, 90.0, 9.9),
        (60.0, 60.0, 0.5),
        (100.0, 30.0, 1.5),
    ];
    let mut cells: Vec<usize> = discs
        .iter()
        .map(|&(ci, cj, r)| disc(&mut mask, n, ci, cj, r, false))
        .collect();
    for connectivity in [Connectivity::Four, Connectivity::Eight] {
        for boundary in [Boundary::Periodic, Boundary::Free] {
            let o = PatchOptions {
                connectivity,
                boundary,
                bins_per_decade: 4,
            };
            let s = patch_statistics(&mask, n, size, &o).unwrap();
            assert_eq!(s.patch_count, discs.len(), "{connectivity:?} {boundary:?}");
            let mut got: Vec<usize> = s.patches.iter().map(|p| p.cells).collect();
            got.sort_unstable();
            cells.sort_unstable();
            assert_eq!(got, cells);
            for p in &s.patches {
                assert_eq!(p.area, p.cells as f64 * cell);
            }
            assert_eq!(s.largest_patch_area, *cells.last().unwrap() as f64 * cell);
            let total: usize = cells.iter().sum();
            assert_eq!(s.contact_fraction, total as f64 / (n * n) as f64);
            // The distribution integrates to one and counts every patch.
            let integral: f64 = s
                .area_distribution
                .iter()
                .map(|b| b.density * (b.area_high - b.area_low))
                .sum();
            assert!((integral - 1.0).abs() < 1e-12);
            assert_eq!(
                s.area_distribution.iter().map(|b| b.count).sum::<usize>(),
                discs.len()
            );
        }
    }
}

#[test]
fn periodic_wrap_joins_a_patch_cut_by_the_boundary() {
    let n = 64;
    let mut mask = vec![false; n * n];
    // A disc centred on a corner: four pieces on the grid, one patch with wrap.
    let cells = disc(&mut mask, n, 0.0, 0.0, 5.0, true);
    // A disc across the left/right edge: two pieces.
    disc(&mut mask, n, 30.0, 63.5, 4.0, true);
    let periodic = PatchOptions::default();
    let s = patch_statistics(&mask, n, 1.0, &periodic).unwrap();
    assert_eq!(s.patch_count, 2);
    assert!(s.patches.iter().any(|p| p.cells == cells));
    let free = PatchOptions {
        boundary: Boundary::Free,
        ..periodic
    };
    assert_eq!(
        patch_statistics(&mask, n, 1.0, &free).unwrap().patch_count,
        6
    );
    // 8-connectivity across the corner of the grid: cells (0, 0) and (n−1, n−1).
    let mut m = vec![false; n * n];
    m[0] = true;
    m[n * n - 1] = true;
    let eight = PatchOptions {
        connectivity: Connectivity::Eight,
        ..periodic
    };
    assert_eq!(patch_statistics(&m, n, 1.0, &eight).unwrap().patch_count, 1);
    assert_eq!(
        patch_statistics(&m, n, 1.0, &periodic).unwrap().patch_count,
        2
    );
}

#[test]
fn perimeters_count_exposed_cell_edges() {
    let n = 16;
    let d = 0.5 / n as f64;
    let mut m = vec![false; n * n];
    // A 3 × 4 rectangle: perimeter 2(3 + 4) edges; an L of 3 cells: 8 edges.
    for i in 2..5 {
        for j in 3..7 {
            m[i * n + j] = true;
        }
    }
    for k in [10 * n + 10, 10 * n + 11, 11 * n + 10] {
        m[k] = true;
    }
    let s = patch_statistics(&m, n, 0.5, &PatchOptions::default()).unwrap();
    assert_eq!(s.patches[0].perimeter, 14.0 * d);
    assert_eq!(s.patches[1].perimeter, 8.0 * d);
    assert_eq!(s.total_perimeter, 22.0 * d);
    // A full row on a periodic grid has no left or right edge; on a free grid it has.
    let mut row = vec![false; n * n];
    row[..n].fill(true);
    let p = patch_statistics(&row, n, 0.5, &PatchOptions::default()).unwrap();
    assert_eq!(
        (p.patch_count, p.patches[0].perimeter),
        (1, 2.0 * n as f64 * d)
    );
    let free = PatchOptions {
        boundary: Boundary::Free,
        ..PatchOptions::default()
    };
    let f = patch_statistics(&row, n, 0.5, &free).unwrap();
    assert_eq!(f.patches[0].perimeter, (2.0 * n as f64 + 2.0) * d);
}

/// Deterministic quantiles of a distribution: F⁻¹((k + ½)/m).
fn quantiles(m: usize, inv: impl Fn(f64) -> f64) -> Vec<f64> {
    (0..m).map(|k| inv((k as f64 + 0.5) / m as f64)).collect()
}

#[test]
fn tail_fits_recover_known_shapes() {
    // Exponential tail beyond p_t = 1 with λ = 0.3: the fit names it and finds λ.
    let exp: Vec<f64> = quantiles(20_000, |u| 1.0 - 0.3 * (1.0 - u).ln());
    let t = pressure_tail(&exp, Some(1.0)).unwrap();
    assert_eq!(t.better, TailShape::Exponential);
    assert!(
        (t.exponential_scale - 0.3).abs() < 1e-3,
        "{}",
        t.exponential_scale
    );
    // Half-normal of width s = 2 (p_t = 0): s² = ⟨p²⟩, named Gaussian.
    let half: Vec<f64> = quantiles(20_000, |u| 2.0 * std::f64::consts::SQRT_2 * inv_erf(u));
    let g = pressure_tail(&half, Some(1e-300)).unwrap();
    assert_eq!(g.better, TailShape::Gaussian);
    assert!(
        (g.gaussian_width - 2.0).abs() < 2e-3,
        "{}",
        g.gaussian_width
    );
    // The Gaussian tail beyond p_t = 3 of the same half-normal: the truncated fit keeps s = 2.
    let tail: Vec<f64> = half.iter().copied().filter(|&p| p >= 3.0).collect();
    let g3 = pressure_tail(&tail, Some(3.0)).unwrap();
    assert_eq!(g3.better, TailShape::Gaussian);
    assert!(
        (g3.gaussian_width - 2.0).abs() < 0.02,
        "{}",
        g3.gaussian_width
    );
    match pressure_tail(&[1.0, 2.0, 3.0], None) {
        Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, "tail_start"),
        other => panic!("{other:?}"),
    }
}

/// erf⁻¹ by Newton on libm-free erf (series/continued fraction through the crate is private).
fn inv_erf(y: f64) -> f64 {
    let erf = |x: f64| {
        persson::asperity::gw_integral(0.0, -x * std::f64::consts::SQRT_2).unwrap() * 2.0 - 1.0
    };
    let mut x = 0.0;
    for _ in 0..100 {
        let e = erf(x) - y;
        let dx = e / (2.0 / std::f64::consts::PI.sqrt() * (-x * x).exp());
        x -= dx;
        if dx.abs() < 1e-15 {
            break;
        }
    }
    x
}

#[test]
fn bad_input() {
    assert!(patch_statistics(&[true; 10], 3, 1.0, &PatchOptions::default()).is_err());
    let o = PatchOptions {
        bins_per_decade: 0,
        ..PatchOptions::default()
    };
    match patch_statistics(&[true; 9], 3, 1.0, &o) {
        Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, "bins_per_decade"),
        other => panic!("{other:?}"),
    }
    // No contact: zero patches, an empty distribution.
    let s = patch_statistics(&[false; 9], 3, 1.0, &PatchOptions::default()).unwrap();
    assert_eq!((s.patch_count, s.area_distribution.len()), (0, 0));
}

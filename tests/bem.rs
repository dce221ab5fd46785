//! Boundary-element solver: Hertz validation, rough-surface invariants,
//! synthesis statistics, height-map I/O and bad input (issue 4).
#![cfg(feature = "bem")]

use persson::bem::surface::{expected_rms, read_height_map, synthesize};
use persson::bem::{hertz, Boundary, Control, GridSurface, Operator, Options, Solver};
use persson::io::npy::write as write_npy;
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::Error;

/// Molinari, EPFL lecture "From single asperity to multi asperity contact",
/// Table 1: free-boundary η for 64² and 128².
const LECTURE_FREE: [(usize, f64); 2] = [(64, 1.40e-2), (128, 4.08e-3)];

/// Free boundary at 256²: we measure η = 1.035e-3 (Love cell kernel), above
/// the lecture's 7.78e-4 (see README: the lecture's η is not the 𝒢-norm).
/// The bound guards against regressions of our discretisation.
const FREE_256_BOUND: f64 = 1.05e-3;

/// Periodic reference discrete solution (Tamaas 2.9 PolonskyKeerRey, same
/// grid, load and kernel, measured η): 3.099e-3 at 128², 1.443e-3 at 256².
const PERIODIC_REFERENCE: [(usize, f64); 2] = [(128, 3.099e-3), (256, 1.443e-3)];

/// Relative agreement with the reference discrete solution: both solves stop
/// at ε ≤ 1e-12, so η agrees to far better than this.
const REFERENCE_REL_TOL: f64 = 1e-3;

/// Load balance: the rescaling step makes Σp/N² exact up to rounding of a
/// sum of N² terms.
const LOAD_REL_TOL: f64 = 1e-12;

/// Contact nodes of the seeded rough solve (seed 42, 128², σ0 = 0.002 E*,
/// ε ≤ 1e-12), measured; A/A0 = nodes/128².
const ROUGH_PINNED_CONTACT_NODES: f64 = 848.0;

/// Nodes the pinned count may move by: rounding of the FFTs on another
/// platform can flip a node at the edge of the contact (a pressure within
/// rounding of zero); any change of the surface or the solver moves more.
const ROUGH_PINNED_NODES: f64 = 2.0;

fn tight() -> Options {
    Options {
        tolerance: 1e-12,
        ..Options::default()
    }
}

#[test]
fn hertz_free_beats_the_lecture_at_64_and_128() {
    for (n, lecture) in LECTURE_FREE {
        let r = hertz::validate(&hertz::HertzCase::new(n, Boundary::Free), &tight()).unwrap();
        assert!(
            r.energy_error < lecture,
            "N = {n}: η = {:e} ≥ {lecture:e}",
            r.energy_error
        );
        // The fitted radius and peak are within 0.3 % already at 64².
        assert!(
            r.contact_radius_error < 3e-3 && r.peak_pressure_error < 3e-3,
            "{r:?}"
        );
    }
}

#[test]
fn hertz_free_256() {
    let r = hertz::validate(&hertz::HertzCase::new(256, Boundary::Free), &tight()).unwrap();
    assert!(r.energy_error < FREE_256_BOUND, "η = {:e}", r.energy_error);
    // a and p₀ from the fit: 2.8e-5 and 1.1e-4 measured.
    assert!(
        r.contact_radius_error < 1e-4 && r.peak_pressure_error < 5e-4,
        "{r:?}"
    );
    // A/A0 → π a² = 0.0314159: within 1.5 % at 256².
    assert!((r.contact_fraction / (std::f64::consts::PI * 0.01) - 1.0).abs() < 1.5e-2);
}

/// 𝒢p_ex against the exact displacement u_ex (free operator, absolute
/// displacements): the largest nodal difference, relative to δ = a²/R, is
/// set by the cells cut by the contact edge and falls like N^−1.5 (measured
/// 9.8e-3 at 64², 3.3e-3 at 128²).
const DISPLACEMENT_128_BOUND: f64 = 5e-3;

#[test]
fn free_operator_reproduces_the_hertz_displacement() {
    let mut worst = Vec::new();
    for n in [64, 128] {
        let case = hertz::HertzCase::new(n, Boundary::Free);
        let mut op = Operator::new(Boundary::Free, n, 1.0, 1.0).unwrap();
        let mut u = vec![0.0; n * n];
        op.apply(&case.exact_pressure(), &mut u).unwrap();
        let err = u
            .iter()
            .zip(&case.exact_displacement())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        worst.push(err / 0.01);
    }
    assert!(worst[1] < DISPLACEMENT_128_BOUND, "{worst:?}");
    // Convergence, not luck: at least the N^−1.5 factor 2.8 (measured 3.0).
    assert!(worst[0] / worst[1] > 2.5, "{worst:?}");
}

/// η_L from the library against the same sums written out here with
/// Johnson's displacement as printed (3.41a/3.42a; the library evaluates the
/// outer branch in a cancellation-free form): rounding only.
const LECTURE_MEASURE_REL_TOL: f64 = 1e-9;

#[test]
fn hertz_lecture_measure_is_reported_for_the_free_boundary_only() {
    let n = 64;
    let case = hertz::HertzCase::new(n, Boundary::Free);
    let r = hertz::validate(&case, &tight()).unwrap();
    let mut s = Solver::new(Operator::new(Boundary::Free, n, 1.0, 1.0).unwrap());
    let sol = s
        .solve(
            &case.heights(),
            Control::MeanPressure(case.mean_pressure()),
            &tight(),
        )
        .unwrap();
    let (a, p0) = (case.contact_radius, case.peak_pressure());
    let johnson = |r: f64| {
        if r <= a {
            std::f64::consts::PI * p0 * (2.0 * a * a - r * r) / (4.0 * a)
        } else {
            p0 / (2.0 * a) * ((2.0 * a * a - r * r) * (a / r).asin() + a * (r * r - a * a).sqrt())
        }
    };
    let (mut num, mut den) = (0.0, 0.0);
    for ((r, p), u) in case
        .radii()
        .iter()
        .zip(&sol.pressure)
        .zip(&sol.displacement)
    {
        let (pe, ue) = (persson::reference::pressure_profile(*r, a, p0), johnson(*r));
        num += (u - ue) * (p - pe);
        den += ue * pe;
    }
    let want = (num.abs() / den).sqrt();
    let got = r.energy_error_displacement.unwrap();
    assert!(
        (got / want - 1.0).abs() < LECTURE_MEASURE_REL_TOL,
        "η_L = {got:e} vs {want:e}"
    );
    // Not the η: measured 1.24e-3 against η = 1.13e-2 at 64².
    assert!(got < 0.2 * r.energy_error);
    let r = hertz::validate(&hertz::HertzCase::new(n, Boundary::Periodic), &tight()).unwrap();
    assert_eq!(r.energy_error_displacement, None);
}

#[test]
fn hertz_periodic_equals_reference_discrete_solution() {
    for (n, reference) in PERIODIC_REFERENCE {
        let r = hertz::validate(&hertz::HertzCase::new(n, Boundary::Periodic), &tight()).unwrap();
        let rel = (r.energy_error / reference - 1.0).abs();
        assert!(
            rel < REFERENCE_REL_TOL,
            "N = {n}: η = {:e} vs {reference:e}",
            r.energy_error
        );
    }
}

#[test]
fn hertz_penetration_control_gives_the_hertz_load() {
    // Free boundary, δ = a²/R with a = 0.1: the mean pressure must be the Hertz
    // load 4a³/3; 128² resolves it to 0.5 % (measured 0.1 %).
    let case = hertz::HertzCase::new(128, Boundary::Free);
    let mut s = Solver::new(Operator::new(Boundary::Free, 128, 1.0, 1.0).unwrap());
    let sol = s
        .solve(&case.heights(), Control::Penetration(0.01), &tight())
        .unwrap();
    assert!(
        (sol.mean_pressure / case.mean_pressure() - 1.0).abs() < 5e-3,
        "{}",
        sol.mean_pressure
    );
    // And load control returns the Hertz approach δ = a²/R.
    let sol = s
        .solve(
            &case.heights(),
            Control::MeanPressure(case.mean_pressure()),
            &tight(),
        )
        .unwrap();
    assert!((sol.approach / 0.01 - 1.0).abs() < 5e-3, "{}", sol.approach);
}

fn rough_spectrum() -> SelfAffine {
    // L = 1: q_l = 2π, roll-off at 4 q_l, cut-off at 32 q_l (N = 128 resolves
    // it with 2 nodes per shortest half-wavelength), H = 0.8, rms slope 0.1.
    let ql = std::f64::consts::TAU;
    SelfAffine::new(ql, 4.0 * ql, 32.0 * ql, 0.8, Amplitude::RmsSlope(0.1)).unwrap()
}

#[test]
fn rough_solve_invariants_and_reproducibility() {
    let spec = rough_spectrum();
    let surf = synthesize(&spec, 128, 1.0, 42).unwrap();
    let again = synthesize(&spec, 128, 1.0, 42).unwrap();
    assert_eq!(surf.heights, again.heights);
    let pressure = 0.002; // E* = 1: A/A0 ≈ 2p/(E* slope) ≈ 4 %
    let mut s = Solver::new(Operator::new(Boundary::Periodic, 128, 1.0, 1.0).unwrap());
    let sol = s
        .solve(&surf.heights, Control::MeanPressure(pressure), &tight())
        .unwrap();
    assert!((sol.mean_pressure / pressure - 1.0).abs() < LOAD_REL_TOL);
    assert!(sol.pressure.iter().all(|p| *p >= 0.0));
    // Zero gap on the contact, none negative elsewhere, relative to σ_h: the
    // stopping rule bounds the p-weighted mean gap by 1e-12 σ_h; pointwise
    // the gap at contact nodes measured ≤ 1e-9 σ_h.
    let sigma = surf.rms_height();
    for (p, g) in sol.pressure.iter().zip(&sol.gap) {
        if *p > 0.0 {
            assert!(g.abs() <= 1e-8 * sigma, "gap {g:e} at p = {p:e}");
        } else {
            assert!(*g >= -1e-8 * sigma, "overlap {g:e}");
        }
    }
    // The displacement is 𝒢p (the solver derives it from the final gap):
    // rounding only, relative to the largest displacement.
    let mut u = vec![0.0; sol.pressure.len()];
    Operator::new(Boundary::Periodic, 128, 1.0, 1.0)
        .unwrap()
        .apply(&sol.pressure, &mut u)
        .unwrap();
    let u_max = u.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let du = u
        .iter()
        .zip(&sol.displacement)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(du < 1e-12 * u_max, "max |Δu| = {du:e} of {u_max:e}");
    // Bit-for-bit reproducible from the seed (fresh solver, same input).
    let mut s2 = Solver::new(Operator::new(Boundary::Periodic, 128, 1.0, 1.0).unwrap());
    let sol2 = s2
        .solve(&again.heights, Control::MeanPressure(pressure), &tight())
        .unwrap();
    assert_eq!(
        sol.contact_fraction.to_bits(),
        sol2.contact_fraction.to_bits()
    );
    assert_eq!(sol.pressure, sol2.pressure);
    // No closed form for a rough contact: the node count of this seeded run
    // (Pcg64Mcg surfaces are value-stable), within ROUGH_PINNED_NODES.
    let nodes = sol.contact_fraction * (128 * 128) as f64;
    assert!(
        (nodes - ROUGH_PINNED_CONTACT_NODES).abs() <= ROUGH_PINNED_NODES,
        "{nodes} nodes in contact, pinned {ROUGH_PINNED_CONTACT_NODES}"
    );
}

#[test]
fn synthesis_is_value_stable_across_versions() {
    // Golden values of seed 7 (Pcg64Mcg + in-house Box–Muller, module docs):
    // a change here changes every user's surfaces.
    let s = synthesize(&rough_spectrum(), 16, 1.0, 7).unwrap();
    let golden = [GOLDEN_0, GOLDEN_1];
    for (h, g) in s.heights.iter().zip(golden) {
        assert!((h - g).abs() <= GOLDEN_REL_TOL * g.abs(), "{h:e} vs {g:e}");
    }
}

/// Heights [0] and [1] of seed 7 on 16² (measured with rustfft 6.4.1).
const GOLDEN_0: f64 = 1.502618957178541e-4;
const GOLDEN_1: f64 = 2.6112469406014166e-4;
/// The random draws are value-stable; the FFT's rounding may change with a
/// rustfft update, by a few ulps of the largest mode.
const GOLDEN_REL_TOL: f64 = 1e-12;

#[test]
fn synthesis_matches_the_spectrum_moments() {
    let spec = rough_spectrum();
    let (n, l) = (64, 1.0);
    // Expectation over the grid's modes equals the spectrum's rms over its
    // band: heights exactly (cell integrals tile the band; 4×4 Gauss on cells
    // cut by the band edges costs < 1 %), slopes to O(Δq²/q²) per cell.
    let (eh, es) = expected_rms(&spec, n, l);
    let h = spec.rms_height(spec.q_min(), spec.q_max()).unwrap().value;
    let sl = spec.rms_slope(spec.q_min(), spec.q_max()).unwrap().value;
    assert!((eh / h - 1.0).abs() < 1e-2, "{eh} vs {h}");
    assert!((es / sl - 1.0).abs() < 2e-2, "{es} vs {sl}");
    // Sample means over 40 seeds: rms height (dominated by ~50 long-wave
    // modes, sampling spread ≈ 1/√(40·50)·… ≈ 3 %) and rms slope (thousands of
    // modes, < 1 %).
    let (mut h2, mut s2) = (0.0, 0.0);
    let seeds = 40;
    for seed in 0..seeds {
        let s = synthesize(&spec, n, l, seed).unwrap();
        h2 += s.rms_height().powi(2);
        s2 += s.rms_slope().unwrap().powi(2);
    }
    let (mh, ms) = ((h2 / seeds as f64).sqrt(), (s2 / seeds as f64).sqrt());
    assert!((mh / eh - 1.0).abs() < 5e-2, "{mh} vs {eh}");
    assert!((ms / es - 1.0).abs() < 1e-2, "{ms} vs {es}");
}

#[test]
fn full_contact_is_an_answer() {
    let surf = synthesize(&rough_spectrum(), 32, 1.0, 3).unwrap();
    let mut s = Solver::new(Operator::new(Boundary::Periodic, 32, 1.0, 1.0).unwrap());
    let sol = s
        .solve(&surf.heights, Control::MeanPressure(10.0), &tight())
        .unwrap();
    assert_eq!(sol.contact_fraction, 1.0);
}

#[test]
fn not_converged_is_an_error() {
    let surf = synthesize(&rough_spectrum(), 64, 1.0, 3).unwrap();
    let mut s = Solver::new(Operator::new(Boundary::Periodic, 64, 1.0, 1.0).unwrap());
    let opts = Options {
        max_iterations: 2,
        ..tight()
    };
    match s.solve(&surf.heights, Control::MeanPressure(0.01), &opts) {
        Err(Error::NotConverged {
            iterations,
            residual,
            ..
        }) => {
            assert_eq!(iterations, 2);
            assert!(residual > 1e-12);
        }
        other => panic!("expected NotConverged, got {other:?}"),
    }
}

#[test]
fn bad_input_is_a_clear_error() {
    assert!(matches!(
        hertz::validate(&hertz::HertzCase::new(4, Boundary::Free), &tight()),
        Err(Error::InvalidParameter { .. })
    ));
    let surf = synthesize(&rough_spectrum(), 16, 1.0, 1).unwrap();
    let mut s = Solver::new(Operator::new(Boundary::Periodic, 16, 1.0, 1.0).unwrap());
    for p in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            s.solve(&surf.heights, Control::MeanPressure(p), &tight()),
            Err(Error::InvalidParameter { .. })
        ));
    }
    let mut h = surf.heights.clone();
    h[5] = f64::INFINITY;
    assert!(GridSurface::new(16, 1.0, h.clone()).is_err());
    assert!(s.solve(&h, Control::MeanPressure(0.1), &tight()).is_err());
    // Memory: a 32768² free solve needs ~100 GiB, more than this machine has.
    let e = persson::bem::check_memory(32768, Boundary::Free).unwrap_err();
    assert!(e.to_string().contains("GiB"), "{e}");
}

fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("persson-bem-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

/// Hand-made `.npy` bytes (version 1.0).
fn npy_bytes(descr: &str, fortran: bool, shape: &str, data: &[u8]) -> Vec<u8> {
    let mut h = format!(
        "{{'descr': '{descr}', 'fortran_order': {}, 'shape': {shape}, }}",
        if fortran { "True" } else { "False" }
    );
    while (10 + h.len() + 1) % 64 != 0 {
        h.push(' ');
    }
    h.push('\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend_from_slice(&(h.len() as u16).to_le_bytes());
    out.extend_from_slice(h.as_bytes());
    out.extend_from_slice(data);
    out
}

#[test]
fn height_maps_round_trip_in_every_layout() {
    let n = 8;
    let h: Vec<f64> = (0..n * n).map(|k| k as f64 * 0.25 - 3.0).collect();
    // f64, C order, via our writer.
    let p = tmp("c.npy");
    write_npy(&p, n, n, &h).unwrap();
    assert_eq!(read_height_map(&p, 2.0).unwrap().heights, h);
    // f64 Fortran order: column-major bytes.
    let mut bytes = Vec::new();
    for j in 0..n {
        for i in 0..n {
            bytes.extend_from_slice(&h[i * n + j].to_le_bytes());
        }
    }
    let p = tmp("f.npy");
    std::fs::write(&p, npy_bytes("<f8", true, "(8, 8)", &bytes)).unwrap();
    assert_eq!(read_height_map(&p, 2.0).unwrap().heights, h);
    // f64 big-endian (the one .npy reader of persson::io reads both byte orders).
    let bytes: Vec<u8> = h.iter().flat_map(|v| v.to_be_bytes()).collect();
    let p = tmp("be.npy");
    std::fs::write(&p, npy_bytes(">f8", false, "(8, 8)", &bytes)).unwrap();
    assert_eq!(read_height_map(&p, 2.0).unwrap().heights, h);
    // f32, C order (the values are exact in f32).
    let bytes: Vec<u8> = h.iter().flat_map(|v| (*v as f32).to_le_bytes()).collect();
    let p = tmp("s.npy");
    std::fs::write(&p, npy_bytes("<f4", false, "(8, 8)", &bytes)).unwrap();
    assert_eq!(read_height_map(&p, 2.0).unwrap().heights, h);
    // Text matrix with a comment.
    let mut text = String::from("# heights\n");
    for i in 0..n {
        let row: Vec<String> = (0..n).map(|j| format!("{}", h[i * n + j])).collect();
        text.push_str(&row.join(" "));
        text.push('\n');
    }
    let p = tmp("h.txt");
    std::fs::write(&p, text).unwrap();
    let s = read_height_map(&p, 2.0).unwrap();
    assert_eq!((s.heights, s.size), (h.clone(), 2.0));
}

#[test]
fn bad_height_maps_name_the_problem() {
    let data = vec![0u8; 8 * 64];
    let cases = [
        ("i8.npy", npy_bytes("<i8", false, "(8, 8)", &data), "dtype"),
        ("3d.npy", npy_bytes("<f8", false, "(4, 4, 4)", &data), "2-D"),
        (
            "rect.npy",
            npy_bytes("<f8", false, "(4, 16)", &data),
            "square",
        ),
        (
            "short.npy",
            npy_bytes("<f8", false, "(8, 8)", &data[..100]),
            "bytes",
        ),
        (
            "small.npy",
            npy_bytes("<f8", false, "(4, 4)", &data[..128]),
            "this one is 4 × 4",
        ),
    ];
    for (name, bytes, needle) in cases {
        let p = tmp(name);
        std::fs::write(&p, bytes).unwrap();
        let e = read_height_map(&p, 1.0).unwrap_err();
        assert!(matches!(e, Error::Parse { .. }), "{name}: {e:?}");
        assert!(e.to_string().contains(needle), "{name}: {e}");
    }
    let p = tmp("nan.txt");
    let mut t = String::new();
    for i in 0..8 {
        let row: Vec<&str> = (0..8)
            .map(|j| if i == 2 && j == 3 { "nan" } else { "1" })
            .collect();
        t.push_str(&row.join(" "));
        t.push('\n');
    }
    std::fs::write(&p, t).unwrap();
    let e = read_height_map(&p, 1.0).unwrap_err();
    assert!(e.to_string().contains("height[2, 3]"), "{e}");
    let p = tmp("ragged.txt");
    std::fs::write(&p, "1 2 3\n4 5\n").unwrap();
    let e = read_height_map(&p, 1.0).unwrap_err();
    assert!(e.to_string().contains(":2:"), "{e}");
}

/// A constant added to the heights changes nothing physical: the solver forms
/// h − max h before anything else, so a large mean height costs no digits in
/// the gap. (Forming u − h + max h instead stalled these solves at ε ≈ 4e-10
/// with heights + 100.) Measured: the same iterations (36 free, 39 periodic)
/// and residuals to 3 digits, with and without the offset.
#[test]
fn a_height_offset_changes_nothing() {
    let surf = synthesize(&rough_spectrum(), 64, 1.0, 7).unwrap();
    let shifted: Vec<f64> = surf.heights.iter().map(|h| h + 100.0).collect();
    let opts = Options {
        tolerance: 1e-11,
        ..Options::default()
    };
    for boundary in [Boundary::Free, Boundary::Periodic] {
        let solve = |h: &[f64]| {
            let mut s = Solver::new(Operator::new(boundary, 64, 1.0, 1.0).unwrap());
            s.solve(h, Control::MeanPressure(0.002), &opts).unwrap()
        };
        let (a, b) = (solve(&surf.heights), solve(&shifted));
        assert!(
            b.iterations <= a.iterations + 1,
            "{boundary:?}: {} vs {} iterations",
            b.iterations,
            a.iterations
        );
        let p_max = a.pressure.iter().copied().fold(0.0, f64::max);
        let dp = a
            .pressure
            .iter()
            .zip(&b.pressure)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert!(dp < 1e-8 * p_max, "{boundary:?}: max |Δp| = {dp:e}");
        assert!((a.approach - b.approach).abs() < 1e-9 * surf.rms_height());
    }
}

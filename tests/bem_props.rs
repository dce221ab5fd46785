//! Property tests of the FFT-BEM solver (issue 8, item 3): random self-affine
//! spectra, seeds, grids (15², 16², 24², 32², periodic and free) and pressures
//! spanning decades. 128 cases of three solves each: ~0.5 s in release.
#![cfg(feature = "bem")]

use persson::bem::histogram::integral;
use persson::bem::rough::{self, RoughOptions};
use persson::bem::surface::synthesize;
use persson::bem::{Boundary, Control, Operator, Options, Solver};
use persson::spectrum::{Amplitude, SelfAffine};
use proptest::prelude::*;

/// Solver tolerance ε of every solve.
const TOL: f64 = 1e-12;

/// Mean pressure against its target: the solver rescales p to the target
/// every step, so only the rounding of an N² sum remains (≤ N² ε_mach ≈ 2e-13
/// at 32²).
const LOAD_REL_TOL: f64 = 1e-12;

/// Pointwise gap on the contact (and overlap off it), relative to the rms
/// height: the stopping rule bounds only the p-weighted mean gap, by TOL σ_h.
/// Measured pointwise over 1024 cases: up to 3.2e-10 σ_h (a bound of 1e-10
/// fails, 1e-8 passes all 1024).
const GAP_REL_TOL: f64 = 1e-8;

/// A random rough contact problem.
#[derive(Debug, Clone)]
struct Case {
    grid: usize,
    boundary: Boundary,
    hurst: f64,
    /// Roll-off and cut-off in units of q_l = 2π/L.
    k_r: f64,
    k_s: f64,
    rms_slope: f64,
    seed: u64,
    /// Three increasing pressures, unit of E* (E* = 1).
    pressures: [f64; 3],
}

fn case() -> impl Strategy<Value = Case> {
    (
        prop_oneof![Just(15usize), Just(16usize), Just(24usize), Just(32usize)],
        prop_oneof![Just(Boundary::Periodic), Just(Boundary::Free)],
        0.05f64..0.95,
        1.0f64..3.0,
        0.0f64..1.0,
        -3.0f64..1.0,
        any::<u64>(),
        -4.0f64..-1.5,
        0.3f64..1.5,
        0.3f64..1.5,
    )
        .prop_map(|(grid, boundary, hurst, k_r, s, ls, seed, lp, d1, d2)| {
            // q_s from k_r + 1 up to the grid's Nyquist wavenumber N/2 − 1.
            let k_s = (k_r + 1.0) + s * (grid as f64 / 2.0 - 2.0 - k_r);
            let rms_slope = 10f64.powf(ls);
            let p0 = 10f64.powf(lp) * rms_slope;
            Case {
                grid,
                boundary,
                hurst,
                k_r,
                k_s,
                rms_slope,
                seed,
                pressures: [p0, p0 * 10f64.powf(d1), p0 * 10f64.powf(d1 + d2)],
            }
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn solutions_satisfy_the_contact_conditions(c in case()) {
        let q = std::f64::consts::TAU;
        let s = SelfAffine::new(q, c.k_r * q, c.k_s * q, c.hurst, Amplitude::RmsSlope(c.rms_slope))
            .unwrap();
        let surf = synthesize(&s, c.grid, 1.0, c.seed).unwrap();
        let n2 = c.grid * c.grid;
        let h_max = surf.heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let sigma = {
            let m = surf.heights.iter().sum::<f64>() / n2 as f64;
            (surf.heights.iter().map(|h| (h - m).powi(2)).sum::<f64>() / (n2 as f64 - 1.0)).sqrt()
        };
        let mut solver = Solver::new(Operator::new(c.boundary, c.grid, 1.0, 1.0).unwrap());
        // An independent operator to recompute the gap from p alone.
        let mut op = Operator::new(c.boundary, c.grid, 1.0, 1.0).unwrap();
        let opts = Options { tolerance: TOL, ..Options::default() };
        let mut last_fraction = 0.0;
        for &p in &c.pressures {
            let sol = solver.solve(&surf.heights, Control::MeanPressure(p), &opts).unwrap();
            prop_assert!(sol.pressure.iter().all(|v| v.is_finite() && *v >= 0.0));
            prop_assert!(sol.gap.iter().chain(&sol.displacement).all(|v| v.is_finite()));
            prop_assert!(sol.approach.is_finite() && sol.residual <= TOL);
            let mean = sol.pressure.iter().sum::<f64>() / n2 as f64;
            prop_assert!((mean / p - 1.0).abs() <= LOAD_REL_TOL, "mean {mean:e} vs {p:e}");
            prop_assert!((sol.mean_pressure / p - 1.0).abs() <= LOAD_REL_TOL);
            // g = 𝒢p − (h − max h) − δ, from p alone.
            let mut u = vec![0.0; n2];
            op.apply(&sol.pressure, &mut u).unwrap();
            for ((ui, hi), pi) in u.iter().zip(&surf.heights).zip(&sol.pressure) {
                let g = ui - (hi - h_max) - sol.approach;
                if *pi > 0.0 {
                    prop_assert!(g.abs() <= GAP_REL_TOL * sigma, "gap {g:e} at p = {pi:e}, sigma {sigma:e}");
                } else {
                    prop_assert!(g >= -GAP_REL_TOL * sigma, "overlap {g:e}, sigma {sigma:e}");
                }
            }
            let count = sol.pressure.iter().filter(|v| **v > 0.0).count();
            prop_assert_eq!(sol.contact_fraction, count as f64 / n2 as f64);
            prop_assert!((0.0..=1.0).contains(&sol.contact_fraction) && sol.contact_fraction > 0.0);
            prop_assert!(sol.contact_fraction >= last_fraction,
                "A/A0 fell from {last_fraction} to {} at p = {p:e}", sol.contact_fraction);
            last_fraction = sol.contact_fraction;
        }
    }
}

/// ∫ P dσ of a histogram against A/A0: a sum of at most 60 bins of counts
/// over N² (rounding only).
const HISTOGRAM_REL_TOL: f64 = 1e-12;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The rough-contact loop (used by `persson bem rough`, scenes and the
    /// resolution sweep): each histogram integrates to its A/A0, spans
    /// [0, max p] in the bins asked for, and the mean separation is the mean
    /// gap, non-negative up to the gap tolerance.
    #[test]
    fn rough_loop_histograms_integrate_to_the_contact_fraction(c in case(), bins in 1usize..60) {
        let q = std::f64::consts::TAU;
        let s = SelfAffine::new(q, c.k_r * q, c.k_s * q, c.hurst, Amplitude::RmsSlope(c.rms_slope))
            .unwrap();
        let surf = synthesize(&s, c.grid, 1.0, c.seed).unwrap();
        let options = RoughOptions {
            boundary: c.boundary,
            solver: Options { tolerance: TOL, warm_start: true, ..Options::default() },
            bins: Some(bins),
            ..RoughOptions::default()
        };
        let points = rough::solve(&surf, 1.0, &c.pressures, &options, &mut ()).unwrap();
        prop_assert_eq!(points.len(), 3);
        let sigma = surf.rms_height();
        for (pt, &p) in points.iter().zip(&c.pressures) {
            prop_assert_eq!(pt.nominal_pressure, p);
            let h = pt.histogram.as_ref().unwrap();
            prop_assert_eq!(h.len(), bins);
            prop_assert_eq!(h[0].sigma_low, 0.0);
            let total = integral(h);
            prop_assert!((total - pt.contact_fraction).abs() <= HISTOGRAM_REL_TOL * pt.contact_fraction,
                "∫P = {total} vs A/A0 = {}", pt.contact_fraction);
            prop_assert!(pt.mean_separation >= -GAP_REL_TOL * sigma);
        }
    }
}

/// A `.npy` header with a shape whose element count overflows `usize`:
/// before the checked product, `rows·cols` wrapped to 0, an empty data block
/// passed the length check and the Fortran-order transpose indexed out of
/// bounds (a panic on user data).
#[test]
fn npy_shape_overflow_is_an_error() {
    let header = "{'descr': '<f8', 'fortran_order': True, 'shape': (4294967296, 4294967296), }\n";
    let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
    bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
    bytes.extend_from_slice(header.as_bytes());
    let e =
        persson::bem::surface::height_map_from_bytes(std::path::Path::new("x.npy"), &bytes, 1.0)
            .unwrap_err()
            .to_string();
    assert!(e.contains("too large"), "{e}");
}

//! Property tests (proptest) over random valid parameters spanning many
//! decades. Failing cases are persisted under `proptest-regressions/`.

use persson::spectrum::{Amplitude, SelfAffine, Spectrum, Tabulated};
use persson::theory::{contact_fraction, Persson};
use proptest::prelude::*;

/// A self-affine spectrum with cut-offs anywhere in 1e-3 … 1e13 1/m.
fn self_affine() -> impl Strategy<Value = SelfAffine> {
    (
        0.01f64..0.99,
        -3.0f64..8.0,
        0.0f64..2.0,
        0.5f64..5.0,
        -3.0f64..1.0,
    )
        .prop_map(|(h, lq, roll, span, ls)| {
            let q_l = 10f64.powf(lq);
            let q_r = q_l * 10f64.powf(roll);
            let q_s = q_r * 10f64.powf(span);
            SelfAffine::new(q_l, q_r, q_s, h, Amplitude::RmsSlope(10f64.powf(ls))).unwrap()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn area_is_a_finite_fraction_monotone_in_load_and_zeta(
        s in self_affine(), lp in -12.0f64..1.0, lz in 0.0f64..1.0, f in 1.001f64..10.0,
    ) {
        let m = Persson::new(&s, 1.0).unwrap();
        let p = 10f64.powf(lp);
        let zeta = m.zeta_max().powf(lz);
        let a = m.point(zeta, p).unwrap();
        prop_assert!(a.g.is_finite() && a.contact_fraction.is_finite() && a.non_contact_fraction.is_finite());
        prop_assert!((0.0..=1.0).contains(&a.contact_fraction));
        prop_assert!((0.0..=1.0).contains(&a.non_contact_fraction));
        // more load, more area; more magnification, less area
        let b = m.point(zeta, p * f).unwrap();
        prop_assert!(b.contact_fraction >= a.contact_fraction);
        let c = m.point((zeta * f).min(m.zeta_max()).max(zeta), p).unwrap();
        prop_assert!(c.contact_fraction <= a.contact_fraction);
        // A + (1 − A) = 1 to rounding
        prop_assert!((a.contact_fraction + a.non_contact_fraction - 1.0).abs() <= 4.0 * f64::EPSILON);
    }

    #[test]
    fn g_scales_as_inverse_square_pressure(s in self_affine(), lp in -12.0f64..0.0, f in 0.01f64..100.0) {
        let m = Persson::new(&s, 1.0).unwrap();
        let p = 10f64.powf(lp);
        let (g1, g2) = (m.g(m.zeta_max(), p).unwrap().value, m.g(m.zeta_max(), p * f).unwrap().value);
        prop_assert!(((g2 * f * f - g1) / g1).abs() < 1e-14);
    }

    #[test]
    fn tabulated_and_analytic_spectra_agree(s in self_affine(), lz in 0.0f64..1.0) {
        let decades = (s.q_max() / s.q_min()).log10();
        let n = (decades * 10.0).ceil() as usize + 1;
        let mut q: Vec<f64> = (0..n).map(|i| s.q_min() * 10f64.powf(decades * i as f64 / (n - 1) as f64)).collect();
        q.push(s.q_r());
        q.sort_by(f64::total_cmp);
        q.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * *b);
        q[0] = s.q_min();
        *q.last_mut().unwrap() = s.q_max();
        let t = Tabulated::new(&q.iter().map(|&x| (x, s.c(x))).collect::<Vec<_>>()).unwrap();
        let zeta = (s.q_max() / s.q_min()).powf(lz);
        let (ms, mt) = (Persson::new(&s, 1.0).unwrap(), Persson::new(&t, 1.0).unwrap());
        let (a, b) = (ms.g(zeta, 1.0).unwrap().value, mt.g(zeta, 1.0).unwrap().value);
        // q_r moved by at most 1e-9 relative when dedup merged it with a sample.
        prop_assert!(((a - b) / a).abs() < 1e-8 || a == 0.0, "{a} vs {b}");
    }

    #[test]
    fn contact_fraction_finite_for_any_g(lg in -12.0f64..30.0) {
        let a = contact_fraction(10f64.powf(lg), 0.0).unwrap();
        prop_assert!(a.fraction.is_finite() && a.ln_complement.is_finite() && a.error.is_finite());
        prop_assert!(a.fraction > 0.0 && a.fraction <= 1.0);
    }
}

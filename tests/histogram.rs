//! Pressure histograms of BEM fields: their integral is the contact fraction.
#![cfg(feature = "bem")]

use persson::bem::histogram::{integral, PressureCounts};
use persson::bem::pressure_histogram;

/// Rounding of sums over a few values.
const ROUNDING: f64 = 1e-12;

#[test]
fn histograms_integrate_to_the_contact_fraction() {
    // 5 contact nodes of 8, then 8 nodes out of contact: 5/16 over both
    let field = [0.0, 0.5, 1.2, 3.7, 0.0, 0.0, 2.2, 0.01];
    let mut h = PressureCounts::new(1.0);
    h.add(&field);
    h.add(&[0.0; 8]);
    let bins = h.bins(5);
    assert!((integral(&bins) - 5.0 / 16.0).abs() < ROUNDING);
    assert!(bins.last().unwrap().sigma_high >= 3.7);
    // fine bins of σ0/200 = 0.005: 3.7 lies in fine bin 740, 5 bins of 149
    assert!((bins[0].sigma_high - 149.0 * 0.005).abs() < ROUNDING);
    // one field, equal bins up to its maximum: 5 of 8 nodes
    let one = pressure_histogram(&field, 4).unwrap();
    assert!((integral(&one) - 5.0 / 8.0).abs() < ROUNDING);
    assert_eq!(one[3].sigma_high, 3.7);
    assert!(pressure_histogram(&field, 0).is_err());
}

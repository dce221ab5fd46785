//! Speed of the rubber-friction theory: `cargo bench --bench friction`.
//!
//! Targets (issue 26, one thread): μ at 100 velocities for a 3-decade master
//! curve and a 5-decade spectrum in < 100 ms without the flash temperature
//! and < 2 s with it. Each bench includes the set-up (`Friction::new`, which
//! builds the master curve's angular interpolant) and the default tolerance
//! 1e-8; the flash bench computes the isothermal μ too.

use persson::friction::{
    log_velocities, Friction, FrictionOptions, MasterCurve, Prony, PronyTerm, Rubber,
    TemperatureShift, Thermal, Viscoelastic,
};
use persson::spectrum::{Amplitude, SelfAffine};

fn main() {
    divan::main();
}

const T_REF: f64 = 293.15;

/// 5 decades: q_l = 1e3, roll-off 1e4, q_s = 1e8 1/m, H = 0.8, rms slope 1.3.
fn spectrum() -> SelfAffine {
    SelfAffine::new(1e3, 1e4, 1e8, 0.8, Amplitude::RmsSlope(1.3)).unwrap()
}

/// A tread-like rubber: a broad 16-term Prony transition, E∞ = 2 MPa.
fn prony() -> Prony {
    let terms: Vec<PronyTerm> = (0..16)
        .map(|k| PronyTerm {
            modulus: 3e8 / (1.0 + (k as f64 - 8.0).powi(2) / 8.0),
            relaxation_time: 10f64.powf(k as f64 - 12.0),
        })
        .collect();
    Prony::new(2e6, &terms).unwrap()
}

/// The Prony rubber sampled as a DMA master curve over 3 decades (10 points
/// per decade, 1e3 to 1e6 rad/s).
fn master_curve() -> MasterCurve {
    let p = prony();
    let pts: Vec<(f64, f64, f64)> = (0..31)
        .map(|i| {
            let w = 10f64.powf(3.0 + 0.1 * i as f64);
            let e = p.modulus(w);
            (w, e.storage_modulus, e.loss_modulus)
        })
        .collect();
    MasterCurve::new(&pts).unwrap()
}

fn curve(v: Viscoelastic, thermal: bool) -> f64 {
    let s = spectrum();
    let mut rubber = Rubber::new(v, TemperatureShift::wlf(T_REF, 8.86, 101.6).unwrap());
    if thermal {
        rubber = rubber.with_thermal(Thermal::new(0.25, 1200.0, 1500.0).unwrap());
    }
    let options = FrictionOptions {
        breaks: vec![1e4],
        ..Default::default()
    };
    let f = Friction::new(&s, &rubber, &options).unwrap();
    let vs = log_velocities(1e-8, 1e2, 100).unwrap();
    let pts = f.sweep(&vs, &[T_REF], &[2e5]).unwrap();
    pts.iter()
        .map(|p| {
            p.flash
                .as_ref()
                .unwrap_or(&p.isothermal)
                .friction_coefficient
        })
        .sum()
}

#[divan::bench(sample_count = 10)]
fn master_curve_100_velocities() -> f64 {
    curve(divan::black_box(master_curve()).into(), false)
}

#[divan::bench(sample_count = 3)]
fn master_curve_100_velocities_flash() -> f64 {
    curve(divan::black_box(master_curve()).into(), true)
}

#[divan::bench(sample_count = 10)]
fn prony_16_terms_100_velocities() -> f64 {
    curve(divan::black_box(prony()).into(), false)
}

#[divan::bench(sample_count = 3)]
fn prony_16_terms_100_velocities_flash() -> f64 {
    curve(divan::black_box(prony()).into(), true)
}

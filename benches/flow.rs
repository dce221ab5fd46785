//! Conductance and leakage: theory load curves and the Reynolds solve.
//!
//! `cargo bench --bench flow`. Targets (issue 23): a 100-load theory curve
//! of either quantity under 10 ms; Reynolds on a 512² gap under 2 s and on
//! 1024² under 10 s, one thread.

use persson::conductance::{Conductance, ConductanceOptions, Conductivity, GapLaw};
use persson::gap::DensityOptions;
use persson::leakage::{CriticalJunction, Drive, EffectiveMedium, Seal};
use persson::spectrum::{Amplitude, SelfAffine};

fn main() {
    divan::main();
}

fn spectrum() -> SelfAffine {
    SelfAffine::new(1e4, 4e4, 1e7, 0.8, Amplitude::RmsSlope(1.0)).unwrap()
}

fn seal() -> Seal {
    Seal {
        seal_width: 1e-3,
        seal_length: 1e-2,
        viscosity: 1e-3,
        drive: Drive::Liquid { pressure_drop: 1e5 },
    }
}

/// 100 pressures from 1e-4 E* to 0.3 E* (E* = 1 GPa): leaking to sealed.
fn pressures() -> Vec<f64> {
    (0..100)
        .map(|i| 1e9 * 10f64.powf(-4.0 + 3.5 * i as f64 / 99.0))
        .collect()
}

/// Barber's thermal conductance at 100 loads (tolerance 1e-9).
#[divan::bench]
fn conductance_curve_100(b: divan::Bencher) {
    let s = spectrum();
    let opts = ConductanceOptions {
        conductivity: Some(Conductivity::both(50.0).unwrap()),
        density: DensityOptions {
            breaks: vec![4e4],
            ..Default::default()
        },
        ..Default::default()
    };
    let model = Conductance::new(&s, 1e9, opts).unwrap();
    let p = pressures();
    b.bench(|| model.load_curve(divan::black_box(&p)).unwrap());
}

/// The critical-junction leak rate at 100 loads (tolerance 1e-10).
#[divan::bench]
fn critical_junction_curve_100(b: divan::Bencher) {
    let s = spectrum();
    let model = CriticalJunction::new(&s, 1e9, seal())
        .unwrap()
        .with_breaks(&[4e4]);
    let p = pressures();
    b.bench(|| model.load_curve(divan::black_box(&p)).unwrap());
}

/// The effective-medium leak rate at 100 loads (one P(u) table, then a
/// P(u) and a Bruggeman root per load).
#[divan::bench(sample_count = 10)]
fn effective_medium_curve_100(b: divan::Bencher) {
    let s = spectrum();
    let opts = DensityOptions {
        breaks: vec![4e4],
        ..Default::default()
    };
    let model = EffectiveMedium::new(&s, 1e9, seal(), opts).unwrap();
    let p = pressures();
    b.bench(|| model.load_curve(divan::black_box(&p)).unwrap());
}

/// The gap conductance (gas) at 100 loads (one P(u) table).
#[divan::bench(sample_count = 10)]
fn gap_conductance_curve_100(b: divan::Bencher) {
    let s = spectrum();
    let opts = ConductanceOptions {
        gap_law: Some(GapLaw::Gas {
            gas_conductivity: 0.026,
            mean_free_path: 7e-8,
        }),
        density: DensityOptions {
            breaks: vec![4e4],
            ..Default::default()
        },
        ..Default::default()
    };
    let model = Conductance::new(&s, 1e9, opts).unwrap();
    let p = pressures();
    b.bench(|| model.load_curve(divan::black_box(&p)).unwrap());
}

/// The effective-medium leak rate at one load (adaptive P(u) and a Bruggeman root).
#[divan::bench(sample_count = 10)]
fn effective_medium_point(b: divan::Bencher) {
    let s = spectrum();
    let opts = DensityOptions {
        breaks: vec![4e4],
        ..Default::default()
    };
    let model = EffectiveMedium::new(&s, 1e9, seal(), opts).unwrap();
    b.bench(|| model.point(divan::black_box(1e7)).unwrap());
}

#[cfg(feature = "flow")]
mod reynolds {
    use persson::bem::reynolds::{flow, FlowDirection, GapField};
    use persson::bem::surface::synthesize;
    use persson::spectrum::{Amplitude, SelfAffine};

    /// A gap field of a synthesised surface, closed (in contact) where the
    /// height is above 0.67 h_rms (a quarter of the nodes: the open part
    /// percolates) or nowhere (`open`: every node an unknown, the largest system).
    fn field(n: usize, open: bool) -> GapField {
        let q_l = std::f64::consts::TAU;
        let s = SelfAffine::new(
            q_l,
            4.0 * q_l,
            (n / 4) as f64 * q_l,
            0.8,
            Amplitude::RmsSlope(0.1),
        )
        .unwrap();
        let surf = synthesize(&s, n, 1.0, 5).unwrap();
        let cut = if open {
            f64::INFINITY
        } else {
            0.67 * surf.rms_height()
        };
        let top = surf.heights.iter().cloned().fold(f64::MIN, f64::max);
        let gap = surf
            .heights
            .iter()
            .map(|&h| if h > cut { 0.0 } else { (top - h) * 1e-3 })
            .map(|g| g.max(0.0))
            .collect();
        GapField::new(n, 1e-3, gap).unwrap()
    }

    #[divan::bench(args = [512, 1024], sample_count = 3)]
    fn reynolds_open(b: divan::Bencher, n: usize) {
        let f = field(n, true);
        b.bench(|| flow(&f, 1e-3, FlowDirection::X).unwrap());
    }

    #[divan::bench(args = [512, 1024], sample_count = 3)]
    fn reynolds_quarter_closed(b: divan::Bencher, n: usize) {
        let f = field(n, false);
        b.bench(|| flow(&f, 1e-3, FlowDirection::X).unwrap());
    }
}

//! Real against random (issue 39): the FFT-BEM on a map and on its
//! surrogates. No false alarm on maps that are themselves random-phase
//! Gaussian surfaces; a true alarm, with its sign, on a plateau surface
//! (peaks cut flat: more contact) and on sparse tall bumps (less contact).

use persson::bem::surface::{synthesize, GridSurface};
use persson::spectrum::{Amplitude, SelfAffine};
use persson_studies::input::SurrogateKindName;
use persson_studies::surrogates::{Plan, SurrogatesOutput, SurrogatesReport};

const N: usize = 64;

/// A Gaussian self-affine map (H = 0.8, roll-off at k = 4, E* = 1 units):
/// rms slope 0.1 on the grid.
fn gaussian(seed: u64) -> GridSurface {
    let q0 = std::f64::consts::TAU;
    let s = SelfAffine::new(
        q0,
        4.0 * q0,
        N as f64 / 2.0 * q0,
        0.8,
        Amplitude::RmsSlope(0.1),
    )
    .unwrap();
    synthesize(&s, N, 1.0, seed).unwrap()
}

/// Nominal pressures (E* = 1) where A/A0 is about 2 to 15 % on the grid.
const PRESSURES: [f64; 3] = [0.002, 0.005, 0.01];

fn compare(map: &GridSurface, kind: SurrogateKindName, count: usize) -> SurrogatesReport {
    let spec = SurrogatesOutput {
        count: Some(count),
        kind: Some(kind),
        ..SurrogatesOutput::default()
    };
    let plan = Plan::new(&spec, ("map", map), 1.0, &PRESSURES).unwrap();
    let solved = plan
        .jobs()
        .into_iter()
        .map(|j| plan.solve(j).unwrap())
        .collect();
    plan.gather(solved, &[], 0.0).unwrap()
}

/// The Gaussian map with its heights above the `q` quantile cut flat.
fn plateau(seed: u64, q: f64) -> GridSurface {
    let mut g = gaussian(seed);
    let mut sorted = g.heights.clone();
    sorted.sort_by(f64::total_cmp);
    let cut = sorted[(sorted.len() as f64 * q) as usize];
    for h in &mut g.heights {
        *h = h.min(cut);
    }
    g
}

/// Sparse tall bumps: `count` Gaussian bumps of width `w` (cells) and
/// equal height on a faint copy of the Gaussian map.
fn bumps(seed: u64, count: usize, w: f64) -> GridSurface {
    let g = gaussian(seed);
    let rms = g.rms_height();
    let mut h: Vec<f64> = g.heights.iter().map(|v| 0.2 * v).collect();
    for k in 0..count {
        let (ci, cj) = ((k * 37 + 5) % N, (k * 53 + 17) % N);
        for i in 0..N {
            for j in 0..N {
                let d = |a: usize, c: usize| {
                    let t = (a as f64 - c as f64).abs();
                    t.min(N as f64 - t)
                };
                let r2 = d(i, ci).powi(2) + d(j, cj).powi(2);
                h[i * N + j] += 4.0 * rms * (-r2 / (2.0 * w * w)).exp();
            }
        }
    }
    GridSurface::new(N, 1.0, h).unwrap()
}

/// The comparisons of a map that is itself a random-phase Gaussian surface,
/// over seeds and loads.
#[test]
fn no_false_alarm_on_random_maps() {
    let (mut flagged, mut tails_flagged, mut total) = (0, 0, 0);
    let (mut z_sum, mut z2_sum) = (0.0, 0.0);
    for seed in 1..=12 {
        let r = compare(&gaussian(seed), SurrogateKindName::Phase, 8);
        assert!((r.threshold - 2.365).abs() < 1e-12, "t(0.975, 7)");
        for p in &r.points {
            total += 1;
            z_sum += p.z;
            z2_sum += p.z * p.z;
            flagged += usize::from(p.significant);
            let tz = p.tail_z.expect("a tail at these loads");
            tails_flagged += usize::from(tz.abs() > r.threshold);
            // The map's A/A0 within the 95 % prediction interval of one
            // more surrogate, as the z column states it.
            let half = r.threshold * p.surrogate_standard_deviation * (1.0 + 1.0 / 8.0f64).sqrt();
            assert_eq!(
                (p.map_contact_fraction - p.surrogate_contact_fraction).abs() > half,
                p.significant
            );
        }
    }
    // A random map is one more draw of its surrogates' distribution: z is
    // Student's t with 7 degrees of freedom (sd 1.18) and flagged at the
    // nominal 5 % of the comparisons: 1.8 of 36 expected, at most 5 with
    // probability 0.99 for independent ones. (Over 40 seeds, 120 loads:
    // 8 flagged, rms z 1.25, mean z −0.35.)
    let n = total as f64;
    assert!(flagged <= 5, "{flagged} of {total} loads flagged");
    assert!(
        tails_flagged <= 5,
        "{tails_flagged} of {total} tails flagged"
    );
    assert!((z_sum / n).abs() < 0.6, "mean z {}", z_sum / n);
    let rms = (z2_sum / n).sqrt();
    assert!((0.7..1.7).contains(&rms), "rms z {rms}");
}

/// A plateau surface (a Gaussian map with its highest 10 % cut flat) makes
/// more contact than random surfaces of its spectrum: the plateaus carry the
/// load on flat tops where the surrogates have peaks.
#[test]
fn a_plateau_surface_makes_more_contact() {
    let map = plateau(1, 0.9);
    let r = compare(&map, SurrogateKindName::Phase, 8);
    assert!(r.map_heights.skewness < -0.2, "{:?}", r.map_heights);
    assert!(r.surrogate_heights.skewness.abs() < 0.1);
    // At the two lower loads the plateaus are a large part of the contact.
    for p in &r.points[..2] {
        assert!(p.significant && p.z > 0.0 && p.ratio > 1.25, "{p:?}");
    }
}

/// Sparse tall bumps make less contact than random surfaces of their
/// spectrum: the load sits on a few bumps whose tops are as curved as the
/// spectrum's slopes allow, where a random surface spreads it over many
/// summits.
#[test]
fn sparse_bumps_make_less_contact() {
    let map = bumps(1, 16, 3.0);
    let r = compare(&map, SurrogateKindName::Phase, 8);
    assert!(r.map_heights.skewness > 1.0, "{:?}", r.map_heights);
    for p in &r.points {
        assert!(p.significant && p.z < 0.0 && p.ratio < 0.75, "{p:?}");
    }
}

/// The amplitude-adjusted surrogates keep the map's heights, so a plateau's
/// difference that comes from its height distribution shrinks.
#[test]
fn amplitude_adjusted_surrogates_keep_the_heights() {
    let map = plateau(1, 0.9);
    let r = compare(&map, SurrogateKindName::AmplitudeAdjusted, 4);
    assert!((r.surrogate_heights.skewness - r.map_heights.skewness).abs() < 1e-12);
    assert!(
        r.spectrum_mismatch.unwrap() < 0.01,
        "{:?}",
        r.spectrum_mismatch
    );
    let phase = compare(&map, SurrogateKindName::Phase, 4);
    assert!(
        (r.points[0].ratio - 1.0).abs() < (phase.points[0].ratio - 1.0).abs(),
        "{} against {}",
        r.points[0].ratio,
        phase.points[0].ratio
    );
}

#[test]
fn bad_input_names_the_field() {
    let map = gaussian(1);
    let spec = |count| SurrogatesOutput {
        count: Some(count),
        ..SurrogatesOutput::default()
    };
    let e = Plan::new(&spec(1), ("map", &map), 1.0, &PRESSURES).unwrap_err();
    assert!(e.to_string().contains("count"), "{e}");
    let e = Plan::new(&spec(4), ("map", &map), 1.0, &[]).unwrap_err();
    assert!(e.to_string().contains("nominal_pressure"), "{e}");
    let flat = GridSurface::new(N, 1.0, vec![0.5; N * N]).unwrap();
    let e = Plan::new(&spec(4), ("map", &flat), 1.0, &PRESSURES).unwrap_err();
    assert!(e.to_string().contains("heights"), "{e}");
}

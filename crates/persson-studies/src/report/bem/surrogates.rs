//! The surrogates' row of the accuracy report: how many surrogates a user
//! needs, and what they cost.

use persson::clock::Instant;

use persson::bem::surface::synthesize;
use persson::error::Result;
use persson::spectrum::{Amplitude, SelfAffine};

use super::super::accuracy::{AccuracyRow, Extent, Knob, MethodAccuracy};
use crate::surrogates::{Plan, SurrogatesOutput};

/// σ0/E* of the rows: A/A0 ≈ 0.13 on these maps.
const PRESSURE: f64 = 0.005;

/// The relative standard error `sd/(√K · mean)` of the surrogates' mean A/A0
/// against K, on a Gaussian map (H = 0.8, roll-off at 4 × 2π/L, rms slope
/// 0.1) of 64² and 128² (256² with [`Extent::Full`]) at σ0 = 0.005 E*;
/// seconds = the whole comparison (the map's solve, the K surrogates and
/// theirs). The error falls as 1/√K: a 2 % standard error needs
/// K ≈ (sd/mean / 0.02)², which the title states per grid.
pub(super) fn accuracy(extent: Extent) -> Result<Vec<MethodAccuracy>> {
    let grids: &[usize] = match extent {
        Extent::Default => &[64, 128],
        Extent::Full => &[64, 128, 256],
    };
    grids.iter().map(|&n| grid(n)).collect()
}

fn grid(n: usize) -> Result<MethodAccuracy> {
    let q0 = std::f64::consts::TAU;
    let s = SelfAffine::new(
        q0,
        4.0 * q0,
        n as f64 / 2.0 * q0,
        0.8,
        Amplitude::RmsSlope(0.1),
    )?;
    let map = synthesize(&s, n, 1.0, 1)?;
    let mut rows = Vec::new();
    let mut scatter = 0.0;
    for count in [2, 4, 8, 16] {
        let spec = SurrogatesOutput {
            count: Some(count),
            ..SurrogatesOutput::default()
        };
        let t0 = Instant::now();
        let plan = Plan::new(&spec, ("map", &map), 1.0, &[PRESSURE])?;
        let solved = plan
            .jobs()
            .into_iter()
            .map(|j| plan.solve(j))
            .collect::<Result<Vec<_>>>()?;
        let r = plan.gather(solved, &[], 0.0)?;
        let seconds = t0.elapsed().as_secs_f64();
        let p = &r.points[0];
        scatter = p.surrogate_standard_deviation / p.surrogate_contact_fraction;
        rows.push(AccuracyRow {
            setting: count as f64,
            error: p.surrogate_standard_error / p.surrogate_contact_fraction,
            error_bound: None,
            residual: None,
            seconds,
        });
    }
    let needed = (scatter / 0.02).powi(2).ceil().max(2.0);
    Ok(MethodAccuracy {
        method: if n == 64 {
            "surrogates-64"
        } else if n == 128 {
            "surrogates-128"
        } else {
            "surrogates-256"
        },
        title: format!(
            "Surrogates of a {n}² map, σ0 = {PRESSURE} E*: one surrogate's A/A0 scatters by {} \
             (relative sd); a 2 % standard error of their mean needs K ≈ {needed}",
            crate::table::number(scatter, 2)
        ),
        knob: Knob::Count,
        reference: "the relative standard error sd/(√K · mean) of the surrogates' mean A/A0 \
                    (statistical, against the mean of infinitely many); time: the whole \
                    comparison, K + 1 solves"
            .into(),
        rows,
    })
}

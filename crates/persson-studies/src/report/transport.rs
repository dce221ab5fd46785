//! The transport entries of the accuracy report Barber's
//! identity on Holm's circular spot through the BEM's stiffness solve
//! (feature `bem`), Reynolds flow against its closed forms (feature `flow`),
//! and the two-phase Bruggeman medium against σ1(1 − 2a).

use super::accuracy::{time_it, AccuracyRow, Extent, Knob, MethodAccuracy};
use persson::error::Result;

/// Every transport row of the accuracy report in this build.
///
/// # Errors
/// A solve that fails (none should).
pub fn accuracy(extent: Extent) -> Result<Vec<MethodAccuracy>> {
    // Only the BEM rows have a grid to extend.
    let _ = extent;
    let methods = vec![
        #[cfg(feature = "bem")]
        barber_holm(extent)?,
        #[cfg(feature = "flow")]
        reynolds_closed_forms(extent)?,
        bruggeman_two_phase()?,
    ];
    Ok(methods)
}

/// Barber's identity on one circular contact spot of radius a = L/4, the
/// free-boundary BEM's exact stiffness K of that contact set (a linear
/// solve, [`persson::bem::stiffness`]) turned into the electrical
/// conductance C = 2K/((ρ1 + ρ2) E*), against Holm's constriction
/// C = 4a/(ρ1 + ρ2) (Holm, *Electric Contacts* (1967) §4; the flat punch's
/// K = 2E*a, Johnson, *Contact Mechanics* Eq. 3.33). The error is that of
/// the pixelated disc (a/Δ = N/4 nodes per radius); seconds = the stiffness
/// solve.
#[cfg(feature = "bem")]
fn barber_holm(extent: Extent) -> Result<MethodAccuracy> {
    use persson::bem::stiffness::{contact_stiffness, StiffnessOptions};
    use persson::bem::{Boundary, Operator};
    use persson::conductance::{electrical_conductance, Resistivity};
    let (size, e_star) = (1.0, 1.0);
    let rho = Resistivity::new(1.7e-8, 2.8e-8)?;
    let mut grids = vec![32, 64, 128];
    if extent == Extent::Full {
        grids.extend([256, 512]);
    }
    let a = size / 4.0;
    let holm = 4.0 * a / rho.sum();
    let mut rows = Vec::new();
    for n in grids {
        let dx = size / n as f64;
        let mut op = Operator::new(Boundary::Free, n, size, e_star)?;
        // The contact set: nodes (cell centres) within a of the centre.
        let pressure: Vec<f64> = (0..n * n)
            .map(|k| {
                let x = ((k % n) as f64 + 0.5) * dx - 0.5 * size;
                let y = ((k / n) as f64 + 0.5) * dx - 0.5 * size;
                if x.hypot(y) < a {
                    1.0
                } else {
                    0.0
                }
            })
            .collect();
        let options = StiffnessOptions {
            tolerance: 1e-12,
            ..StiffnessOptions::default()
        };
        let (k, seconds) = time_it(0.2, || contact_stiffness(&mut op, &pressure, &options));
        let k = k?;
        // K/A0 with A0 = L²: the spot's stiffness is K = (K/A0) L².
        let stiffness = persson::Estimate {
            value: k.stiffness * size * size,
            error: k.stiffness_error_bound * size * size,
        };
        let c = electrical_conductance(stiffness, e_star, &rho)?;
        rows.push(AccuracyRow {
            setting: n as f64,
            error: (c.value / holm - 1.0).abs(),
            error_bound: None,
            residual: Some(k.residual),
            seconds,
        });
    }
    Ok(MethodAccuracy {
        method: "barber-holm",
        title: "Barber's identity on Holm's circular spot: BEM stiffness of a disc (free boundary) → conductance".into(),
        knob: Knob::Grid,
        reference: "Holm C = 4a/(ρ1 + ρ2) (K = 2E*a); relative error of C = 2K/((ρ1 + ρ2) E*), a = L/4; time: the stiffness solve".into(),
        rows,
    })
}

/// Reynolds flow ([`persson::bem::reynolds`]) against its closed forms on an
/// N × N gap: a uniform slot (plane Poiseuille σ = g³/(12η)), a gap varying
/// along the flow only (resistances in series: (N − 1)/Σ 1/c over the
/// faces, c the harmonic mean of the nodes' σ) and across it only
/// (conductances in parallel: the mean σ), each along x and along y. The
/// error is the largest relative error of σ_eff; seconds = one solve of the
/// series case along x.
#[cfg(feature = "flow")]
fn reynolds_closed_forms(extent: Extent) -> Result<MethodAccuracy> {
    use persson::bem::reynolds::{flow, FlowDirection, GapField};
    let eta = 1e-3;
    let sigma = |g: f64| g * g * g / (12.0 * eta);
    let face = |a: f64, b: f64| 2.0 * a * b / (a + b);
    let mut grids = vec![16, 64, 256];
    if extent == Extent::Full {
        grids.push(1024);
    }
    let mut rows = Vec::new();
    for n in grids {
        let g =
            |a: usize| 1e-7 * (1.0 + 0.9 * (a as f64 * 0.7).sin()) * (1.0 + a as f64 / n as f64);
        // Gaps depending on the index along x (j) or along y (i) only.
        let field = |along_x: bool| {
            let gap = (0..n * n)
                .map(|k| if along_x { g(k % n) } else { g(k / n) })
                .collect();
            GapField::new(n, 1e-3, gap)
        };
        let series = (n - 1) as f64
            / (0..n - 1)
                .map(|a| 1.0 / face(sigma(g(a)), sigma(g(a + 1))))
                .sum::<f64>();
        let parallel = (0..n).map(|b| sigma(g(b))).sum::<f64>() / n as f64;
        let uniform = GapField::new(n, 1e-3, vec![2e-7; n * n])?;
        let mut error: f64 = 0.0;
        for (dir, x) in [(FlowDirection::X, true), (FlowDirection::Y, false)] {
            let rel = |got: f64, want: f64| (got / want - 1.0).abs();
            let f = flow(&uniform, eta, dir)?;
            error = error.max(rel(f.effective_flow_conductivity, sigma(2e-7)));
            let f = flow(&field(x)?, eta, dir)?;
            error = error.max(rel(f.effective_flow_conductivity, series));
            let f = flow(&field(!x)?, eta, dir)?;
            error = error.max(rel(f.effective_flow_conductivity, parallel));
        }
        let along = field(true)?;
        let (_, seconds) = time_it(0.2, || flow(&along, eta, FlowDirection::X));
        rows.push(AccuracyRow {
            setting: n as f64,
            error,
            error_bound: None,
            residual: None,
            seconds,
        });
    }
    Ok(MethodAccuracy {
        method: "reynolds-closed-forms",
        title: "Reynolds flow on a gap field (finite volumes, sparse Cholesky) against closed forms".into(),
        knob: Knob::Grid,
        reference: "Poiseuille g³/(12η), series (N − 1)/Σ 1/c, parallel mean σ, along x and y: largest relative error of σ_eff; time: one series solve".into(),
        rows,
    })
}

/// The 2-D Bruggeman medium ([`persson::leakage::bruggeman`]) of two phases,
/// a at σ = 0 and 1 − a at σ1, against σ_eff = σ1 (1 − 2a) (Kirkpatrick,
/// Rev. Mod. Phys. 45, 574 (1973)); error relative to σ1; seconds = one solve.
fn bruggeman_two_phase() -> Result<MethodAccuracy> {
    let s1 = 3.0e-12;
    let mut rows = Vec::new();
    for a in [0.1, 0.3, 0.45, 0.49] {
        let (got, seconds) = time_it(0.05, || {
            persson::leakage::bruggeman(&[(a, 0.0), (1.0 - a, s1)])
        });
        rows.push(AccuracyRow {
            setting: a,
            error: (got? - s1 * (1.0 - 2.0 * a)).abs() / s1,
            error_bound: None,
            residual: None,
            seconds,
        });
    }
    Ok(MethodAccuracy {
        method: "bruggeman-two-phase",
        title: "Effective medium (2-D Bruggeman), two phases: blocked fraction a, open 1 − a"
            .into(),
        knob: Knob::Fraction,
        reference: "σ_eff = σ1 (1 − 2a); error |σ_eff − σ1(1 − 2a)|/σ1; time: one solve".into(),
        rows,
    })
}

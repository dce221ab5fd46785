//! The rubber-friction entry of `report accuracy`: μ against its closed form
//! for a frequency-independent loss modulus.

use std::f64::consts::PI;

use super::accuracy::{time_it, AccuracyRow, Extent, Knob, MethodAccuracy};
use persson::error::Result;
use persson::friction::{Friction, FrictionOptions, MasterCurve, Rubber, TemperatureShift};
use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
use persson::theory::contact_fraction;

/// E = E1 + i E2 sign(ω), Pa.
const E1: f64 = 2e6;
const E2: f64 = 5e5;
/// σ0, Pa: G(q1) ≈ 58, A/A0 ≈ 0.07 (partial contact).
const PRESSURE: f64 = 1e5;
/// The velocities (m/s) of every setting: μ does not depend on v.
const VELOCITIES: [f64; 3] = [1e-6, 1e-2, 1.0];

/// μ of a frequency-independent E, γ = 1 (S = 1), ν = ½, against the closed
/// form μ = 8 E2 I(G1)/(π k² (1 − ν²) σ0), k = |E|/((1 − ν²) σ0),
/// I(G) = ∫₀^G erf(1/(2√g)) dg = G erf(x) + √(G/π) e^{−x²} − ½ erfc(x),
/// x = 1/(2√G), G1 = (π/4) k² ∫ q³C dq: the friction integrals' tolerance
/// 1e-4 … 1e-12.
///
/// # Errors
/// A friction integral that fails.
pub(super) fn friction_quadrature(extent: Extent) -> Result<MethodAccuracy> {
    let s = SelfAffine::new(1e2, 1e3, 1e7, 0.8, Amplitude::CR(1e-15))?;
    // Three equal rows (1, 10, 100 rad/s), held constant outside.
    let table = MasterCurve::new(&[(1.0, E1, E2), (10.0, E1, E2), (100.0, E1, E2)])?;
    let rubber = Rubber::new(table, TemperatureShift::none(293.15)?);
    let k = E1.hypot(E2) / (0.75 * PRESSURE);
    let g1 = PI / 4.0 * k * k * s.moment(3, s.q_min(), s.q_max())?.value;
    let x = 0.5 / g1.sqrt();
    // erf(x) and erfc(x) are A/A0 at G1 and its complement.
    let p = contact_fraction(g1, 0.0)?;
    let integral = g1 * p.fraction + (g1 / PI).sqrt() * (-x * x).exp() - 0.5 * p.complement;
    let exact = 8.0 * E2 * integral / (PI * k * k * 0.75 * PRESSURE);
    let mut tols = vec![1e-4, 1e-6, 1e-8, 1e-10, 1e-12];
    if extent == Extent::Full {
        tols.insert(1, 1e-5);
        tols.push(1e-13);
    }
    let rows = tols
        .iter()
        .map(|&tolerance| {
            let options = FrictionOptions {
                gamma: 1.0,
                tolerance,
                breaks: vec![1e3],
                ..Default::default()
            };
            let run = || -> Result<(f64, f64)> {
                // Set-up included: the angular interpolant is built per rubber.
                let f = Friction::new(&s, &rubber, &options)?;
                let mut worst: (f64, f64) = (0.0, 0.0);
                for &v in &VELOCITIES {
                    let p = f.point(v, 293.15, PRESSURE)?;
                    let r = &p.isothermal;
                    worst = (
                        worst
                            .0
                            .max(((r.friction_coefficient - exact) / exact).abs()),
                        worst.1.max(r.friction_coefficient_error_bound / exact),
                    );
                }
                Ok(worst)
            };
            let (r, seconds) = time_it(0.05, run);
            let (error, estimate) = r?;
            Ok(AccuracyRow {
                setting: tolerance,
                error,
                error_bound: Some(estimate),
                residual: None,
                seconds: seconds / VELOCITIES.len() as f64,
            })
        })
        .collect::<Result<_>>()?;
    Ok(MethodAccuracy {
        method: "friction",
        title: "rubber friction μ (Persson 2001), adaptive Clenshaw–Curtis march in ln q".into(),
        knob: Knob::Tolerance,
        reference: "closed form for a frequency-independent loss modulus (γ = 1, σ0 = 1e5 Pa, \
                    E = 2e6 + 5e5 i Pa); largest relative error over v = 1e-6 … 1 m/s; \
                    time per μ value"
            .into(),
        rows,
    })
}

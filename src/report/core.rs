//! The core's entries: G(ζ) by quadrature for closure spectra, and the
//! extreme cases of G, A/A0, H, ζ and pressure.

use super::{case, time_it, AccuracyRow, Extent, StabilityCase};
use crate::error::Result;
use crate::spectrum::{Amplitude, FnSpectrum, SelfAffine, Spectrum};
use crate::theory::{contact_fraction, Persson};

/// G(ζ) of a closure spectrum by adaptive quadrature, against the closed form
/// of the same self-affine spectrum, for tolerances 1e-4 … 1e-14.
///
/// # Errors
/// A quadrature that fails to converge.
pub(super) fn g_quadrature(extent: Extent) -> Result<Vec<AccuracyRow>> {
    let s = SelfAffine::new(1e3, 1e4, 1e13, 0.8, Amplitude::RmsSlope(1.0))?;
    let exact = Persson::new(&s, 1.0)?;
    let zetas = [3.0, 10.0, 1e3, 1e6, 1e10];
    let mut tols = vec![1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    if extent == Extent::Full {
        tols.insert(1, 1e-5);
        tols.push(1e-15);
    }
    tols.iter()
        .map(|&tol| {
            // No break declared at the roll-off kink: the quadrature must find it.
            let f = FnSpectrum::new(move |q| s.c(q), s.q_min(), s.q_max(), tol)?;
            let m = Persson::new(&f, 1.0)?;
            let run = || -> Result<(f64, f64)> {
                let mut worst: (f64, f64) = (0.0, 0.0);
                for &z in &zetas {
                    let g = m.g(z, 1e-3)?;
                    let e = exact.g(z, 1e-3)?.value;
                    worst = (
                        worst.0.max(((g.value - e) / e).abs()),
                        worst.1.max(g.error / e),
                    );
                }
                Ok(worst)
            };
            let (r, seconds) = time_it(0.05, run);
            let (error, estimate) = r?;
            Ok(AccuracyRow {
                method: "G(zeta), closure spectrum, adaptive Gauss-Kronrod".into(),
                knob: "tolerance".into(),
                setting: tol,
                error,
                estimate: Some(estimate),
                seconds: seconds / zetas.len() as f64,
                reference: "closed form of the same self-affine spectrum".into(),
            })
        })
        .collect()
}

/// The extreme and stiff cases of the core: G from 1e-12 to 1e30, H to 0.01
/// and 0.99, ζ to 1e10, pressures from 1e-12 E* to 10 E*.
///
/// # Errors
/// An input the library rejects (none of these should be).
pub(super) fn stability() -> Result<Vec<StabilityCase>> {
    let mut out = Vec::new();
    for lg in [-12, -6, -3, 0, 3, 6, 12, 20, 30] {
        let g = 10f64.powi(lg);
        let a = contact_fraction(g, 0.0)?;
        out.push(case(
            format!("A/A0 at G = 1e{lg}"),
            a.fraction,
            a.error,
            &[a.complement, a.ln_complement],
        ));
    }
    for h in [0.01, 0.5, 0.99] {
        let s = SelfAffine::new(1.0, 1.0, 1e10, h, Amplitude::RmsSlope(1.0))?;
        let m = Persson::new(&s, 1.0)?;
        for lp in [-12, -6, 0, 1] {
            let p = 10f64.powi(lp);
            for zeta in [1.0 + 1e-12, 1e5, 1e10] {
                let pt = m.point(zeta, p)?;
                out.push(case(
                    format!("H = {h}, zeta = {zeta:e}, pressure = 1e{lp} E*: A/A0"),
                    pt.contact_fraction,
                    pt.error_bound,
                    &[pt.g, pt.g_error_bound, pt.non_contact_fraction],
                ));
            }
        }
    }
    Ok(out)
}

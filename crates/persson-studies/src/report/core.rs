//! The core's entries: G(ζ) by quadrature for spectra given as functions,
//! and the extreme cases of G, A/A0, H, ζ and pressure.

use super::accuracy::{time_it, AccuracyRow, Extent, Knob, MethodAccuracy};
use super::stability::{case, num, Family, StabilityCase};
use crate::table;
use persson::error::Result;
use persson::spectrum::{Amplitude, FnSpectrum, SelfAffine, Spectrum};
use persson::theory::{contact_fraction, Persson};

/// G(ζ) of a spectrum given as a function by adaptive quadrature, against the
/// closed form of the same self-affine spectrum, for tolerances 1e-4 … 1e-14.
///
/// # Errors
/// A quadrature that fails to converge.
pub(super) fn g_quadrature(extent: Extent) -> Result<MethodAccuracy> {
    let s = SelfAffine::new(1e3, 1e4, 1e13, 0.8, Amplitude::RmsSlope(1.0))?;
    let exact = Persson::new(&s, 1.0)?;
    let zetas = [3.0, 10.0, 1e3, 1e6, 1e10];
    let mut tols = vec![1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    if extent == Extent::Full {
        tols.insert(1, 1e-5);
        tols.push(1e-15);
    }
    let rows = tols
        .iter()
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
                setting: tol,
                error,
                error_bound: Some(estimate),
                residual: None,
                seconds: seconds / zetas.len() as f64,
            })
        })
        .collect::<Result<_>>()?;
    Ok(MethodAccuracy {
        method: "g-quadrature",
        title: "G(ζ) of a spectrum given as a function, adaptive Gauss–Kronrod".into(),
        knob: Knob::Tolerance,
        reference: "closed form of the same self-affine spectrum, H = 0.8; \
                    largest relative error over ζ = 3 … 1e10; time per G value"
            .into(),
        rows,
    })
}

/// References of the A/A0(G) family: (log10 G, erf(1/(2√G))), mpmath at 40
/// digits with G = `10f64.powi(lg)` taken exactly (tests/reference/stability.py).
#[allow(clippy::excessive_precision)] // the references keep 20 digits
const AREA_AT_G: [(i32, f64); 9] = [
    (-12, 1.0),
    (-6, 1.0),
    (-3, 1.0),
    (0, 5.2049987781304653768e-1),
    (3, 1.7839754502932037385e-2),
    (6, 5.6418953653196118415e-4),
    (12, 5.6418958354770927115e-7),
    (20, 5.6418958354775628695e-11),
    (30, 5.6418958354775628134e-16),
];

/// References of the self-affine family: (H, ζ, log10 σ0/E*, A/A0) for
/// q_l = q_r = 1, q_s = 1e10, rms slope 1, from the closed form
/// G = (ζ^{2−2H} − 1)/(8 (σ0/E*)² (q_s^{2−2H} − 1)), mpmath at 40 digits
/// (tests/reference/stability.py).
#[allow(clippy::excessive_precision)] // the references keep 20 digits
const SELF_AFFINE: [(f64, f64, i32, f64); 36] = [
    (0.01, 1.000000000001, -12, 1.0),
    (0.01, 100000.0, -12, 1.4222307267654871066e-7),
    (0.01, 10000000000.0, -12, 1.5957691216057306797e-12),
    (0.01, 1.000000000001, -6, 1.0),
    (0.01, 100000.0, -6, 1.4147350326038623508e-1),
    (0.01, 10000000000.0, -6, 1.5957691216046667935e-6),
    (0.01, 1.000000000001, 0, 1.0),
    (0.01, 100000.0, 0, 1.0),
    (0.01, 10000000000.0, 0, 9.544997361036415856e-1),
    (0.01, 1.000000000001, 1, 1.0),
    (0.01, 100000.0, 1, 1.0),
    (0.01, 10000000000.0, 1, 1.0),
    (0.5, 1.000000000001, -12, 1.5851246654310805723e-1),
    (0.5, 100000.0, -12, 5.0462902753024621986e-10),
    (0.5, 10000000000.0, -12, 1.5957691216057306797e-12),
    (0.5, 1.000000000001, -6, 1.0),
    (0.5, 100000.0, -6, 5.0462899388797663773e-4),
    (0.5, 10000000000.0, -6, 1.5957691216046667935e-6),
    (0.5, 1.000000000001, 0, 1.0),
    (0.5, 100000.0, 0, 1.0),
    (0.5, 10000000000.0, 0, 9.544997361036415856e-1),
    (0.5, 1.000000000001, 1, 1.0),
    (0.5, 100000.0, 1, 1.0),
    (0.5, 10000000000.0, 1, 1.0),
    (0.99, 1.000000000001, -12, 8.6292696264976924033e-6),
    (0.99, 100000.0, -12, 2.3983966156178154374e-12),
    (0.99, 10000000000.0, -12, 1.5957691216057306797e-12),
    (0.99, 1.000000000001, -6, 1.0),
    (0.99, 100000.0, -6, 2.3983966156142035111e-6),
    (0.99, 10000000000.0, -6, 1.5957691216046667935e-6),
    (0.99, 1.000000000001, 0, 1.0),
    (0.99, 100000.0, 0, 9.9735242583186408322e-1),
    (0.99, 10000000000.0, 0, 9.544997361036415856e-1),
    (0.99, 1.000000000001, 1, 1.0),
    (0.99, 100000.0, 1, 1.0),
    (0.99, 10000000000.0, 1, 1.0),
];

/// The reference of the self-affine case (H, ζ, σ0 = 10^lp E*), if tabulated.
fn self_affine_reference(h: f64, zeta: f64, lp: i32) -> Option<f64> {
    SELF_AFFINE
        .iter()
        .find(|r| r.0 == h && r.1 == zeta && r.2 == lp)
        .map(|r| r.3)
}

/// The extreme and stiff cases of the core: G from 1e-12 to 1e30, H to 0.01
/// and 0.99, ζ to 1e10, pressures from 1e-12 E* to 10 E*, each against its
/// high-precision reference.
///
/// # Errors
/// An input the library rejects (none of these should be).
pub(super) fn stability() -> Result<Vec<StabilityCase>> {
    let mut out = Vec::new();
    for (lg, reference) in AREA_AT_G {
        let g = 10f64.powi(lg);
        let a = contact_fraction(g, 0.0)?;
        out.push(case(
            Family::ContactFraction,
            format!("A/A0 at G = {}", num(g)),
            (a.fraction, a.error),
            &[a.complement, a.ln_complement],
            Some(reference),
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
                    Family::SelfAffine,
                    format!(
                        "A/A0 at H = {h}, ζ = {}, σ0 = {} E*",
                        table::number(zeta, 13),
                        num(p)
                    ),
                    (pt.contact_fraction, pt.error_bound),
                    &[pt.g, pt.g_error_bound, pt.non_contact_fraction],
                    self_affine_reference(h, zeta, lp),
                ));
            }
        }
    }
    Ok(out)
}

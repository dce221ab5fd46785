//! The warnings of an FFT-BEM rough contact (feature `bem`).

use super::{fallen_back, push, Warning};

/// [`Warning::PreconditionerFallback`] when some solve of `points` fell back
/// to the plain solver ([`persson::bem::rough::RoughPoint::fallback`]).
pub fn preconditioner_fallback(points: &[persson::bem::rough::RoughPoint]) -> Option<Warning> {
    fallen_back(
        points
            .iter()
            .filter_map(|p| p.fallback.map(|f| (p.nominal_pressure, f.iterations))),
    )
}

/// The warnings of an FFT-BEM rough contact: a synthesised surface
/// band-limited by its grid, pressures above 0.1 E*, a surface steeper than 1,
/// solves finished by the plain solver.
pub fn of_rough(r: &persson::bem::rough::RoughReport) -> Vec<Warning> {
    let mut w = Vec::new();
    push(&mut w, preconditioner_fallback(&r.points));
    let pressures: Vec<f64> = r.points.iter().map(|p| p.nominal_pressure).collect();
    push(
        &mut w,
        Warning::high_pressure(&pressures, r.contact_modulus),
    );
    if let persson::bem::rough::SurfaceOrigin::Synthesised { spectrum, .. } = &r.surface {
        push(
            &mut w,
            Warning::band_limited(r.grid, r.surface_rms_slope, spectrum.rms_slope),
        );
        push(&mut w, Warning::steep_slope(spectrum.rms_slope));
    } else {
        push(&mut w, Warning::steep_slope(r.surface_rms_slope));
    }
    w
}

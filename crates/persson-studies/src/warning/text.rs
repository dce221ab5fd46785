//! The text of each warning for people: one line that names the input
//! (never a CLI flag; the CLI appends its own).

use std::fmt;

use super::{Warning, HIGH_PRESSURE_RATIO};
use crate::naming::names::ConventionName;
use crate::table::number;

impl fmt::Display for Warning {
    /// The text of the group the warning is in (each group a function, in
    /// the order of the variants).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // A study's warning: the text its study wrote (Warning::described).
        if let Some(text) = self.message() {
            return f.write_str(text);
        }
        type Text = fn(&Warning, &mut fmt::Formatter<'_>, &mut bool) -> fmt::Result;
        const GROUPS: [Text; 4] = [
            text_of_inputs,
            text_of_theories,
            text_of_solves,
            text_of_rest,
        ];
        for text in GROUPS {
            let mut mine = true;
            let r = text(self, f, &mut mine);
            if mine {
                return r;
            }
        }
        Ok(())
    }
}

/// The text of the warnings of this group; `mine` set to false for the others.
fn text_of_inputs(w: &Warning, f: &mut fmt::Formatter<'_>, mine: &mut bool) -> fmt::Result {
    let n = |v: f64| number(v, 6);
    match w {
        Warning::NotComputed {
            table,
            quantity,
            count,
        } => write!(
            f,
            "{quantity} could not be computed ({count} value{} of the table {table} \
             came out NaN or infinite; shown as – and null)",
            if *count == 1 { "" } else { "s" }
        ),
        Warning::CurvatureNotComputed { file, shape } => write!(
            f,
            "{}: no curvature (h''_rms, rms mean curvature: null): the map has {} × {} \
             points, and a curvature needs at least 3 along x and y (or a periodic map)",
            file.display(),
            shape[0],
            shape[1]
        ),
        Warning::HighPressure {
            nominal_pressure,
            contact_modulus,
            count,
        } => high_pressure(f, *nominal_pressure, *contact_modulus, *count),
        Warning::SteepSlope { rms_slope } => write!(
            f,
            "rms slope h'_rms = {} is above 1: outside the small-slope theory \
             (lengths are in m and wavevectors in 1/m: a height in µm given as m?)",
            n(*rms_slope)
        ),
        Warning::ZetaBeyondBand { zeta, zeta_max } => write!(
            f,
            "ζ = {} is beyond q_s/q_l = {}: C(q) = 0 above q_s, so the result is that of \
             full magnification ζ = {}",
            n(*zeta),
            n(*zeta_max),
            n(*zeta_max)
        ),
        Warning::BandLimited {
            grid,
            surface_rms_slope,
            rms_slope,
        } => write!(
            f,
            "the {grid}² surface is band-limited by its grid: its rms slope is {} against \
             the spectrum's {} (a finer grid, or a smaller q_s, resolves it)",
            n(*surface_rms_slope),
            n(*rms_slope)
        ),
        Warning::PsdConvention { file, convention } => {
            write!(
                f,
                "spectrum file {} read in the `{convention}` convention",
                file.display()
            )?;
            if *convention == ConventionName::Persson {
                write!(
                    f,
                    "; a SurfaceTopography or contact.engineering PSD needs the \
                     `surface-topography` convention"
                )?;
            }
            Ok(())
        }
        Warning::RisingSpectrum {
            file,
            c_first,
            c_last,
        } => write!(
            f,
            "C(q) of {} does not fall with q (C = {} at the first q, {} at the last): \
             is it a height map or profile? a measured surface is read as a height map, \
             not as a spectrum",
            file.display(),
            n(*c_first),
            n(*c_last)
        ),
        Warning::ClippedBand {
            q_s_requested,
            q_s,
            q_l,
            grid,
            pixels_per_wavelength,
        } => write!(
            f,
            "q_s = {} is not resolved by the coarsest grid ({grid}², {} pixels per \
             wavelength); the theories and the BEM use q_s = {} (= {}·q_l)",
            n(*q_s_requested),
            n(*pixels_per_wavelength),
            n(*q_s),
            n(*q_s / *q_l)
        ),
        _ => {
            *mine = false;
            Ok(())
        }
    }
}

/// The text of the warnings of this group; `mine` set to false for the others.
fn text_of_theories(w: &Warning, f: &mut fmt::Formatter<'_>, mine: &mut bool) -> fmt::Result {
    let n = |v: f64| number(v, 6);
    match w {
        Warning::Resampled {
            file,
            points,
            max_deviation,
        } => write!(
            f,
            "{}: the x positions are not equally spaced (up to {} pixel(s) off the equally \
             spaced grid): the heights were linearly interpolated onto {points} equally \
             spaced points",
            file.display(),
            n(*max_deviation)
        ),
        Warning::HurstNotFitted { file, bins } => write!(
            f,
            "{}: no Hurst exponent (hurst null): {bins} spectrum bin(s) in the band, a fit \
             needs 3",
            file.display()
        ),
        Warning::HurstOutOfRange {
            file,
            hurst,
            hurst_error,
        } => write!(
            f,
            "{}: no Hurst exponent (hurst null): the fit gives H = {} ± {}, outside (0, 1) \
             where the spectrum is w-affine",
            file.display(),
            n(*hurst),
            n(*hurst_error)
        ),
        Warning::BinsLeftOut {
            file,
            count,
            of,
            q_range,
        } => write!(
            f,
            "{}: {count} of {of} bins of the line scans' 1D spectrum (q = {} … {} 1/m) do \
             not fall faster than 1/q and have no isotropic 2D counterpart: left out of \
             C(q) (the rms values keep them)",
            file.display(),
            n(q_range.0),
            n(q_range.1)
        ),
        Warning::SumBands { bands, ratio } => {
            let b: Vec<String> = bands
                .iter()
                .map(|(a, b)| format!("{} … {}", n(*a), n(*b)))
                .collect();
            write!(
                f,
                "the rough bodies' spectra cover bands q = {} 1/m, a factor {} apart: \
                 outside their common band the summed roughness is one body's alone",
                b.join(" and "),
                n(*ratio)
            )
        }
        _ => {
            *mine = false;
            Ok(())
        }
    }
}

/// The text of the warnings of this group; `mine` set to false for the others.
fn text_of_solves(w: &Warning, f: &mut fmt::Formatter<'_>, mine: &mut bool) -> fmt::Result {
    let n = |v: f64| number(v, 6);
    match w {
        Warning::MeasurementGap {
            below,
            above,
            q_range,
        } => write!(
            f,
            "the reliable bands of {} and {} do not overlap: no measurement covers \
             q = {} … {} 1/m, where the combined spectrum is interpolated (power law)",
            below.display(),
            above.display(),
            n(q_range.0),
            n(q_range.1)
        ),
        Warning::PreconditionerFallback {
            nominal_pressure,
            iterations,
        } => {
            let list: Vec<String> = nominal_pressure.iter().map(|&p| n(p)).collect();
            write!(
                f,
                "the preconditioned BEM solver stalled at σ0 = {} (after {} iteration(s)) \
                 and the plain Polonsky–Keer loop finished: same answer and tolerance, \
                 more time",
                list.join(", "),
                iterations
                    .iter()
                    .map(|k| k.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        }
        _ => {
            *mine = false;
            Ok(())
        }
    }
}

/// The text of the warnings of this group; `mine` set to false for the others.
fn text_of_rest(w: &Warning, f: &mut fmt::Formatter<'_>, mine: &mut bool) -> fmt::Result {
    match w {
        Warning::MapNotPeriodic => write!(
            f,
            "the map is not periodic: its coarser copies are block averages, each a \
             smoother surface, so N → ∞ is a resolution trend, not a continuum limit; \
             trust the finest grid (the map as measured)"
        ),
        _ => {
            *mine = false;
            Ok(())
        }
    }
}

/// The text of [`Warning::HighPressure`]: a unit slip when σ0 exceeds E*
/// itself, strains of order one above 0.1 E*.
fn high_pressure(
    f: &mut fmt::Formatter<'_>,
    nominal_pressure: f64,
    contact_modulus: f64,
    count: usize,
) -> fmt::Result {
    let n = |v: f64| number(v, 6);
    let which = if count > 1 {
        format!(
            "{count} nominal pressures, up to σ0 = {}, are",
            n(nominal_pressure)
        )
    } else {
        format!("the nominal pressure σ0 = {} is", n(nominal_pressure))
    };
    if nominal_pressure > contact_modulus {
        write!(
            f,
            "{which} above E* = {} itself: are E (or E*) and σ0 in one unit? \
             (E typed in MPa or GPa, σ0 in Pa?)",
            n(contact_modulus)
        )
    } else {
        write!(
            f,
            "{which} above 0.1 E* = {} (E* = {}): strains of order one, outside \
             the small-strain theory (or E and σ0 in different units?)",
            n(HIGH_PRESSURE_RATIO * contact_modulus),
            n(contact_modulus)
        )
    }
}

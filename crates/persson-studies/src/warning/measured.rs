//! The warnings of a measured surface (feature `topography`).

use super::Warning;

/// The warnings of a measured surface's analysis: what the reader did (a
/// line scan resampled) and what the analysis could not do (no Hurst fit,
/// bins left out of the 2D spectrum).
pub fn of_measured(file: &std::path::Path, a: &persson::topography::Analysis) -> Vec<Warning> {
    of_notes(file, &a.notes)
}

/// The warnings of a measured surface's notes ([`of_measured`] without the
/// analysis: for a spectrum that keeps only its notes, as a pickled Python
/// `Spectrum` does). `file` names the input (a stand-in such as `(array)`
/// for heights that came from no file).
pub fn of_notes(file: &std::path::Path, notes: &[persson::topography::Note]) -> Vec<Warning> {
    use persson::topography::Note;
    let file = file.to_path_buf();
    notes
        .iter()
        .map(|note| match note {
            Note::Resampled {
                points,
                max_deviation,
            } => Warning::Resampled {
                file: file.clone(),
                points: *points,
                max_deviation: *max_deviation,
            },
            Note::HurstNotFitted { bins } => Warning::HurstNotFitted {
                file: file.clone(),
                bins: *bins,
            },
            Note::HurstOutOfRange { hurst, hurst_error } => Warning::HurstOutOfRange {
                file: file.clone(),
                hurst: *hurst,
                hurst_error: *hurst_error,
            },
            Note::CurvatureNotComputed { shape, .. } => Warning::CurvatureNotComputed {
                file: file.clone(),
                shape: *shape,
            },
            Note::BinsLeftOut { q, of } => Warning::BinsLeftOut {
                file: file.clone(),
                count: q.len(),
                of: *of,
                q_range: q
                    .iter()
                    .fold((f64::INFINITY, 0.0), |(lo, hi), &v| (lo.min(v), hi.max(v))),
            },
        })
        .collect()
}

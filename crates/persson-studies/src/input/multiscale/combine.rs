//! Reading the measurements and combining their spectra (feature `topography`).

use persson::error::{Error, Result};

use super::super::HeightMapSpec;
use super::{BandSpectrum, MeasurementBand, MultiScaleReport, BINS_PER_DECADE};
use crate::warning::Warning;

/// Read, condition and combine the measurements.
///
/// # Errors
/// No measurement; the errors of each file (named); a tip radius so large
/// that a measurement has no reliable band.
pub fn multi_scale(specs: &[HeightMapSpec]) -> Result<MultiScaleReport> {
    use persson::topography::{self as topo, AnalysisOptions, Measurement};
    let mut expanded = Vec::with_capacity(specs.len());
    for s in specs {
        match s.dataset_measurements()? {
            Some(ms) => expanded.extend(ms),
            None => expanded.push(s.clone()),
        }
    }
    let specs = &expanded[..];
    let maps: Vec<topo::Topography> = specs.iter().map(|s| s.read()).collect::<Result<_>>()?;
    let measurements: Vec<Measurement<'_>> = specs
        .iter()
        .zip(&maps)
        .map(|(s, t)| Measurement {
            topography: t,
            options: AnalysisOptions {
                detrend: s.detrend,
                window: s.window,
                q_max: s.q_max,
                bins: None,
            },
            tip_radius: s.tip_radius,
        })
        .collect();
    let m = topo::multi_scale(&measurements, BINS_PER_DECADE).map_err(|e| name_file(specs, e))?;
    let mut warnings = Vec::new();
    for (s, c) in specs.iter().zip(&m.measurements) {
        for w in crate::warning::of_measured(&s.label(), &c.analysis) {
            crate::warning::push(&mut warnings, Some(w));
        }
    }
    for g in &m.gaps {
        warnings.push(Warning::MeasurementGap {
            below: specs[g.below].label(),
            above: specs[g.above].label(),
            q_range: g.q_range,
        });
    }
    Ok(MultiScaleReport {
        measurements: specs
            .iter()
            .zip(&m.measurements)
            .map(|(s, c)| MeasurementBand {
                file: s.label(),
                shape: c.analysis.shape,
                pixel_size: c.analysis.pixel_size.clone(),
                q_min: c.reliable.0,
                q_max: c.reliable.1,
                tip_cutoff_length: c.tip_cutoff_length,
                rms_height: c.analysis.rms_height,
                psd: BandSpectrum {
                    q: c.analysis.psd.q.clone(),
                    c: c.analysis.psd.c.clone(),
                    count: c.analysis.psd.count.clone(),
                },
            })
            .collect(),
        q: m.q,
        c: m.c,
        count: m.count,
        contributors: m.contributors,
        q_min: m.q_min,
        q_max: m.q_max,
        warnings,
    })
}

/// An error of the numerics naming "measurement i": name its file.
fn name_file(specs: &[HeightMapSpec], e: Error) -> Error {
    if let Error::Inconsistent { name, requirement } = &e {
        if let Some(i) = name
            .strip_prefix("measurement ")
            .and_then(|n| n.parse::<usize>().ok())
            .filter(|i| (1..=specs.len()).contains(i))
        {
            return Error::parse(&specs[i - 1].file, 0, 0, requirement.clone());
        }
    }
    e
}

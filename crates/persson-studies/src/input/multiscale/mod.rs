//! One spectrum from several measurements of a surface (`--surface A
//! --surface B …`, a scene's `multi_scale` spectrum): each file read and
//! conditioned as a single `height_map`, then combined by
//! [`persson::topography::multi_scale`]; the report shows each
//! measurement's band and the combined spectrum.

use std::path::PathBuf;

use persson::error::Result;
use persson::spectrum::Tabulated;
use serde::Serialize;

use super::{Described, HeightMapSpec};
use crate::table::{number, Cell, Table, Tabulate};
use crate::warning::Warning;

// Reading and combining the measurements (feature `topography`).
#[cfg_attr(not(feature = "topography"), path = "off.rs")]
mod combine;
pub use combine::multi_scale;

/// Edges per decade of the common log grid (as a single measurement's).
pub const BINS_PER_DECADE: usize = 10;

/// A measurement's band in a multi-scale spectrum.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct MeasurementBand {
    /// The file.
    pub file: PathBuf,
    /// `[ny, nx]`.
    pub shape: [usize; 2],
    /// `[Δx, Δy]` or `[Δx]`, m.
    pub pixel_size: Vec<f64>,
    /// Lower end of its reliable band (the bins it contributes), 1/m.
    pub q_min: f64,
    /// Upper end of its reliable band, 1/m.
    pub q_max: f64,
    /// Tip-radius cut-off λ_c, m (none: no tip radius given, or no artefact).
    pub tip_cutoff_length: Option<f64>,
    /// rms height of the detrended heights, m.
    pub rms_height: f64,
    /// Its binned spectrum over its band.
    pub psd: BandSpectrum,
}

/// A measurement's binned spectrum on the common bins.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct BandSpectrum {
    /// Mean q of each bin, 1/m.
    pub q: Vec<f64>,
    /// Mean C of each bin, m⁴ (Persson).
    pub c: Vec<f64>,
    /// Modes in each bin.
    pub count: Vec<usize>,
}

/// The combined spectrum of several measurements and each one's band.
#[derive(Debug, Clone, Serialize)]
#[non_exhaustive]
pub struct MultiScaleReport {
    /// Each measurement, in the order given.
    pub measurements: Vec<MeasurementBand>,
    /// Mode-weighted mean q of each bin, 1/m.
    pub q: Vec<f64>,
    /// Mode-weighted mean C of each bin, m⁴ (Persson).
    pub c: Vec<f64>,
    /// Modes of all measurements in each bin.
    pub count: Vec<usize>,
    /// Measurements contributing to each bin.
    pub contributors: Vec<usize>,
    /// Lower end of the union band, 1/m.
    pub q_min: f64,
    /// Upper end of the union band, 1/m.
    pub q_max: f64,
    /// Remarks (gaps between bands, each file's own).
    pub warnings: Vec<Warning>,
}

impl MultiScaleReport {
    /// The combined spectrum as a [`Tabulated`] one.
    ///
    /// # Errors
    /// Fewer than two bins, a bin with C = 0.
    pub fn to_tabulated(&self) -> Result<Tabulated> {
        let pts: Vec<(f64, f64)> = self.q.iter().copied().zip(self.c.iter().copied()).collect();
        Tabulated::new(&pts)
    }

    /// What the spectrum is, in words, for report titles.
    pub fn describe(&self) -> String {
        let parts: Vec<String> = self
            .measurements
            .iter()
            .map(|m| {
                format!(
                    "{} (q = {} … {} 1/m)",
                    m.file.display(),
                    number(m.q_min, 4),
                    number(m.q_max, 4)
                )
            })
            .collect();
        format!(
            "{} measurements combined (mode-weighted mean over overlaps): {}",
            parts.len(),
            parts.join(", ")
        )
    }
}

/// The combined spectrum as a scene's spectrum, described, with warnings.
///
/// # Errors
/// As [`multi_scale`].
pub fn described(specs: &[HeightMapSpec]) -> Result<Described<Tabulated>> {
    let r = multi_scale(specs)?;
    Ok(Described {
        value: r.to_tabulated()?,
        description: Some(r.describe()),
        warnings: r.warnings,
    })
}

impl Tabulate for MultiScaleReport {
    /// Two tables: `measurements` (each file's band) and `psd` (the combined
    /// spectrum: q, C, modes, measurements per bin).
    fn tables(&self) -> Vec<Table> {
        let mut m = Table::new("measurements", "Measurements and their reliable bands")
            .column("file", "file")
            .column("shape", "points")
            .column("q_min", "q_min (1/m)")
            .column("q_max", "q_max (1/m)")
            .column("tip_cutoff_length", "tip cut-off λ_c (m)")
            .column("rms_height", "h_rms (m)");
        for b in &self.measurements {
            m.push(vec![
                Cell::from(b.file.display().to_string()),
                Cell::from(format!("{} × {}", b.shape[0], b.shape[1])),
                Cell::Num(b.q_min),
                Cell::Num(b.q_max),
                b.tip_cutoff_length.map_or(Cell::Empty, Cell::Num),
                Cell::Num(b.rms_height),
            ]);
        }
        let mut t = Table::new(
            "psd",
            "Combined isotropic power spectrum C(q) (Persson's normalisation, mode-weighted mean)",
        )
        .column("q", "q (1/m)")
        .column("c", "C (m⁴)")
        .column("count", "modes")
        .column("contributors", "measurements");
        for i in 0..self.q.len() {
            t.push(vec![
                Cell::Num(self.q[i]),
                Cell::Num(self.c[i]),
                Cell::from(self.count[i]),
                Cell::from(self.contributors[i]),
            ]);
        }
        vec![m, t]
    }
}

//! Histograms of contact pressures: one bin type for a single solve
//! ([`pressure_histogram`]) and for counts accumulated over many solves
//! ([`PressureCounts`]).
//!
//! Both are normalised like Persson's P(σ) without the δ(σ) of the
//! non-contact area: the bins integrate to the contact fraction A/A0.

use serde::Serialize;

use crate::error::{Error, Result};

/// One bin of a pressure histogram.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct HistogramBin {
    /// Lower edge σ of the bin (unit of the pressure).
    pub sigma_low: f64,
    /// Upper edge σ of the bin.
    pub sigma_high: f64,
    /// P(σ): nodes in the bin / (nodes · bin width), so that the bins
    /// integrate to A/A0.
    pub density: f64,
}

impl HistogramBin {
    /// The centre of the bin.
    pub fn sigma(&self) -> f64 {
        0.5 * (self.sigma_low + self.sigma_high)
    }
}

/// ∫ P dσ of a histogram: Σ_k P_k Δσ_k (= A/A0).
pub fn integral(bins: &[HistogramBin]) -> f64 {
    bins.iter()
        .map(|b| b.density * (b.sigma_high - b.sigma_low))
        .sum()
}

/// Histogram of the contact pressures (p > 0) over `bins` equal bins from 0
/// to max p.
///
/// # Formula
/// ```text
/// P_k = #{i : p_i ∈ bin k, p_i > 0} / (N² Δσ),   Σ_k P_k Δσ = A/A0
/// ```
///
/// # Errors
/// `bins == 0`.
pub fn pressure_histogram(pressure: &[f64], bins: usize) -> Result<Vec<HistogramBin>> {
    if bins == 0 {
        return Err(Error::invalid("bins", 0.0, ">= 1"));
    }
    let p_max = pressure.iter().copied().fold(0.0, f64::max);
    if p_max <= 0.0 {
        return Ok(Vec::new());
    }
    let width = p_max / bins as f64;
    let mut counts = vec![0usize; bins];
    for &p in pressure.iter().filter(|p| **p > 0.0) {
        let k = ((p / width) as usize).min(bins - 1);
        counts[k] += 1;
    }
    let norm = 1.0 / (pressure.len() as f64 * width);
    Ok(counts
        .iter()
        .enumerate()
        .map(|(k, &c)| HistogramBin {
            sigma_low: k as f64 * width,
            sigma_high: (k + 1) as f64 * width,
            density: c as f64 * norm,
        })
        .collect())
}

/// A pressure histogram with a yield stress: the elastic part in bins and
/// the plastic part (the δ-peak at σY) as its own number.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SaturatedHistogram {
    /// Bins of the nodes with 0 < p < σY, equal widths from 0 to σY:
    /// they integrate to `elastic_fraction`.
    pub bins: Vec<HistogramBin>,
    /// Fraction of nodes at p = σY (the weight of the δ-peak at σY).
    pub plastic_fraction: f64,
}

/// Histogram of a saturated solution ([`super::Options::yield_stress`]):
/// the nodes with `0 < p < σY` in `bins` equal bins on `[0, σY)`, the nodes
/// at `p ≥ σY` counted apart (not smeared into the last bin).
///
/// # Formula
/// ```text
/// P_k = #{i : p_i ∈ bin k, 0 < p_i < σY} / (N² Δσ),  Δσ = σY / bins
/// Σ_k P_k Δσ + #{p_i = σY}/N² = A/A0
/// ```
///
/// # Errors
/// `bins == 0`, σY not finite and > 0.
pub fn saturated_histogram(
    pressure: &[f64],
    bins: usize,
    yield_stress: f64,
) -> Result<SaturatedHistogram> {
    if bins == 0 {
        return Err(Error::invalid("bins", 0.0, ">= 1"));
    }
    let y = crate::error::check::positive("yield_stress", yield_stress)?;
    let width = y / bins as f64;
    let mut counts = vec![0usize; bins];
    let mut plastic = 0usize;
    for &p in pressure.iter().filter(|p| **p > 0.0) {
        if p >= y {
            plastic += 1;
        } else {
            counts[((p / width) as usize).min(bins - 1)] += 1;
        }
    }
    let nodes = pressure.len().max(1) as f64;
    let norm = 1.0 / (nodes * width);
    Ok(SaturatedHistogram {
        bins: counts
            .iter()
            .enumerate()
            .map(|(k, &c)| HistogramBin {
                sigma_low: k as f64 * width,
                sigma_high: (k + 1) as f64 * width,
                density: c as f64 * norm,
            })
            .collect(),
        plastic_fraction: plastic as f64 / nodes,
    })
}

/// Fine bins per nominal pressure σ0 of [`PressureCounts`] (rebinned to the
/// requested number of bins at the end, on edges that are multiples of σ0/200).
const FINE_BINS_PER_SIGMA0: f64 = 200.0;

/// Counts of contact pressures in fine bins of width σ0/200, accumulated over
/// several solves (seeds); rebinned by [`PressureCounts::bins`].
#[derive(Debug, Clone, PartialEq)]
pub struct PressureCounts {
    width: f64,
    counts: Vec<u64>,
    nodes: u64,
}

impl PressureCounts {
    /// No counts yet, for nominal pressure `sigma0`.
    pub fn new(sigma0: f64) -> Self {
        PressureCounts {
            width: sigma0 / FINE_BINS_PER_SIGMA0,
            counts: Vec::new(),
            nodes: 0,
        }
    }

    /// Add a pressure field.
    pub fn add(&mut self, pressure: &[f64]) {
        self.nodes += pressure.len() as u64;
        for &p in pressure.iter().filter(|p| **p > 0.0 && p.is_finite()) {
            let k = (p / self.width) as usize;
            if k >= self.counts.len() {
                self.counts.resize(k + 1, 0);
            }
            self.counts[k] += 1;
        }
    }

    /// `bins` equal bins from 0 past the largest pressure (edges on the fine
    /// grid); empty when nothing was counted.
    ///
    /// # Formula
    /// ```text
    /// P_k = #{p ∈ bin k, p > 0} / (nodes Δσ),   Σ_k P_k Δσ = A/A0 (mean over solves)
    /// ```
    pub fn bins(&self, bins: usize) -> Vec<HistogramBin> {
        if bins == 0 || self.counts.is_empty() || self.nodes == 0 {
            return Vec::new();
        }
        let per = self.counts.len().div_ceil(bins).max(1);
        let width = per as f64 * self.width;
        let norm = 1.0 / (self.nodes as f64 * width);
        (0..bins)
            .map(|k| {
                let c: u64 = self.counts.iter().skip(k * per).take(per).sum();
                HistogramBin {
                    sigma_low: k as f64 * width,
                    sigma_high: (k + 1) as f64 * width,
                    density: c as f64 * norm,
                }
            })
            .collect()
    }
}

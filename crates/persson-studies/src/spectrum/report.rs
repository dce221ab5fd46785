//! The spectrum summary: moments, a power-law fit and C(q).

use serde::Serialize;

use crate::table::{number, Table, Tabulate};

use crate::table::surface_prefix;

/// The spectrum's moments, a power-law fit and C(q) (`persson spectrum`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SpectrumReport {
    /// What the surface is, if known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// Lower cut-off q_l.
    pub q_l: f64,
    /// Upper cut-off q_s.
    pub q_s: f64,
    /// Lower end of the band of the moments.
    pub q_min: f64,
    /// Upper end of the band of the moments.
    pub q_max: f64,
    /// rms height over the band.
    pub rms_height: f64,
    /// Its error bound.
    pub rms_height_error_bound: f64,
    /// rms slope over the band.
    pub rms_slope: f64,
    /// Its error bound.
    pub rms_slope_error_bound: f64,
    /// rms curvature over the band.
    pub rms_curvature: f64,
    /// Its error bound.
    pub rms_curvature_error_bound: f64,
    /// Half of `rms_curvature`, the rms mean curvature ∇²h/2 (1/m): what
    /// SurfaceTopography and contact.engineering call `rms_curvature`.
    pub mean_curvature_rms: f64,
    /// Power law C = prefactor q^exponent fitted over the upper half (in log q) of [q_l, q_s].
    pub power_law_fit: PowerLawFit,
    /// C(q) at log-spaced q.
    pub table: Vec<SpectrumPoint>,
    /// C(q) on a fine grid, for the figure.
    #[serde(skip)]
    pub curve: Vec<SpectrumPoint>,
    /// Remarks on the input (never a change of a number); the CLI prints them
    /// on stderr and in the top-level `warnings` of `--json`.
    #[serde(skip)]
    pub warnings: Vec<crate::warning::Warning>,
}

/// A power law fitted to C(q).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PowerLawFit {
    /// Prefactor.
    pub prefactor: f64,
    /// Exponent −2(H + 1).
    pub exponent: f64,
    /// H = −exponent/2 − 1.
    pub hurst: f64,
    /// Lower end of the fit.
    pub q_min: f64,
    /// Upper end of the fit.
    pub q_max: f64,
}

/// One point of C(q).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SpectrumPoint {
    /// Wavevector q.
    pub q: f64,
    /// C(q), Persson's normalisation.
    pub c: f64,
}

impl Tabulate for SpectrumReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "spectrum",
            format!(
                "{}Spectrum (Persson's normalisation), moments over q in [{}, {}] 1/m",
                surface_prefix(&self.surface),
                number(self.q_min, 6),
                number(self.q_max, 6)
            ),
        )
        .scalar("q_l", "q_l", self.q_l)
        .scalar("q_s", "q_s", self.q_s)
        .scalar("rms_height", "rms height h_rms", self.rms_height)
        .scalar("rms_slope", "rms slope h'_rms", self.rms_slope)
        .scalar("rms_curvature", "rms curvature h''_rms", self.rms_curvature)
        .scalar(
            "mean_curvature_rms",
            "rms mean curvature",
            self.mean_curvature_rms,
        )
        .scalar(
            "exponent",
            "fitted exponent of C(q)",
            self.power_law_fit.exponent,
        )
        .scalar("hurst", "fitted H", self.power_law_fit.hurst)
        .column("q", "q")
        .column("c", "C(q)");
        for p in &self.table {
            t.push(vec![p.q.into(), p.c.into()]);
        }
        vec![t]
    }
}

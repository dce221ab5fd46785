//! Remarks on a measured surface: what the reader did to the data, or
//! what the analysis could not do, that the user should know of. The
//! numbers are computed regardless; they are typed data, and an
//! application words them as warnings (`persson_studies::warning::of_measured`).

/// A remark on a measured surface ([`crate::topography::Topography::notes`],
/// [`crate::topography::Analysis::notes`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
// Exhaustive on purpose: the application that words these as warnings must
// handle every note, so a new one is a compile error there, not a silence.
pub enum Note {
    /// The x positions of a line scan are not equally spaced (beyond the
    /// precision written): the heights were linearly interpolated onto
    /// `points` equally spaced positions from the first to the last x.
    Resampled {
        /// Points of the scan (and of the equally spaced grid).
        points: usize,
        /// The largest `|x_i − x_0 − iΔ|` of the file, in units of Δ.
        max_deviation: f64,
    },
    /// Too few spectrum bins with C > 0 in the band for a Hurst fit (3 needed):
    /// `hurst` is not given.
    HurstNotFitted {
        /// Bins with C > 0 in the band.
        bins: usize,
    },
    /// The fitted Hurst exponent is outside (0, 1), where the self-affine
    /// model holds: `hurst` is not given.
    HurstOutOfRange {
        /// The fitted H.
        hurst: f64,
        /// Its standard error.
        hurst_error: f64,
    },
    /// The real-space curvature (5-point Laplacian; 3-point along line
    /// scans) needs a point with neighbours on both sides: a non-periodic
    /// map of fewer than 3 points along x or y (a line scan of fewer than 3
    /// points) has none, so `rms_curvature` and `mean_curvature_rms` are not
    /// given.
    CurvatureNotComputed {
        /// `[ny, nx]` of the surface.
        shape: [usize; 2],
        /// Whether it was taken as periodic (then every point has them).
        periodic: bool,
    },
    /// Bins of a line scan's 1D spectrum whose local log-log slope is not
    /// below −1 (a noise floor, a few modes at low q) have no isotropic 2D
    /// counterpart ([`crate::spectrum::Convention::Profile1D`]) and were left
    /// out of the 2D spectrum; the rms values, from the 1D spectrum, keep them.
    BinsLeftOut {
        /// The q of the bins left out, 1/m.
        q: Vec<f64>,
        /// The bins of the 1D spectrum.
        of: usize,
    },
}

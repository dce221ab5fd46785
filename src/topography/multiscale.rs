//! One spectrum from several measurements of the same surface at different
//! scales (a coarse large scan, a medium one, a fine small one).
//!
//! Each measurement contributes its reliable band: from its size
//! (`q ≥ 2π/max(Lx, Ly)`, the lowest bin of its radial average) down to a
//! short-wavelength cut-off, the smallest of
//! - the Nyquist wavevector `π/Δ`,
//! - a cut-off the user gives (`q_max` of [`AnalysisOptions`]),
//! - for scanning probes, the tip-radius criterion of [`tip_radius_cutoff`]
//!   (`q_c = 2π/λ_c`, as SurfaceTopography's reliability analysis).
//!
//! Within that band a measurement contributes only its *reliable* bins
//! ([`Contribution::reliable`]), which leaves out two biases (measured by
//! `examples/multiscale_bias.rs` on three maps cut from one surface with
//! white noise of 3 % of their rms height; without these cuts A/A0 at
//! 1 MPa from the combined spectrum was 33–52 % below that of the whole
//! surface's spectrum, at every seed):
//! - **the noise and aliasing floor** at the short-wavelength end. A map's
//!   floor `C_f` is the mean C of its corner modes, `π/Δ < |q| ≤ √2·π/Δ`
//!   (summed while its spectrum is binned, from the same transform),
//!   where a self-affine surface has least power: white noise of variance
//!   σ² gives `σ²Δ²/(2π)²` there (a test checks it), and point sampling
//!   adds the aliased power. The reliable band ends at the first bin whose C
//!   is below [`FLOOR_FACTOR`]`·C_f` (the floor's share at most 1 %).
//!   Line scans have no corner modes: their band ends at the cut-offs above.
//! - **the window's main lobe** at the long-wavelength end: a window
//!   averages C over ±2 modes (Hann; more for Blackman), which raises a
//!   steep spectrum's lowest bins (measured: +45 % at 4–8 modes of a map).
//!   A windowed measurement's reliable band starts at [`LOW_MODES`]`·2π/L`,
//!   the lowest-reaching one's too: nothing else measures its lowest bins,
//!   and kept they made A/A0 at 1 MPa 1.5 % low on average (48 seeds, 3 %
//!   noise). A measurement taken as periodic (no window) keeps all its bins.
//!
//! All measurements are binned on one log grid over the union band
//! ([`Bins::Log`] over `[min_i q_lo⁽ⁱ⁾, max_i q_hi⁽ⁱ⁾]`); a measurement
//! contributes to the bins that lie wholly below its cut-off (C falls by a
//! factor ≈ 2 across a bin of a tenth of a decade: a partly covered bin
//! would be biased high), and in every bin the contributions are averaged,
//! weighted by their mode counts:
//!
//! # Formula
//! ```text
//! C̄_b = Σ_i n_b⁽ⁱ⁾ C̄_b⁽ⁱ⁾ / Σ_i n_b⁽ⁱ⁾            [m⁴]
//! q̄_b = Σ_i n_b⁽ⁱ⁾ q̄_b⁽ⁱ⁾ / Σ_i n_b⁽ⁱ⁾            [1/m]
//! ```
//! with `C̄_b⁽ⁱ⁾` the mean C of the `n_b⁽ⁱ⁾` Fourier modes of measurement i in
//! bin b ([`super::Psd`]). A mode's periodogram value has a relative variance
//! of about 1 (χ² with two degrees of freedom), so the mode-count weights are
//! the inverse-variance weights and `C̄_b` is the mean over all modes of all
//! measurements in the bin. (SurfaceTopography's `log_average` takes the
//! unweighted mean of the measurements instead; `docs/multiscale.md` compares
//! the two.) For line scans the counts are those of the 1D modes (±q over all
//! profiles), as [`super::Psd::count`] says.
//!
//! Reliable bands that do not overlap leave a gap (a [`Gap`] in the result, the
//! measurements on either side named by index); the combined table then
//! interpolates across it as a power law.
//!
//! # References
//! T. D. B. Jacobs, T. Junge & L. Pastewka, Surf. Topogr.: Metrol. Prop. 5,
//! 013001 (2017), doi:10.1088/2051-672X/aa51f8 (multi-scale spectra);
//! M. C. Röttger et al., Surf. Topogr.: Metrol. Prop. 10, 035032 (2022),
//! doi:10.1088/2051-672X/ac860a (contact.engineering, averaging);
//! A. Sanner et al., Appl. Surf. Sci. Adv. 7, 100190 (2022),
//! doi:10.1016/j.apsadv.2021.100190 (tip-radius reliability cut-off).

use super::{analyse, Analysis, AnalysisOptions, Bins, Topography};
use crate::error::{check, Error, Result};
use crate::spectrum::Tabulated;

/// The lowest bins of a windowed measurement: left out below
/// `LOW_MODES · 2π/L` (the window's main lobe averages C over ±2 modes,
/// which biases a steep spectrum high there: +45 % at 4–8 modes, measured
/// by `examples/multiscale_bias.rs`).
pub const LOW_MODES: f64 = 8.0;

/// A bin is reliable while its C is at least this many times the map's
/// floor (white noise, aliasing): their excess is then at most 1 %.
pub const FLOOR_FACTOR: f64 = 100.0;

/// SurfaceTopography's default safety factor f of the tip-radius criterion
/// (Sanner et al. 2022 estimate 1/2 from simulated scans).
pub const TIP_SAFETY_FACTOR: f64 = 0.5;

/// One measurement of a multi-scale set: the map (or line scans), how to
/// analyse it (its `q_max` the user's cut-off) and the radius of the probe
/// that scanned it, if any.
#[derive(Debug, Clone)]
pub struct Measurement<'a> {
    /// The heights.
    pub topography: &'a Topography,
    /// Detrending, window and the user's cut-off `q_max` (its `bins` are
    /// replaced by the common grid).
    pub options: AnalysisOptions,
    /// Radius R of the scanning probe's tip, m (`None`: not a scanning
    /// probe, no tip-radius cut-off).
    pub tip_radius: Option<f64>,
}

/// A measurement's part of the combined spectrum.
#[derive(Debug, Clone, serde::Serialize)]
#[non_exhaustive]
pub struct Contribution {
    /// Its analysis on the common bins (spectrum, statistics, Hurst fit).
    pub analysis: Analysis,
    /// Lower end of the bins it contributes, 1/m (`2π/max(Lx, Ly)`).
    pub q_min: f64,
    /// Upper end: the smallest of Nyquist, the user's `q_max` and the
    /// tip-radius cut-off, 1/m.
    pub q_max: f64,
    /// The tip-radius cut-off λ_c, m (`None`: no tip radius, or no tip
    /// artefact at the smallest scale).
    pub tip_cutoff_length: Option<f64>,
    /// The floor of a map's spectrum: the mean C of its corner modes,
    /// `π/Δ < |q| ≤ √2·π/Δ`, m⁴ (white noise and aliased power; `None` for
    /// line scans).
    pub floor: Option<f64>,
    /// The bins it contributes to the combined spectrum: its reliable band
    /// (module docs), `[q_lo, q_hi]` in 1/m.
    pub reliable: (f64, f64),
}

/// A wavevector range no measurement covers.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Gap {
    /// Index of the measurement below the gap (the one whose band ends at
    /// `q_range.0`).
    pub below: usize,
    /// Index of the measurement above it.
    pub above: usize,
    /// The uncovered range, 1/m.
    pub q_range: (f64, f64),
}

/// The combined spectrum of several measurements ([`multi_scale`]).
#[derive(Debug, Clone, serde::Serialize)]
#[non_exhaustive]
pub struct MultiScale {
    /// Mode-weighted mean |q| of each non-empty bin, 1/m.
    pub q: Vec<f64>,
    /// Mode-weighted mean C of each bin, m⁴ (Persson).
    pub c: Vec<f64>,
    /// Modes of all measurements in each bin.
    pub count: Vec<usize>,
    /// How many measurements contribute to each bin.
    pub contributors: Vec<usize>,
    /// Lower end of the union band, 1/m.
    pub q_min: f64,
    /// Upper end of the union band, 1/m.
    pub q_max: f64,
    /// Each measurement's contribution, in the order given.
    pub measurements: Vec<Contribution>,
    /// Ranges between the bands that no measurement covers.
    pub gaps: Vec<Gap>,
}

impl MultiScale {
    /// The combined spectrum as the crate's [`Tabulated`] (power law between
    /// the bins, across a gap too).
    ///
    /// # Errors
    /// Fewer than two bins, a bin with C = 0.
    pub fn to_tabulated(&self) -> Result<Tabulated> {
        let pts: Vec<(f64, f64)> = self.q.iter().copied().zip(self.c.iter().copied()).collect();
        Tabulated::new(&pts)
    }
}

/// Combine measurements of one surface into one spectrum (module docs).
///
/// `per_decade`: edges per decade of the common log grid (10 as a single
/// measurement's spectrum).
///
/// # Errors
/// No measurement; `per_decade` zero; a tip radius not finite and positive,
/// or so large that no scale of a measurement is reliable; fewer than two
/// reliable bins in all; the errors of [`analyse`] (the index of the
/// measurement named).
pub fn multi_scale(measurements: &[Measurement<'_>], per_decade: usize) -> Result<MultiScale> {
    if measurements.is_empty() {
        return Err(Error::invalid("number of measurements", 0.0, "at least 1"));
    }
    let mut bands = Vec::with_capacity(measurements.len());
    for (i, m) in measurements.iter().enumerate() {
        bands.push(band(m).map_err(|e| numbered(i, e))?);
    }
    let q_lo = bands.iter().map(|b| b.0).fold(f64::INFINITY, f64::min);
    let q_hi = bands.iter().map(|b| b.1).fold(0.0, f64::max);
    let edges = Bins::Log { per_decade }.edges(q_lo, q_hi)?;
    let nb = edges.len() - 1;
    let (mut w, mut wq, mut wc, mut who) = (
        vec![0usize; nb],
        vec![0.0; nb],
        vec![0.0; nb],
        vec![0usize; nb],
    );
    let analyses = analyse_all(measurements, &bands, &edges)?;
    // A map's floor comes from the transform of its analysis (the corner
    // modes, binned in the same pass); line scans have none.
    let floors: Vec<Option<f64>> = analyses
        .iter()
        .map(|a| a.psd.corner_mean.filter(|c| *c > 0.0))
        .collect();
    let tops: Vec<f64> = analyses
        .iter()
        .zip(&bands)
        .zip(&floors)
        .map(|((a, &(lo, hi, _)), floor)| reliable_top(a, &edges, lo, hi, *floor))
        .collect();
    let bin_of = |q: f64| {
        edges
            .partition_point(|e| *e < q)
            .saturating_sub(1)
            .min(nb - 1)
    };
    let mut contributions = Vec::with_capacity(measurements.len());
    for (i, ((a, &(lo, hi, tip)), floor)) in
        analyses.into_iter().zip(&bands).zip(floors).enumerate()
    {
        let bottom = if a.window == super::Window::None {
            lo
        } else {
            LOW_MODES * lo
        };
        let reliable = (bottom, tops[i].max(bottom));
        for ((&q, &c), &n) in a.psd.q.iter().zip(&a.psd.c).zip(&a.psd.count) {
            let b = bin_of(q);
            // A bin straddling the measurement's own lowest q counts (as a
            // single measurement's first bin); one straddling a raised
            // bottom does not.
            let below = bottom > lo && edges[b] < bottom * (1.0 - 1e-12);
            if below || edges[b + 1] > reliable.1 * (1.0 + 1e-12) {
                continue;
            }
            w[b] += n;
            wq[b] += n as f64 * q;
            wc[b] += n as f64 * c;
            who[b] += 1;
        }
        contributions.push(Contribution {
            analysis: a,
            q_min: lo,
            q_max: hi,
            tip_cutoff_length: tip,
            floor,
            reliable,
        });
    }
    let keep: Vec<usize> = (0..nb).filter(|&b| w[b] > 0).collect();
    if keep.len() < 2 {
        return Err(Error::Inconsistent {
            name: "multi-scale spectrum".into(),
            requirement: format!(
                "at least two bins in the measurements' reliable bands, found {}: a \
                 windowed scan's band starts at {LOW_MODES} modes (its window's main lobe \
                 below) and ends where its noise floor or cut-off begins; larger scans, or \
                 periodic ones without a window, have more",
                keep.len()
            ),
        });
    }
    Ok(MultiScale {
        q: keep.iter().map(|&b| wq[b] / w[b] as f64).collect(),
        c: keep.iter().map(|&b| wc[b] / w[b] as f64).collect(),
        count: keep.iter().map(|&b| w[b]).collect(),
        contributors: keep.iter().map(|&b| who[b]).collect(),
        q_min: q_lo,
        q_max: q_hi,
        gaps: gaps(
            &contributions
                .iter()
                .map(|c| (c.reliable.0, c.reliable.1, None))
                .collect::<Vec<_>>(),
        ),
        measurements: contributions,
    })
}

/// Each measurement's analysis on the common bins wholly below its cut-off,
/// in parallel (one thread each) where the platform has threads: they are
/// independent and the FFTs of large maps dominate the time. A browser's
/// module has one thread.
fn analyse_all(
    measurements: &[Measurement<'_>],
    bands: &[(f64, f64, Option<f64>)],
    edges: &[f64],
) -> Result<Vec<Analysis>> {
    let analyse = |i: usize, (m, &(lo, hi, _)): (&Measurement<'_>, &(f64, f64, Option<f64>))| {
        analyse_on(m, edges, lo, hi).map_err(|e| numbered(i, e))
    };
    let analyses: Vec<Result<Analysis>> = if std::thread::available_parallelism().is_err() {
        measurements
            .iter()
            .zip(bands)
            .enumerate()
            .map(|(i, mb)| analyse(i, mb))
            .collect()
    } else {
        std::thread::scope(|scope| {
            let handles: Vec<_> = measurements
                .iter()
                .zip(bands)
                .enumerate()
                .map(|(i, mb)| scope.spawn(move || analyse(i, mb)))
                .collect();
            handles
                .into_iter()
                .map(|h| {
                    h.join().unwrap_or_else(|_| {
                        Err(Error::Inconsistent {
                            name: "multi-scale analysis".into(),
                            requirement: "a measurement's analysis panicked".into(),
                        })
                    })
                })
                .collect()
        })
    };
    analyses.into_iter().collect()
}

/// The top of a measurement's reliable band (module docs): the lower edge
/// of the first bin from the bottom whose C is below [`FLOOR_FACTOR`] times
/// the map's floor, else its cut-off `hi`.
fn reliable_top(a: &Analysis, edges: &[f64], lo: f64, hi: f64, floor: Option<f64>) -> f64 {
    let Some(f) = floor else { return hi };
    a.psd
        .q
        .iter()
        .zip(&a.psd.c)
        .find(|&(_, &c)| c < FLOOR_FACTOR * f)
        .map_or(hi, |(&q, _)| {
            let b = edges.partition_point(|e| *e < q).saturating_sub(1);
            edges[b].clamp(lo, hi)
        })
}

/// A measurement's analysis on the common bins wholly below its cut-off.
fn analyse_on(m: &Measurement<'_>, edges: &[f64], lo: f64, hi: f64) -> Result<Analysis> {
    // The common bins wholly below the measurement's cut-off: modes beyond
    // it (aliased, noisy, sharper than the tip) stay out, and no bin is
    // averaged over part of its width (C falls by a factor 10^(0.1·2(1+H))
    // ≈ 2 across a bin: a partial bin is biased).
    let own: Vec<f64> = edges.iter().copied().take_while(|e| *e <= hi).collect();
    if own.len() < 2 {
        return Err(Error::invalid(
            "short-wavelength cut-off",
            hi,
            format!(
                "at least one whole bin of the common grid above q = {}",
                crate::error::num(lo)
            ),
        ));
    }
    let options = AnalysisOptions {
        q_max: Some(hi),
        bins: Some(Bins::Edges(own)),
        ..m.options.clone()
    };
    analyse(m.topography, &options)
}

/// A measurement's band `(q_lo, q_hi, λ_c)`: `2π/max(Lx, Ly)` to the smallest
/// of Nyquist, the user's q_max and the tip-radius cut-off.
fn band(m: &Measurement<'_>) -> Result<(f64, f64, Option<f64>)> {
    use std::f64::consts::TAU;
    let t = m.topography;
    let (q_min, nyquist) = t.band();
    let q_lo = match t.layout() {
        super::Layout::Map => (TAU / t.lx()).min(TAU / t.ly()),
        super::Layout::LineScans => TAU / t.lx(),
    };
    let mut q_hi = nyquist;
    if let Some(q) = m.options.q_max {
        check::positive("q_max", q)?;
        q_hi = q_hi.min(q);
    }
    let tip = match m.tip_radius {
        Some(r) => tip_radius_cutoff(t, r, TIP_SAFETY_FACTOR)?,
        None => None,
    };
    if let Some(l) = tip {
        q_hi = q_hi.min(TAU / l);
    }
    if q_hi <= q_min {
        return Err(Error::invalid(
            "short-wavelength cut-off",
            q_hi,
            format!(
                "above q_min = 2π/L = {} 1/m (the measurement has no reliable band)",
                crate::error::num(q_min)
            ),
        ));
    }
    Ok((q_lo, q_hi, tip))
}

/// The ranges between the bands that no band covers, with the measurements
/// on either side.
fn gaps(bands: &[(f64, f64, Option<f64>)]) -> Vec<Gap> {
    let mut order: Vec<usize> = (0..bands.len()).collect();
    order.sort_by(|&a, &b| bands[a].0.total_cmp(&bands[b].0));
    let mut out = Vec::new();
    let mut reach = (bands[order[0]].1, order[0]);
    for &i in &order[1..] {
        if bands[i].0 > reach.0 {
            out.push(Gap {
                below: reach.1,
                above: i,
                q_range: (reach.0, bands[i].0),
            });
        }
        if bands[i].1 > reach.0 {
            reach = (bands[i].1, i);
        }
    }
    out
}

/// The tip-radius reliability cut-off of a scanning-probe measurement: the
/// stencil length λ_c below which the most negative scale-dependent
/// curvature along x is sharper than the tip (a rigid sphere of radius R
/// cannot follow a valley of curvature below −1/R).
///
/// # Formula
/// ```text
/// h''_λ(x) = [h(x + λ/2) − 2 h(x) + h(x − λ/2)] / (λ/2)²     λ = 2 s Δx, s = 1, 2, …
/// λ_c:  min_x h''_λ(x) = −f / R
/// ```
/// over the points whose stencil lies inside the map (periodic maps wrap),
/// every row. The objective `min_x h''_λ + f/R` is found negative at the
/// smallest scale and non-negative at the largest (λ = L/2); the integer
/// step s where it changes sign is found by bisection, and λ_c is the linear
/// interpolation of the objective between s − 1 and s (SurfaceTopography
/// solves for a continuous λ with a Fourier-interpolated stencil; on the
/// integer steps the stencils are the same).
///
/// R in m (the unit of the heights), f dimensionless ([`TIP_SAFETY_FACTOR`]).
/// Returns `None` when the criterion holds at the smallest scale (no tip
/// artefact).
///
/// # Errors
/// R or f not finite and positive; the criterion violated even at λ = L/2
/// (no reliable data in the measurement).
///
/// # References
/// A. Sanner, W. G. Nöhring, L. A. Thimons, T. D. B. Jacobs & L. Pastewka,
/// Appl. Surf. Sci. Adv. 7, 100190 (2022), doi:10.1016/j.apsadv.2021.100190
/// (the criterion and f = 1/2); SurfaceTopography 1.27,
/// `scanning_probe_reliability_cutoff`.
pub fn tip_radius_cutoff(
    t: &Topography,
    tip_radius: f64,
    safety_factor: f64,
) -> Result<Option<f64>> {
    check::positive("tip_radius", tip_radius)?;
    check::positive("safety_factor", safety_factor)?;
    let target = safety_factor / tip_radius;
    let objective = |s: usize| min_curvature(t, s) + target;
    let s_max = (t.nx() / 4).max(1);
    if objective(1) >= 0.0 {
        return Ok(None);
    }
    if objective(s_max) < 0.0 {
        return Err(Error::invalid(
            "tip_radius",
            tip_radius,
            format!(
                "small enough that the measured curvature is within −{safety_factor}/R at some \
                 scale up to L/2 (the whole measurement is sharper than the tip)"
            ),
        ));
    }
    let (mut lo, mut hi) = (1, s_max);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if objective(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let (f_lo, f_hi) = (objective(lo), objective(hi));
    let s = lo as f64 + f_lo / (f_lo - f_hi) * (hi - lo) as f64;
    Ok(Some(2.0 * s * t.dx()))
}

/// `min_x h''` with the stencil of half-width `s` pixels along x, every row.
fn min_curvature(t: &Topography, s: usize) -> f64 {
    let nx = t.nx();
    let d2 = (s as f64 * t.dx()).powi(2);
    let mut min = f64::INFINITY;
    for row in t.heights().chunks_exact(nx) {
        let range = if t.periodic() {
            0..nx
        } else {
            s.min(nx)..nx.saturating_sub(s)
        };
        for i in range {
            let (l, r) = ((i + nx - s % nx) % nx, (i + s) % nx);
            min = min.min(row[l] - 2.0 * row[i] + row[r]);
        }
    }
    min / d2
}

/// An error of the i-th measurement.
fn numbered(i: usize, e: Error) -> Error {
    Error::Inconsistent {
        name: format!("measurement {}", i + 1),
        requirement: e.to_string(),
    }
}

//! What a BEM solution gives besides the area: the statistics of its contact
//! patches with the tail of its pressure distribution
//! ([`persson::bem::patches`]), and the stress below the surface
//! ([`persson::bem::subsurface`]), as typed reports with their tables
//! (`bem rough --patches`, `bem rough --subsurface`, `bem hertz --subsurface`).
//!
//! # Patch-area exponent
//! The patch areas of a self-affine elastic contact fall off as a power law
//! of the number density, n(A) ∝ A^{−τ}, at large A (Hyun, Pei, Molinari &
//! Robbins 2004; Müser & Wang, Lubricants 6, 85 (2018); docs/asperity.md
//! sets the measured τ beside them). The report fits it by least squares on
//! the log-binned density (not the counts per bin, which fall as A^{1−τ}):
//! ```text
//! ln n_k = c − τ ln √(A_low,k A_high,k)      over the bins with a patch
//! ```
//! (`patch_area_exponent` = τ; none with fewer than three such bins).
//!
//! # Hertz axis
//! Johnson (1985) §3.4, on the axis of a Hertz contact of radius a and peak
//! pressure p0, ζ = z/a:
//! ```text
//! σ_z/p0 = −1/(1 + ζ²),   σ_r/p0 = −(1 + ν)(1 − ζ atan(1/ζ)) + 1/(2(1 + ζ²))
//! ```
//! `bem hertz --subsurface` puts the BEM's stress on the axis beside these.
//!
//! # References
//! - S. Hyun, L. Pei, J.-F. Molinari, M. O. Robbins, Phys. Rev. E 70, 026117
//!   (2004), doi:10.1103/PhysRevE.70.026117.
//! - C. Campañá, M. H. Müser, EPL 77, 38005 (2007), doi:10.1209/0295-5075/77/38005.
//! - K. L. Johnson, *Contact Mechanics* (CUP 1985), §3.4, §4.2.

mod adhesive;
mod figures;
mod section;
mod solves;

use serde::Serialize;

pub use adhesive::{
    adhesive_controlled_path, adhesive_path, adhesive_sphere, adhesive_warnings, sphere_warnings,
    AdhesiveBemReport, AdhesiveIteration, AdhesiveSphereReport, LawKind, PathControl,
    SpherePullOff,
};
pub use figures::{hertz_section_figure, planes};
pub use section::{hertz_section, VerticalSection};
pub use solves::{indexed, Details, StressMap, SubsurfaceOptions, DEFAULT_POISSON};

use crate::table::{Table, Tabulate};
use persson::bem::hertz::HertzCase;
use persson::bem::kernel::Boundary;
use persson::bem::patches::{
    pressure_patches, pressure_tail, AreaBin, Connectivity, PatchOptions, PatchStatistics,
    PressureTail,
};
use persson::bem::subsurface::{LinePoint, Subsurface, SubsurfaceReport};
use persson::bem::{Control, Iteration, Operator, Options, Solver};
use persson::error::{Error, Result};

/// The patches of one solve.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PatchPoint {
    /// Nominal pressure σ0 of the solve.
    pub nominal_pressure: f64,
    /// Fraction of nodes in contact.
    pub contact_fraction: f64,
    /// Number of patches.
    pub patch_count: usize,
    /// Largest patch area, m².
    pub largest_patch_area: f64,
    /// Mean patch area, m².
    pub mean_patch_area: f64,
    /// Sum of the perimeters, m.
    pub total_perimeter: f64,
    /// τ of n(A) ∝ A^{−τ} (module docs), when three bins hold patches.
    pub patch_area_exponent: Option<f64>,
    /// The log-binned distribution of patch areas.
    pub area_distribution: Vec<AreaBin>,
    /// The pressure tail's fits (none without contact).
    pub pressure_tail: Option<PressureTail>,
}

/// Patch statistics of every solve of a rough contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct PatchReport {
    /// Grid side N.
    pub grid: usize,
    /// Side L, m.
    pub size: f64,
    /// Neighbourhood.
    pub connectivity: Connectivity,
    /// Boundary (periodic joins patches across it).
    pub boundary: Boundary,
    /// Log bins per decade.
    pub bins_per_decade: usize,
    /// One point per solve.
    pub points: Vec<PatchPoint>,
}

impl PatchReport {
    /// An empty report for solves on an `n × n` grid of side `size`.
    pub fn new(n: usize, size: f64, options: &PatchOptions) -> Self {
        PatchReport {
            grid: n,
            size,
            connectivity: options.connectivity,
            boundary: options.boundary,
            bins_per_decade: options.bins_per_decade,
            points: Vec::new(),
        }
    }

    /// Add the patches of the pressure field `pressure` (σ0 `nominal_pressure`).
    ///
    /// # Errors
    /// As [`pressure_patches`] and [`pressure_tail`].
    pub fn push(&mut self, nominal_pressure: f64, pressure: &[f64]) -> Result<()> {
        let options = PatchOptions {
            connectivity: self.connectivity,
            boundary: self.boundary,
            bins_per_decade: self.bins_per_decade,
        };
        let s = pressure_patches(pressure, self.grid, self.size, &options)?;
        let tail = if s.patch_count > 0 {
            Some(pressure_tail(pressure, None)?)
        } else {
            None
        };
        self.points.push(point(nominal_pressure, s, tail));
        Ok(())
    }
}

fn point(nominal_pressure: f64, s: PatchStatistics, tail: Option<PressureTail>) -> PatchPoint {
    PatchPoint {
        nominal_pressure,
        contact_fraction: s.contact_fraction,
        patch_count: s.patch_count,
        largest_patch_area: s.largest_patch_area,
        mean_patch_area: s.mean_patch_area,
        total_perimeter: s.total_perimeter,
        patch_area_exponent: area_exponent(&s.area_distribution),
        area_distribution: s.area_distribution,
        pressure_tail: tail,
    }
}

/// τ of n(A) ∝ A^{−τ}: least squares of ln n on ln A (bin centres) over the
/// bins with a patch; none with fewer than three.
pub fn area_exponent(bins: &[AreaBin]) -> Option<f64> {
    let xy: Vec<(f64, f64)> = bins
        .iter()
        .filter(|b| b.count > 0 && b.density > 0.0)
        .map(|b| ((b.area_low * b.area_high).sqrt().ln(), b.density.ln()))
        .collect();
    if xy.len() < 3 {
        return None;
    }
    let n = xy.len() as f64;
    let (mx, my) = xy
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = xy.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    (sxx > 0.0).then(|| -sxy / sxx)
}

impl Tabulate for PatchReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_patches",
            format!(
                "Contact patches ({:?}-neighbour, {} boundary) and the pressure tail p ≥ mean contact pressure",
                self.connectivity,
                self.boundary.name()
            )
            .replace("Four", "4")
            .replace("Eight", "8"),
        )
        .column("nominal_pressure", "σ0")
        .column("contact_fraction", "A/A0")
        .column("patch_count", "patches")
        .column("largest_patch_area", "largest (m²)")
        .column("mean_patch_area", "mean (m²)")
        .column("total_perimeter", "perimeter (m)")
        .column_digits("patch_area_exponent", "τ", 3)
        .column("better", "tail");
        let mut bins = Table::new(
            "bem_patch_areas",
            format!(
                "Patch-area distribution n(A), {} log bins per decade (∫ n dA = 1)",
                self.bins_per_decade
            ),
        )
        .column("nominal_pressure", "σ0")
        .column("area_low", "A low (m²)")
        .column("area_high", "A high (m²)")
        .column("count", "patches")
        .column("density", "n(A) (1/m²)");
        for p in &self.points {
            let better = p.pressure_tail.as_ref().map_or(String::new(), |t| {
                serde_json::to_value(t.better)
                    .ok()
                    .and_then(|v| v.as_str().map(String::from))
                    .unwrap_or_default()
            });
            t.push(vec![
                p.nominal_pressure.into(),
                p.contact_fraction.into(),
                p.patch_count.into(),
                p.largest_patch_area.into(),
                p.mean_patch_area.into(),
                p.total_perimeter.into(),
                p.patch_area_exponent.into(),
                better.into(),
            ]);
            // Empty bins are in the JSON; the table lists the patches found.
            for b in p.area_distribution.iter().filter(|b| b.count > 0) {
                bins.push(vec![
                    p.nominal_pressure.into(),
                    b.area_low.into(),
                    b.area_high.into(),
                    b.count.into(),
                    b.density.into(),
                ]);
            }
        }
        vec![t, bins]
    }
}

/// The stress below one solve.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SubsurfacePoint {
    /// Nominal pressure σ0 of the solve.
    pub nominal_pressure: f64,
    /// The planes' maxima, the overall maxima and the first yield.
    #[serde(flatten)]
    pub report: SubsurfaceReport,
}

/// Check the depths of `--depth`: each finite, > 0 and at most the side `size`.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `depth`; an empty list.
pub fn check_depths(depths: &[f64], size: f64) -> Result<()> {
    if depths.is_empty() {
        return Err(Error::Inconsistent {
            name: "depth".into(),
            requirement: "at least one depth below the surface".into(),
        });
    }
    for &z in depths {
        if !(z.is_finite() && z > 0.0 && z <= size) {
            return Err(Error::invalid(
                "depth",
                z,
                format!("> 0 and at most the side L = {size} of the domain"),
            ));
        }
    }
    Ok(())
}

/// The stress below `pressure` (`n × n`, side `size`) on the planes `depths`.
/// `planes` receives each plane's von Mises map (for files).
///
/// # Errors
/// As [`check_depths`], [`Subsurface::new`] and [`Subsurface::report`].
#[allow(clippy::too_many_arguments)]
pub fn subsurface(
    nominal_pressure: f64,
    pressure: &[f64],
    n: usize,
    size: f64,
    boundary: Boundary,
    poisson: f64,
    depths: &[f64],
    tensile_yield_stress: Option<f64>,
    planes: &mut dyn FnMut(usize, &[f64]) -> Result<()>,
) -> Result<SubsurfacePoint> {
    check_depths(depths, size)?;
    let mut s = Subsurface::new(pressure, n, size, boundary, poisson)?;
    for (j, &z) in depths.iter().enumerate() {
        let plane = s.plane(z)?;
        planes(j, &plane.von_mises_stress)?;
    }
    Ok(SubsurfacePoint {
        nominal_pressure,
        report: s.report(depths, tensile_yield_stress)?,
    })
}

/// The stress below every solve of a rough contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SubsurfaceStudy {
    /// Depths asked for, m.
    pub depth: Vec<f64>,
    /// One point per solve.
    pub points: Vec<SubsurfacePoint>,
}

impl SubsurfaceStudy {
    /// An empty study at `depths`.
    pub fn new(depths: &[f64]) -> Self {
        SubsurfaceStudy {
            depth: depths.to_vec(),
            points: Vec::new(),
        }
    }
}

impl Tabulate for SubsurfaceStudy {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_subsurface",
            "Stress below the surface: the largest von Mises stress and maximum shear on each plane (unit of the pressure)",
        )
        .column("nominal_pressure", "σ0")
        .column("depth", "z (m)")
        .column("von_mises_stress", "max σ_vM")
        .column("max_shear_stress", "max τ")
        .column("yielded_fraction", "σ_vM ≥ Y");
        for p in &self.points {
            for s in &p.report.planes {
                t.push(vec![
                    p.nominal_pressure.into(),
                    s.depth.into(),
                    s.von_mises_stress.value.into(),
                    s.max_shear_stress.value.into(),
                    s.yielded_fraction.into(),
                ]);
            }
        }
        vec![t]
    }
}

/// Johnson's axis stresses of a Hertz contact (module docs): (σ_z, σ_r)/p0
/// at ζ = z/a.
pub fn hertz_axis(zeta: f64, poisson: f64) -> (f64, f64) {
    let sz = -1.0 / (1.0 + zeta * zeta);
    let sr = -(1.0 + poisson) * (1.0 - zeta * (1.0 / zeta).atan()) + 0.5 / (1.0 + zeta * zeta);
    (sz, sr)
}

/// One depth on the axis of the Hertz contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AxisPoint {
    /// Depth z, m.
    pub depth: f64,
    /// z/a.
    pub depth_ratio: f64,
    /// σ_zz/p0 of the BEM pressure.
    pub stress_zz: f64,
    /// σ_xx/p0 (= σ_r on the axis).
    pub stress_rr: f64,
    /// Maximum shear/p0.
    pub max_shear_stress: f64,
    /// Von Mises/p0.
    pub von_mises_stress: f64,
    /// Johnson's σ_z/p0.
    pub theory_stress_zz: f64,
    /// Johnson's σ_r/p0.
    pub theory_stress_rr: f64,
}

/// The stress on the axis of a BEM Hertz contact against Johnson's.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct HertzSubsurface {
    /// Grid side N.
    pub grid: usize,
    /// Boundary.
    pub boundary: Boundary,
    /// Poisson ratio ν.
    pub poisson: f64,
    /// Hertz contact radius a and peak pressure p0.
    pub hertz_contact_radius: f64,
    /// p0 = 2E*a/(πR).
    pub hertz_peak_pressure: f64,
    /// Largest |Δσ|/p0 of σ_z and σ_r on the axis against Johnson's.
    pub stress_error: f64,
    /// The axis points.
    pub points: Vec<AxisPoint>,
    /// Largest maximum shear on the axis /p0 and its z/a (BEM).
    pub max_shear_stress: f64,
    /// Its depth ratio z/a.
    pub depth_ratio: f64,
    /// The solved pressure field, `N × N` (for [`hertz_section`]; not serialised).
    #[serde(skip)]
    pub pressure: Vec<f64>,
    /// Side L of the grid, m (not serialised).
    #[serde(skip)]
    pub size: f64,
}

/// Depths of the axis profile, in units of the contact radius.
const AXIS_RATIOS: usize = 40;

/// Solve the Hertz `case` by the BEM and put the stress on its axis beside
/// Johnson's closed forms at z/a = 0.05, 0.1, …, 2.
///
/// # Errors
/// The solve's; ν outside (−1, 0.5].
pub fn hertz_subsurface(
    case: &HertzCase,
    options: &Options,
    poisson: f64,
    progress: &mut dyn FnMut(Iteration),
) -> Result<HertzSubsurface> {
    case.check()?;
    let op = Operator::new(case.boundary, case.grid, case.size, case.e_star)?;
    let mut solver = Solver::new(op);
    let sol = solver.solve_observed(
        &case.heights(),
        Control::MeanPressure(case.mean_pressure()),
        options,
        progress,
    )?;
    let n = case.grid;
    let s = Subsurface::new(&sol.pressure, n, case.size, case.boundary, poisson)?;
    let (a, p0) = (case.contact_radius, case.peak_pressure());
    let ratios: Vec<f64> = (1..=AXIS_RATIOS).map(|k| 0.05 * k as f64).collect();
    let depths: Vec<f64> = ratios.iter().map(|r| r * a).collect();
    let line = s.line([n / 2, n / 2], &depths)?;
    let points: Vec<AxisPoint> = line
        .iter()
        .zip(&ratios)
        .map(|(l, &r)| axis_point(l, r, p0, poisson))
        .collect();
    let stress_error = points
        .iter()
        .map(|p| {
            (p.stress_zz - p.theory_stress_zz)
                .abs()
                .max((p.stress_rr - p.theory_stress_rr).abs())
        })
        .fold(0.0, f64::max);
    let best = points
        .iter()
        .max_by(|x, y| x.max_shear_stress.total_cmp(&y.max_shear_stress))
        .copied();
    Ok(HertzSubsurface {
        grid: n,
        boundary: case.boundary,
        poisson,
        hertz_contact_radius: a,
        hertz_peak_pressure: p0,
        stress_error,
        max_shear_stress: best.map_or(0.0, |b| b.max_shear_stress),
        depth_ratio: best.map_or(0.0, |b| b.depth_ratio),
        points,
        pressure: sol.pressure,
        size: case.size,
    })
}

fn axis_point(l: &LinePoint, ratio: f64, p0: f64, poisson: f64) -> AxisPoint {
    let (sz, sr) = hertz_axis(ratio, poisson);
    AxisPoint {
        depth: l.depth,
        depth_ratio: ratio,
        stress_zz: l.stress[2] / p0,
        stress_rr: l.stress[0] / p0,
        max_shear_stress: l.max_shear_stress / p0,
        von_mises_stress: l.von_mises_stress / p0,
        theory_stress_zz: sz,
        theory_stress_rr: sr,
    }
}

impl Tabulate for HertzSubsurface {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_hertz_subsurface",
            format!(
                "Stress on the axis of the Hertz contact (FFT-BEM pressure, {} boundary, N = {}) against Johnson (1985) §3.4",
                self.boundary.name(),
                self.grid
            ),
        )
        .scalar("poisson", "ν", self.poisson)
        .scalar("hertz_contact_radius", "a", self.hertz_contact_radius)
        .scalar("hertz_peak_pressure", "p0", self.hertz_peak_pressure)
        .scalar("stress_error", "max |Δσ|/p0", self.stress_error)
        .scalar("max_shear_stress", "max τ/p0", self.max_shear_stress)
        .scalar("depth_ratio", "at z/a", self.depth_ratio)
        .column_digits("depth_ratio", "z/a", 3)
        .column("stress_zz", "σ_z/p0")
        .column("theory_stress_zz", "Johnson")
        .column("stress_rr", "σ_r/p0")
        .column("theory_stress_rr", "Johnson")
        .column("max_shear_stress", "τ/p0")
        .column("von_mises_stress", "σ_vM/p0");
        for p in &self.points {
            t.push(vec![
                p.depth_ratio.into(),
                p.stress_zz.into(),
                p.theory_stress_zz.into(),
                p.stress_rr.into(),
                p.theory_stress_rr.into(),
                p.max_shear_stress.into(),
                p.von_mises_stress.into(),
            ]);
        }
        vec![t]
    }
}

//! The adhesive BEM along a path of mean gaps (`bem rough --work-of-adhesion`):
//! the force–separation curve of one surface, tensile part included, and its
//! pull-off, from [`persson::bem::adhesive`].
//!
//! Each mean gap ḡ is solved by the gap-based Polonsky–Keer iteration (Rey,
//! Anciaux & Molinari, Comput. Mech. 60, 69 (2017)) with the cohesive law
//! W′(g): Maugis–Dugdale, a constant attraction Δγ/ρ for 0 < g < ρ, or the
//! exponential law with the same work Δγ = ∫ W′ dg. Mean-gap control is
//! stable everywhere on the curve, so a path in and out reaches the tensile
//! branch and the pull-off −min p̄ without the jump out of contact of a load
//! control: the path's order (approach then retraction) gives its hysteresis.
//! Successive gaps start from the previous solution.

use serde::Serialize;

use crate::table::{Table, Tabulate};
use crate::Warning;
use persson::adhesion::MaugisDugdale;
use persson::bem::adhesive::{
    AdhesiveOptions, AdhesivePoint, AdhesiveSequence, AdhesiveSolver, CohesiveLaw,
    RESOLVED_COHESIVE_LENGTH,
};
pub use persson::bem::adhesive::{LawKind, PathControl};
use persson::bem::{Boundary, Method, Operator};
use persson::error::{check, Error, Result};

pub use crate::naming::names::AdhesiveIteration;

impl AdhesiveIteration {
    /// The solver's method (`None`: by the law).
    fn method(self) -> Option<Method> {
        match self {
            AdhesiveIteration::Auto => None,
            AdhesiveIteration::Plain => Some(Method::Plain),
            AdhesiveIteration::Preconditioned => Some(Method::PRECONDITIONED),
        }
    }
}

/// One adhesive path on one surface.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AdhesiveBemReport {
    /// Grid side N.
    pub grid: usize,
    /// Side L, m.
    pub size: f64,
    /// Periodic, or free (the surface a window of an infinite half-space).
    pub boundary: Boundary,
    /// E*, Pa.
    pub contact_modulus: f64,
    /// The cohesive law.
    pub adhesion: LawKind,
    /// Δγ, J/m².
    pub work_of_adhesion: f64,
    /// ρ, m.
    pub adhesion_range: f64,
    /// Δγ/ρ, the Maugis–Dugdale cohesive stress (the exponential law's peak), Pa.
    pub cohesive_stress: f64,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// One point per mean gap, in the order given (`mean_pressure` negative in tension).
    pub points: Vec<AdhesivePoint>,
    /// The pull-off stress −min p̄ over the path (0 when never in tension), Pa.
    pub pull_off_stress: f64,
}

/// Solve the adhesive contact of the periodic surface `heights` (N × N,
/// side `size`, m) against a flat half-space of modulus `contact_modulus` at
/// each of `mean_gaps` (m) in order.
///
/// # Errors
/// A bad law, grid, tolerance or mean gap (named), as
/// [`AdhesiveSolver::sequence`].
pub fn adhesive_path(
    heights: &[f64],
    grid: (usize, f64, f64),
    law: (LawKind, f64, f64),
    mean_gaps: &[f64],
    options: &AdhesiveOptions,
) -> Result<AdhesiveBemReport> {
    adhesive_controlled_path(
        heights,
        grid,
        Boundary::Periodic,
        law,
        PathControl::MeanGap(mean_gaps),
        options,
        AdhesiveIteration::Auto,
    )
}

/// [`adhesive_path`] on either boundary, under mean-gap or approach
/// control ([`AdhesiveSolver::sequence_approach`] for the latter), with the
/// iteration `iteration`.
///
/// # Errors
/// As [`adhesive_path`]; mean-gap control on the free boundary
/// (`mean_gap`); a bad approach (`approach`).
pub fn adhesive_controlled_path(
    heights: &[f64],
    (n, size, contact_modulus): (usize, f64, f64),
    boundary: Boundary,
    (kind, work_of_adhesion, adhesion_range): (LawKind, f64, f64),
    control: PathControl<'_>,
    options: &AdhesiveOptions,
    iteration: AdhesiveIteration,
) -> Result<AdhesiveBemReport> {
    let (name, values) = match control {
        PathControl::MeanGap(g) => ("mean_gap", g),
        PathControl::Approach(d) => ("approach", d),
    };
    if values.is_empty() {
        return Err(Error::Inconsistent {
            name: name.into(),
            requirement: format!("at least one {}", name.replace('_', " ")),
        });
    }
    // Δγ = 0 is no adhesion at all: the elastic BEM (`bem rough`) answers that.
    check::positive("work_of_adhesion", work_of_adhesion)?;
    check::positive("adhesion_range", adhesion_range)?;
    let law = kind.law(work_of_adhesion, adhesion_range)?;
    let op = Operator::new(boundary, n, size, contact_modulus)?;
    let mut solver = AdhesiveSolver::new(op)?;
    solver.set_method(iteration.method());
    let AdhesiveSequence {
        points,
        pull_off_pressure,
        ..
    } = solver.path(heights, &law, control, options)?;
    Ok(AdhesiveBemReport {
        grid: n,
        size,
        boundary,
        contact_modulus,
        adhesion: kind,
        work_of_adhesion,
        adhesion_range,
        cohesive_stress: work_of_adhesion / adhesion_range,
        tolerance: options.tolerance,
        points,
        // + 0.0: a path never in tension reports 0, not −0.
        pull_off_stress: pull_off_pressure + 0.0,
    })
}

/// The warnings of an adhesive path: a cohesive zone the grid does not
/// resolve, solves the plain iteration finished, solves short of the tolerance.
pub fn adhesive_warnings(r: &AdhesiveBemReport) -> Vec<Warning> {
    path_warnings(
        r.size / r.grid as f64,
        r.adhesion.law(r.work_of_adhesion, r.adhesion_range),
        r.contact_modulus,
        r.tolerance,
        &r.points,
    )
}

/// [`adhesive_warnings`] of one path: grid spacing L/N, the law, E*, tolerance ε.
fn path_warnings(
    spacing: f64,
    law: Result<CohesiveLaw>,
    contact_modulus: f64,
    tolerance: f64,
    points: &[AdhesivePoint],
) -> Vec<Warning> {
    let mut out = Vec::new();
    // The law was built from the same values before the solve: an error
    // here cannot happen, and then there is nothing to resolve.
    if let Ok(law) = law {
        let (_, adhesion_range) = law.parameters();
        let cohesive_length = law.cohesive_length(contact_modulus);
        if adhesion_range < spacing || cohesive_length < RESOLVED_COHESIVE_LENGTH * spacing {
            out.push(
                Warning::CohesiveZoneUnresolved {
                    adhesion_range,
                    cohesive_length,
                    grid_spacing: spacing,
                    message: String::new(),
                }
                .described(describe),
            );
        }
    }
    let gaps = |f: &dyn Fn(&AdhesivePoint) -> bool| -> Vec<f64> {
        points.iter().filter(|p| f(p)).map(|p| p.mean_gap).collect()
    };
    let fell_back = gaps(&|p| p.fallback.is_some());
    if !fell_back.is_empty() {
        out.push(
            Warning::AdhesiveFallback {
                mean_gap: fell_back,
                message: String::new(),
            }
            .described(describe),
        );
    }
    let unconverged = gaps(&|p| !p.converged);
    if !unconverged.is_empty() {
        out.push(
            Warning::AdhesiveNotConverged {
                mean_gap: unconverged,
                tolerance,
                message: String::new(),
            }
            .described(describe),
        );
    }
    out
}

impl Tabulate for AdhesiveBemReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_adhesion",
            format!(
                "Adhesive BEM ({}, {}² {}): force along the path, in the order given",
                match self.adhesion {
                    LawKind::Maugis => "Maugis–Dugdale",
                    LawKind::Exponential => "exponential law",
                },
                self.grid,
                self.boundary.name()
            ),
        )
        .scalar("work_of_adhesion", "Δγ (J/m²)", self.work_of_adhesion)
        .scalar("adhesion_range", "ρ (m)", self.adhesion_range)
        .scalar("cohesive_stress", "Δγ/ρ", self.cohesive_stress)
        .scalar("pull_off_stress", "pull-off −min p̄", self.pull_off_stress)
        .column("approach", "δ (m)")
        .column("mean_gap", "ḡ (m)")
        .column("mean_pressure", "p̄")
        .column("contact_fraction", "A_rep/A0")
        .column("cohesive_fraction", "A_coh/A0")
        .column("iterations", "iterations")
        .omittable(1)
        .column("residual", "ε")
        .omittable(1);
        for p in &self.points {
            t.push(vec![
                p.approach.into(),
                p.mean_gap.into(),
                p.mean_pressure.into(),
                p.contact_fraction.into(),
                p.cohesive_fraction.into(),
                p.iterations.into(),
                p.residual.into(),
            ]);
        }
        vec![t]
    }
}

/// The pull-off of a sphere from the adhesive BEM on one grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct SpherePullOff {
    /// Grid side N.
    pub grid: usize,
    /// The pull-off force F = L² max(−p̄) over the path (unit of E* L²).
    pub pull_off_force: f64,
    /// F/(π R Δγ): JKR's 1.5, DMT's 2.
    pub reduced_pull_off_force: f64,
    /// F / F_MD − 1 against Maugis's pull-off force (Maugis–Dugdale law only).
    pub maugis_dugdale_difference: Option<f64>,
    /// Points the plain iteration finished after the preconditioned one stalled.
    pub fallbacks: usize,
    /// The path in and out (mean gaps, pressures, fractions).
    pub points: Vec<AdhesivePoint>,
}

/// The adhesive sphere (`bem hertz --work-of-adhesion`): the pull-off force
/// against JKR's and DMT's limits at the Maugis parameter λ of the law.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AdhesiveSphereReport {
    /// Side L of the periodic cell (unit of length).
    pub size: f64,
    /// Sphere radius R.
    pub radius: f64,
    /// E*.
    pub contact_modulus: f64,
    /// The cohesive law.
    pub adhesion: LawKind,
    /// Δγ.
    pub work_of_adhesion: f64,
    /// ρ.
    pub adhesion_range: f64,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// λ = (Δγ/ρ)(9R/(2πΔγE*²))^{1/3} (Maugis 1992; with ρ the
    /// Maugis–Dugdale range, h0 = ρ).
    pub maugis_parameter: f64,
    /// JKR's pull-off force 1.5 π R Δγ (λ → ∞).
    pub jkr_pull_off_force: f64,
    /// DMT's pull-off force 2 π R Δγ (λ → 0).
    pub dmt_pull_off_force: f64,
    /// Maugis's (1992) pull-off force at λ, πRΔγ · (−min P̄)
    /// ([`persson::adhesion::MaugisDugdale`]): the exact answer of the
    /// Maugis–Dugdale law for a paraboloid on a half-space; `None` for the
    /// exponential law, which has no closed form.
    pub maugis_dugdale_pull_off_force: Option<f64>,
    /// One row per grid.
    pub per_grid: Vec<SpherePullOff>,
}

/// A sphere h = −r²/(2R) centred in the periodic cell of side `size`,
/// approached and retracted under mean-gap control on each of `grids`.
///
/// The path: from ḡ = ḡ_touch + 2ρ (out of range) in to ḡ_touch − 1.5 δ_s in
/// 10 steps, then out to ḡ_touch + 5 δ_s + 2ρ in 50 steps, with ḡ_touch the
/// mean gap at first touch and δ_s = (π² Δγ² R / E*²)^{1/3} the JKR approach
/// scale; the cell must hold the contact (a JKR radius well below L/2).
///
/// # Errors
/// As [`adhesive_path`].
pub fn adhesive_sphere(
    grids: &[usize],
    (size, radius, contact_modulus): (f64, f64, f64),
    (kind, work_of_adhesion, adhesion_range): (LawKind, f64, f64),
    options: &AdhesiveOptions,
) -> Result<AdhesiveSphereReport> {
    use std::f64::consts::PI;
    for (name, v) in [
        ("size", size),
        ("radius", radius),
        ("contact_modulus", contact_modulus),
        ("work_of_adhesion", work_of_adhesion),
        ("adhesion_range", adhesion_range),
    ] {
        check::positive(name, v)?;
    }
    let dg = work_of_adhesion;
    let approach_scale = (PI * PI * dg * dg * radius / (contact_modulus * contact_modulus)).cbrt();
    let lambda = MaugisDugdale::parameter(radius, contact_modulus, dg, dg / adhesion_range)?;
    let md_force = match kind {
        LawKind::Maugis => Some(MaugisDugdale::new(lambda)?.pull_off_force() * PI * radius * dg),
        LawKind::Exponential => None,
    };
    let per_grid = grids
        .iter()
        .map(|&n| {
            let h = sphere(n, size, radius);
            let h_max = h.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let touch = h.iter().map(|v| h_max - v).sum::<f64>() / (n * n) as f64;
            let start = touch + 2.0 * adhesion_range;
            let deepest = touch - 1.5 * approach_scale;
            let last = touch + 5.0 * approach_scale + 2.0 * adhesion_range;
            if !(deepest > 0.0 && last.is_finite()) {
                // The path goes 1.5 approach scales past first touch: it must
                // stay above a mean gap of 0 (the sphere pressed flat on the cell).
                return Err(Error::Inconsistent {
                    name: "work_of_adhesion, radius, contact_modulus".into(),
                    requirement: format!(
                        "an adhesive approach scale (π²Δγ²R/E*²)^(1/3) = {} m whose 1.5-fold \
                         stays within the mean gap {} m of the sphere at first touch on the \
                         cell of side {} m (a larger size, or a smaller Δγ)",
                        crate::table::number(approach_scale, 4),
                        crate::table::number(touch, 4),
                        crate::table::number(size, 4),
                    ),
                });
            }
            let mut gaps: Vec<f64> = (0..=10)
                .map(|k| start + (deepest - start) * k as f64 / 10.0)
                .collect();
            gaps.extend((1..=50).map(|k| deepest + (last - deepest) * k as f64 / 50.0));
            let r = adhesive_path(
                &h,
                (n, size, contact_modulus),
                (kind, work_of_adhesion, adhesion_range),
                &gaps,
                options,
            )?;
            let force = r.pull_off_stress * size * size;
            Ok(SpherePullOff {
                grid: n,
                pull_off_force: force,
                reduced_pull_off_force: force / (PI * radius * dg),
                maugis_dugdale_difference: md_force.map(|f| force / f - 1.0),
                fallbacks: r.points.iter().filter(|p| p.fallback.is_some()).count(),
                points: r.points,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(AdhesiveSphereReport {
        size,
        radius,
        contact_modulus,
        adhesion: kind,
        work_of_adhesion,
        adhesion_range,
        tolerance: options.tolerance,
        maugis_parameter: lambda,
        jkr_pull_off_force: 1.5 * PI * radius * dg,
        dmt_pull_off_force: 2.0 * PI * radius * dg,
        maugis_dugdale_pull_off_force: md_force,
        per_grid,
    })
}

/// Heights −r²/(2R) of a sphere centred in the cell, at the cell centres.
fn sphere(n: usize, size: f64, radius: f64) -> Vec<f64> {
    let dx = size / n as f64;
    (0..n * n)
        .map(|k| {
            let x = ((k / n) as f64 + 0.5) * dx - 0.5 * size;
            let y = ((k % n) as f64 + 0.5) * dx - 0.5 * size;
            -(x * x + y * y) / (2.0 * radius)
        })
        .collect()
}

impl Tabulate for AdhesiveSphereReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_adhesive_sphere",
            format!(
                "Adhesive sphere ({}, periodic cell): pull-off force against JKR, DMT and Maugis",
                match self.adhesion {
                    LawKind::Maugis => "Maugis–Dugdale",
                    LawKind::Exponential => "exponential law",
                }
            ),
        )
        .scalar("maugis_parameter", "Maugis λ", self.maugis_parameter)
        .scalar("jkr_pull_off_force", "JKR 1.5πRΔγ", self.jkr_pull_off_force)
        .scalar("dmt_pull_off_force", "DMT 2πRΔγ", self.dmt_pull_off_force);
        if let Some(f) = self.maugis_dugdale_pull_off_force {
            t = t.scalar("maugis_dugdale_pull_off_force", "Maugis–Dugdale F_MD", f);
        }
        t = t
            .column("grid", "N")
            .column("pull_off_force", "F")
            .column_digits("reduced_pull_off_force", "F/(πRΔγ)", 5);
        let md = self.maugis_dugdale_pull_off_force.is_some();
        if md {
            t = t.column("maugis_dugdale_difference", "F/F_MD − 1");
        }
        t = t.column("fallbacks", "fallbacks");
        for g in &self.per_grid {
            let mut row = vec![
                g.grid.into(),
                g.pull_off_force.into(),
                g.reduced_pull_off_force.into(),
            ];
            if md {
                row.push(g.maugis_dugdale_difference.unwrap_or(f64::NAN).into());
            }
            row.push(g.fallbacks.into());
            t.push(row);
        }
        vec![t]
    }
}

/// The warnings of an adhesive sphere: as [`adhesive_warnings`] on each grid.
pub fn sphere_warnings(r: &AdhesiveSphereReport) -> Vec<Warning> {
    let mut out: Vec<Warning> = Vec::new();
    for g in &r.per_grid {
        let spacing = r.size / g.grid as f64;
        let law = r.adhesion.law(r.work_of_adhesion, r.adhesion_range);
        for w in path_warnings(spacing, law, r.contact_modulus, r.tolerance, &g.points) {
            if !out.contains(&w) {
                out.push(w);
            }
        }
    }
    out
}

/// The text of the adhesive BEM's warnings ([`Warning::described`]).
pub(crate) fn describe(w: &Warning, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    let n = |v: f64| crate::table::number(v, 6);
    match w {
        Warning::CohesiveZoneUnresolved {
            adhesion_range,
            cohesive_length,
            grid_spacing,
            ..
        } => {
            if adhesion_range < grid_spacing {
                write!(
                    f,
                    "the adhesion range ρ = {} is below the grid spacing L/N = {}",
                    n(*adhesion_range),
                    n(*grid_spacing)
                )?;
            } else {
                write!(
                    f,
                    "the cohesive length E*Δγ/σ_c² = E*ρ²/Δγ = {} spans only {:.1} grid \
                     spacings L/N = {}",
                    n(*cohesive_length),
                    cohesive_length / grid_spacing,
                    n(*grid_spacing)
                )?;
            }
            write!(
                f,
                ": the cohesive zone is not resolved and the pull-off depends on the grid \
                 (and, for Maugis–Dugdale, on the solver's path: several solutions are \
                 stationary); refine the grid or lengthen the range"
            )
        }
        Warning::AdhesiveFallback { mean_gap, .. } => write!(
            f,
            "the preconditioned adhesive solver stalled at mean gap ḡ = {} and the plain \
             iteration finished: same tolerance, more time",
            mean_gap
                .iter()
                .map(|&g| n(g))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Warning::AdhesiveNotConverged {
            mean_gap,
            tolerance,
            ..
        } => write!(
            f,
            "the adhesive solve at mean gap ḡ = {} stopped short of the tolerance {} \
             (iteration limit): its numbers are not converged",
            mean_gap
                .iter()
                .map(|&g| n(g))
                .collect::<Vec<_>>()
                .join(", "),
            n(*tolerance)
        ),
        _ => Ok(()),
    }
}

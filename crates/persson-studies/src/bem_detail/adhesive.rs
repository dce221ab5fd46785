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
use persson::bem::adhesive::{
    AdhesiveOptions, AdhesivePoint, AdhesiveSequence, AdhesiveSolver, CohesiveLaw,
};
use persson::bem::{Boundary, Operator};
use persson::error::{Error, Result};

/// The cohesive law of an adhesive BEM path, by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LawKind {
    /// Maugis–Dugdale: constant attraction Δγ/ρ for gaps below ρ.
    Maugis,
    /// Exponential: attraction (Δγ/ρ) e^{−g/ρ}.
    Exponential,
}

impl LawKind {
    /// The law with work of adhesion `work_of_adhesion` (J/m²) and range
    /// `adhesion_range` (m).
    ///
    /// # Errors
    /// Either not finite and > 0 (each named).
    pub fn law(self, work_of_adhesion: f64, adhesion_range: f64) -> Result<CohesiveLaw> {
        match self {
            LawKind::Maugis => CohesiveLaw::maugis(work_of_adhesion, adhesion_range),
            LawKind::Exponential => CohesiveLaw::exponential(work_of_adhesion, adhesion_range),
        }
    }
}

/// One adhesive path on one periodic surface.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[non_exhaustive]
pub struct AdhesiveBemReport {
    /// Grid side N.
    pub grid: usize,
    /// Side L, m.
    pub size: f64,
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
    (n, size, contact_modulus): (usize, f64, f64),
    (kind, work_of_adhesion, adhesion_range): (LawKind, f64, f64),
    mean_gaps: &[f64],
    options: &AdhesiveOptions,
) -> Result<AdhesiveBemReport> {
    if mean_gaps.is_empty() {
        return Err(Error::Inconsistent {
            name: "mean_gap".into(),
            requirement: "at least one mean gap".into(),
        });
    }
    let law = kind.law(work_of_adhesion, adhesion_range)?;
    let op = Operator::new(Boundary::Periodic, n, size, contact_modulus)?;
    let mut solver = AdhesiveSolver::new(op)?;
    let AdhesiveSequence {
        points,
        pull_off_pressure,
        ..
    } = solver.sequence(heights, &law, mean_gaps, options)?;
    Ok(AdhesiveBemReport {
        grid: n,
        size,
        contact_modulus,
        adhesion: kind,
        work_of_adhesion,
        adhesion_range,
        cohesive_stress: work_of_adhesion / adhesion_range,
        tolerance: options.tolerance,
        points,
        pull_off_stress: pull_off_pressure,
    })
}

/// The warnings of an adhesive path: a cohesive zone shorter than the grid
/// spacing, solves the plain iteration finished, solves short of the tolerance.
pub fn adhesive_warnings(r: &AdhesiveBemReport) -> Vec<Warning> {
    let spacing = r.size / r.grid as f64;
    let mut out = Vec::new();
    if r.adhesion_range < spacing {
        out.push(Warning::CohesiveZoneUnresolved {
            adhesion_range: r.adhesion_range,
            grid_spacing: spacing,
        });
    }
    let gaps = |f: &dyn Fn(&AdhesivePoint) -> bool| -> Vec<f64> {
        r.points
            .iter()
            .filter(|p| f(p))
            .map(|p| p.mean_gap)
            .collect()
    };
    let fell_back = gaps(&|p| p.fallback.is_some());
    if !fell_back.is_empty() {
        out.push(Warning::AdhesiveFallback {
            mean_gap: fell_back,
        });
    }
    let unconverged = gaps(&|p| !p.converged);
    if !unconverged.is_empty() {
        out.push(Warning::AdhesiveNotConverged {
            mean_gap: unconverged,
            tolerance: r.tolerance,
        });
    }
    out
}

impl Tabulate for AdhesiveBemReport {
    fn tables(&self) -> Vec<Table> {
        let mut t = Table::new(
            "bem_adhesion",
            format!(
                "Adhesive BEM ({}, {}² periodic): force against mean gap, in the order given",
                match self.adhesion {
                    LawKind::Maugis => "Maugis–Dugdale",
                    LawKind::Exponential => "exponential law",
                },
                self.grid
            ),
        )
        .scalar("work_of_adhesion", "Δγ (J/m²)", self.work_of_adhesion)
        .scalar("adhesion_range", "ρ (m)", self.adhesion_range)
        .scalar("cohesive_stress", "Δγ/ρ", self.cohesive_stress)
        .scalar("pull_off_stress", "pull-off −min p̄", self.pull_off_stress)
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

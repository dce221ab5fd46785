//! What a contact loop returns and reports while it runs.

/// One iteration's state, reported to an observer (progress bars, logs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Iteration {
    /// Iteration number, from 0.
    pub iteration: usize,
    /// Convergence measure ε before this iteration's step.
    pub residual: f64,
    /// Fraction of nodes in contact.
    pub contact_fraction: f64,
}

/// The preconditioned loop stalled and the plain one finished the solve
/// (the answer is the plain solver's, to the same tolerance). The
/// application layer turns this into a warning.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct Fallback {
    /// Iterations of the preconditioned loop before it was abandoned.
    pub iterations: usize,
    /// Its ε when it was abandoned.
    pub residual: f64,
}

/// A converged contact solution.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Solution {
    /// Nodal pressures, `N × N` row-major (unit of E*).
    pub pressure: Vec<f64>,
    /// Gap between the surfaces, ≥ 0 up to the tolerance, 0 on the contact (unit of L).
    pub gap: Vec<f64>,
    /// Normal displacement of the elastic surface `u = 𝒢p` (unit of L).
    pub displacement: Vec<f64>,
    /// Mean pressure Σp/N² (equals the target under mean pressure control).
    pub mean_pressure: f64,
    /// Approach δ from first touch (see [`super::solver`]), unit of L.
    pub approach: f64,
    /// A/A0: fraction of nodes with p > 0 (elastic + plastic).
    pub contact_fraction: f64,
    /// Fraction of nodes with 0 < p < σY (all of the contact without a yield stress).
    pub elastic_fraction: f64,
    /// Fraction of nodes with p = σY (0 without a yield stress).
    pub plastic_fraction: f64,
    /// Mean interpenetration (plastic displacement, −gap) over the nodes at
    /// p = σY, unit of L (0 without plastic nodes).
    pub plastic_displacement_mean: f64,
    /// Largest interpenetration over the nodes at p = σY, unit of L.
    pub plastic_displacement_max: f64,
    /// CG iterations used (all stages, a fallback's included).
    pub iterations: usize,
    /// Final ε (≤ tol).
    pub residual: f64,
    /// Wall-clock time of the solve, s.
    pub seconds: f64,
    /// Set when the preconditioned loop stalled and the plain one finished
    /// the solve.
    pub fallback: Option<Fallback>,
}

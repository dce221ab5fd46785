//! Closed-form Hertz contact of a rigid sphere on an elastic half-space, and
//! the BEM validation against it.
//!
//! # Formula
//! ```text
//! a³ = 3 F R / (4 E*)          contact radius (F total force, R sphere radius)
//! p₀ = 3F/(2π a²) = 2E* a/(π R) peak pressure
//! p(r) = p₀ √(1 − r²/a²),  r < a
//! δ = a²/R                      approach
//! u(r) = π p₀ (2a² − r²)/(4aE*),  r ≤ a         surface displacement
//! u(r) = p₀/(2aE*) [(2a² − r²) asin(a/r) + a √(r² − a²)],  r > a
//! ```
//! The rigid surface is the paraboloid `h(r) = −r²/(2R)` (Hertz's
//! approximation of the sphere), centred on the node `(L/2, L/2)`.
//!
//! # With a yield stress
//! [`plastic_disc`] solves the same ball with `0 ≤ p ≤ σY` (σY below p₀:
//! a plastic disc p = σY of radius c inside an elastic annulus) on a list
//! of grids. Reference: a 1-D axisymmetric solution of the same problem
//! (examples/hertz_plastic_rings.py), c/a_H = 0.7402 at σY = 0.8 p₀.
//!
//! # References
//! H. Hertz, J. reine angew. Math. 92, 156 (1882); K. L. Johnson, *Contact
//! Mechanics* (CUP 1985), §4.2; the closed forms are those of
//! [`crate::reference`]. J. F. Molinari, EPFL lecture "From single asperity
//! to multi asperity contact", Table 1 (η per grid).

use super::kernel::{Boundary, Operator};
use super::solver::{Control, Iteration, Options, Solver};
use crate::error::{check, Error, Result};
use crate::reference;

/// Hertz contact radius `a = (3FR/(4E*))^{1/3}` (unit of R); see
/// [`crate::reference::Ball`].
#[deprecated(since = "0.4.0", note = "use persson::reference::ball_contact_radius")]
pub fn contact_radius(force: f64, radius: f64, e_star: f64) -> f64 {
    reference::ball_contact_radius(force, radius, e_star)
}

/// Total force `F = 4E* a³/(3R)` that gives the contact radius `a`; see
/// [`crate::reference::Ball::from_contact_radius`].
#[deprecated(since = "0.4.0", note = "use persson::reference::ball_load")]
pub fn force_for_radius(a: f64, radius: f64, e_star: f64) -> f64 {
    reference::ball_load(a, radius, e_star)
}

/// Peak pressure `p₀ = 2E* a/(πR)`; see [`crate::reference::Ball`].
#[deprecated(since = "0.4.0", note = "use persson::reference::ball_peak_pressure")]
pub fn peak_pressure(a: f64, radius: f64, e_star: f64) -> f64 {
    reference::ball_peak_pressure(a, radius, e_star)
}

/// Pressure `p₀ √(1 − r²/a²)` inside the contact, 0 outside
/// ([`crate::reference::pressure_profile`]).
#[deprecated(since = "0.4.0", note = "use persson::reference::pressure_profile")]
pub fn pressure(r: f64, a: f64, p0: f64) -> f64 {
    reference::pressure_profile(r, a, p0)
}

/// Normal surface displacement of the Hertz contact at distance `r` from the
/// centre (unit of `a`), zero at infinity: Johnson's eqs. 3.41a and 3.42a,
/// cancellation-free ([`crate::reference::ball_displacement`]).
#[deprecated(since = "0.4.0", note = "use persson::reference::ball_displacement")]
pub fn displacement(r: f64, a: f64, p0: f64, e_star: f64) -> f64 {
    reference::ball_displacement(r, a, p0, e_star)
}

/// The free-boundary η per grid side N reported in Table 1 of J. F. Molinari,
/// EPFL lecture "From single asperity to multi asperity contact".
pub const LECTURE_ETA: [(usize, f64); 6] = [
    (64, 1.40e-2),
    (128, 4.08e-3),
    (256, 7.78e-4),
    (512, 3.66e-4),
    (1024, 1.20e-4),
    (2048, 1.66e-5),
];

/// Molinari's η for grid side `n`, if his Table 1 has one ([`LECTURE_ETA`]).
pub fn lecture_eta(n: usize) -> Option<f64> {
    LECTURE_ETA.iter().find(|(g, _)| *g == n).map(|(_, v)| *v)
}

/// A Hertz validation problem on an `N × N` grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzCase {
    /// Grid side N (nodes per side).
    pub grid: usize,
    /// Boundary condition of the elastic half-space.
    pub boundary: Boundary,
    /// Side L of the square domain.
    pub size: f64,
    /// Sphere radius R (unit of L).
    pub radius: f64,
    /// Contact modulus E*.
    pub e_star: f64,
    /// Target Hertz contact radius a (unit of L); the load follows from it.
    pub contact_radius: f64,
}

impl HertzCase {
    /// The standard validation case: L = 1, R = 1, E* = 1, a = 0.1 L.
    pub fn new(grid: usize, boundary: Boundary) -> Self {
        HertzCase {
            grid,
            boundary,
            size: 1.0,
            radius: 1.0,
            e_star: 1.0,
            contact_radius: 0.1,
        }
    }

    /// Nominal mean pressure `F/L²`.
    pub fn mean_pressure(&self) -> f64 {
        reference::ball_load(self.contact_radius, self.radius, self.e_star)
            / (self.size * self.size)
    }

    /// Peak Hertz pressure p₀.
    pub fn peak_pressure(&self) -> f64 {
        reference::ball_peak_pressure(self.contact_radius, self.radius, self.e_star)
    }

    /// Node distances from the centre `(L/2, L/2)`, row-major.
    pub fn radii(&self) -> Vec<f64> {
        let n = self.grid;
        let dx = self.size / n as f64;
        let c = 0.5 * self.size;
        (0..n * n)
            .map(|k| {
                let (x, y) = ((k / n) as f64 * dx - c, (k % n) as f64 * dx - c);
                x.hypot(y)
            })
            .collect()
    }

    /// Exact Hertz pressure averaged over each node's cell (m × m midpoint
    /// sub-samples per cell).
    pub fn cell_averaged_pressure(&self, m: usize) -> Vec<f64> {
        let n = self.grid;
        let dx = self.size / n as f64;
        let c = 0.5 * self.size;
        let p0 = self.peak_pressure();
        (0..n * n)
            .map(|k| {
                let (x0, y0) = ((k / n) as f64 * dx - c, (k % n) as f64 * dx - c);
                let mut s = 0.0;
                for a in 0..m {
                    for b in 0..m {
                        let x = x0 + ((a as f64 + 0.5) / m as f64 - 0.5) * dx;
                        let y = y0 + ((b as f64 + 0.5) / m as f64 - 0.5) * dx;
                        s += reference::pressure_profile(x.hypot(y), self.contact_radius, p0);
                    }
                }
                s / (m * m) as f64
            })
            .collect()
    }

    /// Rigid surface heights `−r²/(2R)`.
    pub fn heights(&self) -> Vec<f64> {
        self.radii()
            .iter()
            .map(|r| -r * r / (2.0 * self.radius))
            .collect()
    }

    /// Exact Hertz pressure at the nodes.
    pub fn exact_pressure(&self) -> Vec<f64> {
        let p0 = self.peak_pressure();
        self.radii()
            .iter()
            .map(|&r| reference::pressure_profile(r, self.contact_radius, p0))
            .collect()
    }

    /// Exact Hertz surface displacement at the nodes ([`displacement`]).
    pub fn exact_displacement(&self) -> Vec<f64> {
        let p0 = self.peak_pressure();
        self.radii()
            .iter()
            .map(|&r| reference::ball_displacement(r, self.contact_radius, p0, self.e_star))
            .collect()
    }

    /// Check the case: positive inputs, a < L/2, a grid of 8 to 32768 and
    /// scales that f64 carries (below).
    ///
    /// # Bound
    /// With ρ = a/L, the solve's scales are monomials of L, ρ, R and E*:
    /// ```text
    /// p₀ = (2/π) E* ρ L/R,   F/L² = (4/3) E* ρ³ L/R,   L²/R (heights),   ρ² L²/R (the contact's)
    /// ```
    /// Each must lie in [f64::MIN_POSITIVE/ε, ε f64::MAX] ≈ [1e-292, 4e292]:
    /// then it and its rounding are normal f64, and the solver's sums of up
    /// to 1/ε ≥ N² of them stay finite. Decided on logarithms; the input
    /// furthest from 1 in order of magnitude among the failing monomial's
    /// is named (ρ standing for `contact_radius`, so that a size with the
    /// default a = 0.1 L names `size`). L = 1e300 gave "height[0, 0] =
    /// −inf", 1e-300 "pressure = NaN", a = 1e-300 "pressure = 0".
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `size`, `radius`,
    /// `contact_modulus`, `contact_radius` or `grid`.
    pub fn check(&self) -> Result<()> {
        check::positive("size", self.size)?;
        check::positive("radius", self.radius)?;
        check::positive("contact_modulus", self.e_star)?;
        check::open("contact_radius", self.contact_radius, 0.0, 0.5 * self.size)?;
        super::check_grid(self.grid)?;
        let (l, rho, r, e) = (
            self.size,
            self.contact_radius / self.size,
            self.radius,
            self.e_star,
        );
        let ln = [l.ln(), rho.ln(), r.ln(), e.ln()];
        // (what, ln of the constant, exponents of L, ρ, R, E*)
        let scales: [(&str, f64, [f64; 4]); 4] = [
            (
                "the peak pressure p₀ = 2E*a/(πR)",
                std::f64::consts::FRAC_2_PI.ln(),
                [1.0, 1.0, -1.0, 1.0],
            ),
            (
                "the mean pressure F/L² = 4E*a³/(3RL²)",
                (4.0f64 / 3.0).ln(),
                [1.0, 3.0, -1.0, 1.0],
            ),
            ("the height scale L²/R", 0.0, [2.0, 0.0, -1.0, 0.0]),
            (
                "the contact's height scale a²/R",
                0.0,
                [2.0, 2.0, -1.0, 0.0],
            ),
        ];
        let (lo, hi) = (
            (f64::MIN_POSITIVE / f64::EPSILON).ln(),
            (f64::EPSILON * f64::MAX).ln(),
        );
        let names = ["size", "contact_radius", "radius", "contact_modulus"];
        let values = [l, self.contact_radius, r, e];
        for (what, c, exp) in scales {
            let v: f64 = c + (0..4).map(|j| exp[j] * ln[j]).sum::<f64>();
            if !(lo..=hi).contains(&v) {
                let j = (0..4)
                    .filter(|&j| exp[j] != 0.0)
                    .max_by(|&a, &b| ln[a].abs().total_cmp(&ln[b].abs()))
                    .unwrap_or(0);
                return Err(Error::invalid(
                    names[j],
                    values[j],
                    format!(
                        "such that {what} is within [1e-292, 4e292] (here e^{}), where f64 \
                         carries it and its rounding (L = {}, R = {}, E* = {}, a = {})",
                        crate::error::approx(v),
                        crate::error::num(l),
                        crate::error::num(r),
                        crate::error::num(e),
                        crate::error::num(self.contact_radius)
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// The outcome of a Hertz validation.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct HertzReport {
    /// Grid side N.
    pub grid: usize,
    /// Boundary condition.
    pub boundary: Boundary,
    /// η: energy norm of the pressure error relative to that of p_ex.
    pub energy_error: f64,
    /// η_L: the measure of Molinari's lecture (Table 1) with the exact
    /// displacement u_ex,
    /// `sqrt(|Σ(u − u_ex)(p − p_ex)| / Σ u_ex p_ex)` (free boundary only;
    /// `None` for the periodic one, whose displacement is defined up to a
    /// constant that this measure depends on). Not a norm: the sum changes
    /// sign with N, and on the contact `u − u_ex` is nearly the constant
    /// `δ − δ_ex`, so it mostly measures how Σ(p − p_ex) cancels. Measured at
    /// the [`HertzCase::new`] defaults, 64² to 1024²: 6–13× below η
    /// (examples/hertz_eta_study.rs).
    pub energy_error_displacement: Option<f64>,
    /// Contact radius a from the fit of p² = p₀²(1 − r²/a²).
    pub contact_radius: f64,
    /// |a_fit − a| / a.
    pub contact_radius_error: f64,
    /// Peak pressure p₀ from the same fit.
    pub peak_pressure: f64,
    /// |p₀_fit − p₀| / p₀.
    pub peak_pressure_error: f64,
    /// A/A0 of the numerical solution (exact: π a²/L²).
    pub contact_fraction: f64,
    /// Solver iterations.
    pub iterations: usize,
    /// Final solver residual ε.
    pub residual: f64,
    /// Wall-clock seconds of the solve.
    pub seconds: f64,
}

/// Solve the Hertz case and compare with the closed form.
///
/// # Formula
/// ```text
/// η = sqrt(⟨p − p_ex, 𝒢(p − p_ex)⟩ / ⟨p_ex, 𝒢 p_ex⟩)     (Molinari, Table 1)
/// fit: p_i² = c₀ + c₁ r_i² by least squares over p_i > 0;  p₀ = √c₀,  a = √(−c₀/c₁)
/// ```
/// 𝒢 is the discrete compliance operator of the solve (periodic or free),
/// p_ex the Hertz pressure sampled at the nodes. With the free operator the
/// displacement u = 𝒢p is absolute, and the lecture's own definition
/// ```text
/// η_L² = |Σ (u − u_ex)(p − p_ex)| / Σ u_ex p_ex      (Molinari, after Table 1)
/// ```
/// with u_ex the exact [`displacement`] at the nodes is reported as well.
///
/// # Errors
/// Invalid case (grid < 8, non-positive sizes, a ≥ L/2), solver errors.
pub fn validate(case: &HertzCase, opts: &Options) -> Result<HertzReport> {
    validate_observed(case, opts, &mut |_| {})
}

/// [`validate`], calling `observer` once per solver iteration.
///
/// # Errors
/// As [`validate`].
pub fn validate_observed(
    case: &HertzCase,
    opts: &Options,
    observer: &mut dyn FnMut(Iteration),
) -> Result<HertzReport> {
    case.check()?;
    let op = Operator::new(case.boundary, case.grid, case.size, case.e_star)?;
    let mut solver = Solver::new(op);
    let control = Control::MeanPressure(case.mean_pressure());
    let sol = solver.solve_observed(&case.heights(), control, opts, observer)?;
    let exact = case.exact_pressure();
    let err: Vec<f64> = sol
        .pressure
        .iter()
        .zip(&exact)
        .map(|(p, e)| p - e)
        .collect();
    let mut work = vec![0.0; err.len()];
    let op = solver.operator();
    let num = op.energy_product(&err, &err, &mut work)?;
    let den = op.energy_product(&exact, &exact, &mut work)?;
    let (a, p0) = fit(&case.radii(), &sol.pressure)?;
    let lecture = match case.boundary {
        Boundary::Free => Some(lecture_error(
            &sol.pressure,
            &sol.displacement,
            &exact,
            &case.exact_displacement(),
        )),
        Boundary::Periodic => None,
    };
    Ok(HertzReport {
        grid: case.grid,
        boundary: case.boundary,
        energy_error: (num.max(0.0) / den).sqrt(),
        energy_error_displacement: lecture,
        contact_radius: a,
        contact_radius_error: (a - case.contact_radius).abs() / case.contact_radius,
        peak_pressure: p0,
        peak_pressure_error: (p0 - case.peak_pressure()).abs() / case.peak_pressure(),
        contact_fraction: sol.contact_fraction,
        iterations: sol.iterations,
        residual: sol.residual,
        seconds: sol.seconds,
    })
}

/// `sqrt(|Σ(u − u_ex)(p − p_ex)| / Σ u_ex p_ex)` (the η of Molinari's lecture).
fn lecture_error(p: &[f64], u: &[f64], p_ex: &[f64], u_ex: &[f64]) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for ((p, u), (pe, ue)) in p.iter().zip(u).zip(p_ex.iter().zip(u_ex)) {
        num += (u - ue) * (p - pe);
        den += ue * pe;
    }
    (num.abs() / den).sqrt()
}

/// Least-squares fit of `p² = c₀ + c₁ r²` over the nodes with p > 0;
/// returns `(a, p₀)`.
fn fit(radii: &[f64], p: &[f64]) -> Result<(f64, f64)> {
    let (mut n, mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (r, p) in radii.iter().zip(p) {
        if *p > 0.0 {
            let (x, y) = (r * r, p * p);
            n += 1.0;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
    }
    let det = n * sxx - sx * sx;
    let c1 = (n * sxy - sx * sy) / det;
    let c0 = (sy - c1 * sx) / n;
    if !(n >= 3.0 && det > 0.0 && c0 > 0.0 && c1 < 0.0) {
        let why = if n < 3.0 {
            format!("only {n} nodes are in contact")
        } else {
            format!(
                "the {n} contact nodes give p² = c₀ + c₁r² with c₀ = {}, c₁ = {} (the \
                 contact covers the grid or its pressures are not resolved)",
                crate::error::num(c0),
                crate::error::num(c1)
            )
        };
        return Err(Error::Inconsistent {
            name: "Hertz fit".into(),
            requirement: format!(
                "at least 3 contact nodes whose p² falls with r² (c₀ > 0 > c₁); {why}"
            ),
        });
    }
    Ok(((-c0 / c1).sqrt(), c0.sqrt()))
}

/// One grid of the Hertz ball with a yield stress ([`plastic_disc`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct PlasticDiscRow {
    /// Grid side N.
    pub grid: usize,
    /// Radius c of the plastic disc (p = σY), from the count of nodes at σY:
    /// `c = √(n_pl Δ²/π)` (unit of L).
    pub plastic_radius: f64,
    /// c / a_H (a_H the elastic Hertz radius at the same load).
    pub plastic_radius_ratio: f64,
    /// `c(N) − c(N_prev)` against the previous grid of the list.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plastic_radius_change: Option<f64>,
    /// Radius of the whole contact from the count of nodes with p > 0,
    /// `√(n Δ²/π)` (unit of L).
    pub contact_radius: f64,
    /// Rigid-body approach δ (unit of L; the elastic Hertz value is a_H²/R).
    pub approach: f64,
    /// A/A0 (elastic + plastic).
    pub contact_fraction: f64,
    /// Fraction of nodes with 0 < p < σY.
    pub elastic_fraction: f64,
    /// Fraction of nodes at p = σY.
    pub plastic_fraction: f64,
    /// Mean interpenetration over the nodes at σY (unit of L).
    pub plastic_displacement_mean: f64,
    /// Largest interpenetration (unit of L).
    pub plastic_displacement_max: f64,
    /// Solver iterations (elastic + saturated stage).
    pub iterations: usize,
    /// Final residual ε.
    pub residual: f64,
    /// Wall time of the solve, s.
    pub seconds: f64,
}

/// The Hertz ball with a yield stress on a list of grids.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct PlasticDiscReport {
    /// Boundary condition.
    pub boundary: Boundary,
    /// Side L of the domain.
    pub size: f64,
    /// Ball radius R.
    pub radius: f64,
    /// Contact modulus E*.
    pub contact_modulus: f64,
    /// Solver tolerance ε.
    pub tolerance: f64,
    /// Yield stress σY (unit of E*).
    pub yield_stress: f64,
    /// σY / p₀_H.
    pub yield_ratio: f64,
    /// Elastic Hertz contact radius a_H at this load.
    pub hertz_contact_radius: f64,
    /// Elastic Hertz peak pressure p₀_H.
    pub hertz_peak_pressure: f64,
    /// Mean pressure F/L².
    pub nominal_pressure: f64,
    /// One row per grid, in the caller's order.
    pub rows: Vec<PlasticDiscRow>,
}

/// Solve the Hertz case of `case` (its `grid` is ignored) with the yield
/// stress `yield_stress` on each grid of `grids`.
///
/// # Formula
/// ```text
/// c = √(n_pl Δ²/π),   n_pl = #{p_i = σY}      (plastic disc)
/// r_A = √(n Δ²/π),    n = #{p_i > 0}           (whole contact)
/// ```
/// Both are node counts: they move in steps of whole shells of nodes of
/// equal radius (8-fold lattice symmetry), a scatter of ~±0.2 % of c at 512²
/// (README, "Yield stress").
///
/// # Errors
/// No grid; an invalid case or grid; σY not finite and positive or ≤ the mean
/// pressure; a grid too large for memory; solver errors.
pub fn plastic_disc(
    case: &HertzCase,
    grids: &[usize],
    yield_stress: f64,
    opts: &Options,
    observer: &mut dyn FnMut(usize, Iteration),
) -> Result<PlasticDiscReport> {
    if grids.is_empty() {
        return Err(Error::invalid("grid", 0.0, "at least one grid"));
    }
    let y = check::positive("yield_stress", yield_stress)?;
    let opts = Options {
        yield_stress: Some(y),
        ..*opts
    };
    let mut rows: Vec<PlasticDiscRow> = Vec::with_capacity(grids.len());
    for (k, &n) in grids.iter().enumerate() {
        let c = HertzCase { grid: n, ..*case };
        c.check()?;
        super::check_memory(n, c.boundary)?;
        let op = Operator::new(c.boundary, n, c.size, c.e_star)?;
        let mut solver = Solver::new(op);
        let sol = solver.solve_observed(
            &c.heights(),
            Control::MeanPressure(c.mean_pressure()),
            &opts,
            &mut |it| observer(k, it),
        )?;
        let area = c.size * c.size / std::f64::consts::PI;
        let plastic_radius = (sol.plastic_fraction * area).sqrt();
        rows.push(PlasticDiscRow {
            grid: n,
            plastic_radius,
            plastic_radius_ratio: plastic_radius / c.contact_radius,
            plastic_radius_change: rows.last().map(|r| plastic_radius - r.plastic_radius),
            contact_radius: (sol.contact_fraction * area).sqrt(),
            approach: sol.approach,
            contact_fraction: sol.contact_fraction,
            elastic_fraction: sol.elastic_fraction,
            plastic_fraction: sol.plastic_fraction,
            plastic_displacement_mean: sol.plastic_displacement_mean,
            plastic_displacement_max: sol.plastic_displacement_max,
            iterations: sol.iterations,
            residual: sol.residual,
            seconds: sol.seconds,
        });
    }
    Ok(PlasticDiscReport {
        boundary: case.boundary,
        size: case.size,
        radius: case.radius,
        contact_modulus: case.e_star,
        tolerance: opts.tolerance,
        yield_stress: y,
        yield_ratio: y / case.peak_pressure(),
        hertz_contact_radius: case.contact_radius,
        hertz_peak_pressure: case.peak_pressure(),
        nominal_pressure: case.mean_pressure(),
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_forms_are_consistent() {
        // a = 0.1 R: F = 4e-3/3, p₀ = 0.2/π, and p₀ = 3F/(2πa²).
        let f = reference::ball_load(0.1, 1.0, 1.0);
        assert!((reference::ball_contact_radius(f, 1.0, 1.0) - 0.1).abs() < 1e-16);
        let p0 = reference::ball_peak_pressure(0.1, 1.0, 1.0);
        assert!((p0 - 3.0 * f / (2.0 * std::f64::consts::PI * 0.01)).abs() < 1e-16);
        assert_eq!(reference::pressure_profile(0.2, 0.1, p0), 0.0);
    }

    /// Rounding of the closed forms (a few ulps of u ~ 1e-2).
    const DISPLACEMENT_REL_TOL: f64 = 1e-14;

    #[test]
    fn displacement_matches_high_precision_values() {
        // mpmath (40 digits) of Johnson's 3.41a/3.42a as written, a = 0.1,
        // p₀ = 2a/π (R = E* = 1): δ = a²/R = 0.01 at the centre, δ/2 at r = a.
        let p0 = reference::ball_peak_pressure(0.1, 1.0, 1.0);
        let cases = [
            (0.0, 0.01),
            (0.05, 0.00875),
            (0.1, 0.005),
            (0.1000001, 0.004_999_990_011_999_217),
            (0.15, 0.002_978_113_899_088_96),
            (0.3, 0.001_431_021_803_713_569_6),
            (0.7, 6.075_500_956_664_112e-4),
            (10.0, 4.244_174_258_466_282e-5),
            (1000.0, 4.244_131_820_028_007e-7),
        ];
        for (r, want) in cases {
            let got = reference::ball_displacement(r, 0.1, p0, 1.0);
            assert!(
                (got / want - 1.0).abs() < DISPLACEMENT_REL_TOL,
                "r = {r}: {got:e} vs {want:e}"
            );
        }
    }

    #[test]
    fn fit_recovers_an_exact_profile() {
        let case = HertzCase::new(64, Boundary::Free);
        let (a, p0) = fit(&case.radii(), &case.exact_pressure()).unwrap();
        assert!((a - 0.1).abs() < 1e-12 && (p0 - case.peak_pressure()).abs() < 1e-12);
    }

    /// A fit over many contact nodes whose p² does not fall with r² says
    /// why, not "at least 3 contact nodes".
    #[test]
    fn a_failed_fit_says_why() {
        let radii = [0.0, 0.1, 0.2, 0.3, 0.4];
        let e = fit(&radii, &[1.0; 5]).unwrap_err().to_string();
        assert!(e.contains("the 5 contact nodes give p²"), "{e}");
        assert!(!e.contains("got"), "{e}");
        let e = fit(&radii, &[1.0, 0.5, 0.0, 0.0, 0.0])
            .unwrap_err()
            .to_string();
        assert!(e.contains("only 2 nodes are in contact"), "{e}");
    }
}

//! The exact contact stiffness of a solved BEM contact: a linear solve on
//! the converged contact set.
//!
//! # What it solves
//! ```text
//! find Δp on the contact set C = {p > 0}, Δp = 0 elsewhere, with
//!   (𝒢 Δp)_i = Δδ = 1   for i ∈ C           (the gap stays closed on C)
//! K/A0 = dσ0/dδ = (1/N²) Σ_i Δp_i = −dσ0/dū
//! ```
//! A frictionless elastic contact pressed further by dδ keeps its contact
//! set to first order (the nodes with p > 0 stay in contact, the open gaps
//! stay open), so the pressure increment is the solution of the elastic
//! problem on the fixed set with a uniform displacement increment: this is
//! the derivative of the discrete load–approach curve, without finite
//! differences. With the periodic operator the mean of 𝒢p is zero, so the
//! mean gap changes by −dδ and K = −dσ0/dū, the stiffness of
//! [`crate::separation`]; with the free operator δ is the rigid approach.
//! Barber's identity turns K into the contact conductance
//! ([`crate::conductance`]).
//!
//! # Method
//! Conjugate gradients on 𝒢_CC (symmetric positive definite: 𝒢 is
//! positive semidefinite with only the constant in its kernel, which no
//! vector supported on C ≠ all nodes contains), from Δp = 0, two masked
//! FFT applications of [`Operator`] per iteration. CG from zero makes
//! 1ᵀΔp_k = ‖Δp_k‖²_𝒢 increase to its limit, and the remaining error is
//! ‖r_k‖²_{𝒢⁻¹} ≤ ‖r_k‖²/λ_min with, for the periodic operator,
//! λ_min ≥ 2 (1 − |C|/N²)/(E* q_max), q_max = √2 π N/L (the eigenvalues
//! 2/(E*|q|) of 𝒢, less the weight of the removed q = 0 mode). That bound is
//! the `stiffness_error_bound`; the free operator's λ_min is taken from the
//! same formula with |C|/N² = 0 (not a proven bound there). Stops when
//! ‖r‖ ≤ `tolerance`·‖1_C‖.
//!
//! # References
//! - J. R. Barber, Proc. R. Soc. Lond. A 459, 53 (2003) (incremental stiffness
//!   of a frictionless contact, fixed contact set).
//! - M. R. Hestenes, E. Stiefel, J. Res. Natl. Bur. Stand. 49, 409 (1952) (CG).

use serde::Serialize;

use super::{Boundary, Operator};
use crate::error::{check, Error, Result};

/// Accuracy knobs of [`contact_stiffness`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StiffnessOptions {
    /// Relative residual ‖r‖/‖1_C‖ at which CG stops, in [1e-15, 0.1].
    pub tolerance: f64,
    /// Most CG iterations.
    pub max_iterations: usize,
}

impl Default for StiffnessOptions {
    /// tolerance 1e-10, 10 000 iterations.
    fn default() -> Self {
        StiffnessOptions {
            tolerance: 1e-10,
            max_iterations: 10_000,
        }
    }
}

/// The stiffness of one solved contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct BemStiffness {
    /// K/A0 = dσ0/dδ, unit of E* per unit of L (Pa/m in SI).
    pub stiffness: f64,
    /// Bound on the absolute error of K/A0 left by CG (module docs).
    pub stiffness_error_bound: f64,
    /// Nodes in the contact set.
    pub contact_nodes: usize,
    /// CG iterations.
    pub iterations: usize,
    /// Final ‖r‖/‖1_C‖.
    pub residual: f64,
}

/// K/A0 of the contact whose pressures are `pressure` (`N × N`, the BEM's
/// [`super::Solution::pressure`]), on the operator it was solved with.
///
/// # Errors
/// Wrong length; no contact node, or every node in contact (K is then
/// undefined or infinite); bad options; [`Error::NotConverged`].
pub fn contact_stiffness(
    op: &mut Operator,
    pressure: &[f64],
    options: &StiffnessOptions,
) -> Result<BemStiffness> {
    check::tolerance("tolerance", options.tolerance)?;
    let n = op.n();
    let n2 = n * n;
    if pressure.len() != n2 {
        return Err(Error::invalid(
            "pressure",
            pressure.len() as f64,
            format!("N² = {n2} values"),
        ));
    }
    let mask: Vec<f64> = pressure
        .iter()
        .map(|&p| if p > 0.0 { 1.0 } else { 0.0 })
        .collect();
    let contact = mask.iter().filter(|&&m| m > 0.0).count();
    if contact == 0 || (contact == n2 && op.boundary() == Boundary::Periodic) {
        return Err(Error::invalid(
            "contact_fraction",
            contact as f64 / n2 as f64,
            "strictly between 0 and 1 (K/A0 is 0 or infinite otherwise)",
        ));
    }
    let mut x = vec![0.0; n2];
    let mut r = mask.clone(); // b − A·0 = 1_C
    let mut d = r.clone();
    let mut ad = vec![0.0; n2];
    let b_norm = (contact as f64).sqrt();
    let mut rr: f64 = contact as f64;
    let mut iterations = 0;
    while rr.sqrt() > options.tolerance * b_norm {
        if iterations >= options.max_iterations {
            return Err(Error::NotConverged {
                what: "contact stiffness (CG on the contact set)".into(),
                iterations,
                residual: rr.sqrt() / b_norm,
                tolerance: options.tolerance,
            });
        }
        op.apply(&d, &mut ad)?;
        let mut dad = 0.0;
        for k in 0..n2 {
            ad[k] *= mask[k];
            dad += d[k] * ad[k];
        }
        if dad <= 0.0 {
            break; // exact solution reached in fewer steps than the dimension
        }
        let alpha = rr / dad;
        let mut rr_new = 0.0;
        for k in 0..n2 {
            x[k] += alpha * d[k];
            r[k] -= alpha * ad[k];
            rr_new += r[k] * r[k];
        }
        let beta = rr_new / rr;
        for k in 0..n2 {
            d[k] = r[k] + beta * d[k];
        }
        rr = rr_new;
        iterations += 1;
    }
    let sum: f64 = x.iter().sum();
    let q_max = std::f64::consts::SQRT_2 * std::f64::consts::PI * n as f64 / op.size();
    let fraction = if op.boundary() == Boundary::Periodic {
        contact as f64 / n2 as f64
    } else {
        0.0
    };
    let lambda_min = 2.0 * (1.0 - fraction) / (op.e_star() * q_max);
    let k = sum / n2 as f64;
    Ok(BemStiffness {
        stiffness: k,
        stiffness_error_bound: rr / lambda_min / n2 as f64 + 64.0 * f64::EPSILON * k.abs(),
        contact_nodes: contact,
        iterations,
        residual: rr.sqrt() / b_norm,
    })
}

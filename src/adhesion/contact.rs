//! Adhesive contact: A/A0 against σ0 (tensile σ0 included) and magnification,
//! from the stress diffusion with the moving detachment boundary −σ_a(ζ).
//!
//! # What it solves
//! ```text
//! ∂P/∂t = ∂²P/∂σ²  for σ > −σ_a(t),   P(−σ_a(t), t) = 0,   P(σ, 0) = δ(σ − σ0)
//! t(ζ) = σ0² G(ζ) = (π/4) E*² ∫_{q_l}^{ζq_l} q³ C dq,   σ_a(ζ) = [c_a γ_eff(ζ) E* ζ q_l]^{1/2}
//! ```
//! (Persson, Eur. Phys. J. E 8, 385 (2002) and Phys. Rev. Lett. 89, 245502
//! (2002); γ_eff and σ_a in [`crate::adhesion`]). σ0 may be negative (tension)
//! down to the pull-off stress −σ_p = −σ_a(1); beyond it nothing is in contact.
//!
//! # Method
//! The Volterra equation of the second kind for the detachment rate
//! g = −dA/dt (Buonocore, Nobile & Ricciardi, Adv. Appl. Probab. 19, 784
//! (1987)), whose kernel vanishes where σ_a is constant, so that Δγ = 0
//! returns erf(1/(2√G)) (the image solution of [`crate::stress`]) to rounding.
//! Product trapezoidal rule (O(N²) in the N nodes) on a mesh in ln ζ:
//! uniform with `nodes_per_e_fold` nodes per unit of ln ζ (at least that many
//! however short the span), preceded by a geometric grading with ratio
//! e^{1/nodes_per_e_fold} that starts where t(ζ) = d²/120 (d = σ0 + σ_a(1),
//! the start's distance from the boundary; Lévy's first-passage density
//! d e^{−d²/4t}/√(4π t³) is ~1e-11 of its peak there) and ends where its step
//! reaches the uniform one, plus a geometric grading on both sides of every ζ
//! where γ_eff changes sign (there σ_a grows like √(ζ − ζ_c)). The output ζ
//! are mesh nodes.
//!
//! # Accuracy knob and error estimate
//! Every point is solved on the mesh and on the mesh with every interval
//! halved (in ln ζ); the difference bounds the error of the finer value for
//! an error falling at least like h^{3/2} (the integrands behave like √(t − τ)
//! on the diagonal), i.e. once both meshes resolve the boundary. The mesh is
//! doubled until every fraction's estimate is below `tolerance` or the finer
//! mesh would exceed `max_nodes`; then the point carries
//! [`Flag::ToleranceNotMet`] and its (larger) estimate. The estimate is not a
//! rigorous bound: where σ_a(ζ) starts from 0 (γ_eff crossing zero) dσ_a/dt
//! is infinite for an instant and the convergence order drops locally.

use super::detachment::BoundaryNode;
use super::model::AdhesionModel;
use super::moving::{solve, Solution};
use crate::error::{check, Error, Result};
use crate::quad::Estimate;

/// Default tolerance of the fractions.
const DEFAULT_TOLERANCE: f64 = 1e-5;
/// Default nodes per unit of ln ζ of the coarser mesh.
const DEFAULT_NODES: usize = 24;
/// Default cap on the finer mesh's nodes.
const DEFAULT_MAX_NODES: usize = 8_000;
/// Lévy grading starts at t = d²/LEVY_START (density ~1e-11 of its peak).
const LEVY_START: f64 = 120.0;
/// ln of the grading ratio times the mesh density (r = e^{1/24} at 24 nodes per e-fold).
const LEVY_GRADING: f64 = 1.0;
/// Bisection steps locating a sign change of γ_eff in ln ζ.
const ONSET_BISECTIONS: usize = 50;
/// Grading towards a sign change of γ_eff stops at this fraction of a mesh step.
const ONSET_FLOOR: f64 = 1e-6;
/// Rounding allowance added to every estimate (the sums have ≤ 1e4 terms of size ≤ 1).
const ROUNDING: f64 = 1e-14;

/// A condition of an adhesive point that a user should know about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Flag {
    /// σ0 ≤ −σ_p: the tension exceeds the pull-off stress, nothing is in contact.
    Detached,
    /// The error estimate exceeds the tolerance at the largest mesh allowed.
    ToleranceNotMet,
}

/// A/A0 and the loads at one nominal pressure and magnification.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct AdhesivePoint {
    /// Nominal pressure σ0 (Pa; negative in tension).
    pub nominal_pressure: f64,
    /// Magnification ζ.
    pub zeta: f64,
    /// A/A0 = ∫_{−σ_a}^∞ P dσ.
    pub contact_fraction: f64,
    /// Estimate of the absolute error of `contact_fraction`.
    pub contact_fraction_error_bound: f64,
    /// 1 − A/A0, computed as the detached fraction ∫ g dt (the trapezoid rule
    /// of the detachment rate), independently of `contact_fraction`.
    pub non_contact_fraction: f64,
    /// Estimate of the absolute error of `non_contact_fraction`.
    pub non_contact_fraction_error_bound: f64,
    /// The part of A/A0 under tension, ∫_{−σ_a}^0 P dσ.
    pub tensile_fraction: f64,
    /// Estimate of the absolute error of `tensile_fraction`.
    pub tensile_fraction_error_bound: f64,
    /// σ_a(ζ) (Pa).
    pub detachment_stress: f64,
    /// γ_eff(ζ) (J/m²).
    pub effective_interfacial_energy: f64,
    /// ∫ σ P dσ (Pa): the pressure carried by the contact seen at ζ.
    pub carried_pressure: f64,
    /// Estimate of the absolute error of `carried_pressure`.
    pub carried_pressure_error_bound: f64,
    /// ∫ σ_a dA_detached (Pa): the tension released by detachment up to ζ;
    /// carried_pressure − released_tension = σ0.
    pub released_tension: f64,
    /// Estimate of the absolute error of `released_tension`.
    pub released_tension_error_bound: f64,
    /// σ_p = σ_a(1) (Pa).
    pub pull_off_stress: f64,
    /// Nodes of the finer mesh.
    pub nodes: usize,
    /// Conditions the user should know about.
    pub flags: Vec<Flag>,
}

/// The adhesive contact solver for one [`AdhesionModel`].
#[derive(Clone, Copy)]
pub struct AdhesiveContact<'a> {
    model: AdhesionModel<'a>,
    tolerance: f64,
    nodes_per_e_fold: usize,
    max_nodes: usize,
}

/// One mesh with its boundary.
struct Mesh {
    nodes: Vec<BoundaryNode>,
}

impl Mesh {
    fn arrays(&self) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        (
            self.nodes.iter().map(|n| n.t).collect(),
            self.nodes.iter().map(|n| n.b).collect(),
            self.nodes.iter().map(|n| n.db).collect(),
        )
    }
}

impl<'a> AdhesiveContact<'a> {
    /// The solver with tolerance 1e-5 on the fractions, 24 nodes per unit of
    /// ln ζ to start and at most 8 000 nodes.
    pub fn new(model: AdhesionModel<'a>) -> Self {
        AdhesiveContact {
            model,
            tolerance: DEFAULT_TOLERANCE,
            nodes_per_e_fold: DEFAULT_NODES,
            max_nodes: DEFAULT_MAX_NODES,
        }
    }

    /// Set the tolerance of the fractions' error estimates.
    ///
    /// # Errors
    /// `tolerance` outside [1e-15, 0.1].
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        self.tolerance = check::tolerance("tolerance", tolerance)?;
        Ok(self)
    }

    /// Set the starting mesh density (nodes per unit of ln ζ) and the cap on
    /// the finer mesh: the accuracy knob of the Volterra solver.
    ///
    /// # Errors
    /// `nodes_per_e_fold` outside 2 … 10⁵ or `max_nodes` outside 16 … 10⁵.
    pub fn with_nodes(mut self, nodes_per_e_fold: usize, max_nodes: usize) -> Result<Self> {
        if !(2..=100_000).contains(&nodes_per_e_fold) {
            return Err(Error::invalid(
                "nodes_per_e_fold",
                nodes_per_e_fold as f64,
                "from 2 to 1e5",
            ));
        }
        if !(16..=100_000).contains(&max_nodes) {
            return Err(Error::invalid(
                "max_nodes",
                max_nodes as f64,
                "from 16 to 1e5",
            ));
        }
        self.nodes_per_e_fold = nodes_per_e_fold;
        self.max_nodes = max_nodes;
        Ok(self)
    }

    /// The model.
    pub fn model(&self) -> &AdhesionModel<'a> {
        &self.model
    }

    /// A/A0 at σ0 = `nominal_pressure` (Pa, may be ≤ 0) and magnification ζ.
    ///
    /// # Errors
    /// σ0 not finite or |σ0| > √f64::MAX/4 ≈ 3.4e153; ζ outside [1, ζ_max].
    ///
    /// # Examples
    /// ```
    /// use persson::adhesion::{AdhesionModel, AdhesiveContact};
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// let s = SelfAffine::new(1e4, 1e5, 1e8, 0.8, Amplitude::RmsSlope(1.0)).unwrap();
    /// // Δγ = 0: the non-adhesive A/A0 = erf(1/(2√G)), G = (E*/σ0)² h'²/8
    /// let c = AdhesiveContact::new(AdhesionModel::new(&s, 1e7, 0.0).unwrap());
    /// let p = c.point(2e6, 1e4).unwrap();
    /// let a = persson::theory::Persson::new(&s, 1e7).unwrap().point(1e4, 2e6).unwrap();
    /// assert!((p.contact_fraction - a.contact_fraction).abs() < 1e-13);
    /// ```
    pub fn point(&self, nominal_pressure: f64, zeta: f64) -> Result<AdhesivePoint> {
        Ok(self
            .magnification_curve(nominal_pressure, &[zeta])?
            .remove(0))
    }

    /// [`AdhesiveContact::point`] at each ζ of `zetas` for one σ0 (one solve).
    ///
    /// # Errors
    /// As [`AdhesiveContact::point`].
    pub fn magnification_curve(
        &self,
        nominal_pressure: f64,
        zetas: &[f64],
    ) -> Result<Vec<AdhesivePoint>> {
        // |σ0| ≤ √f64::MAX/4: with σ_a² ≤ f64::MAX/16 (the bound of
        // `AdhesionModel::new`) every (σ − b)² of the diffusion is at most
        // f64::MAX/4
        let bound = f64::MAX.sqrt() / 4.0;
        if !(nominal_pressure.is_finite() && nominal_pressure.abs() <= bound) {
            return Err(Error::invalid(
                "nominal_pressure",
                nominal_pressure,
                format!(
                    "finite and in [-{0}, {0}] so that the squares of the adhesive stress \
                     diffusion stay finite in f64",
                    crate::error::approx(bound)
                ),
            ));
        }
        let zetas = zetas
            .iter()
            .map(|&z| self.model.check_zeta(z))
            .collect::<Result<Vec<_>>>()?;
        let pull = self.model.pull_off_stress()?;
        if nominal_pressure <= -pull.value {
            return zetas
                .iter()
                .map(|&z| self.detached(nominal_pressure, z, pull.value))
                .collect();
        }
        self.solve_converged(nominal_pressure, &zetas, pull.value)
    }

    /// [`AdhesiveContact::point`] at each σ0 of `pressures` at one ζ.
    ///
    /// # Errors
    /// As [`AdhesiveContact::point`], for the first bad pressure.
    pub fn load_curve(&self, pressures: &[f64], zeta: f64) -> Result<Vec<AdhesivePoint>> {
        pressures.iter().map(|&p| self.point(p, zeta)).collect()
    }

    /// A point where σ0 ≤ −σ_p: no contact.
    fn detached(&self, sigma0: f64, zeta: f64, pull: f64) -> Result<AdhesivePoint> {
        let (gamma, sigma) = self.model.gamma_sigma(zeta)?;
        Ok(AdhesivePoint {
            nominal_pressure: sigma0,
            zeta,
            contact_fraction: 0.0,
            contact_fraction_error_bound: 0.0,
            non_contact_fraction: 1.0,
            non_contact_fraction_error_bound: 0.0,
            tensile_fraction: 0.0,
            tensile_fraction_error_bound: 0.0,
            detachment_stress: sigma.value,
            effective_interfacial_energy: gamma.value,
            carried_pressure: 0.0,
            carried_pressure_error_bound: 0.0,
            released_tension: -sigma0,
            released_tension_error_bound: 0.0,
            pull_off_stress: pull,
            nodes: 0,
            flags: vec![Flag::Detached],
        })
    }

    /// Solve on meshes of growing density until the estimate meets the tolerance.
    fn solve_converged(&self, sigma0: f64, zetas: &[f64], pull: f64) -> Result<Vec<AdhesivePoint>> {
        let mut density = self.nodes_per_e_fold;
        loop {
            let coarse = self.mesh(sigma0, zetas, density, pull)?;
            let fine = self.refine(&coarse)?;
            let n_fine = fine.nodes.len();
            let points = self.compare(sigma0, zetas, pull, &coarse, &fine)?;
            let worst = points
                .iter()
                .map(|p| {
                    p.contact_fraction_error_bound
                        .max(p.tensile_fraction_error_bound)
                })
                .fold(0.0, f64::max);
            if worst <= self.tolerance {
                return Ok(points);
            }
            if 2 * n_fine > self.max_nodes {
                return Ok(points
                    .into_iter()
                    .map(|mut p| {
                        p.flags.push(Flag::ToleranceNotMet);
                        p
                    })
                    .collect());
            }
            density *= 2;
        }
    }

    /// The coarser mesh: uniform in ln ζ, the output ζ inserted, graded near
    /// ζ = 1 on Lévy's time scale of the start.
    fn mesh(&self, sigma0: f64, zetas: &[f64], density: usize, pull: f64) -> Result<Mesh> {
        let top = zetas.iter().copied().fold(1.0, f64::max);
        let span = top.ln();
        // at least `density` intervals however short the span (ζ near 1)
        let n = ((density as f64 * span).ceil() as usize).max(density);
        let step = span / n as f64;
        // Geometric grading from Lévy's time scale of the start, t = d²/120,
        // until its steps reach the uniform step: the detachment rate varies
        // on the scale of t itself there.
        let d = sigma0 + pull;
        let ratio = (LEVY_GRADING / density as f64).exp();
        let graded_to = (step / (ratio - 1.0)).min(span);
        let start = self
            .u_at_time(d * d / LEVY_START, span)?
            .min(graded_to / ratio);
        let mut u: Vec<f64> = (0..=n)
            .map(|i| span * i as f64 / n as f64)
            .filter(|&v| v < start || v >= graded_to)
            .collect();
        let mut v = start;
        while v > 0.0 && v < graded_to {
            u.push(v);
            v *= ratio;
        }
        u.extend(zetas.iter().map(|z| z.ln()));
        self.grade_onsets(&mut u, span, n, density)?;
        u.sort_by(f64::total_cmp);
        u.dedup_by(|a, b| (*a - *b).abs() <= 1e-15 * b.abs().max(1e-300));
        self.nodes_at(&u)
    }

    /// ln ζ where t(ζ) = `time` (bisection; `span` when t(ζ_end) < time).
    fn u_at_time(&self, time: f64, span: f64) -> Result<f64> {
        let t = |v: f64| -> Result<f64> { Ok(self.model.boundary_node(v.exp())?.t) };
        if t(span)? <= time {
            return Ok(span);
        }
        let (mut lo, mut hi) = (0.0, span);
        for _ in 0..ONSET_BISECTIONS {
            let mid = 0.5 * (lo + hi);
            if t(mid)? < time {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(lo)
    }

    /// Geometric grading on both sides of each ln ζ where γ_eff changes sign:
    /// there σ_a grows like √(ζ − ζ_c) and dσ_a/dt is infinite for an instant.
    fn grade_onsets(&self, u: &mut Vec<f64>, span: f64, n: usize, density: usize) -> Result<()> {
        if span <= 0.0 {
            return Ok(());
        }
        let gamma = |v: f64| -> Result<f64> { Ok(self.model.gamma_sigma(v.exp())?.0.value) };
        let step = span / n as f64;
        let ratio = (4.0 / density as f64).exp().max(1.01);
        let mut prev = gamma(0.0)?;
        for i in 1..=n {
            let (lo0, hi0) = (step * (i - 1) as f64, step * i as f64);
            let next = gamma(hi0)?;
            if (prev > 0.0) != (next > 0.0) {
                let (mut lo, mut hi) = (lo0, hi0);
                for _ in 0..ONSET_BISECTIONS {
                    let mid = 0.5 * (lo + hi);
                    if (gamma(mid)? > 0.0) == (prev > 0.0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let c = 0.5 * (lo + hi);
                let mut h = step;
                while h > ONSET_FLOOR * step {
                    for v in [c - h, c + h] {
                        if v > 0.0 && v < span {
                            u.push(v);
                        }
                    }
                    h /= ratio;
                }
                u.push(c);
            }
            prev = next;
        }
        Ok(())
    }

    /// Boundary nodes at u = ln ζ.
    fn nodes_at(&self, u: &[f64]) -> Result<Mesh> {
        let top = self.model.zeta_max();
        let nodes = u
            .iter()
            .map(|&v| {
                self.model
                    .boundary_node(if v == 0.0 { 1.0 } else { v.exp().min(top) })
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Mesh { nodes })
    }

    /// The mesh with every interval halved in ln ζ.
    fn refine(&self, coarse: &Mesh) -> Result<Mesh> {
        let mut nodes = Vec::with_capacity(2 * coarse.nodes.len());
        for pair in coarse.nodes.windows(2) {
            nodes.push(pair[0]);
            let mid = 0.5 * (pair[0].zeta.ln() + pair[1].zeta.ln());
            nodes.push(self.model.boundary_node(mid.exp())?);
        }
        if let Some(last) = coarse.nodes.last() {
            nodes.push(*last);
        }
        Ok(Mesh { nodes })
    }

    /// Solve on both meshes and build the points at the output ζ.
    fn compare(
        &self,
        sigma0: f64,
        zetas: &[f64],
        pull: f64,
        coarse: &Mesh,
        fine: &Mesh,
    ) -> Result<Vec<AdhesivePoint>> {
        let index = zetas
            .iter()
            .map(|&z| {
                coarse
                    .nodes
                    .iter()
                    .position(|n| (n.zeta - z).abs() <= 1e-13 * z)
                    .ok_or_else(|| Error::NotConverged {
                        what: format!("adhesion: mesh node at zeta = {z:e}"),
                        iterations: coarse.nodes.len(),
                        residual: f64::NAN,
                        tolerance: 0.0,
                    })
            })
            .collect::<Result<Vec<_>>>()?;
        let run = |m: &Mesh, at: &[usize]| -> Solution {
            let (t, b, db) = m.arrays();
            solve(&t, &b, &db, sigma0, at)
        };
        let sc = run(coarse, &index);
        let sf = run(fine, &index.iter().map(|i| 2 * i).collect::<Vec<_>>());
        let scale = sigma0.abs().max(pull).max(f64::MIN_POSITIVE);
        let est = |f: &[f64], c: &[f64], k: usize, s: f64| Estimate {
            value: f[k],
            error: (f[k] - c[k]).abs() + ROUNDING * s,
        };
        zetas
            .iter()
            .enumerate()
            .map(|(k, &z)| {
                let (gamma, sigma) = self.model.gamma_sigma(z)?;
                let a = est(&sf.contact, &sc.contact, k, 1.0);
                let d = est(&sf.detached, &sc.detached, k, 1.0);
                let at = est(&sf.tensile, &sc.tensile, k, 1.0);
                let l = est(&sf.carried, &sc.carried, k, scale);
                let r = est(&sf.released, &sc.released, k, scale);
                Ok(AdhesivePoint {
                    nominal_pressure: sigma0,
                    zeta: z,
                    contact_fraction: a.value,
                    contact_fraction_error_bound: a.error,
                    non_contact_fraction: d.value,
                    non_contact_fraction_error_bound: d.error,
                    tensile_fraction: at.value,
                    tensile_fraction_error_bound: at.error,
                    detachment_stress: sigma.value,
                    effective_interfacial_energy: gamma.value,
                    carried_pressure: l.value,
                    carried_pressure_error_bound: l.error,
                    released_tension: r.value,
                    released_tension_error_bound: r.error,
                    pull_off_stress: pull,
                    nodes: fine.nodes.len(),
                    flags: Vec::new(),
                })
            })
            .collect()
    }
}

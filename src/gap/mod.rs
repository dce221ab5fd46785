//! The distribution of interfacial separations P(u) from Persson's theory.
//!
//! # Formula
//! ```text
//! P(u) = (A(ζ1)/A0) δ(u) + P_nc(u),
//! P_nc(u) = ∫_1^{ζ1} dζ (−A′(ζ)/A0) [φ_h(u − u1(ζ)) + φ_h(u + u1(ζ))],   u ≥ 0
//! φ_h(x) = e^{−x²/(2h²)} / (√(2π) h),   h(ζ)² = 2π ∫_{ζ q_l}^{q_s} q C(q) dq
//! ```
//! ζ1 = q_s/q_l. The area −dA that leaves contact between ζ and ζ + dζ is
//! separated by u1(ζ) on average (Yang & Persson 2008; [`magnified`]); the
//! roughness not yet resolved at ζ (wavevectors above ζ q_l, rms height h(ζ))
//! spreads that separation into a Gaussian, folded at u = 0 so that no
//! separation is negative (Almqvist, Campañá, Prodanov & Persson 2011: the
//! P(u) of Persson's theory). The weights integrate to A(1)/A0 = 1
//! exactly, so P is normalised: `contact_fraction + ∫ P_nc du = 1`.
//!
//! Without the fold the first moment telescopes, ∫ (−A′) u1 dζ = ū(σ0) of
//! [`crate::separation`] exactly (module docs of [`magnified`]); the fold
//! adds E|X| − u1 = 2h φ(u1/h) − 2u1 Φ(−u1/h) ≥ 0 per node (φ, Φ the
//! standard normal density and distribution), reported as
//! [`SeparationDensity::fold_shift`], so that ∫ u P(u) du = ū + fold_shift.
//! (The paper's text was not available here; the fold is our reading of
//! its P(u), and the only choice not fixed by normalisation. Both
//! numbers are reported so a user can see its size.)
//!
//! # Method
//! The ζ-integral runs in s = ln ζ on panels (split at the spectrum's break
//! points, `panels_per_decade` per decade of ζ) with the 7-point Gauss /
//! 15-point Kronrod pair. Panels are halved until the two rules agree to
//! `rule_tolerance` on the weight ∫(−A′)dζ (closed form, cheap: at low load
//! all of it sits just above ζ = 1) and then on the volume ∫(−A′)u1 dζ
//! (relative to ū). u1 is computed at the 15 Kronrod nodes of each panel
//! (one vector q-integral each, `Magnified::point`), and every
//! result — P_nc(u) at a u, or ∫ P_nc(u) f(u) du — comes with the summed
//! per-panel difference of the two rules plus the propagated errors of u1 as
//! its error bound (P_nc(u) at u ≪ ū, where narrow Gaussians of the largest
//! ζ dominate, is the least resolved: ~1e−2 relative at u = 1e−4 ū, 1e−8 at
//! u = 1e−2 ū, measured). Expectations over one node's folded Gaussian are adaptive
//! Gauss–Kronrod over u ∈ [max(0, u1 − 10h), u1 + 10h] (the mass beyond
//! 10h is below 1e−22).
//!
//! # References
//! - A. Almqvist, C. Campañá, N. Prodanov, B. N. J. Persson, J. Mech. Phys.
//!   Solids 59, 2355 (2011) (P(u)).
//! - C. Yang, B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214 (2008),
//!   doi:10.1088/0953-8984/20/21/215214 (u1(ζ)).
//! - B. N. J. Persson, Phys. Rev. Lett. 99, 125502 (2007) (ū(p)).

mod band;
mod fast_e1;
pub mod magnified;
pub mod points;
pub mod table;

use serde::Serialize;

use crate::error::{check, Error, Result};
use crate::quad::{integrate, Estimate};
use crate::separation::Separation;
use crate::spectrum::Spectrum;
use magnified::Magnified;
pub use points::PointSet;
pub use table::{SeparationTable, TableOptions};

/// Default relative tolerance of the q-integrals behind u1(ζ).
pub const DEFAULT_TOLERANCE: f64 = 1e-9;

/// Default agreement of the Gauss and Kronrod ζ-rules per panel.
const DEFAULT_RULE_TOLERANCE: f64 = 1e-10;

/// Default number of ζ-panels per decade of magnification.
const DEFAULT_PANELS_PER_DECADE: usize = 3;

/// Gauss–Kronrod G7/K15 abscissae on [−1, 1] (non-negative half, descending;
/// the odd-indexed ones are the Gauss nodes).
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights for [`XGK`].
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// Gauss weights for the nodes XGK[1], XGK[3], XGK[5], XGK[7].
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// Node weight (fraction of A0) below which a node does not set the largest separation.
const NEGLIGIBLE_WEIGHT: f64 = 1e-18;

/// Below this window/u1 ratio a node's Gaussian is treated as a point mass.
const NARROW: f64 = 1e-6;

/// Width, in units of h, of the u-window of one node's Gaussian.
const WINDOW: f64 = 10.0;

/// Accuracy knobs of [`SeparationDensity`].
#[derive(Debug, Clone, PartialEq)]
pub struct DensityOptions {
    /// Relative tolerance of the q-integrals behind u1(ζ), in [1e-15, 0.1].
    pub tolerance: f64,
    /// ζ-panels per decade of magnification (each 15 evaluations of u1), ≥ 1.
    pub panels_per_decade: usize,
    /// Wavevectors (1/m) where C(q) has a kink (the roll-off q_r): panel ends.
    pub breaks: Vec<f64>,
    /// Panels are halved until the Gauss and Kronrod rules agree on ∫(−A′)dζ
    /// to this (absolute, the total is ≤ 1) and on ∫(−A′) u1 dζ to this
    /// relative to ū; in [1e-15, 0.1].
    pub rule_tolerance: f64,
    /// ζ-panels per unit of s = ln m3 of the load curves' table
    /// ([`TableOptions::zeta_panels_per_unit`], > 0, ≤ 100; default
    /// [`table::DEFAULT_CURVE_PANELS_PER_UNIT`]): the accuracy knob of the
    /// effective-medium and gap-conductance load curves (their error
    /// against time: docs/speed.md).
    pub table_panels_per_unit: f64,
}

impl DensityOptions {
    /// The table options of the load curves: `table_panels_per_unit`, the
    /// breaks, the default q-rule.
    pub fn table(&self) -> TableOptions {
        TableOptions {
            zeta_panels_per_unit: self.table_panels_per_unit,
            breaks: self.breaks.clone(),
            ..TableOptions::default()
        }
    }
}

impl Default for DensityOptions {
    fn default() -> Self {
        DensityOptions {
            table_panels_per_unit: table::DEFAULT_CURVE_PANELS_PER_UNIT,
            tolerance: DEFAULT_TOLERANCE,
            panels_per_decade: DEFAULT_PANELS_PER_DECADE,
            breaks: Vec::new(),
            rule_tolerance: DEFAULT_RULE_TOLERANCE,
        }
    }
}

/// One quadrature node in ζ: the rule's coefficients (weight × ζ × half
/// the panel width, Kronrod and Gauss), −A′/A0, the volume rate (−A′/A0)·u1
/// with its error, u1 and h.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Node {
    kronrod: f64,
    gauss: f64,
    loss: f64,
    volume: f64,
    volume_error: f64,
    u1: f64,
    h: f64,
}

impl Node {
    /// (−A′/A0)(E|X| − u1): the fold's addition to the first moment.
    fn fold(&self) -> f64 {
        if self.loss == 0.0 || !self.u1.is_finite() || self.u1 > WINDOW * self.h {
            0.0
        } else {
            self.loss * (folded_mean(self.u1, self.h) - self.u1)
        }
    }
}

/// One point of a tabulated P(u).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct DensityPoint {
    /// Interfacial separation u, m.
    pub separation: f64,
    /// P_nc(u), the continuous part of P(u), 1/m.
    pub separation_density: f64,
    /// Bound on the absolute error of `separation_density`, 1/m.
    pub separation_density_error_bound: f64,
}

/// P(u) at one nominal pressure (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SeparationDensity {
    nominal_pressure: f64,
    contact_fraction: f64,
    mean_separation: Estimate,
    panels: Vec<Panel>,
    /// ∫(−A′/A0) u1 dζ over the ζ-range the panels leave out (the table's
    /// ζ < ζ_lo; 0 for the adaptive route).
    volume_below: Estimate,
    /// Weight of P_nc the panels leave out (the table's erfc(x_lo)).
    weight_left_out: f64,
}

/// The 15 Kronrod nodes of one ζ-panel.
#[derive(Debug, Clone, PartialEq)]
struct Panel {
    start: f64,
    nodes: Vec<Node>,
}

impl Panel {
    /// (Kronrod, Gauss) sums of the integrand f(node) (which includes −A′).
    fn rule(&self, f: impl Fn(&Node) -> f64) -> (f64, f64) {
        let (mut k, mut g) = (0.0, 0.0);
        for n in &self.nodes {
            let v = f(n);
            k += n.kronrod * v;
            g += n.gauss * v;
        }
        (k, g)
    }
}

/// Narrowest ζ-panel, in ln ζ (the resolution of
/// [`magnified::ADAPTIVE_RESOLUTION`]).
const MIN_PANEL: f64 = 1e-9;

/// Most ζ-panels of one P(u).
const MAX_PANELS: usize = 4_000;

/// Refinement rounds of the u1 stage.
const MAX_ROUNDS: usize = 12;

/// The (Kronrod, Gauss) integrals of −A′ζ over one panel in s = ln ζ.
fn weight_rule(m: &Magnified<'_>, s0: f64, s1: f64, zeta_max: f64) -> Result<(f64, f64)> {
    let half = 0.5 * (s1 - s0);
    let mid = 0.5 * (s1 + s0);
    let (mut k, mut g) = (0.0, 0.0);
    for (j, &x) in XGK.iter().enumerate() {
        let signs: &[f64] = if x == 0.0 { &[1.0] } else { &[-1.0, 1.0] };
        for &sign in signs {
            let zeta = (mid + sign * half * x).exp().clamp(1.0, zeta_max);
            let w = m.area(zeta)?.1 * zeta * half;
            k += WGK[j] * w;
            if j % 2 == 1 {
                g += WG[j / 2] * w;
            }
        }
    }
    Ok((k, g))
}

/// u1, h and the weights at the 15 Kronrod nodes of one panel.
fn panel_nodes(m: &Magnified<'_>, s0: f64, s1: f64, zeta_max: f64) -> Result<Panel> {
    let half = 0.5 * (s1 - s0);
    let mid = 0.5 * (s1 + s0);
    let mut nodes = Vec::with_capacity(15);
    for (j, &x) in XGK.iter().enumerate() {
        let signs: &[f64] = if x == 0.0 { &[1.0] } else { &[-1.0, 1.0] };
        for &sign in signs {
            let zeta = (mid + sign * half * x).exp().clamp(1.0, zeta_max);
            let gauss = if j % 2 == 1 { WG[j / 2] } else { 0.0 };
            let pt = m.point(zeta)?;
            nodes.push(Node {
                kronrod: WGK[j] * zeta * half,
                gauss: gauss * zeta * half,
                loss: pt.area_loss_rate,
                volume: pt.volume_rate.value,
                volume_error: pt.volume_rate.error,
                u1: pt.critical_separation.value,
                h: pt.rms_height,
            });
        }
    }
    Ok(Panel { start: s0, nodes })
}

impl SeparationDensity {
    /// Build P(u) for `spectrum`, E* = `contact_modulus` and σ0 = `pressure`.
    ///
    /// # Errors
    /// E*, σ0 not finite and positive; bad options (`tolerance`,
    /// `panels_per_decade` = 0); quadrature failures; σ0 so low against E*
    /// that the contact is lost closer to ζ = 1 than the routes resolve
    /// ([`Error::InvalidParameter`] naming `nominal_pressure`, or
    /// `contact_modulus` when E* is beyond 1e±30;
    /// bound: σ0 ≥ 6.5 E* √(π ∫q³C dq over [q_l, q_l(1 + 1e-9)])).
    ///
    /// # Examples
    /// ```
    /// use persson::gap::{DensityOptions, SeparationDensity};
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// # fn main() -> persson::Result<()> {
    /// let s = SelfAffine::new(1e4, 4e4, 1e6, 0.8, Amplitude::RmsSlope(0.5))?;
    /// let p = SeparationDensity::new(&s, 1e9, 1e7, &DensityOptions::default())?;
    /// // normalised: the contact's δ weight plus the continuous part
    /// let norm = p.contact_fraction() + p.non_contact_fraction().value;
    /// assert!((norm - 1.0).abs() < 1e-9);
    /// # Ok(()) }
    /// ```
    pub fn new(
        spectrum: &dyn Spectrum,
        contact_modulus: f64,
        pressure: f64,
        options: &DensityOptions,
    ) -> Result<Self> {
        check::tolerance("rule_tolerance", options.rule_tolerance)?;
        if options.panels_per_decade == 0 {
            return Err(Error::invalid("panels_per_decade", 0.0, ">= 1"));
        }
        let m = Magnified::new(
            spectrum,
            contact_modulus,
            pressure,
            options.tolerance,
            &options.breaks,
        )?;
        magnified::check_resolved(
            spectrum,
            contact_modulus,
            pressure,
            table::X_LOW,
            magnified::ADAPTIVE_RESOLUTION,
        )?;
        let zeta_max = m.zeta_max();
        let (a1, _) = m.area(zeta_max)?;
        let mean = Separation::new(spectrum, contact_modulus)?
            .with_tolerance(options.tolerance)?
            .with_breaks(&options.breaks)
            .mean_separation(pressure)?;
        let tol = options.rule_tolerance;
        // Stage 1: resolve the weight −A′ζ (closed form, cheap) on the panels.
        let mut work = panels(spectrum, zeta_max, options)?;
        let mut fine = Vec::new();
        while let Some((s0, s1)) = work.pop() {
            let (k, g) = weight_rule(&m, s0, s1, zeta_max)?;
            if (k - g).abs() > tol && s1 - s0 > MIN_PANEL && fine.len() + work.len() < MAX_PANELS {
                let mid = 0.5 * (s0 + s1);
                work.push((s0, mid));
                work.push((mid, s1));
            } else {
                fine.push((s0, s1));
            }
        }
        fine.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Stage 2: u1 at the nodes; split panels whose ∫ (−A′) u1 is not resolved.
        let scale = mean.value.abs().max(f64::MIN_POSITIVE);
        let mut done: Vec<Panel> = Vec::new();
        let mut todo: Vec<(f64, f64)> = fine;
        for _round in 0..MAX_ROUNDS {
            let mut next = Vec::new();
            for (s0, s1) in todo.drain(..) {
                let panel = panel_nodes(&m, s0, s1, zeta_max)?;
                let (k, g) = panel.rule(|n| n.volume);
                if (k - g).abs() > tol * scale
                    && s1 - s0 > MIN_PANEL
                    && done.len() + next.len() < MAX_PANELS
                {
                    let mid = 0.5 * (s0 + s1);
                    next.push((s0, mid));
                    next.push((mid, s1));
                } else {
                    done.push(panel);
                }
            }
            if next.is_empty() {
                break;
            }
            todo = next;
        }
        for (s0, s1) in todo {
            done.push(panel_nodes(&m, s0, s1, zeta_max)?);
        }
        done.sort_by(|a, b| a.start.total_cmp(&b.start));
        Ok(SeparationDensity {
            nominal_pressure: pressure,
            contact_fraction: a1,
            mean_separation: mean,
            panels: done,
            volume_below: Estimate {
                value: 0.0,
                error: 0.0,
            },
            weight_left_out: 0.0,
        })
    }

    /// σ0.
    pub(crate) fn nominal_pressure(&self) -> f64 {
        self.nominal_pressure
    }

    /// A(ζ1)/A0: the weight of δ(u), the contact at full magnification.
    pub fn contact_fraction(&self) -> f64 {
        self.contact_fraction
    }

    /// ū of [`crate::separation`] at σ0 (the telescoped first moment).
    pub fn mean_separation(&self) -> Estimate {
        self.mean_separation
    }

    /// ∫ P_nc du (= 1 − A(ζ1)/A0 up to the ζ-rule's error).
    pub fn non_contact_fraction(&self) -> Estimate {
        let mut e = self.sum(|n| n.loss, |_| 0.0);
        e.error += self.weight_left_out;
        e
    }

    /// ∫ f dζ by the ζ-rule, with the Gauss–Kronrod differences and the
    /// propagated node errors `err(node)` as the error.
    fn sum(&self, f: impl Fn(&Node) -> f64, err: impl Fn(&Node) -> f64) -> Estimate {
        let (mut total, mut e) = (0.0, 0.0);
        for panel in &self.panels {
            let (k, g) = panel.rule(&f);
            total += k;
            e += (k - g).abs() + panel.rule(&err).0.abs();
        }
        Estimate {
            value: total,
            error: e + 16.0 * f64::EPSILON * total.abs(),
        }
    }

    /// P_nc(u), 1/m, for u ≥ 0 (0 for u < 0).
    pub fn density(&self, separation: f64) -> Estimate {
        if separation.is_nan() || separation < 0.0 {
            return Estimate {
                value: 0.0,
                error: 0.0,
            };
        }
        let u = separation;
        // |∂φ_fold/∂u1| ≤ 2·max|φ′| = 2/(√(2π e) h²).
        let slope = 2.0 / (std::f64::consts::TAU * std::f64::consts::E).sqrt();
        self.sum(
            |n| n.loss * folded(u, n.u1, n.h),
            |n| {
                if n.h > 0.0 {
                    n.volume_error * slope / (n.h * n.h)
                } else {
                    0.0
                }
            },
        )
    }

    /// P_nc at each separation (m), for tables and plots.
    pub fn curve(&self, separations: &[f64]) -> Vec<DensityPoint> {
        separations
            .iter()
            .map(|&u| {
                let d = self.density(u);
                DensityPoint {
                    separation: u,
                    separation_density: d.value,
                    separation_density_error_bound: d.error,
                }
            })
            .collect()
    }

    /// ∫₀^∞ u P(u) du, m (the contact contributes 0): the unfolded
    /// moment plus the fold's shift.
    pub fn first_moment(&self) -> Estimate {
        let a = self.unfolded_first_moment();
        let b = self.fold_shift();
        Estimate {
            value: a.value + b.value,
            error: a.error + b.error,
        }
    }

    /// ∫ (−A′/A0) u1 dζ, the first moment without the fold: equals ū
    /// (module docs of [`magnified`]).
    pub fn unfolded_first_moment(&self) -> Estimate {
        let mut e = self.sum(|n| n.volume, |n| n.volume_error);
        e.value += self.volume_below.value;
        e.error += self.volume_below.error;
        e
    }

    /// ∫ u P du − ∫ (−A′/A0) u1 dζ = Σ (−A′)(E|X| − u1) ≥ 0: what the fold
    /// at u = 0 adds to the mean separation, m.
    pub fn fold_shift(&self) -> Estimate {
        self.sum(Node::fold, |n| n.volume_error)
    }

    /// The largest separation any node's window reaches, max(u1 + 10h), m,
    /// over the nodes whose weight is above 1e−18 (near ζ = 1, u1 grows
    /// without bound while −A′ vanishes faster).
    pub fn largest_separation(&self) -> f64 {
        self.panels
            .iter()
            .flat_map(|p| p.nodes.iter())
            .filter(|n| n.kronrod * n.loss > NEGLIGIBLE_WEIGHT && n.u1.is_finite())
            .map(|n| n.u1 + WINDOW * n.h)
            .fold(0.0, f64::max)
    }

    /// ∫ P_nc(u) f(u) du for f bounded on the window of every node: each
    /// node's folded Gaussian by adaptive Gauss–Kronrod (absolute tolerance
    /// `tolerance` × max|f| on the window), then the ζ-rule. `lipschitz`
    /// bounds |f′| (used to propagate u1's error; pass 0 when unknown).
    ///
    /// # Errors
    /// `f` not finite on a window; quadrature failures.
    pub fn expectation(
        &self,
        f: &dyn Fn(f64) -> f64,
        tolerance: f64,
        lipschitz: f64,
    ) -> Result<Estimate> {
        check::tolerance("tolerance", tolerance)?;
        let (mut total, mut e) = (0.0, 0.0);
        for panel in &self.panels {
            let (mut k, mut g) = (0.0, 0.0);
            for n in &panel.nodes {
                if n.loss == 0.0 || !n.u1.is_finite() {
                    continue;
                }
                let v = node_expectation(f, n.u1, n.h, tolerance)?;
                k += n.kronrod * n.loss * v.value;
                g += n.gauss * n.loss * v.value;
                e += n.kronrod * (n.loss * v.error + lipschitz * n.volume_error);
            }
            total += k;
            e += (k - g).abs();
        }
        Ok(Estimate {
            value: total,
            error: e + 16.0 * f64::EPSILON * total.abs(),
        })
    }
}

/// E f(|X|), X ~ N(u1, h²), by adaptive quadrature over the window.
fn node_expectation(f: &dyn Fn(f64) -> f64, u1: f64, h: f64, tolerance: f64) -> Result<Estimate> {
    if h <= 0.0 {
        return Ok(Estimate {
            value: f(u1.abs()),
            error: 0.0,
        });
    }
    if WINDOW * h <= NARROW * u1 {
        // The Gaussian is narrower than quadrature can resolve at u1: a point
        // mass, with the variation of f over ±3h as the error.
        let v = f(u1);
        let spread = (f(u1 + 3.0 * h) - v).abs().max((f(u1 - 3.0 * h) - v).abs());
        return Ok(Estimate {
            value: v,
            error: spread,
        });
    }
    let lo = (u1 - WINDOW * h).max(0.0);
    let hi = u1 + WINDOW * h;
    let g = |u: f64| f(u) * folded(u, u1, h);
    // Split at the peak so each half is one-signed in slope.
    let mid = u1.clamp(lo, hi);
    let mut total = Estimate {
        value: 0.0,
        error: 0.0,
    };
    for (a, b) in [(lo, mid), (mid, hi)] {
        if b > a {
            let r = integrate("P(u) expectation", g, a, b, tolerance, tolerance, 100_000)?;
            total.value += r.value;
            total.error += r.error;
        }
    }
    Ok(total)
}

/// The folded normal density φ_h(u − u1) + φ_h(u + u1) at u ≥ 0.
fn folded(u: f64, u1: f64, h: f64) -> f64 {
    if h <= 0.0 {
        return 0.0;
    }
    let c = 1.0 / ((std::f64::consts::TAU).sqrt() * h);
    let (a, b) = ((u - u1) / h, (u + u1) / h);
    c * ((-0.5 * a * a).exp() + (-0.5 * b * b).exp())
}

/// E|X| for X ~ N(u1, h²): u1 erf(u1/(√2 h)) + h √(2/π) e^{−u1²/(2h²)}.
fn folded_mean(u1: f64, h: f64) -> f64 {
    if h <= 0.0 {
        return u1.abs();
    }
    let t = u1 / (std::f64::consts::SQRT_2 * h);
    u1 * crate::special::erf(t) + h * (2.0 / std::f64::consts::PI).sqrt() * (-t * t).exp()
}

/// Panels in s = ln ζ over [0, ln ζ1], split at the break points.
fn panels(
    spectrum: &dyn Spectrum,
    zeta_max: f64,
    options: &DensityOptions,
) -> Result<Vec<(f64, f64)>> {
    let q_l = spectrum.q_min();
    let s_max = zeta_max.ln();
    let mut ends = vec![0.0, s_max];
    for &b in &options.breaks {
        if b.is_finite() && b > q_l && b < spectrum.q_max() {
            ends.push((b / q_l).ln());
        }
    }
    ends.sort_by(f64::total_cmp);
    ends.dedup();
    let per_unit = options.panels_per_decade as f64 / std::f64::consts::LN_10;
    let mut out = Vec::new();
    for pair in ends.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let n = ((b - a) * per_unit).ceil().max(1.0) as usize;
        for i in 0..n {
            out.push((
                a + (b - a) * i as f64 / n as f64,
                a + (b - a) * (i + 1) as f64 / n as f64,
            ));
        }
    }
    Ok(out)
}

//! P(u) at many loads from one load-independent table: the fast route of
//! the load curves (effective medium, gap conductance).
//!
//! # Formula
//! The ζ-integral of [`super::SeparationDensity`] in s = ln m3(ζ),
//! m3(ζ) = ∫_{q_l}^{ζ q_l} q³ C dq, where the weight is the same bump for
//! every load, only shifted by ln g:
//! ```text
//! G = g m3 = g e^s,  g = (π/4)(E*/σ0)²,  x = 1/(2√G):   −dA/A0 = x e^{−x²}/√π ds
//! ```
//! The q-integrals of u1(ζ) ([`super::magnified`]: F, p/K, ∂F/∂ζ) depend on
//! the load only through p(ζ) = σ0/A(ζ) inside E1((w p/E*)²) and e^{−(w p/E*)²};
//! the wavevector nodes, C(q) and w_ζ(q) at them are load-independent.
//!
//! # Method
//! Fixed composite G7/K15 rules, built once: in s over [s_lo, ln m3(q_s/q_l)]
//! (split at the breaks, `zeta_panels_per_unit` panels per unit of s), and
//! for each ζ-node in v = √(ln(q/(ζq_l))) (v = t² on the first segment, as
//! [`super::magnified`]) with `q_panels` panels per segment between breaks.
//! s_lo is set by the lowest load: there x = 6.5, so the weight below it,
//! erfc(6.5) < 4e−20, is left out (and added to the error bounds); a higher
//! load likewise skips the panels lying wholly below its own x = 6.5. A load
//! then costs one sum over the stored nodes of the panels it keeps
//! (module `gap::band`: E1 and e^{−x²} at the nodes with x ≥ 1, stored power
//! series for the rest): no adaptive integral, no root of m3. The bounds are
//! the summed |Kronrod − Gauss| of both rules, as in the adaptive route; the
//! tests check the table against [`super::SeparationDensity::new`]
//! (adaptive, 1e-9).
//!
//! The first moment below the first panel kept telescopes: ∫_1^{ζ_b}
//! (−(Aū)′) dζ = ū(σ0) − A(ζ_b) ū(ζ_b), from the full band (ζ = 1, with
//! 8× the q-panels; it also gives the stiffness,
//! [`SeparationTable::stiffness`]) and a band stored at each panel's start.

use super::band::{Band, QNode};
use super::{Node, Panel, SeparationDensity, WG, WGK, XGK};
use crate::error::{check, Error, Result};
use crate::quad::Estimate;
use crate::special::{erf, erfc};
use crate::spectrum::Spectrum;

/// x = 1/(2√G) at the table's lowest s for its lowest load.
pub(crate) const X_LOW: f64 = 6.5;

/// Default ζ-panels per unit of s = ln m3.
const DEFAULT_ZETA_PANELS_PER_UNIT: f64 = 0.5;

/// Default ζ-panels per unit of s of the load curves' table
/// ([`crate::gap::DensityOptions::table_panels_per_unit`]): their error is
/// set by the fixed u-rule of [`crate::gap::PointSet`] (measured 2.4e-5
/// against the adaptive route with 0.5 panels per unit, 2.7e-5 with 0.35,
/// 4.3e-5 with 0.25; `examples/flow_accuracy.rs`), so the coarser ζ-rule
/// costs no accuracy and a third of the time.
pub const DEFAULT_CURVE_PANELS_PER_UNIT: f64 = 0.35;

/// The full band's (ζ = 1: ū(σ0) and the stiffness) q-panels, per q-panel
/// of the other bands.
const FULL_BAND_PANELS: usize = 8;

/// Default q-panels per segment of a ζ-node's band.
const DEFAULT_Q_PANELS: usize = 2;

/// Accuracy knobs of [`SeparationTable`].
#[derive(Debug, Clone, PartialEq)]
pub struct TableOptions {
    /// G7/K15 panels per unit of s = ln m3(ζ), > 0 (finite).
    pub zeta_panels_per_unit: f64,
    /// G7/K15 panels per segment (between breaks) of each band's q-rule, ≥ 1.
    pub q_panels: usize,
    /// Wavevectors (1/m) where C(q) has a kink (the roll-off q_r): panel ends.
    pub breaks: Vec<f64>,
}

impl Default for TableOptions {
    fn default() -> Self {
        TableOptions {
            zeta_panels_per_unit: DEFAULT_ZETA_PANELS_PER_UNIT,
            q_panels: DEFAULT_Q_PANELS,
            breaks: Vec::new(),
        }
    }
}

/// One ζ-node: its s-rule coefficients (× dζ/ds), m3, dm3/dζ, h and the band's q-rule.
#[derive(Debug, Clone)]
struct ZetaNode {
    kronrod: f64,
    gauss: f64,
    m3: f64,
    dm3: f64,
    h: f64,
    band: Band,
}

/// One ζ-panel: its ends in s, the band at its start (for the telescoped
/// first moment of the panels a load leaves out) and its 15 nodes.
#[derive(Debug, Clone)]
struct ZetaPanel {
    start: f64,
    end: f64,
    edge: ZetaNode,
    nodes: Vec<ZetaNode>,
}

/// The load-independent part of P(u) for one spectrum and E* (module docs).
#[derive(Debug, Clone)]
pub struct SeparationTable {
    contact_modulus: f64,
    lowest_pressure: f64,
    m3_total: f64,
    /// ζ-panels of 15 nodes each, by increasing s.
    panels: Vec<ZetaPanel>,
    /// The full band (ζ = 1) for ū(σ0).
    full: ZetaNode,
}

/// ζ with m3(ζ) = target by safeguarded Newton in ln ζ (to 1e-14 relative).
fn zeta_of_m3(spectrum: &dyn Spectrum, target: f64) -> Result<f64> {
    let q_l = spectrum.q_min();
    let (mut lo, mut hi) = (0.0f64, (spectrum.q_max() / q_l).ln());
    let mut s = 0.5 * (lo + hi);
    for _ in 0..200 {
        let q = q_l * s.exp();
        let f = spectrum.moment(3, q_l, q)?.value - target;
        if f > 0.0 {
            hi = s;
        } else {
            lo = s;
        }
        let slope = q * q * q * q * spectrum.c(q);
        let newton = s - f / slope;
        s = if slope > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (hi - lo) <= 1e-14 * hi.max(1.0) || f == 0.0 {
            break;
        }
    }
    Ok(s.exp())
}

/// The (node, Kronrod weight, Gauss weight) triples of composite G7/K15 on
/// `[a, b]` with `n` panels.
fn gk_nodes(a: f64, b: f64, n: usize) -> Vec<(f64, f64, f64)> {
    let mut out = Vec::with_capacity(15 * n);
    let width = (b - a) / n as f64;
    for i in 0..n {
        let lo = a + width * i as f64;
        let (half, mid) = (0.5 * width, lo + 0.5 * width);
        for (j, &x) in XGK.iter().enumerate() {
            let gauss = if j % 2 == 1 { WG[j / 2] } else { 0.0 };
            let signs: &[f64] = if x == 0.0 { &[1.0] } else { &[-1.0, 1.0] };
            for &sign in signs {
                out.push((mid + sign * half * x, WGK[j] * half, gauss * half));
            }
        }
    }
    out
}

/// The q-rule of the band [lo, q_s] (module docs; the substitution of
/// [`super::magnified`]).
fn band_rule(spectrum: &dyn Spectrum, lo: f64, breaks: &[f64], n: usize) -> Result<Band> {
    let q_s = spectrum.q_max();
    if lo >= q_s * (1.0 - 1e-12) {
        return Ok(Band::default());
    }
    let mut knots = vec![0.0, (q_s / lo).ln().sqrt()];
    for &b in breaks {
        if b.is_finite() && b > lo && b < q_s {
            knots.push((b / lo).ln().sqrt());
        }
    }
    knots.sort_by(f64::total_cmp);
    knots.dedup();
    let root_pi = std::f64::consts::PI.sqrt();
    let mut out = Vec::new();
    for (i, pair) in knots.windows(2).enumerate() {
        let first = i == 0;
        let (a, b) = if first {
            (pair[0].sqrt(), pair[1].sqrt())
        } else {
            (pair[0], pair[1])
        };
        for (y, wk, wg) in gk_nodes(a, b, n) {
            // v = y (or y², dv = 2y dy on the first segment)
            let (v, jac_v) = if first { (y * y, 2.0 * y) } else { (y, 1.0) };
            let delta = lo * (v * v).exp_m1();
            let q = lo + delta;
            let m3 = spectrum.moment(3, lo, q)?.value;
            let c = spectrum.c(q);
            if m3.is_nan() || m3 <= 0.0 || c == 0.0 {
                continue;
            }
            let w = 1.0 / (std::f64::consts::PI * m3).sqrt();
            let f = root_pi * q * q * c * 2.0 * v * q * jac_v;
            out.push(QNode {
                kronrod: wk * f,
                gauss: wg * f,
                w,
            });
        }
    }
    Ok(Band::new(out))
}

impl SeparationTable {
    /// The table for `spectrum` and E* = `contact_modulus`, valid for every
    /// nominal pressure ≥ `lowest_pressure`.
    ///
    /// # Errors
    /// E* or `lowest_pressure` not finite and positive; `zeta_panels_per_unit`
    /// not finite and positive, or above 100; `q_panels` 0 or above 100;
    /// E*/σ0 so large at the lowest pressure that G = (E*/σ0)²⟨|∇h|²⟩/8
    /// overflows f64, or that the contact is lost closer to ζ = 1 than the
    /// routes resolve (σ0 ≥ 6.5 E* √(π ∫q³C dq over [q_l, q_l(1 + 5e-13)]);
    /// [`Error::InvalidParameter`] naming `nominal_pressure` or
    /// `contact_modulus`, E* when it is beyond 1e±30).
    ///
    /// # Examples
    /// ```
    /// use persson::gap::{SeparationTable, TableOptions};
    /// use persson::spectrum::{Amplitude, SelfAffine};
    /// # fn main() -> persson::Result<()> {
    /// let s = SelfAffine::new(1e4, 4e4, 1e6, 0.8, Amplitude::RmsSlope(0.5))?;
    /// let table = SeparationTable::new(&s, 1e9, 1e6, &TableOptions::default())?;
    /// let p = table.density(1e7)?;
    /// let norm = p.contact_fraction() + p.non_contact_fraction().value;
    /// assert!((norm - 1.0).abs() < 1e-6);
    /// # Ok(()) }
    /// ```
    pub fn new(
        spectrum: &dyn Spectrum,
        contact_modulus: f64,
        lowest_pressure: f64,
        options: &TableOptions,
    ) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        check::positive("nominal_pressure", lowest_pressure)?;
        let per_unit = check::positive("zeta_panels_per_unit", options.zeta_panels_per_unit)?;
        if per_unit > 100.0 {
            return Err(Error::invalid(
                "zeta_panels_per_unit",
                per_unit,
                "in (0, 100]",
            ));
        }
        if options.q_panels == 0 || options.q_panels > 100 {
            return Err(Error::invalid(
                "q_panels",
                options.q_panels as f64,
                "an integer in [1, 100]",
            ));
        }
        let q_l = spectrum.q_min();
        let q_s = spectrum.q_max();
        let m3_total = spectrum.moment(3, q_l, q_s)?.value;
        if m3_total.is_nan() || m3_total <= 0.0 {
            return Err(Error::invalid(
                "spectrum",
                m3_total,
                "a positive slope moment ∫q³C dq",
            ));
        }
        // g_max = (π/4)(E*/σ0)² and G = g_max m3 finite (the bound of
        // `theory::check_g_finite`): else s_lo = ln(1/(4 X_LOW² g_max)) is
        // −∞ and the panels between it and s_hi never end.
        crate::theory::check_g_finite(
            contact_modulus,
            lowest_pressure,
            std::f64::consts::TAU * m3_total,
        )?;
        super::magnified::check_resolved(
            spectrum,
            contact_modulus,
            lowest_pressure,
            X_LOW,
            super::magnified::TABLE_RESOLUTION,
        )?;
        let r = contact_modulus / lowest_pressure;
        let g_max = 0.25 * std::f64::consts::PI * r * r;
        let s_hi = m3_total.ln();
        let s_lo = (0.25 / (X_LOW * X_LOW * g_max)).ln().min(s_hi);
        let node = |zeta: f64, kronrod: f64, gauss: f64, q_panels: usize| -> Result<ZetaNode> {
            let lo = zeta * q_l;
            let m3 = spectrum.moment(3, q_l, lo)?.value;
            let dm3 = q_l * lo * lo * lo * spectrum.c(lo);
            let h2 = std::f64::consts::TAU * spectrum.moment(1, lo, q_s)?.value;
            Ok(ZetaNode {
                kronrod,
                gauss,
                m3,
                dm3,
                h: h2.max(0.0).sqrt(),
                band: band_rule(spectrum, lo, &options.breaks, q_panels)?,
            })
        };
        // s-panels split at the breaks
        let mut ends = vec![s_lo, s_hi];
        for &b in &options.breaks {
            if b.is_finite() && b > q_l && b < q_s {
                let s = spectrum.moment(3, q_l, b)?.value.ln();
                if s > s_lo && s < s_hi {
                    ends.push(s);
                }
            }
        }
        ends.sort_by(f64::total_cmp);
        ends.dedup();
        let mut panels = Vec::new();
        for pair in ends.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let n = ((b - a) * per_unit).ceil().max(1.0) as usize;
            let width = (b - a) / n as f64;
            for i in 0..n {
                let start = a + width * i as f64;
                let end = if i + 1 == n { b } else { start + width };
                let mut nodes = Vec::with_capacity(15);
                for (s, wk, wg) in gk_nodes(start, start + width, 1) {
                    let zeta = zeta_of_m3(spectrum, s.exp())?;
                    let mut n = node(zeta, wk, wg, options.q_panels)?;
                    // dζ/ds = m3/(dm3/dζ): the ζ-weights of Node
                    let jac = if n.dm3 > 0.0 { n.m3 / n.dm3 } else { 0.0 };
                    n.kronrod *= jac;
                    n.gauss *= jac;
                    nodes.push(n);
                }
                let edge = node(
                    zeta_of_m3(spectrum, start.exp())?,
                    0.0,
                    0.0,
                    options.q_panels,
                )?;
                panels.push(ZetaPanel {
                    start,
                    end,
                    edge,
                    nodes,
                });
            }
        }
        // one band, summed once a load: a finer rule for ū(σ0) and K
        let full = node(1.0, 0.0, 0.0, FULL_BAND_PANELS * options.q_panels)?;
        Ok(SeparationTable {
            contact_modulus,
            lowest_pressure,
            m3_total,
            panels,
            full,
        })
    }

    /// The contact stiffness K = −dσ0/dū at σ0 = `pressure`, Pa/m, from
    /// the full band (formula of [`crate::separation::Separation::stiffness`]:
    /// K = σ0 / (√π ∫ q² C w e^{−(w σ0/E*)²} dq)); `+∞` (error 0) where
    /// the integral underflows, deep in full contact.
    ///
    /// # Errors
    /// σ0 not finite and positive.
    pub fn stiffness(&self, pressure: f64) -> Result<Estimate> {
        check::positive("nominal_pressure", pressure)?;
        let (k, e) = self.full.band.sums(pressure / self.contact_modulus);
        if k[1] <= 0.0 {
            return Ok(Estimate {
                value: f64::INFINITY,
                error: 0.0,
            });
        }
        let value = pressure / k[1];
        Ok(Estimate {
            value,
            error: value * (e[1] / k[1] + 4.0 * f64::EPSILON),
        })
    }

    /// Number of ζ-nodes (15 per panel).
    pub fn zeta_nodes(&self) -> usize {
        15 * self.panels.len()
    }

    /// u1 and the volume rate at one node for load factor g and σ0:
    /// (A, −A′, ū, error of ū, u1, volume, volume error).
    fn magnified(&self, n: &ZetaNode, g: f64, pressure: f64) -> [f64; 7] {
        let big_g = g * n.m3;
        let (a, loss) = if big_g <= 0.0 {
            (1.0, 0.0)
        } else {
            let x = 0.5 / big_g.sqrt();
            let loss = x * (-x * x).exp() * g * n.dm3 / (std::f64::consts::PI.sqrt() * big_g);
            (erf(x), loss)
        };
        let p = pressure / a;
        let (k, e) = n.band.sums(p / self.contact_modulus);
        let half_pi_dm = 0.5 * std::f64::consts::PI * n.dm3;
        let (u, u_err) = (k[0], e[0]);
        let (compliance, c_err) = (k[1] / p, e[1] / p);
        let (dz, dz_err) = (half_pi_dm * k[2], half_pi_dm * e[2]);
        let dp = pressure * loss / (a * a);
        let du = dz - dp * compliance;
        let du_err = dz_err + dp * c_err;
        let vol = loss * u - du * a;
        let vol_err = loss * u_err + a * du_err + 8.0 * f64::EPSILON * (loss * u + (du * a).abs());
        let u1 = if loss > 0.0 {
            (u - du * a / loss).max(0.0)
        } else if du < 0.0 {
            f64::INFINITY
        } else {
            u
        };
        [a, loss, u, u_err, u1, vol.max(0.0), vol_err]
    }

    /// P(u) at σ0 = `pressure` from the table.
    ///
    /// # Errors
    /// σ0 not finite, or below the table's lowest pressure.
    pub fn density(&self, pressure: f64) -> Result<SeparationDensity> {
        check::positive("nominal_pressure", pressure)?;
        if pressure < self.lowest_pressure * (1.0 - 1e-12) {
            return Err(Error::invalid(
                "nominal_pressure",
                pressure,
                format!(
                    "at least the table's lowest pressure {}",
                    crate::error::num(self.lowest_pressure)
                ),
            ));
        }
        let r = self.contact_modulus / pressure;
        let g = 0.25 * std::f64::consts::PI * r * r;
        // panels wholly below s_cut, where x > X_LOW, carry a weight below
        // erfc(6.5) at this load: left out, their first moment telescoped
        let s_cut = (0.25 / (X_LOW * X_LOW * g)).ln();
        let first = self
            .panels
            .iter()
            .position(|p| p.end > s_cut)
            .unwrap_or(self.panels.len().saturating_sub(1));
        let kept = self.panels.get(first..).unwrap_or_default();
        let panels = kept
            .iter()
            .map(|panel| Panel {
                start: panel.start,
                nodes: panel
                    .nodes
                    .iter()
                    .map(|n| {
                        let [_, loss, _, _, u1, volume, volume_error] =
                            self.magnified(n, g, pressure);
                        Node {
                            kronrod: n.kronrod,
                            gauss: n.gauss,
                            loss,
                            volume,
                            volume_error,
                            u1,
                            h: n.h,
                        }
                    })
                    .collect(),
            })
            .collect();
        let x1 = 0.5 / (g * self.m3_total).sqrt();
        let (k, e) = self.full.band.sums(pressure / self.contact_modulus);
        let mean = Estimate {
            value: k[0],
            error: e[0],
        };
        // the telescoped first moment below the first panel kept:
        // ū(σ0) − A(ζ_b) ū(ζ_b), and the weight left out there, erfc(x_b)
        let (below, missing) = match kept.first() {
            Some(panel) => {
                let edge = self.magnified(&panel.edge, g, pressure);
                let x_b = 0.5 / (g * panel.edge.m3).sqrt();
                (
                    Estimate {
                        value: (mean.value - edge[0] * edge[2]).max(0.0),
                        error: mean.error + edge[0] * edge[3] + 8.0 * f64::EPSILON * mean.value,
                    },
                    if panel.edge.m3 > 0.0 { erfc(x_b) } else { 0.0 },
                )
            }
            None => (mean, 0.0),
        };
        Ok(SeparationDensity {
            nominal_pressure: pressure,
            contact_fraction: erf(x1),
            mean_separation: mean,
            panels,
            volume_below: below,
            weight_left_out: missing,
        })
    }
}

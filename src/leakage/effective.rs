//! The effective-medium (2-D Bruggeman) leak rate (module docs of
//! [`crate::leakage`]).

use serde::Serialize;

use super::{LeakStatus, Seal};
use crate::error::{check, Error, Result};
use crate::gap::{DensityOptions, PointSet, SeparationDensity, SeparationTable};
use crate::quad::Estimate;
use crate::spectrum::Spectrum;

/// Absolute tolerance of each node's u-integral of the Bruggeman residual
/// at the root (the residual is a mean of values in [−1, 1]).
const NODE_TOLERANCE: f64 = 1e-11;

/// Newton steps on the adaptive residual after the point rule's root.
const POLISH_STEPS: usize = 4;

/// Relative width of the final bracket of σ_eff.
const ROOT_TOLERANCE: f64 = 1e-13;

/// The 2-D Bruggeman conductivity of a discrete mixture.
///
/// # Formula
/// ```text
/// Σ_i f_i (σ_i − σ_eff)/(σ_i + σ_eff) = 0,   Σ f_i = 1
/// two phases, a at σ = 0 and 1 − a at σ1:  σ_eff = σ1 (1 − 2a)  (a < ½), else 0
/// ```
/// The residual decreases monotonically in σ_eff; the root is bracketed in
/// ln σ_eff and found by the Illinois variant of false position to
/// `ROOT_TOLERANCE` (1e-13) relative. A mixture whose conducting fraction is
/// at most ½ has σ_eff = 0 (below the 2-D threshold).
///
/// # Errors
/// A fraction or conductivity negative or not finite; fractions not summing
/// to 1 within 1e-12.
///
/// # References
/// D. A. G. Bruggeman, Ann. Phys. 416, 636 (1935); S. Kirkpatrick, Rev. Mod.
/// Phys. 45, 574 (1973) (the d-dimensional form; d = 2 here).
///
/// # Examples
/// ```
/// // 30 % blocked, 70 % at σ1 = 2: σ_eff = 2 (1 − 0.6) = 0.8
/// let s = persson::leakage::bruggeman(&[(0.3, 0.0), (0.7, 2.0)]).unwrap();
/// assert!((s - 0.8).abs() < 1e-12); // root bracketed to 1e-13 in ln σ
/// ```
pub fn bruggeman(phases: &[(f64, f64)]) -> Result<f64> {
    let mut sum = 0.0;
    let mut top: f64 = 0.0;
    for &(f, s) in phases {
        check::non_negative("fraction", f)?;
        check::non_negative("flow_conductivity", s)?;
        sum += f;
        top = top.max(s);
    }
    if (sum - 1.0).abs() > 1e-12 {
        return Err(Error::invalid("fraction", sum, "fractions summing to 1"));
    }
    let residual = |s: f64| -> Result<Estimate> {
        Ok(Estimate {
            value: phases.iter().map(|&(f, c)| f * (c - s) / (c + s)).sum(),
            error: 0.0,
        })
    };
    Ok(solve(&residual, top, f64::MIN_POSITIVE.sqrt() * top)?.value)
}

/// Root of a decreasing residual r(σ) on (0, hi]: 0 when r(lo) ≤ 0.
/// The error comes from r's error over its slope at the root.
fn solve(r: &dyn Fn(f64) -> Result<Estimate>, hi: f64, lo: f64) -> Result<Estimate> {
    if hi <= 0.0 {
        return Ok(Estimate {
            value: 0.0,
            error: 0.0,
        });
    }
    let (mut a, mut b) = (lo.ln(), hi.ln());
    let (mut fa, mut fb) = (r(lo)?.value, r(hi)?.value);
    if fa <= 0.0 {
        return Ok(Estimate {
            value: 0.0,
            error: 0.0,
        });
    }
    if fb >= 0.0 {
        return Ok(Estimate {
            value: hi,
            error: 0.0,
        });
    }
    let mut side = 0i32;
    let mut last = Estimate {
        value: 0.0,
        error: 0.0,
    };
    for _ in 0..300 {
        let t = (a * fb - b * fa) / (fb - fa);
        let t = if t > a && t < b { t } else { 0.5 * (a + b) };
        last = r(t.exp())?;
        if last.value > 0.0 {
            a = t;
            fa = last.value;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        } else {
            b = t;
            fb = last.value;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        }
        if (b - a) <= ROOT_TOLERANCE || last.value == 0.0 {
            break;
        }
    }
    let t = 0.5 * (a + b);
    let s = t.exp();
    // |dr/d ln σ| from the bracket; the residual's error moves the root by δr/|r′|.
    let slope = ((fa - fb) / (b - a).max(f64::EPSILON))
        .abs()
        .max(f64::MIN_POSITIVE);
    Ok(Estimate {
        value: s,
        error: s * ((b - a) + last.error / slope),
    })
}

/// The effective medium at one nominal pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct EffectiveMediumPoint {
    /// Nominal pressure σ0 (unit of E*).
    pub nominal_pressure: f64,
    /// Whether the seal leaks (sealed: A(ζ1)/A0 ≥ ½, the 2-D Bruggeman threshold).
    pub status: LeakStatus,
    /// A(ζ1)/A0 at full magnification.
    pub contact_fraction: f64,
    /// σ_eff, m³/(Pa s).
    pub effective_flow_conductivity: f64,
    /// Bound on the absolute error of σ_eff.
    pub effective_flow_conductivity_error_bound: f64,
    /// Q = (L_y/L_x) σ_eff Δ, m³/s.
    pub leak_rate: f64,
    /// Bound on the absolute error of Q, m³/s.
    pub leak_rate_error_bound: f64,
}

/// The effective-medium leak rate for one spectrum, E* and seal.
pub struct EffectiveMedium<'a> {
    spectrum: &'a dyn Spectrum,
    contact_modulus: f64,
    seal: Seal,
    options: DensityOptions,
}

impl<'a> EffectiveMedium<'a> {
    /// The model, with P(u) built with `options`.
    ///
    /// # Errors
    /// E* not finite and positive; a bad seal ([`Seal::validate`]).
    pub fn new(
        spectrum: &'a dyn Spectrum,
        contact_modulus: f64,
        seal: Seal,
        options: DensityOptions,
    ) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        seal.validate()?;
        Ok(EffectiveMedium {
            spectrum,
            contact_modulus,
            seal,
            options,
        })
    }

    /// σ_eff and Q at σ0 = `pressure`.
    ///
    /// # Errors
    /// σ0 not finite and positive; quadrature failures.
    pub fn point(&self, pressure: f64) -> Result<EffectiveMediumPoint> {
        let density =
            SeparationDensity::new(self.spectrum, self.contact_modulus, pressure, &self.options)?;
        self.point_from(&density)
    }

    /// [`EffectiveMedium::point_from`], the error bound from the fixed
    /// point rule only (no adaptive check of the residual at the root), the
    /// root's search started at `start` (ln 12ησ_eff of the previous load)
    /// when given: the route of [`EffectiveMedium::load_curve`].
    fn point_fast(
        &self,
        density: &SeparationDensity,
        start: Option<f64>,
    ) -> Result<EffectiveMediumPoint> {
        self.solve_point(density, false, start)
    }

    /// σ_eff and Q from a P(u) already built.
    ///
    /// # Method
    /// P_nc as fixed weighted points ([`PointSet`]), the Bruggeman residual
    /// r(t) = Σ w (u³ − c)/(u³ + c) − A(ζ1)/A0 in t = ln c, c = 12η σ_eff
    /// (decreasing), by Newton's method safeguarded by bisection on the
    /// bracket [ln(1e−60 c_max), ln c_max], c_max = u_max³, to `ROOT_TOLERANCE`
    /// in t. The error of σ_eff: the residual's error at the root (both rules'
    /// |Kronrod − Gauss|, [`PointSet::expectation`]; here the residual is
    /// re-evaluated at the root by the adaptive
    /// [`SeparationDensity::expectation`] to 1e-11) over |dr/dt|, plus the
    /// last step.
    ///
    /// # Errors
    /// Quadrature failures.
    pub fn point_from(&self, density: &SeparationDensity) -> Result<EffectiveMediumPoint> {
        self.solve_point(density, true, None)
    }

    fn solve_point(
        &self,
        density: &SeparationDensity,
        adaptive: bool,
        start: Option<f64>,
    ) -> Result<EffectiveMediumPoint> {
        let eta12 = 12.0 * self.seal.viscosity;
        let a1 = density.contact_fraction();
        let mut out = EffectiveMediumPoint {
            nominal_pressure: density.nominal_pressure(),
            status: LeakStatus::Sealed,
            contact_fraction: a1,
            effective_flow_conductivity: 0.0,
            effective_flow_conductivity_error_bound: 0.0,
            leak_rate: 0.0,
            leak_rate_error_bound: 0.0,
        };
        if a1 >= 0.5 {
            return Ok(out);
        }
        let points = PointSet::new(density);
        let s = bruggeman_points(&points, a1, adaptive.then_some(density), start)?;
        if s.value > 0.0 {
            out.status = LeakStatus::Leaking;
        }
        let (value, error) = (s.value / eta12, s.error / eta12);
        let q = self.seal.leak_rate(value)?;
        out.effective_flow_conductivity = value;
        out.effective_flow_conductivity_error_bound = error;
        out.leak_rate = q;
        out.leak_rate_error_bound = self.seal.leak_rate(error)? + 8.0 * f64::EPSILON * q;
        Ok(out)
    }

    /// σ_eff and Q at each pressure, from one [`SeparationTable`] built for
    /// the lowest of them ([`DensityOptions::table`]: the breaks and
    /// `table_panels_per_unit`, the curve's accuracy knob): the same quantities as [`EffectiveMedium::point`], faster by
    /// the table, with the fixed rules' bounds (tests/leakage.rs checks the
    /// agreement with [`EffectiveMedium::point`]).
    ///
    /// # Errors
    /// As [`EffectiveMedium::point`], for the first bad pressure.
    pub fn load_curve(&self, pressures: &[f64]) -> Result<Vec<EffectiveMediumPoint>> {
        for &p in pressures {
            check::positive("nominal_pressure", p)?;
        }
        let Some(lowest) = pressures.iter().copied().reduce(f64::min) else {
            return Ok(Vec::new());
        };
        let table = SeparationTable::new(
            self.spectrum,
            self.contact_modulus,
            lowest,
            &self.options.table(),
        )?;
        // each root starts from the previous loads' roots, extrapolated
        // linearly in ln σ0 (3 Newton steps a load on a curve of 100 loads,
        // against 4.4 from the previous root and ~9 from ln ⟨u³⟩)
        let eta12 = 12.0 * self.seal.viscosity;
        let mut roots: Vec<(f64, f64)> = Vec::new();
        pressures
            .iter()
            .map(|&p| {
                let s = p.ln();
                let start = match roots.as_slice() {
                    [.., (s0, t0), (s1, t1)] if s1 != s0 => {
                        Some(t1 + (t1 - t0) * (s - s1) / (s1 - s0))
                    }
                    [.., (_, t1)] => Some(*t1),
                    [] => None,
                };
                let point = self.point_fast(&table.density(p)?, start)?;
                let c = point.effective_flow_conductivity * eta12;
                if c > 0.0 {
                    roots.push((s, c.ln()));
                } else {
                    roots.clear();
                }
                Ok(point)
            })
            .collect()
    }
}

/// The root c = 12η σ_eff of the Bruggeman residual over weighted points
/// (method of [`EffectiveMedium::point_from`]): 0 when the residual is ≤ 0
/// at the bottom of the bracket.
fn bruggeman_points(
    points: &PointSet,
    contact: f64,
    adaptive: Option<&SeparationDensity>,
    start: Option<f64>,
) -> Result<Estimate> {
    let top = points.largest_separation().powi(3).min(f64::MAX.sqrt());
    if top.is_nan() || top <= 0.0 {
        return Ok(Estimate {
            value: 0.0,
            error: 0.0,
        });
    }
    let residual = |t: f64| -> (f64, f64) {
        let c = t.exp();
        let (r, d) = points.sum2(|u| {
            let u3 = u * u * u;
            if !u3.is_finite() {
                return (1.0, 0.0);
            }
            // one division a point, not three (the root's sums are most of
            // the curve's time after the table sums)
            let inv = 1.0 / (u3 + c);
            let two_c_inv = 2.0 * c * inv;
            (1.0 - two_c_inv, -two_c_inv * u3 * inv)
        });
        (r - contact, d)
    };
    let (mut a, mut b) = ((top * 1e-60).ln(), top.ln());
    if residual(a).0 <= 0.0 {
        return Ok(Estimate {
            value: 0.0,
            error: 0.0,
        });
    }
    // start at the given point, else at the mean of u³ over the open
    // area, inside the bracket
    let mut t = match start.filter(|t| *t > a && *t < b) {
        Some(t) => t,
        None => {
            let (m3, m0) = points.sum2(|u| (u * u * u, 1.0));
            if m3 > 0.0 && m0 > 0.0 {
                (m3 / m0).ln().clamp(a, b)
            } else {
                0.5 * (a + b)
            }
        }
    };
    let mut step = b - a;
    let mut slope = 0.0;
    // the last Newton step, while the steps are Newton's (for the
    // quadratic-convergence prediction below)
    let mut last_newton: Option<f64> = None;
    for _ in 0..300 {
        let (r, d) = residual(t);
        slope = d;
        if r > 0.0 {
            a = t;
        } else {
            b = t;
        }
        if r == 0.0 {
            step = 0.0;
            break;
        }
        let newton = if d < 0.0 { t - r / d } else { f64::NAN };
        let this = (newton - t).abs();
        // converged: this step is below the tolerance, or (quadratic
        // convergence, the step ratio measured on the last two) the next
        // one would be: C = |Δt_k|/|Δt_{k−1}|², next ≈ C |Δt_k|² (counted
        // in the error). The step may round onto the bracket's end (t
        // itself), which must not send the search to bisection.
        let next_step =
            last_newton.map_or(f64::INFINITY, |prev| this * (this / prev) * (this / prev));
        if this <= ROOT_TOLERANCE || (next_step <= ROOT_TOLERANCE && this < 1e-3) {
            step = this + next_step.min(this);
            t = newton.clamp(a, b);
            break;
        }
        let next = if newton > a && newton < b {
            last_newton = Some(this);
            newton
        } else {
            last_newton = None;
            0.5 * (a + b)
        };
        step = (next - t).abs();
        t = next;
        if step <= ROOT_TOLERANCE || b - a <= ROOT_TOLERANCE {
            break;
        }
    }
    let mut c = t.exp();
    let mut e = points.expectation(|u| 1.0 - 2.0 * c / (u * u * u + c));
    if let Some(d) = adaptive {
        // polish on the adaptive residual: the point rule's root is off the
        // adaptive one by |r| / |r′| (a few Newton steps with the point slope)
        for _ in 0..POLISH_STEPS {
            let r = d.expectation(&|u| 1.0 - 2.0 * c / (u * u * u + c), NODE_TOLERANCE, 0.0)?;
            let off = r.value - contact;
            e = Estimate {
                value: r.value,
                error: r.error + off.abs(),
            };
            if slope >= 0.0 || (off / slope).abs() <= ROOT_TOLERANCE {
                break;
            }
            t -= off / slope;
            c = t.exp();
            step = (off / slope).abs();
        }
    }
    let shift = e.error / slope.abs().max(f64::MIN_POSITIVE);
    Ok(Estimate {
        value: c,
        error: c * (step + shift),
    })
}

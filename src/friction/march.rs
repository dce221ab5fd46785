//! The adaptive panel march over x = ln q that integrates G, μ (and, with the
//! flash temperature, T_q) from q_l to q1 for one (v, T, σ0).
//!
//! Panels are processed left to right because G (and T_q) are cumulative:
//! each panel starts from the state at its left end, evaluates the integrands
//! on 17 Chebyshev–Lobatto nodes, obtains G (and T) at the nodes by
//! cumulative Chebyshev integration, and is accepted when the nested
//! 17-point and 9-point Clenshaw–Curtis values of ∫dG, ∫dμ (and ∫dT) agree to
//! the tolerance; otherwise it is bisected.

use super::chebyshev::{rule, Map, NODES};
use super::heat::{heat_kernel, heat_kernel_per_capacity, Thermal, MIN_HEAT_CAPACITY};
use super::problem::Friction;
use super::result::{
    DecadeContribution, FrictionResult, MagnificationPoint, TableExcursion, DECADE,
};
use super::shift::ShiftFactors;
use crate::error::{Error, Result};
use crate::special::erf;

/// Bisection depth cap of a panel.
const MAX_DEPTH: usize = 40;

/// Rounding budget per panel sum, in ulps of the summed magnitudes.
const SUM_ULPS: f64 = 8.0;

/// The inputs of one calculation.
pub(crate) struct Conditions {
    pub velocity: f64,
    pub temperature: f64,
    pub nominal_pressure: f64,
    pub factors: ShiftFactors,
}

/// The integrands at one node, without the G-dependent factors S P (for dμ)
/// and S (for dT): dG/dx, dμ/dx/(S P), dT/dx/S and the out-of-table parts.
#[derive(Clone, Copy, Default)]
pub(crate) struct Base {
    pub g: f64,
    pub mb: f64,
    pub hb: f64,
    pub g_out: f64,
    pub mb_out: f64,
    pub omega: f64,
}

/// One panel's node values.
#[derive(Clone, Copy)]
pub(crate) struct PanelOut {
    pub dxdt: [f64; NODES],
    pub g: [f64; NODES],
    pub big_g: [f64; NODES],
    pub m: [f64; NODES],
    pub dm_dg: [f64; NODES],
    pub dm_dt: [f64; NODES],
    pub f: [f64; NODES],
    pub g_out: [f64; NODES],
    pub m_out: [f64; NODES],
    /// Whether the panel's collocation equations were solved.
    pub ok: bool,
}

impl Default for PanelOut {
    fn default() -> Self {
        PanelOut {
            dxdt: [0.0; NODES],
            g: [0.0; NODES],
            big_g: [0.0; NODES],
            m: [0.0; NODES],
            dm_dg: [0.0; NODES],
            dm_dt: [0.0; NODES],
            f: [0.0; NODES],
            g_out: [0.0; NODES],
            m_out: [0.0; NODES],
            ok: true,
        }
    }
}

/// A panel boundary: its x, whether the panel to its right starts at a
/// (x − a)^{3/2} point, whether it is a profile point.
#[derive(Clone, Copy)]
struct Break {
    x: f64,
    singular: bool,
    profile: bool,
}

/// The running state at the current x.
#[derive(Clone, Copy, Default)]
pub(crate) struct State {
    pub g: f64,
    pub g_err: f64,
    pub mu: f64,
    pub mu_err: f64,
    /// T_q − T (the flash temperature so far), K.
    pub rise: f64,
    pub rise_err: f64,
    pub g_out: f64,
    pub mu_out: f64,
}

/// One (v, T, σ0) calculation, isothermal or with the flash temperature.
pub(crate) struct Run<'r, 'a> {
    pub fr: &'r Friction<'a>,
    pub c: &'r Conditions,
    pub thermal: Option<&'r Thermal>,
    /// 1/((1 − ν²) σ0), 1/Pa.
    pub k_e: f64,
    /// 4 v/((1 − ν²) ρ c): dT/dx = S · heat_k · q⁵ C b_T A h (below ρc =
    /// [`MIN_HEAT_CAPACITY`]: 4v/(1 − ν²), with h/(ρc) from `kernel`).
    pub heat_k: f64,
    pub x_lo: f64,
    length: f64,
    pub state: State,
    decades: Vec<DecadeContribution>,
    profile: Vec<MagnificationPoint>,
    omega_range: (f64, f64),
    pub shift_extended: Option<f64>,
    pub evaluations: usize,
    converged: bool,
}

impl<'r, 'a> Run<'r, 'a> {
    pub fn new(fr: &'r Friction<'a>, c: &'r Conditions, thermal: Option<&'r Thermal>) -> Self {
        let one_minus = 1.0 - fr.rubber.poisson().powi(2);
        let x_lo = fr.spectrum.q_min().ln();
        Run {
            fr,
            c,
            thermal,
            k_e: 1.0 / (one_minus * c.nominal_pressure),
            heat_k: thermal.map_or(0.0, |t| {
                if t.volumetric_heat_capacity() < MIN_HEAT_CAPACITY {
                    // `kernel` returns h/(ρc): 1/(ρc) is not formed
                    4.0 * c.velocity / one_minus
                } else {
                    4.0 * c.velocity / (one_minus * t.volumetric_heat_capacity())
                }
            }),
            x_lo,
            length: fr.q1.ln() - x_lo,
            state: State::default(),
            decades: Vec::new(),
            profile: Vec::new(),
            omega_range: (f64::INFINITY, 0.0),
            shift_extended: None,
            evaluations: 0,
            converged: true,
        }
    }

    /// S(G), P(G) and d(S P)/dG.
    #[inline]
    pub fn sp(&self, g: f64) -> (f64, f64, f64) {
        let (p, dp) = contact(g);
        let s = self.fr.gamma + (1.0 - self.fr.gamma) * p * p;
        (s, p, (s + 2.0 * (1.0 - self.fr.gamma) * p * p) * dp)
    }

    /// The node integrands at wavevector q with C(q) = `c_q`, heat kernel
    /// `h_q` and shift factors `f`.
    #[inline]
    pub fn base(&mut self, q: f64, c_q: f64, h_q: f64, f: ShiftFactors) -> Base {
        self.evaluations += 1;
        let omega = f.shift_factor * q * self.c.velocity;
        let ang = self.fr.angular.eval(omega);
        let q4c = q * q * q * q * c_q;
        let b = f.vertical_shift;
        let bk = b * self.k_e;
        Base {
            g: 0.5 * q4c * bk * bk * ang.modulus_squared,
            mb: 2.0 * q4c * bk * ang.loss,
            hb: self.heat_k * q * q4c * b * ang.loss * h_q,
            g_out: 0.5 * q4c * bk * bk * ang.modulus_squared_outside,
            mb_out: 2.0 * q4c * bk * ang.loss_outside,
            omega,
        }
    }

    /// The heat kernel at q (0 without thermal properties): h(q), or
    /// h(q)/(ρc) below ρc = [`MIN_HEAT_CAPACITY`] (then `heat_k` has no
    /// 1/(ρc)), so that heat_k · h is the same product without overflow.
    pub fn kernel(&self, q: f64) -> f64 {
        self.thermal.map_or(0.0, |t| {
            if t.volumetric_heat_capacity() < MIN_HEAT_CAPACITY {
                heat_kernel_per_capacity(q, self.c.velocity, t)
            } else {
                heat_kernel(q, self.c.velocity, t.thermal_diffusivity())
            }
        })
    }

    /// Node positions of the panel [a, a + h]: (x, dx/dt, q), q clamped to
    /// [q_l, q1] (e^{ln q} may round past the band, where C = 0).
    pub fn nodes(&self, a: f64, h: f64, map: Map) -> [(f64, f64, f64); NODES] {
        let r = rule();
        let (lo, hi) = (self.fr.spectrum.q_min(), self.fr.q1);
        std::array::from_fn(|j| {
            let (x, d) = map.at(a, h, r.t[j]);
            (x, d, x.exp().clamp(lo, hi))
        })
    }

    /// The isothermal panel: G by cumulative integration, then dμ.
    fn panel_iso(&mut self, a: f64, h: f64, map: Map) -> PanelOut {
        let r = rule();
        let f = self.c.factors;
        let mut out = PanelOut::default();
        let mut base = [Base::default(); NODES];
        for (j, &(_, d, q)) in self.nodes(a, h, map).iter().enumerate() {
            base[j] = self.base(q, self.fr.spectrum.c(q), 0.0, f);
            out.dxdt[j] = d;
            out.g[j] = base[j].g;
            self.track_omega(base[j].omega);
        }
        for (j, b) in base.iter().enumerate() {
            let cum: f64 = (0..NODES)
                .map(|k| r.cum[j][k] * out.g[k] * out.dxdt[k])
                .sum();
            out.big_g[j] = self.state.g + cum;
            let (s, p, dsp) = self.sp(out.big_g[j]);
            out.m[j] = s * p * b.mb;
            out.dm_dg[j] = dsp * b.mb;
            out.g_out[j] = b.g_out;
            out.m_out[j] = s * p * b.mb_out;
        }
        out
    }

    pub fn track_omega(&mut self, omega: f64) {
        self.omega_range = (self.omega_range.0.min(omega), self.omega_range.1.max(omega));
    }

    /// The panel boundaries: profile points (every 1/points_per_decade of a
    /// decade from q_l), the caller's breaks and, isothermally with a master
    /// curve, the images q = ω_i/(a_T v) of the table's frequencies.
    fn breaks(&self) -> Vec<Break> {
        let (lo, hi) = (self.x_lo, self.x_lo + self.length);
        let eps = 1e-12 * self.length.max(1.0);
        let step = DECADE / self.fr.points_per_decade as f64;
        let mut b = vec![Break {
            x: lo,
            singular: false,
            profile: true,
        }];
        let mut k = 1.0;
        while lo + k * step < hi - eps {
            b.push(Break {
                x: lo + k * step,
                singular: false,
                profile: true,
            });
            k += 1.0;
        }
        b.push(Break {
            x: hi,
            singular: false,
            profile: true,
        });
        for &q in &self.fr.breaks {
            b.push(Break {
                x: q.ln(),
                singular: false,
                profile: false,
            });
        }
        if self.thermal.is_none() {
            let shift = (self.c.factors.shift_factor * self.c.velocity).ln();
            for &y in &self.fr.table_ln {
                b.push(Break {
                    x: y - shift,
                    singular: true,
                    profile: false,
                });
            }
        }
        b.retain(|p| p.x >= lo - eps && p.x <= hi + eps);
        b.sort_by(|p, q| p.x.total_cmp(&q.x));
        let mut out: Vec<Break> = Vec::with_capacity(b.len());
        for p in b {
            match out.last_mut() {
                Some(last) if p.x - last.x <= eps => {
                    last.singular |= p.singular;
                    last.profile |= p.profile;
                }
                _ => out.push(p),
            }
        }
        out[0].x = lo;
        let n = out.len();
        out[n - 1].x = hi;
        out
    }

    /// March over all panels, left to right.
    fn march(&mut self) -> Result<()> {
        self.state = State::default();
        let n_dec = ((self.length / DECADE) - 1e-12).ceil().max(1.0) as usize;
        let q_l = self.x_lo.exp();
        self.decades = (0..n_dec)
            .map(|k| DecadeContribution {
                q_min: q_l * 10f64.powi(k as i32),
                q_max: (q_l * 10f64.powi(k as i32 + 1)).min(self.fr.q1),
                friction_coefficient: 0.0,
                friction_coefficient_error_bound: 0.0,
            })
            .collect();
        self.profile.clear();
        self.converged = true;
        let breaks = self.breaks();
        self.record_profile(breaks[0].x);
        for pair in breaks.windows(2) {
            let map = if pair[0].singular {
                Map::LeftSingular
            } else {
                Map::Linear
            };
            self.panel(pair[0].x, pair[1].x - pair[0].x, map, 0)?;
            if pair[1].profile {
                self.record_profile(pair[1].x);
            }
        }
        Ok(())
    }

    /// Solve, accept or bisect the panel [a, a + h].
    fn panel(&mut self, a: f64, h: f64, map: Map, depth: usize) -> Result<()> {
        let out = if self.thermal.is_some() {
            self.panel_flash(a, h, map)
        } else {
            self.panel_iso(a, h, map)
        };
        let can_split = depth < MAX_DEPTH && h > 1e-13 * self.length;
        if !out.ok && !can_split {
            return Err(Error::NotConverged {
                what: "flash-temperature collocation".into(),
                iterations: depth,
                residual: f64::NAN,
                tolerance: self.fr.tolerance,
            });
        }
        let e = self.estimates(&out, h);
        let fine = out.ok && e.within;
        if fine || !can_split {
            if !fine {
                self.converged = false;
            }
            return self.accept(a, h, &out, &e);
        }
        self.panel(a, 0.5 * h, map, depth + 1)?;
        self.panel(a + 0.5 * h, 0.5 * h, Map::Linear, depth + 1)
    }

    /// Record the profile point at x.
    fn record_profile(&mut self, x: f64) {
        let q = x.exp();
        let (_, p, _) = self.sp(self.state.g);
        self.profile.push(MagnificationPoint {
            zeta: (x - self.x_lo).exp(),
            q,
            g: self.state.g,
            contact_fraction: p,
            friction_coefficient: self.state.mu,
            temperature: self.c.temperature + self.state.rise,
            flash_temperature: self.state.rise,
        });
    }

    /// The adaptive march, then the result.
    pub fn solve(mut self) -> Result<FrictionResult> {
        self.march()?;
        self.result()
    }
}

/// P(G) = erf(1/(2√G)) and dP/dG = −e^{−x²} x/(√π G), x = 1/(2√G) (P = 1 at G = 0).
#[inline]
fn contact(g: f64) -> (f64, f64) {
    if g <= 0.0 || g.is_nan() {
        return (1.0, 0.0);
    }
    let x = 0.5 / g.sqrt();
    (
        erf(x),
        -(-x * x).exp() * x / (std::f64::consts::PI.sqrt() * g),
    )
}

/// Error estimates of one panel and whether they meet the tolerance.
pub(crate) struct Estimates {
    pub i_g: f64,
    pub i_m: f64,
    pub i_f: f64,
    pub e_g: f64,
    pub e_m: f64,
    pub e_f: f64,
    pub within: bool,
}

impl Run<'_, '_> {
    /// The 17- and 9-point integrals and the acceptance test.
    fn estimates(&self, out: &PanelOut, h: f64) -> Estimates {
        let r = rule();
        let int = |v: &[f64; NODES], w: &[f64; NODES]| -> f64 {
            (0..NODES).map(|j| w[j] * v[j] * out.dxdt[j]).sum()
        };
        let (i_g, i_m, i_f) = (
            int(&out.g, &r.w16),
            int(&out.m, &r.w16),
            int(&out.f, &r.w16),
        );
        let e_g = (i_g - int(&out.g, &r.w8)).abs();
        let e_m = (i_m - int(&out.m, &r.w8)).abs();
        let e_f = (i_f - int(&out.f, &r.w8)).abs();
        // Each panel meets the tolerance relative to its own integral plus its
        // share of the total so far (all integrands are ≥ 0).
        let (tol, share) = (self.fr.tolerance, h / self.length);
        let s = &self.state;
        let rise = s.rise;
        let within = e_g <= tol * (i_g.abs() + s.g * share)
            && e_m <= tol * (i_m.abs() + s.mu * share)
            && e_f <= tol * (i_f.abs() + rise * share);
        Estimates {
            i_g,
            i_m,
            i_f,
            e_g,
            e_m,
            e_f,
            within,
        }
    }

    /// Add an accepted panel to the state, the decade bins and the error bounds.
    fn accept(&mut self, a: f64, h: f64, out: &PanelOut, e: &Estimates) -> Result<()> {
        let r = rule();
        let eps_i = self.fr.angular.relative_error();
        let s = self.state;
        let mut prop = 0.0;
        let mut abs_m = 0.0;
        for j in 0..NODES {
            let w = r.w16[j] * out.dxdt[j];
            let dg = s.g_err + e.e_g + eps_i * out.big_g[j];
            prop += w
                * (out.dm_dg[j].abs() * dg
                    + eps_i * out.m[j].abs()
                    + out.dm_dt[j].abs() * (s.rise_err + e.e_f));
            abs_m += w * out.m[j].abs();
            self.state.g_out += w * out.g_out[j];
            self.state.mu_out += w * out.m_out[j];
        }
        let rounding = SUM_ULPS * f64::EPSILON;
        let mu_err = e.e_m + prop + rounding * abs_m;
        self.state.g += e.i_g;
        self.state.g_err += e.e_g + (rounding + eps_i) * e.i_g.abs();
        self.state.mu += e.i_m;
        self.state.mu_err += mu_err;
        self.state.rise += e.i_f;
        let hottest = self.c.temperature + self.state.rise; // the rise never decreases
        if self.thermal.is_some() && self.fr.rubber.shift().beyond_table(hottest) {
            self.shift_extended = Some(hottest);
        }
        self.state.rise_err += e.e_f + (rounding + eps_i) * e.i_f.abs();
        let k = (((a + 0.5 * h - self.x_lo) / DECADE).floor().max(0.0) as usize)
            .min(self.decades.len() - 1);
        self.decades[k].friction_coefficient += e.i_m;
        self.decades[k].friction_coefficient_error_bound += mu_err;
        if !(self.state.mu.is_finite() && self.state.g.is_finite() && self.state.rise.is_finite()) {
            return Err(Error::NotConverged {
                what: "friction integrand (not finite: moduli or pressures beyond f64?)".into(),
                iterations: self.evaluations,
                residual: f64::NAN,
                tolerance: self.fr.tolerance,
            });
        }
        Ok(())
    }

    /// The typed result from the final state.
    fn result(self) -> Result<FrictionResult> {
        let s = self.state;
        let (p, dp) = contact(s.g);
        let table_excursion = self.excursion();
        let tol = self.fr.tolerance;
        let converged = self.converged
            && s.mu_err <= 10.0 * tol * s.mu.abs() + f64::MIN_POSITIVE
            && s.g_err <= 10.0 * tol * s.g.abs() + f64::MIN_POSITIVE;
        Ok(FrictionResult {
            friction_coefficient: s.mu,
            friction_coefficient_error_bound: s.mu_err,
            contact_fraction: p,
            contact_fraction_error_bound: dp.abs() * s.g_err + 4.0 * f64::EPSILON * p,
            g: s.g,
            g_error_bound: s.g_err,
            flash_temperature: s.rise,
            flash_temperature_error_bound: s.rise_err,
            decades: self.decades,
            profile: self.profile,
            table_excursion,
            shift_table_extended_to: self.shift_extended,
            converged,
            evaluations: self.evaluations,
        })
    }

    /// The master curve's use outside its table.
    fn excursion(&self) -> Option<TableExcursion> {
        let (lo, hi) = self.fr.rubber.viscoelastic().frequency_range()?;
        let (wmin, wmax) = self.omega_range;
        let s = self.state;
        let frac = |part: f64, whole: f64| {
            if whole > 0.0 {
                (part / whole).clamp(0.0, 1.0)
            } else {
                0.0
            }
        };
        Some(TableExcursion {
            frequency_min: lo,
            frequency_max: hi,
            reduced_frequency_min: wmin,
            reduced_frequency_max: wmax,
            decades_below: (lo / wmin).log10().max(0.0),
            decades_above: (wmax / hi).log10().max(0.0),
            friction_fraction: frac(s.mu_out, s.mu),
            g_fraction: frac(s.g_out, s.g),
        })
    }
}

//! The flash-temperature panel: T_q, G and μ together, by collocation.
//!
//! # Formula
//! With x = ln q and the heat kernel h(q) of [`super::heat`]:
//! ```text
//! dT_q/dx = q f(q, T_q) h(q),   f = 4 v q⁴ C(q) S(q) b_T A(a_T q v) / ((1 − ν²) ρ c)
//! dG/dx   = ½ q⁴ C(q) b_T² B(a_T q v) / ((1 − ν²) σ0)²
//! dμ/dx   = 2 q⁴ C(q) S(q) P(q) b_T A(a_T q v) / ((1 − ν²) σ0)
//! ```
//! with a_T, b_T at T_q and T_{q_l} = T (the background temperature).
//! f is the heat produced per unit volume and time just under the contact
//! spots of magnification q, divided by ρc: the power σ0 v dμ of band dq,
//! spread over the contact area P(q) A0 and the depth profile 2q e^{−2qz}
//! (so σ0 and P cancel). Writing T_q = T + ∫_{q_l}^{q} dq′ f(q′) h(q′) as
//! an ODE in x is exact for this kernel, which depends on q′ only.
//!
//! # Method
//! On a panel the 16 unknown node temperatures satisfy the collocation
//! equations T_j = T_a + Σ_k S_jk F_k(T_k) (S the cumulative Chebyshev
//! integration matrix, F = dT/dt) with G_j from the same cumulative
//! integration of dG. They are solved by Newton's method with the Jacobian
//! I − S diag(∂F_k/∂T_k) (∂F/∂T by a forward difference; the weak coupling
//! through S(G) is left out of the Jacobian, not out of the residual). The
//! Jacobian is kept from one iteration to the next (a chord iteration) while
//! the residual falls at least tenfold per step, and refreshed otherwise; the
//! stopping rule is on the residual either way. A panel whose iteration does
//! not converge is bisected.
//!
//! # References
//! B. N. J. Persson, J. Phys.: Condens. Matter 18, 7789 (2006),
//! doi:10.1088/0953-8984/18/32/025 (T_q fed back into E(ω, T_q) in
//! μ and G).

use super::chebyshev::{rule, solve, Map, NODES};
use super::march::{Base, PanelOut, Run};
use crate::error::Result;

/// Newton iterations allowed per panel before it is bisected.
const MAX_NEWTON: usize = 30;

/// Residual at which Newton stops, relative to the rise at the panel's end
/// (at least this, and at least 1e-3 × the tolerance).
const NEWTON_TOL: f64 = 1e-14;

/// Forward-difference step of ∂F/∂T, relative to the background temperature.
const DIFF_STEP: f64 = 1e-6;

/// The Jacobian is kept (chord iteration) while each step cuts the largest
/// residual by at least this factor; otherwise it is refreshed.
const CHORD_RATE: f64 = 0.1;

impl Run<'_, '_> {
    /// The node integrands at temperature T.
    fn base_at(&mut self, q: f64, c_q: f64, h_q: f64, t: f64) -> Result<Base> {
        let f = self.fr.rubber.shift().factors_extended(t)?;
        Ok(self.base(q, c_q, h_q, f))
    }

    /// The flash panel [a, a + h] (module docs); `ok = false` when Newton fails.
    pub(crate) fn panel_flash(&mut self, a: f64, h: f64, map: Map) -> PanelOut {
        let nodes = self.nodes(a, h, map);
        let c_q: [f64; NODES] = std::array::from_fn(|j| self.fr.spectrum.c(nodes[j].2));
        let h_q: [f64; NODES] = std::array::from_fn(|j| self.kernel(nodes[j].2));
        let mut out = PanelOut {
            dxdt: std::array::from_fn(|j| nodes[j].1),
            ..PanelOut::default()
        };
        match self.newton(a, &nodes, &c_q, &h_q, &mut out) {
            Ok(true) => {}
            _ => out.ok = false,
        }
        out
    }

    /// Newton's method on the collocation equations for the node rises
    /// T_j − T; fills `out` on success. The temperature derivatives (the
    /// Jacobian and ∂μ/∂T) are refreshed only when the residual stops
    /// falling fast (a chord iteration otherwise): each refresh costs a
    /// second integrand evaluation per node.
    fn newton(
        &mut self,
        a: f64,
        nodes: &[(f64, f64, f64); NODES],
        c_q: &[f64; NODES],
        h_q: &[f64; NODES],
        out: &mut PanelOut,
    ) -> Result<bool> {
        let r = rule();
        let (t0, rise_a) = (self.c.temperature, self.state.rise);
        let step = DIFF_STEP * t0;
        let stop = NEWTON_TOL.max(1e-3 * self.fr.tolerance);
        let b0 = self.base_at(nodes[0].2, c_q[0], h_q[0], t0 + rise_a)?;
        let (s0, _, _) = self.sp(self.state.g);
        let mut rise: [f64; NODES] =
            std::array::from_fn(|j| rise_a + s0 * b0.hb * (nodes[j].0 - a));
        rise[0] = rise_a;
        // ∂(hb, mb)/∂T at the nodes, from the last refresh.
        let mut slope = [(0.0, 0.0); NODES];
        let (mut refresh, mut previous) = (true, f64::INFINITY);
        for _ in 0..MAX_NEWTON {
            let mut base = [b0; NODES];
            for j in 1..NODES {
                base[j] = self.base_at(nodes[j].2, c_q[j], h_q[j], t0 + rise[j])?;
            }
            if refresh {
                for j in 0..NODES {
                    let plus = self.base_at(nodes[j].2, c_q[j], h_q[j], t0 + rise[j] + step)?;
                    slope[j] = ((plus.hb - base[j].hb) / step, (plus.mb - base[j].mb) / step);
                }
            }
            let df = self.fill_nodes(&base, &slope, out);
            // Residuals of the 16 unknowns (node 0 is the known rise at a).
            let mut res = [0.0; NODES];
            let (mut worst, mut scale) = (0.0f64, rise_a.abs());
            for j in 1..NODES {
                let cum: f64 = (0..NODES)
                    .map(|k| r.cum[j][k] * out.f[k] * out.dxdt[k])
                    .sum();
                res[j - 1] = -(rise[j] - rise_a - cum);
                worst = worst.max(res[j - 1].abs());
                scale = scale.max(rise_a.abs() + cum.abs());
            }
            if !worst.is_finite() {
                return Ok(false);
            }
            if worst <= stop * scale {
                for b in &base {
                    self.track_omega(b.omega);
                }
                return Ok(true);
            }
            refresh = worst > CHORD_RATE * previous;
            previous = worst;
            let mut jac = [[0.0; NODES]; NODES];
            for j in 1..NODES {
                for k in 1..NODES {
                    let diagonal = f64::from(u8::from(j == k));
                    jac[j - 1][k - 1] = diagonal - r.cum[j][k] * out.dxdt[k] * df[k];
                }
            }
            if !solve(&mut jac, &mut res, NODES - 1) {
                return Ok(false);
            }
            for j in 1..NODES {
                rise[j] = (rise[j] + res[j - 1]).max(rise_a);
            }
        }
        Ok(false)
    }

    /// The node values of `out` from the integrands at the current rises
    /// (`base`) and their temperature derivatives `slope` = (∂hb/∂T,
    /// ∂mb/∂T); returns ∂F/∂T at the nodes.
    fn fill_nodes(
        &self,
        base: &[Base; NODES],
        slope: &[(f64, f64); NODES],
        out: &mut PanelOut,
    ) -> [f64; NODES] {
        let r = rule();
        let mut df = [0.0; NODES];
        out.g = std::array::from_fn(|j| base[j].g);
        for j in 0..NODES {
            let cum: f64 = (0..NODES)
                .map(|k| r.cum[j][k] * out.g[k] * out.dxdt[k])
                .sum();
            out.big_g[j] = self.state.g + cum;
            let (s, p, dsp) = self.sp(out.big_g[j]);
            out.f[j] = s * base[j].hb;
            df[j] = s * slope[j].0;
            out.m[j] = s * p * base[j].mb;
            out.dm_dg[j] = dsp * base[j].mb;
            out.dm_dt[j] = s * p * slope[j].1;
            out.g_out[j] = base[j].g_out;
            out.m_out[j] = s * p * base[j].mb_out;
        }
        df
    }
}

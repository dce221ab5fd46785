//! The elastic (σY → ∞) solution by the method of images, and the one-image
//! building blocks reused by the finite-yield image sum.
//!
//! Everything here is dimensionless: s = σ/σH, the Gaussian kernel has
//! variance 2τ, written with its width w = 2√τ:
//!
//! ```text
//! φ(z) = e^{−z²/w²} / (w√π)
//! Q(x) = ∫₋₁¹ P0ᵒᵈᵈ(u) φ(x − u) du = ∫₀¹ P0(u) [φ(x − u) − φ(x + u)] du
//! ```
//! (P0ᵒᵈᵈ the odd extension of P0). The elastic density is P(s) = Q(s) for
//! s ≥ 0 (Persson, Bucher & Chiaia (2002), Eq. 7 with σY → ∞).

use super::gauss;
use super::method::ImageQuadrature;
use super::start::{Start, TabulatedStart};
use crate::error::Result;
use crate::quad::{integrate, Estimate};
use crate::special::{erf, erfc, j1};

const EPS: f64 = f64::EPSILON;
const SQRT_PI: f64 = 1.772_453_850_905_516;
const FRAC_2_SQRT_PI: f64 = std::f64::consts::FRAC_2_SQRT_PI;
/// Largest window half-width L·w (in units of σH) for the cylinder's windowed
/// rules; it keeps every window away from the singularity at s = −1.
const MAX_WINDOW: f64 = 0.6;
/// Above this width the Hertz closed form is replaced by a Gauss rule (the
/// closed form's terms grow like |x| ~ L·w and cancel).
const HERTZ_CLOSED_MAX_W: f64 = 2.0;
/// Evaluation budget of adaptive quadratures (tabulated starts, fractions).
const MAX_EVALS: usize = 200_000;

/// How Q(x) is evaluated.
enum Kernel<'a> {
    /// φ(x−1) − φ(x+1).
    Flat,
    /// The erf/Gaussian closed form.
    HertzClosed,
    /// One Gauss–Legendre rule over the whole support: Q = Σ cⱼ φ(x − uⱼ).
    Global {
        u: Vec<f64>,
        c: Vec<f64>,
        bound: f64,
    },
    /// Cylinder, small w: a Gauss rule on the window |u − x| ≤ L w.
    CylWindow {
        /// Interior rule: W_j e^{−L² t_j²} and t_j.
        int_c: Vec<f64>,
        int_t: Vec<f64>,
        /// The interior rule is used for x ≤ x_star, where its bound is ≤ `int_bound`.
        x_star: f64,
        int_bound: f64,
        /// Edge rule (index in gauss::SIZES) and its bound for every x > x_star.
        edge: usize,
        edge_bound: f64,
    },
    /// Adaptive quadrature on each segment of a table.
    Tabulated(&'a TabulatedStart),
}

/// Q(x) for one start and one width w, with error bounds.
pub(crate) struct Images<'a> {
    w: f64,
    inv_w2: f64,
    /// 1/(w√π)
    norm: f64,
    /// L: the Gaussian is cut at |x − u| = L w.
    l: f64,
    /// Bound on the Gaussian tail cut off by the window, per Q evaluation.
    pub(crate) trunc: f64,
    /// Target for each quadrature.
    tol_q: f64,
    kernel: Kernel<'a>,
    /// How each image is evaluated.
    pub(crate) method: ImageQuadrature,
}

impl<'a> Images<'a> {
    /// Set up Q for `start` at width `w` > 0 and absolute tolerance `tol`.
    pub(crate) fn new(start: &'a Start, w: f64, tol: f64) -> Self {
        let norm = 1.0 / (w * SQRT_PI);
        let tol_t = 0.01 * tol;
        // ∫_{|u−x|>Lw} |P0ᵒᵈᵈ| φ ≤ 2 e^{−L²}/(w√π) ≤ tol_t
        let l = (2.0 * norm / tol_t).ln().max(1.0).sqrt();
        let trunc = 2.0 * norm * (-l * l).exp();
        let tol_q = 0.1 * tol;
        let inv_w2 = 1.0 / (w * w);
        let (kernel, method) = match start {
            Start::Flat => (Kernel::Flat, ImageQuadrature::ClosedForm),
            Start::Hertz if w <= HERTZ_CLOSED_MAX_W => {
                (Kernel::HertzClosed, ImageQuadrature::ClosedForm)
            }
            Start::Hertz => {
                let ln_norm = norm.ln();
                let (i, bound) = gauss::choose(tol_q, 2.0, |b| {
                    (2.0 * (1.0 + b * b).sqrt()).ln() + b * b * inv_w2 + ln_norm
                });
                let r = gauss::rule(i);
                let c = r.x.iter().zip(&r.w).map(|(t, wt)| wt * 2.0 * t).collect();
                (
                    Kernel::Global {
                        u: r.x.clone(),
                        c,
                        bound,
                    },
                    ImageQuadrature::GaussLegendre { nodes: r.x.len() },
                )
            }
            Start::Cylinder if l * w > MAX_WINDOW => {
                let h = std::f64::consts::FRAC_PI_2;
                let ln_norm = norm.ln();
                let (i, bound) = gauss::choose(tol_q, 2.0, |b| {
                    let s = (h * b).sinh();
                    (h * (h * b).cosh()).ln() + s * s * inv_w2 + ln_norm
                });
                let r = gauss::rule(i);
                let u = r.x.iter().map(|t| (h * t).sin()).collect::<Vec<_>>();
                let c = u.iter().zip(&r.w).map(|(s, wt)| wt * h * s).collect();
                (
                    Kernel::Global { u, c, bound },
                    ImageQuadrature::GaussLegendreSine { nodes: r.x.len() },
                )
            }
            Start::Cylinder => {
                let lw = l * w;
                let ln_norm = norm.ln();
                // the smallest interior rule whose bound holds up to within 4Lw of
                // the edge (else the one reaching furthest)
                let mut pick = (INTERIOR[0], -1.0);
                for &i in &INTERIOR {
                    let xs = interior_reach(gauss::SIZES[i], lw, l, ln_norm, tol_q);
                    if xs > pick.1 {
                        pick = (i, xs);
                    }
                    if xs >= 0.0 && 1.0 - xs <= 4.0 * lw {
                        break;
                    }
                }
                let r = gauss::rule(pick.0);
                let n = r.x.len();
                let int_c =
                    r.x.iter()
                        .zip(&r.w)
                        .map(|(t, wt)| wt * (-(l * t) * (l * t)).exp())
                        .collect();
                // when no rule reaches the tolerance, use the largest short of the
                // edge and report its bound
                let x_star = if pick.1 >= 0.0 {
                    pick.1
                } else {
                    (1.0 - 2.0 * lw).max(0.0)
                };
                let int_bound = interior_ln_bound(x_star, lw, l, n, ln_norm).exp();
                // the edge windows [x − Lw, 1] are longest at x = x_star
                let (edge, edge_bound) = edge_rule(x_star, lw, w, ln_norm, tol_q);
                (
                    Kernel::CylWindow {
                        int_c,
                        int_t: r.x.clone(),
                        x_star,
                        int_bound,
                        edge,
                        edge_bound,
                    },
                    ImageQuadrature::WindowedGauss {
                        window_half_width: l,
                    },
                )
            }
            Start::Tabulated(t) => (Kernel::Tabulated(t), ImageQuadrature::AdaptiveGaussKronrod),
        };
        Images {
            w,
            inv_w2,
            norm,
            l,
            trunc,
            tol_q,
            kernel,
            method,
        }
    }

    /// Half-width L·w beyond the support [−1, 1] where Q is cut off.
    pub(crate) fn reach(&self) -> f64 {
        self.l * self.w
    }

    /// φ(z).
    #[inline]
    fn phi(&self, z: f64) -> f64 {
        self.norm * (-(z * z) * self.inv_w2).exp()
    }

    /// Q(x) with an absolute error bound.
    ///
    /// # Formula
    /// ```text
    /// flat:  Q = φ(x − 1)(1 − e^{−4x/w²})
    /// Hertz: Q = x [erf((1−x)/w) + erf((1+x)/w)] − (w/√π) e^{−(1−x)²/w²}(1 − e^{−4x/w²})
    /// else:  Gauss rules on the smooth integrand (cylinder: u = sin θ globally, or a
    ///        window |u − x| ≤ L w with a Gauss–Jacobi rule at the edge u = 1)
    /// ```
    /// Q is odd; x < 0 is reduced to −Q(−x).
    ///
    /// # Errors
    /// Only the adaptive quadrature of tabulated starts can fail.
    pub(crate) fn q(&self, x: f64) -> Result<Estimate> {
        if x < 0.0 {
            let e = self.q(-x)?;
            return Ok(Estimate {
                value: -e.value,
                error: e.error,
            });
        }
        if x - 1.0 > self.reach() {
            return Ok(Estimate {
                value: 0.0,
                error: self.trunc,
            });
        }
        Ok(match &self.kernel {
            Kernel::Flat => {
                let v = self.phi(x - 1.0) * -(-4.0 * x * self.inv_w2).exp_m1();
                Estimate {
                    value: v,
                    error: 8.0 * EPS * v,
                }
            }
            Kernel::HertzClosed => self.hertz_closed(x),
            Kernel::Global { u, c, bound } => {
                let (mut s, mut a) = (0.0, 0.0);
                for (uj, cj) in u.iter().zip(c) {
                    let d = x - uj;
                    let t = cj * (-(d * d) * self.inv_w2).exp();
                    s += t;
                    a += t.abs();
                }
                Estimate {
                    value: self.norm * s,
                    error: bound + (u.len() as f64 + 4.0) * EPS * self.norm * a,
                }
            }
            Kernel::CylWindow {
                int_c,
                int_t,
                x_star,
                int_bound,
                edge,
                edge_bound,
            } => self.cyl_window(x, int_c, int_t, *x_star, *int_bound, *edge, *edge_bound),
            Kernel::Tabulated(t) => self.tabulated(t, x)?,
        })
    }

    fn hertz_closed(&self, x: f64) -> Estimate {
        let w = self.w;
        let a1 = (1.0 - x) / w;
        let a2 = (1.0 + x) / w;
        let (e, emag) = if x <= 1.0 {
            let (p, q) = (erf(a1), erf(a2));
            (p + q, p.abs() + q)
        } else {
            let (p, q) = (erfc(-a1), erfc(a2));
            (p - q, p + q)
        };
        let g1 = (-a1 * a1).exp();
        let g = g1 * -(-4.0 * x * self.inv_w2).exp_m1();
        let k = w / SQRT_PI;
        let v = x * e - k * g;
        Estimate {
            value: v,
            error: 16.0 * EPS * (x * emag + k * g1) + 4.0 * EPS * v.abs(),
        }
    }

    /// Cylinder, window [x − Lw, x + Lw] ∩ (−1, 1], x ≥ 0, L w ≤ 0.6.
    #[allow(clippy::too_many_arguments)]
    fn cyl_window(
        &self,
        x: f64,
        int_c: &[f64],
        int_t: &[f64],
        x_star: f64,
        int_bound: f64,
        edge: usize,
        edge_bound: f64,
    ) -> Estimate {
        let lw = self.reach();
        let trunc = self.trunc;
        // Interior rule (Gauss–Legendre in u): fixed Gaussian factors.
        if x <= x_star {
            let n = int_t.len();
            let (mut s, mut a) = (0.0, 0.0);
            for (t, c) in int_t.iter().zip(int_c) {
                let u = x + lw * t;
                let v = c * u / ((1.0 - u) * (1.0 + u)).sqrt();
                s += v;
                a += v.abs();
            }
            return Estimate {
                value: self.norm * lw * s,
                error: int_bound + trunc + (n as f64 + 8.0) * EPS * self.norm * lw * a,
            };
        }
        // Edge rule: Gauss–Jacobi (weight (1 − u)^{−1/2}) on [a, 1], as a
        // Gauss–Legendre rule in v with u = 1 − (1 − a) v².
        let a = x - lw;
        let len = 1.0 - a;
        let r = gauss::rule(edge);
        let n = r.x.len();
        let (mut s, mut acc) = (0.0, 0.0);
        for (v, wt) in r.x[n / 2..].iter().zip(&r.w[n / 2..]) {
            let d = len * v * v; // 1 − u
            let u = 1.0 - d;
            let z = (x - 1.0) + d; // x − u
            let t = wt * u / (1.0 + u).sqrt() * (-(z * z) * self.inv_w2).exp();
            s += t;
            acc += t.abs();
        }
        let f = 2.0 * len.sqrt() * self.norm;
        Estimate {
            value: f * s,
            error: edge_bound + trunc + (n as f64 + 8.0) * EPS * f * acc,
        }
    }

    fn tabulated(&self, t: &TabulatedStart, x: f64) -> Result<Estimate> {
        let lo = (x - self.reach()).max(0.0);
        let hi = x + self.reach();
        let nseg = t.s.len() as f64;
        let mut out = Estimate {
            value: 0.0,
            error: self.trunc,
        };
        for (a, b) in t.segments() {
            let (a, b) = (a.max(lo), b.min(hi));
            if a >= b {
                continue;
            }
            // in z = u − x: with nodes in u, their rounding (ulp(x)) moves the
            // Gaussian by ε x/w of its width, 5e-11 of the result at G = 1e-12
            let f = |z: f64| {
                let u = x + z;
                t.eval(u) * self.phi(z) * -(-4.0 * x * u * self.inv_w2).exp_m1()
            };
            let r = integrate(
                "stress: image integral of a tabulated start",
                f,
                a - x,
                b - x,
                self.tol_q / nseg,
                1e-14,
                MAX_EVALS,
            )?;
            out.value += r.value;
            out.error += r.error;
        }
        Ok(out)
    }
}

/// ln of the Gauss–Legendre bound for the interior window [x − Lw, x + Lw]
/// (minimised over a few ellipses that avoid the singularities at ±1).
///
/// # Formula
/// ```text
/// on E_ρ: |u| ≤ x + Lwα, |1 − u²| ≥ δ₊δ₋ (δ± = 1 ± x − Lwα), |e^{−(x−u)²/w²}| ≤ e^{L²β²}
/// ```
fn interior_ln_bound(x: f64, lw: f64, l: f64, n: usize, ln_norm: f64) -> f64 {
    let mut best = f64::INFINITY;
    for beta in [0.3f64, 0.5, 0.7, 0.9, 1.2] {
        let alpha = (1.0 + beta * beta).sqrt();
        let dp = 1.0 - x - lw * alpha;
        let dm = 1.0 + x - lw * alpha;
        if dp <= 0.0 || dm <= 0.0 {
            continue;
        }
        let lb = l * beta;
        let ln_m = (lw * (x + lw * alpha)).ln() - 0.5 * (dp * dm).ln() + lb * lb + ln_norm;
        best = best.min(gauss::ln_bound(n, beta, ln_m, 2.0));
    }
    best
}

/// The smallest edge rule whose bound holds for the window [x − Lw, 1] (and
/// so for every shorter edge window), with that bound.
fn edge_rule(x: f64, lw: f64, w: f64, ln_norm: f64, tol_q: f64) -> (usize, f64) {
    let a = x - lw;
    let c = 0.5 * (a + 1.0);
    let h = 0.5 * (1.0 - a);
    let wint = 2.0 * std::f64::consts::SQRT_2 * h.sqrt();
    let mut pick = (EDGE[EDGE.len() - 1], f64::INFINITY);
    for &i in &EDGE {
        let m = gauss::SIZES[i] / 2;
        let mut best = f64::INFINITY;
        for beta in gauss::BETAS {
            let alpha = (1.0 + beta * beta).sqrt();
            let dm = 1.0 + c - h * alpha;
            if dm <= 0.0 {
                continue;
            }
            let hb = h * beta / w;
            let ln_m = (c.abs() + h * alpha).ln() - 0.5 * dm.ln() + hb * hb + ln_norm;
            best = best.min(gauss::ln_bound(m, beta, ln_m, wint));
        }
        pick = (i, best.exp());
        if pick.1 <= tol_q {
            break;
        }
    }
    pick
}

/// Interior window rules tried: 48, 64, 96, 128 nodes (indices in [`gauss::SIZES`]).
const INTERIOR: [usize; 4] = [5, 6, 7, 8];

/// The largest x in [0, 1 − Lw] up to which the n-point interior bound is
/// ≤ `tol` (it increases with x), or −1 if it fails already at x = 0.
fn interior_reach(n: usize, lw: f64, l: f64, ln_norm: f64, tol: f64) -> f64 {
    let ib = |x: f64| interior_ln_bound(x, lw, l, n, ln_norm).exp();
    let (mut lo, mut hi) = (0.0, (1.0 - lw).max(0.0));
    if ib(hi) <= tol {
        return hi;
    }
    if ib(0.0) > tol {
        return -1.0;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if ib(mid) <= tol {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}
/// Edge rules tried, as Gauss–Legendre indices (48 … 384 nodes: Gauss–Jacobi
/// with half as many).
const EDGE: [usize; 7] = [5, 6, 7, 8, 9, 10, 11];

/// D = erfc((x − u)/w) − erfc((x + u)/w) for x ≥ u ≥ 0, to a few ulps
/// (the arguments are formed from x ± u, never as a difference of quotients).
///
/// # Formula
/// ```text
/// D = erfc((x−u)/w) − erfc((x+u)/w)            when 4xu/w² ≥ 1/4 (ratio ≤ e^{−4xu/w²})
/// D = (2/√π) ∫_{(x−u)/w}^{(x+u)/w} e^{−t²} dt   (8-point Gauss) when 4xu/w² < 1/4
/// ```
pub(crate) fn erfc_diff(x: f64, u: f64, w: f64) -> f64 {
    erfc_diff_gap(x, u, x - u, w)
}

/// [`erfc_diff`] with the gap x − u supplied by the caller, for integrands
/// where it is known more accurately than the difference of the rounded x
/// and u (u = cos θ ≈ 1: x − u = (x − 1) + 2 sin²(θ/2)).
fn erfc_diff_gap(x: f64, u: f64, gap: f64, w: f64) -> f64 {
    let (lo, hi) = (gap / w, (x + u) / w);
    if 4.0 * x * u >= 0.25 * w * w {
        if lo >= 0.0 {
            erfc(lo) - erfc(hi)
        } else {
            erf(hi) - erf(lo)
        }
    } else {
        let (a, b) = (x / w, u / w);
        let r = gauss::rule(0);
        let s: f64 =
            r.x.iter()
                .zip(&r.w)
                .map(|(t, wt)| {
                    let v = a + b * t;
                    wt * (-v * v).exp()
                })
                .sum();
        FRAC_2_SQRT_PI * b * s
    }
}

/// Split points d·4ᵏ (k = −3 … ) up to 1 for a feature of width d at 0.
fn scale_points(d: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let mut p = d / 64.0;
    while p < 1.0 && p > 0.0 {
        out.push(p);
        p *= 4.0;
    }
    out
}

/// [a, b] cut at the split points inside it.
fn pieces(a: f64, b: f64, splits: &[f64]) -> Vec<f64> {
    let mut out = vec![a];
    out.extend(splits.iter().copied().filter(|&p| p > a && p < b));
    out.push(b);
    out
}

/// Σ of adaptive Gauss–Kronrod integrals over consecutive `points`, each to
/// 1e-15 relative, or `abs_tol`, or 1e-16 of the sum so far, with the sum of
/// their error estimates.
fn integrate_pieces(
    what: &str,
    f: impl Fn(f64) -> f64,
    points: &[f64],
    abs_tol: f64,
) -> Result<Estimate> {
    let mut out = Estimate {
        value: 0.0,
        error: 0.0,
    };
    for ab in points.windows(2) {
        if ab[1] > ab[0] {
            let tol = abs_tol.max(1e-16 * out.value.abs());
            let r = integrate(what, &f, ab[0], ab[1], tol, 1e-15, MAX_EVALS)?;
            out.value += r.value;
            out.error += r.error;
        }
    }
    Ok(out)
}

/// The elastic contact fraction A∞ = ∫₀^∞ P ds = ∫₀¹ P0(u) erf(u/w) du.
///
/// # Formula
/// ```text
/// flat:     erf(c)                                        c = 1/w
/// Hertz:    erf(c)(1 − 1/(2c²)) + e^{−c²}/(c√π)         (c ≥ 1/√2)
///           (2/√π) Σ (−1)ᵏ 2 c^{2k+1} / (k!(2k+1)(2k+3))  (c < 1/√2)
/// cylinder: ∫₀^{π/2} sin t erf(c sin t) dt: series Σ (2/√π)(−1)ᵏ c^{2k+1} W₂ₖ₊₂/(k!(2k+1))
///           (Wallis W₂ₘ = (π/2)(2m−1)!!/(2m)!!) for c ≤ 1, else 1 − adaptive quadrature
///           of sin t erfc(c sin t)
/// ```
/// (docs/stress.md.)
///
/// # Errors
/// Quadrature failure (cylinder at c > 1, tabulated starts).
pub(crate) fn contact_fraction(start: &Start, w: f64) -> Result<Estimate> {
    let c = 1.0 / w;
    Ok(match start {
        Start::Flat => Estimate::rounded(erf(c), 4.0),
        Start::Hertz => {
            if c >= std::f64::consts::FRAC_1_SQRT_2 {
                let v = erf(c) * (1.0 - 0.5 / (c * c)) + (-c * c).exp() / (c * SQRT_PI);
                Estimate::rounded(v, 16.0)
            } else {
                let c2 = c * c;
                let (mut term, mut sum, mut mag) = (c, 0.0, 0.0); // c^{2k+1}(−1)^k/k!
                for k in 0..60 {
                    let kf = k as f64;
                    let t = 2.0 * term / ((2.0 * kf + 1.0) * (2.0 * kf + 3.0));
                    sum += t;
                    mag += t.abs();
                    if t.abs() < 1e-18 * sum.abs() {
                        break;
                    }
                    term *= -c2 / (kf + 1.0);
                }
                Estimate {
                    value: FRAC_2_SQRT_PI * sum,
                    error: 8.0 * EPS * FRAC_2_SQRT_PI * mag,
                }
            }
        }
        Start::Cylinder => {
            if c <= 1.0 {
                let c2 = c * c;
                let (mut term, mut wallis, mut sum, mut mag) =
                    (c, std::f64::consts::FRAC_PI_4, 0.0, 0.0);
                for k in 0..60 {
                    let kf = k as f64;
                    let t = term * wallis / (2.0 * kf + 1.0);
                    sum += t;
                    mag += t.abs();
                    if t.abs() < 1e-18 * sum.abs() {
                        break;
                    }
                    term *= -c2 / (kf + 1.0);
                    // W_{2k+4} = W_{2k+2} (2k+3)/(2k+4)
                    wallis *= (2.0 * kf + 3.0) / (2.0 * kf + 4.0);
                }
                Estimate {
                    value: FRAC_2_SQRT_PI * sum,
                    error: 8.0 * EPS * FRAC_2_SQRT_PI * mag,
                }
            } else {
                let f = |t: f64| t.sin() * erfc(c * t.sin());
                let h = std::f64::consts::FRAC_PI_2;
                let split = (8.0 / c).min(h);
                let mut r = integrate(
                    "stress: cylinder contact fraction",
                    f,
                    0.0,
                    split,
                    1e-18,
                    1e-15,
                    MAX_EVALS,
                )?;
                if split < h {
                    let r2 = integrate(
                        "stress: cylinder contact fraction",
                        f,
                        split,
                        h,
                        1e-18,
                        1e-15,
                        MAX_EVALS,
                    )?;
                    r.value += r2.value;
                    r.error += r2.error;
                }
                Estimate {
                    value: 1.0 - r.value,
                    error: r.error + EPS,
                }
            }
        }
        Start::Tabulated(t) => {
            let mut out = Estimate {
                value: 0.0,
                error: 0.0,
            };
            // erf(cu) rises on the scale w at u = 0: split there so that no
            // adaptive rule can step over it
            let near_zero = scale_points(w);
            for (a, b) in t.segments() {
                let r = integrate_pieces(
                    "stress: tabulated contact fraction",
                    |u: f64| t.eval(u) * erf(u * c),
                    &pieces(a, b, &near_zero),
                    1e-18,
                )?;
                out.value += r.value;
                out.error += r.error;
            }
            out
        }
    })
}

/// F(x) = ∫₀¹ P0(u) [erfc((x − u)/w) − erfc((x + u)/w)] du for x ≥ 1: twice
/// the elastic mass beyond x, and the flux absorbed at a wall at x (Eq. for
/// A_pl and A_el in [`super::images`]).
///
/// # Errors
/// Quadrature failure.
pub(crate) fn beyond(start: &Start, w: f64, x: f64) -> Result<Estimate> {
    let what = "stress: mass beyond the yield stress";
    // In v = 1 − u the gap x − u = (x − 1) + v is exact, and the integrand
    // lives within the decay length d of v = 0: split there (a single adaptive
    // rule over [0, 1] steps over a peak of width 1e-6 and reports 0 ± 0).
    let z0 = (x - 1.0) / w;
    let near_edge = scale_points(w / (1.0 + 2.0 * z0));
    let gap = |v: f64| (x - 1.0) + v;
    let mut f: Estimate = match start {
        Start::Flat => Estimate::rounded(erfc_diff(x, 1.0, w), 16.0),
        Start::Hertz => integrate_pieces(
            what,
            |v: f64| {
                let u = 1.0 - v;
                2.0 * u * erfc_diff_gap(x, u, gap(v), w)
            },
            &pieces(0.0, 1.0, &near_edge),
            1e-300,
        )?,
        // u = sin t = cos θ (θ = π/2 − t), v = 1 − u = 2 sin²(θ/2): the
        // Jacobian removes P0's singularity at u = 1
        Start::Cylinder => {
            let theta: Vec<f64> = near_edge
                .iter()
                .map(|v| 2.0 * (0.5 * v).sqrt().min(1.0).asin())
                .collect();
            integrate_pieces(
                what,
                |th: f64| {
                    let h = (0.5 * th).sin();
                    let u = th.cos();
                    u * erfc_diff_gap(x, u, gap(2.0 * h * h), w)
                },
                &pieces(0.0, std::f64::consts::FRAC_PI_2, &theta),
                1e-300,
            )?
        }
        Start::Tabulated(t) => {
            let mut out = Estimate {
                value: 0.0,
                error: 0.0,
            };
            for (lo, hi) in t.segments() {
                let r = integrate_pieces(
                    what,
                    |v: f64| {
                        let u = 1.0 - v;
                        t.eval(u) * erfc_diff_gap(x, u, gap(v), w)
                    },
                    &pieces(1.0 - hi, 1.0 - lo, &near_edge),
                    1e-300,
                )?;
                out.value += r.value;
                out.error += r.error;
            }
            out
        }
    };
    // conditioning: erfc(z) moves by 2z² δ relatively when z = (x − u)/w has
    // relative error δ ≈ 2ε (one subtraction, one division)
    let z = (x - 1.0) / w;
    f.error += f.value * (2.0 * z * z + 4.0) * 4.0 * EPS;
    Ok(f)
}

/// Bessel-based sine coefficient of the cylinder, (π/2) J1(γ) (Persson, Bucher & Chiaia (2002), after Eq. 12).
#[inline]
pub(crate) fn cylinder_coefficient(gamma: f64) -> f64 {
    std::f64::consts::FRAC_PI_2 * j1(gamma)
}

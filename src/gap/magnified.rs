//! The interface seen at magnification ζ: apparent contact area A(ζ), the
//! mean separation ū(ζ) inside it, and the separation u1(ζ) of the area that
//! leaves contact between ζ and ζ + dζ.
//!
//! # Formula
//! ```text
//! G(ζ)   = (π/4)(E*/σ0)² ∫_{q_l}^{ζ q_l} q³ C dq,       A(ζ)/A0 = erf(1/(2√G))
//! dA/dζ  = −x e^{−x²} G′(ζ) / (√π G),   x = 1/(2√G),   G′ = (π/4)(E*/σ0)² q_l (ζq_l)³ C(ζq_l)
//! p(ζ)   = σ0 A0/A(ζ)                                  mean pressure in the apparent contact
//! ū(ζ)   = F(ζ, p(ζ)),
//! F(ζ,p) = √π ∫_{ζq_l}^{q_s} q² C w_ζ · ½ E1((w_ζ p/E*)²) dq,  w_ζ(q) = (π ∫_{ζq_l}^{q} q′³C dq′)^{−1/2}
//! dū/dζ  = ∂F/∂ζ + ∂F/∂p · p′(ζ),          p′ = −σ0 A′/A²
//! ∂F/∂p  = −1/K_ζ(p)                       (the stiffness of the cut problem)
//! ∂F/∂ζ  = √π ∫ q² C (∂w_ζ/∂ζ) (½E1(x²) − e^{−x²}) dq,   x = w_ζ p/E*,
//!          ∂w_ζ/∂ζ = (π/2) w_ζ³ q_l (ζq_l)³ C(ζq_l)
//! u1(ζ)  = ū(ζ) + ū′(ζ) A(ζ)/A′(ζ) = d(A ū)/dA
//! ```
//! ū(ζ) is Persson's separation law (Phys. Rev. Lett. 99, 125502 (2007),
//! Eqs. 4–6; [`crate::separation`]) applied to the roughness that is not yet
//! resolved at ζ — the spectrum cut to `[ζ q_l, q_s]` — under the pressure
//! p(ζ) that the apparent contact carries. This is the prescription of
//! Persson & Yang (2008) and Lorenz & Persson (2009) as we recall it (their
//! text was not at hand here, so no equation numbers): p replaced by
//! p(ζ) = F_N/A(ζ) and the q-integral restricted to q > ζ q_l. Where w(q)'s
//! lower limit stays implicit we cut it too (w_ζ), so that ū(ζ) is exactly the
//! separation theory of the cut spectrum — the boundary term of ∂F/∂ζ then
//! vanishes (w_ζ → ∞ at q = ζ q_l, E1 → 0).
//!
//! u1 follows from the balance of the separation volume (Yang & Persson,
//! J. Phys.: Condens. Matter 20, 215214 (2008)):
//! A(ζ−dζ) ū(ζ−dζ) = A(ζ) ū(ζ) + [A(ζ−dζ) − A(ζ)] u1(ζ), i.e. u1 = (Aū)′/A′.
//! Integrating −A′ u1 = −(Aū)′ from ζ = 1 (A = A0, ū(1) = ū) to q_s/q_l
//! (ū = 0) gives ∫ (−A′/A0) u1 dζ = ū exactly, which the tests use.
//!
//! # Method
//! The three q-integrals (F, 1/K, ∂F/∂ζ) in v = √(ln(q/(ζq_l))) as in
//! [`crate::separation`], in one globally adaptive Gauss–Kronrod (G7/K15)
//! pass over shared nodes (one evaluation of w, E1 and e^{−x²} serves all
//! three), each to the relative tolerance `tolerance` with |K − G| summed
//! over the panels as its error. A and A′ are closed forms of the spectrum's
//! exact moment.
//!
//! # References
//! - B. N. J. Persson, C. Yang, J. Phys.: Condens. Matter 20, 315011 (2008),
//!   doi:10.1088/0953-8984/20/31/315011.
//! - B. Lorenz, B. N. J. Persson, EPL 86, 44006 (2009), doi:10.1209/0295-5075/86/44006.
//! - C. Yang, B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214 (2008),
//!   doi:10.1088/0953-8984/20/21/215214 (u1 = ū + ū′A/A′).

use std::cell::RefCell;

use crate::error::{check, Error, Result};
use crate::quad::Estimate;
use crate::special::{e1, erf};
use crate::spectrum::Spectrum;

/// Evaluations allowed per q-integral.
const MAX_EVALS: usize = 2_000_000;

/// Arguments of e^{−x²} and E1(x²) beyond which both underflow.
const UNDERFLOW_ARG: f64 = 745.0;

/// ζ − 1 below which the adaptive P(u) ([`super::SeparationDensity::new`])
/// does not resolve a magnification apart from ζ = 1: 1e-9, its narrowest
/// ζ-panel in ln ζ (`MIN_PANEL` of [`super`]), so that the weight −dA/A0
/// lying closer to 1 sits inside one unsplittable panel. Measured on
/// self-affine spectra (H = 0.5, 0.8): P(u) keeps its normalisation within
/// its error bound (≤ 3e-10) down to ζ − 1 ≈ 1e-9 at the weight's lower
/// edge; from 3e-10 on it errs by more than its bound (4e-3 against 2e-3 at
/// 4e-12), and loses 59 % of its weight at 2.5e-15.
pub(crate) const ADAPTIVE_RESOLUTION: f64 = 1e-9;

/// The same for the load curves' table ([`super::SeparationTable`]), which
/// places its nodes in s = ln m3 and not in ln ζ: 5e-13. Measured on the
/// same spectra: the table keeps its normalisation within its error bound
/// down to ζ − 1 ≈ 5e-13 at the weight's lower edge and exceeds it from
/// 2.5e-13 on (3e-6 against 2.5e-6; 2e-1 against 6e-2 at 2.5e-17).
pub(crate) const TABLE_RESOLUTION: f64 = 5e-13;

/// The same for the critical junction's ζ_c, found by a root search in
/// ln ζ to 1e-13 and used as one point ([`Magnified::point`]), not as a
/// quadrature's nodes: 1e-13. Measured on the same spectra: Q changes
/// smoothly with σ0 down to ζ_c − 1 ≈ 7e-14; below, ζ_c carries the
/// rounding of 1 + δ (Q stalls as σ0 falls further) and near 1e-15 it
/// rounds onto 1, where −A′ = 0 and u1 and Q become +∞.
pub(crate) const CRITICAL_RESOLUTION: f64 = 1e-13;

/// Refuse a load so low (against E*) that the contact is lost, from A/A0 = 1
/// down to A/A0 = erf(`x_edge`), closer to ζ = 1 than a route resolves
/// (`resolution`: [`ADAPTIVE_RESOLUTION`], [`TABLE_RESOLUTION`] or
/// [`CRITICAL_RESOLUTION`]): the
/// magnifications that carry the result round towards ζ = 1, and the routes
/// then lose the area −dA.
///
/// # Bound
/// G(ζ) = g m3(ζ), g = (π/4)(E*/σ0)², reaches 1/(4 x_edge²) at ζ_edge; it
/// must lie at least δ = `resolution` above 1:
/// ```text
/// g m3(q_l, q_l(1 + δ)) ≤ 1/(4 x_edge²)   ⇔   σ0 ≥ E* x_edge √(π m3_δ)
/// ```
/// (m3 increases with ζ). `x_edge` is where the result's weight begins: 6.5
/// for P(u) (the area beyond is erfc(6.5) < 4e-20), erf⁻¹(a_c) for the
/// critical junction.
///
/// # Errors
/// [`Error::InvalidParameter`] naming `nominal_pressure` with that bound, or
/// `contact_modulus` (at most σ0/(x_edge √(π m3_δ))) when E* is beyond
/// 1e±30 ([`crate::error::ratio_culprit`]).
pub(crate) fn check_resolved(
    spectrum: &dyn Spectrum,
    contact_modulus: f64,
    pressure: f64,
    x_edge: f64,
    resolution: f64,
) -> Result<()> {
    let q_l = spectrum.q_min();
    let m3 = spectrum.moment(3, q_l, q_l * (1.0 + resolution))?.value;
    let factor = x_edge * (std::f64::consts::PI * m3).sqrt();
    if pressure >= contact_modulus * factor {
        return Ok(());
    }
    let approx = crate::error::approx;
    let why = format!(
        "so that the contact is not lost within ζ − 1 < {} of ζ = 1, closer than the \
         magnifications are resolved (σ0 ≥ E* x √(π ∫q³C dq over [q_l, q_l(1 + {0})]))",
        crate::error::num(resolution)
    );
    Err(
        match crate::error::ratio_culprit(contact_modulus, pressure) {
            "contact_modulus" => Error::invalid(
                "contact_modulus",
                contact_modulus,
                format!(
                    "at most {} (σ0 = {}, x = {x_edge:.3}) {why}",
                    approx(pressure / factor),
                    crate::error::num(pressure)
                ),
            ),
            _ => Error::invalid(
                "nominal_pressure",
                pressure,
                format!(
                    "at least {} (E* = {}, x = {x_edge:.3}) {why}",
                    approx(contact_modulus * factor),
                    crate::error::num(contact_modulus)
                ),
            ),
        },
    )
}

/// The spectrum restricted to `[lo, q_s]`: the roughness not yet resolved at
/// magnification ζ = lo/q_l.
pub(crate) struct Band<'a> {
    inner: &'a dyn Spectrum,
    lo: f64,
}

impl Spectrum for Band<'_> {
    fn c(&self, q: f64) -> f64 {
        if q < self.lo {
            0.0
        } else {
            self.inner.c(q)
        }
    }
    fn q_min(&self) -> f64 {
        self.lo
    }
    fn q_max(&self) -> f64 {
        self.inner.q_max()
    }
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        let a = a.max(self.lo);
        if a >= b {
            return Ok(Estimate {
                value: 0.0,
                error: 0.0,
            });
        }
        self.inner.moment(k, a, b)
    }
}

/// Everything the leakage and P(u) need at one magnification.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub(crate) struct MagnifiedPoint {
    /// Magnification ζ.
    pub zeta: f64,
    /// A(ζ)/A0.
    pub contact_fraction: f64,
    /// −dA/dζ / A0 (≥ 0).
    pub area_loss_rate: f64,
    /// Mean pressure in the apparent contact, p(ζ) = σ0 A0/A(ζ).
    pub apparent_pressure: f64,
    /// ū(ζ), m.
    pub mean_separation: Estimate,
    /// u1(ζ) = ū + ū′ A/A′, m (0 where the cut problem is in full contact;
    /// +∞ where −A′ underflows while ū′ does not, near ζ = 1).
    pub critical_separation: Estimate,
    /// −d(A ū)/dζ / A0 = (−A′/A0) u1, m: finite where u1 overflows.
    pub volume_rate: Estimate,
    /// rms height of the roughness above ζ q_l, √(2π ∫_{ζq_l}^{q_s} q C dq), m.
    pub rms_height: f64,
}

/// The magnification-resolved interface of one spectrum, E* and σ0.
pub(crate) struct Magnified<'a> {
    spectrum: &'a dyn Spectrum,
    contact_modulus: f64,
    pressure: f64,
    tolerance: f64,
    breaks: Vec<f64>,
}

impl<'a> Magnified<'a> {
    /// The model at nominal pressure `pressure` (unit of E*).
    ///
    /// # Errors
    /// E*, σ0 not finite and positive; tolerance outside [1e-15, 0.1]; E*/σ0
    /// so large that G = (E*/σ0)²⟨|∇h|²⟩/8 overflows f64 (naming
    /// `nominal_pressure` or `contact_modulus`, E* when it is beyond 1e±30,
    /// `error::ratio_culprit`).
    pub(crate) fn new(
        spectrum: &'a dyn Spectrum,
        contact_modulus: f64,
        pressure: f64,
        tolerance: f64,
        breaks: &[f64],
    ) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        check::positive("nominal_pressure", pressure)?;
        let (q_l, q_s) = (spectrum.q_min(), spectrum.q_max());
        let slope_variance = std::f64::consts::TAU * spectrum.moment(3, q_l, q_s)?.value;
        crate::theory::check_g_finite(contact_modulus, pressure, slope_variance)?;
        Ok(Magnified {
            spectrum,
            contact_modulus: check::positive("contact_modulus", contact_modulus)?,
            pressure: check::positive("nominal_pressure", pressure)?,
            tolerance: check::tolerance("tolerance", tolerance)?,
            breaks: breaks.to_vec(),
        })
    }

    /// (π/4)(E*/σ0)².
    fn g_factor(&self) -> f64 {
        let r = self.contact_modulus / self.pressure;
        0.25 * std::f64::consts::PI * r * r
    }

    /// Full magnification q_s/q_l.
    pub(crate) fn zeta_max(&self) -> f64 {
        self.spectrum.q_max() / self.spectrum.q_min()
    }

    /// G(ζ) with its error.
    pub(crate) fn g(&self, zeta: f64) -> Result<Estimate> {
        let q_l = self.spectrum.q_min();
        let m = self.spectrum.moment(3, q_l, zeta * q_l)?;
        let f = self.g_factor();
        Ok(Estimate {
            value: f * m.value,
            error: f * m.error + 2.0 * f64::EPSILON * f * m.value,
        })
    }

    /// (A(ζ)/A0, −dA/dζ /A0).
    pub(crate) fn area(&self, zeta: f64) -> Result<(f64, f64)> {
        let g = self.g(zeta)?.value;
        if g <= 0.0 {
            return Ok((1.0, 0.0));
        }
        let q_l = self.spectrum.q_min();
        let q = zeta * q_l;
        let g_prime = self.g_factor() * q_l * q * q * q * self.spectrum.c(q);
        let x = 0.5 / g.sqrt();
        let loss = x * (-x * x).exp() * g_prime / (std::f64::consts::PI.sqrt() * g);
        Ok((erf(x), loss))
    }

    /// ū(ζ), u1(ζ) and the area at one magnification (module docs).
    ///
    /// # Errors
    /// ζ outside [1, q_s/q_l]; quadrature failure.
    pub(crate) fn point(&self, zeta: f64) -> Result<MagnifiedPoint> {
        let zeta_max = self.zeta_max();
        if !(zeta.is_finite() && (1.0..=zeta_max).contains(&zeta)) {
            return Err(Error::invalid(
                "zeta",
                zeta,
                format!("in [1, q_s/q_l = {zeta_max:e}]"),
            ));
        }
        let (a, loss) = self.area(zeta)?;
        let p = self.pressure / a;
        let q_l = self.spectrum.q_min();
        let lo = zeta * q_l;
        let h2 = std::f64::consts::TAU * self.spectrum.moment(1, lo, self.spectrum.q_max())?.value;
        let zero = Estimate {
            value: 0.0,
            error: 0.0,
        };
        let mut out = MagnifiedPoint {
            zeta,
            contact_fraction: a,
            area_loss_rate: loss,
            apparent_pressure: p,
            mean_separation: zero,
            critical_separation: zero,
            volume_rate: zero,
            rms_height: h2.max(0.0).sqrt(),
        };
        if lo >= self.spectrum.q_max() * (1.0 - 1e-12) {
            return Ok(out); // nothing left to resolve: ū = u1 = 0
        }
        let band = Band {
            inner: self.spectrum,
            lo,
        };
        let [u, c, dz] = self.cut_integrals(&band, zeta, p)?;
        out.mean_separation = u;
        let dp = self.pressure * loss / (a * a); // p′(ζ) = −σ0 A′/A² = σ0 loss/A²
                                                 // −∂F/∂p = 1/K = (√π/p) ∫ q² C w e^{−x²} dq
        let compliance = Estimate {
            value: c.value / p,
            error: c.error / p,
        };
        // ū′ = ∂F/∂ζ − p′/K;  u1 = ū + ū′ A/A′ = ū − ū′ A/loss.
        let du = dz.value - dp * compliance.value;
        let du_err = dz.error + dp * compliance.error;
        // (−A′) u1 = loss·ū − ū′·A
        let vol = loss * u.value - du * a;
        out.volume_rate = Estimate {
            value: vol.max(0.0),
            error: loss * u.error
                + a * du_err
                + 8.0 * f64::EPSILON * (loss * u.value + (du * a).abs()),
        };
        out.critical_separation = if loss > 0.0 {
            let ratio = a / loss;
            let u1 = u.value - du * ratio;
            Estimate {
                value: u1.max(0.0),
                error: u.error
                    + ratio * du_err
                    + 8.0 * f64::EPSILON * (u.value.abs() + (du * ratio).abs()),
            }
        } else {
            Estimate {
                value: if du < 0.0 { f64::INFINITY } else { u.value },
                error: 0.0,
            }
        };
        Ok(out)
    }

    /// [F, p/K, ∂F/∂ζ] at (ζ, p) on the cut spectrum `band` (module docs),
    /// in one adaptive pass over shared nodes.
    fn cut_integrals(&self, band: &Band<'_>, zeta: f64, p: f64) -> Result<[Estimate; 3]> {
        let q_l = self.spectrum.q_min();
        let lo = zeta * q_l;
        let dm = q_l * lo * lo * lo * self.spectrum.c(lo); // −∂m3/∂ζ
        let r = p / self.contact_modulus;
        let sqrt_pi = std::f64::consts::PI.sqrt();
        let half_pi = 0.5 * std::f64::consts::PI;
        let kernel = |q: f64, c: f64, w: f64| {
            let x2 = (w * r) * (w * r);
            if x2 >= UNDERFLOW_ARG {
                return [0.0; 3];
            }
            let base = sqrt_pi * q * q * c;
            let (half_e1, ex) = (0.5 * e1(x2), (-x2).exp());
            [
                base * w * half_e1,
                base * w * ex,
                base * half_pi * w * w * w * dm * (half_e1 - ex),
            ]
        };
        let mut out = v_integral(band, &self.breaks, self.tolerance, kernel)?;
        for e in &mut out {
            e.error += 8.0 * f64::EPSILON * e.value.abs();
        }
        Ok(out)
    }
}

/// Gauss–Kronrod G7/K15 on [−1, 1]: abscissae (non-negative half,
/// descending), Kronrod weights, Gauss weights of the odd-indexed abscissae.
const GK_X: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const GK_WK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
const GK_WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// Rounding floor of a panel sum, relative to Σ|panel values| (≈ 100 ulps).
const ROUNDOFF: f64 = 100.0 * f64::EPSILON;

/// A G7/K15 panel of a vector integrand: (first, a, b, Kronrod values, |K − G|).
type Panel<const M: usize> = (bool, f64, f64, [f64; M], [f64; M]);

/// One G7/K15 panel of a vector integrand: (Kronrod values, |K − G|).
fn gk15<const M: usize>(f: &dyn Fn(f64) -> [f64; M], a: f64, b: f64) -> ([f64; M], [f64; M]) {
    let (half, mid) = (0.5 * (b - a), 0.5 * (a + b));
    let (mut k, mut g) = ([0.0; M], [0.0; M]);
    for (j, &x) in GK_X.iter().enumerate() {
        let signs: &[f64] = if x == 0.0 { &[1.0] } else { &[-1.0, 1.0] };
        for &s in signs {
            let y = f(mid + s * half * x);
            for i in 0..M {
                k[i] += GK_WK[j] * y[i];
                if j % 2 == 1 {
                    g[i] += GK_WG[j / 2] * y[i];
                }
            }
        }
    }
    let mut e = [0.0; M];
    for i in 0..M {
        e[i] = (k[i] - g[i]).abs() * half;
        k[i] *= half;
    }
    (k, e)
}

/// The panel ends of [`v_integral`] in v = √ln(q/q_l): 0, v(q_s) and the
/// spectrum's breaks inside (q_l, q_s), sorted, without repeats.
fn knots(q_l: f64, q_s: f64, breaks: &[f64]) -> Vec<f64> {
    let mut knots = vec![0.0, (q_s / q_l).ln().sqrt()];
    for &b in breaks {
        if b.is_finite() && b > q_l && b < q_s {
            knots.push((b / q_l).ln().sqrt());
        }
    }
    knots.sort_by(f64::total_cmp);
    knots.dedup();
    knots
}

/// Per component: the sum of the panels' values, of their error estimates
/// and of the values' magnitudes, in the panels' order.
fn totals<const M: usize>(panels: &[Panel<M>]) -> ([f64; M], [f64; M], [f64; M]) {
    let (mut total, mut error, mut size) = ([0.0; M], [0.0; M], [0.0; M]);
    for p in panels {
        for i in 0..M {
            total[i] += p.3[i];
            error[i] += p.4[i];
            size[i] += p.3[i].abs();
        }
    }
    (total, error, size)
}

/// ∫_{q_min}^{q_max} kernel(q, C(q), w(q)) dq for a spectrum and M integrands
/// sharing their nodes, in v = √(ln(q/q_min)) (v = t² on the first segment),
/// w = (π m3(q_min, q))^{−1/2}: the substitution of [`crate::separation`].
/// Globally adaptive G7/K15: the panel with the largest error relative to its
/// component's total is halved until every component's summed |K − G| is
/// within `tolerance` of its total (or no panel can be halved in f64).
fn v_integral<const M: usize>(
    spectrum: &dyn Spectrum,
    breaks: &[f64],
    tolerance: f64,
    kernel: impl Fn(f64, f64, f64) -> [f64; M],
) -> Result<[Estimate; M]> {
    let q_l = spectrum.q_min();
    let knots = knots(q_l, spectrum.q_max(), breaks);
    let failure: RefCell<Option<Error>> = RefCell::new(None);
    let integrand = |v: f64| -> [f64; M] {
        let delta = q_l * (v * v).exp_m1();
        let q = q_l + delta;
        let width = q - q_l;
        let m3 = if width > 0.0 {
            match spectrum.moment(3, q_l, q) {
                Ok(m) => m.value * (delta / width),
                Err(e) => {
                    failure.borrow_mut().get_or_insert(e);
                    return [0.0; M];
                }
            }
        } else {
            q_l * q_l * q_l * spectrum.c(q_l) * delta
        };
        let c = spectrum.c(q);
        if m3.is_nan() || m3 <= 0.0 || c == 0.0 {
            return [0.0; M];
        }
        let w = 1.0 / (std::f64::consts::PI * m3).sqrt();
        let mut y = kernel(q, c, w);
        for y_i in &mut y {
            *y_i *= 2.0 * v * q;
        }
        y
    };
    // the first segment in t (v = t²), the others in v
    let first = |t: f64| {
        let mut y = integrand(t * t);
        for y_i in &mut y {
            *y_i *= 2.0 * t;
        }
        y
    };
    let pick = |is_first: bool| -> &dyn Fn(f64) -> [f64; M] {
        if is_first {
            &first
        } else {
            &integrand
        }
    };
    let mut panels: Vec<Panel<M>> = Vec::new();
    for (i, pair) in knots.windows(2).enumerate() {
        let (a, b) = if i == 0 {
            (pair[0].sqrt(), pair[1].sqrt())
        } else {
            (pair[0], pair[1])
        };
        let (k, e) = gk15(pick(i == 0), a, b);
        panels.push((i == 0, a, b, k, e));
    }
    let mut evals = 15 * panels.len();
    loop {
        if let Some(e) = failure.borrow_mut().take() {
            return Err(e);
        }
        let (total, error, size) = totals(&panels);
        // A component whose total cancels below its panels' sizes cannot be
        // had to better than rounding of those: the target is the larger of
        // `tolerance` × total and ROUNDOFF × Σ|panel|.
        let mut scale = [0.0; M];
        for i in 0..M {
            scale[i] = (tolerance * total[i].abs())
                .max(ROUNDOFF * size[i])
                .max(f64::MIN_POSITIVE);
        }
        let relative = |e: &[f64; M]| (0..M).map(|i| e[i] / scale[i]).fold(0.0, f64::max);
        let done = (0..M).all(|i| error[i] <= scale[i]);
        // the panel with the largest error relative to its component's total
        let worst = panels
            .iter()
            .enumerate()
            .filter(|(_, p)| p.2 - p.1 > 1e-14 * p.2.abs().max(p.1.abs()))
            .map(|(j, p)| (j, relative(&p.4)))
            .filter(|w| w.1 > 0.0)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        let Some((j, _)) = worst.filter(|_| !done) else {
            return Ok(std::array::from_fn(|i| Estimate {
                value: total[i],
                error: error[i],
            }));
        };
        if evals >= MAX_EVALS {
            return Err(Error::NotConverged {
                what: "q-integrals of the cut separation problem".into(),
                iterations: evals,
                residual: relative(&error),
                tolerance,
            });
        }
        let (is_first, a, b, _, _) = panels.swap_remove(j);
        let m = 0.5 * (a + b);
        let (k1, e1_) = gk15(pick(is_first), a, m);
        let (k2, e2_) = gk15(pick(is_first), m, b);
        panels.push((is_first, a, m, k1, e1_));
        panels.push((is_first, m, b, k2, e2_));
        evals += 30;
    }
}

impl Magnified<'_> {
    /// The magnification ζ_c at which A(ζ_c)/A0 = `fraction`, or `None` when
    /// A/A0 stays above it up to q_s/q_l (the contact never opens that far).
    ///
    /// # Formula
    /// ```text
    /// erf(x_c) = a_c,   G_c = 1/(4 x_c²),   ∫_{q_l}^{ζ_c q_l} q³ C dq = G_c / ((π/4)(E*/σ0)²)
    /// ```
    /// x_c by Newton on erf (quadratic convergence, to 2 ulp); ζ_c by
    /// safeguarded Newton–bisection on the moment in ln ζ, to `tolerance`
    /// relative in ζ.
    ///
    /// # Errors
    /// `fraction` outside (0, 1); moment failures.
    pub(crate) fn zeta_at_fraction(&self, fraction: f64) -> Result<Option<Estimate>> {
        check::open("percolation_threshold", fraction, 0.0, 1.0)?;
        let x = erf_inverse(fraction);
        let g_c = 0.25 / (x * x);
        let target = g_c / self.g_factor();
        let q_l = self.spectrum.q_min();
        let q_s = self.spectrum.q_max();
        let total = self.spectrum.moment(3, q_l, q_s)?.value;
        if total <= target {
            return Ok(None);
        }
        let (mut lo, mut hi) = (0.0f64, (q_s / q_l).ln());
        let mut s = 0.5 * (lo + hi);
        for _ in 0..200 {
            let q = q_l * s.exp();
            let f = self.spectrum.moment(3, q_l, q)?.value - target;
            if f > 0.0 {
                hi = s;
            } else {
                lo = s;
            }
            let slope = q * q * q * q * self.spectrum.c(q);
            let newton = s - f / slope;
            s = if slope > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (hi - lo) <= self.tolerance.min(1e-13) * hi.max(1.0) || f == 0.0 {
                break;
            }
        }
        let zeta = s.exp();
        Ok(Some(Estimate {
            value: zeta,
            error: zeta * (hi - lo).max(4.0 * f64::EPSILON * s.abs()),
        }))
    }
}

/// erf⁻¹(a) for 0 < a < 1 by Newton's method from a logarithmic start.
pub(crate) fn erf_inverse(a: f64) -> f64 {
    // Start: erf(x) ≈ 1 − e^{−x²}·(…) in the tail, ≈ 2x/√π near 0.
    let mut x = if a < 0.9 {
        0.5 * std::f64::consts::PI.sqrt() * a
    } else {
        (-(1.0 - a).ln()).sqrt()
    };
    let c = 2.0 / std::f64::consts::PI.sqrt();
    for _ in 0..100 {
        // Residual against the complement in the tail keeps relative accuracy.
        let r = if a < 0.5 {
            erf(x) - a
        } else {
            (1.0 - a) - crate::special::erfc(x)
        };
        let step = r / (c * (-x * x).exp());
        x -= step;
        if step.abs() <= 2.0 * f64::EPSILON * x.abs() {
            break;
        }
    }
    x
}

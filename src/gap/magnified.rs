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
//! Persson & Yang (2008) Sec. 2 and Lorenz & Persson (2009) ("ū(ζ) … can be
//! calculated from [the ū(p) law] if p is replaced with p(ζ) = F_N/A(ζ) and
//! the integral over q is restricted to q > ζ q_L"). The papers leave w(q)'s
//! lower limit implicit; we cut it too (w_ζ), so that ū(ζ) is exactly the
//! separation theory of the cut spectrum — the boundary term of ∂F/∂ζ then
//! vanishes (w_ζ → ∞ at q = ζ q_l, E1 → 0).
//!
//! u1 follows from the balance of the separation volume (Yang & Persson,
//! J. Phys.: Condens. Matter 20, 215214 (2008), Sec. 4):
//! A(ζ−dζ) ū(ζ−dζ) = A(ζ) ū(ζ) + [A(ζ−dζ) − A(ζ)] u1(ζ), i.e. u1 = (Aū)′/A′.
//! Integrating −A′ u1 = −(Aū)′ from ζ = 1 (A = A0, ū(1) = ū) to q_s/q_l
//! (ū = 0) gives ∫ (−A′/A0) u1 dζ = ū exactly, which the tests use.
//!
//! # Method
//! Every q-integral in v = √(ln(q/(ζq_l))), adaptive Gauss–Kronrod with the
//! relative tolerance `tolerance` (as [`crate::separation`], whose
//! [`Separation`] gives F and K on the cut spectrum). A and A′ are closed
//! forms of the spectrum's exact moment.
//!
//! # References
//! - B. N. J. Persson, C. Yang, J. Phys.: Condens. Matter 20, 315011 (2008),
//!   doi:10.1088/0953-8984/20/31/315011, Sec. 2.
//! - B. Lorenz, B. N. J. Persson, EPL 86, 44006 (2009), doi:10.1209/0295-5075/86/44006.
//! - C. Yang, B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214 (2008),
//!   doi:10.1088/0953-8984/20/21/215214 (u1 = ū + ū′A/A′).

use std::cell::RefCell;

use crate::error::{check, Error, Result};
use crate::quad::{integrate, Estimate};
use crate::separation::Separation;
use crate::special::{e1, erf};
use crate::spectrum::Spectrum;

/// Evaluations allowed per q-integral.
const MAX_EVALS: usize = 2_000_000;

/// Arguments of e^{−x²} and E1(x²) beyond which both underflow.
const UNDERFLOW_ARG: f64 = 745.0;

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
pub struct MagnifiedPoint {
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
pub struct Magnified<'a> {
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
    /// E*, σ0 not finite and positive; tolerance outside [1e-15, 0.1].
    pub fn new(
        spectrum: &'a dyn Spectrum,
        contact_modulus: f64,
        pressure: f64,
        tolerance: f64,
        breaks: &[f64],
    ) -> Result<Self> {
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
    pub fn zeta_max(&self) -> f64 {
        self.spectrum.q_max() / self.spectrum.q_min()
    }

    /// G(ζ) with its error.
    pub fn g(&self, zeta: f64) -> Result<Estimate> {
        let q_l = self.spectrum.q_min();
        let m = self.spectrum.moment(3, q_l, zeta * q_l)?;
        let f = self.g_factor();
        Ok(Estimate {
            value: f * m.value,
            error: f * m.error + 2.0 * f64::EPSILON * f * m.value,
        })
    }

    /// (A(ζ)/A0, −dA/dζ /A0).
    pub fn area(&self, zeta: f64) -> Result<(f64, f64)> {
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
    pub fn point(&self, zeta: f64) -> Result<MagnifiedPoint> {
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
        let sep = Separation::new(&band, self.contact_modulus)?
            .with_tolerance(self.tolerance)?
            .with_breaks(&self.breaks);
        let u = sep.mean_separation(p)?;
        let k = sep.stiffness(p)?;
        out.mean_separation = u;
        let dz = self.d_zeta(&band, zeta, p)?;
        let dp = self.pressure * loss / (a * a); // p′(ζ) = −σ0 A′/A² = σ0 loss/A²
        let compliance = if k.value.is_infinite() {
            zero
        } else {
            Estimate {
                value: 1.0 / k.value,
                error: k.error / (k.value * k.value),
            }
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

    /// ∂F/∂ζ at (ζ, p) on the cut spectrum `band` (module docs).
    fn d_zeta(&self, band: &Band<'_>, zeta: f64, p: f64) -> Result<Estimate> {
        let q_l = self.spectrum.q_min();
        let lo = zeta * q_l;
        let dm = q_l * lo * lo * lo * self.spectrum.c(lo); // −∂m3/∂ζ
        if dm == 0.0 {
            return Ok(Estimate {
                value: 0.0,
                error: 0.0,
            });
        }
        let r = p / self.contact_modulus;
        let sqrt_pi = std::f64::consts::PI.sqrt();
        let half_pi = 0.5 * std::f64::consts::PI;
        let kernel = |q: f64, c: f64, w: f64| {
            let x2 = (w * r) * (w * r);
            if x2 >= UNDERFLOW_ARG {
                0.0
            } else {
                sqrt_pi * q * q * c * half_pi * w * w * w * dm * (0.5 * e1(x2) - (-x2).exp())
            }
        };
        let q = v_integral(band, &self.breaks, self.tolerance, "∂ū/∂ζ", kernel)?;
        Ok(Estimate {
            value: q.value,
            error: q.error + 8.0 * f64::EPSILON * q.value.abs(),
        })
    }
}

/// ∫_{q_min}^{q_max} kernel(q, C(q), w(q)) dq for a spectrum, in
/// v = √(ln(q/q_min)) (v = t² on the first segment), w = (π m3(q_min, q))^{−1/2};
/// the same substitution as [`crate::separation`], see there.
fn v_integral(
    spectrum: &dyn Spectrum,
    breaks: &[f64],
    tolerance: f64,
    what: &str,
    kernel: impl Fn(f64, f64, f64) -> f64,
) -> Result<Estimate> {
    let q_l = spectrum.q_min();
    let q_s = spectrum.q_max();
    let mut knots = vec![0.0, (q_s / q_l).ln().sqrt()];
    for &b in breaks {
        if b.is_finite() && b > q_l && b < q_s {
            knots.push((b / q_l).ln().sqrt());
        }
    }
    knots.sort_by(f64::total_cmp);
    knots.dedup();
    let failure: RefCell<Option<Error>> = RefCell::new(None);
    let integrand = |v: f64| {
        let delta = q_l * (v * v).exp_m1();
        let q = q_l + delta;
        let width = q - q_l;
        let m3 = if width > 0.0 {
            match spectrum.moment(3, q_l, q) {
                Ok(m) => m.value * (delta / width),
                Err(e) => {
                    failure.borrow_mut().get_or_insert(e);
                    return f64::NAN;
                }
            }
        } else {
            q_l * q_l * q_l * spectrum.c(q_l) * delta
        };
        let c = spectrum.c(q);
        if m3.is_nan() || m3 <= 0.0 || c == 0.0 {
            return 0.0;
        }
        let w = 1.0 / (std::f64::consts::PI * m3).sqrt();
        kernel(q, c, w) * 2.0 * v * q
    };
    let mut total = Estimate {
        value: 0.0,
        error: 0.0,
    };
    for (i, pair) in knots.windows(2).enumerate() {
        let r = if i == 0 {
            integrate(
                what,
                |t: f64| integrand(t * t) * 2.0 * t,
                pair[0].sqrt(),
                pair[1].sqrt(),
                f64::MIN_POSITIVE,
                tolerance,
                MAX_EVALS,
            )
        } else {
            integrate(
                what,
                integrand,
                pair[0],
                pair[1],
                f64::MIN_POSITIVE,
                tolerance,
                MAX_EVALS,
            )
        };
        if let Some(e) = failure.borrow_mut().take() {
            return Err(e);
        }
        let r = r?;
        total.value += r.value;
        total.error += r.error;
    }
    Ok(total)
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
    pub fn zeta_at_fraction(&self, fraction: f64) -> Result<Option<Estimate>> {
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

//! A user-supplied closure C(q), integrated adaptively.

use super::{check_range, clip, Spectrum};
use crate::error::{check, Result};
use crate::quad::{integrate, Estimate};

/// A spectrum given by any function C(q) on `[q_min, q_max]`.
///
/// Moments are computed by adaptive Gauss–Kronrod quadrature in `s = ln q`,
/// ```text
/// m_k(a, b) = ∫_{ln a}^{ln b} q^{k+1} C(q) ds,
/// ```
/// which makes power-law integrands smooth over many decades, with breakpoints
/// at the user's kinks. The error estimate of the quadrature is returned.
pub struct FnSpectrum<F> {
    f: F,
    q_min: f64,
    q_max: f64,
    breaks: Vec<f64>,
    tol: f64,
}

impl<F: Fn(f64) -> f64 + Send + Sync> FnSpectrum<F> {
    /// C(q) = `f(q)` on `[q_min, q_max]`, moments to relative tolerance `tol`.
    ///
    /// # Errors
    /// `q_min`, `q_max` not finite and positive, or not `q_min < q_max`;
    /// `tol` outside `[1e-15, 0.1]`.
    pub fn new(f: F, q_min: f64, q_max: f64, tol: f64) -> Result<Self> {
        check::positive("q_min", q_min)?;
        check::positive("q_max", q_max)?;
        if q_max <= q_min {
            return Err(crate::Error::invalid(
                "q_max",
                q_max,
                format!("> q_min = {q_min:e}"),
            ));
        }
        check::tolerance("tolerance", tol)?;
        Ok(FnSpectrum {
            f,
            q_min,
            q_max,
            breaks: Vec::new(),
            tol,
        })
    }

    /// Wavevectors where C(q) has a kink (e.g. a roll-off); the quadrature
    /// splits there.
    pub fn with_breaks(mut self, breaks: &[f64]) -> Self {
        self.breaks = breaks.to_vec();
        self
    }
}

impl<F: Fn(f64) -> f64 + Send + Sync> Spectrum for FnSpectrum<F> {
    fn c(&self, q: f64) -> f64 {
        if q >= self.q_min && q <= self.q_max {
            (self.f)(q)
        } else {
            0.0
        }
    }
    fn q_min(&self) -> f64 {
        self.q_min
    }
    fn q_max(&self) -> f64 {
        self.q_max
    }
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        check_range(a, b)?;
        let Some((a, b)) = clip(a, b, self.q_min, self.q_max) else {
            return Ok(Estimate {
                value: 0.0,
                error: 0.0,
            });
        };
        let mut cuts = vec![a];
        cuts.extend(self.breaks.iter().copied().filter(|&x| x > a && x < b));
        cuts.push(b);
        let kp1 = f64::from(k) + 1.0;
        let mut total = Estimate {
            value: 0.0,
            error: 0.0,
        };
        for w in cuts.windows(2) {
            let g = |s: f64| {
                let q = s.exp();
                q.powf(kp1) * (self.f)(q)
            };
            let r = integrate(
                "spectrum moment",
                g,
                w[0].ln(),
                w[1].ln(),
                0.0,
                self.tol,
                200_000,
            )?;
            total.value += r.value;
            total.error += r.error;
        }
        Ok(total)
    }
}

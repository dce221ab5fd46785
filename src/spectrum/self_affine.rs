//! The self-affine spectrum with a roll-off (Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Eq. 5).

use super::{check_range, clip, power, Spectrum};
use crate::error::{check, Error, Result};
use crate::quad::Estimate;

/// Rounding budget of the closed-form moments, in ulps of the result: two
/// `powf`, one `ln_1p`, one `expm1` and a handful of products.
const MOMENT_ULPS: f64 = 16.0;

/// How the amplitude of a [`SelfAffine`] spectrum is given.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Amplitude {
    /// C(q_r) in m⁴.
    CR(f64),
    /// rms height over `[q_l, q_s]`, m.
    RmsHeight(f64),
    /// rms slope over `[q_l, q_s]`, dimensionless.
    RmsSlope(f64),
}

/// Self-affine spectrum with roll-off.
///
/// # Formula
/// ```text
/// C(q) = C_r                         q_l ≤ q < q_r
/// C(q) = C_r (q/q_r)^{−2(H+1)}       q_r ≤ q ≤ q_s
/// C(q) = 0                           otherwise
/// ```
/// with Hurst exponent H ∈ (0, 1) (fractal dimension D_f = 3 − H), roll-off
/// q_r and cut-offs q_l ≤ q_r < q_s, all in 1/m. The moments
/// `m_k(a,b) = C_r q_r^{k+1} ∫ t^{k} (or t^{k−2H−2}) dt` over `t = q/q_r` are
/// evaluated in closed form by `power::integral`, which is stable as the
/// exponent crosses −1 (H → 0 for `m_1`, H → 1 for `m_3`).
///
/// # References
/// Persson, Bucher & Chiaia, Phys. Rev. B 65, 184106 (2002), Eq. 5, doi:10.1103/PhysRevB.65.184106;
/// the crate docs, Conventions (docs/conventions.md).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SelfAffine {
    q_l: f64,
    q_r: f64,
    q_s: f64,
    hurst: f64,
    c_r: f64,
}

impl SelfAffine {
    /// Build the spectrum, with the amplitude given in any of the three ways.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `q_l`, `q_r`, `q_s`, `hurst` or the
    /// amplitude when non-finite or out of range; [`Error::Inconsistent`] unless
    /// `q_l ≤ q_r < q_s`.
    ///
    /// # Examples
    /// ```
    /// use persson::spectrum::{Amplitude, SelfAffine, Spectrum};
    /// let s = SelfAffine::new(1e4, 1e4, 1e8, 0.8, Amplitude::RmsHeight(1e-6)).unwrap();
    /// let h = s.rms_height(0.0, f64::INFINITY).unwrap().value;
    /// assert!((h - 1e-6).abs() < 1e-20);
    /// ```
    pub fn new(q_l: f64, q_r: f64, q_s: f64, hurst: f64, amplitude: Amplitude) -> Result<Self> {
        check::positive("q_l", q_l)?;
        check::positive("q_r", q_r)?;
        check::positive("q_s", q_s)?;
        check::open("hurst", hurst, 0.0, 1.0)?;
        if !(q_l <= q_r && q_r < q_s) {
            return Err(Error::Inconsistent {
                name: "q_l, q_r, q_s".into(),
                requirement: format!(
                    "q_l <= q_r < q_s, got q_l = {q_l:e}, q_r = {q_r:e}, q_s = {q_s:e}"
                ),
            });
        }
        let mut s = SelfAffine {
            q_l,
            q_r,
            q_s,
            hurst,
            c_r: 1.0,
        };
        // the moments of C/C_r: m1 and m3 per unit C_r, both > 0
        let (unit1, unit3) = (s.moment_exact(1, q_l, q_s), s.moment_exact(3, q_l, q_s));
        let (name, value) = match amplitude {
            Amplitude::CR(c) => ("c_r", check::positive("c_r", c)?),
            Amplitude::RmsHeight(h) => ("rms_height", check::positive("rms_height", h)?),
            Amplitude::RmsSlope(g) => ("rms_slope", check::positive("rms_slope", g)?),
        };
        s.c_r = match amplitude {
            Amplitude::CR(c) => c,
            Amplitude::RmsHeight(h) => h * h / (std::f64::consts::TAU * unit1),
            Amplitude::RmsSlope(g) => g * g / (std::f64::consts::TAU * unit3),
        };
        // C_r and the height and slope variances 2π C_r m_k (every theory's
        // inputs) finite and > 0: checked as computed, and the bounds stated
        // for the amplitude given (the variance is C_r·2π m_k, so the bounds
        // on C_r are f64::MAX/(2π m_k) and on h_rms, h'_rms their √(·2π m_k))
        let variances = [
            std::f64::consts::TAU * unit1 * s.c_r,
            std::f64::consts::TAU * unit3 * s.c_r,
        ];
        if !(s.c_r.is_finite() && s.c_r > 0.0 && variances.iter().all(|v| v.is_finite())) {
            return Err(amplitude_range(name, value, unit1, unit3));
        }
        Ok(s)
    }

    /// Lower cut-off q_l, 1/m.
    pub fn q_l(&self) -> f64 {
        self.q_l
    }
    /// Roll-off wavevector q_r, 1/m.
    pub fn q_r(&self) -> f64 {
        self.q_r
    }
    /// Upper cut-off q_s, 1/m.
    pub fn q_s(&self) -> f64 {
        self.q_s
    }
    /// Hurst exponent H.
    pub fn hurst(&self) -> f64 {
        self.hurst
    }
    /// C(q_r), m⁴.
    pub fn c_r(&self) -> f64 {
        self.c_r
    }

    /// `∫_a^b q^k C(q) dq`, closed form (see the type's docs).
    fn moment_exact(&self, k: i32, a: f64, b: f64) -> f64 {
        let Some((a, b)) = clip(a, b, self.q_l, self.q_s) else {
            return 0.0;
        };
        let k = f64::from(k);
        let scale = self.c_r * self.q_r.powf(k + 1.0);
        let mut sum = 0.0;
        if let Some((a1, b1)) = clip(a, b, self.q_l, self.q_r) {
            sum += power::integral(a1, b1, k, self.q_r);
        }
        if let Some((a2, b2)) = clip(a, b, self.q_r, self.q_s) {
            sum += power::integral(a2, b2, k - 2.0 * self.hurst - 2.0, self.q_r);
        }
        scale * sum
    }
}

/// The error for an amplitude whose C_r, ⟨h²⟩ or ⟨|∇h|²⟩ leaves f64,
/// naming the amplitude given with its range.
///
/// # Bound
/// With u_k = ∫ q^k (C/C_r) dq (closed form), C_r = c_r, h_rms²/(2π u1) or
/// h'²_rms/(2π u3), and the variances are 2π u_k C_r. All finite and C_r > 0
/// (a normal f64) need
/// ```text
/// f64::MIN_POSITIVE ≤ C_r ≤ f64::MAX / (2π max(1, u1, u3))
/// ```
/// i.e. h_rms ∈ √(2π u1 [lo, hi]), h'_rms ∈ √(2π u3 [lo, hi]) for those C_r
/// bounds [lo, hi] (each square root taken apart, so no bound overflows).
fn amplitude_range(name: &str, value: f64, unit1: f64, unit3: f64) -> Error {
    let tau = std::f64::consts::TAU;
    let lo = f64::MIN_POSITIVE;
    let hi = f64::MAX / (tau * unit1.max(unit3).max(1.0 / tau));
    let (lo, hi, what) = match name {
        "rms_height" => {
            let s = (tau * unit1).sqrt();
            (lo.sqrt() * s, hi.sqrt() * s, "the rms height, ")
        }
        "rms_slope" => {
            let s = (tau * unit3).sqrt();
            (lo.sqrt() * s, hi.sqrt() * s, "the rms slope, ")
        }
        _ => (lo, hi, ""),
    };
    Error::invalid(
        name,
        value,
        format!(
            "in [{}, {}] for these cut-offs and H, so that {what}C(q_r) and the height and \
             slope variances 2π∫q C dq, 2π∫q³ C dq are finite, positive f64",
            crate::error::approx(lo),
            crate::error::approx(hi)
        ),
    )
}

impl Spectrum for SelfAffine {
    fn c(&self, q: f64) -> f64 {
        if q < self.q_l || q > self.q_s || q.is_nan() {
            0.0
        } else if q < self.q_r {
            self.c_r
        } else {
            self.c_r * (q / self.q_r).powf(-2.0 * (self.hurst + 1.0))
        }
    }
    fn q_min(&self) -> f64 {
        self.q_l
    }
    fn q_max(&self) -> f64 {
        self.q_s
    }
    fn moment(&self, k: i32, a: f64, b: f64) -> Result<Estimate> {
        check_range(a, b)?;
        Ok(Estimate::rounded(self.moment_exact(k, a, b), MOMENT_ULPS))
    }
}

//! The curvature kernels of the BGT theory: the average over the summits'
//! curvature ratio at a given mean curvature.
//!
//! # Formula
//! ```text
//! K_γ(λ) = ½ ∫_0^1 (1 − v)^γ F(v) e^{−λ v} dv,     λ ≥ 0
//! ```
//! v = c², c = (κ1 − κ2)/(κ1 + κ2), and F the Hertz factor of the quantity
//! ([`super::hertz_ellipse`]): γ = 1, F = 1 for the number of contacts;
//! γ = ½, F = F_A for the area; γ = ¾, F = F_P for the load (F ≡ 1 in the
//! geometric-mean approximation). K is entire in λ and K → 1/(2λ) as λ → ∞
//! (Watson's lemma, F(0) = 1).
//!
//! # Method
//! Built once per process (a few ms, [`std::sync::OnceLock`]):
//! - values at Chebyshev nodes of λ ∈ [0, 1], [1, 4], [4, 16], [16, 64],
//!   [64, 256] by the tanh-sinh rule on v ∈ [0, 1] (step 1/32, |t| ≤ 4,
//!   257 nodes; it absorbs the branch point of (1 − v)^γ F(v) at v = 1, where
//!   F has a logarithmic singularity), and a Chebyshev series of
//!   [`CHEBYSHEV_TERMS`] terms on each interval;
//! - λ > 256: 20-point Gauss–Laguerre in s = λv (exact for degree 39, the
//!   nodes stay below v = 0.26), with F from a Chebyshev series on [0, 1/3],
//!   where F is analytic.
//!
//! Accuracy: the unit tests compare the series with the tanh-sinh sums at
//! step 1/64 (1e-14 relative) and the λ > 256 branch with the direct rule.

use std::sync::OnceLock;

use super::hertz_ellipse::factors;
use super::EllipticHertz;
use crate::error::{Error, Result};

/// Terms of each Chebyshev series.
pub(crate) const CHEBYSHEV_TERMS: usize = 32;

/// Interval ends of the Chebyshev pieces in λ.
const BREAKS: [f64; 6] = [0.0, 1.0, 4.0, 16.0, 64.0, 256.0];

/// tanh-sinh step and half-width in t.
const DE_STEP: f64 = 1.0 / 32.0;
const DE_HALF_WIDTH: f64 = 4.0;

/// Below this 1 − v the integrand is dropped (it is ≤ 1e-30 there).
const END_CUT: f64 = 1e-30;

/// Upper end of the Chebyshev series of F used with Gauss–Laguerre.
const F_SERIES_END: f64 = 1.0 / 3.0;

/// 20-point Gauss–Laguerre nodes and weights (mpmath, 20 digits).
#[allow(clippy::excessive_precision)] // the mpmath digits are kept
const LAGUERRE: [(f64, f64); 20] = [
    (0.070_539_889_691_988_753, 0.168_746_801_851_113_86),
    (0.372_126_818_001_611_44, 0.291_254_362_006_068_28),
    (0.916_582_102_483_273_56, 0.266_686_102_867_001_29),
    (1.707_306_531_028_343_9, 0.166_002_453_269_506_84),
    (2.749_199_255_309_432_1, 0.074_826_064_668_792_371),
    (4.048_925_313_850_886_9, 0.024_964_417_309_283_221),
    (5.615_174_970_861_616_5, 0.006_202_550_844_572_236_8),
    (7.459_017_453_671_063_3, 0.001_144_962_386_476_908_2),
    (9.594_392_869_581_096_8, 0.000_155_741_773_027_811_97),
    (12.038_802_546_964_316, 0.000_015_401_440_865_224_916),
    (14.814_293_442_630_74, 1.086_486_366_517_982_4e-6),
    (17.948_895_520_519_376, 5.330_120_909_556_714_8e-8),
    (21.478_788_240_285_011, 1.757_981_179_050_582e-9),
    (25.451_702_793_186_906, 3.725_502_402_512_320_9e-11),
    (29.932_554_631_700_612, 4.767_529_251_578_190_5e-13),
    (35.013_434_240_479, 3.372_844_243_362_438_4e-15),
    (40.833_057_056_728_571, 1.155_014_339_500_398_8e-17),
    (47.619_994_047_346_502, 1.539_522_140_582_343_6e-20),
    (55.810_795_750_063_899, 5.286_442_725_569_157_8e-24),
    (66.524_416_525_615_754, 1.656_456_612_499_023_3e-28),
];

/// A Chebyshev series on [a, b].
#[derive(Debug, Clone)]
pub(crate) struct Chebyshev {
    a: f64,
    b: f64,
    c: Vec<f64>,
}

impl Chebyshev {
    /// Interpolate `f` at the `n` Chebyshev points of the first kind.
    pub(crate) fn fit(a: f64, b: f64, n: usize, f: impl Fn(f64) -> f64) -> Self {
        let vals: Vec<f64> = Self::nodes(a, b, n).map(f).collect();
        Self::from_values(a, b, &vals)
    }

    /// The `n` Chebyshev points of the first kind on [a, b], in the order
    /// [`Chebyshev::from_values`] expects.
    pub(crate) fn nodes(a: f64, b: f64, n: usize) -> impl Iterator<Item = f64> {
        let pi = std::f64::consts::PI;
        (0..n).map(move |k| {
            let x = (pi * (k as f64 + 0.5) / n as f64).cos();
            0.5 * (a + b) + 0.5 * (b - a) * x
        })
    }

    /// The series through `vals` at [`Chebyshev::nodes`].
    pub(crate) fn from_values(a: f64, b: f64, vals: &[f64]) -> Self {
        let pi = std::f64::consts::PI;
        let n = vals.len();
        let c = (0..n)
            .map(|j| {
                let s: f64 = vals
                    .iter()
                    .enumerate()
                    .map(|(k, v)| v * (pi * j as f64 * (k as f64 + 0.5) / n as f64).cos())
                    .sum();
                s * if j == 0 { 1.0 } else { 2.0 } / n as f64
            })
            .collect();
        Chebyshev { a, b, c }
    }

    /// Three series on the same interval and of the same length at one x, in
    /// one Clenshaw loop (the summit table evaluates its three weights together).
    pub(crate) fn eval3(series: &[Chebyshev; 3], x: f64) -> [f64; 3] {
        let s0 = &series[0];
        let t = (2.0 * x - s0.a - s0.b) / (s0.b - s0.a);
        let (mut b1, mut b2) = ([0.0; 3], [0.0; 3]);
        for k in (1..s0.c.len()).rev() {
            for j in 0..3 {
                let b0 = 2.0 * t * b1[j] - b2[j] + series[j].c[k];
                b2[j] = b1[j];
                b1[j] = b0;
            }
        }
        [0, 1, 2].map(|j| t * b1[j] - b2[j] + series[j].c[0])
    }

    /// The largest magnitude of the last `n` coefficients (an estimate of
    /// the interpolation error once their decay has levelled off).
    pub(crate) fn tail(&self, n: usize) -> f64 {
        self.c
            .iter()
            .rev()
            .take(n)
            .fold(0.0, |m: f64, c| m.max(c.abs()))
    }

    /// Clenshaw summation at x ∈ [a, b].
    pub(crate) fn eval(&self, x: f64) -> f64 {
        let t = (2.0 * x - self.a - self.b) / (self.b - self.a);
        let (mut b1, mut b2) = (0.0, 0.0);
        for &c in self.c.iter().skip(1).rev() {
            let b0 = 2.0 * t * b1 - b2 + c;
            b2 = b1;
            b1 = b0;
        }
        t * b1 - b2 + self.c[0]
    }
}

/// One kernel K_γ.
#[derive(Debug, Clone)]
pub(crate) struct Kernel {
    gamma: f64,
    pieces: Vec<Chebyshev>,
    /// F on [0, 1/3]; `None` for F ≡ 1.
    f_small: Option<Chebyshev>,
}

impl Kernel {
    /// K_γ(λ) for λ ≥ 0.
    pub(crate) fn eval(&self, lambda: f64) -> f64 {
        if lambda <= BREAKS[5] {
            let i = BREAKS[1..].partition_point(|&b| b < lambda).min(4);
            return self.pieces[i].eval(lambda);
        }
        let sum: f64 = LAGUERRE
            .iter()
            .map(|&(s, w)| {
                let v = s / lambda;
                let f = self.f_small.as_ref().map_or(1.0, |c| c.eval(v));
                w * (1.0 - v).powf(self.gamma) * f
            })
            .sum();
        0.5 * sum / lambda
    }
}

/// The three kernels of one Hertz treatment.
#[derive(Debug, Clone)]
pub(crate) struct Kernels {
    /// γ = 1, F = 1: number of contacts.
    pub count: Kernel,
    /// γ = ½, F_A: area.
    pub area: Kernel,
    /// γ = ¾, F_P: load.
    pub load: Kernel,
}

/// The tanh-sinh nodes of [0, 1]: (v, 1 − v, weight).
pub(crate) fn de_nodes(step: f64) -> Vec<(f64, f64, f64)> {
    let half_pi = std::f64::consts::FRAC_PI_2;
    let n = (DE_HALF_WIDTH / step).round() as i64;
    (-n..=n)
        .map(|k| {
            let t = k as f64 * step;
            let s = half_pi * t.sinh();
            // v = 1/(1 + e^{−2s}), 1 − v = 1/(1 + e^{2s}), dv/dt = (π/2) cosh t / (2 cosh² s).
            let v = 1.0 / (1.0 + (-2.0 * s).exp());
            let w = 1.0 / (1.0 + (2.0 * s).exp());
            let weight = step * half_pi * t.cosh() / (2.0 * s.cosh().powi(2));
            (v, w, weight)
        })
        .collect()
}

/// g(v) = (1 − v)^γ F(v) at the nodes, for the three kernels.
struct Integrand {
    gamma: f64,
    nodes: Vec<(f64, f64)>, // (v, weight·g)
}

impl Integrand {
    fn value(&self, lambda: f64) -> f64 {
        0.5 * self
            .nodes
            .iter()
            .map(|&(v, wg)| wg * (-lambda * v).exp())
            .sum::<f64>()
    }

    fn kernel(&self, f_small: Option<Chebyshev>) -> Kernel {
        let pieces = BREAKS
            .windows(2)
            .map(|w| Chebyshev::fit(w[0], w[1], CHEBYSHEV_TERMS, |l| self.value(l)))
            .collect();
        Kernel {
            gamma: self.gamma,
            pieces,
            f_small,
        }
    }
}

/// Build the kernels of a treatment from the tanh-sinh rule of step `step`.
pub(crate) fn build(hertz: EllipticHertz, step: f64) -> Result<Kernels> {
    let nodes = de_nodes(step);
    let mut count = Vec::with_capacity(nodes.len());
    let mut area = Vec::with_capacity(nodes.len());
    let mut load = Vec::with_capacity(nodes.len());
    for &(v, w, weight) in &nodes {
        if w < END_CUT {
            continue;
        }
        let f = match hertz {
            EllipticHertz::Exact => factors(v, w)?,
            EllipticHertz::GeometricMean => super::hertz_ellipse::Factors {
                area: 1.0,
                load: 1.0,
            },
        };
        count.push((v, weight * w));
        area.push((v, weight * w.sqrt() * f.area));
        load.push((v, weight * w.powf(0.75) * f.load));
    }
    let small = |which: fn(super::hertz_ellipse::Factors) -> f64| -> Result<Option<Chebyshev>> {
        if hertz == EllipticHertz::GeometricMean {
            return Ok(None);
        }
        let vals = Chebyshev::nodes(0.0, F_SERIES_END, CHEBYSHEV_TERMS)
            .map(|v| factors(v, 1.0 - v).map(which))
            .collect::<Result<Vec<f64>>>()?;
        Ok(Some(Chebyshev::from_values(0.0, F_SERIES_END, &vals)))
    };
    Ok(Kernels {
        count: Integrand {
            gamma: 1.0,
            nodes: count,
        }
        .kernel(None),
        area: Integrand {
            gamma: 0.5,
            nodes: area,
        }
        .kernel(small(|f| f.area)?),
        load: Integrand {
            gamma: 0.75,
            nodes: load,
        }
        .kernel(small(|f| f.load)?),
    })
}

static EXACT: OnceLock<Option<Kernels>> = OnceLock::new();
static GEOMETRIC_MEAN: OnceLock<Option<Kernels>> = OnceLock::new();

/// The process-wide kernels of a treatment (built on first use).
///
/// # Errors
/// [`Error::NotConverged`] if the elliptic Hertz factors could not be
/// computed (not expected; the build is deterministic).
pub(crate) fn kernels(hertz: EllipticHertz) -> Result<&'static Kernels> {
    let cell = match hertz {
        EllipticHertz::Exact => &EXACT,
        EllipticHertz::GeometricMean => &GEOMETRIC_MEAN,
    };
    cell.get_or_init(|| build(hertz, DE_STEP).ok())
        .as_ref()
        .ok_or_else(|| Error::NotConverged {
            what: "BGT curvature kernels (elliptic Hertz factors)".into(),
            iterations: 0,
            residual: f64::NAN,
            tolerance: f64::EPSILON,
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chebyshev series and Laguerre branch against the direct tanh-sinh sum at
    /// half the step: interpolation and quadrature error together.
    const KERNEL_TOL: f64 = 1e-14;

    #[test]
    fn series_match_the_direct_rule() {
        for hertz in [EllipticHertz::Exact, EllipticHertz::GeometricMean] {
            let k = kernels(hertz).unwrap();
            // Direct sums at step/2 for the three kernels.
            let nodes = de_nodes(DE_STEP / 2.0);
            for lambda in [
                0.0, 0.3, 1.0, 2.7, 9.9, 30.0, 100.0, 255.0, 256.5, 400.0, 1e3,
            ] {
                for (kern, gamma, which) in [
                    (&k.count, 1.0, 0usize),
                    (&k.area, 0.5, 1),
                    (&k.load, 0.75, 2),
                ] {
                    let direct: f64 = nodes
                        .iter()
                        .filter(|n| n.1 >= END_CUT)
                        .map(|&(v, w, wt)| {
                            let f = match (hertz, which) {
                                (_, 0) | (EllipticHertz::GeometricMean, _) => 1.0,
                                (_, 1) => factors(v, w).unwrap().area,
                                _ => factors(v, w).unwrap().load,
                            };
                            wt * w.powf(gamma) * f * (-lambda * v).exp()
                        })
                        .sum::<f64>()
                        * 0.5;
                    let got = kern.eval(lambda);
                    assert!(
                        ((got - direct) / direct).abs() < KERNEL_TOL,
                        "{hertz:?} γ = {gamma}, λ = {lambda}: {got} vs {direct}"
                    );
                }
            }
        }
    }

    #[test]
    fn count_kernel_closed_form() {
        // K_1(λ) = ½ [1/λ − (1 − e^{−λ})/λ²], K_1(0) = ¼.
        let k = kernels(EllipticHertz::GeometricMean).unwrap();
        for lambda in [0.5f64, 3.0, 20.0, 100.0, 500.0] {
            let exact = 0.5 * (1.0 / lambda - (-(-lambda).exp_m1()) / (lambda * lambda));
            let got = k.count.eval(lambda);
            assert!(
                ((got - exact) / exact).abs() < KERNEL_TOL,
                "λ = {lambda}: {got} vs {exact}"
            );
        }
        assert!((k.count.eval(0.0) - 0.25).abs() < KERNEL_TOL);
    }

    #[test]
    fn laguerre_rule_is_exact_for_polynomials() {
        // Σ w s^k = k! for k ≤ 39.
        let mut fact = 1.0;
        for k in 0..30 {
            if k > 0 {
                fact *= k as f64;
            }
            let s: f64 = LAGUERRE.iter().map(|&(x, w)| w * x.powi(k)).sum();
            assert!(((s - fact) / fact).abs() < 1e-13, "k = {k}: {s} vs {fact}");
        }
    }
}

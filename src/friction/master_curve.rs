//! A measured viscoelastic master curve (a DMA export): E′(ω), E″(ω) at the
//! reference temperature, log-log interpolated, and its angular integrals
//! A(w), B(w) computed exactly segment by segment.
//!
//! # Formula
//! Between table points i and i + 1 each modulus is a power law,
//! ```text
//! E(ω) = E_i (ω/ω_i)^{s_i},   s_i = ln(E_{i+1}/E_i) / ln(ω_{i+1}/ω_i)
//! ```
//! and outside the table it is held at the end values (the choice made here:
//! a power-law continuation of a master curve's end is unreliable, and every
//! use outside the table is reported, see [`super::TableExcursion`]).
//! With u = cos φ, a segment [lo, hi] ⊂ (0, 1] of u (lo = ω_i/w) contributes
//! ```text
//! ∫_lo^hi V(w u) u^m (1 − u²)^{−1/2} du,   V = E″ (m = 1, for A), E′² or E″² (m = 0, for B)
//! = V(w lo) lo^{m+1} Σ_k c_k lo^{2k} (ρ^{n_k} − 1)/n_k,   c_k = C(2k, k)/4^k,  ρ = hi/lo,  n_k = σ + m + 1 + 2k
//! = V(w lo) lo^{−σ} Σ_k C(β, k)(−1)^k [v^{k+1/2}]_{1−hi²}^{1−lo²}/(2k + 1),   β = (σ + m − 1)/2
//! ```
//! (σ the segment's exponent of V): the first series (binomial expansion of
//! (1 − u²)^{−1/2}) for hi ≤ 3/4, the second (expansion of u^{σ+m−1} in
//! v = 1 − u²) for lo ≥ 3/4; both converge at least like (9/16)^k and every
//! term of the first is positive. The clamped ends integrate in closed form:
//! ∫_0^a u/√(1−u²) du = 1 − √(1 − a²), ∫_0^a du/√(1−u²) = arcsin a.
//!
//! # References
//! - M. Abramowitz, I. A. Stegun, *Handbook of Mathematical Functions* (1964),
//!   Eq. 3.6.8 (the binomial series).
//! - J. D. Ferry, *Viscoelastic Properties of Polymers*, 3rd ed. (Wiley, 1980),
//!   ch. 11 (master curves by time–temperature superposition).

use std::f64::consts::TAU;
use std::path::Path;

use super::columns::{cell_error, parse_rows, Row};
use super::modulus::{modulus_requirement, AngularIntegrals, Modulus, MAX_MODULUS};
use crate::error::{Error, Result};

/// The boundary between the two series of the segment integral.
const SPLIT: f64 = 0.75;

/// Relative size of the last term kept in the series (below the f64 epsilon).
const SERIES_TOL: f64 = 1e-17;

/// Term cap of the series: (9/16)^k < 1e-17 at k = 68.
const SERIES_MAX_TERMS: usize = 400;

/// The minimum number of points of a master curve.
const MIN_POINTS: usize = 3;

/// The unit of a master curve's frequency column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrequencyUnit {
    /// Angular frequency ω in rad/s.
    RadPerSecond,
    /// Frequency f in Hz (ω = 2π f).
    Hertz,
}

crate::names::named! {
    FrequencyUnit, "frequency_unit", "The unit of a master curve's frequency column." {
        RadPerSecond = "rad/s": "Angular frequency ω in rad/s.",
        Hertz = "Hz": "Frequency f in Hz (ω = 2π f).",
    }
}

/// A master curve E′(ω), E″(ω) at the reference temperature, log-log
/// interpolated and held at its end values outside the table.
#[derive(Debug, Clone, PartialEq)]
pub struct MasterCurve {
    omega: Vec<f64>,
    ln_omega: Vec<f64>,
    storage: Vec<f64>,
    loss: Vec<f64>,
    storage_slope: Vec<f64>,
    loss_slope: Vec<f64>,
}

impl MasterCurve {
    /// From points (ω in rad/s, E′, E″ in Pa), in increasing or decreasing ω.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `frequency[i]`, `storage_modulus[i]`
    /// or `loss_modulus[i]` (0-based) for a value not finite and > 0, a
    /// modulus above [`MAX_MODULUS`], a repeated or
    /// non-monotone frequency; fewer than 3 points.
    pub fn new(points: &[(f64, f64, f64)]) -> Result<Self> {
        if points.len() < MIN_POINTS {
            return Err(Error::invalid(
                "number of master-curve points",
                points.len() as f64,
                "at least 3",
            ));
        }
        let positive = |name: &str, i: usize, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(Error::invalid(format!("{name}[{i}]"), v, "finite and > 0"))
            }
        };
        let modulus = |name: &str, i: usize, v: f64| {
            if v.is_finite() && v > 0.0 && v <= MAX_MODULUS {
                Ok(())
            } else {
                Err(Error::invalid(
                    format!("{name}[{i}]"),
                    v,
                    modulus_requirement(),
                ))
            }
        };
        for (i, &(w, e1, e2)) in points.iter().enumerate() {
            positive("frequency", i, w)?;
            modulus("storage_modulus", i, e1)?;
            modulus("loss_modulus", i, e2)?;
        }
        let ascending = points[1].0 > points[0].0;
        for i in 1..points.len() {
            let (prev, w) = (points[i - 1].0, points[i].0);
            if w == prev {
                return Err(Error::invalid(
                    format!("frequency[{i}]"),
                    w,
                    format!("different from frequency[{}] (a repeated frequency)", i - 1),
                ));
            }
            if (w > prev) != ascending {
                return Err(Error::invalid(
                    format!("frequency[{i}]"),
                    w,
                    format!(
                        "{} than frequency[{}] = {prev:e} (frequencies must be monotone)",
                        if ascending { "greater" } else { "less" },
                        i - 1
                    ),
                ));
            }
        }
        let mut pts = points.to_vec();
        if !ascending {
            pts.reverse();
        }
        let omega: Vec<f64> = pts.iter().map(|p| p.0).collect();
        let storage: Vec<f64> = pts.iter().map(|p| p.1).collect();
        let loss: Vec<f64> = pts.iter().map(|p| p.2).collect();
        let slope = |v: &[f64]| -> Vec<f64> {
            (0..v.len() - 1)
                .map(|i| (v[i + 1] / v[i]).ln() / ((omega[i + 1] - omega[i]) / omega[i]).ln_1p())
                .collect()
        };
        Ok(MasterCurve {
            ln_omega: omega.iter().map(|w| w.ln()).collect(),
            storage_slope: slope(&storage),
            loss_slope: slope(&loss),
            omega,
            storage,
            loss,
        })
    }

    /// Read a DMA export: three columns ω (or f), E′, E″ (Pa), `#` comments,
    /// an optional header line; the frequency unit is the caller's.
    ///
    /// # Errors
    /// [`Error::Io`]; [`Error::Parse`] with the file's line for a cell that is
    /// not a number, a row without three columns, a frequency or modulus not
    /// finite and > 0, a modulus above [`MAX_MODULUS`], a
    /// repeated or non-monotone frequency; fewer than 3 rows.
    pub fn from_file(path: &Path, unit: FrequencyUnit) -> Result<Self> {
        Self::from_bytes(path, &crate::io::read(path)?, unit)
    }

    /// [`MasterCurve::from_file`] on content in memory (`path` names it in errors).
    ///
    /// # Errors
    /// As [`MasterCurve::from_file`], without the I/O errors.
    pub fn from_bytes(path: &Path, bytes: &[u8], unit: FrequencyUnit) -> Result<Self> {
        let freq = match unit {
            FrequencyUnit::RadPerSecond => "omega",
            FrequencyUnit::Hertz => "f",
        };
        let rows = parse_rows(path, bytes, &[freq, "storage_modulus", "loss_modulus"], 0)?;
        check_rows(path, &rows, freq)?;
        let scale = match unit {
            FrequencyUnit::RadPerSecond => 1.0,
            FrequencyUnit::Hertz => TAU,
        };
        let points: Vec<(f64, f64, f64)> = rows
            .iter()
            .map(|r| (r.values[0] * scale, r.values[1], r.values[2]))
            .collect();
        Self::new(&points).map_err(|e| Error::parse(path, 0, 0, e.to_string()))
    }

    /// The table (ω in rad/s, E′, E″), in increasing ω.
    pub(crate) fn points(&self) -> impl Iterator<Item = (f64, f64, f64)> + '_ {
        (0..self.omega.len()).map(|i| (self.omega[i], self.storage[i], self.loss[i]))
    }

    /// The tabulated angular frequencies, increasing, rad/s.
    pub fn frequencies(&self) -> &[f64] {
        &self.omega
    }

    /// (ω_min, ω_max) of the table, rad/s.
    pub fn frequency_range(&self) -> (f64, f64) {
        (self.omega[0], self.omega[self.omega.len() - 1])
    }

    /// E(ω) by log-log interpolation, held at the end values outside the table
    /// (ω in rad/s, any sign: E(−ω) = conj E(ω)).
    pub(crate) fn modulus(&self, omega: f64) -> Modulus {
        let w = omega.abs();
        let n = self.omega.len();
        let (e1, e2) = if w <= self.omega[0] {
            (self.storage[0], self.loss[0])
        } else if w >= self.omega[n - 1] {
            (self.storage[n - 1], self.loss[n - 1])
        } else {
            let i = self.omega.partition_point(|&x| x <= w) - 1;
            let l = (w / self.omega[i]).ln();
            (
                self.storage[i] * (self.storage_slope[i] * l).exp(),
                self.loss[i] * (self.loss_slope[i] * l).exp(),
            )
        };
        Modulus::new(e1, if omega < 0.0 { -e2 } else { e2 })
    }

    /// A(w), B(w) exactly (module docs) with the parts from outside the table;
    /// O(number of points below w).
    pub(crate) fn angular(&self, w: f64) -> AngularIntegrals {
        self.angular_ln(w.ln())
    }

    /// [`Self::angular`] at y = ln w. The ratios u_i = ω_i/w = e^{−(y − ln ω_i)}
    /// and 1 − u_i² = −expm1(−2(y − ln ω_i)) come from log differences: the
    /// out-of-table parts vary like √(1 − u²) at the table's ends, where a
    /// ratio rounded to 1 ± ε would cost √ε.
    pub(crate) fn angular_ln(&self, y: f64) -> AngularIntegrals {
        let n = self.omega.len();
        let sq = |i: usize| self.storage[i].powi(2) + self.loss[i].powi(2);
        let ln_w = &self.ln_omega;
        // Below the table: u ∈ [0, a0], E = E_0; 1 − √(1 − a0²) = a0²/(1 + √(1 − a0²)).
        let d0 = (y - ln_w[0]).max(0.0);
        let (a0, c0) = ((-d0).exp(), (-(-2.0 * d0).exp_m1()).sqrt());
        let mut r = AngularIntegrals {
            loss_outside: self.loss[0] * a0 * a0 / (1.0 + c0),
            modulus_squared_outside: sq(0) * a0.atan2(c0), // arcsin a0
            ..Default::default()
        };
        for i in 0..n - 1 {
            if y <= ln_w[i] {
                break;
            }
            let lo = (ln_w[i] - y).exp();
            let hi = (ln_w[i + 1] - y).exp().min(1.0);
            r.loss += segment(self.loss[i], self.loss_slope[i], 1, lo, hi);
            let e1 = segment(
                self.storage[i].powi(2),
                2.0 * self.storage_slope[i],
                0,
                lo,
                hi,
            );
            let e2 = segment(self.loss[i].powi(2), 2.0 * self.loss_slope[i], 0, lo, hi);
            r.modulus_squared += e1 + e2;
        }
        let dt = y - ln_w[n - 1];
        if dt > 0.0 {
            // Above the table: u ∈ [top, 1]: √(1 − top²) and arccos(top).
            let (top, ct) = ((-dt).exp(), (-(-2.0 * dt).exp_m1()).sqrt());
            r.loss_outside += self.loss[n - 1] * ct;
            r.modulus_squared_outside += sq(n - 1) * ct.atan2(top); // arccos top
        }
        r.loss += r.loss_outside;
        r.modulus_squared += r.modulus_squared_outside;
        r
    }
}

/// Check the rows of a master-curve file, naming the line.
fn check_rows(path: &Path, rows: &[Row], freq: &str) -> Result<()> {
    if rows.len() < MIN_POINTS {
        return Err(Error::parse(
            path,
            0,
            0,
            format!("{} data rows: a master curve needs at least 3", rows.len()),
        ));
    }
    let names = [freq, "storage_modulus", "loss_modulus"];
    for row in rows {
        for (j, name) in names.iter().enumerate() {
            let v = row.values[j];
            if !(v.is_finite() && v > 0.0) {
                return Err(cell_error(path, row, name, v, "finite and > 0"));
            }
            if j > 0 && v > MAX_MODULUS {
                return Err(cell_error(path, row, name, v, &modulus_requirement()));
            }
        }
    }
    let ascending = rows[1].values[0] > rows[0].values[0];
    for pair in rows.windows(2) {
        let (prev, w) = (pair[0].values[0], pair[1].values[0]);
        if w == prev {
            let msg = format!(
                "different from line {}'s (a repeated frequency)",
                pair[0].line
            );
            return Err(cell_error(path, &pair[1], freq, w, &msg));
        }
        if (w > prev) != ascending {
            let msg = format!(
                "{} than {} on line {} (frequencies must be monotone)",
                if ascending { "greater" } else { "less" },
                crate::error::num(prev),
                pair[0].line
            );
            return Err(cell_error(path, &pair[1], freq, w, &msg));
        }
    }
    Ok(())
}

/// V_lo ∫_lo^hi (u/lo)^σ u^m (1 − u²)^{−1/2} du for 0 < lo < hi ≤ 1.
pub(crate) fn segment(v_lo: f64, sigma: f64, m: i32, lo: f64, hi: f64) -> f64 {
    if hi <= lo {
        return 0.0;
    }
    if hi <= SPLIT {
        v_lo * series_low(sigma, m, lo, hi)
    } else if lo >= SPLIT {
        v_lo * lo.powf(-sigma) * series_high(sigma + f64::from(m), lo, hi)
    } else {
        let v_split = v_lo * (SPLIT / lo).powf(sigma);
        v_lo * series_low(sigma, m, lo, SPLIT)
            + v_split * SPLIT.powf(-sigma) * series_high(sigma + f64::from(m), SPLIT, hi)
    }
}

/// ∫_lo^hi (u/lo)^σ u^m (1 − u²)^{−1/2} du for hi ≤ 3/4: the binomial series.
fn series_low(sigma: f64, m: i32, lo: f64, hi: f64) -> f64 {
    let ln_rho = ((hi - lo) / lo).ln_1p();
    let base = sigma + f64::from(m) + 1.0;
    let rho_base = (base * ln_rho).exp();
    let (lo2, hi2) = (lo * lo, hi * hi);
    let (mut c, mut lo_pow, mut hi_pow) = (1.0, 1.0, 1.0); // c_k, lo^{2k}, hi^{2k}
    let mut sum = 0.0;
    for k in 0..SERIES_MAX_TERMS {
        let n = base + 2.0 * k as f64;
        let x = n * ln_rho;
        // lo^{2k} (ρ^n − 1)/n = (ρ^{base} hi^{2k} − lo^{2k})/n: by expm1 where
        // the difference would cancel, directly elsewhere.
        let ratio = if n == 0.0 {
            lo_pow * ln_rho
        } else if x.abs() < 0.5 {
            lo_pow * x.exp_m1() / n
        } else {
            (hi_pow * rho_base - lo_pow) / n
        };
        let term = c * ratio;
        sum += term;
        if k > 0 && term.abs() <= SERIES_TOL * sum.abs() {
            break;
        }
        c *= (2 * k + 1) as f64 / (2 * k + 2) as f64;
        lo_pow *= lo2;
        hi_pow *= hi2;
    }
    sum * lo.powi(m + 1)
}

/// ∫_lo^hi u^p (1 − u²)^{−1/2} du for lo ≥ 3/4: the series in v = 1 − u².
fn series_high(p: f64, lo: f64, hi: f64) -> f64 {
    let beta = 0.5 * (p - 1.0);
    let v_hi = (1.0 - lo) * (1.0 + lo);
    let v_lo = (1.0 - hi) * (1.0 + hi);
    // ln(v_hi/v_lo) ≥ 0 from the exact difference v_hi − v_lo = (hi − lo)(hi + lo).
    let ln_ratio = if v_lo > 0.0 {
        ((hi - lo) * (hi + lo) / v_lo).ln_1p()
    } else {
        f64::INFINITY
    };
    let mut d = 1.0; // C(β, k)(−1)^k
    let mut sum = 0.0;
    let (mut hi_pow, mut lo_pow) = (v_hi.sqrt(), v_lo.sqrt()); // v^{k+1/2}
    for k in 0..SERIES_MAX_TERMS {
        let e = k as f64 + 0.5;
        // v_hi^e − v_lo^e: by expm1 where it would cancel, directly elsewhere.
        let diff = if e * ln_ratio < 0.5 {
            hi_pow * -(-e * ln_ratio).exp_m1()
        } else {
            hi_pow - lo_pow
        };
        let term = d * diff / (2 * k + 1) as f64;
        sum += term;
        if k > 0 && term.abs() <= SERIES_TOL * sum.abs() {
            break;
        }
        d *= (k as f64 - beta) / (k + 1) as f64;
        hi_pow *= v_hi;
        lo_pow *= v_lo;
    }
    sum
}

impl MasterCurve {
    /// The table's ln ω_i: where A and B have their (w − ω_i)^{3/2} kinks.
    pub(crate) fn ln_frequencies(&self) -> Vec<f64> {
        self.ln_omega.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quad::integrate;
    use std::f64::consts::FRAC_PI_2;

    /// A(w) and B(w) of a constant modulus: E″ and (π/2)|E|².
    fn constant(e1: f64, e2: f64) -> (f64, f64) {
        (e2, FRAC_PI_2 * (e1 * e1 + e2 * e2))
    }

    /// The series against adaptive Gauss–Kronrod at 1e-14: both near rounding.
    const SEGMENT_TOL: f64 = 1e-13;

    #[test]
    fn segment_matches_quadrature() {
        for &(sigma, m) in &[
            (0.0, 1),
            (0.37, 1),
            (-0.8, 1),
            (1.6, 0),
            (-2.5, 0),
            (-1.0, 0),
            (-2.0, 1),
        ] {
            for &(lo, hi) in &[
                (1e-6f64, 3e-6f64),
                (0.1, 0.5),
                (0.5, 0.9),
                (0.8, 0.95),
                (0.7, 1.0),
                (0.2, 1.0),
                (0.9999, 1.0),
            ] {
                let f = |u: f64| (u / lo).powf(sigma) * u.powi(m) / ((1.0 - u) * (1.0 + u)).sqrt();
                // Near u = 1, u = cos φ removes the endpoint singularity; far
                // from it u itself (cos φ near π/2 would lose digits).
                let q = if hi <= 0.5 {
                    integrate("seg", f, lo, hi, 0.0, 1e-14, 1_000_000).unwrap()
                } else {
                    let (pa, pb) = (hi.acos(), lo.acos());
                    let g = |p: f64| (p.cos() / lo).powf(sigma) * p.cos().powi(m); // du/√(1−u²) = dφ
                    integrate("seg", g, pa, pb, 0.0, 1e-14, 1_000_000).unwrap()
                };
                let s = segment(1.0, sigma, m, lo, hi);
                assert!(
                    (s - q.value).abs() <= SEGMENT_TOL * q.value,
                    "σ {sigma} m {m} [{lo}, {hi}]: {s} vs {}",
                    q.value
                );
            }
        }
    }

    #[test]
    fn constant_table_gives_constant_integrals() {
        let t = MasterCurve::new(&[(1.0, 2e6, 3e5), (10.0, 2e6, 3e5), (100.0, 2e6, 3e5)]).unwrap();
        let (a, b) = constant(2e6, 3e5);
        for &w in &[1e-3, 1.0, 5.0, 50.0, 1e3, 1e9] {
            let r = t.angular(w);
            assert!((r.loss - a).abs() <= 1e-14 * a, "A({w}) = {}", r.loss);
            assert!((r.modulus_squared - b).abs() <= 1e-14 * b, "B({w})");
        }
    }

    #[test]
    fn interpolation_and_clamping() {
        let t = MasterCurve::new(&[(100.0, 4e6, 1e6), (10.0, 2e6, 2e5), (1.0, 1e6, 1e5)]).unwrap();
        assert_eq!(t.frequency_range(), (1.0, 100.0));
        let e = t.modulus(10f64.sqrt());
        assert!((e.storage_modulus - 2e6 / 2f64.sqrt()).abs() < 1e-8);
        assert!((e.loss_modulus - 1e5 * 2f64.sqrt()).abs() < 1e-9);
        assert_eq!(t.modulus(1e-9).loss_modulus, 1e5);
        assert_eq!(t.modulus(-1e9).loss_modulus, -1e6);
    }
}

//! Time–temperature superposition: the horizontal shift factor a_T (WLF or a
//! table) and the optional vertical shift b_T.
//!
//! # Formula
//! ```text
//! E(ω, T) = b_T E(a_T ω, T_ref)
//! WLF:       log10 a_T = −C1 (T − T_ref) / (C2 + T − T_ref)      (T − T_ref > −C2)
//! table:     ln a_T linear in T between the rows; b_T linear in T
//! entropic:  b_T = T / T_ref
//! ```
//! Temperatures in K (C2 in K, C1 dimensionless). a_T < 1 above T_ref: a hotter
//! rubber behaves as the reference rubber at a lower frequency.
//!
//! # References
//! - M. L. Williams, R. F. Landel, J. D. Ferry, J. Am. Chem. Soc. 77, 3701
//!   (1955), doi:10.1021/ja01619a008 (the WLF equation).
//! - J. D. Ferry, *Viscoelastic Properties of Polymers*, 3rd ed. (Wiley, 1980),
//!   ch. 11 (reduced variables; the vertical factor T ρ/(T_ref ρ_ref), here
//!   with ρ constant).

use std::f64::consts::LN_10;
use std::path::Path;

use super::columns::{cell_error, parse_rows};
use crate::error::{check, Error, Result};

/// a_T and b_T at one temperature.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[non_exhaustive]
pub struct ShiftFactors {
    /// Horizontal shift a_T (dimensionless).
    pub shift_factor: f64,
    /// Vertical shift b_T (dimensionless).
    pub vertical_shift: f64,
}

/// A table a_T(T) (and optionally b_T(T)).
#[derive(Debug, Clone, PartialEq)]
pub struct ShiftTable {
    temperature: Vec<f64>,
    ln_shift: Vec<f64>,
    vertical: Option<Vec<f64>>,
}

impl ShiftTable {
    /// From rows (T in K, a_T[, b_T]); increasing or decreasing T; every row
    /// with the same number of columns.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `temperature[i]`, `shift_factor[i]` or
    /// `vertical_shift[i]` for a value not finite and > 0 or a repeated or
    /// non-monotone temperature; fewer than 2 rows.
    pub fn new(rows: &[(f64, f64, Option<f64>)]) -> Result<Self> {
        if rows.len() < 2 {
            return Err(Error::invalid(
                "number of shift-table rows",
                rows.len() as f64,
                "at least 2",
            ));
        }
        let with_b = rows[0].2.is_some();
        for (i, r) in rows.iter().enumerate() {
            let bad =
                |name: &str, v: f64| Error::invalid(format!("{name}[{i}]"), v, "finite and > 0");
            if !(r.0.is_finite() && r.0 > 0.0) {
                return Err(bad("temperature", r.0));
            }
            if !(r.1.is_finite() && r.1 > 0.0) {
                return Err(bad("shift_factor", r.1));
            }
            match r.2 {
                Some(b) if !(b.is_finite() && b > 0.0) => return Err(bad("vertical_shift", b)),
                b if b.is_some() != with_b => {
                    return Err(Error::invalid(
                        format!("vertical_shift[{i}]"),
                        b.unwrap_or(f64::NAN),
                        "given on every row or on none",
                    ))
                }
                _ => {}
            }
        }
        let ascending = rows[1].0 > rows[0].0;
        for i in 1..rows.len() {
            let (prev, t) = (rows[i - 1].0, rows[i].0);
            if t == prev || (t > prev) != ascending {
                return Err(Error::invalid(
                    format!("temperature[{i}]"),
                    t,
                    format!("strictly monotone (temperature[{}] = {prev})", i - 1),
                ));
            }
        }
        let mut r = rows.to_vec();
        if !ascending {
            r.reverse();
        }
        Ok(ShiftTable {
            temperature: r.iter().map(|x| x.0).collect(),
            ln_shift: r.iter().map(|x| x.1.ln()).collect(),
            vertical: with_b.then(|| r.iter().map(|x| x.2.unwrap_or(1.0)).collect()),
        })
    }

    /// Read a shift table: columns `T, a_T` or `T, a_T, b_T` (K, –, –), `#` comments.
    ///
    /// # Errors
    /// [`Error::Io`]; [`Error::Parse`] naming the line of a cell that is not a
    /// number, not finite and > 0, or a repeated or non-monotone temperature.
    pub fn from_file(path: &Path) -> Result<Self> {
        Self::from_bytes(path, &crate::io::read(path)?)
    }

    /// [`ShiftTable::from_file`] on content in memory.
    ///
    /// # Errors
    /// As [`ShiftTable::from_file`], without the I/O errors.
    pub fn from_bytes(path: &Path, bytes: &[u8]) -> Result<Self> {
        let names = ["temperature", "shift_factor", "vertical_shift"];
        let rows = parse_rows(path, bytes, &names, 1)?;
        for row in &rows {
            for (j, &v) in row.values.iter().enumerate() {
                if !(v.is_finite() && v > 0.0) {
                    return Err(cell_error(path, row, names[j], v, "finite and > 0"));
                }
            }
            if row.values.len() != rows[0].values.len() {
                return Err(Error::parse(
                    path,
                    row.line,
                    0,
                    "every row needs the same number of columns",
                ));
            }
        }
        for pair in rows.windows(2) {
            let (a, b) = (pair[0].values[0], pair[1].values[0]);
            let up = rows[1].values[0] > rows[0].values[0];
            if b == a || (b > a) != up {
                let msg = format!("strictly monotone (line {} has {a})", pair[0].line);
                return Err(cell_error(path, &pair[1], "temperature", b, &msg));
            }
        }
        let r: Vec<(f64, f64, Option<f64>)> = rows
            .iter()
            .map(|r| (r.values[0], r.values[1], r.values.get(2).copied()))
            .collect();
        Self::new(&r).map_err(|e| Error::parse(path, 0, 0, e.to_string()))
    }

    /// (T_min, T_max), K.
    pub fn temperature_range(&self) -> (f64, f64) {
        (
            self.temperature[0],
            self.temperature[self.temperature.len() - 1],
        )
    }

    /// The temperature (K) where the table's a_T (ln a_T linear in T between
    /// rows) equals 1: the reference temperature of the master curve it
    /// shifts. `None` when no row pair brackets a_T = 1.
    ///
    /// # Examples
    /// ```
    /// use persson::friction::ShiftTable;
    /// let t = ShiftTable::new(&[(280.0, 100.0, None), (300.0, 0.1, None)]).unwrap();
    /// // ln a_T = ln 100 − (T − 280) ln 1000/20 crosses 0 at T = 280 + 20·2/3.
    /// let t_ref = t.unit_shift_temperature().unwrap();
    /// assert!((t_ref - (280.0 + 40.0 / 3.0)).abs() < 1e-12);
    /// ```
    pub fn unit_shift_temperature(&self) -> Option<f64> {
        let (t, y) = (&self.temperature, &self.ln_shift);
        (0..t.len() - 1).find_map(|i| {
            if y[i] == 0.0 {
                return Some(t[i]);
            }
            if y[i + 1] == 0.0 {
                return Some(t[i + 1]);
            }
            (y[i].signum() != y[i + 1].signum())
                .then(|| t[i] + (t[i + 1] - t[i]) * y[i] / (y[i] - y[i + 1]))
        })
    }

    /// (ln a_T, b_T) by linear interpolation, extended linearly beyond the ends.
    fn at(&self, t: f64) -> (f64, Option<f64>) {
        let n = self.temperature.len();
        let i = self
            .temperature
            .partition_point(|&x| x <= t)
            .clamp(1, n - 1)
            - 1;
        let f = (t - self.temperature[i]) / (self.temperature[i + 1] - self.temperature[i]);
        let lin = |v: &[f64]| v[i] + f * (v[i + 1] - v[i]);
        (lin(&self.ln_shift), self.vertical.as_deref().map(lin))
    }
}

/// The horizontal shift a_T(T).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum HorizontalShift {
    /// a_T = 1: a temperature-independent modulus.
    None,
    /// Williams–Landel–Ferry, C1 (–) and C2 (K).
    Wlf {
        /// C1 (dimensionless, > 0).
        c1: f64,
        /// C2 in K (> 0).
        c2: f64,
    },
    /// A table a_T(T) (its b_T column, if any, is used by [`VerticalShift::Table`]).
    Table(ShiftTable),
}

/// The vertical shift b_T(T).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum VerticalShift {
    /// b_T = 1.
    None,
    /// b_T = T/T_ref (entropic elasticity at constant density).
    Entropic,
    /// b_T from the shift table's third column.
    Table,
}

crate::names::named! {
    VerticalShift, "vertical_shift",
    "The vertical shift b_T of time–temperature superposition." {
        None = "none": "b_T = 1.",
        Entropic = "entropic": "b_T = T/T_ref (entropic elasticity).",
        Table = "table": "b_T from the shift table's third column.",
    }
}

/// Time–temperature superposition of the reference master curve.
#[derive(Debug, Clone, PartialEq)]
pub struct TemperatureShift {
    reference_temperature: f64,
    horizontal: HorizontalShift,
    vertical: VerticalShift,
}

/// The largest WLF constant C1: −log10(f64::MIN_POSITIVE) ≈ 307.65.
///
/// # Bound
/// Above T_ref the shift log10 a_T = −C1 ΔT/(C2 + ΔT) falls towards −C1;
/// a_T stays a positive (normal) f64 at every T > T_ref, which the flash
/// temperature reaches from any background temperature, iff 10^(−C1) ≥
/// f64::MIN_POSITIVE.
pub const MAX_WLF_C1: f64 = 307.652_655_568_588_8;

impl TemperatureShift {
    /// No shift: E does not depend on T (T_ref only labels the curve).
    ///
    /// # Errors
    /// `reference_temperature` not finite and > 0 (K).
    pub fn none(reference_temperature: f64) -> Result<Self> {
        Ok(TemperatureShift {
            reference_temperature: check::positive("reference_temperature", reference_temperature)?,
            horizontal: HorizontalShift::None,
            vertical: VerticalShift::None,
        })
    }

    /// WLF with constants C1, C2 (K) about T_ref (K).
    ///
    /// # Errors
    /// Any of them not finite and > 0, naming `reference_temperature`,
    /// `wlf_c1` or `wlf_c2`; C1 above [`MAX_WLF_C1`] (`wlf_c1`).
    ///
    /// # Examples
    /// ```
    /// use persson::friction::TemperatureShift;
    /// // The "universal" constants C1 = 17.44, C2 = 51.6 K: at T = T_ref + 51.6 K, log10 a_T = −8.72.
    /// let s = TemperatureShift::wlf(273.15, 17.44, 51.6).unwrap();
    /// let f = s.factors(273.15 + 51.6).unwrap();
    /// assert!((f.shift_factor.log10() + 8.72).abs() < 1e-12);
    /// ```
    pub fn wlf(reference_temperature: f64, c1: f64, c2: f64) -> Result<Self> {
        let mut s = Self::none(reference_temperature)?;
        check::positive("wlf_c1", c1)?;
        if c1 > MAX_WLF_C1 {
            return Err(Error::invalid(
                "wlf_c1",
                c1,
                format!(
                    "at most −log10(f64::MIN_POSITIVE) = {} so that a_T ≥ 10^(−C1) stays a \
                     positive f64 at every temperature above T_ref (the flash temperature \
                     heats; measured C1 are 5–40)",
                    crate::error::approx(MAX_WLF_C1)
                ),
            ));
        }
        s.horizontal = HorizontalShift::Wlf {
            c1,
            c2: check::positive("wlf_c2", c2)?,
        };
        Ok(s)
    }

    /// A table a_T(T) about T_ref (K); its b_T column, if any, is used as the
    /// vertical shift.
    ///
    /// # Errors
    /// `reference_temperature` not finite and > 0, or outside the table's
    /// temperatures.
    pub fn table(reference_temperature: f64, table: ShiftTable) -> Result<Self> {
        let mut s = Self::none(reference_temperature)?;
        let (lo, hi) = table.temperature_range();
        if !(lo..=hi).contains(&reference_temperature) {
            return Err(Error::invalid(
                "reference_temperature",
                reference_temperature,
                format!("within the shift table's range [{lo}, {hi}] K"),
            ));
        }
        if table.vertical.is_some() {
            s.vertical = VerticalShift::Table;
        }
        s.horizontal = HorizontalShift::Table(table);
        Ok(s)
    }

    /// The same shift with another vertical shift.
    ///
    /// # Errors
    /// [`VerticalShift::Table`] without a shift table that has a b_T column.
    pub fn with_vertical(mut self, vertical: VerticalShift) -> Result<Self> {
        if vertical == VerticalShift::Table
            && !matches!(&self.horizontal, HorizontalShift::Table(t) if t.vertical.is_some())
        {
            return Err(Error::Inconsistent {
                name: "vertical_shift".into(),
                requirement: "a table b_T needs a shift table with a third column".into(),
            });
        }
        self.vertical = vertical;
        Ok(self)
    }

    /// T_ref, K.
    pub fn reference_temperature(&self) -> f64 {
        self.reference_temperature
    }

    /// The horizontal shift.
    pub fn horizontal(&self) -> &HorizontalShift {
        &self.horizontal
    }

    /// The vertical shift.
    pub fn vertical(&self) -> VerticalShift {
        self.vertical
    }

    /// The lowest temperature the shift accepts (K): for WLF the T_min of
    /// WLF range (`wlf_range`, above the singularity T_ref − C2), the table's
    /// first row, 0 otherwise.
    pub fn lowest_temperature(&self) -> f64 {
        match &self.horizontal {
            HorizontalShift::None => 0.0,
            HorizontalShift::Wlf { c1, c2 } => wlf_range(self.reference_temperature, *c1, *c2).0,
            HorizontalShift::Table(t) => t.temperature_range().0,
        }
    }

    /// a_T and b_T at T (K).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming `temperature`: not finite and > 0;
    /// for WLF outside the range where a_T is a finite, positive f64 (it
    /// starts above the singularity T_ref − C2: [`Self::lowest_temperature`]);
    /// outside the shift table.
    pub fn factors(&self, temperature: f64) -> Result<ShiftFactors> {
        check::positive("temperature", temperature)?;
        if let HorizontalShift::Table(t) = &self.horizontal {
            let (lo, hi) = t.temperature_range();
            if !(lo..=hi).contains(&temperature) {
                return Err(Error::invalid(
                    "temperature",
                    temperature,
                    format!("within the shift table's range [{lo}, {hi}] K"),
                ));
            }
        }
        self.factors_extended(temperature)
    }

    /// As [`Self::factors`], but a shift table is extended linearly beyond its
    /// ends (used for flash temperatures, which are reported when they leave it).
    pub(crate) fn factors_extended(&self, temperature: f64) -> Result<ShiftFactors> {
        let dt = temperature - self.reference_temperature;
        let (ln_a, b_table) = match &self.horizontal {
            HorizontalShift::None => (0.0, None),
            HorizontalShift::Wlf { c1, c2 } => {
                if dt + c2 <= 0.0 || dt.is_nan() {
                    // at or below the singularity
                    return Err(Error::invalid(
                        "temperature",
                        temperature,
                        format!(
                            "> T_ref − C2 = {} K (the WLF singularity)",
                            ((self.reference_temperature - c2) * 1e6).round() / 1e6
                        ),
                    ));
                }
                // above it, a_T still overflows up to T_min, and underflows
                // beyond T_max for a large C1: that range is stated (at
                // 193.15 K, above 191.55 K, the shift was refused as
                // "a_T = inf", 3.10 of the issue-37 audit)
                let (lo, hi) = wlf_range(self.reference_temperature, *c1, *c2);
                if !(temperature >= lo && temperature <= hi) {
                    let round = |t: f64| (t * 1e6).round() / 1e6;
                    return Err(Error::invalid(
                        "temperature",
                        temperature,
                        format!(
                            "in [{}, {} K, where the WLF shift a_T = 10^(−C1 (T − T_ref)/(C2 + \
                             T − T_ref)) (C1 = {}, C2 = {} K, T_ref = {} K) is a finite, \
                             positive f64; it is singular at T_ref − C2 = {} K",
                            round(lo),
                            if hi.is_finite() {
                                format!("{}]", round(hi))
                            } else {
                                "∞)".into()
                            },
                            crate::error::num(*c1),
                            crate::error::num(*c2),
                            crate::error::num(self.reference_temperature),
                            round(self.reference_temperature - c2)
                        ),
                    ));
                }
                (-LN_10 * c1 * dt / (c2 + dt), None)
            }
            HorizontalShift::Table(t) => t.at(temperature),
        };
        let b = match self.vertical {
            VerticalShift::None => 1.0,
            VerticalShift::Entropic => temperature / self.reference_temperature,
            VerticalShift::Table => b_table.unwrap_or(1.0),
        };
        let a = ln_a.exp();
        if !(a.is_finite() && a > 0.0 && b.is_finite() && b > 0.0) {
            return Err(Error::invalid(
                "temperature",
                temperature,
                format!("a temperature with a finite, positive shift (a_T = {a:e}, b_T = {b:e})"),
            ));
        }
        Ok(ShiftFactors {
            shift_factor: a,
            vertical_shift: b,
        })
    }

    /// Whether T lies beyond a shift table's range (flash heating).
    pub(crate) fn beyond_table(&self, temperature: f64) -> bool {
        matches!(&self.horizontal, HorizontalShift::Table(t) if temperature > t.temperature_range().1)
    }
}

/// The temperatures [T_min, T_max] (K) at which the WLF shift
/// a_T = e^{ln a}, ln a = −ln 10 · C1 ΔT/(C2 + ΔT), ΔT = T − T_ref, is a
/// finite, positive (normal) f64.
///
/// # Bound
/// Below T_ref, ln a grows without bound as ΔT → −C2; ln a ≤ L = ln f64::MAX
/// solves to ΔT ≥ −L C2/(ln 10 C1 + L). Above T_ref, ln a falls towards
/// −ln 10 C1; ln a ≥ ℓ = ln f64::MIN_POSITIVE (< 0) holds for every ΔT when
/// ln 10 C1 + ℓ ≤ 0 (C1 ≤ 307.6) and else for ΔT ≤ −ℓ C2/(ln 10 C1 + ℓ).
/// Each end is pulled inwards by 1e-12 relative so that the computed a_T,
/// rounded, stays inside f64.
pub(crate) fn wlf_range(reference_temperature: f64, c1: f64, c2: f64) -> (f64, f64) {
    let (l_hi, l_lo) = (f64::MAX.ln(), f64::MIN_POSITIVE.ln());
    let k = LN_10 * c1;
    let below = l_hi * c2 / (k + l_hi) * (1.0 - 1e-12);
    let above = if k + l_lo <= 0.0 {
        f64::INFINITY
    } else {
        -l_lo * c2 / (k + l_lo) * (1.0 - 1e-12)
    };
    (reference_temperature - below, reference_temperature + above)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wlf_and_its_singularity() {
        let s = TemperatureShift::wlf(300.0, 8.86, 101.6).unwrap();
        assert_eq!(s.factors(300.0).unwrap().shift_factor, 1.0);
        let e = s.factors(300.0 - 101.6).unwrap_err().to_string();
        assert!(e.contains("temperature") && e.contains("WLF"), "{e}");
        assert!(s.factors(f64::NAN).is_err());
        let f = s.factors(250.0).unwrap();
        let want = 10f64.powf(8.86 * 50.0 / (101.6 - 50.0));
        assert!((f.shift_factor / want - 1.0).abs() < 1e-13);
    }

    #[test]
    fn table_interpolation_and_range() {
        let t = ShiftTable::from_bytes(
            Path::new("s"),
            b"# T a_T b_T\n320 0.01 1.1\n300 1 1\n280 100 0.9\n",
        )
        .unwrap();
        let s = TemperatureShift::table(300.0, t).unwrap();
        assert_eq!(s.vertical(), VerticalShift::Table);
        let f = s.factors(310.0).unwrap();
        assert!((f.shift_factor - 0.1).abs() < 1e-14);
        assert!((f.vertical_shift - 1.05).abs() < 1e-14);
        assert!(s.factors(330.0).is_err());
        assert!((s.factors_extended(330.0).unwrap().shift_factor - 1e-3).abs() < 1e-16);
        let e = ShiftTable::from_bytes(Path::new("s.txt"), b"300 1\n300 2\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("s.txt:2"), "{e}");
        let e = ShiftTable::from_bytes(Path::new("s.txt"), b"300 1\n310 -2\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("s.txt:2") && e.contains("shift_factor"), "{e}");
    }
}

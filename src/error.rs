//! The one error type at the library boundary.
//!
//! Every variant carries typed fields (the parameter, its value and what was
//! required; the file, line and column) so that callers and the CLI can report
//! exactly what was wrong with the input.

use std::path::PathBuf;

/// Result alias used throughout the crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can go wrong in `persson`.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A numeric parameter is outside its allowed range.
    #[error("invalid {name} = {}: must be {requirement}", num(*.value))]
    InvalidParameter {
        /// The parameter's name as the user wrote it (CLI flag / JSON key).
        name: String,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        requirement: String,
    },
    /// Two or more parameters are individually valid but inconsistent.
    #[error("inconsistent {name}: {requirement}")]
    Inconsistent {
        /// The parameters involved.
        name: String,
        /// What must hold between them.
        requirement: String,
    },
    /// A file could not be parsed.
    #[error("{}{}: {message}", path.display(), position(*.line, *.column))]
    Parse {
        /// The file.
        path: PathBuf,
        /// 1-based line (0 when the whole file is at fault).
        line: usize,
        /// 1-based column (0 when unknown).
        column: usize,
        /// What was wrong, naming the field.
        message: String,
    },
    /// A file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// An iterative method or a quadrature did not reach its tolerance.
    #[error("{what} did not converge: {iterations} iterations, residual {} > tolerance {}", num(*.residual), num(*.tolerance))]
    NotConverged {
        /// The computation.
        what: String,
        /// Iterations or function evaluations spent.
        iterations: usize,
        /// The residual or error estimate reached.
        residual: f64,
        /// The tolerance asked for.
        tolerance: f64,
    },
}

/// `:line:column`, `:line` (column unknown) or nothing (the whole file).
fn position(line: usize, column: usize) -> String {
    match (line, column) {
        (0, _) => String::new(),
        (l, 0) => format!(":{l}"),
        (l, c) => format!(":{l}:{c}"),
    }
}

/// Of E* and σ0, the input to name when a function of their ratio leaves
/// f64's range or the routes' resolution: σ0 (the load, which the bounds
/// are stated for), unless E* lies outside [1e-30, 1e30] and further from 1
/// in order of magnitude than σ0. Moduli range from 1e3 Pa (gels) to 1e12
/// Pa (diamond), or are 1 in reduced units and 1e-6–1e3 in MPa or GPa: an E*
/// beyond 1e±30 is a typing error in every unit system, while a small or
/// large σ0 against an ordinary E* is the load the user asked for.
pub(crate) fn ratio_culprit(contact_modulus: f64, pressure: f64) -> &'static str {
    let (e, p) = (contact_modulus.log10().abs(), pressure.log10().abs());
    if e > 30.0 && e > p {
        "contact_modulus"
    } else {
        "nominal_pressure"
    }
}

/// A number as a person writes it: plain in [1e-4, 1e7), else scientific.
pub(crate) fn num(v: f64) -> String {
    if v == 0.0 || !v.is_finite() || (1e-4..1e7).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// A derived bound as a person reads it: [`num`] of `v` rounded to four
/// significant digits (bounds computed from other inputs carry no more).
pub(crate) fn approx(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return num(v);
    }
    let rounded: f64 = format!("{v:.3e}").parse().unwrap_or(v);
    num(rounded)
}

impl Error {
    /// Shorthand for [`Error::InvalidParameter`].
    pub fn invalid(name: impl Into<String>, value: f64, requirement: impl Into<String>) -> Self {
        Error::InvalidParameter {
            name: name.into(),
            value,
            requirement: requirement.into(),
        }
    }

    /// Shorthand for [`Error::Parse`].
    pub fn parse(
        path: impl Into<PathBuf>,
        line: usize,
        column: usize,
        message: impl Into<String>,
    ) -> Self {
        Error::Parse {
            path: path.into(),
            line,
            column,
            message: message.into(),
        }
    }
}

/// Checks of the ranges every parameter of the crate is held to, public so
/// that the layers above (the studies, the command line, the Python package)
/// refuse a value with the same words as the numerics: each returns the
/// value when it is in range, else an [`Error::InvalidParameter`] naming the
/// parameter, its value and the allowed range.
///
/// # Examples
/// ```
/// use persson::error::{check, Error};
/// assert_eq!(check::positive("size", 2.0).unwrap(), 2.0);
/// let e = check::positive("size", -1.0).unwrap_err();
/// assert_eq!(e.to_string(), "invalid size = -1: must be finite and > 0");
/// assert!(matches!(e, Error::InvalidParameter { .. }));
/// ```
pub mod check {
    use super::{num, Error, Result};

    /// `v` finite and `> 0`.
    pub fn positive(name: &str, v: f64) -> Result<f64> {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(Error::invalid(name, v, "finite and > 0"))
        }
    }

    /// `v` finite and `≥ 0`.
    pub fn non_negative(name: &str, v: f64) -> Result<f64> {
        if v.is_finite() && v >= 0.0 {
            Ok(v)
        } else {
            Err(Error::invalid(name, v, "finite and >= 0"))
        }
    }

    /// `v` finite and in the open interval `(lo, hi)`.
    pub fn open(name: &str, v: f64, lo: f64, hi: f64) -> Result<f64> {
        if v.is_finite() && v > lo && v < hi {
            Ok(v)
        } else {
            Err(Error::invalid(
                name,
                v,
                format!("in the open interval ({lo}, {hi})"),
            ))
        }
    }

    /// `v` finite and `≥ lo`.
    pub(crate) fn at_least(name: &str, v: f64, lo: f64) -> Result<f64> {
        if v.is_finite() && v >= lo {
            Ok(v)
        } else {
            Err(Error::invalid(name, v, format!("finite and >= {lo}")))
        }
    }

    /// A yield stress σY: finite, `> 0` and above every nominal (mean)
    /// pressure of `pressures` (with 0 ≤ p ≤ σY no contact carries a mean
    /// pressure σ0 ≥ σY: no solution exists). The one check of the saturated
    /// BEM and of the studies built on it.
    ///
    /// # Examples
    /// ```
    /// use persson::error::check;
    /// assert!(check::yield_stress("yield_stress", 0.05, &[0.01, 0.02]).is_ok());
    /// let e = check::yield_stress("yield_stress", 0.02, &[0.01, 0.02]).unwrap_err();
    /// assert!(e.to_string().contains("no solution exists"));
    /// ```
    pub fn yield_stress(name: &str, v: f64, pressures: &[f64]) -> Result<f64> {
        positive(name, v)?;
        let top = pressures
            .iter()
            .copied()
            .filter(|p| p.is_finite())
            .fold(0.0, f64::max);
        if v <= top {
            return Err(Error::invalid(
                name,
                v,
                format!(
                    "> every nominal pressure (largest {}): with 0 ≤ p ≤ σY no contact carries \
                     a mean pressure σ0 ≥ σY, so no solution exists",
                    num(top)
                ),
            ));
        }
        Ok(v)
    }

    /// A tolerance: finite and in `[1e-15, 0.1]`.
    pub fn tolerance(name: &str, v: f64) -> Result<f64> {
        if v.is_finite() && (1e-15..=0.1).contains(&v) {
            Ok(v)
        } else {
            Err(Error::invalid(name, v, "in [1e-15, 0.1]"))
        }
    }
}
